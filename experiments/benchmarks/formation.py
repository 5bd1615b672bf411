"""``soccer-sim bench formation``: speed of formation queries.

For every built-in formation set and situation it measures

* the median time of one ``Formation.positions(ball)`` call, for balls inside
  the field and for balls out of play (beyond the touchlines and goal lines,
  where the ball is projected onto the samples' hull), each median taken over
  batches of calls on distinct random balls; and
* the time of one vectorised ``Formation.positions_many`` call on 100,000
  random balls spread over the field plus a 5 m margin (so about a fifth of
  them are outside the samples' hull).
"""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.limits import ranged

    parser.add_argument("--queries", type=ranged("queries"), default=100_000, help="balls per vectorised call (default 100000)")
    parser.add_argument("--single", type=ranged("single"), default=20_000, help="single calls timed per case (default 20000)")
    parser.add_argument("--batch", type=ranged("batch"), default=200, help="calls per timed batch (default 200)")
    parser.add_argument("--repeats", type=ranged("repeats"), default=5, help="vectorised calls timed; the best is reported")
    parser.add_argument("--seed", type=ranged("seed"), default=0, help="seed of the random ball positions")
    parser.add_argument(
        "--set", dest="sets", action="append", metavar="NAME", help="only this built-in set (repeatable; default: all)"
    )


def run(args: argparse.Namespace) -> int:
    import time

    import numpy as np

    import formations
    from experiments.commands.errors import fail
    from experiments.reporting import Table
    from soccer_sim.config import STANDARD_FIELD

    names = args.sets or formations.builtin_names()
    unknown = sorted(set(names) - set(formations.builtin_names()))
    if unknown:
        return fail(f"--set: unknown formation set(s) {', '.join(unknown)}; built-in: "
                    f"{', '.join(formations.builtin_names())}")
    if args.batch > args.single:
        return fail(f"--batch ({args.batch}) must not exceed --single ({args.single})")
    rng = np.random.default_rng(args.seed)
    hl, hw = STANDARD_FIELD.half_length, STANDARD_FIELD.half_width
    inside = np.column_stack((rng.uniform(-hl, hl, args.single), rng.uniform(-hw, hw, args.single)))
    outside = _out_of_play(rng, args.single, hl, hw)
    margin = 5.0
    many = np.column_stack(
        (rng.uniform(-hl - margin, hl + margin, args.queries), rng.uniform(-hw - margin, hw + margin, args.queries))
    )
    inside_list = [tuple(p) for p in inside.tolist()]
    outside_list = [tuple(p) for p in outside.tolist()]

    table = Table(
        "Formation queries",
        ["set", "situation", "samples", "triangles", "1 ball in (µs)", "1 ball out (µs)",
         f"{args.queries:,} balls (s)", "µs/ball"],
        labels=2,
        caption=f"1 ball: median over batches of {args.batch} calls, in field / out of play; "
        f"{args.queries:,} balls: one vectorised call, best of {args.repeats}",
    )
    worst_single = 0.0
    worst_many = 0.0
    for name in names:
        team = formations.load_builtin(name)
        for situation, formation in team.own_formations().items():
            single_in = _median_single(formation.positions, inside_list, args.batch)
            single_out = _median_single(formation.positions, outside_list, args.batch)
            best = float("inf")
            for _ in range(max(1, args.repeats)):
                start = time.perf_counter()
                formation.positions_many(many)
                best = min(best, time.perf_counter() - start)
            worst_single = max(worst_single, single_in, single_out)
            worst_many = max(worst_many, best)
            table.rows.append([
                name,
                situation.value,
                str(formation.n_samples),
                str(len(formation.triangles)),
                f"{single_in:.2f}",
                f"{single_out:.2f}",
                f"{best:.4f}",
                f"{best / len(many) * 1e6:.3f}",
            ])
    table.print()
    print(
        f"slowest single-query median: {worst_single:.2f} µs (target < 20 µs); "
        f"slowest vectorised {args.queries:,}-ball call: {worst_many:.4f} s (target < 0.2 s for 100,000)"
    )
    return 0


def _median_single(query, balls: list[tuple[float, float]], batch: int) -> float:
    """Median over batches of the mean time of one call, microseconds."""
    import statistics
    import time

    for ball in balls[:batch]:  # warm-up
        query(ball)
    times = []
    for start in range(0, len(balls) - batch + 1, batch):
        chunk = balls[start : start + batch]
        begin = time.perf_counter()
        for ball in chunk:
            query(ball)
        times.append((time.perf_counter() - begin) / len(chunk))
    return statistics.median(times) * 1e6


def _out_of_play(rng, count: int, hl: float, hw: float):
    """Balls up to 5 m beyond the touchlines or goal lines."""
    import numpy as np

    x = rng.uniform(-hl - 5.0, hl + 5.0, count)
    y = rng.uniform(-hw - 5.0, hw + 5.0, count)
    beyond_goal_line = rng.random(count) < 0.5
    x = np.where(beyond_goal_line, np.sign(x) * rng.uniform(hl, hl + 5.0, count), x)
    y = np.where(beyond_goal_line, y, np.sign(y) * rng.uniform(hw, hw + 5.0, count))
    return np.column_stack((x, y))
