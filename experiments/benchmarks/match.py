"""``soccer-sim bench match``: wall time of whole matches between two teams.

Reports the median and fastest time per match and the microseconds per cycle (everything
included: both teams, views, commands, motion rules, pymunk, referee, statistics), after
the kernel warm-up (:mod:`experiments.warmup`: kernels missing from the cache are compiled
by helper processes, then loaded here) and one warm-up match that pays for imports and for
anything else loaded on first use. ``--profile`` adds a cProfile top list of one more
match.
"""

from __future__ import annotations

import argparse

from experiments.benchmarks import add_match_arguments
from experiments.limits import ranged


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_match_arguments(parser, matches=5)
    parser.add_argument("--observation", choices=("full", "partial"), default="full",
                        help="full (default) or partial observation: each player's own view and messages")
    parser.add_argument("--profile", action="store_true", help="also print a cProfile top list of one match")
    parser.add_argument("--top", type=ranged("top"), default=25, help="entries in the profile top list (default: 25)")


def run(args: argparse.Namespace) -> int:
    import cProfile
    import io
    import pstats
    import statistics
    import time

    from experiments.commands.errors import fail
    from experiments.reporting import Table
    from experiments.warmup import load_kernels, warm_kernels
    from soccer_sim import ConfigError, MatchConfig, TeamError, TeamNotFoundError, run_match

    from soccer_sim.perception.config import ObservationConfig

    observation = ObservationConfig(args.observation)
    config = MatchConfig(max_cycles=args.cycles, observation=observation)
    # Kernels missing from the cache are compiled by other processes and this one loads them,
    # as a tournament's workers do (a process that compiled them runs some 5 % slower).
    load_kernels(warm_kernels((args.home, args.away), observation=args.observation, here=False).kernels)
    try:  # the warm-up match also checks the teams and the seed
        run_match(args.home, args.away, seed=args.seed, config=MatchConfig(max_cycles=200, observation=observation))
    except (TeamNotFoundError, TeamError, ConfigError, ValueError) as exc:
        return fail(str(exc))
    times, cycles, goals = [], [], []
    for i in range(args.matches):
        start = time.perf_counter()
        result = run_match(args.home, args.away, seed=args.seed + i, config=config)
        times.append(time.perf_counter() - start)
        cycles.append(result.cycles)
        goals.append(sum(result.score))
    median = statistics.median(times)
    per_cycle = [t / c * 1e6 for t, c in zip(times, cycles)]
    table = Table(f"{args.home} vs {args.away}: {args.matches} matches of {cycles[0]} cycles, "
                  f"{args.observation} observation",
                  ["median s / match", "min s / match", "median µs / cycle", "min µs / cycle", "goals / match"],
                  labels=0)
    table.rows.append([f"{median:.3f}", f"{min(times):.3f}", f"{statistics.median(per_cycle):.1f}",
                       f"{min(per_cycle):.1f}", f"{statistics.mean(goals):.1f}"])
    table.print()
    if args.profile:
        profiler = cProfile.Profile()
        profiler.enable()
        run_match(args.home, args.away, seed=args.seed, config=config)
        profiler.disable()
        out = io.StringIO()
        pstats.Stats(profiler, stream=out).sort_stats("tottime").print_stats(args.top)
        print(out.getvalue())
    return 0
