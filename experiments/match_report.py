"""What a person wants to know about one match, read from its event log.

The half-time and final score, the goals in order (cycle, scoring team, the
scorer's shirt number), how many set plays of each kind each team was given,
the offside calls against each team and the dropped balls. Shirt numbers are
1-based (the event log's player indices are 0-based: shirt = index + 1).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from soccer_sim import EventKind, MatchResult, PlayMode
from soccer_sim.state import NO_PLAYER, SET_PLAYS

SIDES = ("home", "away")
"""Team labels, in the order of every (home, away) pair."""

SET_PLAY_KINDS: tuple[str, ...] = tuple(mode.name.lower() for mode in sorted(SET_PLAYS))
"""Set-play kinds counted, as named in the report (kick_off, kick_in, corner_kick, goal_kick, free_kick)."""


@dataclass(frozen=True)
class Goal:
    """One goal."""

    cycle: int
    team: int
    """Team credited with the goal (0 home, 1 away)."""
    shirt: int | None
    """Shirt number (1..11) of the last player to touch the ball, None if nobody had; in an
    own goal that player belongs to the other team."""
    own_goal: bool


@dataclass
class MatchReport:
    """The report of one match; :meth:`as_dict` is the machine-readable form."""

    team_names: tuple[str, str]
    seed: int
    cycles: int
    score: tuple[int, int]
    half_time_score: tuple[int, int] | None
    """Score at half time, None if the match ended before it."""
    goals: list[Goal] = field(default_factory=list)
    set_plays: tuple[dict[str, int], dict[str, int]] = field(default_factory=lambda: ({}, {}))
    """Per team, set-play kind -> how many the team was awarded (kick-offs included), and
    ``goal_kick_retake``: goal kicks taken again because the ball was played before it left
    the penalty area (not counted in ``goal_kick``)."""
    offsides: tuple[int, int] = (0, 0)
    """Offside calls against each team."""
    drop_balls: int = 0
    """Set plays not taken in time, restarted by dropping the ball."""
    statistics: tuple[dict[str, float], dict[str, float]] = field(default_factory=lambda: ({}, {}))
    scenario: str = "full-match"
    """The scenario played (:attr:`soccer_sim.MatchResult.scenario`)."""
    end_reason: str = "time_over"
    """Why the match ended (:attr:`soccer_sim.MatchResult.end_reason`)."""

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready dictionary (shirt numbers 1..11; teams named "home" and "away"); the
        scenario and the end reason are left to the caller (``play`` adds them for a scenario)."""
        pair = lambda values: dict(zip(SIDES, values))  # noqa: E731
        return {
            "teams": pair(self.team_names),
            "seed": self.seed,
            "cycles": self.cycles,
            "score": pair(self.score),
            "half_time_score": None if self.half_time_score is None else pair(self.half_time_score),
            "goals": [
                {"cycle": g.cycle, "team": SIDES[g.team], "scorer_shirt": g.shirt, "own_goal": g.own_goal}
                for g in self.goals
            ],
            "set_plays": pair(self.set_plays),
            "offsides": pair(self.offsides),
            "drop_balls": self.drop_balls,
            "statistics": pair(self.statistics),
        }


def match_report(result: MatchResult) -> MatchReport:
    """Build the report of a finished match from its events and statistics."""
    events = result.events
    score = [0, 0]
    half_time: tuple[int, int] | None = None
    goals: list[Goal] = []
    set_plays: tuple[dict[str, int], dict[str, int]] = tuple(
        {**{k: 0 for k in SET_PLAY_KINDS}, "goal_kick_retake": 0} for _ in SIDES
    )
    out_since_goal_kick = True
    offsides = [0, 0]
    drop_balls = 0
    for i, kind in enumerate(events.kind):
        team = events.team[i]
        if kind == EventKind.GOAL:
            score[team] += 1
            player = events.player[i]
            shirt = None if player == NO_PLAYER else player + 1
            goals.append(Goal(events.cycle[i], team, shirt, bool(events.detail[i])))
        elif kind == EventKind.HALF_TIME:
            half_time = (score[0], score[1])
        elif kind == EventKind.OUT:
            out_since_goal_kick = True
        elif kind == EventKind.SET_PLAY and team in (0, 1) and PlayMode(events.detail[i]) in SET_PLAYS:
            mode = PlayMode(events.detail[i])
            # A goal kick with no ball out since the previous one is that goal kick retaken.
            retake = mode == PlayMode.GOAL_KICK and not out_since_goal_kick
            set_plays[team]["goal_kick_retake" if retake else mode.name.lower()] += 1
            if mode == PlayMode.GOAL_KICK:
                out_since_goal_kick = False
        elif kind == EventKind.OFFSIDE:
            offsides[team] += 1
        elif kind == EventKind.DROP_BALL:
            drop_balls += 1
    return MatchReport(
        team_names=tuple(result.team_names),
        seed=result.seed,
        cycles=result.cycles,
        score=(int(result.score[0]), int(result.score[1])),
        half_time_score=half_time,
        goals=goals,
        set_plays=set_plays,
        offsides=(offsides[0], offsides[1]),
        drop_balls=drop_balls,
        statistics=(result.statistics[0].as_dict(), result.statistics[1].as_dict()),
        scenario=result.scenario,
        end_reason=result.end_reason,
    )
