"""Fuzzing the command line with special files and extreme numbers.

Every input and output option of every command is handed a FIFO, a private device node (null,
zero, full: made with ``os.mknod`` in the test's own directory, skipped where that is not
permitted; the machine's own ``/dev`` is never named), a symbolic link to such a node, or a
directory; every numeric option is handed huge, tiny, negative and non-finite numbers. Each run
goes through ``experiments.cli.main`` in a forked child (:mod:`tests.experiments.forked`) with a
time bound, and must end by the convention of :mod:`experiments.commands.errors` (no
traceback, status 0, 1 or 2, one ``error:`` line for a failure) within the bound, with every
file set up before it (special files included) as it was. A special file where a regular file
is read or written must be refused; a directory only where a directory is expected may do.

The default run is derandomized and small (the same examples every time); the ``slow`` variants
draw many more. A failing example is reported as found (no shrinking: a hang costs the bound).
"""

from __future__ import annotations

import argparse
import os
import shutil
import stat
from dataclasses import dataclass
from pathlib import Path

import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from experiments.commands.errors import TRACEBACK_VARIABLE
from tests.experiments.extremes import extreme_arguments
from tests.experiments.forked import Forked, run_forked
from tests.experiments.test_cli_fuzz import FAST_COMMANDS, SLOW_COMMANDS, Outcome, check_convention
from tests.robustness.steps import DEVICES, Fixtures, Unsupported, make_device
from tests.robustness.watch import changed, snapshot

BOUND = 15.0
"""Seconds a run may take: a tiny match or a refusal takes well under one (a few on a loaded machine)."""

FAST = settings(max_examples=6, deadline=None, derandomize=True, database=None,
                phases=(Phase.explicit, Phase.generate), suppress_health_check=list(HealthCheck))
SLOW = settings(max_examples=60, deadline=None, database=None, phases=(Phase.explicit, Phase.generate),
                suppress_health_check=list(HealthCheck))

PLAY = ("play", "idle", "chaser", "--cycles", "5")
TOURNAMENT = ("tournament", "--teams", "idle,chaser", "--games", "2", "--cycles", "5", "--workers", "1",
              "--no-progress")
INCREMENTAL = ("experiment", "incremental", "--n", "8", "--trials", "1")
LAZY = ("bench", "lazy-assignment", "--sizes", "8", "--robots", "3", "--densities", "0.1", "--sizes-3d", "",
        "--repeats", "1")
TRANSFER = ("experiment", "transfer", "--report-only", "--engine-only")
DISTRIBUTED = ("experiment", "distributed", "--grid-sizes", "", "--etsp-sizes", "4", "--worst-sizes", "4",
               "--sweep-areas", "", "--trials", "1")


# ------------------------------------------------------------------------------ where a special file goes
@dataclass(frozen=True)
class Slot:
    """One place a command takes a file: ``argv`` with ``{p}`` where the special file is named,
    ``at`` the special file's path (``{p}`` itself, or a file inside a directory option)."""

    name: str
    argv: tuple[str, ...]
    at: str = "x"
    directory_ok: bool = False
    """A directory here is what the option expects (the run may succeed)."""


