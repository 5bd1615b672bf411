"""Fuzzing the command line: random argument lists and damaged input files.

Every run goes through ``experiments.cli.main`` in-process and must end by the convention of
:mod:`experiments.commands.errors`: no traceback, at most one line on stderr (``error: ...``
for a non-zero status, nothing at all for success), exit status 0, 1 or 2, and every input
file byte for byte as it was. For the damaged files the status is 0 exactly when the library
itself reads the file without complaint.

Unexpected exceptions are raised (``SOCCER_SIM_TRACEBACK=1``) so that hypothesis reports the
failing argv or file rather than a one-line summary. The default run is derandomized (the same
examples every time, a few seconds each); the ``slow`` ones draw many more, at random.

Matches are kept tiny: teams ``idle`` and ``chaser``, ``--cycles 5`` (the fixed options of each
command are appended after the random tokens, so they win).
"""

from __future__ import annotations

import argparse
import contextlib
import functools
import hashlib
import io
import json
import os
import warnings
from dataclasses import dataclass
from pathlib import Path
from unittest import mock

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from experiments.commands.errors import TRACEBACK_VARIABLE, CommandParser
from soccer_sim.config import STANDARD_FIELD as FIELD

# a damaged results file is ~20 kB of bytes: hypothesis says so when it reports one
pytestmark = pytest.mark.filterwarnings("ignore:Generating overly large repr")

FAST = settings(max_examples=60, deadline=None, derandomize=True, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
SLOW = settings(max_examples=200, deadline=None, database=None,
                suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])

JUNK = ["", "0", "-1", "1", "2", "x", "nan", "inf", "-", "--", ",", "a,b", "é", "a\nb", "1e3", "-5.5", "None",
        "idle", "chaser", "nobody", "no_such_pkg.mod:Team", "experiments.cli:COMMAND_MODULES", "4-3-3", "kick-off"]
"""Values and positionals mixed with the real flags."""

OUTPUT_FLAGS = {"--out", "--png", "--csv", "--parquet", "--tables", "--record", "--record-dir", "--rcg", "--rcg-dir"}
"""Options whose value a command writes (a file named there may change)."""


# ------------------------------------------------------------------------------ the input files
@dataclass(frozen=True)
class Inputs:
    """Valid input files of every kind, plus junk, in one directory; ``outputs``: places to write."""

    root: Path
    files: dict[str, Path]
    outputs: list[str]

    def digests(self) -> dict[Path, str]:
        return {path: _sha256(path) for path in self.files.values() if path.is_file()}


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _results_file(path: Path) -> None:
    """A real tournament results file (idle v chaser, 2 matches of 5 cycles), played in-process."""
    from experiments.results.store import ResultStore
    from experiments.runner.spec import code_version, config_description, config_for, config_hash, paired_specs
    from experiments.runner.worker import play_spec

    config = config_for(5)
    digest, version = config_hash(config), code_version()
    params = {"teams": ["idle", "chaser"], "games": 2, "seed": 0, "cycles": 5}
    with ResultStore.create(path, "tournament", digest, config_description(config), params) as store:
        for spec in paired_specs("idle", "chaser", 2, 0, 5):
            store.add(play_spec(spec, digest, version, None))


def _agent2d_text() -> str:
    """An agent2d 'Method Delaunay' (version 2) formation, written by the formation tests' helper."""
    import importlib.util

    helper = Path(__file__).parents[1] / "formations" / "agent2d_samples.py"
    spec = importlib.util.spec_from_file_location("_agent2d_samples_for_fuzz", helper)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.dt_v2_text()


