"""``soccer-sim bench roles``: microseconds per call of every role assigner.

The situations and the timing are :func:`agents.roles.timing.time_assigners`'s: random players
and role targets on the field, each call timed after a warm-up call, the median over
situations of the best run.
"""

from __future__ import annotations

import argparse

from experiments.limits import ranged


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--players", type=ranged("players"), default=10, help="outfield players (default: 10)")
    parser.add_argument("--situations", type=ranged("situations"), default=20, help="random situations (default: 20)")
    parser.add_argument("--number", type=ranged("number"), default=500, help="calls per timing run (default: 500)")


def run(args: argparse.Namespace) -> int:
    from agents.roles.timing import time_assigners
    from experiments.reporting import Table

    columns = ("assign", "steer", "assign+steer")
    table = Table(f"role assigners: µs per call, {args.players} players, median over {args.situations} situations",
                  ["assigner", *columns])
    for name, times in time_assigners(args.players, args.situations, number=args.number).items():
        table.rows.append([name, *(f"{times[c]:.1f}" if c in times else "" for c in columns)])
    table.print()
    return 0