SLOTS = [
    # inputs
    Slot("formation validate FILE", ("formation", "validate", "{p}")),
    Slot("formation show FILE", ("formation", "show", "{p}", "--out", "out.png")),
    Slot("formation import FILE", ("formation", "import", "helios", "{p}", "out.json"), directory_ok=True),
    Slot("scenarios FILE", ("scenarios", "{p}"), at="x.toml"),
    Slot("play --scenario", (*PLAY, "--scenario", "{p}"), at="x.toml"),
    Slot("results show FILE", ("results", "show", "{p}")),
    Slot("results export FILE", ("results", "export", "{p}", "--csv", "out.csv")),
    Slot("replay FILE", ("replay", "{p}", "--png", "out.png"), at="x.rrd"),
    Slot("replay --results", ("replay", "--results", "{p}", "--row", "0", "--out", "out.rrd")),
    Slot("experiment transfer --out-real", (*TRANSFER, "rcssserver", "--out-real", "{p}"), at="x.sqlite"),
    Slot("experiment transfer --read-sim", (*TRANSFER, "simulator", "--out-sim", "results.sqlite", "--read-sim", "{p}"),
         at="x.sqlite"),
    # outputs
    Slot("formation show --out", ("formation", "show", "4-4-2", "--out", "{p}"), at="x.png", directory_ok=True),
    Slot("formation import OUT", ("formation", "import", "helios", "agent2d.conf", "{p}"), at="x.json"),
    Slot("play --record", (*PLAY, "--record", "{p}"), at="x.rrd"),
    Slot("play --rcg", (*PLAY, "--rcg", "{p}"), at="x.rcg"),
    Slot("results show --tables", ("results", "show", "results.sqlite", "--tables", "{p}"), directory_ok=True),
    Slot("a file inside results show --tables", ("results", "show", "results.sqlite", "--tables", "t"),
         at="t/league.csv"),
    Slot("results export --csv", ("results", "export", "results.sqlite", "--csv", "{p}"), at="x.csv"),
    Slot("results export --parquet", ("results", "export", "results.sqlite", "--parquet", "{p}"), at="x.parquet"),
    Slot("replay --png", ("replay", "match.rrd", "--png", "{p}"), at="x.png", directory_ok=True),
    Slot("replay --out", ("replay", "--results", "results.sqlite", "--row", "0", "--out", "{p}"), at="x.rrd"),
    Slot("experiment incremental --out", (*INCREMENTAL, "--out", "{p}"), directory_ok=True),
    Slot("bench lazy-assignment --out", (*LAZY, "--out", "{p}"), directory_ok=True),
]
"""Every file option of the commands that run in a second or two."""

SLOW_SLOTS = [
    *SLOTS,
    Slot("tournament --out", (*TOURNAMENT, "--out", "{p}"), at="x.sqlite"),
    Slot("tournament --tables", (*TOURNAMENT, "--out", "t.sqlite", "--tables", "{p}"), directory_ok=True),
    Slot("a file inside tournament --tables", (*TOURNAMENT, "--out", "t.sqlite", "--tables", "t"), at="t/league.csv"),
    Slot("tournament --record-dir", (*TOURNAMENT, "--out", "t.sqlite", "--record-dir", "{p}"), directory_ok=True),
    Slot("tournament --rcg-dir", (*TOURNAMENT, "--out", "t.sqlite", "--rcg-dir", "{p}"), directory_ok=True),
    Slot("experiment distributed --out", (*DISTRIBUTED, "--out", "{p}"), directory_ok=True),
]
"""With the commands that start worker processes."""

KINDS = ("fifo", "null-device", "zero-device", "full-device", "link-to-device", "directory")
"""What is put where a command reads or writes a file."""

INPUTS = ("results.sqlite", "match.rrd", "agent2d.conf")
"""The valid files the slots name besides the special one (copied into every run's directory)."""


def make_special(path: Path, kind: str) -> None:
    """A ``kind`` special file at ``path`` (Unsupported where the platform does not allow it)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    if kind == "fifo":
        if not hasattr(os, "mkfifo"):
            raise Unsupported("no os.mkfifo")
        os.mkfifo(path)
    elif kind == "directory":
        path.mkdir()
    elif kind == "link-to-device":
        make_device(path.parent / f".{path.name}.node", "null")
        os.symlink(f".{path.name}.node", path)
    else:
        make_device(path, kind.removesuffix("-device"))


@pytest.fixture(scope="module")
def fixtures(tmp_path_factory) -> Fixtures:
    """The valid input files, made once by this checkout's CLI."""
    fixtures = Fixtures(tmp_path_factory.mktemp("special-fixtures"))
    for name in INPUTS:
        try:
            fixtures.path(name)
        except Unsupported as exc:
            pytest.fail(str(exc))
    return fixtures