@pytest.fixture(scope="module")
def inputs(tmp_path_factory) -> Inputs:
    from formations.builtin import builtin_path
    from soccer_sim.scenarios import get_scenario
    from soccer_sim.scenarios.files import scenario_to_dict

    root = tmp_path_factory.mktemp("fuzz-inputs")
    files = {
        "formation.json": root / "formation.json",
        "agent2d.conf": root / "agent2d.conf",
        "scenario.json": root / "scenario.json",
        "scenario.toml": root / "scenario.toml",
        "stored.sqlite": root / "stored.sqlite",
        "junk.bin": root / "junk.bin",
        "empty.json": root / "empty.json",
    }
    files["formation.json"].write_bytes(builtin_path("4-4-2").read_bytes())
    files["agent2d.conf"].write_text(_agent2d_text())
    files["scenario.json"].write_text(json.dumps(scenario_to_dict(get_scenario("kick-off")), indent=2))
    toml = Path(__import__("soccer_sim.scenarios", fromlist=["x"]).__file__).parent / "data" / "corner.toml"
    files["scenario.toml"].write_bytes(toml.read_bytes())
    _results_file(files["stored.sqlite"])
    files["junk.bin"].write_bytes(bytes(range(256)) * 4)
    files["empty.json"].write_bytes(b"")
    (root / "a-directory").mkdir()
    outputs = [str(root / "out" / name) for name in ("x.png", "x.json", "x.csv", "x.parquet", "x.rrd", "dir")]
    (root / "out").mkdir()
    return Inputs(root, files, [*outputs, str(root / "a-directory"), str(root / "missing" / "x.png")])


# ------------------------------------------------------------------------------ running the CLI
@dataclass
class Outcome:
    argv: list[str]
    status: int
    out: str
    err: str


@functools.cache
def _cli_is_wired() -> bool:
    from experiments.cli import build_parser

    return isinstance(build_parser(), CommandParser)


def _as_command_parsers(parser: argparse.ArgumentParser) -> None:
    """Make ``parser`` and every sub-parser under it a CommandParser (it adds no state)."""
    parser.__class__ = CommandParser
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in action.choices.values():
                _as_command_parsers(sub)


@contextlib.contextmanager
def _one_line_parser():
    """experiments.cli's parser as a CommandParser (what cli.py is to build: usage errors in one
    line); a no-op once cli.py builds it so."""
    import experiments.cli as cli

    if _cli_is_wired():
        yield
        return
    real = cli.build_parser

    def build_parser():
        parser = real()
        _as_command_parsers(parser)
        return parser

    with mock.patch.object(cli, "build_parser", build_parser):
        yield


def run_cli(argv: list[str], cwd: Path) -> Outcome:
    """``main(argv)`` in ``cwd`` with stdout and stderr captured (and the warnings a user would
    see counted as stderr lines); no display, so the replay viewer never opens."""
    from experiments.cli import main

    out, err = io.StringIO(), io.StringIO()
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    env[TRACEBACK_VARIABLE] = "1"
    previous = os.getcwd()
    os.chdir(cwd)
    try:
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err), \
                mock.patch.dict(os.environ, env, clear=True), _one_line_parser(), \
                warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("default")
            warnings.filterwarnings("ignore", category=DeprecationWarning)
            warnings.filterwarnings("ignore", category=PendingDeprecationWarning)
            try:
                status = main(argv)
            except SystemExit as exc:
                status = exc.code if isinstance(exc.code, int) else (0 if exc.code is None else 1)
    finally:
        os.chdir(previous)
    shown = "".join(f"warning: {w.category.__name__}: {w.message}\n" for w in caught)
    return Outcome(list(argv), status, out.getvalue(), err.getvalue() + shown)


def check_convention(outcome: Outcome) -> None:
    """No traceback, status 0/1/2, one 'error: ' line on stderr for a failure, none for success."""
    where = f"argv={outcome.argv!r} status={outcome.status} stderr={outcome.err!r}"
    assert "Traceback" not in outcome.err, where
    assert outcome.status in (0, 1, 2), where
    lines = outcome.err.splitlines()
    if outcome.status == 0:
        assert lines == [], where
    else:
        assert len(lines) == 1 and lines[0].startswith("error: "), where


