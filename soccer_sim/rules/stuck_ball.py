"""A ball nobody gets away is dropped where it lies (rcssserver's ``BallStuckRef``).

A ball within ``stuck_ball_radius`` of one point for ``stuck_ball_cycles`` cycles of play on
is dropped there: DROP_BALL event (detail PLAY_ON), every player within that radius pushed
out to it and stopped, the ball stopped; play goes on. Present unless ``stuck_ball_cycles``
is None.
"""

from __future__ import annotations

import math

from soccer_sim.rules.judge import Judge
from soccer_sim.rules.play_modes import PLAY_ON, PlayModes
from soccer_sim.rules.spots import push_clear_of_spot
from soccer_sim.state import NO_PLAYER, NO_TEAM, EventKind, PlayMode, WorldState


class BallStuckJudge(Judge):
    """rcssserver's ``BallStuckRef``."""

    name = "stuck_ball"

    def __init__(self, modes: PlayModes) -> None:
        self.modes = modes
        rules = modes.config.rules
        self._cycles = rules.stuck_ball_cycles
        self._radius = rules.stuck_ball_radius
        self._radius2 = rules.stuck_ball_radius ** 2
        self._anchor = (math.nan, math.nan)
        self._since = 0
        """The ball has stayed within ``stuck_ball_radius`` of ``_anchor`` since this cycle."""

    def analyse(self, state: WorldState, x: float, y: float) -> bool:
        if state.play_mode != PLAY_ON:
            return False
        ax, ay = self._anchor
        if not (x - ax) ** 2 + (y - ay) ** 2 <= self._radius2:  # (also when no anchor yet: NaN)
            self._anchor = (x, y)
            self._since = state.cycle
            return False
        if state.cycle - self._since + 1 < self._cycles:
            return False
        modes = self.modes
        modes.events.add(state.cycle, EventKind.DROP_BALL, NO_TEAM, NO_PLAYER, x, y, int(PLAY_ON))
        moved = push_clear_of_spot(state.pos, x, y, self._radius, modes.config.field)
        if moved is not None:
            state.vel[moved] = 0.0
        state.ball_vel[:] = 0.0
        modes.hooks.ball_dropped(state, x, y)
        self._anchor = (x, y)
        self._since = state.cycle + 1
        return False

    def play_mode_change(self, state: WorldState, mode: PlayMode) -> None:
        """Every mode starts a new watch, from where the ball lies."""
        self._anchor = (float(state.ball[0]), float(state.ball[1]))
        self._since = state.mode_start
