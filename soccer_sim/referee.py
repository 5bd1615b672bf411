"""The referee: play modes, restarts, goals, offside, the goalkeeper's catch and time.

The match loop calls the referee at fixed points of every cycle (see soccer_sim.match):
``kick_mask`` before kicks are applied, ``on_commands`` after them (with the players whose
kick was applied and the goalkeepers' catch requests), ``apply_moves`` for kick-off
placement, and ``after_step`` once the physics has moved everything. The referee reads and
writes the :class:`~soccer_sim.state.WorldState` arrays directly (absolute frame, metres,
metres per cycle) and appends to the :class:`~soccer_sim.state.EventLog`.

Cycle bookkeeping: ``state.mode_start`` is the first cycle in which the teams act under the
current play mode. A mode set while judging cycle ``c`` starts at ``c + 1``; the opening
kick-off starts at the cycle of :meth:`Referee.start`. The first half is cycles
``0 .. half_cycles - 1``; half time is called in ``after_step`` of its last cycle, so the
second half begins at ``cycle == half_cycles``; time over is called in ``after_step`` of
the match's last cycle.

Decisions where the rules leave room:

* **No last touch.** When the ball goes out and nobody has touched it since the last
  kick-off, the restart goes to the team defending the half where it left: a kick-in for
  that team, or a goal kick (never a corner) at a goal line.
* **Last touch** is the last player that kicked the ball or whose body touched it; when
  several bodies touch it in one cycle the one nearest the ball afterwards counts.
* **Restart spots** are chosen in :mod:`soccer_sim.restarts` (kick-in where the ball's
  centre crossed the touchline, ``corner_inset`` inside the corner, goal-area corner,
  penalty-area edge); the free kick for offside is taken on the offside line as it was when
  the ball was played, level with the offender.
* **Set plays** keep the ball on its spot until the mode team kicks it; body touches do not
  take a set play and are not judged (no TOUCH/PASS events, no last touch). Opponents are
  pushed to ``set_play_clearance`` every cycle (at a kick-off to the larger of that and the
  centre-circle radius); players pushed by the referee lose their velocity. There is no
  double-touch rule. At a goal kick the opponents also leave the penalty area, and once
  taken the ball must leave the area before an opponent plays it, else the goal kick is
  retaken (``goal_kick_leaves_area``); a team-mate of the taker playing it first puts it in
  play, or with ``proper_goal_kicks`` retakes it too, at most ``max_goal_kicks`` times in a
  row before the opponents get an indirect free kick on the penalty area's edge (rcssserver's
  rule; the taker may play it again). Free kicks are indirect in name only: a goal scored
  straight from a free kick or a kick-off counts.
* **After a goal** the play mode is AFTER_GOAL for ``goal_pause_cycles``: the ball waits on
  the centre spot, nobody kicks, the teams may place their players (``apply_moves``); then
  the conceding team kicks off.
* **Kick-off** positions: players standing in the opponents' half are put on the halfway
  line after the pause that follows a goal, and reflected across it at the start, at half
  time and when there is no pause; ``apply_moves`` targets are clamped onto it.
* **Back-pass**: a goalkeeper's catch of a ball whose last play was a team-mate's kick (a
  pass in flight) is refused: BACK_PASS event and an indirect free kick for the opponents
  (``back_pass_rule``).
* **Stuck ball**: a ball within ``stuck_ball_radius`` of one point for ``stuck_ball_cycles``
  cycles of play on is dropped where it lies, the players within that radius pushed out.
* **Catch area.** A point robot has no orientation, so the catch rectangle
  (``catch_length`` x ``catch_width``) is aligned from the goalkeeper towards the ball: the
  ball's centre lies on its axis and the catch succeeds when the centre-to-centre distance is
  at most ``catch_length`` (the width never excludes a ball on the axis). Goalkeeper and
  ball must both be inside the goalkeeper's own penalty area, the mode must be play on, and
  ``catch_ban_cycles`` must have passed since the last attempt made with goalkeeper and ball
  in the area (successful or not; requests outside the area are ignored and start no ban).
  A goalkeeper that kicks in a cycle cannot also catch in it. While holding, the goalkeeper
  (and the ball) is kept inside its penalty area; opponents are not kept away, and the
  held ball does not collide. Holding for ``goalie_hold_cycles`` cycles gives the opponents
  a free kick on the nearest point of the penalty area's front or side line.
* **Offside** positions are judged whenever one team plays the ball: a kick in play on, at
  a free kick, at a kick-off or by a goalkeeper releasing a held ball, and a body touch in
  play on (a deflection off a team-mate counts as playing it, and a kicker's own touch in
  the cycle of its kick re-judges the positions rather than clearing them). Kicks from
  kick-ins, corners and goal kicks, and cycles in which both teams play the ball, clear
  all marks instead; so does the goalkeeper's catch. A marked player is penalised when it
  plays the ball (kick or body touch); with ``offside_active_distance`` set, also when it
  ends a play-on cycle that close to the ball.
* **Scenarios** (:mod:`soccer_sim.scenarios`): the sides may differ in size (player rows
  ``0..h-1`` home, the rest away) and a side may have no goalkeeper (no catch); play may open
  with any set play or in play on (:meth:`Referee.start`); without set plays every restart
  becomes a dropped ball on its spot (:meth:`Referee._drop_ball`); the match may end early
  (:meth:`Referee.stop`, or a shorter ``end_cycle``) and may have no half time.
* **Events.** ``GOAL``: team = scoring team, player = last toucher (of the other team on an
  own goal, then ``detail`` = 1). ``OUT``: team/player = last toucher, detail 0 for a
  touchline, 1 for a goal line. ``PASS``: team/player = passer, detail = receiver index; a
  pass begins with a kick (a ball bouncing off one player's body to a team-mate is not a
  pass) and is received by a team-mate's kick, body touch or catch.
  ``TOUCH``: a body touch, recorded once per continuous contact. ``SET_PLAY``: team = mode
  team (NO_TEAM in play on), player = the kicker when a kick started play on, detail = the
  PlayMode value. ``DROP_BALL``: detail = the set play that timed out. ``OFFSIDE``: the
  offender and its position. ``SHOT``: the first kicker of the shooting team (also has its
  ``KICK`` event), detail 0. Every goal is also a shot: a goal not preceded by a SHOT of the
  scoring team since the opponents last played the ball (a kick whose noiseless path fell
  short or wide, but the ball's noise carried it in, or a goal off a body) records a SHOT
  with detail 1 in the goal's cycle, just before the GOAL, for the scorer, at the spot
  where its team last played the ball. Other event positions are the ball's, absolute frame.
"""

