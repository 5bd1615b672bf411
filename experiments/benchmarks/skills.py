"""``soccer-sim bench skills``: microseconds per call of every soccer skill for a team of 11.

The situations and the timing are :func:`agents.skills.timing.time_skills`'s: reproducible
random mid-game views, each call timed after a warm-up call, the median over views of the
best of three runs.
"""

from __future__ import annotations

import argparse

from experiments.limits import ranged


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--views", type=ranged("views"), default=20, help="random situations (default: 20)")
    parser.add_argument("--number", type=ranged("number"), default=200, help="calls per timing run (default: 200)")


def run(args: argparse.Namespace) -> int:
    from agents.skills.timing import time_skills
    from experiments.reporting import Table

    table = Table(f"skills: µs per call, 11 players, median over {args.views} situations", ["call", "µs"])
    for name, micro in time_skills(args.views, number=args.number).items():
        table.rows.append([name, f"{micro:.1f}"])
    table.print()
    return 0
