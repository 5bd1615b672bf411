"""Goals, the ball out of the field, and who touched it last (rcssserver's ``TouchRef``).

* **Goal**: the whole ball beyond a goal line between the posts (where its centre crossed the
  line, interpolated within the cycle); it counts for the team attacking that goal, whoever
  touched last. After it the play mode is AFTER_GOAL for ``goal_pause_cycles``, then the
  conceding team kicks off (:class:`~soccer_sim.rules.play_modes.PlayModes`).
* **Out**: a kick-in for the opponents of the last toucher where the ball's centre crossed the
  touchline; over a goal line a corner kick for the attackers if a defender touched it last,
  else a goal kick. Spots: :mod:`soccer_sim.rules.spots`.
* **No last touch** (nobody touched it since the last kick-off): the restart goes to the team
  defending the half where it left: a kick-in, or a goal kick (never a corner).
* **Last touch** is the last player that kicked the ball or whose body touched it; when
  several bodies touch it in one cycle the one nearest the ball afterwards counts. A body
  touch records one TOUCH event per continuous contact.
"""

from __future__ import annotations

import math

import numpy as np

from soccer_sim.rules.judge import Judge
from soccer_sim.rules.play_modes import AFTER_GOAL, KICK_OFF, PlayModes
from soccer_sim.rules.spots import corner_spot, goal_kick_spot, line_crossing
from soccer_sim.state import AWAY, HOME, NO_PLAYER, NO_TEAM, EventKind, PlayMode, WorldState


class BallOutJudge(Judge):
    """rcssserver's ``TouchRef`` (its ``analyse``: goals and the ball out of the field). First
    in the list: a ball out of the field ends the cycle's analysis."""

    name = "ball_out"

    def __init__(self, modes: PlayModes) -> None:
        self.modes = modes
        f, p = modes.config.field, modes.config.physics
        self._goal_x = f.half_length + p.ball_radius  # whole ball beyond the goal line
        self._touch_y = f.half_width + p.ball_radius  # whole ball beyond the touchline
        self._post_y = f.goal_width / 2.0

    def analyse(self, state: WorldState, x: float, y: float) -> bool:
        if x > self._goal_x or x < -self._goal_x or y > self._touch_y or y < -self._touch_y:
            self._ball_left_field(state, x, y)
            return True
        return False

    def _ball_left_field(self, state: WorldState, bx: float, by: float) -> None:
        """The whole ball is beyond a goal line or touchline: goal, kick-in, corner or goal kick."""
        modes = self.modes
        px, py = modes.prev_ball
        line, x, y = line_crossing(px, py, bx, by, self._goal_x, self._touch_y)
        f = modes.config.field
        last = state.last_touch
        last_team = state.team_of(last) if last != NO_PLAYER else NO_TEAM
        last_index = last - last_team * modes.n if last != NO_PLAYER else NO_PLAYER
        events = modes.events
        if line == "goal_line":
            goal_side = 1 if x > 0 else -1
            defender = HOME if state.attack_direction(HOME) == -goal_side else AWAY
            attacker = 1 - defender
            if abs(y) < self._post_y:
                self._goal(state, attacker, last_team, last_index, x, y)
                return
            events.add(state.cycle, EventKind.OUT, last_team, last_index, x, y, 1)
            if last_team == defender:
                sx, sy = corner_spot(f, goal_side, y, modes.config.rules.corner_inset)
                modes.restart(state, PlayMode.CORNER_KICK, attacker, sx, sy)
            else:
                sx, sy = goal_kick_spot(f, goal_side, y)
                modes.restart(state, PlayMode.GOAL_KICK, defender, sx, sy)
            return
        events.add(state.cycle, EventKind.OUT, last_team, last_index, x, y, 0)
        x = min(max(x, -f.half_length), f.half_length)
        y = math.copysign(f.half_width, y)
        if last_team == NO_TEAM:
            taker = HOME if state.attack_direction(HOME) * x <= 0.0 else AWAY
        else:
            taker = 1 - last_team
        modes.restart(state, PlayMode.KICK_IN, taker, x, y)

    def _goal(self, state: WorldState, scorer: int, last_team: int, last_index: int, x: float, y: float) -> None:
        """GOAL event (``detail`` 1 for an own goal), score, then the pause or the kick-off."""
        modes = self.modes
        own_goal = last_team != NO_TEAM and last_team != scorer
        modes.hooks.goal_scored(state, scorer, last_team, last_index)
        state.score[scorer] += 1
        modes.events.add(state.cycle, EventKind.GOAL, scorer, last_index, x, y, int(own_goal))
        if not modes.set_plays:
            state.last_touch = NO_PLAYER
            modes.drop_ball(state, KICK_OFF, 0.0, 0.0)
        elif modes.config.rules.goal_pause_cycles > 0:
            modes.restart(state, AFTER_GOAL, 1 - scorer, 0.0, 0.0)
        else:
            modes.kick_off(state, 1 - scorer)


class TouchJudge(Judge):
    """rcssserver's ``TouchRef`` (its ``ballTouched``): the last touch and TOUCH events."""

    name = "touch"

    def __init__(self, modes: PlayModes) -> None:
        self.modes = modes
        self._touching: tuple[int, ...] = ()
        """Rows touching the ball at the end of the last cycle with a touch."""
        self._touch_cycle = -1
        """The last cycle with a body touch."""

    def ball_touched(self, state: WorldState, rows: list[int], x: float, y: float) -> bool:
        """TOUCH events for new contacts; the last touch goes to the toucher nearest the ball."""
        n = self.modes.n
        previous = self._touching
        for row in rows:
            if row not in previous:
                team = HOME if row < n else AWAY
                self.modes.events.add(state.cycle, EventKind.TOUCH, team, row - team * n, x, y, 0)
        if len(rows) == 1:
            nearest = rows[0]
        else:
            d = np.hypot(state.pos[rows, 0] - x, state.pos[rows, 1] - y)
            nearest = rows[int(np.argmin(d))]
        state.last_touch = nearest
        self._touching = tuple(rows)
        self._touch_cycle = state.cycle
        return False

    def analyse(self, state: WorldState, x: float, y: float) -> bool:
        """A play-on cycle without a touch ends every contact."""
        if self._touch_cycle != state.cycle:
            self._touching = ()
        return False

    def ball_placed(self, state: WorldState, x: float, y: float) -> None:
        self._touching = ()

    def ball_dropped(self, state: WorldState, x: float, y: float) -> None:
        self._touching = ()
