"""The figures of ``bench soccer`` for one soccer-sim match.

The counts come from what the match already records: its statistics
(:mod:`soccer_sim.statistics`), its event log (:class:`~soccer_sim.state.EventKind`), the
match report (:mod:`experiments.match_report`: set plays, retakes, offsides, dropped balls)
and how shots end (:mod:`soccer_sim.analysis.shots`); the per-cycle figures (distance run,
team length and width, stamina, players near the ball) come from :class:`FiguresRecorder`,
which feeds :class:`~experiments.benchmarks.soccer_cycles.CycleFigures` and
:class:`~experiments.benchmarks.soccer_plays.PlayFigures` (passes and shots as a log shows
them) exactly as :mod:`experiments.benchmarks.soccer_rcg` does from a game log.

Every figure is for both teams together (a sum) unless its name says otherwise.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING

import numpy as np

from experiments.benchmarks.soccer_cycles import CycleFigures, log_frame
from experiments.benchmarks.soccer_plays import PlayFigures

if TYPE_CHECKING:
    from soccer_sim import MatchResult
    from soccer_sim.match import Match

COUNTED = ("goals", "shots", "shots ending on a body", "passes", "kicks", "tackles", "tackles won", "fouls",
           "corners", "kick-ins", "goal kicks", "free kicks", "offside calls", "goalkeeper catches",
           "set-play retakes", "dropped balls", "teammate contacts", "body commands dropped")
"""The counted figures, in table order (the per-cycle ones follow, then distance by role)."""
ROLE_PREFIX = "distance run by "
"""Prefix of the per-role figures' names: ``distance run by LABEL (km per player)``."""


def role_figure(label: str) -> str:
    """The name of the figure of the distance run by players with role label ``label``."""
    return f"{ROLE_PREFIX}{label} (km per player)"


def place_figures(cycles: CycleFigures, groups: Mapping[str, str] | None = None) -> dict[str, float]:
    """The mean place of each role label's (or group's) players as figures: x towards the
    opponents' goal and |y| (m; :meth:`CycleFigures.role_places`)."""
    figures: dict[str, float] = {}
    for label, (x, y) in cycles.role_places(groups).items():
        figures[f"mean x of {label} (m)"] = x
        figures[f"mean |y| of {label} (m)"] = y
    return figures


class FiguresRecorder:
    """A match recorder feeding :class:`CycleFigures` every cycle; with ``roles`` it also asks
    every team that offers :class:`~soccer_sim.team_hooks.ReportsRoles` for its players' role
    labels each cycle (a team without it leaves its players' labels unknown)."""

    def __init__(self, roles: bool = True) -> None:
        self.roles = roles
        self.cycles: CycleFigures | None = None
        self.plays: PlayFigures | None = None

    def on_start(self, match: Match) -> None:
        from soccer_sim.team_hooks import ReportsRoles

        state, config = match.state, match.config
        n = state.sizes[0]
        team = np.repeat([0, 1], state.sizes)
        stamina = config.stamina
        self.cycles = CycleFigures(team, 3.0 * config.physics.player_speed_max,
                                   stamina.recover_dec_thr * stamina.maximum)
        goalie = np.zeros(team.size, dtype=bool)
        for side, index in enumerate(match.goalies):
            if index >= 0:
                goalie[state.first_row(side) + index] = True
        self._outfield_base = ~goalie
        self._reporters = [(t if self.roles and isinstance(t, ReportsRoles) else None) for t in match.teams]
        self._unknown = [[None] * size for size in state.sizes]
        self._n = n
        self.cycles.start(log_frame(state.pos, state.home_attacks))
        f, p = config.field, config.physics
        self.plays = PlayFigures(team, f.half_length, f.goal_width, p.ball_radius, p.ball_decay)
        self._mark = len(match.events)

    def on_cycle(self, match: Match) -> None:
        from soccer_sim.state import PlayMode

        state = match.state
        assert self.cycles is not None
        labels = None
        if any(self._reporters):
            labels = []
            for i, reporter in enumerate(self._reporters):
                labels.extend(reporter.role_labels() if reporter is not None else self._unknown[i])
        play_on = state.play_mode == PlayMode.PLAY_ON
        self.cycles.add(log_frame(state.pos, state.home_attacks), log_frame(state.ball, state.home_attacks),
                        state.stamina, self._outfield_base & state.present, play_on, labels)
        catches, tackles = self._new_plays(match)
        ball = np.concatenate((log_frame(state.ball, state.home_attacks), log_frame(state.ball_vel, state.home_attacks)))
        assert self.plays is not None
        self.plays.add(np.asarray(match.kickers), catches, tackles, np.asarray(match.touchers), ball, play_on)

    def _new_plays(self, match: Match) -> tuple[np.ndarray, np.ndarray]:
        """Rows that caught the ball and rows that won a tackle in this cycle (its new events)."""
        from soccer_sim.state import EventKind

        events, state = match.events, match.state
        catches, tackles = [], []
        for i in range(self._mark, len(events)):
            kind = events.kind[i]
            if kind == EventKind.CATCH:
                catches.append(state.first_row(events.team[i]) + events.player[i])
            elif kind == EventKind.TACKLE and events.detail[i] % 2 == 1:
                tackles.append(state.first_row(events.team[i]) + events.player[i])
        self._mark = len(events)
        return np.array(catches, dtype=np.intp), np.array(tackles, dtype=np.intp)

    def on_end(self, match: Match) -> None:
        pass


