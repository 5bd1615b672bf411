"""The goalkeeper's catch, hold and release, and the back-pass rule (rcssserver's
``CatchRef``, with the catch decision rcssserver makes in ``Player::catchBall``).

**Catch area.** A point robot has no orientation, so the catch rectangle (``catch_length`` x
``catch_width``) is aligned from the goalkeeper towards the ball: the ball's centre lies on
its axis and the catch succeeds when the centre-to-centre distance is at most
``catch_length`` (the width never excludes a ball on the axis). Goalkeeper and ball must both
be inside the goalkeeper's own penalty area, the mode must be play on, and
``catch_ban_cycles`` must have passed since the last attempt made with goalkeeper and ball in
the area (successful or not; requests outside the area are ignored and start no ban; half
time lifts the bans). A goalkeeper that kicks in a cycle cannot also catch in it. While
holding, the goalkeeper (and the ball) is kept inside its penalty area; opponents are not
kept away, and the held ball does not collide. Holding for ``goalie_hold_cycles`` cycles
gives the opponents a free kick on the nearest point of the penalty area's front or side
line. A kick by the holder releases the ball.

**Back-pass** (``back_pass_rule``): a catch of a ball whose last play was a team-mate's kick
(a pass in flight) is refused: BACK_PASS event and an indirect free kick for the opponents
(outside the goal area).

**Player types** (:mod:`soccer_sim.player_types`): a goalkeeper whose type stretches the
catchable length (rcssserver's ``catchable_area_l_stretch``, s >= 1) also catches a ball up
to ``s * catch_length`` away, with a probability falling linearly from 1 at
``catch_length`` to 0 at ``s * catch_length`` (rcssserver's rule with its default
``catch_probability`` of 1), drawn from :attr:`GoalkeeperJudge.rng`. The default type
(s = 1) never draws.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from soccer_sim.kernels import PT_CATCH_STRETCH
from soccer_sim.rules.judge import Judge
from soccer_sim.rules.play_modes import GOALIE_HOLDS, PLAY_ON, PlayModes
from soccer_sim.rules.spots import clamp_into_penalty_area, in_penalty_area, out_of_goal_area, penalty_area_edge_spot
from soccer_sim.state import NO_PLAYER, EventKind, PlayMode, WorldState

_NEVER = -(10**9)


class GoalkeeperJudge(Judge):
    """rcssserver's ``CatchRef``: catches, holding the ball, back passes.

    ``passer`` returns the row of the player whose kick the ball is travelling from (or
    NO_PLAYER), for the back-pass rule (:meth:`soccer_sim.analysis.plays.PlayAnalysis.passer`).
    """

    name = "goalkeeper"

    def __init__(self, modes: PlayModes, passer: Callable[[], int], rng: np.random.Generator | None = None,
                 types: np.ndarray | None = None) -> None:
        self.modes = modes
        self._passer = passer
        self._last_attempt = [_NEVER, _NEVER]
        self.types = types
        """Each player row's type parameters (:attr:`soccer_sim.kinematics.Kinematics.types`,
        which the match's kinematics keep up to date): the goalkeeper's
        ``catchable_area_l_stretch``; None: 1 for all."""
        self.rng = rng
        """The generator of the stretched area's catch draws (the match's tackle generator);
        None: no catch in the stretched area."""

    def catch_requested(self, state: WorldState, team: int, kickers: np.ndarray) -> None:
        """A catch request by ``team``'s goalkeeper (see the module docstring)."""
        if state.play_mode != PLAY_ON or state.ball_holder != NO_PLAYER:
            return
        modes = self.modes
        row = modes.goalie_rows[team]
        if row == NO_PLAYER or row in kickers:
            return
        rules = modes.config.rules
        if state.cycle - self._last_attempt[team] <= rules.catch_ban_cycles:
            return
        f = modes.config.field
        direction = state.attack_direction(team)
        gx, gy = float(state.pos[row, 0]), float(state.pos[row, 1])
        bx, by = float(state.ball[0]), float(state.ball[1])
        if not (in_penalty_area(f, direction, gx, gy) and in_penalty_area(f, direction, bx, by)):
            return  # not a catch situation: no attempt, no ban
        self._last_attempt[team] = state.cycle
        distance = math.hypot(bx - gx, by - gy)
        if distance > rules.catch_length:
            stretch = 1.0 if self.types is None else float(self.types[row, PT_CATCH_STRETCH])
            reach = rules.catch_length * stretch
            if distance > reach or self.rng is None:
                return
            if self.rng.random() >= 1.0 - (distance - rules.catch_length) / (reach - rules.catch_length):
                return
        n = modes.n
        passer = self._passer()
        if rules.back_pass_rule and passer != NO_PLAYER and passer != row and state.team_of(passer) == team:
            modes.events.add(state.cycle, EventKind.BACK_PASS, team, row - team * n, bx, by, passer - team * n)
            x, y = out_of_goal_area(f, direction, bx, by)
            modes.restart(state, PlayMode.FREE_KICK, 1 - team, x, y)
            return
        modes.hooks.ball_caught(state, row, bx, by)
        state.last_touch = row
        state.ball_holder = row
        state.ball_vel[:] = 0.0
        state.ball[0], state.ball[1] = gx, gy
        modes.events.add(state.cycle, EventKind.CATCH, team, row - team * n, bx, by, 0)
        modes.set_mode(state, GOALIE_HOLDS, team, player=row - team * n)

    def keep_holder_in_area(self, state: WorldState) -> None:
        """Every cycle of a held ball: the goalkeeper (and the ball) kept in its penalty area;
        holding too long gives the opponents a free kick."""
        modes = self.modes
        row = state.ball_holder
        team = state.mode_team
        f = modes.config.field
        direction = state.attack_direction(team)
        if row == NO_PLAYER:
            row = modes.goalie_rows[team]
        gx, gy = clamp_into_penalty_area(f, direction, float(state.pos[row, 0]), float(state.pos[row, 1]))
        state.pos[row, 0], state.pos[row, 1] = gx, gy
        state.ball[0], state.ball[1] = gx, gy
        state.ball_vel[:] = 0.0
        if state.cycle - state.mode_start + 1 >= modes.config.rules.goalie_hold_cycles:
            x, y = penalty_area_edge_spot(f, direction, gx, gy)
            modes.restart(state, PlayMode.FREE_KICK, 1 - team, x, y)

    def kick_taken(self, state: WorldState, rows: list[int], mode: PlayMode, x: float, y: float) -> bool:
        if mode == GOALIE_HOLDS:
            state.ball_holder = NO_PLAYER  # released
        return False

    def half_time(self, state: WorldState) -> None:
        self._last_attempt = [_NEVER, _NEVER]