def written_paths(argv: list[str]) -> set[str]:
    """The tokens of ``argv`` that name a file the command may write."""
    named = {argv[i + 1] for i, token in enumerate(argv[:-1]) if token in OUTPUT_FLAGS}
    named |= {token.split("=", 1)[1] for token in argv if token.split("=", 1)[0] in OUTPUT_FLAGS and "=" in token}
    if argv[:2] == ["formation", "import"]:
        named |= set(argv[2:])  # OUT is the last positional
    return named


# ------------------------------------------------------------------------------ argv fuzzing
def _flags(prefix: list[str]) -> list[str]:
    """The option strings of the sub-command ``prefix`` names, read from the real parser."""
    from experiments.cli import build_parser

    parser = build_parser()
    for word in prefix:
        action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
        parser = action.choices[word]
    return [s for action in parser._actions for s in action.option_strings if s not in ("-h", "--help")]


#: Sub-command -> options appended last (so they win) to keep every valid run tiny.
FAST_COMMANDS: dict[tuple[str, ...], list[str]] = {
    ("formation", "validate"): [],
    ("formation", "show"): [],
    ("formation", "import", "helios"): [],
    ("scenarios",): [],
    ("play",): ["--cycles", "5"],
    ("results", "show"): [],
    ("results", "export"): [],
    ("replay",): [],
    ("bench", "lazy-assignment"): ["--sizes", "8", "--robots", "3", "--densities", "0.1", "--sizes-3d", "",
                                   "--repeats", "1"],
    ("bench", "formation"): ["--queries", "50", "--single", "50", "--batch", "25", "--repeats", "1",
                             "--set", "4-3-3"],
    ("bench", "match"): ["--matches", "1", "--cycles", "5", "--home", "idle", "--away", "chaser"],
    ("experiment", "incremental"): ["--n", "8", "--trials", "1"],
    ("experiment", "distributed"): ["--grid-sizes", "", "--etsp-sizes", "4", "--worst-sizes", "4",
                                    "--sweep-areas", "", "--trials", "1"],
}

#: Run commands and longer ones, for the slow fuzz only.
SLOW_COMMANDS: dict[tuple[str, ...], list[str]] = {
    **FAST_COMMANDS,
    ("tournament",): ["--teams", "idle,chaser", "--games", "2", "--cycles", "5", "--workers", "1", "--no-progress"],
    ("experiment", "case-study"): ["--teams", "idle,chaser", "--opponents", "chaser", "--baseline", "idle",
                                   "--games", "2", "--cycles", "5", "--workers", "1", "--no-progress"],
    ("experiment", "penalty-shot"): ["--trials", "1", "--limit", "5", "--workers", "1", "--team", "chaser",
                                     "--keeper", "idle", "--no-progress"],
    ("bench", "soccer"): ["--matches", "1", "--cycles", "5", "--home", "idle", "--away", "chaser"],
    ("bench", "roles"): ["--situations", "1", "--number", "1"],
    ("bench", "assignment"): ["--sizes", "4", "--repeats", "1", "--quality-instances", "2"],
}


def _argv_strategy(prefix: tuple[str, ...], fixed: list[str], inputs: Inputs):
    """``prefix``, up to six tokens drawn from its real flags, junk and file paths, then ``fixed``."""
    paths = [str(p) for p in inputs.files.values()] + inputs.outputs + [str(inputs.root / "nothing-here.json")]
    # formation import keeps its layout word: the flags are those of `formation import`'s parser
    vocabulary = _flags(list(prefix[:2]) if prefix[0] == "formation" else list(prefix)) + JUNK + paths
    return st.lists(st.sampled_from(vocabulary), max_size=6).map(lambda tokens: [*prefix, *tokens, *fixed])


def _fuzz_argv(inputs: Inputs, argv: list[str]) -> None:
    pristine = {path: path.read_bytes() for path in inputs.files.values()}
    before = inputs.digests()
    try:
        outcome = run_cli(argv, inputs.root)
        check_convention(outcome)
        written = written_paths(argv)
        changed = [str(path) for path, digest in before.items() if _sha256(path) != digest and str(path) not in written]
        assert not changed, f"argv={argv!r} changed input files {changed}"
    finally:
        for path, data in pristine.items():  # the next example starts from the same files
            if not path.is_file() or path.read_bytes() != data:
                path.write_bytes(data)


