"""The match loop: teams decide, the match applies the motion rules, pymunk resolves
collisions, the referee judges, recorders observe.

One cycle (100 ms of game time by default):

1. each team gets its team-relative view and returns a command, validated and turned back
   into the absolute frame (:mod:`soccer_sim.view`); under partial observation what its players
   say goes into the channel and their neck turns and view widths to the observer (the sees of
   the next cycles look through them);
2. before a kick-off and in the pause after a goal, teams may place their players
   (``TeamCommand.move``);
3. tackles (:mod:`soccer_sim.tackles`; players frozen after a tackle or sent off do nothing),
   then kicks by players allowed by the referee with the ball within reach (or held), then
   the successful tackles' pushes;
4. the referee judges the kicks, the tackles (fouls, cards) and the goalkeepers' catch requests;
5. dashes, the stamina model and the movement noise of players and ball
   (:mod:`soccer_sim.kinematics`; players are restored at the start of each half); who dashed
   is kept for the next cycle's foul rule (``WorldState.dashed_before``);
6. the collision solver moves everything for one cycle, in as many sub-steps as needed so
   that no player passes through another (:class:`~soccer_sim.physics.SubstepPlanner`), and
   body-ball contacts are resolved (``PhysicsConfig.body_ball_contact``); players are kept
   within the field plus its margin;
7. velocity decay;
8. the referee judges goals, outs, restarts, offside and time;
9. the cycle counter advances and recorders observe.

A match is a pure function of (teams, config, scenario, seed): all randomness comes from
generators spawned from ``numpy.random.SeedSequence(seed)`` (the physics noise first, then one
per team, home first, then the scenario's start-state draws, then the tackles' and the foul
decisions' draws, made only when somebody tackles), and nothing else is random.

A :class:`~soccer_sim.scenarios.Scenario` sets the sides' sizes (player rows ``0..h-1`` home,
``h..h+a-1`` away), the start state, the opening play mode, the rules it switches and the end
conditions; the default scenario is the regular match. The match resolves configuration and
scenario once into a :class:`~soccer_sim.setup.MatchSetup`, which the referee and the teams'
:class:`~soccer_sim.team.SideInfo` are built from; its :class:`~soccer_sim.ending.MatchEnd`
decides when the match ends.
"""

from __future__ import annotations

import gc
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.kinematics import CycleNoise, Kinematics
from soccer_sim.errors import SoccerSimError
from soccer_sim.kernels import PT_DECAY, PT_INERTIA_MOMENT, one_body_command
from soccer_sim.perception.observer import Observer
from soccer_sim.physics import Physics, SubstepPlanner
from soccer_sim.player_types import check_choice, draw_player_types
from soccer_sim.recorder import Recorder, check_recorders
from soccer_sim.referee import Referee
from soccer_sim.registry import resolve_team
from soccer_sim.scenarios.scenario import Scenario, line_up
from soccer_sim.setup import MatchSetup, SetupTypeError
from soccer_sim.state import AWAY, HOME, NO_PLAYER, EventLog, PlayMode, WorldState
from soccer_sim.statistics import StatisticsRecorder, TeamStatistics
from soccer_sim.tackles import Tackles
from soccer_sim.team import SideInfo, Team, team_failure
from soccer_sim.team_hooks import ChoosesPlayerTypes, check_observation_mode
from soccer_sim.view import TeamFrame

_KICK_OFF = PlayMode.KICK_OFF
_TIME_OVER = PlayMode.TIME_OVER
_AFTER_GOAL = PlayMode.AFTER_GOAL
_GOALIE_HOLDS = PlayMode.GOALIE_HOLDS
_NO_KICKERS = np.zeros(0, dtype=np.int64)


@dataclass
class MatchResult:
    """The outcome of a match."""

    score: tuple[int, int]
    """(home goals, away goals)."""
    events: EventLog
    statistics: tuple[TeamStatistics, TeamStatistics]
    """(home, away) statistics."""
    state: WorldState
    """The final world state."""
    team_names: tuple[str, str]
    seed: int
    cycles: int
    """Cycles played."""
    end_reason: str = "time_over"
    """Why the match ended: ``"time_over"`` (the configuration's length), ``"cycle_limit"`` (the
    scenario's), or the scenario's end condition that was met (``"goal"``, ``"scored"``, ``"out"``,
    ``"lost"``)."""
    scenario: str = "full-match"
    """Name of the scenario played."""


