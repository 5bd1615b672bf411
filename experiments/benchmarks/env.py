"""``soccer-sim bench env``: steps per second of the PettingZoo environment, against the same
play as a plain match.

Both sides are played by the same cheap policy (actions drawn once from a seeded generator and
replayed), so the comparison measures what the environment adds: the environment's loop calls
the policy for all 22 agents and steps; the plain match plays two
:class:`~soccer_sim.env.PolicyTeam` teams with that policy (the same observations and actions,
built inside the match loop).

A second table gives the throughput of the ways to step many agents: the single environment
(its dict API), its batched arrays (``step_arrays``, where the environment has it), and the
vector environment (:mod:`soccer_sim.env.vector`) of ``--envs`` matches in this process and on
``--processes`` worker processes, in environment steps (match cycles, summed over the matches)
and agent-steps (steps times the 22 agents) per second of wall time. The dict API builds every
agent's infos each step; ``step_arrays`` and the vector environment (``infos=False``) do not.
Worker start-up and the resets are left out of the timing; the first run of each is a warm-up.
"""

from __future__ import annotations

import argparse
import statistics
import time



def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.limits import ranged

    parser.add_argument("--cycles", type=ranged("cycles"), default=3000, help="cycles per run (default: %(default)s)")
    parser.add_argument("--repeats", type=ranged("repeats"), default=3, help="runs of each (default: %(default)s)")
    parser.add_argument("--action-mode", choices=("low_level", "high_level"), default="low_level",
                        help="also time the high-level actions (default: %(default)s)")
    parser.add_argument("--envs", type=ranged("envs"), default=4,
                        help="matches in the vector environment (default: %(default)s)")
    parser.add_argument("--processes", type=ranged("processes"), default=2,
                        help="worker processes of the subprocess vector environment (default: %(default)s)")


class _ReplayedPolicy:
    """Actions from a fixed table, in turn: costs next to nothing."""

    def __init__(self, table: np.ndarray) -> None:
        self.table, self.k = table, 0

    def act(self, observation: np.ndarray) -> np.ndarray:
        self.k = (self.k + 1) % len(self.table)
        return self.table[self.k]


def _action_table(action_mode: str) -> np.ndarray:
    import numpy as np

    rng = np.random.default_rng(0)
    if action_mode == "high_level":
        return rng.integers(0, 13, size=(997,))
    return rng.uniform(-1, 1, size=(997, 5)).astype(np.float32)


def _dict_run(args: argparse.Namespace, table: np.ndarray, seed: int) -> float:
    """Seconds per step of one run of the single environment's dict API."""
    from soccer_sim.env import parallel_env

    environment = parallel_env(controlled="both", max_cycles=args.cycles, action_mode=args.action_mode)
    policy = _ReplayedPolicy(table)
    observations, _ = environment.reset(seed=seed)
    start, steps = time.perf_counter(), 0
    while environment.agents:
        observations, *_ = environment.step({agent: policy.act(observations[agent]) for agent in environment.agents})
        steps += 1
    return (time.perf_counter() - start) / steps


def _arrays_run(args: argparse.Namespace, table: np.ndarray, seed: int) -> float | None:
    """Seconds per step of one run of the batched ``step_arrays`` (None where the environment lacks it)."""
    from soccer_sim.env import parallel_env
    import numpy as np

    environment = parallel_env(controlled="both", max_cycles=args.cycles, action_mode=args.action_mode)
    if not hasattr(environment, "step_arrays"):
        return None
    environment.reset_arrays(seed)
    agents = len(environment.possible_agents)
    rows = [table[(np.arange(agents) + k) % len(table)] for k in range(97)]
    start, steps = time.perf_counter(), 0
    while environment.agents:
        environment.step_arrays(rows[steps % len(rows)])
        steps += 1
    return (time.perf_counter() - start) / steps


def _vector_run(args: argparse.Namespace, table: np.ndarray, vector, seed: int) -> float:
    """Seconds per match step of one run of ``--cycles`` steps of a vector environment."""
    import numpy as np

    shape = (vector.num_envs, vector.num_agents)
    rows = [table[(np.arange(np.prod(shape)) + k) % len(table)].reshape(*shape, *table.shape[1:]) for k in range(97)]
    vector.reset(seed=seed)
    start = time.perf_counter()
    for step in range(args.cycles):
        vector.step(rows[step % len(rows)])
    return (time.perf_counter() - start) / (args.cycles * vector.num_envs)


def _throughput(args: argparse.Namespace, table: np.ndarray) -> None:
    """The throughput table; the ways run in turn within each repeat, so that a load on the
    machine weighs on all of them alike."""
    from experiments.reporting import Table
    from soccer_sim.env.vector import vector_env

    agents = 22
    workers = min(args.processes, args.envs)
    options = {"infos": False, "controlled": "both", "max_cycles": args.cycles + 1, "action_mode": args.action_mode}
    with vector_env(args.envs, **options) as local, vector_env(args.envs, processes=workers, **options) as remote:
        ways = [("single environment (dict API)", 1, lambda seed: _dict_run(args, table, seed)),
                ("single environment, step_arrays", 1, lambda seed: _arrays_run(args, table, seed)),
                (f"vector environment, {args.envs} matches in process", args.envs,
                 lambda seed: _vector_run(args, table, local, seed)),
                (f"vector environment, {args.envs} matches on {workers} process{'es' * (workers != 1)}", args.envs,
                 lambda seed: _vector_run(args, table, remote, seed))]
        times: list[list[float | None]] = [[] for _ in ways]
        for repeat in range(args.repeats + 1):  # the first is a warm-up
            for k, (_, _, timed) in enumerate(ways):
                seconds = timed(repeat)
                if repeat:
                    times[k].append(seconds)
    medians = [None if None in t else statistics.median(t) for t in times]
    out = Table(f"Throughput, 22 agents per match, {args.action_mode} actions ({args.repeats} runs of "
                f"{args.cycles} cycles per match, in turn; medians, wall time)",
                ["how", "matches", "steps / s", "agent-steps / s", "x single"], labels=1)
    for (label, matches, _), step in zip(ways, medians):
        if step is None:
            out.rows.append([label, str(matches), "-", "-", "-"])
            continue
        out.rows.append([label, str(matches), f"{1.0 / step:,.0f}", f"{agents / step:,.0f}",
                         f"{medians[0] / step:.2f}"])
    if medians[1] is None:
        out.caption = "step_arrays: not offered by this environment"
    out.print()


def run(args: argparse.Namespace) -> int:
    from experiments.reporting import Table
    from soccer_sim import MatchConfig, run_match
    from soccer_sim.env import PolicyTeam, parallel_env
    import numpy as np

    table = _action_table(args.action_mode)
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
    _throughput(args, table)
    return 0
