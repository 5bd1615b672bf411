"""``soccer-sim bench env``: steps per second of the PettingZoo environment, against the same
play as a plain match.

Both sides are played by the same cheap policy (actions drawn once from a seeded generator and
replayed), so the comparison measures what the environment adds: the environment's loop calls
the policy for all 22 agents and steps; the plain match plays two
:class:`~soccer_sim.env.PolicyTeam` teams with that policy (the same observations and actions,
built inside the match loop).
"""

from __future__ import annotations

import argparse
import statistics
import time

import numpy as np


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.arguments import positive_int

    parser.add_argument("--cycles", type=positive_int, default=3000, help="cycles per run (default: %(default)s)")
    parser.add_argument("--repeats", type=positive_int, default=3, help="runs of each (default: %(default)s)")
    parser.add_argument("--action-mode", choices=("low_level", "high_level"), default="low_level",
                        help="also time the high-level actions (default: %(default)s)")


class _ReplayedPolicy:
    """Actions from a fixed table, in turn: costs next to nothing."""

    def __init__(self, table: np.ndarray) -> None:
        self.table, self.k = table, 0

    def act(self, observation: np.ndarray) -> np.ndarray:
        self.k = (self.k + 1) % len(self.table)
        return self.table[self.k]


def run(args: argparse.Namespace) -> int:
    from experiments.reporting import Table
    from soccer_sim import MatchConfig, run_match
    from soccer_sim.env import PolicyTeam, parallel_env

    rng = np.random.default_rng(0)
    if args.action_mode == "high_level":
        table = rng.integers(0, 13, size=(997,))
    else:
        table = rng.uniform(-1, 1, size=(997, 5)).astype(np.float32)
    config = MatchConfig(max_cycles=args.cycles)
    env_times, plain_times = [], []
    for repeat in range(args.repeats + 1):  # the first of each is a warm-up
        environment = parallel_env(controlled="both", max_cycles=args.cycles, config=config,
                                   action_mode=args.action_mode)
        policy = _ReplayedPolicy(table)
        observations, _ = environment.reset(seed=repeat)
        start = time.perf_counter()
        steps = 0
        while environment.agents:
            actions = {agent: policy.act(observations[agent]) for agent in environment.agents}
            observations, *_ = environment.step(actions)
            steps += 1
        elapsed = time.perf_counter() - start
        if args.action_mode == "low_level":
            start = time.perf_counter()
            run_match(PolicyTeam(_ReplayedPolicy(table)), PolicyTeam(_ReplayedPolicy(table)), seed=repeat,
                      config=config)
            plain = time.perf_counter() - start
        else:
            plain = float("nan")
        if repeat:
            env_times.append(elapsed / steps)
            plain_times.append(plain / args.cycles)
    env_step, plain_cycle = statistics.median(env_times), statistics.median(plain_times)
    table_out = Table(f"PettingZoo environment, 22 agents, {args.action_mode} actions "
                      f"({args.repeats} runs of {args.cycles} cycles, medians)",
                      ["µs / env step", "env steps / s", "µs / plain match cycle", "env step / plain cycle"], labels=0)
    table_out.rows.append([f"{env_step * 1e6:.0f}", f"{1.0 / env_step:.0f}",
                           "-" if np.isnan(plain_cycle) else f"{plain_cycle * 1e6:.0f}",
                           "-" if np.isnan(plain_cycle) else f"{env_step / plain_cycle:.2f}"])
    table_out.print()
    return 0