def initial_positions(config: MatchConfig) -> np.ndarray:
    """(2n, 2) opening line-up of the regular match, absolute frame: each team spread over its
    own half in three lines (the goalkeeper on its goal line's centre); the referee's kick-off
    and the teams' ``move`` commands refine it."""
    own = line_up(config.players_per_team, config.rules.goalie_index, config.field.half_length,
                  config.field.half_width)
    return np.concatenate([own, -own])


class SeedError(SoccerSimError, ValueError):
    """A match seed that is not a non-negative integer."""


class Match:
    """One match between two teams; :meth:`run` plays it to the end.

    Attributes recorders may read: ``state``, ``events``, ``config``, ``teams``,
    ``team_names``, ``teammate_contacts`` and the rows of the last cycle's ``kickers`` and
    ``touchers``.
    """

    def __init__(self, home: Team | str | type, away: Team | str | type, seed: int = 0,
                 config: MatchConfig | None = None, recorders: Iterable[Recorder] = (),
                 scenario: Scenario | str | None = None, *, setup: MatchSetup | None = None) -> None:
        """``config`` and ``scenario`` are resolved into the match's :class:`MatchSetup`
        (:meth:`MatchSetup.resolve`); or give an already resolved ``setup`` instead of them."""
        if setup is None:
            setup = MatchSetup.resolve(config, scenario)
        elif not isinstance(setup, MatchSetup):
            raise SetupTypeError(f"setup must be a MatchSetup, got {type(setup).__name__}")
        elif config is not None or scenario is not None:
            raise SetupTypeError("give either config and scenario or a setup resolved from them, not both")
        if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
            raise SeedError(f"seed must be a non-negative integer, got {seed!r}")
        recorders = check_recorders(recorders)
        self.setup = setup
        """Sides, goalkeepers, rules on/off, start and end of the match, resolved once."""
        self.config = config = setup.config
        """The configuration played (the scenario's offside switch applied)."""
        self.scenario = scenario = setup.scenario
        self.seed = int(seed)
        (home_team, home_name), (away_team, away_name) = resolve_team(home), resolve_team(away)
        if home_team is away_team:
            raise ValueError("the same team object cannot play both sides; pass two instances (or names)")
        self.teams: tuple[Team, Team] = (home_team, away_team)
        self.team_names = (home_name, away_name)

        self.sizes = sizes = setup.sizes
        """(home, away) players."""
        self.goalies = setup.goalies
        """Each side's goalkeeper index within the side (-1: none)."""
        n2 = sizes[0] + sizes[1]
        # A new stream goes at the end: the earlier children stay what they were.
        physics_seq, home_seq, away_seq, scenario_seq, tackle_seq, types_seq, perception_seq = \
            np.random.SeedSequence(self.seed).spawn(7)
        self._perception_seq = perception_seq
        self._team_seeds = (home_seq, away_seq)
        self.end_cycle = setup.end_cycle
        """Cycles the match lasts at most."""
        self.state = state = WorldState(sizes)
        """The world; its arrays are created once, here, and only ever written in place."""
        if scenario.is_regular:
            state.pos[:] = initial_positions(config)
        else:
            rng = np.random.default_rng(scenario_seq) if scenario.randomised else None
            pos, vel, ball, ball_vel = scenario.start_state(config, rng)
            state.pos[:], state.vel[:] = pos, vel
            state.ball[:], state.ball_vel[:] = ball, ball_vel
        self._arrays = (state.pos, state.vel, state.ball, state.ball_vel, state.bodies, state.stamina, state.effort,
                        state.recovery, state.capacity)
        """The state's arrays, looked up once (the state never replaces them)."""
        self.events = EventLog()
        tackle_rng = np.random.default_rng(tackle_seq)
        self.kinematics = Kinematics(config, n2)
        types = self.kinematics.types  # (kept up to date in place when the teams choose their types)
        self.referee = Referee(setup, self.events, tackle_rng, types)
        self.tackles = Tackles(config, state, setup.goalie_rows, tackle_rng, types)
        self.physics = Physics(config, state)
        self.player_types = draw_player_types(config, types_seq)
        """The match's heterogeneous player types (type 0 the default; :mod:`soccer_sim.player_types`)."""
        self.type_ids = np.zeros(n2, dtype=np.intp)
        """Each player row's type id (chosen by the teams in :meth:`start`; 0 for a team that does not choose)."""
        self._restore_players()
        self.noise = CycleNoise(np.random.default_rng(physics_seq), n2)
        self.commands = np.zeros((n2, 4))
        """Absolute commands of this cycle: per player row ``[dash_x, dash_y, kick_x, kick_y]``."""
        self._dash = self.commands[:, 0:2]
        self._kick = self.commands[:, 2:4]
        audio = config.observation.audio
        self.frames = (TeamFrame(HOME, home_name, state, self.commands, self.type_ids, audio),
                       TeamFrame(AWAY, away_name, state, self.commands, self.type_ids, audio))
        self.observer: Observer | None = None
        """The partial-observation model (built in :meth:`start` under ``observation.mode ==
        "partial"``; None under full observation)."""
        for team in (HOME, AWAY):
            check_observation_mode(self.teams[team], self.team_names[team], config.observation.mode)
        self._end = setup.end
        self._condition: str | None = None
        """The scenario's end condition that ended the match, if one did."""
        self._event_mark = 0
        self.statistics = StatisticsRecorder()
        self.recorders: tuple[Recorder, ...] = (self.statistics, *recorders)
        self.kickers = _NO_KICKERS
        self.touchers = _NO_KICKERS
        self._catch = np.zeros(2, dtype=bool)
        self._goalie_rows = np.array(setup.goalie_rows, dtype=np.int64)
        self._team_rows = (slice(0, sizes[0]), slice(sizes[0], n2))
        self._moving = np.zeros(n2, dtype=bool)
        """The rows a kick-off placement moves this cycle (after the one-body-command rule)."""
        self._no_tackles = np.full(n2, np.nan)
        self.ignored_commands = np.zeros(2, dtype=np.int64)
        """Body commands each team sent that were not executed, (home, away): rcssserver executes
        one per player and cycle (:func:`soccer_sim.kernels.one_body_command`)."""
        self._kicker_rows = np.zeros(n2, dtype=np.int64)
        self._substeps = SubstepPlanner(config)
        self._started = False

    @property
    def end_reason(self) -> str:
        """Why the match ended (:attr:`MatchResult.end_reason`; ``"time_over"`` while it runs
        and no end condition has been met)."""
        return self._end.reason(self.state.cycle, self._condition)

    @property
    def teammate_contacts(self) -> Sequence[int]:
        """New contacts between teammates so far, (home, away)."""
        return self.physics.teammate_contacts

    # ------------------------------------------------------------------------------------
    def run(self) -> MatchResult:
        """Play the whole match and return its result."""
        self.start()
        state, is_over = self.state, self._end.is_over
        # The loop allocates only short-lived objects; the cyclic garbage collector's passes
        # over them cost about a twentieth of a match, so it pauses until the end.
        collecting = gc.isenabled()
        gc.disable()
        try:
            while not is_over(state):
                self.step()
        finally:
            if collecting:
                gc.enable()
        return self.finish()

    def start(self) -> None:
        """Reset the teams, let the referee set up the opening kick-off, notify recorders."""
        if self._started:
            raise RuntimeError("a Match can be played only once; create a new one")
        self._started = True
        infos = self._choose_types()
        if self.config.observation.partial:
            self.observer = Observer(self.config.observation, self.sizes, self.team_names,
                                     self.kinematics.types[:, PT_DECAY], self.kinematics.types[:, PT_INERTIA_MOMENT],
                                     self.type_ids,
                                     np.random.default_rng(self._perception_seq))
        for team in (HOME, AWAY):
            info = infos[team]
            rng = np.random.default_rng(self._team_seeds[team])
            try:
                self.teams[team].reset(info, self.config, rng)
            except (Exception, SystemExit) as exc:
                raise team_failure(self.team_names[team], "reset", exc) from exc
        self.referee.start(self.state, self.setup.start_mode, self.setup.start_side)
        self._event_mark = len(self.events)
        for recorder in self.recorders:
            recorder.on_start(self)

    def finish(self) -> MatchResult:
        """Notify recorders of the end and assemble the result."""
        for recorder in self.recorders:
            recorder.on_end(self)
        state = self.state
        assert self.statistics.result is not None
        reason = self._end.reason(state.cycle, self._condition)
        return MatchResult(score=(int(state.score[0]), int(state.score[1])), events=self.events,
                           statistics=self.statistics.result, state=state, team_names=self.team_names,
                           seed=self.seed, cycles=state.cycle, end_reason=reason, scenario=self.scenario.name)

    def step(self) -> None:
        """Simulate one cycle; a RuntimeError once the referee has called time."""
        state, referee, kin = self.state, self.referee, self.kinematics
        if state.play_mode == _TIME_OVER:
            raise RuntimeError(f"the match is over (time over after cycle {state.cycle}); no more cycles")
        pos, vel, ball, ball_vel, bodies, stamina, effort, recovery, capacity = self._arrays
        self.noise.draw()

        # 1-2. Teams decide; one body command per player (tackle > catch > kick > move > dash);
        # kick-off placement.
        moves = self._collect_commands()
        home_frame, away_frame = self.frames
        tackling = home_frame.tackling or away_frame.tackling
        # (with tackles switched off a tackle request is no command at all)
        tackle = self._tackles_asked() if tackling and self.config.tackles.enabled else self._no_tackles
        moving = self._moving
        placing = state.play_mode == _KICK_OFF or state.play_mode == _AFTER_GOAL
        keeper = NO_PLAYER  # the goalkeeper holding the ball whose move is a body command
        if placing:
            for team, rows in enumerate(self._team_rows):
                moving[rows] = moves[team] is not None
        elif state.play_mode == _GOALIE_HOLDS and moves[state.mode_team] is not None:
            keeper = referee.holding_keeper(state, state.mode_team)
            if keeper != NO_PLAYER:
                moving[keeper] = True
        one_body_command(self.commands, tackle, self._catch, self._goalie_rows, moving, self.sizes[0],
                         self.ignored_commands)
        if placing:
            for team, rows in enumerate(self._team_rows):
                if moves[team] is not None:
                    referee.apply_moves(state, team, moves[team], moving[rows])
            moving[:] = False
        elif keeper != NO_PLAYER:
            if moving[keeper]:
                team = state.mode_team
                x, y = moves[team][keeper - state.first_row(team)]
                referee.move_keeper(state, float(x), float(y))
            moving[keeper] = False

        # 3-4. Tackles (frozen and sent-off players idle), kicks, then the referee judges
        # kicks, tackles and catches.
        if tackling or self.tackles.busy:
            tackled = self.tackles.resolve(state, tackle, self._foul_asked(), tackling, self.commands, self._catch,
                                           referee.kick_mask(state))
        else:
            tackled = None
        holder = state.ball_holder
        count, _ = kin.kick_candidates(pos, ball, self._kick, referee.kick_mask(state), holder, self._kicker_rows)
        if count:
            kickers = self._kicker_rows[:count].copy()
            dist = kin.ball_distance
            kin.kick(kickers, pos, vel, ball, ball_vel, self._kick, dist, holder, self.noise.kick)
            state.last_touch = int(kickers[np.argmin(dist[kickers])]) if count > 1 else int(kickers[0])
        else:
            kickers = _NO_KICKERS
        self.kickers = kickers
        if tackled is not None:
            self.tackles.push(state, tackled, count > 0)
            referee.on_commands(state, kickers, self._catch, tackled)
            if tackled.pushers:  # the tacklers' bodies let the pushed ball go, as a kicker's do
                kickers = np.union1d(kickers, tackled.pushers).astype(np.int64)
        else:
            referee.on_commands(state, kickers, self._catch)

        # 5. Dashes (remembered for the next cycle's foul rule).
        kin.dash(vel, ball_vel, stamina, effort, recovery, capacity, self._dash, self.noise.motion)
        np.any(self._dash != 0.0, axis=1, out=state.dashed_before)

        # 6. Collision solving. A held ball does not collide; when the goalkeeper kicks it away
        # it passes through the goalkeeper's body like any kicked ball passes its kicker.
        holder = state.ball_holder
        physics = self.physics
        physics.set_ball_collides(holder == NO_PLAYER)
        substeps = self._substeps.count(bodies, holder == NO_PLAYER)
        self.touchers = physics.step(substeps, kickers)
        if holder != NO_PLAYER:  # (the referee keeps it touching the goalkeeper, keep_hold)
            ball_vel[:] = 0.0

        # 7-9. Decay, the referee, time, observers.
        kin.decay(vel, ball_vel)
        half = state.half
        referee.after_step(state, self.touchers)
        if self._end.conditions:
            self._check_end()
        if state.half != half:
            self._restore_players()  # players come back fresh for the second half
        if self.tackles.busy:
            self.tackles.end_cycle(state)
        state.cycle += 1
        for recorder in self.recorders:
            recorder.on_cycle(self)

    # ------------------------------------------------------------------------------------
    def _collect_commands(self) -> list[np.ndarray | None]:
        """Each team's command from its view (under partial observation: its players' views,
        :meth:`Observer.observe`, and what its players say goes into the channel)."""
        state, observer = self.state, self.observer
        moves: list[np.ndarray | None] = [None, None]
        sign = state.home_attacks
        views = observer.observe(state) if observer is not None else None
        for team in (HOME, AWAY):
            frame = self.frames[team]
            view = frame.update_view(state, sign) if views is None else views[team]
            try:
                command = self.teams[team].act(view)
            except (Exception, SystemExit) as exc:
                raise team_failure(frame.name, "act", exc) from exc
            self._catch[team], moves[team] = frame.read_command(command, sign)
            sign = -sign
        if observer is not None:
            said = [f.said if f.said is not None else (None,) * f.n for f in self.frames]
            observer.say(state.cycle, said, state.pos, checked=True)  # (read_command checked the messages)
            home_frame, away_frame = self.frames
            if home_frame.turns_neck or away_frame.turns_neck:
                observer.turn_necks(np.concatenate([home_frame.neck_turn, away_frame.neck_turn]), state.present)
            if home_frame.changes_view or away_frame.changes_view:
                observer.change_views(state.cycle, np.concatenate([home_frame.view_width, away_frame.view_width]),
                                      state.present)
        return moves

    def _tackles_asked(self) -> np.ndarray:
        """(P,) both teams' tackle directions this cycle (absolute, radians; NaN for none)."""
        home_frame, away_frame = self.frames
        return np.concatenate([home_frame.tackle if home_frame.tackling else np.full(home_frame.n, np.nan),
                               away_frame.tackle if away_frame.tackling else np.full(away_frame.n, np.nan)])

    def _foul_asked(self) -> np.ndarray:
        """(P,) both teams' foul flags this cycle."""
        home_frame, away_frame = self.frames
        return np.concatenate([home_frame.foul, away_frame.foul])

    def _check_end(self) -> None:
        """Judge the scenario's end conditions on this cycle's events
        (:meth:`~soccer_sim.ending.MatchEnd.condition_met`); the first met ends the match
        (the referee calls TIME_OVER)."""
        events = self.events
        mark, end = self._event_mark, len(events)
        self._event_mark = end
        condition = self._end.condition_met(events, mark, end)
        if condition is not None:
            self._condition = condition
            self.referee.stop(self.state)
            self._event_mark = len(events)

    def _choose_types(self) -> tuple[SideInfo, SideInfo]:
        """Ask each team that offers :class:`~soccer_sim.team_hooks.ChoosesPlayerTypes` for its
        players' types (checked against ``pt_max``), give the players their parameters, and
        return the teams' SideInfo with the types filled in."""
        bare = [self.setup.side_info(team, self.team_names) for team in (HOME, AWAY)]
        first = (0, self.sizes[0])
        for team in (HOME, AWAY):
            chooser = self.teams[team]
            if not isinstance(chooser, ChoosesPlayerTypes):
                continue
            name = self.team_names[team]
            try:
                choice = chooser.choose_player_types(self.player_types, bare[team])
            except (Exception, SystemExit) as exc:
                raise team_failure(name, "choose_player_types", exc) from exc
            ids = check_choice(choice, self.player_types, self.sizes[team], self.config.player_types.pt_max, name)
            self.type_ids[first[team]:first[team] + self.sizes[team]] = ids
        if self.type_ids.any():
            self.kinematics.set_types([self.player_types[i] for i in self.type_ids])
            self._restore_players()
        rows = [tuple(int(i) for i in self.type_ids[first[t]:first[t] + self.sizes[t]]) for t in (HOME, AWAY)]
        return tuple(replace(bare[t], player_types=self.player_types, own_types=rows[t], opponent_types=rows[1 - t])
                     for t in (HOME, AWAY))  # type: ignore[return-value]

    def _restore_players(self) -> None:
        """Fresh players: at the start of the match and of the second half."""
        state = self.state
        self.kinematics.restore(state.stamina, state.effort, state.recovery, state.capacity)


def run_match(home: Team | str | type, away: Team | str | type, seed: int = 0,
              config: MatchConfig | None = None, recorders: Iterable[Recorder] = (),
              scenario: Scenario | str | None = None) -> MatchResult:
    """Play a whole match and return its :class:`MatchResult`.

    ``home`` and ``away`` are Team objects, Team classes, registered names (``"chaser"``) or
    ``package.module:Attribute`` paths. ``scenario`` is a :class:`Scenario`, the name of one in
    the library (:func:`soccer_sim.scenarios.scenario_names`) or None for the regular match.
    The result is a pure function of the teams, the config, the scenario and the seed.
    """
    return Match(home, away, seed=seed, config=config, recorders=recorders, scenario=scenario).run()
