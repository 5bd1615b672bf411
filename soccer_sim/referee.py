"""The referee: the rules of :mod:`soccer_sim.rules` put together for the match loop.

The match loop calls the referee at fixed points of every cycle (see soccer_sim.match):
``kick_mask`` before kicks are applied, ``on_commands`` after them (with the players whose
kick was applied and the goalkeepers' catch requests), ``apply_moves`` for kick-off
placement, and ``after_step`` once the physics has moved everything. The referee reads and
writes the :class:`~soccer_sim.state.WorldState` arrays directly (absolute frame, metres,
metres per cycle) and appends to the :class:`~soccer_sim.state.EventLog`.

It holds a play-mode state machine (:class:`~soccer_sim.rules.play_modes.PlayModes`: set
plays, restarts, kick-offs, the pause after a goal, time) and a list of judges, one per rule,
each receiving the same hooks (:mod:`soccer_sim.rules.judge`), as rcssserver's ``Stadium``
holds its ``Referee`` subclasses. In order: :class:`~soccer_sim.rules.restarts.BallOutJudge`
(goals, the ball out), :class:`~soccer_sim.rules.offside.OffsideJudge` (with
``RuleConfig.offside``), :class:`~soccer_sim.rules.goal_kick.GoalKickJudge` (with
``goal_kick_leaves_area``), :class:`~soccer_sim.rules.restarts.TouchJudge` (last touch),
:class:`~soccer_sim.analysis.plays.PlayAnalysis` (PASS and SHOT events),
:class:`~soccer_sim.rules.goalkeeper.GoalkeeperJudge` (catch, hold, back pass),
:class:`~soccer_sim.rules.stuck_ball.BallStuckJudge` (unless ``stuck_ball_cycles`` is None)
and :class:`~soccer_sim.rules.fouls.FoulJudge` (fouls and cards after tackles, with
``TackleConfig.enabled``). :meth:`Referee.add_judge` appends another.

Cycle bookkeeping: ``state.mode_start`` is the first cycle in which the teams act under the
current play mode. A mode set while judging cycle ``c`` starts at ``c + 1``; the opening
kick-off starts at the cycle of :meth:`Referee.start`. The first half is cycles
``0 .. half_cycles - 1``; half time is called in ``after_step`` of its last cycle, so the
second half begins at ``cycle == half_cycles``; time over is called in ``after_step`` of
the match's last cycle.

**Scenarios** (:mod:`soccer_sim.scenarios`): the sides may differ in size (player rows
``0..h-1`` home, the rest away) and a side may have no goalkeeper (no catch); play may open
with any set play or in play on (:meth:`Referee.start`); without set plays every restart
becomes a dropped ball on its spot (:meth:`~soccer_sim.rules.play_modes.PlayModes.drop_ball`); the match may end early
(:meth:`Referee.stop`, or a shorter ``end_cycle``) and may have no half time. All of this
comes from the match's :class:`~soccer_sim.setup.MatchSetup`; when time is up is decided by
its :class:`~soccer_sim.ending.MatchEnd`.

**Events.** ``KICK``: every kick applied. ``GOAL``: team = scoring team, player = last
toucher (of the other team on an own goal, then ``detail`` = 1). ``OUT``: team/player = last
toucher, detail 0 for a touchline, 1 for a goal line. ``TOUCH``: a body touch, recorded once
per continuous contact. ``SET_PLAY``: team = mode team (NO_TEAM in play on), player = the
kicker when a kick started play on, detail = the PlayMode value. ``DROP_BALL``: detail = the
set play that timed out. ``OFFSIDE``: the offender and its position. ``TACKLE``, ``FOUL``,
``YELLOW_CARD``, ``RED_CARD``: see :mod:`soccer_sim.tackles` and :mod:`soccer_sim.rules.fouls`.
``PASS`` and ``SHOT``: see :mod:`soccer_sim.analysis.plays`. Other event positions are the
ball's, absolute frame.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from soccer_sim.analysis.plays import PlayAnalysis
from soccer_sim.rules import (
    BallOutJudge,
    BallStuckJudge,
    FoulJudge,
    GoalKickJudge,
    GoalkeeperJudge,
    Hooks,
    Judge,
    OffsideJudge,
    PlayModes,
    TouchJudge,
)
from soccer_sim.setup import MatchSetup
from soccer_sim.state import AWAY, HOME, NO_PLAYER, EventKind, EventLog, PlayMode, WorldState

if TYPE_CHECKING:
    from soccer_sim.tackles import TackleOutcome

_PLAY_ON = PlayMode.PLAY_ON
_GOALIE_HOLDS = PlayMode.GOALIE_HOLDS
_TIME_OVER = PlayMode.TIME_OVER


class Referee:
    """Applies the rules of the game to a :class:`WorldState`, recording events in ``events``.

    One referee serves one match. ``modes`` is its play-mode state machine, ``judges`` its
    rules in the order they hear every hook.
    """

    def __init__(self, setup: MatchSetup, events: EventLog, rng: np.random.Generator | None = None,
                 types: np.ndarray | None = None) -> None:
        """``setup``: the match's sides, goalkeepers, rules on/off and end
        (:meth:`MatchSetup.resolve`; ``MatchSetup.resolve(config)`` for the regular match).
        ``rng``: the generator of the foul decisions and of the goalkeepers' catches in a
        stretched catchable area (the match's tackle generator; without one, fouls draw from
        a fixed seed, 0, and no catch is stretched). ``types``: each player row's type
        parameters (:attr:`soccer_sim.kinematics.Kinematics.types`; None: the configuration's
        default type for all)."""
        if not isinstance(setup, MatchSetup):
            raise TypeError(f"setup must be a MatchSetup (MatchSetup.resolve(config, scenario)), "
                            f"got {type(setup).__name__}")
        self.setup = setup
        self.config = config = setup.config
        self.events = events
        r = config.rules
        home = setup.sizes[0]
        self._n = home
        self._sizes = setup.sizes
        self.hooks = Hooks()
        self.modes = modes = PlayModes(setup, events, self.hooks)
        self.plays = PlayAnalysis(config, events, home)
        self.goalkeeper = GoalkeeperJudge(modes, self.plays.passer, rng, types)
        judges: list[Judge] = [BallOutJudge(modes)]
        if setup.offside:
            judges.append(OffsideJudge(modes))
        if r.goal_kick_leaves_area:
            judges.append(GoalKickJudge(modes))
        judges += [TouchJudge(modes), self.plays, self.goalkeeper]
        if r.stuck_ball_cycles is not None:
            judges.append(BallStuckJudge(modes))
        if config.tackles.enabled:
            judges.append(FoulJudge(modes, np.random.default_rng(0) if rng is None else rng, types))
        self.hooks.set(judges)
        self.kick_mask = modes.kick_mask
        """(2n,) bool: which players may kick now (:meth:`PlayModes.kick_mask`; a cached read-only
        array). Play on: everybody. Set plays: the mode team. Goalkeeper holding: the holder
        only. Time over: nobody."""
        self.apply_moves = modes.apply_moves
        """KICK_OFF (before the kick) and AFTER_GOAL only: teleport a team's players to targets
        ((n, 2), absolute frame), clamped into the team's own half of the field (lines
        included), the team not kicking off kept out of the centre circle. Moved players stop.
        Ignored in any other play mode (:meth:`PlayModes.apply_moves`)."""

    def holding_keeper(self, state: WorldState, team: int) -> int:
        """The row of ``team``'s goalkeeper if it holds the ball now (its ``TeamCommand.move``
        is then a body command, :meth:`move_keeper`), else NO_PLAYER."""
        if state.play_mode != _GOALIE_HOLDS or state.mode_team != team:
            return NO_PLAYER
        row = self.modes.goalie_rows[team]
        return row if row != NO_PLAYER and row == state.ball_holder else NO_PLAYER

    def move_keeper(self, state: WorldState, x: float, y: float) -> bool:
        """The holding goalkeeper's move to (x, y), absolute frame, within ``goalie_max_moves``
        (:meth:`GoalkeeperJudge.holder_moves`); whether it was made."""
        return self.goalkeeper.holder_moves(state, x, y)

    @property
    def judges(self) -> tuple[Judge, ...]:
        """The judges, in the order they hear every hook."""
        return tuple(self.hooks.judges)

    def add_judge(self, judge: Judge) -> None:
        """Add a rule: ``judge`` hears every hook after the judges already there (build it with
        :attr:`modes` to restart play)."""
        self.hooks.set([*self.hooks.judges, judge])

    # ------------------------------------------------------------------ public API

    def start(self, state: WorldState, mode: PlayMode = PlayMode.KICK_OFF, team: int = HOME) -> None:
        """Open play in ``mode`` (SET_PLAY event). The default, the opening kick-off: ``team``
        (home) kicks off, ball still on the centre spot, every player moved into its own half
        and the other team out of the centre circle. Another set play (kick-in, corner kick,
        goal kick, free kick) belongs to ``team`` and is taken where the ball lies, the
        opponents cleared from it. ``PLAY_ON``: the ball and the players as they are."""
        self._check_state(state)
        self.modes.start(state, mode, team)

    def stop(self, state: WorldState) -> None:
        """End the match after the cycle being judged (a scenario's end condition was met):
        TIME_OVER event and play mode, as at the end of the last cycle."""
        if state.play_mode != _TIME_OVER:
            self.modes.time_over(state)

    def on_commands(self, state: WorldState, kickers: np.ndarray, catch_requests: np.ndarray,
                    tackles: TackleOutcome | None = None) -> None:
        """Judge this cycle's kicks and tackles (already applied to ``state.ball_vel``) and
        catch requests.

        ``kickers``: int array of the player rows whose kick was applied. ``catch_requests``:
        (2,) bool, whether the home / away goalkeeper asked to catch. ``tackles``: this
        cycle's tackles, if any (:class:`~soccer_sim.tackles.TackleOutcome`). Every kick is
        recorded (KICK) and every tackle (TACKLE); the judges hear ``kick_taken`` for the
        kickers and the tacklers that pushed the ball until one stops play; otherwise a kick
        from a set play or a held ball starts play on; then the pushing tacklers are judged
        for fouls (``tackle_taken``).
        """
        pushers = () if tackles is None else tackles.pushers
        has_kick = len(kickers) > 0 or len(pushers) > 0
        if tackles is None and not has_kick and not (catch_requests[0] or catch_requests[1]):
            return
        if state.play_mode == _TIME_OVER:
            return
        n = self._n
        if tackles is not None:
            bx, by = state.ball.tolist()
            for row, reached, foul in zip(tackles.rows, tackles.reached, tackles.fouls):
                team = HOME if row < n else AWAY
                self.events.add(state.cycle, EventKind.TACKLE, team, row - team * n, bx, by,
                                int(reached) + 2 * int(foul))
        if has_kick:
            rows = sorted(int(row) for row in kickers)
            mode = state.play_mode
            bx, by = state.ball.tolist()
            for row in rows:
                team = HOME if row < n else AWAY
                self.events.add(state.cycle, EventKind.KICK, team, row - team * n, bx, by, 0)
            if pushers:
                rows = sorted(set(rows) | set(pushers))
            for call in self.hooks.kick_judges:
                if call(state, rows, mode, bx, by):
                    break
            else:
                if mode != _PLAY_ON:
                    self.modes.set_play_taken(state, rows[0])
                if pushers:
                    assert tackles is not None and tackles.dashed is not None
                    for row, foul in zip(tackles.rows, tackles.fouls):
                        if row in pushers and state.play_mode == _PLAY_ON:
                            self.hooks.tackle_taken(state, row, foul, tackles.dashed)
        for team in (HOME, AWAY):
            if catch_requests[team]:
                self.goalkeeper.catch_requested(state, team, kickers)

    def after_step(self, state: WorldState, touchers: np.ndarray) -> None:
        """Judge the cycle after the physics step. ``touchers``: int array of the rows whose
        body touched the ball during the step. In play on the judges hear ``ball_touched``
        (until one stops play) and ``analyse``; a held ball is kept (:meth:`GoalkeeperJudge.keep_hold`); a set
        play or the pause after a goal is kept; then time is judged."""
        mode = state.play_mode
        if mode == _TIME_OVER:
            return
        if mode == _PLAY_ON:
            if len(touchers):
                rows = sorted(set(int(r) for r in touchers))
                bx, by = float(state.ball[0]), float(state.ball[1])
                for call in self.hooks.touch_judges:
                    if call(state, rows, bx, by):
                        break
            bx, by = state.ball.tolist()
            for call in self.hooks.analyse_judges:
                if call(state, bx, by):
                    break
        elif mode == _GOALIE_HOLDS:
            self.goalkeeper.keep_hold(state)
        else:
            self.modes.keep(state)
        self.modes.judge_time(state)
        ball = state.ball
        self.modes.prev_ball = (float(ball[0]), float(ball[1]))

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
