"""``soccer-sim experiment assigners``: does positioning matter, and what do the role assigners do?

Three parts, each a set of matches on paired seeds: seed ``s`` is played twice, once with each
team at home, so that both sides of the pitch and both halves' noise are shared.

* **league**: every pairing of the built-in teams given with ``--league`` (default: the
  assigner variants and the reference opponents): goals, shots and passes per match, every
  kind of set play, and the longest stretch of play on with the ball barely moving (within
  3 m) -- is it soccer?
* **chaser**: each of those teams against ``chaser`` (everybody runs at the ball).
* **baselines**: ``mmd+msd2`` against ``random`` and against ``statues`` (outfield players who
  never leave their kick-off spots): the mean goal difference with its standard error and
  95% confidence interval -- does positioning matter?
* **claims**: each assigner of ``--assigners`` against the same opponent (``--opponent``):
  role switches per minute, teammate contacts and distances to the role targets per match --
  SCRAM's claims in our game (MMDR switches least, SCRAM teams collide least).

Matches run in a process pool (``--workers``, default: every core).
"""

from __future__ import annotations

import argparse
import itertools
import math
import os
import time
from collections import Counter
from dataclasses import dataclass, field

import numpy as np

from experiments.commands.play import positive_int

STALL_RADIUS = 3.0
"""The ball 'barely moves' while it stays within this distance of where it was (m)."""

DEFAULT_LEAGUE = ("mmdr", "mmd+msd2", "static", "greedy", "bidding", "counter-442", "press-433", "possession")
DEFAULT_CLAIMS = ("mmdr", "mmd+msd2", "greedy", "greedy-offense", "static", "bidding")


@dataclass
class MatchSummary:
    """What a study keeps of one match (home first)."""

    home: str
    away: str
    seed: int
    score: tuple[int, int]
    shots: tuple[int, int]
    passes: tuple[int, int]
    contacts: tuple[int, int]
    reported: tuple[dict[str, float], dict[str, float]]
    set_plays: dict[str, int] = field(default_factory=dict)
    longest_stall: int = 0
    """Longest run of play-on cycles with the ball within STALL_RADIUS of one point."""
    seconds: float = 0.0


class _StallWatch:
    """Recorder: the longest stretch of play on with the ball barely moving."""

    def on_start(self, match) -> None:
        self.anchor: np.ndarray | None = None
        self.since = 0
        self.longest = 0

    def on_cycle(self, match) -> None:
        from soccer_sim.state import PlayMode

        state = match.state
        if state.play_mode != PlayMode.PLAY_ON:
            self.anchor = None
            return
        if self.anchor is None or math.dist(state.ball, self.anchor) > STALL_RADIUS:
            self.anchor, self.since = state.ball.copy(), state.cycle
        self.longest = max(self.longest, state.cycle - self.since)

    def on_end(self, match) -> None:
        pass


def play_one(job: tuple[str, str, int, int | None]) -> MatchSummary:
    """Play one match (``home``, ``away``, ``seed``, cycles or None) and summarise it."""
    from soccer_sim import EventKind, MatchConfig, PlayMode, run_match

    home, away, seed, cycles = job
    watch = _StallWatch()
    start = time.perf_counter()
    result = run_match(home, away, seed=seed, config=MatchConfig(max_cycles=cycles), recorders=[watch])
    events = result.events.as_arrays()
    modes = events["detail"][events["kind"] == EventKind.SET_PLAY]
    set_plays = Counter(PlayMode(int(m)).name.lower() for m in modes if m not in (PlayMode.PLAY_ON,
                                                                                   PlayMode.TIME_OVER))
    h, a = result.statistics
    return MatchSummary(home, away, seed, result.score, (h.shots, a.shots), (h.passes, a.passes),
                        (h.teammate_contacts, a.teammate_contacts), (dict(h.reported), dict(a.reported)),
                        dict(set_plays), watch.longest, time.perf_counter() - start)


