"""``soccer-sim bench replay``: what recording a rerun replay adds to a match, and the file size.

Each seed's match is played twice in one process, without and with a
:class:`~soccer_sim.replay.RerunRecorder` (the order alternating from seed to seed, after a
warm-up match that loads the compiled kernels); the table gives the median wall times, the
median overhead of recording and the replay files' sizes.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.limits import ranged

    parser.add_argument("--home", default="mmdr", help="home team (default: %(default)s)")
    parser.add_argument("--away", default="mmd+msd2", help="away team (default: %(default)s)")
    parser.add_argument("--matches", type=ranged("matches"), default=3, help="seeds played (default: %(default)s)")
    parser.add_argument("--cycles", type=ranged("cycles"), default=None, help="cycles per match (default: a full match)")


def run(args: argparse.Namespace) -> int:
    from experiments.commands.errors import fail
    from experiments.configuration import match_config
    from experiments.reporting import Table
    from soccer_sim import ConfigError, TeamError, TeamNotFoundError, run_match
    from soccer_sim.replay import RerunRecorder

    config = match_config(args.cycles)
    plain, recorded, sizes = [], [], []
    with tempfile.TemporaryDirectory() as scratch:
        try:
            # Warm-up: loads the compiled kernels and rerun, once per process in real use too.
            run_match(args.home, args.away, seed=0, config=match_config(50),
                      recorders=[RerunRecorder(Path(scratch) / "warm-up.rrd")])
        except (TeamNotFoundError, TeamError, ConfigError) as exc:
            return fail(str(exc))
        for seed in range(args.matches):
            path = Path(scratch) / f"{seed}.rrd"
            order = (False, True) if seed % 2 == 0 else (True, False)
            for record in order:
                start = time.perf_counter()
                run_match(args.home, args.away, seed=seed, config=config,
                          recorders=[RerunRecorder(path)] if record else [])
                (recorded if record else plain).append(time.perf_counter() - start)
            sizes.append(path.stat().st_size / 1e6)
    overheads = [r / p - 1.0 for r, p in zip(recorded, plain)]
    table = Table(f"Recording {args.home} vs {args.away}: {args.matches} matches",
                  ["median s, plain", "median s, recorded", "median overhead", "largest overhead", "median file MB",
                   "largest file MB"], labels=0)
    table.rows.append([f"{statistics.median(plain):.3f}", f"{statistics.median(recorded):.3f}",
                       f"{100 * statistics.median(overheads):.1f} %", f"{100 * max(overheads):.1f} %",
                       f"{statistics.median(sizes):.2f}", f"{max(sizes):.2f}"])
    table.print()
    return 0