def counted_figures(result: MatchResult) -> dict[str, float | None]:
    """The counted figures (:data:`COUNTED`) of a finished match."""
    from experiments.match_report import match_report
    from soccer_sim.analysis.shots import shot_endings
    from soccer_sim.state import EventKind

    home, away = result.statistics
    report = match_report(result)
    plays = report.set_plays
    both = lambda key: float(plays[0][key] + plays[1][key])  # noqa: E731
    return {
        "goals": float(sum(result.score)),
        "shots": float(home.shots + away.shots),
        "shots ending on a body": float(sum(ending == "body" for _, ending in shot_endings(result.events))),
        "passes": float(home.passes + away.passes),
        "kicks": float(home.kicks + away.kicks),
        "tackles": float(home.tackles + away.tackles),
        "tackles won": float(home.tackles_won + away.tackles_won),
        "fouls": float(home.fouls + away.fouls),
        "corners": both("corner_kick"),
        "kick-ins": both("kick_in"),
        "goal kicks": both("goal_kick"),
        "free kicks": both("free_kick"),
        "offside calls": float(sum(report.offsides)),
        "goalkeeper catches": float(len(result.events.of_kind(EventKind.CATCH))),
        "set-play retakes": both("goal_kick_retake"),
        "dropped balls": float(report.drop_balls),
        "teammate contacts": float(home.teammate_contacts + away.teammate_contacts),
        "body commands dropped": float(home.ignored_commands + away.ignored_commands),
    }


def match_figures(home: str, away: str, seed: int, cycles: int | None = None, *, roles: bool = True,
                  recorders: tuple = (), observation: str = "full") -> dict[str, float | None]:
    """Play one match and return every figure of it by name (None: not defined for it);
    ``observation``: ``"full"`` or ``"partial"``."""
    from soccer_sim import MatchConfig, run_match
    from soccer_sim.perception.config import ObservationConfig

    recorder = FiguresRecorder(roles)
    config = MatchConfig(max_cycles=cycles, observation=ObservationConfig(observation))
    result = run_match(home, away, seed=seed, config=config,
                       recorders=[recorder, *recorders])
    assert recorder.cycles is not None
    figures = counted_figures(result)
    assert recorder.plays is not None
    figures.update(recorder.plays.figures())
    figures.update(recorder.cycles.figures())
    figures.update({role_figure(label): km for label, km in recorder.cycles.role_distances().items()})
    # Positions also count for their role kind (labels that are kinds already count as such).
    from agents.teams.positions import POSITION_KINDS

    groups = {**POSITION_KINDS, **{kind: kind for kind in POSITION_KINDS.values()}}
    figures.update({role_figure(group): km for group, km in recorder.cycles.role_distances(groups).items()})
    figures.update(place_figures(recorder.cycles))
    figures.update(place_figures(recorder.cycles, groups))
    return figures
