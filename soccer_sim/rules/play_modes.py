"""The play-mode state machine: set plays, restarts, kick-offs, the pause after a goal, time.

rcssserver keeps this in its ``Stadium`` (``change_play_mode``) and its ``TimeRef`` (half
time, time over); the judges (:mod:`soccer_sim.rules.judge`) decide *when* play stops and
call :meth:`PlayModes.restart` or :meth:`PlayModes.kick_off`; this module decides *how*: the
ball put still on its spot, the opponents cleared from it every cycle, a set play not taken
in time dropped, the players moved into their halves for a kick-off. Every switch is
recorded as a SET_PLAY event and announced to the judges (``play_mode_change``); every
restart first tells them the ball was placed (``ball_placed``), ending passes, offside
positions and pending decisions.

Decisions where the rules leave room:

* **Set plays** keep the ball on its spot until the mode team kicks it; body touches do not
  take a set play and are not judged (no TOUCH/PASS events, no last touch). Opponents are
  pushed to ``set_play_clearance`` every cycle (at a kick-off to the larger of that and the
  centre-circle radius; at a goal kick also out of the penalty area); players pushed by the
  referee lose their velocity. There is no double-touch rule. Free kicks are indirect in
  name only: a goal scored straight from a free kick or a kick-off counts. A set play not
  taken within ``set_play_timeout`` cycles becomes a dropped ball (play on, DROP_BALL event).
* **After a goal** the play mode is AFTER_GOAL for ``goal_pause_cycles``: the ball waits on
  the centre spot, nobody kicks, the teams may place their players (``apply_moves``); then
  the conceding team kicks off.
* **Kick-off** positions: players standing in the opponents' half are put on the halfway
  line after the pause that follows a goal, and reflected across it at the start, at half
  time and when there is no pause; ``apply_moves`` targets are clamped onto it.
* **Without set plays** (a scenario's choice) every restart but the opening one becomes a
  dropped ball on its spot (:meth:`PlayModes.drop_ball`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from soccer_sim.ending import HALF_TIME_DUE, TIME_OVER_DUE
from soccer_sim.rules.judge import Hooks
from soccer_sim.rules.spots import (
    clamp_into_own_half,
    keep_in_own_half,
    mirror_into_own_half,
    push_clear_of_spot,
    push_out_of_circle,
    push_out_of_penalty_area,
)
from soccer_sim.state import AWAY, HOME, NO_PLAYER, NO_TEAM, SET_PLAYS, EventKind, EventLog, PlayMode, WorldState

if TYPE_CHECKING:
    from soccer_sim.setup import MatchSetup

PLAY_ON = PlayMode.PLAY_ON
KICK_OFF = PlayMode.KICK_OFF
GOALIE_HOLDS = PlayMode.GOALIE_HOLDS
TIME_OVER = PlayMode.TIME_OVER
AFTER_GOAL = PlayMode.AFTER_GOAL
GOAL_KICK = PlayMode.GOAL_KICK
_DROP_INSET = 1.0
"""Without set plays, a ball dropped in place of a restart lies at least this far (m) inside
the lines (a kick-in's spot on the touchline would be out again at the slightest touch)."""


def _frozen(a: np.ndarray) -> np.ndarray:
    a.flags.writeable = False
    return a


class PlayModes:
    """Play modes of one match, and the players' layout the judges share, as the match's
    :class:`~soccer_sim.setup.MatchSetup` gives them: the sides' sizes and goalkeepers, set
    plays on or off (off: every restart but the opening one is a dropped ball) and, through
    its :class:`~soccer_sim.ending.MatchEnd`, when half time and time over come.
    """

    def __init__(self, setup: MatchSetup, events: EventLog, hooks: Hooks) -> None:
        self.setup = setup
        self.config = config = setup.config
        self.events = events
        self.hooks = hooks
        home, away = setup.sizes
        n2 = home + away
        self.n = home
        """Home players: rows below it are home's, the others away's."""
        self.sizes = (home, away)
        self.rows = (slice(0, home), slice(home, n2))
        self.goalie_rows = setup.goalie_rows
        """Each team's goalkeeper row, NO_PLAYER if it has none."""
        self.set_plays = setup.set_plays
        self._clock = setup.end.clock
        r = config.rules
        self._clearance = r.set_play_clearance
        self._kick_off_radius = max(r.set_play_clearance, config.field.centre_circle_radius)
        home_rows = np.repeat([1.0, -1.0], [home, away])
        self._row_direction = {1: home_rows, -1: -home_rows}
        """Attack direction of every player row, keyed by ``state.home_attacks``."""
        # Cached read-only kick masks (kick_mask returns one of these, never a new array).
        self._mask_all = _frozen(np.ones(n2, dtype=bool))
        self._mask_none = _frozen(np.zeros(n2, dtype=bool))
        self._mask_team = tuple(_frozen(np.arange(n2) < home) if team == HOME else _frozen(np.arange(n2) >= home)
                                for team in (HOME, AWAY))
        self._mask_row = [_frozen(np.arange(n2) == row) for row in range(n2)]
        self._spot = (0.0, 0.0)
        self._spot_owner: tuple[int, int, int] | None = None
        """(mode, team, start) of the set play ``_spot`` belongs to; a set play the referee did
        not begin itself (a state built or loaded elsewhere) takes the ball's position as spot."""
        self.prev_ball = (float("nan"), float("nan"))
        """The ball's position at the end of the previous cycle (to tell where it crossed a line)."""

    # ------------------------------------------------------------------ asked by the match loop

    def start(self, state: WorldState, mode: PlayMode, team: int) -> None:
        """Open play in ``mode``; see :meth:`soccer_sim.referee.Referee.start`."""
        if mode == KICK_OFF:
            self.kick_off(state, team, first_cycle=state.cycle)
        elif mode == PLAY_ON:
            bx, by = float(state.ball[0]), float(state.ball[1])
            self.prev_ball = (bx, by)
            self.hooks.ball_placed(state, bx, by)
            self.set_mode(state, PLAY_ON, NO_TEAM, first_cycle=state.cycle)
        elif mode in SET_PLAYS:
            self.restart(state, mode, team, float(state.ball[0]), float(state.ball[1]), first_cycle=state.cycle)
        else:
            raise ValueError(f"play cannot start in {PlayMode(mode).name}; start with a set play or PLAY_ON")

    def kick_mask(self, state: WorldState) -> np.ndarray:
        """(2n,) bool: which players may kick now (a cached read-only array). Play on:
        everybody; set plays: the mode team; goalkeeper holding: the holder; else nobody."""
        mode = state.play_mode
        if mode == PLAY_ON:
            return self._mask_all
        if mode == GOALIE_HOLDS:
            holder = state.ball_holder
            row = holder if holder != NO_PLAYER else self.goalie_rows[state.mode_team]
            return self._mask_row[row] if row != NO_PLAYER else self._mask_none
        if mode == TIME_OVER or mode == AFTER_GOAL or state.mode_team == NO_TEAM:
            return self._mask_none
        return self._mask_team[state.mode_team]

    def apply_moves(self, state: WorldState, team: int, targets: np.ndarray, moved: np.ndarray | None = None) -> None:
        """KICK_OFF and AFTER_GOAL only: teleport ``team``'s players to ``targets``, clamped
        into their own half, the team not kicking off kept out of the centre circle.
        ``moved``: (n,) bool, the players whose move is their one body command this cycle
        (None: all; the others, who sent a higher one, stay where they are)."""
        if state.play_mode != KICK_OFF and state.play_mode != AFTER_GOAL:
            return
        n = self.sizes[team]
        targets = np.asarray(targets, dtype=float)
        if targets.shape != (n, 2) or not np.isfinite(targets).all():
            raise ValueError(f"kick-off move targets for team {team} must be a finite ({n}, 2) array, "
                             f"got shape {targets.shape}")
        rows = self.rows[team]
        block = state.pos[rows]
        if moved is None:
            block[:] = targets
            state.vel[rows] = 0.0
        else:
            block[moved] = targets[moved]
            state.vel[rows][moved] = 0.0
        clamp_into_own_half(block, state.attack_direction(team), self.config.field)
        if team != state.mode_team:
            direction = state.attack_direction(team)
            push_out_of_circle(block, 0.0, 0.0, self._kick_off_radius, (-float(direction), 0.0))

    def set_play_taken(self, state: WorldState, kicker: int) -> None:
        """``kicker``'s kick started play on (the set play or held ball it was taken from ends)."""
        self.set_mode(state, PLAY_ON, NO_TEAM, player=kicker - state.team_of(kicker) * self.n)

    def keep(self, state: WorldState) -> None:
        """Every cycle of a set play or of the pause after a goal (not play on, not a held ball)."""
        if state.play_mode == AFTER_GOAL:
            self.keep_goal_pause(state)
        else:
            self.keep_set_play(state)

    def judge_time(self, state: WorldState) -> None:
        """End of every cycle (rcssserver's ``TimeRef``): half time or time over when due
        (:meth:`soccer_sim.ending.MatchEnd.clock` decides)."""
        due = self._clock(state.cycle + 1)
        if due == TIME_OVER_DUE:
            self.time_over(state)
        elif due == HALF_TIME_DUE:
            self.half_time(state)

    # ------------------------------------------------------------------ transitions

    def set_mode(self, state: WorldState, mode: PlayMode, team: int, *, player: int = NO_PLAYER,
                 first_cycle: int | None = None) -> None:
        """Switch the play mode, record the SET_PLAY event, tell the judges."""
        state.play_mode = mode
        state.mode_team = team if mode != PLAY_ON else NO_TEAM
        state.mode_start = state.cycle + 1 if first_cycle is None else first_cycle
        self._spot_owner = (mode, state.mode_team, state.mode_start)
        self.hooks.play_mode_change(state, mode)
        self.events.add(state.cycle, EventKind.SET_PLAY, state.mode_team, player,
                        float(state.ball[0]), float(state.ball[1]), int(mode))

    def restart(self, state: WorldState, mode: PlayMode, team: int, x: float, y: float,
                first_cycle: int | None = None) -> None:
        """Begin a set play for ``team`` with the ball still at (x, y). Without set plays
        (other than the opening one) the ball is dropped there instead (:meth:`drop_ball`)."""
        if not self.set_plays and first_cycle is None:
            self.drop_ball(state, mode, x, y)
            return
        self._spot = (x, y)
        self.place_ball(state, x, y)
        self.set_mode(state, mode, team, first_cycle=first_cycle)
        if mode == AFTER_GOAL:
            self.keep_goal_pause(state)
        else:
            self.keep_set_play(state)

    def drop_ball(self, state: WorldState, replaced: PlayMode, x: float, y: float) -> None:
        """Without set plays: the ball is put still on the spot of the restart it replaces
        (``replaced``), moved at least ``_DROP_INSET`` inside the lines, and play goes on at
        once, open to both teams; nobody is moved. DROP_BALL event (detail: ``replaced``)."""
        f = self.config.field
        x_max, y_max = max(f.half_length - _DROP_INSET, 0.0), max(f.half_width - _DROP_INSET, 0.0)
        x, y = min(max(x, -x_max), x_max), min(max(y, -y_max), y_max)
        self.events.add(state.cycle, EventKind.DROP_BALL, NO_TEAM, NO_PLAYER, x, y, int(replaced))
        self.place_ball(state, x, y)
        self.set_mode(state, PLAY_ON, NO_TEAM)

    def place_ball(self, state: WorldState, x: float, y: float) -> None:
        """Put the ball still at (x, y) for a restart; nobody holds it; the judges forget."""
        state.ball[0], state.ball[1] = x, y
        state.ball_vel[:] = 0.0
        state.ball_holder = NO_PLAYER
        self.hooks.ball_placed(state, x, y)
        self.prev_ball = (x, y)

    def kick_off(self, state: WorldState, team: int, first_cycle: int | None = None, *,
                 after_pause: bool = False) -> None:
        """Kick-off for ``team``: ball on the centre spot, everybody stopped, both teams in
        their own halves. Players in the wrong half are put on the halfway line after the
        pause that follows a goal (they had the pause to get back), else reflected across it.
        Without set plays (other than the opening kick-off) the ball is dropped on the centre
        spot and nobody is moved."""
        if not self.set_plays and first_cycle is None:
            state.last_touch = NO_PLAYER
            self.drop_ball(state, KICK_OFF, 0.0, 0.0)
            return
        directions = self._row_direction[state.home_attacks]
        if after_pause:
            keep_in_own_half(state.pos, directions)
        else:
            mirror_into_own_half(state.pos, directions)
        state.vel[:] = 0.0
        state.last_touch = NO_PLAYER
        self.restart(state, KICK_OFF, team, 0.0, 0.0, first_cycle)

    def keep_set_play(self, state: WorldState) -> None:
        """Every cycle of a set play: ball still on its spot, opponents cleared
        (``set_play_clearance``; at a goal kick also out of the penalty area), kick-off halves
        kept; after ``set_play_timeout`` cycles the ball is dropped (play on)."""
        if self._spot_owner != (state.play_mode, state.mode_team, state.mode_start):
            self._spot = (float(state.ball[0]), float(state.ball[1]))
            self._spot_owner = (state.play_mode, state.mode_team, state.mode_start)
        sx, sy = self._spot
        state.ball[0], state.ball[1] = sx, sy
        state.ball_vel[:] = 0.0
        other = 1 - state.mode_team
        rows = self.rows[other]
        if state.play_mode == KICK_OFF:
            self._keep_kick_off_positions(state, other, sx, sy)
        else:
            block = state.pos[rows]
            moved = push_clear_of_spot(block, sx, sy, self._clearance, self.config.field)
            if moved is not None:
                state.vel[rows][moved] = 0.0
            if state.play_mode == GOAL_KICK and self.config.rules.goal_kick_leaves_area:
                # Opponents leave the penalty area too (from a goal kick's spot its lines are
                # beyond the clearance; the second push keeps the clearance for any spot).
                moved = push_out_of_penalty_area(block, -state.attack_direction(other), self.config.field)
                if moved is not None:
                    state.vel[rows][moved] = 0.0
                    push_clear_of_spot(block, sx, sy, self._clearance, self.config.field)
        if state.cycle - state.mode_start + 1 >= self.config.rules.set_play_timeout:
            self.events.add(state.cycle, EventKind.DROP_BALL, NO_TEAM, NO_PLAYER, sx, sy, int(state.play_mode))
            self.set_mode(state, PLAY_ON, NO_TEAM)

    def _keep_kick_off_positions(self, state: WorldState, other: int, sx: float, sy: float) -> None:
        """Both teams in their own half (offenders put on the halfway line), the team not
        kicking off outside the centre circle (pushed radially); moved players stop."""
        pos = state.pos
        rows = self.rows[other]
        moved = keep_in_own_half(pos, self._row_direction[state.home_attacks])
        if moved is not None:
            state.vel[moved] = 0.0
        fallback = (-float(state.attack_direction(other)), 0.0)
        pushed = push_out_of_circle(pos[rows], sx, sy, self._kick_off_radius, fallback)
        if pushed is not None:
            state.vel[rows][pushed] = 0.0

    def keep_goal_pause(self, state: WorldState) -> None:
        """Every cycle of the pause after a goal: the ball waits on the centre spot; at the end
        of the pause the team that conceded kicks off."""
        state.ball[:] = 0.0
        state.ball_vel[:] = 0.0
        if state.cycle - state.mode_start + 1 >= self.config.rules.goal_pause_cycles:
            self.kick_off(state, state.mode_team, after_pause=True)

    def half_time(self, state: WorldState) -> None:
        """Half time as rcssserver 19 has it: the teams keep their ends (no change of sides) and
        away, the right-hand team at the start, kicks off the second half (the kick-off stops
        the ball and the players and puts everybody in their own half)."""
        self.events.add(state.cycle, EventKind.HALF_TIME, NO_TEAM, NO_PLAYER,
                        float(state.ball[0]), float(state.ball[1]), 0)
        state.half = 1
        self.hooks.half_time(state)
        self.kick_off(state, AWAY)

    def time_over(self, state: WorldState) -> None:
        """TIME_OVER event and play mode: nobody holds the ball, nobody may kick."""
        self.events.add(state.cycle, EventKind.TIME_OVER, NO_TEAM, NO_PLAYER,
                        float(state.ball[0]), float(state.ball[1]), 0)
        state.ball_holder = NO_PLAYER
        self.set_mode(state, TIME_OVER, NO_TEAM)