from __future__ import annotations

import math

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.offside import mark_offside_positions
from soccer_sim.restarts import (
    clamp_into_own_half,
    clamp_into_penalty_area,
    corner_spot,
    goal_kick_spot,
    in_penalty_area,
    keep_in_own_half,
    line_crossing,
    mirror_into_own_half,
    out_of_goal_area,
    push_out_of_penalty_area,
    penalty_area_edge_spot,
    push_clear_of_spot,
    push_out_of_circle,
)
from soccer_sim.state import (
    AWAY,
    HOME,
    NO_PLAYER,
    NO_TEAM,
    SET_PLAYS,
    EventKind,
    EventLog,
    PlayMode,
    WorldState,
)

_PLAY_ON = PlayMode.PLAY_ON
_KICK_OFF = PlayMode.KICK_OFF
_GOALIE_HOLDS = PlayMode.GOALIE_HOLDS
_TIME_OVER = PlayMode.TIME_OVER
_AFTER_GOAL = PlayMode.AFTER_GOAL
_GOAL_KICK = PlayMode.GOAL_KICK
_OFFSIDE_MODES = frozenset({PlayMode.PLAY_ON, PlayMode.FREE_KICK, PlayMode.KICK_OFF, PlayMode.GOALIE_HOLDS})
"""Modes in which a kick can put team-mates offside (not kick-ins, corners, goal kicks)."""
_NEVER = -(10**9)
_DROP_INSET = 1.0
"""Without set plays, a ball dropped in place of a restart lies at least this far (m) inside
the lines (a kick-in's spot on the touchline would be out again at the slightest touch)."""