#: Commands whose modules do not follow the convention yet, with what the fuzz found: none now;
#: an entry makes that command's case an expected failure until it is fixed.
KNOWN_ARGV_FAILURES: dict[tuple[str, ...], str] = {}


#: What the longer fuzz finds besides.
KNOWN_ARGV_FAILURES_AT_LENGTH: dict[tuple[str, ...], str] = {**KNOWN_ARGV_FAILURES}


def _argv_cases(commands: dict[tuple[str, ...], list[str]], known: dict, strict: bool = True) -> list:
    """One case per command; a known failure is an expected one (strict where the examples are
    always the same, so that a fix shows)."""
    return [pytest.param(prefix, fixed, id=" ".join(prefix),
                         marks=[pytest.mark.xfail(reason=known[prefix], strict=strict)] if prefix in known else [])
            for prefix, fixed in sorted(commands.items())]


def _argv_test(inputs: Inputs, prefix: tuple[str, ...], fixed: list[str], config: settings) -> None:
    @config
    @given(_argv_strategy(prefix, fixed, inputs))
    def fuzz(argv):
        _fuzz_argv(inputs, argv)

    fuzz()


@pytest.mark.parametrize("prefix, fixed", _argv_cases(FAST_COMMANDS, KNOWN_ARGV_FAILURES))
def test_random_argv_follow_the_convention(inputs, prefix, fixed):
    _argv_test(inputs, prefix, fixed, settings(FAST, max_examples=25))


@pytest.mark.slow
@pytest.mark.parametrize("prefix, fixed", _argv_cases(SLOW_COMMANDS, KNOWN_ARGV_FAILURES_AT_LENGTH, strict=False))
def test_random_argv_follow_the_convention_at_length(inputs, prefix, fixed):
    _argv_test(inputs, prefix, fixed, SLOW)


# ------------------------------------------------------------------------------ damaged files
@st.composite
def damaged(draw, original: bytes) -> bytes:
    """``original`` truncated, with bytes flipped, inserted or deleted, a line dropped or
    duplicated, or replaced by random bytes."""
    kind = draw(st.sampled_from(["truncate", "flip", "insert", "delete", "line", "random"]))
    if kind == "random":
        return draw(st.binary(max_size=300))
    data = bytearray(original)
    if kind == "truncate":
        return bytes(data[:draw(st.integers(0, max(0, len(data) - 1)))])
    if kind == "line":
        lines = bytes(data).splitlines(keepends=True)
        i = draw(st.integers(0, len(lines) - 1))
        if draw(st.booleans()):
            del lines[i]
        else:
            lines.insert(i, lines[i])
        return b"".join(lines)
    for _ in range(draw(st.integers(1, 4))):
        i = draw(st.integers(0, max(0, len(data) - 1)))
        if kind == "flip" and data:
            data[i] = draw(st.integers(0, 255))
        elif kind == "insert":
            data[i:i] = draw(st.sampled_from([b"0", b"-", b"\xff", b"]", b"}", b"\"", b",", b"\n", b"nan", b"1e999",
                                              b"#", b"=", b"[", b"{"]))
        elif kind == "delete" and data:
            del data[i:i + draw(st.integers(1, 8))]
    return bytes(data)


def _reads(kind: str, path: Path) -> bool:
    """Whether the library reads the file as valid (the oracle for exit status 0)."""
    try:
        if kind == "formation":
            from formations import read_any

            read_any(str(path), field=FIELD)
        elif kind == "scenario":
            from soccer_sim import MatchConfig
            from soccer_sim.scenarios import load_scenario

            load_scenario(path).check(MatchConfig())
    except Exception:  # noqa: BLE001 - any refusal: the CLI must refuse it too (its kind is checked there)
        return False
    return True