@pytest.fixture(scope="module")
def warm(fixtures, tmp_path_factory) -> None:
    """Load what the commands load (kernels, matplotlib, rerun) in this process once, so each
    forked run starts warm and takes a fraction of a second."""
    from tests.experiments.test_cli_fuzz import run_cli

    work = tmp_path_factory.mktemp("warm")
    for name in INPUTS:
        shutil.copyfile(fixtures.path(name), work / name)
    for argv in ([*PLAY, "--record", "w.rrd", "--rcg", "w.rcg"], ["formation", "show", "4-4-2", "--out", "w.png"],
                 ["results", "show", "results.sqlite", "--tables", "wt"], ["replay", "match.rrd", "--png", "r.png"]):
        outcome = run_cli(argv, work)
        assert outcome.status == 0, outcome


def run_in_child(argv: list[str], cwd: Path) -> Forked:
    from experiments.cli import main

    return run_forked(lambda: main(argv), bound=BOUND, cwd=cwd, env={TRACEBACK_VARIABLE: "1"})


def check_run(argv: list[str], run: Forked) -> None:
    """No hang, no traceback, no death by a signal, and the one-line convention."""
    where = f"argv={argv!r}"
    assert not run.timed_out, f"{where}: hangs ({run.describe()})"
    assert run.exit_signal is None, f"{where}: {run.describe()}; stderr {run.stderr[-300:]!r}"
    assert run.raised is None, f"{where}: traceback: {run.describe()}"
    status = run.returned if run.exited is None else run.exited
    assert isinstance(status, int), f"{where}: {run.describe()}"
    check_convention(Outcome(argv, status, run.stdout, run.stderr))


def status_of(run: Forked) -> int:
    return run.returned if run.exited is None else run.exited


def _special_example(fixtures: Fixtures, work: Path, slot: Slot, kind: str) -> None:
    for name in INPUTS:
        shutil.copyfile(fixtures.path(name), work / name)
    try:
        make_special(work / slot.at, kind)
    except Unsupported as exc:
        pytest.skip(str(exc))
    argv = [token.replace("{p}", slot.at) for token in slot.argv]
    writes = tuple(sorted({"out.png", "out.json", "out.csv", "out.rrd", "t.sqlite"} | (
        {slot.at} if kind == "directory" and slot.directory_ok else set())))
    before = snapshot(work, writes)
    run = run_in_child(argv, work)
    check_run(argv, run)
    assert not changed(before, work, writes), f"argv={argv!r} ({kind}) changed or replaced {changed(before, work, writes)}"
    if not (kind == "directory" and slot.directory_ok):
        assert status_of(run) != 0, f"argv={argv!r}: a {kind} at {slot.at} was taken as a file: {run.stdout[-200:]!r}"


def _special_test(fixtures: Fixtures, root: Path, kind: str, slots: list[Slot], config: settings) -> None:
    counter = iter(range(10**6))

    @config
    @given(st.sampled_from(slots))
    def fuzz(slot):
        work = root / f"run-{next(counter)}"
        work.mkdir()
        try:
            _special_example(fixtures, work, slot, kind)
        finally:
            shutil.rmtree(work, ignore_errors=True)

    fuzz()


@pytest.mark.parametrize("kind", KINDS)
def test_special_files_on_every_file_option(fixtures, warm, tmp_path, kind):
    _special_test(fixtures, tmp_path, kind, SLOTS, FAST)


@pytest.mark.slow
@pytest.mark.parametrize("kind", KINDS)
def test_special_files_on_every_file_option_at_length(fixtures, warm, tmp_path, kind):
    _special_test(fixtures, tmp_path, kind, SLOW_SLOTS, SLOW)