class Referee:
    """Applies the rules of the game to a :class:`WorldState`, recording events in ``events``.

    One referee serves one match; it keeps a little memory between cycles (the set-play spot,
    offside marks, catch bans, the last player on the ball for passes, the ball's previous
    position to tell where it crossed a line).
    """

    def __init__(self, config: MatchConfig, events: EventLog, sizes: tuple[int, int] | None = None,
                 goalies: tuple[int, int] | None = None, *, set_plays: bool = True, end_cycle: int | None = None,
                 half_time: bool = True) -> None:
        """``sizes``: (home, away) players (None: ``config.players_per_team`` each);
        ``goalies``: each side's goalkeeper index within its side, -1 for none (None:
        ``config.rules.goalie_index`` for both); ``set_plays`` False replaces every restart by a
        dropped ball on the restart spot (see :meth:`_restart`); ``end_cycle``: time over after
        this many cycles (None: ``config.total_cycles``); ``half_time`` False: no half time (one
        period, no change of ends)."""
        self.config = config
        self.events = events
        f, p, r = config.field, config.physics, config.rules
        n = config.players_per_team
        home, away = (n, n) if sizes is None else (int(sizes[0]), int(sizes[1]))
        n2 = home + away
        self._n = home
        """Home players: rows below it are home's, the others away's."""
        self._sizes = (home, away)
        self._first = (0, home)
        """Row of each team's first player."""
        self._rows = (slice(0, home), slice(home, n2))
        self._set_plays = bool(set_plays)
        self._goal_x = f.half_length + p.ball_radius  # whole ball beyond the goal line
        self._touch_y = f.half_width + p.ball_radius  # whole ball beyond the touchline
        self._post_y = f.goal_width / 2.0
        self._clearance = r.set_play_clearance
        self._offside_reach2 = None if r.offside_active_distance is None else r.offside_active_distance ** 2
        self._kick_off_radius = max(r.set_play_clearance, f.centre_circle_radius)
        self._half_end = r.half_cycles if half_time else -1
        self._match_end = config.total_cycles if end_cycle is None else int(end_cycle)
        goalies = (r.goalie_index, r.goalie_index) if goalies is None else goalies
        self._goalie_rows = tuple(NO_PLAYER if g is None or g < 0 else self._first[t] + int(g)
                                  for t, g in enumerate(goalies))
        """Each team's goalkeeper row, NO_PLAYER if it has none."""
        home_rows = np.repeat([1.0, -1.0], [home, away])
        self._row_direction = {1: home_rows, -1: -home_rows}
        """Attack direction of every player row, keyed by ``state.home_attacks``."""
        self._shot_reach = 1.0 / (1.0 - p.ball_decay) if p.ball_decay < 1.0 else math.inf
        # Cached read-only kick masks (kick_mask returns one of these, never a new array).
        self._mask_all = self._frozen(np.ones(n2, dtype=bool))
        self._mask_none = self._frozen(np.zeros(n2, dtype=bool))
        team_masks = []
        for team in (HOME, AWAY):
            m = np.zeros(n2, dtype=bool)
            m[self._rows[team]] = True
            team_masks.append(self._frozen(m))
        self._mask_team = tuple(team_masks)
        self._mask_row = []
        for row in range(n2):
            m = np.zeros(n2, dtype=bool)
            m[row] = True
            self._mask_row.append(self._frozen(m))
        # Memory between cycles.
        self._spot = (0.0, 0.0)
        self._spot_owner: tuple[int, int, int] | None = None
        """(mode, team, start) of the set play ``_spot`` belongs to; a set play the referee did
        not begin itself (a state built or loaded elsewhere) takes the ball's position as spot."""
        self._prev_ball = (math.nan, math.nan)
        self._offside = np.zeros(n2, dtype=bool)
        self._offside_pending = False
        self._offside_rows = np.zeros(0, dtype=np.int64)
        """Rows of ``_offside`` that are marked (while ``_offside_pending``)."""
        self._last_catch_attempt = [_NEVER, _NEVER]
        self._pass_from = NO_PLAYER
        """Row of the player whose kick the ball is travelling from (a pass begins with a kick),
        or NO_PLAYER."""
        self._shot_pending = [False, False]
        """Per team: its latest kick was a SHOT and the opponents have not played the ball since."""
        self._play_spot = [(math.nan, math.nan), (math.nan, math.nan)]
        """Per team: where the ball was when the team last played it (kick, touch or catch)."""
        self._touching: tuple[int, ...] = ()
        self._offside_line = 0.0
        """x of the offside line (absolute frame) when the current marks were made."""
        self._stuck_cycles = r.stuck_ball_cycles
        self._stuck_radius2 = r.stuck_ball_radius ** 2
        self._goal_kick_pending: tuple[int, float, float, int] | None = None
        """(team, spot, taker's row) of a goal kick taken whose ball has not yet left the
        penalty area."""
        self._goal_kick_retakes = 0
        """Retakes in a row of the current goal kick for its own team's fault (``max_goal_kicks``)."""
        self._stuck_anchor = (math.nan, math.nan)
        self._stuck_since = 0
        """The ball has stayed within ``stuck_ball_radius`` of ``_stuck_anchor`` since this cycle."""

    @staticmethod
    def _frozen(a: np.ndarray) -> np.ndarray:
        a.flags.writeable = False
        return a

    # ------------------------------------------------------------------ public API

    def start(self, state: WorldState, mode: PlayMode = PlayMode.KICK_OFF, team: int = HOME) -> None:
        """Open play in ``mode`` (SET_PLAY event). The default, the opening kick-off: ``team``
        (home) kicks off, ball still on the centre spot, every player moved into its own half
        and the other team out of the centre circle. Another set play (kick-in, corner kick,
        goal kick, free kick) belongs to ``team`` and is taken where the ball lies, the
        opponents cleared from it. ``PLAY_ON``: the ball and the players as they are."""
        self._check_state(state)
        if mode == _KICK_OFF:
            self._kick_off(state, team, first_cycle=state.cycle)
        elif mode == _PLAY_ON:
            self._prev_ball = (float(state.ball[0]), float(state.ball[1]))
            self._set_mode(state, _PLAY_ON, NO_TEAM, first_cycle=state.cycle)
        elif mode in SET_PLAYS:
            self._restart(state, mode, team, float(state.ball[0]), float(state.ball[1]), first_cycle=state.cycle)
        else:
            raise ValueError(f"play cannot start in {PlayMode(mode).name}; start with a set play or PLAY_ON")

    def stop(self, state: WorldState) -> None:
        """End the match after the cycle being judged (a scenario's end condition was met):
        TIME_OVER event and play mode, as at the end of the last cycle."""
        if state.play_mode != _TIME_OVER:
            self._time_over(state)

    def kick_mask(self, state: WorldState) -> np.ndarray:
        """(2n,) bool: which players may kick now. Returns a cached read-only array.

        Play on: everybody. Set plays: the mode team. Goalkeeper holding: the holder only.
        Time over: nobody.
        """
        mode = state.play_mode
        if mode == _PLAY_ON:
            return self._mask_all
        if mode == _GOALIE_HOLDS:
            holder = state.ball_holder
            row = holder if holder != NO_PLAYER else self._goalie_rows[state.mode_team]
            return self._mask_row[row] if row != NO_PLAYER else self._mask_none
        if mode == _TIME_OVER or mode == _AFTER_GOAL or state.mode_team == NO_TEAM:
            return self._mask_none
        return self._mask_team[state.mode_team]

    def apply_moves(self, state: WorldState, team: int, targets: np.ndarray) -> None:
        """KICK_OFF (before the kick) and AFTER_GOAL only: teleport ``team``'s players to
        ``targets`` ((n, 2), absolute frame), clamped into the team's own half of the field
        (lines included), the team not kicking off kept out of the centre circle. Moved players
        stop. Ignored in any other play mode."""
        if state.play_mode != _KICK_OFF and state.play_mode != _AFTER_GOAL:
            return
        n = self._sizes[team]
        targets = np.asarray(targets, dtype=float)
        if targets.shape != (n, 2) or not np.isfinite(targets).all():
            raise ValueError(f"kick-off move targets for team {team} must be a finite ({n}, 2) array, "
                             f"got shape {targets.shape}")
        rows = self._rows[team]
        block = state.pos[rows]
        block[:] = targets
        clamp_into_own_half(block, state.attack_direction(team), self.config.field)
        if team != state.mode_team:
            direction = state.attack_direction(team)
            push_out_of_circle(block, 0.0, 0.0, self._kick_off_radius, (-float(direction), 0.0))
        state.vel[rows] = 0.0

    def on_commands(self, state: WorldState, kickers: np.ndarray, catch_requests: np.ndarray) -> None:
        """Judge this cycle's kicks (already applied to ``state.ball_vel``) and catch requests.

        ``kickers``: int array of the player rows whose kick was applied. ``catch_requests``:
        (2,) bool, whether the home / away goalkeeper asked to catch.
        """
        has_kick = len(kickers) > 0
        if not has_kick and not (catch_requests[0] or catch_requests[1]):
            return
        if state.play_mode == _TIME_OVER:
            return
        if has_kick:
            self._judge_kicks(state, sorted(int(row) for row in kickers))
        for team in (HOME, AWAY):
            if catch_requests[team]:
                self._judge_catch(state, team, kickers)

    def after_step(self, state: WorldState, touchers: np.ndarray) -> None:
        """Judge the cycle after the physics step: touches, goals, outs, offside, set plays,
        the goalkeeper's holding time, half time and time over. ``touchers``: int array of the
        rows whose body touched the ball during the step."""
        mode = state.play_mode
        if mode == _TIME_OVER:
            return
        if mode == _PLAY_ON:
            if len(touchers):
                self._judge_touches(state, touchers)
            elif self._touching:
                self._touching = ()
            bx, by = state.ball.tolist()
            if bx > self._goal_x or bx < -self._goal_x or by > self._touch_y or by < -self._touch_y:
                self._ball_left_field(state, bx, by)
            else:
                if self._offside_pending and self._offside_reach2 is not None:
                    self._check_offside_approach(state)
                if self._goal_kick_pending is not None:
                    self._check_goal_kick_left_area(state, bx, by)
                if self._stuck_cycles is not None and state.play_mode == _PLAY_ON:
                    self._check_stuck_ball(state, bx, by)
        elif mode == _GOALIE_HOLDS:
            self._keep_holder_in_area(state)
        elif mode == _AFTER_GOAL:
            self._keep_goal_pause(state)
        else:
            self._keep_set_play(state)
        cycles_done = state.cycle + 1
        if cycles_done >= self._match_end:
            self._time_over(state)
        elif cycles_done == self._half_end:
            self._half_time(state)
        ball = state.ball
        self._prev_ball = (float(ball[0]), float(ball[1]))

    # ------------------------------------------------------------------ play modes

    def _set_mode(self, state: WorldState, mode: PlayMode, team: int, *, player: int = NO_PLAYER,
                  first_cycle: int | None = None) -> None:
        """Switch the play mode and record the SET_PLAY event."""
        state.play_mode = mode
        state.mode_team = team if mode != _PLAY_ON else NO_TEAM
        state.mode_start = state.cycle + 1 if first_cycle is None else first_cycle
        self._stuck_anchor = (float(state.ball[0]), float(state.ball[1]))
        self._stuck_since = state.mode_start
        self._spot_owner = (mode, state.mode_team, state.mode_start)
        self.events.add(state.cycle, EventKind.SET_PLAY, state.mode_team, player,
                        float(state.ball[0]), float(state.ball[1]), int(mode))

    def _restart(self, state: WorldState, mode: PlayMode, team: int, x: float, y: float,
                 first_cycle: int | None = None) -> None:
        """Begin a set play for ``team`` with the ball still at (x, y); forget the offside
        marks and the passer (a restart interrupts every pass). Without set plays (other than
        the opening one) the ball is dropped there instead (:meth:`_drop_ball`)."""
        if not self._set_plays and first_cycle is None:
            self._drop_ball(state, mode, x, y)
            return
        self._spot = (x, y)
        self._place_ball(state, x, y)
        self._set_mode(state, mode, team, first_cycle=first_cycle)
        if mode == _AFTER_GOAL:
            self._keep_goal_pause(state)
        else:
            self._keep_set_play(state)

    def _drop_ball(self, state: WorldState, replaced: PlayMode, x: float, y: float) -> None:
        """Without set plays: the ball is put still on the spot of the restart it replaces
        (``replaced``), moved at least ``_DROP_INSET`` inside the lines, and play goes on at
        once, open to both teams; nobody is moved. DROP_BALL event (detail: ``replaced``)."""
        f = self.config.field
        x_max, y_max = max(f.half_length - _DROP_INSET, 0.0), max(f.half_width - _DROP_INSET, 0.0)
        x, y = min(max(x, -x_max), x_max), min(max(y, -y_max), y_max)
        self.events.add(state.cycle, EventKind.DROP_BALL, NO_TEAM, NO_PLAYER, x, y, int(replaced))
        self._place_ball(state, x, y)
        self._set_mode(state, _PLAY_ON, NO_TEAM)

    def _place_ball(self, state: WorldState, x: float, y: float) -> None:
        """Put the ball still at (x, y) for a restart; forget the holder, the offside marks,
        the passer (a restart interrupts every pass), pending shots, touches and goal kick."""
        state.ball[0], state.ball[1] = x, y
        state.ball_vel[:] = 0.0
        state.ball_holder = NO_PLAYER
        self._clear_offside()
        self._pass_from = NO_PLAYER
        self._shot_pending = [False, False]
        self._touching = ()
        self._goal_kick_pending = None
        self._prev_ball = (x, y)

    def _kick_off(self, state: WorldState, team: int, first_cycle: int | None = None, *,
                  after_pause: bool = False) -> None:
        """Kick-off for ``team``: ball on the centre spot, everybody stopped, both teams in
        their own halves. Players in the wrong half are put on the halfway line after the
        pause that follows a goal (they had the pause to get back), else reflected across it.
        Without set plays (other than the opening kick-off) the ball is dropped on the centre
        spot and nobody is moved."""
        if not self._set_plays and first_cycle is None:
            state.last_touch = NO_PLAYER
            self._drop_ball(state, _KICK_OFF, 0.0, 0.0)
            return
        directions = self._row_direction[state.home_attacks]
        if after_pause:
            keep_in_own_half(state.pos, directions)
        else:
            mirror_into_own_half(state.pos, directions)
        state.vel[:] = 0.0
        state.last_touch = NO_PLAYER
        self._restart(state, _KICK_OFF, team, 0.0, 0.0, first_cycle)

    def _keep_set_play(self, state: WorldState) -> None:
        """Every cycle of a set play: ball still on its spot, opponents cleared, kick-off halves
        kept; after ``set_play_timeout`` cycles the ball is dropped (play on)."""
        if self._spot_owner != (state.play_mode, state.mode_team, state.mode_start):
            self._spot = (float(state.ball[0]), float(state.ball[1]))
            self._spot_owner = (state.play_mode, state.mode_team, state.mode_start)
        sx, sy = self._spot
        state.ball[0], state.ball[1] = sx, sy
        state.ball_vel[:] = 0.0
        other = 1 - state.mode_team
        rows = self._rows[other]
        if state.play_mode == _KICK_OFF:
            self._keep_kick_off_positions(state, other, sx, sy)
        else:
            block = state.pos[rows]
            moved = push_clear_of_spot(block, sx, sy, self._clearance, self.config.field)
            if moved is not None:
                state.vel[rows][moved] = 0.0
            if state.play_mode == _GOAL_KICK and self.config.rules.goal_kick_leaves_area:
                # Opponents leave the penalty area too (from a goal kick's spot its lines are
                # beyond the clearance; the second push keeps the clearance for any spot).
                moved = push_out_of_penalty_area(block, -state.attack_direction(other), self.config.field)
                if moved is not None:
                    state.vel[rows][moved] = 0.0
                    push_clear_of_spot(block, sx, sy, self._clearance, self.config.field)
        if state.cycle - state.mode_start + 1 >= self.config.rules.set_play_timeout:
            self.events.add(state.cycle, EventKind.DROP_BALL, NO_TEAM, NO_PLAYER, sx, sy, int(state.play_mode))
            self._set_mode(state, _PLAY_ON, NO_TEAM)

    def _keep_kick_off_positions(self, state: WorldState, other: int, sx: float, sy: float) -> None:
        """Both teams in their own half (offenders put on the halfway line), the team not
        kicking off outside the centre circle (pushed radially); moved players stop."""
        pos = state.pos
        rows = self._rows[other]
        moved = keep_in_own_half(pos, self._row_direction[state.home_attacks])
        if moved is not None:
            state.vel[moved] = 0.0
        fallback = (-float(state.attack_direction(other)), 0.0)
        pushed = push_out_of_circle(pos[rows], sx, sy, self._kick_off_radius, fallback)
        if pushed is not None:
            state.vel[rows][pushed] = 0.0

    def _keep_goal_pause(self, state: WorldState) -> None:
        """Every cycle of the pause after a goal: the ball waits on the centre spot; at the end
        of the pause the team that conceded kicks off."""
        state.ball[:] = 0.0
        state.ball_vel[:] = 0.0
        if state.cycle - state.mode_start + 1 >= self.config.rules.goal_pause_cycles:
            self._kick_off(state, state.mode_team, after_pause=True)

    def _half_time(self, state: WorldState) -> None:
        """Swap ends: every player position rotated by 180° about the centre spot; away kicks off
        (the kick-off stops the ball and the players)."""
        self.events.add(state.cycle, EventKind.HALF_TIME, NO_TEAM, NO_PLAYER,
                        float(state.ball[0]), float(state.ball[1]), 0)
        state.half = 1
        state.home_attacks = -state.home_attacks
        np.negative(state.pos, out=state.pos)
        self._last_catch_attempt = [_NEVER, _NEVER]
        self._kick_off(state, AWAY)

    def _time_over(self, state: WorldState) -> None:
        self.events.add(state.cycle, EventKind.TIME_OVER, NO_TEAM, NO_PLAYER,
                        float(state.ball[0]), float(state.ball[1]), 0)
        state.ball_holder = NO_PLAYER
        self._clear_offside()
        self._set_mode(state, _TIME_OVER, NO_TEAM)

    # ------------------------------------------------------------------ ball out, goals

    def _ball_left_field(self, state: WorldState, bx: float, by: float) -> None:
        """The whole ball is beyond a goal line or touchline: goal, kick-in, corner or goal kick."""
        px, py = self._prev_ball
        line, x, y = line_crossing(px, py, bx, by, self._goal_x, self._touch_y)
        f = self.config.field
        last = state.last_touch
        last_team = state.team_of(last) if last != NO_PLAYER else NO_TEAM
        last_index = last - last_team * self._n if last != NO_PLAYER else NO_PLAYER
        if line == "goal_line":
            goal_side = 1 if x > 0 else -1
            defender = HOME if state.attack_direction(HOME) == -goal_side else AWAY
            attacker = 1 - defender
            if abs(y) < self._post_y:
                self._goal(state, attacker, last_team, last_index, x, y)
                return
            self.events.add(state.cycle, EventKind.OUT, last_team, last_index, x, y, 1)
            if last_team == defender:
                sx, sy = corner_spot(f, goal_side, y, self.config.rules.corner_inset)
                self._restart(state, PlayMode.CORNER_KICK, attacker, sx, sy)
            else:
                sx, sy = goal_kick_spot(f, goal_side, y)
                self._goal_kick_retakes = 0
                self._restart(state, PlayMode.GOAL_KICK, defender, sx, sy)
            return
        self.events.add(state.cycle, EventKind.OUT, last_team, last_index, x, y, 0)
        x = min(max(x, -f.half_length), f.half_length)
        y = math.copysign(f.half_width, y)
        if last_team == NO_TEAM:
            taker = HOME if state.attack_direction(HOME) * x <= 0.0 else AWAY
        else:
            taker = 1 - last_team
        self._restart(state, PlayMode.KICK_IN, taker, x, y)

    def _goal(self, state: WorldState, scorer: int, last_team: int, last_index: int, x: float, y: float) -> None:
        own_goal = last_team != NO_TEAM and last_team != scorer
        if last_team == scorer and not self._shot_pending[scorer]:
            # Every goal is a shot, also one whose kick looked short of the line or wide when it
            # was taken (the ball's noise carried it in) or that went in off a body.
            sx, sy = self._play_spot[scorer]
            self.events.add(state.cycle, EventKind.SHOT, scorer, last_index, sx, sy, 1)
        state.score[scorer] += 1
        self.events.add(state.cycle, EventKind.GOAL, scorer, last_index, x, y, int(own_goal))
        if not self._set_plays:
            state.last_touch = NO_PLAYER
            self._drop_ball(state, _KICK_OFF, 0.0, 0.0)
        elif self.config.rules.goal_pause_cycles > 0:
            self._restart(state, _AFTER_GOAL, 1 - scorer, 0.0, 0.0)
        else:
            self._kick_off(state, 1 - scorer)

    # ------------------------------------------------------------------ kicks, touches, passes

    def _judge_kicks(self, state: WorldState, rows: list[int]) -> None:
        """KICK (and SHOT / PASS) events, set plays taken, held balls released, offside marks.
        ``rows``: the kickers' rows, sorted."""
        n = self._n
        mode = state.play_mode
        bx, by = state.ball.tolist()
        for row in rows:
            team = HOME if row < n else AWAY
            self.events.add(state.cycle, EventKind.KICK, team, row - team * n, bx, by, 0)
        if self._offside_pending:
            for row in rows:
                if self._offside[row]:
                    self._call_offside(state, row)
                    return
        if self._goal_kick_pending is not None and self._goal_kick_played_early(state, rows):
            return
        self._played(state, rows, state.last_touch, bx, by, kicked=True)
        teams = sorted({HOME if row < n else AWAY for row in rows})
        for team in teams:
            shot = self._is_shot(state, team, bx, by)
            self._shot_pending[team] = shot
            if shot:
                shooter = next(r for r in rows if (HOME if r < n else AWAY) == team)
                self.events.add(state.cycle, EventKind.SHOT, team, shooter - team * n, bx, by, 0)
        if mode == _GOALIE_HOLDS:
            state.ball_holder = NO_PLAYER
        if mode != _PLAY_ON:
            first = rows[0]
            self._set_mode(state, _PLAY_ON, NO_TEAM, player=first - state.team_of(first) * n)
            if mode == _GOAL_KICK and self.config.rules.goal_kick_leaves_area:
                self._goal_kick_pending = (state.team_of(first), bx, by, first)
        self._judge_offside_positions(state, rows, mode, bx)

    def _played(self, state: WorldState, rows: list[int], main: int, x: float, y: float, *,
                kicked: bool = False) -> None:
        """``rows`` (sorted) played the ball together at (x, y) this cycle (``kicked``: by a kick,
        else by a body touch or a catch), ``main`` (one of them if possible) counting as the
        player now on the ball. A PASS event if the ball comes from the kick of a team-mate of
        ``main`` that is not among ``rows``. A kick can start the next pass; a touch by anyone
        but the passer ends the pass (a ball bouncing between team-mates is not passed). The
        opponents of the players in ``rows`` lose their pending shot."""
        if main not in rows:
            main = rows[0]
        prev = self._pass_from
        n = self._n
        if prev != NO_PLAYER and prev not in rows and (prev < n) == (main < n):
            team = HOME if main < n else AWAY
            self.events.add(state.cycle, EventKind.PASS, team, prev - team * n, x, y, main - team * n)
        if kicked:
            self._pass_from = main
        elif prev not in rows:
            self._pass_from = NO_PLAYER
        involved = (rows[0] < n, rows[-1] >= n)  # home / away players among rows (sorted)
        for team in (HOME, AWAY):
            if involved[team]:
                self._play_spot[team] = (x, y)
                self._shot_pending[1 - team] = False

    def _judge_touches(self, state: WorldState, touchers: np.ndarray) -> None:
        """Body touches in play on: offside, TOUCH and PASS events, last touch (the toucher
        nearest the ball when several touched it)."""
        rows = sorted(set(int(r) for r in touchers))
        n = self._n
        bx, by = float(state.ball[0]), float(state.ball[1])
        if self._offside_pending:
            for row in rows:
                if self._offside[row]:
                    self._call_offside(state, row)
                    return
        if self._goal_kick_pending is not None and self._goal_kick_played_early(state, rows):
            return
        self._judge_offside_positions(state, rows, _PLAY_ON, bx)
        previous = self._touching
        for row in rows:
            if row not in previous:
                team = HOME if row < n else AWAY
                self.events.add(state.cycle, EventKind.TOUCH, team, row - team * n, bx, by, 0)
        if len(rows) == 1:
            nearest = rows[0]
        else:
            d = np.hypot(state.pos[rows, 0] - bx, state.pos[rows, 1] - by)
            nearest = rows[int(np.argmin(d))]
        state.last_touch = nearest
        self._played(state, rows, nearest, bx, by)
        self._touching = tuple(rows)

    def _is_shot(self, state: WorldState, team: int, bx: float, by: float) -> bool:
        """Whether the ball's unhindered path (decaying geometrically) takes the whole ball over
        the goal line of ``team``'s opponents between the posts."""
        direction = state.attack_direction(team)
        vx, vy = float(state.ball_vel[0]), float(state.ball_vel[1])
        if direction * vx <= 0.0:
            return False
        t = (direction * self._goal_x - bx) / vx  # path parameter, in units of the kick velocity
        if t < 0.0 or t >= self._shot_reach:
            return False
        return abs(by + t * vy) < self._post_y

    # ------------------------------------------------------------------ offside

    def _judge_offside_positions(self, state: WorldState, rows: list[int], mode: PlayMode, ball_x: float) -> None:
        """``rows`` played the ball (kick or body touch) in ``mode``: when they are of one team
        and the mode allows offside, mark their team-mates in offside positions afresh;
        otherwise clear all marks."""
        n = self._n
        team = HOME if rows[0] < n else AWAY
        one_team = (rows[-1] < n) == (team == HOME)
        if self.config.rules.offside and one_team and mode in _OFFSIDE_MODES:
            line = mark_offside_positions(
                state.pos, self._sizes, team, state.attack_direction(team), ball_x, rows, self._offside)
            self._offside_pending = line is not None
            if line is not None:
                self._offside_rows = np.flatnonzero(self._offside)
                self._offside_line = line
        else:
            self._clear_offside()

    def _clear_offside(self) -> None:
        if self._offside_pending:
            self._offside[:] = False
            self._offside_pending = False

    def _check_offside_approach(self, state: WorldState) -> None:
        """A marked player within ``offside_active_distance`` of the ball is penalised (the
        nearest, if several are)."""
        rows = self._offside_rows
        diff = state.pos[rows] - state.ball
        d2 = (diff * diff).sum(axis=1)
        nearest = int(d2.argmin())
        if d2[nearest] <= self._offside_reach2:
            self._call_offside(state, int(rows[nearest]))

    def _call_offside(self, state: WorldState, row: int) -> None:
        """OFFSIDE event (at the offender's position) and an indirect free kick for the
        defenders on the offside line (as it was when the ball was played), level with the
        offender."""
        n = self._n
        team = HOME if row < n else AWAY
        f = self.config.field
        x = min(max(float(state.pos[row, 0]), -f.half_length), f.half_length)
        y = min(max(float(state.pos[row, 1]), -f.half_width), f.half_width)
        self.events.add(state.cycle, EventKind.OFFSIDE, team, row - team * n, x, y, 0)
        self._restart(state, PlayMode.FREE_KICK, 1 - team, self._offside_line, y)

    # ------------------------------------------------------------------ goal kicks, stuck ball

    def _check_goal_kick_left_area(self, state: WorldState, bx: float, by: float) -> None:
        """The goal kick's ball is in play once it has left the penalty area."""
        team = self._goal_kick_pending[0]
        if not in_penalty_area(self.config.field, state.attack_direction(team), bx, by):
            self._goal_kick_pending = None

    def _goal_kick_played_early(self, state: WorldState, rows: list[int]) -> bool:
        """``rows`` (sorted) played the ball of a goal kick before it left the penalty area.
        An opponent among them retakes the goal kick (not counted against the team); a
        team-mate of the taker retakes it with ``proper_goal_kicks`` (counted, a free kick for
        the opponents once ``max_goal_kicks`` retakes in a row are used up), else puts the ball
        in play; the taker alone changes nothing. Returns whether play was restarted."""
        team, x, y, taker = self._goal_kick_pending
        rules = self.config.rules
        if any(state.team_of(row) != team for row in rows):
            self._goal_kick_retakes = 0
            self._restart(state, _GOAL_KICK, team, x, y)
            return True
        if all(row == taker for row in rows):
            return False
        if not rules.proper_goal_kicks:
            self._goal_kick_pending = None
            return False
        if self._goal_kick_retakes >= rules.max_goal_kicks:
            self._goal_kick_retakes = 0
            fx, fy = penalty_area_edge_spot(self.config.field, state.attack_direction(team),
                                            float(state.ball[0]), float(state.ball[1]))
            self._restart(state, PlayMode.FREE_KICK, 1 - team, fx, fy)
            return True
        self._goal_kick_retakes += 1
        self._restart(state, _GOAL_KICK, team, x, y)
        return True

    def _check_stuck_ball(self, state: WorldState, bx: float, by: float) -> None:
        """Drop the ball where it lies when it has stayed within ``stuck_ball_radius`` for
        ``stuck_ball_cycles`` cycles of play on: DROP_BALL event (detail PLAY_ON), every player
        within that radius pushed out to it, play goes on with the ball still."""
        ax, ay = self._stuck_anchor
        if not (bx - ax) ** 2 + (by - ay) ** 2 <= self._stuck_radius2:  # (also when no anchor yet: NaN)
            self._stuck_anchor = (bx, by)
            self._stuck_since = state.cycle
            return
        if state.cycle - self._stuck_since + 1 < self._stuck_cycles:
            return
        self.events.add(state.cycle, EventKind.DROP_BALL, NO_TEAM, NO_PLAYER, bx, by, int(_PLAY_ON))
        radius = self.config.rules.stuck_ball_radius
        moved = push_clear_of_spot(state.pos, bx, by, radius, self.config.field)
        if moved is not None:
            state.vel[moved] = 0.0
        state.ball_vel[:] = 0.0
        self._clear_offside()
        self._pass_from = NO_PLAYER
        self._touching = ()
        self._stuck_anchor = (bx, by)
        self._stuck_since = state.cycle + 1

    # ------------------------------------------------------------------ goalkeeper

    def _judge_catch(self, state: WorldState, team: int, kickers: np.ndarray) -> None:
        """A catch request by ``team``'s goalkeeper (see the module docstring for the area)."""
        if state.play_mode != _PLAY_ON or state.ball_holder != NO_PLAYER:
            return
        rows = self._goalie_rows
        row = rows[team]
        if row == NO_PLAYER or row in kickers:
            return
        if state.cycle - self._last_catch_attempt[team] <= self.config.rules.catch_ban_cycles:
            return
        f = self.config.field
        direction = state.attack_direction(team)
        gx, gy = float(state.pos[row, 0]), float(state.pos[row, 1])
        bx, by = float(state.ball[0]), float(state.ball[1])
        if not (in_penalty_area(f, direction, gx, gy) and in_penalty_area(f, direction, bx, by)):
            return  # not a catch situation: no attempt, no ban
        self._last_catch_attempt[team] = state.cycle
        if math.hypot(bx - gx, by - gy) > self.config.rules.catch_length:
            return
        n = self._n
        passer = self._pass_from
        if (self.config.rules.back_pass_rule and passer != NO_PLAYER and passer != row
                and state.team_of(passer) == team):
            self.events.add(state.cycle, EventKind.BACK_PASS, team, row - team * n, bx, by, passer - team * n)
            x, y = out_of_goal_area(f, direction, bx, by)
            self._restart(state, PlayMode.FREE_KICK, 1 - team, x, y)
            return
        self._clear_offside()
        self._played(state, [row], row, bx, by)
        state.last_touch = row
        state.ball_holder = row
        state.ball_vel[:] = 0.0
        state.ball[0], state.ball[1] = gx, gy
        self.events.add(state.cycle, EventKind.CATCH, team, row - team * n, bx, by, 0)
        self._set_mode(state, _GOALIE_HOLDS, team, player=row - team * n)

    def _keep_holder_in_area(self, state: WorldState) -> None:
        """Keep the holding goalkeeper (and the ball) in its penalty area; punish holding too long."""
        row = state.ball_holder
        team = state.mode_team
        f = self.config.field
        direction = state.attack_direction(team)
        if row == NO_PLAYER:
            row = self._goalie_rows[team]
        gx, gy = clamp_into_penalty_area(f, direction, float(state.pos[row, 0]), float(state.pos[row, 1]))
        state.pos[row, 0], state.pos[row, 1] = gx, gy
        state.ball[0], state.ball[1] = gx, gy
        state.ball_vel[:] = 0.0
        if state.cycle - state.mode_start + 1 >= self.config.rules.goalie_hold_cycles:
            x, y = penalty_area_edge_spot(f, direction, gx, gy)
            self._restart(state, PlayMode.FREE_KICK, 1 - team, x, y)

    # ------------------------------------------------------------------ checks

    def _check_state(self, state: WorldState) -> None:
        home, away = self._sizes
        n2 = home + away
        for name, shape in (("pos", (n2, 2)), ("vel", (n2, 2)), ("ball", (2,)), ("ball_vel", (2,))):
            arr = getattr(state, name)
            if getattr(arr, "shape", None) != shape:
                sides = f"{home} players per team" if home == away else f"{home} home and {away} away players"
                raise ValueError(f"WorldState.{name} must have shape {shape} for {sides}, "
                                 f"got {getattr(arr, 'shape', type(arr).__name__)}")
        if tuple(state.sizes) != self._sizes:
            raise ValueError(f"WorldState.sizes must be {self._sizes} (home, away players), got {state.sizes}")