def paired_jobs(team: str, opponent: str, games: int, seed: int, cycles: int | None) -> list[tuple]:
    """``games`` matches (rounded up to even): each seed with ``team`` at home and away."""
    return [job for s in range(seed, seed + (games + 1) // 2)
            for job in ((team, opponent, s, cycles), (opponent, team, s, cycles))]


def goal_differences(summaries: list[MatchSummary], team: str) -> np.ndarray:
    """Goal difference of ``team`` in each of its matches."""
    return np.array([(s.score[0] - s.score[1]) * (1 if s.home == team else -1) for s in summaries
                     if team in (s.home, s.away)], dtype=float)


def mean_interval(values: np.ndarray, level: float = 0.95) -> tuple[float, float, float, float]:
    """(mean, standard error, low, high) of ``values``, the interval from Student's t."""
    from scipy import stats

    n = values.size
    mean = float(values.mean()) if n else math.nan
    if n < 2:
        return mean, math.nan, math.nan, math.nan
    se = float(values.std(ddof=1) / math.sqrt(n))
    half = float(stats.t.ppf(0.5 + level / 2, n - 1)) * se
    return mean, se, mean - half, mean + half


def team_figure(summaries: list[MatchSummary], team: str, figure: str) -> np.ndarray:
    """Per match, one of ``team``'s figures: a reported one or ``contacts``."""
    values = []
    for s in summaries:
        for side, name in enumerate((s.home, s.away)):
            if name == team:
                values.append(s.contacts[side] if figure == "contacts" else s.reported[side].get(figure, math.nan))
    return np.array(values, dtype=float)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--part", choices=("all", "league", "chaser", "baselines", "claims"), default="all")
    parser.add_argument("--games", type=positive_int, default=100,
                        help="matches per pairing, sides swapped on paired seeds (default: 100)")
    parser.add_argument("--league", default=",".join(DEFAULT_LEAGUE), help="teams of the league part")
    parser.add_argument("--league-games", type=positive_int, default=8,
                        help="matches per pairing in the league part (default: 8)")
    parser.add_argument("--assigners", default=",".join(DEFAULT_CLAIMS), help="teams of the claims part")
    parser.add_argument("--opponent", default="press-433", help="opponent of the claims part")
    parser.add_argument("--cycles", type=positive_int, default=None, help="cycles per match (default: full)")
    parser.add_argument("--seed", type=int, default=0, help="first seed")
    parser.add_argument("--workers", type=positive_int, default=os.cpu_count() or 1,
                        help="processes (default: every core)")


class _Runner:
    """Plays jobs in one pool of ``workers`` processes kept for the whole study (or inline)."""

    def __init__(self, workers: int) -> None:
        self.pool = None
        if workers > 1:
            from multiprocessing import get_context

            self.pool = get_context("spawn").Pool(workers)

    def __call__(self, jobs: list[tuple]) -> list[MatchSummary]:
        if self.pool is None:
            return [play_one(job) for job in jobs]
        return self.pool.map(play_one, jobs, chunksize=1)

    def close(self) -> None:
        if self.pool is not None:
            self.pool.close()
            self.pool.join()


def _table(title: str, header: list[str], rows: list[list[str]]) -> None:
    from experiments.reporting import Table

    Table(title, header, rows).print()


def _teams(text: str, option: str, minimum: int) -> list[str]:
    """The comma-separated teams of ``option``, each registered or an importable path; a
    RunInputError naming the option otherwise."""
    from experiments.runner.options import team_list

    return team_list(text, option, minimum=minimum)


def run(args: argparse.Namespace) -> int:
    from experiments.commands.errors import FAILED, fail
    from experiments.runner.options import RunInputError
    from soccer_sim import ConfigError, TeamError

    parts = ("league", "chaser", "baselines", "claims") if args.part == "all" else (args.part,)
    try:
        if args.seed < 0:
            raise RunInputError(f"--seed must be a non-negative integer, got {args.seed}")
        league = _teams(args.league, "--league", 2 if "league" in parts else 0)
        claims = _teams(args.assigners, "--assigners", 1 if "claims" in parts else 0)
        opponent = _teams(args.opponent, "--opponent", 1)
        if len(opponent) != 1:
            raise RunInputError(f"--opponent: give one team, got {args.opponent!r}")
        args.opponent = opponent[0]
        if "chaser" in parts and not (league or claims):
            raise RunInputError("the chaser part needs a team in --league or --assigners")
    except RunInputError as exc:
        return fail(str(exc))
    start = time.perf_counter()
    runner = _Runner(args.workers)
    try:
        _study(args, league, claims, runner)
    except (TeamError, ConfigError) as exc:  # a team that broke during a match
        return fail(str(exc), FAILED)
    finally:
        runner.close()
    print(f"wall time {time.perf_counter() - start:.0f} s")
    return 0


def _study(args: argparse.Namespace, league: list[str], claims: list[str], runner: _Runner) -> None:
    _run = runner
    if args.part in ("all", "league"):
        jobs = [job for a, b in itertools.combinations(league, 2)
                for job in paired_jobs(a, b, args.league_games, args.seed, args.cycles)]
        done = _run(jobs)
        goals = np.array([sum(s.score) for s in done], float)
        shots = np.array([sum(s.shots) for s in done], float)
        passes = np.array([sum(s.passes) for s in done], float)
        stalls = np.array([s.longest_stall for s in done], float)
        kinds = Counter()
        for s in done:
            kinds.update({k: 1 for k in s.set_plays})
        _table(f"league: {len(done)} matches between {len(league)} teams", ["per match (both teams)", "mean", "std. error", "max"],
               [[name, f"{v.mean():.2f}", f"{v.std(ddof=1) / math.sqrt(v.size):.2f}", f"{v.max():.0f}"]
                for name, v in (("goals", goals), ("shots", shots), ("passes received", passes),
                                ("longest stall (cycles)", stalls))])
        print("matches with each kind of set play: " + ", ".join(f"{k} {v}" for k, v in sorted(kinds.items())))
        worst = max(done, key=lambda s: s.longest_stall)
        print(f"longest stall: {worst.longest_stall} cycles, {worst.home} v {worst.away}, seed {worst.seed}")
    if args.part in ("all", "chaser"):
        rows = []
        for team in dict.fromkeys([*league, *claims]):
            done = _run(paired_jobs(team, "chaser", args.league_games, args.seed, args.cycles))
            gd = goal_differences(done, team)
            rows.append([team, str(gd.size), f"{gd.mean():+.2f}", f"{gd.min():+.0f}"])
        _table("every team against chaser", ["team", "games", "mean GD", "worst GD"], rows)
    if args.part in ("all", "baselines"):
        rows = []
        for opponent in ("random", "statues"):
            done = _run(paired_jobs("mmd+msd2", opponent, args.games, args.seed, args.cycles))
            gd = goal_differences(done, "mmd+msd2")
            mean, se, low, high = mean_interval(gd)
            wins, draws = int((gd > 0).sum()), int((gd == 0).sum())
            rows.append([f"mmd+msd2 vs {opponent}", str(gd.size), f"{mean:+.2f}", f"{se:.2f}", f"[{low:+.2f}, {high:+.2f}]",
                         f"{wins}/{draws}/{gd.size - wins - draws}"])
        _table("baselines: goal difference of mmd+msd2", ["pairing", "games", "mean GD", "SE", "95% CI", "W/D/L"], rows)
    if args.part in ("all", "claims"):
        rows = []
        for team in claims:
            done = _run(paired_jobs(team, args.opponent, args.games, args.seed, args.cycles))
            gd = goal_differences(done, team)
            cells = [team, f"{gd.mean():+.2f} ({gd.std(ddof=1) / math.sqrt(gd.size):.2f})"]
            for figure in ("role_switches_per_minute", "contacts", "target_distance_mean", "target_distance_max"):
                values = team_figure(done, team, figure)
                cells.append(f"{values.mean():.2f} ({values.std(ddof=1) / math.sqrt(values.size):.2f})")
            rows.append(cells)
        _table(f"claims: each assigner against {args.opponent}, {args.games} games, mean (SE) per match",
               ["team", "GD", "role switches / min", "teammate contacts", "mean distance to target (m)",
                "largest distance to target (m)"], rows)
