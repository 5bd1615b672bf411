"""``soccer-sim bench startup``: how long ``soccer-sim`` takes to start, cold and warm.

Each repeat runs, as separate processes of this Python with this checkout's code:

- ``play`` with an empty numba cache (``NUMBA_CACHE_DIR`` pointed at a new temporary
  directory): a first match on a fresh install, compiling every kernel it needs;
- the same ``play`` again with that cache: every later first match of a process;
- ``soccer-sim --help`` and the ``--help`` of every command and sub-command
  (:func:`experiments.cli.command_paths`): building the command line and printing it, which
  must stay under :data:`HELP_BUDGET_SECONDS` (a command's options are read without importing
  the simulator; see :mod:`experiments.lazy_parser`).

It reports the median and fastest wall time of each (process start to exit, everything
included), the compile time the cold runs printed, the slowest ``--help`` against its budget,
the machine's core count and its load average before and after (other programs running slow
every figure down). ``--help-only`` leaves out the matches (seconds instead of minutes).
"""

from __future__ import annotations

import argparse

from experiments.errors import ExperimentError

HELP_BUDGET_SECONDS = 0.5
"""The wall time within which ``--help`` of any command should print, on a machine whose
programs are in its file cache (warm)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.limits import ranged

    parser.add_argument("--home", default="mmd+msd2", help="home team of the match played (default: mmd+msd2)")
    parser.add_argument("--away", default="press-433", help="away team of the match played (default: press-433)")
    parser.add_argument("--cycles", type=ranged("cycles"), default=None,
                        help="cycles of the match played (default: a full match of 6000)")
    parser.add_argument("--seed", type=ranged("seed"), default=0, help="seed of the match played (default: 0)")
    parser.add_argument("--repeats", type=ranged("repeats"), default=3,
                        help="cold and warm runs of play, and runs of each --help, to take the median of (default: 3)")
    parser.add_argument("--help-only", action="store_true",
                        help="time only the --help of every command (no match played, nothing compiled)")


def run(args: argparse.Namespace) -> int:
    import os
    import statistics
    import sys
    import tempfile

    from experiments.cli import command_paths
    from experiments.reporting import Table

    play = ["play", args.home, args.away, "--seed", str(args.seed)]
    if args.cycles is not None:
        play += ["--cycles", str(args.cycles)]
    helps = {" ".join(["soccer-sim", *path, "--help"]): [*path, "--help"] for path in command_paths()}
    load_before = _load()
    times: dict[str, list[float]] = {} if args.help_only else {"play, cold cache": [], "play, warm cache": []}
    times.update({name: [] for name in helps})
    compile_seconds: list[float] = []
    try:
        for _ in range(args.repeats):
            if not args.help_only:
                with tempfile.TemporaryDirectory(prefix="soccer-sim-bench-cache-") as cache:
                    seconds, stderr = _timed(play, cache)
                    times["play, cold cache"].append(seconds)
                    compile_seconds += _compile_seconds(stderr)
                    times["play, warm cache"].append(_timed(play, cache)[0])
            for name, cli_args in helps.items():
                times[name].append(_timed(cli_args, None)[0])
    except _RunFailed as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1
    what = "--help only" if args.help_only else f"{args.home} v {args.away}, seed {args.seed}, {args.cycles or 6000} cycles"
    table = Table(f"start-up of soccer-sim ({what}; {args.repeats} runs each; {os.cpu_count()} cores)",
                  ["run", "median s", "min s"])
    for name, values in times.items():
        table.rows.append([name, f"{statistics.median(values):.2f}", f"{min(values):.2f}"])
        if name == "play, warm cache" and compile_seconds:
            table.rows.append(["of which compiling (cold)", f"{statistics.median(compile_seconds):.2f}",
                               f"{min(compile_seconds):.2f}"])
    table.print()
    slowest = max(helps, key=lambda name: statistics.median(times[name]))
    seconds = statistics.median(times[slowest])
    verdict = "within" if seconds < HELP_BUDGET_SECONDS else "over"
    print(f"slowest --help: {slowest}, {seconds:.2f} s median: {verdict} the budget of {HELP_BUDGET_SECONDS:g} s")
    print(f"load average (1 min) before {load_before}, after {_load()}")
    return 0


class _RunFailed(ExperimentError):
    """A measured command exited with an error."""


def _timed(cli_args: list[str], cache: str | None) -> tuple[float, str]:
    """Wall seconds of ``python -m experiments.cli *cli_args`` (this checkout's code, the numba
    cache ``cache`` if given) and its stderr; _RunFailed if it fails."""
    import os
    import subprocess
    import sys
    import time
    from pathlib import Path

    import experiments

    root = str(Path(experiments.__file__).resolve().parents[1])
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(filter(None, [root, os.environ.get("PYTHONPATH")])))
    if cache is not None:
        env["NUMBA_CACHE_DIR"] = cache
    command = [sys.executable, "-m", "experiments.cli", *cli_args]
    start = time.perf_counter()
    done = subprocess.run(command, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        last = (done.stderr.strip().splitlines() or ["no output"])[-1]
        raise _RunFailed(f"soccer-sim {' '.join(cli_args)} exited with status {done.returncode}: {last}")
    return seconds, done.stderr


def _compile_seconds(stderr: str) -> list[float]:
    """The seconds in the warm-up's "compiled N kernels in S s ..." line, if it printed one."""
    import re

    match = re.search(r"compiled \d+ kernels in ([0-9.]+) s", stderr)
    return [float(match.group(1))] if match else []


def _load() -> str:
    import os

    try:
        return f"{os.getloadavg()[0]:.2f}"
    except OSError:
        return "unknown"
