"""Recording which compiled kernels a team's matches call, to keep
:mod:`experiments.kernel_manifest` in step with the code.

A numba kernel called from Python is compiled (or loaded from the on-disk cache) the first
time it meets a new tuple of argument types; the kernels it calls are compiled with it. So
the kernels a match needs are exactly the (kernel, argument types) pairs first called from
Python during the match. :func:`record_match` plays one match and returns them, with the
seconds each first call took (compile time when the cache was cold), by watching numba's
dispatcher entry for calls from Python. The match is written as a game log (``.rcg``, into a
temporary file) too, so the log's kernel is among the simulator's own and ``play --rcg``
finds it compiled.

Regenerate the manifest after changing a kernel's arguments (a test compares it with a fresh
recording)::

    python -m experiments.kernel_record --write

Each built-in team plays itself in a fresh process (so every first call is seen) with one
shared, initially empty numba cache, so a kernel's seconds are its cold compile time.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from experiments.limits import ranged

MANIFEST_PATH = Path(__file__).with_name("kernel_manifest.py")
"""The generated module :func:`write_manifest` writes."""

PARTIAL_TEAMS = ("mmdr", "mmd+msd2")
"""The built-in teams (home, away) whose partially observed match records the partial-observation
kernels (the benchmark's pairing: MMDR's and MMD+MSD²'s many-views assignment kernels both)."""

PARTIAL_CYCLES = 600
"""Cycles of that recording (a partially observed match of built-in teams is slow; every
partial-only kernel runs from the first cycles)."""

RECORD_CYCLES = 6000
"""Cycles of each recording match: a whole regulation match, so rare situations (set plays,
shots on goal) call their kernels too."""


def signature_text(signature: tuple) -> str:
    """A kernel's argument types as the manifest writes them: the tuple's ``repr``, except that a
    named tuple's type (``ArgsName(array(float64, 1d, C), ...)`` in numba's own text, which
    cannot be read back) is written ``named('module.Class', (field types,))``, which
    :func:`experiments.warmup.signature_of` reads."""
    texts = [_type_text(t) for t in signature]
    return "(" + ", ".join(texts) + ("," if len(texts) == 1 else "") + ")"


def _type_text(numba_type: object) -> str:
    """One argument type's text (see :func:`signature_text`)."""
    from numba.core import types

    if isinstance(numba_type, (types.NamedTuple, types.NamedUniTuple)):
        cls = numba_type.instance_class
        fields = [_type_text(t) for t in numba_type.types]
        return f"named({cls.__module__ + '.' + cls.__qualname__!r}, ({', '.join(fields)}{',' if len(fields) == 1 else ''}))"
    return repr(numba_type)


def record_match(home: str, away: str, seed: int = 0, cycles: int | None = RECORD_CYCLES,
                 observation: str = "full") -> list[dict]:
    """Play ``home`` v ``away`` in this process and return every kernel first called from
    Python during it: ``{"module", "function", "signature", "seconds"}`` dicts, in call order.

    Kernels already called in this process before are not seen again; run it in a fresh one.
    ``observation``: the match's observation mode (``"full"`` or ``"partial"``)."""
    from numba.core.dispatcher import Dispatcher

    from experiments.configuration import match_config
    from soccer_sim import run_match
    from soccer_sim.rcg import RcgRecorder

    found: list[dict] = []
    original = Dispatcher._compile_for_args

    def watched(self, *args, **kws):
        before = set(self.signatures)
        start = time.perf_counter()
        try:
            return original(self, *args, **kws)
        finally:
            seconds = time.perf_counter() - start
            for signature in set(self.signatures) - before:
                found.append({"module": self.py_func.__module__, "function": self.py_func.__qualname__,
                              "signature": signature_text(signature), "seconds": round(seconds, 3)})

    Dispatcher._compile_for_args = watched
    try:
        with tempfile.TemporaryDirectory(prefix="soccer-sim-record-") as folder:
            run_match(home, away, seed=seed, config=match_config(cycles, observation),
                      recorders=[RcgRecorder(Path(folder) / "match.rcg")])
    finally:
        Dispatcher._compile_for_args = original
    return found


def builtin_teams() -> list[str]:
    """The registered teams shipped with the project (those whose code is in its packages)."""
    from soccer_sim import available_teams

    return [name for name, target in available_teams().items()
            if target.split(".")[0] in ("soccer_sim", "agents")]


def record_teams(teams: list[str], cycles: int = RECORD_CYCLES) -> dict[str, list[dict]]:
    """Each team's self-play recording, each in a fresh process, all sharing one new numba cache;
    then, under :data:`~experiments.warmup.PARTIAL_ENTRY`, the kernels a partially observed
    match of :data:`PARTIAL_TEAMS` adds (over :data:`PARTIAL_CYCLES` cycles)."""
    from experiments.warmup import PARTIAL_ENTRY

    recordings: dict[str, list[dict]] = {}
    with tempfile.TemporaryDirectory(prefix="soccer-sim-kernels-") as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        for team in teams:
            out = subprocess.run([sys.executable, "-m", "experiments.kernel_record", "--team", team,
                                  "--cycles", str(cycles)], env=env, capture_output=True, text=True, check=True)
            recordings[team] = json.loads(out.stdout)
            print(f"{team}: {len(recordings[team])} kernels", file=sys.stderr)
        home, away = PARTIAL_TEAMS
        out = subprocess.run([sys.executable, "-m", "experiments.kernel_record", "--team", home, "--away", away,
                              "--cycles", str(PARTIAL_CYCLES), "--observation", "partial"], env=env,
                             capture_output=True, text=True, check=True)
        recordings[PARTIAL_ENTRY] = json.loads(out.stdout)
        print(f"{PARTIAL_ENTRY}: {len(recordings[PARTIAL_ENTRY])} kernels", file=sys.stderr)
    return recordings


def manifest_text(recordings: dict[str, list[dict]]) -> str:
    """The source of :mod:`experiments.kernel_manifest` for ``recordings`` (team -> kernels)."""
    kernels: dict[tuple[str, str, str], float] = {}
    for found in recordings.values():
        for k in found:
            key = (k["module"], k["function"], k["signature"])
            kernels[key] = max(kernels.get(key, 0.0), k["seconds"])
    order = sorted(kernels)
    index = {key: i for i, key in enumerate(order)}
    lines = ['"""The compiled kernels each built-in team\'s matches call from Python, with their argument',
             "types: what :mod:`experiments.warmup` compiles before the first match.",
             "",
             "Generated by ``python -m experiments.kernel_record --write``; do not edit. Each entry is",
             "(module, function, argument types as numba type expressions, seconds its cold compile took",
             'where it was recorded: a weight for sharing the work between processes)."""',
             "",
             "KERNELS: tuple[tuple[str, str, str, float], ...] = ("]
    lines += [f"    ({m!r}, {f!r}, {s!r}, {kernels[(m, f, s)]!r})," for m, f, s in order]
    lines += [")", "", "TEAMS: dict[str, tuple[int, ...]] = {"]
    for team in sorted(recordings):
        ids = sorted({index[(k["module"], k["function"], k["signature"])] for k in recordings[team]})
        lines.append(f"    {team!r}: ({', '.join(map(str, ids))}{',' if len(ids) == 1 else ''}),")
    lines += ["}", '"""Team name -> indices into KERNELS of the kernels its self-play match calls."""', ""]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m experiments.kernel_record", description=__doc__.split("\n\n")[0])
    parser.add_argument("--team", help="record this team's self-play in this process and print it as JSON")
    parser.add_argument("--away", help="with --team: the away team (default: the same team, a self-play)")
    parser.add_argument("--cycles", type=ranged("cycles"), default=RECORD_CYCLES,
                        help=f"cycles per match (default: {RECORD_CYCLES})")
    parser.add_argument("--observation", choices=("full", "partial"), default="full",
                        help="with --team: the observation mode of the recorded match (default: full)")
    parser.add_argument("--write", action="store_true",
                        help=f"record every built-in team and rewrite {MANIFEST_PATH.name}")
    args = parser.parse_args(argv)
    if args.team:
        print(json.dumps(record_match(args.team, args.away or args.team, cycles=args.cycles,
                                      observation=args.observation)))
        return 0
    if not args.write:
        parser.error("give --team NAME or --write")
    MANIFEST_PATH.write_text(manifest_text(record_teams(builtin_teams(), args.cycles)))
    print(f"wrote {MANIFEST_PATH}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
