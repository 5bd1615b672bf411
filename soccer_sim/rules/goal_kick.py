"""The goal kick's ball must leave the penalty area before it is played (rcssserver's
``FreeKickRef``, its goal-kick part; ``RuleConfig.goal_kick_leaves_area``).

Once a goal kick is taken the ball must leave the penalty area before an opponent plays it,
else the goal kick is retaken; a team-mate of the taker playing it first puts it in play,
or with ``proper_goal_kicks`` retakes it too, at most ``max_goal_kicks`` times in a row
before the opponents get an indirect free kick on the penalty area's edge (rcssserver's
rule; the taker may play it again). While it waits the opponents are kept out of the penalty
area by the set-play clearance (:meth:`soccer_sim.rules.play_modes.PlayModes.keep_set_play`).
"""

from __future__ import annotations

from soccer_sim.rules.judge import Judge
from soccer_sim.rules.play_modes import GOAL_KICK, PlayModes
from soccer_sim.rules.spots import in_penalty_area, penalty_area_edge_spot
from soccer_sim.state import PlayMode, WorldState


class GoalKickJudge(Judge):
    """rcssserver's ``FreeKickRef`` for goal kicks: retakes a goal kick whose ball was played
    inside the penalty area. Present only with ``goal_kick_leaves_area``."""

    name = "goal_kick"

    def __init__(self, modes: PlayModes) -> None:
        self.modes = modes
        self._pending: tuple[int, float, float, int] | None = None
        """(team, spot x, spot y, taker's row) of a goal kick taken whose ball has not yet left
        the penalty area."""
        self._retakes = 0
        """Retakes in a row of the current goal kick for its own team's fault (``max_goal_kicks``)."""

    def kick_taken(self, state: WorldState, rows: list[int], mode: PlayMode, x: float, y: float) -> bool:
        if self._pending is not None:
            return self._played_early(state, rows)
        if mode == GOAL_KICK:
            first = rows[0]
            self._pending = (state.team_of(first), x, y, first)
        return False

    def ball_touched(self, state: WorldState, rows: list[int], x: float, y: float) -> bool:
        return self._pending is not None and self._played_early(state, rows)

    def analyse(self, state: WorldState, x: float, y: float) -> bool:
        """The goal kick's ball is in play once it has left the penalty area."""
        pending = self._pending
        if pending is not None and not in_penalty_area(self.modes.config.field,
                                                        state.attack_direction(pending[0]), x, y):
            self._pending = None
        return False

    def play_mode_change(self, state: WorldState, mode: PlayMode) -> None:
        if mode == GOAL_KICK:
            self._retakes = 0  # a new goal kick (a retake restores its count afterwards)

    def ball_placed(self, state: WorldState, x: float, y: float) -> None:
        self._pending = None

    def _played_early(self, state: WorldState, rows: list[int]) -> bool:
        """``rows`` played the ball of a goal kick before it left the penalty area. An opponent
        among them retakes the goal kick (not counted against the team); a team-mate of the
        taker retakes it with ``proper_goal_kicks`` (counted, a free kick for the opponents once
        ``max_goal_kicks`` retakes in a row are used up), else puts the ball in play; the taker
        alone changes nothing. Returns whether play was restarted."""
        team, x, y, taker = self._pending
        rules = self.modes.config.rules
        if any(state.team_of(row) != team for row in rows):
            self._retakes = 0
            self.modes.restart(state, GOAL_KICK, team, x, y)
            return True
        if all(row == taker for row in rows):
            return False
        if not rules.proper_goal_kicks:
            self._pending = None
            return False
        if self._retakes >= rules.max_goal_kicks:
            self._retakes = 0
            fx, fy = penalty_area_edge_spot(self.modes.config.field, state.attack_direction(team),
                                            float(state.ball[0]), float(state.ball[1]))
            self.modes.restart(state, PlayMode.FREE_KICK, 1 - team, fx, fy)
            return True
        retakes = self._retakes + 1
        self.modes.restart(state, GOAL_KICK, team, x, y)
        self._retakes = retakes
        return True