@pytest.mark.parametrize("slot", SLOTS, ids=lambda slot: slot.name)
def test_every_file_option_is_fuzzed_with_a_fifo(fixtures, warm, tmp_path, slot):
    """Each slot once, with the kind that blocks a careless reader or writer: a FIFO."""
    _special_example(fixtures, tmp_path, slot, "fifo")


def test_device_nodes_are_private(tmp_path):
    """The nodes the fuzz makes are in its own directory (or it is skipped), never /dev's."""
    try:
        make_special(tmp_path / "x", "full-device")
    except Unsupported as exc:
        pytest.skip(str(exc))
    info = (tmp_path / "x").lstat()
    assert stat.S_ISCHR(info.st_mode) and info.st_rdev == os.makedev(*DEVICES["full"])
    assert (tmp_path / "x").resolve().parent == tmp_path.resolve()


# ------------------------------------------------------------------------------ numbers

NUMBER_LISTS = ("--sizes", "--robots", "--densities", "--grid-sizes", "--etsp-sizes", "--worst-sizes", "--sweep-areas",
                "--lambdas", "--sizes-3d", "--degree")
"""Options taking comma-separated numbers."""


def numeric_options(prefix: tuple[str, ...]) -> list[tuple[str, int]]:
    """The options of sub-command ``prefix`` that take numbers, with how many values each takes."""
    from experiments.cli import build_parser

    parser = build_parser()
    for word in prefix[:2] if prefix[0] == "formation" else prefix:
        action = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction))
        parser = action.choices[word]
        if hasattr(parser, "populate"):
            parser.populate()
    found = []
    for action in parser._actions:
        if not action.option_strings or action.nargs == 0:
            continue
        name = getattr(action.type, "__name__", "")
        if name in ("int", "float", "positive_int", "positive_float", "seed_value") or \
                action.option_strings[-1] in NUMBER_LISTS:
            found.append((action.option_strings[-1], action.nargs if isinstance(action.nargs, int) else 1))
    return found


def _number_commands(commands: dict[tuple[str, ...], list[str]]) -> list:
    return [pytest.param(prefix, fixed, id=" ".join(prefix)) for prefix, fixed in sorted(commands.items())
            if (prefix[0] != "formation" or prefix[1] == "show") and numeric_options(prefix)]


def _numbers_test(fixtures: Fixtures, root: Path, prefix: tuple[str, ...], fixed: list[str], config: settings) -> None:
    options = numeric_options(prefix)
    for name in INPUTS:
        shutil.copyfile(fixtures.path(name), root / name)
    positional = {("formation", "show"): ["4-4-2", "--out", "out.png"], ("replay",): ["match.rrd", "--png", "out.png"],
                  ("play",): ["idle", "chaser"],
                  ("results", "show"): ["results.sqlite"], ("results", "export"): ["results.sqlite", "--csv", "out.csv"]}
    writes = ("out.png", "out.csv")
    before = snapshot(root, writes)

    @config
    @given(st.sampled_from(options).flatmap(lambda option: st.tuples(
        st.just(option[0]), st.lists(extreme_arguments(), min_size=option[1], max_size=option[1]))))
    def fuzz(drawn):
        option, values = drawn
        argv = [*prefix, *positional.get(prefix, []), *fixed, option, *values]
        run = run_in_child(argv, root)
        check_run(argv, run)
        assert not changed(before, root, writes), f"argv={argv!r} changed its inputs"

    fuzz()


@pytest.mark.parametrize("prefix, fixed", _number_commands(FAST_COMMANDS))
def test_extreme_numbers_on_every_numeric_option(fixtures, warm, tmp_path, prefix, fixed):
    _numbers_test(fixtures, tmp_path, prefix, fixed, settings(FAST, max_examples=8))


@pytest.mark.slow
@pytest.mark.parametrize("prefix, fixed", _number_commands(SLOW_COMMANDS))
def test_extreme_numbers_at_length(fixtures, warm, tmp_path, prefix, fixed):
    _numbers_test(fixtures, tmp_path, prefix, fixed, SLOW)
