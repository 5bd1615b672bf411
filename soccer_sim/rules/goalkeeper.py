"""The goalkeeper's catch, hold and release, and the back-pass rule (rcssserver's
``CatchRef``, with the catch decision rcssserver makes in ``Player::catchBall`` and the hold of
``Player::move`` and ``Stadium::ballCaught``).

**Catch area.** A point robot has no orientation, so the catch rectangle (``catch_length`` x
``catch_width``) is aligned from the goalkeeper towards the ball: the ball's centre lies on
its axis and the catch succeeds when the centre-to-centre distance is at most
``catch_length`` (the width never excludes a ball on the axis). Goalkeeper and ball must both
be inside the goalkeeper's own penalty area, the mode must be play on, and
``catch_ban_cycles`` must have passed since the last attempt made with goalkeeper and ball in
the area (successful or not; requests outside the area are ignored and start no ban; half
time lifts the bans). A goalkeeper that kicks in a cycle cannot also catch in it.

**The hold** (measured on rcssserver 19, ``tests/data/rcssserver/goalkeeper.json``). A catch
steps the goalkeeper towards the ball until they touch (``player_radius + ball_radius``
apart), the ball staying where it was, and gives the goalkeeper's team a free kick: the play
mode GOALIE_HOLDS, rcssserver's ``free_kick_X`` while its ball catcher is set (what its full
state calls ``goalie_catch_ball_X``). While holding:

* the ball stays touching the goalkeeper, on the side it was caught from; it is still and
  does not collide; only the holder may kick, and its kick releases the ball (play on);
* the goalkeeper may place itself with ``TeamCommand.move`` at most ``goalie_max_moves``
  times (rcssserver's ``Player::move``: further moves are refused, ``(error
  too_many_moves)``, and still take the cycle's body command); the other players' moves are
  no command;
* the goalkeeper may dash and carries the ball with it, but a held ball outside the penalty
  area is a catch fault: CATCH_FAULT event and a free kick for the opponents on the spot,
  moved out of the area (rcssserver waits 30 cycles in ``catch_fault_X`` first; here the free
  kick follows at once, as after a back pass);
* the opponents are kept ``set_play_clearance`` from the ball, as at any free kick;
* a ball held ``set_play_timeout`` cycles (rcssserver's ``drop_ball_time``, counted from the
  catch's cycle) is dropped at the penalty area's front corner on its side (DROP_BALL event,
  play on).

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
from soccer_sim.rules.spots import in_penalty_area, out_of_goal_area, out_of_penalty_area, push_clear_of_spot
from soccer_sim.state import NO_PLAYER, NO_TEAM, EventKind, PlayMode, WorldState

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
        self._hold_side = (1.0, 0.0)
        """Unit vector from the holding goalkeeper to the ball it holds (where it was caught from)."""
        self.moves_since_catch = 0
        """The holding goalkeeper's moves made since its catch (rcssserver's
        ``M_goalie_moves_since_catch``)."""
        self.refused_moves = [0, 0]
        """Each team's goalkeeper moves refused in the whole match (beyond ``goalie_max_moves``)."""

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
        # rcssserver: the goalkeeper steps towards the ball until they touch; the ball stays
        ux, uy = ((bx - gx) / distance, (by - gy) / distance) if distance > 0.0 else (float(direction), 0.0)
        self._hold_side = (ux, uy)
        touching = self._touching()
        state.pos[row, 0], state.pos[row, 1] = bx - touching * ux, by - touching * uy
        state.vel[row] = 0.0
        self.moves_since_catch = 0
        modes.events.add(state.cycle, EventKind.CATCH, team, row - team * n, bx, by, 0)
        modes.set_mode(state, GOALIE_HOLDS, team, player=row - team * n)

    def _touching(self) -> float:
        """Distance from the holding goalkeeper's centre to the held ball's (m)."""
        physics = self.modes.config.physics
        return physics.player_radius + physics.ball_radius

    def holder_moves(self, state: WorldState, x: float, y: float) -> bool:
        """The holding goalkeeper's ``TeamCommand.move`` to (x, y) (absolute frame): made if
        fewer than ``goalie_max_moves`` moves were made since the catch (the ball follows at
        the end of the cycle), else refused and counted. Returns whether it was made."""
        row = state.ball_holder
        limit = self.modes.config.rules.goalie_max_moves
        if limit >= 0 and self.moves_since_catch >= limit:
            self.refused_moves[state.mode_team] += 1
            return False
        state.pos[row, 0], state.pos[row, 1] = x, y
        self.moves_since_catch += 1
        return True

    def keep_hold(self, state: WorldState) -> None:
        """Every cycle of a held ball (see the module docstring): the ball kept touching the
        goalkeeper, a catch fault if it is outside the penalty area, the opponents kept
        clear, the ball dropped when the free kick's time is up."""
        modes = self.modes
        team = state.mode_team
        row = state.ball_holder if state.ball_holder != NO_PLAYER else modes.goalie_rows[team]
        f = modes.config.field
        direction = state.attack_direction(team)
        touching = self._touching()
        bx = float(state.pos[row, 0]) + touching * self._hold_side[0]
        by = float(state.pos[row, 1]) + touching * self._hold_side[1]
        state.ball[0], state.ball[1] = bx, by
        state.ball_vel[:] = 0.0
        if not in_penalty_area(f, direction, bx, by):
            modes.events.add(state.cycle, EventKind.CATCH_FAULT, team, row - team * modes.n, bx, by, 0)
            x, y = out_of_penalty_area(f, direction, bx, by)
            modes.restart(state, PlayMode.FREE_KICK, 1 - team, x, y)
            return
        rows = modes.rows[1 - team]
        moved = push_clear_of_spot(state.pos[rows], bx, by, modes.config.rules.set_play_clearance, f)
        if moved is not None:
            state.vel[rows][moved] = 0.0
        held = state.cycle - state.mode_start + 2  # the catch's own cycle counts (rcssserver's timer)
        if held >= modes.config.rules.set_play_timeout:
            x, y = out_of_penalty_area(f, direction, bx, by)
            modes.events.add(state.cycle, EventKind.DROP_BALL, NO_TEAM, NO_PLAYER, x, y, int(GOALIE_HOLDS))
            modes.place_ball(state, x, y)
            modes.set_mode(state, PLAY_ON, NO_TEAM)

    def kick_taken(self, state: WorldState, rows: list[int], mode: PlayMode, x: float, y: float) -> bool:
        if mode == GOALIE_HOLDS:
            state.ball_holder = NO_PLAYER  # released
        return False

    def half_time(self, state: WorldState) -> None:
        self._last_attempt = [_NEVER, _NEVER]

