"""``soccer-sim bench soccer``: what the play between two teams looks like, in numbers.

Plays ``--matches`` matches on consecutive seeds (sides as given) and prints the mean per
match, with its standard error, of: total goals, shots, shots that ended on a body
(:mod:`soccer_sim.analysis.shots`), kicks, passes, tackles, fouls, free kicks, offside calls,
teammate contacts, and the mean number of players (of both teams) within 2 m of the ball
per play-on cycle (a measure of scrums: well-spaced teams keep it near 1-2). These are the
figures by which the simulator's fidelity and the built-in teams are judged; speed is
``bench match``'s job.
"""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

import numpy as np

from experiments.benchmarks import add_match_arguments

if TYPE_CHECKING:
    from soccer_sim.match import Match

CROWD_RADIUS = 2.0
"""Players whose centre is within this distance of the ball's centre count as near it (m)."""


class NearBallRecorder:
    """Counts, over the play-on cycles, the players within :data:`CROWD_RADIUS` of the ball."""

    def __init__(self) -> None:
        self.cycles = 0
        self.near = 0

    def on_start(self, match: Match) -> None:
        self.cycles = 0
        self.near = 0

    def on_cycle(self, match: Match) -> None:
        from soccer_sim.state import PlayMode

        state = match.state
        if state.play_mode != PlayMode.PLAY_ON:
            return
        offsets = state.pos - state.ball
        self.cycles += 1
        self.near += int(np.count_nonzero(np.einsum("ij,ij->i", offsets, offsets) <= CROWD_RADIUS ** 2))

    def on_end(self, match: Match) -> None:
        pass

    @property
    def mean(self) -> float:
        """Mean number of players near the ball per play-on cycle."""
        return self.near / self.cycles if self.cycles else 0.0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    add_match_arguments(parser, matches=10)


def measure(home: str, away: str, matches: int, seed: int = 0, cycles: int | None = None) -> dict[str, np.ndarray]:
    """Play the matches and return one array per figure (one value per match)."""
    from experiments.match_report import match_report
    from soccer_sim import MatchConfig, run_match
    from soccer_sim.analysis.shots import shot_endings
    from soccer_sim.state import EventKind

    config = MatchConfig(max_cycles=cycles)
    rows: dict[str, list[float]] = {name: [] for name in (
        "goals", "shots", "shots ending on a body", "kicks", "passes", "tackles", "fouls", "free kicks",
        "offside calls", "teammate contacts", "players within 2 m of the ball")}
    for i in range(matches):
        near = NearBallRecorder()
        result = run_match(home, away, seed=seed + i, config=config, recorders=[near])
        home_stats, away_stats = result.statistics
        rows["goals"].append(sum(result.score))
        rows["shots"].append(home_stats.shots + away_stats.shots)
        rows["shots ending on a body"].append(sum(ending == "body" for _, ending in shot_endings(result.events)))
        rows["kicks"].append(home_stats.kicks + away_stats.kicks)
        rows["passes"].append(home_stats.passes + away_stats.passes)
        rows["tackles"].append(home_stats.tackles + away_stats.tackles)
        rows["fouls"].append(home_stats.fouls + away_stats.fouls)
        rows["free kicks"].append(sum(side["free_kick"] for side in match_report(result).set_plays))
        rows["offside calls"].append(len(result.events.of_kind(EventKind.OFFSIDE)))
        rows["teammate contacts"].append(home_stats.teammate_contacts + away_stats.teammate_contacts)
        rows["players within 2 m of the ball"].append(near.mean)
    return {name: np.asarray(values, dtype=float) for name, values in rows.items()}


def run(args: argparse.Namespace) -> int:
    from experiments.commands.errors import fail
    from experiments.reporting import Table
    from soccer_sim import ConfigError, TeamError, TeamNotFoundError

    try:
        figures = measure(args.home, args.away, args.matches, args.seed, args.cycles)
    except (TeamNotFoundError, TeamError, ConfigError, ValueError) as exc:
        return fail(str(exc))
    table = Table(f"{args.home} vs {args.away}: {args.matches} matches (seeds {args.seed}..{args.seed + args.matches - 1})",
                  ["per match (both teams)", "mean", "std. error"])
    for name, values in figures.items():
        error = values.std(ddof=1) / np.sqrt(values.size) if values.size > 1 else float("nan")
        table.rows.append([name, f"{values.mean():.2f}", f"{error:.2f}"])
    table.print()
    return 0
