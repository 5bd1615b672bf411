"""The built-in team's one decision pipeline: every player row, from what it believes to its command.

One pipeline for both observation modes; what differs is only the world model:

* under **full observation** every player believes the truth (:class:`~agents.teams.world_model.TruthBeliefs`:
  one belief row, which every player takes its world from);
* under **partial observation** each player believes what it saw and heard
  (:class:`~agents.teams.world_model.TeamBeliefs`: row ``i`` is player ``i``'s), and the players
  talk in turns (:mod:`agents.teams.speaking`: one team message a cycle, which every team-mate
  in range hears) to keep their beliefs fresh and their roles agreed.

Per cycle (team frame, we attack +x):

1. **Beliefs.** The world model takes in the cycle's view (and the team message heard: its
   world information and its assignment).
2. **Derived world, once per distinct belief** (:func:`~agents.teams.pipeline_kernels.derive_worlds`):
   its ball race (who of ours and theirs controls the ball first, where), attack or defend
   with hysteresis and the block moved at its pace, the formation queried, the targets
   settled (the positions' own behaviours, rest defence, the block's pace) and the support
   spots around our carrier.
3. **Roles, once per distinct belief** (:meth:`Pipeline._assign`): the role assigner on the
   belief's team-mates and targets (under full observation once for the team, every row
   agreeing; under partial observation the speaker of the cycle on its own beliefs, and every
   player follows the assignment it heard last, so the whole team changes assignment together
   the cycle after it is said; a player who heard none lately assigns on its own beliefs, at
   most every ``assign_every`` cycles).
4. **Goals per player row** (:func:`~agents.teams.pipeline_kernels.player_goals`): the followed
   role's target, kept onside; the interception point for the one who goes for the ball and
   the pressers; a steering assigner's own field; the goalkeeper's guard point; follow-ups of
   our shot.
5. **Decisions on the ball and at set plays, per belief** (:mod:`agents.teams.decisions`), for
   a belief whose players include one on the ball by it.
6. **Commands per player row**: the dash at the pace the stamina policy allows (or the
   placement before a kick-off), the kick, catch or tackle decided in step 5, and the
   speaker's team message.

Row ``i``'s command depends on nothing but its belief and its own senses; under partial
observation that is what player ``i`` alone saw and heard.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from agents import skills
from agents.messages import MESSAGE_GRID, MESSAGE_LENGTH, digit_messages
from agents.roles import RoleAssigner, RoleContext, offensive_order
from agents.skills.interception import UNREACHABLE, BallRace, Interception
from agents.skills.movement import DEFAULT_PACING
from agents.skills.player_kernels import Bodies
from agents.skills.pacing import pacing_constants
from agents.teams import mechanism
from agents.teams.ball_role import LeaveMatching
from agents.teams.decisions import NO_SHOT, BeliefDecisions, follow_up_goals
from agents.teams.looking import Looker
from agents.teams.on_ball import ball_reach, make_tackling
from agents.teams.pipeline_kernels import (NORMAL, OUR_SET_PLAY, THEIR_SET_PLAY, assignment_problems, ball_player,
                                           dash_and_say, derive_worlds, follow_assignments, on_ball_rows,
                                           plan_cycle, player_goals)
from agents.teams.pipeline_state import PipelineState, state_of
from agents.teams.positions import nearest_roles
from agents.teams.reporting import RoleFigures
from agents.teams.role_behaviours import RoleBehaviours
from agents.teams.role_kernels import steered_goals
from agents.teams.shape import Shape
from agents.teams.speaking import speaker_of, turn_memory
from agents.teams.style import TeamStyle
from agents.teams.type_choice import time_scales
from agents.teams.world_model import Senses, TeamBeliefs, TruthBeliefs
from formations import FormationSet, Situation
from soccer_sim.config import MatchConfig
from soccer_sim.perception.views import PlayerViews
from soccer_sim.state import SET_PLAYS, PlayMode
from soccer_sim.team import SideInfo, TeamCommand, TeamView

ASSIGN_EVERY = 2
"""Cycles between the assignments of a belief that assigns for itself (under full observation,
or a player who heard no assignment lately) at least: it assigns on the cycles its believer
sees, and at once when the play mode changes; a belief's inputs move little in 0.2 s, and the
assignment it follows is kept between."""

RACE_NEAR = 20.0
"""A belief whose ball is within this (m) of one of its players runs its ball race again on
every cycle its believer sees; farther away..."""
RACE_EVERY = 2
"""... on the cycles it sees at least this many cycles after its last race (and at the latest
one cycle later): between sees a belief only rolls forward, so its last race holds."""

ON_BALL_DISTANCE = 2.2
"""A player who believes the ball within this (m) decides on the ball (a kick, a dribble, a
tackle: rcssserver's ``tackle_dist`` is 2 m, the kickable distance about 1 m)."""

GUARD_STEP = 0.5
"""How far (m) a player takes an opponent to have stepped up towards our attack (-x) in each
cycle since it was last seen, for the offside line it keeps to (:func:`~agents.teams.pipeline_kernels.guard_line_x`):
a back line steps up at about half a sprint (rcssserver's ``player_speed_max`` is 1.05 m/cycle)."""
GUARD_CYCLES = 6
"""... counted for at most this many cycles (3 m at most: a forward stays playable, not deep)."""

SAID_HORIZON = 20
"""Cycles a heard assignment is followed (2 s: the assignment moves on with the ball; a player
out of every speaker's range that long assigns for itself)."""

PLACED = (PlayMode.KICK_OFF, PlayMode.AFTER_GOAL)
"""Play modes in which players are placed (``move``) rather than run."""

_OTHER = {Situation.OUR_SET_PLAY: OUR_SET_PLAY, Situation.THEIR_SET_PLAY: THEIR_SET_PLAY, Situation.NORMAL: NORMAL}


def situation_of(mode: PlayMode, ours: bool, attacking: bool) -> Situation:
    """The formation situation of a play mode: attack or defend in play on, the set-play
    formations at set plays, a held ball and the pause after a goal, else the normal one."""
    if mode == PlayMode.PLAY_ON:
        return Situation.ATTACK if attacking else Situation.DEFEND
    if mode == PlayMode.AFTER_GOAL or mode in SET_PLAYS or mode == PlayMode.GOALIE_HOLDS:
        return Situation.OUR_SET_PLAY if ours else Situation.THEIR_SET_PLAY
    return Situation.NORMAL


class TeamSetup:
    """What the pipeline is built from besides the match: the formation set, the style, how to
    make one belief's role assigner (and its ball-role matching, None: none) and which roles
    are outfield and forwards."""

    def __init__(self, formation_set: FormationSet, style: TeamStyle, make_assigner: Callable[[], RoleAssigner],
                 make_leave: Callable[[], LeaveMatching | None], outfield_roles: np.ndarray,
                 forward_roles: np.ndarray) -> None:
        self.formation_set = formation_set
        self.style = style
        self.make_assigner = make_assigner
        self.make_leave = make_leave
        self.outfield_roles = outfield_roles
        self.forward_roles = forward_roles


class Pipeline:
    """One team's decision pipeline for one match (module docstring). ``world``: the world
    model (:class:`TruthBeliefs` or :class:`TeamBeliefs`, made for this side)."""

    def __init__(self, setup: TeamSetup, side_info: SideInfo, config: MatchConfig, rng: np.random.Generator,
                 world: TruthBeliefs | TeamBeliefs) -> None:
        self.setup = setup
        style, formation_set = setup.style, setup.formation_set
        self.style = style
        self.formation_set = formation_set
        self.world = world
        n, m = side_info.players_per_team, side_info.opponents
        self.n = n
        self.goalie = goalie = side_info.goalie_index
        self.outfield = outfield = np.array([i for i in range(n) if i != goalie], dtype=np.int64)
        k = len(outfield)
        rows = world.ball.shape[0]
        """How many belief rows the world model holds (1: the truth; n: each player's own)."""
        self.skills = ctx = skills.SkillContext.for_match(config, side_info)
        self.model = model = ctx.model
        self.config = config
        roles = len(formation_set.roles)
        self.kick_off_spots = formation_set.positions((0.0, 0.0), Situation.OUR_SET_PLAY)
        self.match_roles = np.zeros((rows, k), dtype=np.int64)
        """(rows, k) the outfield roles each belief holds the side fills (all of them for a full
        side; a smaller side's on the first cycle, :meth:`_pick_roles`)."""
        self._choose_roles = k < len(setup.outfield_roles)
        if not self._choose_roles:
            self.match_roles[:] = setup.outfield_roles[:k]
        # each belief's role assigner, ball-role matching and context, and its decisions
        children = rng.spawn(rows)
        self.assigners = [setup.make_assigner() for _ in range(rows)]
        self.leaves = [setup.make_leave() for _ in range(rows)]
        for assigner, leave, child in zip(self.assigners, self.leaves, children):
            if k:
                assigner.reset(k, child)
                if leave is not None:
                    leave.reset(outfield, n, child)
        first = self.assigners[0] if rows else setup.make_assigner()
        self._steers = type(first).steer is not RoleAssigner.steer
        self._batches = type(first).assign_rows is not RoleAssigner.assign_rows
        scales = time_scales(side_info.player_types, side_info.own_types, outfield, config)
        self.contexts = [RoleContext(
            ball=np.zeros(2), own_goal=model.goal_centre(ours=True), opp_goal=model.goal_centre(ours=False),
            opponents=np.zeros((m, 2)), field_half_length=model.half_length, field_half_width=model.half_width,
            cycle=0, attacking=False, penalty_area_length=model.penalty_area_length,
            penalty_area_half_width=model.penalty_area_half_width, time_scale=scales) for _ in range(rows)]
        kick_off_taker = -1
        if k:  # the outfield player whose own spot is nearest the centre: every player knows it
            kick_off_taker = int(outfield[int(np.argmin(np.hypot(*self.kick_off_spots[outfield].T)))])
        self.kick_off_taker = kick_off_taker
        tackling = make_tackling(model, config, side_info, style.tackling)
        self.decisions = [BeliefDecisions(ctx, config, style, outfield, tackling, kick_off_taker)
                          for _ in range(rows)]
        self.shape = Shape(style.shape, [role.kind for role in formation_set.roles], style.depth, style.attack_push,
                           model.half_length, model.half_width)
        """The team's shape constants (:mod:`agents.teams.shape`)."""
        behaviours = RoleBehaviours(formation_set, model.half_length, model.half_width)
        self._talks = world.talks and k > 0
        self._shared = style.shared_assignment and rows > 1 and k > 0
        """Every player follows the first outfield player's belief's assignment (TeamStyle.shared_assignment)."""
        agrees = style.agreement != "own" and not self._shared
        self.turns = turn_memory(rows, k if self._talks and agrees else 0)
        """What each belief keeps of the proposals heard (the speaking turns; no columns: the
        truth needs no talk, no outfield roles, each follows its own proposal, or the
        assignment is shared without a word)."""
        self._speaks = np.zeros(n, dtype=bool)
        # arrays
        self.rank = np.full(n, -1, dtype=np.int64)
        self.rank[outfield] = np.arange(k)
        self.targets = np.zeros((rows, roles, 2))
        self.proposals = np.tile(np.arange(k, dtype=np.int64), (rows, 1))
        self.followed = self.proposals.copy()
        self.following = self.proposals.copy()
        self.goals = np.zeros((n, 2))
        self.urgent = np.zeros(n, dtype=bool)
        self.attacking = np.zeros(rows, dtype=bool)
        self.previous = np.zeros((rows, roles, 2))
        """(rows, roles, 2) each belief's role targets of the last cycle (its targets move at the block's pace)."""
        self.block = np.zeros((rows, 3))
        """(rows, 3) each belief's block: the formation's query point (x, y) and its shift up the field."""
        self.our_cycles = np.zeros((rows, n), dtype=np.int64)
        self.our_points = np.zeros((rows, n, 2))
        self.our_first = np.full(rows, -1, dtype=np.int64)
        self.their_cycles = np.zeros((rows, m), dtype=np.int64)
        self.their_points = np.zeros((rows, m, 2))
        self.their_first = np.full(rows, -1, dtype=np.int64)
        self.their_cycle = np.zeros(rows, dtype=np.int64)
        self.win_point = np.zeros((rows, 2))
        self.named_ball = np.full(rows, -1, dtype=np.int64)
        self.able = np.ones((rows, n), dtype=bool)
        """(rows, n) who of ours each belief holds may play the ball (not offside when our pass in flight was played)."""
        self.in_flight = np.zeros(rows, dtype=bool)
        """(rows,) whether each belief holds that our pass is in flight."""
        self._assigned_at = np.full(rows, -(1 << 40), dtype=np.int64)
        self._assigned_mode = np.full(rows, -1, dtype=np.int64)
        self._full = np.zeros(rows, dtype=bool)
        self._due = np.zeros(rows, dtype=np.int64)
        self._belief_rows = np.zeros(rows, dtype=np.int64)
        self._rows = np.zeros(n, dtype=np.int64)
        self._outfield_rows = np.zeros(n, dtype=np.int64)
        self._on_ball = np.zeros(n, dtype=bool)
        self._deciding = np.zeros(n, dtype=bool)
        self._problems = (np.zeros((rows, k, 2)), np.zeros((rows, k, 2)))
        self._kicked = np.zeros(rows, dtype=bool)
        self._decided: list[int] = []
        """The beliefs that decided on the ball this cycle."""
        self._no_kicks = np.zeros(rows, dtype=bool)
        self._digits = np.zeros((n if world.talks else 0, MESSAGE_LENGTH), dtype=np.int64)
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))
        self.figures = RoleFigures(config, k)
        """The team's role figures: each player's distance to the target of the role it follows."""
        self._mode_key: tuple[int, bool] = (-1, False)
        self._mode_since = 0
        self.cycles = 0
        """Cycles this pipeline has acted (0: no assignment made yet)."""
        self._play_on_cycles = self._conflict_cycles = self._unfilled_cycles = self._agreed_cycles = 0
        self._spell_start = -1
        """The play-on cycle the players stopped all following one assignment (-1: they do, or play stopped)."""
        self._spells: list[int] = []
        """Each completed spell of disagreement: cycles until they all followed one assignment again."""
        self._goal_kick_keeper = style.goalkeeper_goal_kicks and goalie >= 0
        sp, third = style.shape, model.half_length / 3.0
        arrays = ctx.arrays(TeamView(own_pos=np.zeros((n, 2)), own_vel=np.zeros((n, 2)), opp_pos=np.zeros((m, 2)),
                                     opp_vel=np.zeros((m, 2)), ball=np.zeros(2), ball_vel=np.zeros(2),
                                     stamina=np.zeros(n), own_types=np.array(side_info.own_types or (0,) * n),
                                     opp_types=np.array(side_info.opponent_types or (0,) * m)))
        tables = {situation: formation_set.formation(situation).query_tables for situation in Situation}
        shape = self.shape
        self.state: PipelineState = state_of(dict(
            ball=world.ball, ball_vel=world.ball_vel, ball_age=world.ball_age, mate_pos=world.mate_pos,
            mate_vel=world.mate_vel, mate_effort=world.mate_effort, opp_pos=world.opp_pos, opp_age=world.opp_age,
            opp_vel=world.opp_vel, opp_effort=np.ones(m), guard_x=np.zeros((rows, m)), guard_step=float(GUARD_STEP),
            guard_cycles=int(GUARD_CYCLES), belief_of=world.belief_of, able=self.able, ball_gap=np.zeros(rows),
            assigned_at=self._assigned_at, assigned_mode=self._assigned_mode, assign_every=int(ASSIGN_EVERY),
            steers=bool(self._steers), first_outfield=int(outfield[0]) if k else -1, turns=self.turns,
            said_horizon=int(SAID_HORIZON), settle_every=style.agreement == "speaker",
            radius=arrays.ours.radius, catch_radius=arrays.ours.catch_radius, opp_radius=arrays.theirs.radius,
            opp_catch_radius=arrays.theirs.catch_radius, reach=model.reach, ball_travel=model.ball_travel,
            coast=model.player_coast, race_constants=ctx.intercept_params,
            raced=np.full(rows, -(1 << 40), dtype=np.int64), race_near=float(RACE_NEAR), race_every=int(RACE_EVERY),
            switch_margin=sp.switch_margin, switch_persist=sp.switch_persist, depth=float(shape.depth),
            attack_push=float(shape.attack_push), knobs=shape.settle_record,
            outfield_roles=shape.outfield_roles, back_roles=shape.back_roles, x_limit=model.half_length - 2.0,
            forwards=setup.forward_roles, narrowing=1.0 - style.box_narrowing, narrow_x=third,
            role_codes=behaviours.codes, role_params=behaviours.record,
            is_forward=shape.is_forward, is_back=shape.is_back, offsets=shape.offsets,
            support_players=sp.support_players, support_pressure=sp.support_pressure,
            support_horizon=sp.support_horizon, third_x=third, support_knobs=shape.support_record,
            tables_attack=tables[Situation.ATTACK], tables_defend=tables[Situation.DEFEND],
            tables_our_set_play=tables[Situation.OUR_SET_PLAY], tables_their_set_play=tables[Situation.THEIR_SET_PLAY],
            tables_normal=tables[Situation.NORMAL],
            attacking=self.attacking, pending=np.zeros(rows, dtype=np.int64), in_play=np.zeros(rows, dtype=bool),
            block=self.block, our_cycles=self.our_cycles, our_points=self.our_points,
            our_first=self.our_first, their_cycles=self.their_cycles, their_points=self.their_points,
            their_first=self.their_first, their_cycle=self.their_cycle, win_point=self.win_point,
            previous=self.previous, primed=np.zeros(rows, dtype=bool), named_ball=self.named_ball,
            proposals=self.proposals, followed=self.followed, following=self.following, rank=self.rank,
            match_roles=self.match_roles, full=self._full, targets=self.targets, rows=self._rows,
            outfield_rows=self._outfield_rows, belief_rows=self._belief_rows, due=self._due,
            stationary=bool(style.stationary), spots=self.kick_off_spots, outfield=outfield, goalie=int(goalie),
            offside_margin=float(style.offside_margin), pressers=int(style.pressers),
            keeper_margin=int(skills.GoalieParams().race_margin),
            area_x=float(model.half_length - model.penalty_area_length), area_y=float(model.penalty_area_half_width),
            half_length=float(model.half_length), goals=self.goals, urgent=self.urgent,
            phase=np.zeros(n, dtype=np.int64), row_ball=np.zeros((n, 2)),
            pacing=pacing_constants(model, DEFAULT_PACING, 0.05), budgets=np.zeros(n), last_role=self.rank.copy(),
            unfilled=float(style.unfilled_distance),
            on_ball_distance=float(ON_BALL_DISTANCE),
            keeper_area_x=float(model.half_length - model.penalty_area_length - 2.0),
            keeper_area_y=float(model.penalty_area_half_width + 2.0),
            message_grid=MESSAGE_GRID, ball_decay=float(config.physics.ball_decay)))
        self._kickable = model.kickable_distance
        self.looker = Looker(style.looking, n, config) if style.scans and world.talks else None
        """Where the players look (:mod:`agents.teams.looking`; None: along their bodies)."""

    # ------------------------------------------------------------------ one cycle
    def act(self, view: TeamView | PlayerViews) -> TeamCommand:
        """Every player's command for this cycle (module docstring)."""
        n, command, world, s = self.n, self.command, self.world, self.state
        self.cycles += 1
        cycle, mode, ours = view.cycle, view.play_mode, bool(view.mode_ours)
        senses = world.update(view, self.turns, SAID_HORIZON)
        command.kick[:] = 0.0
        command.dash[:] = 0.0
        command.catch = False
        command.move = None
        command.tackle = command.foul = None
        command.say = None
        if n == 0:
            return command
        key = (int(mode), ours)
        if key != self._mode_key:
            self._mode_key, self._mode_since = key, cycle
        play_on = mode == PlayMode.PLAY_ON
        placed = mode in PLACED
        if self._choose_roles:
            self._pick_roles()
        # 1. who decides on the ball, and who positions itself
        n_on_ball = self._who_decides(mode, ours, senses)
        # 2.-4. the derived world of each belief, its roles, every player's goal
        speaker = speaker_of(cycle, n) if self._talks and senses.present[speaker_of(cycle, n)] else -1
        assigning = int(self.outfield[0]) if self._shared else speaker
        n_rows, n_out, n_beliefs, n_due = plan_cycle(s, self._deciding, int(mode), placed, senses.saw, cycle,
                                                     assigning)
        beliefs = self._belief_rows[:n_beliefs]
        other = _OTHER.get(situation_of(mode, ours, False), NORMAL)  # (in play on each belief's own)
        derive_worlds(s, n_beliefs, play_on, mode == PlayMode.AFTER_GOAL, other,
                      play_on and not self.style.stationary, senses.saw, cycle)
        if placed:
            self.proposals[beliefs] = self.followed[beliefs] = self.following[beliefs] = \
                np.arange(self.proposals.shape[1])
            self._assigned_mode[beliefs] = -1
        elif n_out:
            self._assign(self._due[:n_due], int(mode), cycle)
        follow_assignments(s, n_due, placed, cycle)
        if self._shared and not placed:
            self.following[beliefs] = self.following[self.world.belief_of[assigning]]
        player_goals(s, n_rows, n_beliefs, play_on)
        if self._steers and not self.style.stationary and n_out:
            self._steer(beliefs, play_on, cycle)
        self._goalkeeper_goal(play_on)
        if play_on:
            self.in_flight[beliefs] &= self.their_cycle[beliefs] != 0  # an opponent on the ball ends our pass
            self._follow_ups(beliefs, view, cycle)
            if n_out and mechanism.sampled(cycle):
                self._sample_makespans()
        # 5. placements before a kick-off, then the decisions on the ball and at set plays, per belief
        if placed:  # (players not placed stay where they are)
            move = command.move = senses.position.copy()
            move[self._deciding] = self.goals[self._deciding]
        kicked = self._decide(beliefs) if n_on_ball else self._no_kicks
        decided = self._decided if n_on_ball else ()
        if world.talks:  # a player knows what it just kicked
            world.kicked(command.kick, self._kickable + 0.2)
        # 6. dashes, what the players say, the figures
        switches, mean, largest, far, shared, empty = dash_and_say(
            s, n_rows, n_out, play_on, Bodies(senses.position, senses.velocity, senses.effort, senses.stamina,
                                              senses.capacity), cycle, view.half, command.dash, speaker, self._digits)
        self._after_dashes(decided, view)
        if play_on and n_out:
            self.figures.add(switches, True, mean, largest, far)
            self._count_conflicts(shared, empty)
            if world.talks:
                self._track_agreement(cycle)
        else:
            self._spell_start = -1  # a stoppage ends a spell uncounted
        self._remember_passes(beliefs, kicked, play_on, view)
        if speaker >= 0:
            self._speaks[:] = False
            self._speaks[speaker] = True
            command.say = digit_messages(self._digits, self._speaks)
        if self.looker is not None:
            command.turn_neck = self.looker.turn_necks(view, world.ball, world.ball_age)
        return command

    def _who_decides(self, mode: PlayMode, ours: bool, senses: Senses) -> int:
        """Who decides on the ball this cycle (into ``_on_ball``) and who positions itself
        (``_deciding``): :func:`~agents.teams.pipeline_kernels.on_ball_rows` with our set play's
        taker as the play mode has it. Returns how many decide on the ball."""
        play_on = mode == PlayMode.PLAY_ON
        set_play = not play_on and ours and mode in SET_PLAYS
        taker, reach, nearest = -1, self._kickable + 1.0, False
        if not play_on and ours and mode == PlayMode.GOALIE_HOLDS:  # the goalkeeper alone
            set_play, taker, reach = True, self.goalie, 0.0
        elif set_play:
            if mode == PlayMode.KICK_OFF:
                taker = self.kick_off_taker
            elif mode == PlayMode.GOAL_KICK and self._goal_kick_keeper:
                taker = self.goalie
            nearest = mode != PlayMode.KICK_OFF and taker < 0
        return on_ball_rows(self.state, play_on, set_play, nearest, taker, float(reach),
                            (senses.position, senses.holds, senses.present), self._on_ball, self._deciding)

    def _pick_roles(self) -> None:
        """A smaller side: each belief takes, once, the outfield roles it holds nearest the
        outfield players (a minimal-total-distance matching on the first cycle)."""
        world = self.world
        for b in range(self.match_roles.shape[0]):
            self.match_roles[b] = nearest_roles(self.formation_set, self.setup.outfield_roles, world.ball[b],
                                                world.mate_pos[b][self.outfield])
        self._choose_roles = False

    def _race(self, b: int) -> BallRace:
        """Belief ``b``'s ball race of this cycle as the skills read it."""
        first, their_first = int(self.our_first[b]), int(self.their_first[b])
        first_cycle = int(self.our_cycles[b, first]) if first >= 0 else UNREACHABLE
        return BallRace(Interception(self.our_cycles[b], self.our_points[b], first, first_cycle),
                        Interception(self.their_cycles[b], self.their_points[b], their_first,
                                     int(self.their_cycle[b])))

    def _context(self, b: int, play_on: bool, cycle: int) -> RoleContext:
        """Belief ``b``'s :class:`RoleContext` refreshed from what it holds."""
        context, world = self.contexts[b], self.world
        context.ball = self.win_point[b] if play_on else world.ball[b]
        context.ball_reach = None
        if self.assigners[b].uses_ball_reach and play_on:
            context.ball_reach = ball_reach(self.our_cycles[b], self.outfield, self.model)
        context.opponents = world.opp_pos[b]
        context.cycle = cycle
        context.attacking = bool(self.attacking[b])
        return context

    def _assign(self, beliefs: np.ndarray, mode: int, cycle: int) -> None:
        """The role assigner on each of the due ``beliefs`` (module docstring, step 3): its
        proposal, and the player its assigner names for the ball (bidding's ball role)."""
        play_on = mode == PlayMode.PLAY_ON
        self._assigned_at[beliefs], self._assigned_mode[beliefs] = cycle, mode
        self.named_ball[beliefs] = -1
        leave = self.leaves[0] is not None and play_on
        if beliefs.size > 1 and self._batches and not leave:  # all in one call
            players, role_targets = self._problems[0][:beliefs.size], self._problems[1][:beliefs.size]
            assignment_problems(self.state, beliefs, players, role_targets)
            proposals = self.assigners[0].assign_rows(players, role_targets, self.contexts[0])
            if proposals is not None:
                self.proposals[beliefs] = proposals
                return
        world = self.world
        for b in beliefs.tolist():
            assigner = self.assigners[b]
            players = world.mate_pos[b][self.outfield]
            role_targets = self.targets[b][self.match_roles[b]]
            context = self._context(b, play_on, cycle)
            proposal = None
            if leave:
                named = int(ball_player(self.state, b))
                proposal = self.leaves[b].assign(players, role_targets, named, self.our_points[b],
                                                 self.followed[b], context)
            if proposal is None:
                order = offensive_order(role_targets) if assigner.uses_role_order else None
                proposal = assigner.assign(players, role_targets, order, self.followed[b], context)
            self.proposals[b] = proposal
            named = assigner.ball_player()
            if named is not None and play_on:
                self.named_ball[b] = int(self.outfield[named])

    def _steer(self, beliefs: np.ndarray, play_on: bool, cycle: int) -> None:
        """A steering assigner (potential-field bidding) moves each player not going for the
        ball along its belief's field rather than straight to its role's target."""
        world = self.world
        for b in beliefs.tolist():
            rows = np.flatnonzero((world.belief_of == b) & (self.rank >= 0) & ~self.urgent & self._deciding)
            if not rows.size:
                continue
            players = world.mate_pos[b][self.outfield]
            role_targets = self.targets[b][self.match_roles[b]]
            followed = self.followed[b]
            steps = self.assigners[b].steer(players, role_targets, followed, self._context(b, play_on, cycle))
            ranks = self.rank[rows]
            self.goals[rows] = steered_goals(players[ranks], steps[ranks], role_targets[followed[ranks]])

    def _goalkeeper_goal(self, play_on: bool) -> None:
        """The goalkeeper guards the line between ball and goal, or goes for the ball its belief
        sends it to."""
        goalie = self.goalie
        if goalie < 0 or not self._deciding[goalie]:
            return
        b = int(self.world.belief_of[goalie])
        self.urgent[goalie] = False
        if play_on and int(ball_player(self.state, b)) == goalie:
            self.goals[goalie] = self.our_points[b, goalie]
            self.urgent[goalie] = True
        else:
            self.goals[goalie] = skills.guard_position(self.model, self.world.ball[b])

    def _follow_ups(self, beliefs: np.ndarray, view: TeamView | PlayerViews, cycle: int) -> None:
        """After a belief's own shot, its forwards follow up (:func:`~agents.teams.decisions.follow_up_goals`)
        until the follow-up time is over or an opponent has the ball."""
        params = self.shape.params
        world = self.world
        for b in beliefs.tolist():
            decisions = self.decisions[b]
            if cycle - decisions.shot_cycle > params.follow_up_cycles:
                continue
            if self.their_cycle[b] == 0 and (self.our_first[b] < 0 or self.our_cycles[b, self.our_first[b]] > 0):
                decisions.shot_cycle = NO_SHOT  # an opponent has the ball: the follow-up is over
                continue
            rows = (world.belief_of == b) & self._deciding
            follow_up_goals(params, self.shape.is_forward, self.model.half_length, decisions.shot_from,
                            world.view_of(b), int(ball_player(self.state, b)), self.outfield,
                            self.match_roles[b][self.followed[b]], rows, self.goals, self.urgent)

    def _sample_makespans(self) -> None:
        """Fixed and held roles against the minimal makespan (:mod:`agents.teams.mechanism`), as
        the first outfield player's belief has them."""
        b = int(self.world.belief_of[self.outfield[0]])
        players = np.ascontiguousarray(self.world.mate_pos[b][self.outfield])
        role_targets = np.ascontiguousarray(self.targets[b][self.match_roles[b]])
        self.figures.add_sample(*mechanism.makespans(players, role_targets, self.followed[b]))

    def _decide(self, beliefs: np.ndarray) -> np.ndarray:
        """Step 5 for each belief with a player on the ball by it; returns which beliefs kicked."""
        world, command = self.world, self.command
        kicked = self._kicked
        kicked[:] = False
        self._decided = []
        for b in beliefs.tolist():
            rows = (world.belief_of == b) & self._deciding
            if not (rows & self._on_ball).any():
                continue
            decisions = self.decisions[b]
            kicked[b] = decisions.decide(world.view_of(b), self._race(b), int(ball_player(self.state, b)), rows,
                                         self._mode_since, self.goals, self.urgent, command, bool(self.in_flight[b]),
                                         self.able[b])
            self._decided.append(b)
        return kicked

    def _after_dashes(self, decided: list[int] | tuple, view: TeamView | PlayerViews) -> None:
        """For the ``decided`` beliefs (those that decided on the ball this cycle): the dribbler
        runs with the ball, not to a point; our set-play taker held back by the stamina policy
        runs to the ball anyway (:meth:`~agents.teams.set_plays.SetPlays.run_if_held_back`)."""
        world, command = self.world, self.command
        mode, ours = view.play_mode, view.mode_ours
        for b in decided:
            decisions = self.decisions[b]
            if decisions.dribble_dash is not None and decisions.kicker >= 0:
                command.dash[decisions.kicker] = decisions.dribble_dash
                decisions.dribble_dash = None
            if mode != PlayMode.PLAY_ON and ours:
                taker = decisions.set_plays.taker
                if taker >= 0 and world.belief_of[taker] == b:
                    decisions.set_plays.run_if_held_back(world.view_of(b), self.goals, command.dash)

    def _remember_passes(self, beliefs: np.ndarray, kicked: np.ndarray, play_on: bool,
                         view: TeamView | PlayerViews) -> None:
        """A belief that kicked holds our pass in flight, and the team-mates then in an offside
        position unable to play it; out of play on, without a kick, no pass is in flight."""
        if not play_on:
            self.in_flight[beliefs] = False
        for b in np.flatnonzero(kicked).tolist():
            self.in_flight[b] = True
            own = self.world.view_of(b)
            self.able[b] = ~skills.offside_positions(self.model, own.own_pos, own.opp_pos, own.ball)
            self.able[b][np.flatnonzero(self.command.kick.any(axis=1))] = True
        self.able[~self.in_flight] = True

    def _count_conflicts(self, shared: int, empty: int) -> None:
        """Count the play-on cycles whose believed roles clash: ``shared`` roles two players both
        believe they hold, ``empty`` roles nobody believes they hold."""
        self._play_on_cycles += 1
        self._conflict_cycles += shared > 0
        self._unfilled_cycles += empty > 0

    def _track_agreement(self, cycle: int) -> None:
        """Count the play-on cycles in which every outfield player on the pitch follows one
        assignment, and time the spells in between (players who hold their own beliefs only:
        under the truth every player follows the one belief's)."""
        on_pitch = self.outfield[self._deciding[self.outfield]]
        followed = self.followed[self.world.belief_of[on_pitch]]
        agreed = bool((followed == followed[0]).all()) if on_pitch.size else True
        self._agreed_cycles += agreed
        if agreed and self._spell_start >= 0:
            self._spells.append(cycle - self._spell_start)
            self._spell_start = -1
        elif not agreed and self._spell_start < 0:
            self._spell_start = cycle

    # ------------------------------------------------------------------ reporting
    def statistics(self) -> dict[str, float]:
        """The role figures (:class:`~agents.teams.reporting.RoleFigures`) and, when the players
        hold their own beliefs, the shares of play-on cycles with a role that two players both
        believe they hold (``role_conflict_share``), that nobody believes they hold
        (``believed_unfilled_share``) and in which every outfield player follows one assignment
        (``all_follow_one_share``), and the median number of play-on cycles from when they stop
        following one assignment until they all follow one again (``agreement_latency_median``,
        over the spells that ended before a stoppage; 0 without any)."""
        merged = self.figures.statistics()
        if self.world.talks:
            cycles = max(self._play_on_cycles, 1)
            merged["role_conflict_share"] = self._conflict_cycles / cycles
            merged["believed_unfilled_share"] = self._unfilled_cycles / cycles
            merged["all_follow_one_share"] = self._agreed_cycles / cycles
            merged["agreement_latency_median"] = float(np.median(self._spells)) if self._spells else 0.0
        return merged

    def situation(self, b: int) -> Situation:
        """Belief ``b``'s formation situation this cycle."""
        mode, ours = self._mode_key
        return situation_of(PlayMode(mode) if mode >= 0 else PlayMode.KICK_OFF, ours, bool(self.attacking[b]))