#: (input file, name of the damaged copy, kind, argv with FILE and OUT as placeholders)
READERS = [
    ("formation.json", "f.json", "formation", ["formation", "validate", "FILE"]),
    ("agent2d.conf", "f.conf", "formation", ["formation", "validate", "FILE"]),
    ("agent2d.conf", "f.conf", "formation", ["formation", "import", "helios", "FILE", "OUT/imported.json"]),
    ("scenario.json", "s.json", "scenario", ["scenarios", "FILE"]),
    ("scenario.toml", "s.toml", "scenario", ["scenarios", "FILE"]),
    ("scenario.toml", "s.toml", "scenario", ["play", "idle", "chaser", "--cycles", "5", "--scenario", "FILE"]),
    ("stored.sqlite", "r.sqlite", "results", ["results", "show", "FILE"]),
    ("stored.sqlite", "r.sqlite", "results", ["results", "export", "FILE", "--csv", "OUT/matches.csv"]),
]

#: Readers whose commands do not follow the convention yet: none now (as above).
KNOWN_FILE_FAILURES: dict[tuple[str, ...], str] = {}


def _reader_cases(strict: bool = True) -> list:
    cases = []
    for reader in READERS:
        reason = KNOWN_FILE_FAILURES.get((reader[3][0],))
        cases.append(pytest.param(reader, id=f"{reader[3][0]}-{reader[3][1]}-{reader[0]}",
                                  marks=[pytest.mark.xfail(reason=reason, strict=strict)] if reason else []))
    return cases


def _fuzz_file(inputs: Inputs, tmp: Path, reader: tuple, data: bytes) -> Outcome:
    source, name, kind, template = reader
    path = tmp / name
    path.write_bytes(data)
    out = tmp / "out"
    out.mkdir(exist_ok=True)
    argv = [str(path) if token == "FILE" else token.replace("OUT", str(out)) for token in template]
    digest = _sha256(path)
    outcome = run_cli(argv, tmp)
    check_convention(outcome)
    assert _sha256(path) == digest, f"{argv!r} changed its input file ({len(data)} bytes: {data[:80]!r}...)"
    if kind in ("formation", "scenario") and argv[0] != "play":
        valid = _reads(kind, path)
        assert (outcome.status == 0) == valid, (f"{argv!r}: status {outcome.status}, library reads it: {valid}; "
                                                f"stderr {outcome.err!r}; file starts {data[:120]!r}")
    elif outcome.status != 0:
        assert outcome.status == 2, f"{argv!r}: a bad input file is bad input (2), got {outcome.status}"
    return outcome


def _file_test(inputs: Inputs, tmp: Path, reader: tuple, config: settings):
    original = inputs.files[reader[0]].read_bytes()

    @config
    @given(damaged(original))
    def fuzz(data):
        _fuzz_file(inputs, tmp, reader, data)

    fuzz()


@pytest.mark.parametrize("reader", _reader_cases())
def test_damaged_files_are_refused_in_one_line_and_left_unchanged(inputs, reader, tmp_path):
    _file_test(inputs, tmp_path, reader, settings(FAST, max_examples=30))


@pytest.mark.slow
@pytest.mark.parametrize("reader", _reader_cases(strict=False))
def test_damaged_files_at_length(inputs, reader, tmp_path):
    _file_test(inputs, tmp_path, reader, SLOW)


def test_the_valid_files_are_read(inputs, tmp_path):
    """The undamaged inputs pass (so a refusal above is the damage's doing)."""
    for reader in READERS:
        outcome = _fuzz_file(inputs, tmp_path, reader, inputs.files[reader[0]].read_bytes())
        assert outcome.status == 0 and outcome.out, outcome
    for kind, name in (("formation", "formation.json"), ("formation", "agent2d.conf"), ("scenario", "scenario.json"),
                       ("scenario", "scenario.toml")):
        assert _reads(kind, inputs.files[name])
