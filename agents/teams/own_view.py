"""The built-in team's positioning under partial observation, each player on its own world model.

Every player of a :class:`~agents.teams.decentralised.DecentralisedPlay` team who is not on the
ball decides here, with the steps of :class:`~agents.teams.formation_team.FormationTeam` run on
what it alone believes (row ``i`` of :class:`~agents.teams.world_model.TeamBeliefs`):

1. its ball race (who of ours and theirs reaches its believed ball first, and where);
2. in play on, attack or defend with hysteresis and its block moved at the block's pace;
   at set plays the set-play formation at its believed ball (at the centre after a goal);
3. the formation queried at its block (or ball), the targets shifted and settled as the team's
   are (rest defence, the block's pace), and when it believes we attack, support spots around
   our carrier as role targets;
4. the role assigner run on its believed team-mates and targets (its *proposal*; on the
   cycles it sees, at most every :data:`ASSIGN_EVERY` cycles, and at once when the play mode
   changes), and the assignment most of the votes it holds agree on followed
   (:func:`agents.roles.voting.follow_votes`); before a kick-off everybody lines up in its own
   role (by shirt number), which every player knows without a word;
5. its goal: the followed role's target, pulled back onside; its interception point when it
   believes it goes for the ball or presses; a steering assigner's field (bidding) where it
   leads; the goalkeeper's guard point;
6. its dash at the pace the stamina policy allows (:func:`agents.skills.player_kernels.paced_dash_rows`),
   or its placement before a kick-off.

Who decides and who assigns, and the steps before the assigner, are one compiled call for the
whole team (:func:`~agents.teams.own_view_kernels.before_roles`); the assigner one call for all
the players that assign when it has a batch form (:meth:`~agents.roles.RoleAssigner.assign_rows`:
the distance-only ones) and one per player otherwise; following the votes and the goals one
more call (:mod:`agents.teams.own_view_after`); the dashes and the role figures, after the whole
brains acted, a last one that also makes what the players say (:meth:`OwnViewPositioning.finish`).
The three compiled calls take the team's arrays as one compiled record made on the first cycle
(:mod:`agents.teams.own_view_state`), so each call hands over little more than the players'
senses of the cycle. Missing from the full
team's open play: the positions' own runs and the follow-ups of shots (only the shooter
knows it shot), and an assigner's own choice of the player who goes for the ball (bidding's
ball role): each player takes the first of ours in its ball race. The player on the ball,
our set-play taker and the goalkeeper near its goal decide with a whole brain
(:mod:`agents.teams.decentralised`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from agents import skills
from agents.messages import CYCLE_MODULUS, WORLD_GRID
from agents.roles import RoleAssigner, RoleContext, offensive_order
from agents.roles.voting import VoteBook
from agents.skills.movement import DEFAULT_PACING
from agents.skills.pacing import pacing_constants
from agents.teams import mechanism
from agents.teams.on_ball import ball_reach
from agents.teams.own_view_kernels import assignment_problems
from agents.teams.own_view_state import (OTHER_TABLES, PositioningState, before_roles_of, dash_and_say_of,
                                         follow_and_goals_of, state_of)
from agents.teams.positions import nearest_roles
from agents.teams.reporting import RoleFigures
from agents.teams.role_kernels import steered_goals
from agents.teams.world_model import TeamBeliefs
from formations import Situation
from soccer_sim.config import MatchConfig
from soccer_sim.perception.views import PlayerViews
from soccer_sim.state import SET_PLAYS, PlayMode
from soccer_sim.team import TeamView

if TYPE_CHECKING:
    from agents.teams.formation_team import FormationTeam

ASSIGN_EVERY = 4
"""Cycles between a player's assignments at least (it assigns on the cycles it sees): its
believed inputs move little in 0.4 s, and the held assignment is kept between."""

RACE_NEAR = 20.0
"""A player who believes the ball within this (m) runs its ball race again on every cycle it
sees; farther away..."""
RACE_EVERY = 2
"""... on the cycles it sees at least this many cycles after its last race (and at the latest
one cycle later): between sees its beliefs only roll forward, so the last race holds."""

PLACED = (PlayMode.KICK_OFF, PlayMode.AFTER_GOAL)
"""Play modes in which players are placed (``move``) rather than run."""


class OwnViewPositioning:
    """The positioning of a team's players, each on its own beliefs (module docstring).

    ``brains``: the players' own brains (one :class:`FormationTeam` each, reset), whose
    formation, style, assigner and context each player uses; ``view``: a team view with the
    side's array shapes (for the skills' checked arrays)."""

    def __init__(self, brains: list[FormationTeam], config: MatchConfig, view: TeamView) -> None:
        first = brains[0]
        self.brains = brains
        self.n = n = first.n
        self.goalie = first.goalie
        self.outfield = first.outfield
        self.model = model = first.model
        self.formation_set = first.formation_set
        self.style = first.style
        k = len(self.outfield)
        roles = len(self.formation_set.roles)
        self.rank = np.full(n, -1, dtype=np.int64)
        """(n,) each player's index among the outfield players (-1: the goalkeeper)."""
        self.rank[self.outfield] = np.arange(k)
        self.match_roles = np.zeros((n, k), dtype=np.int64)
        """(n, k) the outfield roles each player believes the side fills (all of them for a full
        side; a smaller side's players each pick theirs on the first cycle)."""
        if not first._choose_roles:
            self.match_roles[:] = first._match_roles
        self._choose_roles = first._choose_roles
        self._steers = first._steers
        self._batches = type(first.assigner).assign_rows is not RoleAssigner.assign_rows
        """Whether the assigner answers many views in one call (:meth:`RoleAssigner.assign_rows`)."""
        shape = first.shape
        arrays = first.skills.arrays(view)
        # each player's memory
        self.attacking = np.zeros(n, dtype=bool)
        self._pending = np.zeros(n, dtype=np.int64)
        self._in_play = np.zeros(n, dtype=bool)
        self._block = np.zeros((n, 3))
        self._primed = np.zeros(n, dtype=bool)
        self.targets = np.zeros((n, roles, 2))
        """(n, roles, 2) each player's role targets this cycle (its formation query, settled)."""
        self._previous = np.zeros((n, roles, 2))
        self._state: PositioningState | None = None
        self._state_of: tuple = ()
        self._full = np.zeros(n, dtype=bool)
        self._mode, self._ours = PlayMode.KICK_OFF, False
        """The play mode of the last positioning, and whether it was ours (for :meth:`situation`)."""
        self.proposals = np.tile(np.arange(k, dtype=np.int64), (n, 1))
        """(n, k) the assignment each player computed last (its vote)."""
        self.followed = self.proposals.copy()
        """(n, k) the assignment each player follows."""
        self._last_followed = self.followed.copy()
        self._next = self.followed.copy()
        """(n, k) the assignment each player follows from this cycle on (made before it is followed)."""
        # each player's last ball race (kept between its races) and this cycle's goals
        self._raced = np.full(n, -(1 << 40), dtype=np.int64)
        self.our_cycles = np.zeros((n, n), dtype=np.int64)
        self.our_points = np.zeros((n, n, 2))
        self.our_first = np.full(n, -1, dtype=np.int64)
        self.their_cycle = np.zeros(n, dtype=np.int64)
        self.win_point = np.zeros((n, 2))
        self.goals = np.zeros((n, 2))
        self.urgent = np.zeros(n, dtype=bool)
        self._phase = np.zeros(n, dtype=np.int64)
        self._budgets = np.zeros(n)
        self._assigned_at = np.full(n, -(1 << 40), dtype=np.int64)
        self._assigned_mode = np.full(n, -1, dtype=np.int64)
        self._rows, self._outfield_rows, self._due_rows = (np.zeros(n, dtype=np.int64) for _ in range(3))
        """This cycle's deciding rows, their outfield ones and who of those assigns (filled by before_roles)."""
        self._counts = (0, 0)
        """How many of those rows and outfield rows there are (:meth:`step` for :meth:`finish`)."""
        self._problems = (np.zeros((n, k, 2)), np.zeros((n, self.match_roles.shape[1], 2)))
        """Room for the assignment problems of the players who assign in one cycle (their
        believed outfield players and their roles' targets)."""
        sp, style, third = shape.params, self.style, model.half_length / 3.0
        self._record = dict(
            # who assigns
            assigned_at=self._assigned_at, assigned_mode=self._assigned_mode, assign_every=int(ASSIGN_EVERY),
            steers=bool(self._steers), first_outfield=int(self.outfield[0]) if self.outfield.size else -1,
            # the ball race
            radius=arrays.ours.radius, catch_radius=arrays.ours.catch_radius, opp_radius=arrays.theirs.radius,
            opp_catch_radius=arrays.theirs.catch_radius, reach=model.reach, ball_travel=model.ball_travel,
            coast=model.player_coast, raced=self._raced,
            race_constants=first.skills.intercept_params,
            race_near=float(RACE_NEAR), race_every=int(RACE_EVERY),
            # the switch, the block and the settled targets
            switch_margin=sp.switch_margin, switch_persist=sp.switch_persist, depth=float(shape.depth),
            attack_push=float(shape.attack_push), knobs=shape.settle_record, outfield_roles=shape.outfield_roles,
            back_roles=shape.back_roles, x_limit=model.half_length - 2.0, forwards=first._forward_roles,
            narrowing=1.0 - style.box_narrowing, narrow_x=third,
            # the support spots
            is_forward=shape.is_forward, is_back=shape.is_back, offsets=shape.offsets,
            support_players=sp.support_players, support_pressure=sp.support_pressure,
            support_horizon=sp.support_horizon, third_x=third, support_knobs=shape.support_record,
            # each player's memory, assignments, targets and rows
            attacking=self.attacking, pending=self._pending, in_play=self._in_play, block=self._block,
            our_cycles=self.our_cycles, our_points=self.our_points, our_first=self.our_first,
            their_cycle=self.their_cycle, win_point=self.win_point, previous=self._previous, primed=self._primed,
            proposals=self.proposals, followed=self.followed, following=self._next, rank=self.rank,
            match_roles=self.match_roles, full=self._full, targets=self.targets, rows=self._rows,
            outfield_rows=self._outfield_rows, due=self._due_rows,
            # goals, dashes and the role figures
            stationary=bool(style.stationary), spots=first.kick_off_spots, outfield=self.outfield,
            goalie=int(self.goalie), offside_margin=float(style.offside_margin), pressers=int(style.pressers),
            keeper_margin=int(skills.GoalieParams().race_margin),
            area_x=float(model.half_length - model.penalty_area_length),
            area_y=float(model.penalty_area_half_width), half_length=float(model.half_length), goals=self.goals,
            urgent=self.urgent, phase=self._phase,
            pacing=pacing_constants(model, DEFAULT_PACING, 0.05), budgets=self._budgets,
            last_followed=self._last_followed, unfilled=float(style.unfilled_distance),
            # what the players say
            world_grid=WORLD_GRID, vote_modulus=int(CYCLE_MODULUS))
        """The compiled record's fields but the world models', the votes' and the formations'
        (:mod:`agents.teams.own_view_state`; made on the first cycle, :meth:`_state_for`)."""
        self._no_votes, self._no_vote_cycles = np.zeros((n, n, 0), dtype=np.int64), np.zeros((n, n), dtype=np.int64)
        self.figures = RoleFigures(config, k)
        """The team's role figures: each player's distance to the target of the role it follows."""

    # ------------------------------------------------------------------ one cycle
    def step(self, views: PlayerViews, beliefs: TeamBeliefs, deciding: np.ndarray, votes: VoteBook | None,
             count: int | None = None) -> np.ndarray | None:
        """Position the ``deciding`` players (n,) bool for this cycle up to their goals (their
        dashes follow in :meth:`finish`); returns their placements (n, 2) in a play mode that
        places players, else None. ``votes``: the team's :class:`~agents.roles.voting.VoteBook`
        (None: no outfield roles); ``count``: how many players decide, when the caller knows."""
        self._counts = (0, 0)
        if not (deciding.any() if count is None else count):
            return None
        mode = views.play_mode
        play_on = mode == PlayMode.PLAY_ON
        placed = mode in PLACED
        cycle = views.cycle
        ball = beliefs.ball
        if self._choose_roles:
            self._pick_roles(np.flatnonzero(views.present), beliefs)
        self._mode, self._ours = mode, bool(views.mode_ours)
        state = self._state_for(beliefs, votes)
        sampled = mechanism.sampled(cycle)
        other = OTHER_TABLES[self._situation_of(mode, self._ours).value] if not play_on else 0
        n_rows, n_out, n_due = before_roles_of(
            state, deciding, int(mode), play_on, mode == PlayMode.AFTER_GOAL, placed,
            play_on and not self.style.stationary, sampled, other, views.velocity, views.effort, views.saw, cycle)
        outfield_rows = self._outfield_rows[:n_out]
        if placed:
            self.line_up(outfield_rows)
        elif n_out:
            self._assign(self._due_rows[:n_due], beliefs, int(mode), cycle)
        style = self.style
        follow_and_goals_of(state, n_rows, n_out, n_due, placed, play_on, cycle)
        if self._steers and not style.stationary:
            self._steer(outfield_rows, beliefs, play_on, cycle)
        goalie = self.goalie
        if goalie >= 0 and deciding[goalie]:
            self.goals[goalie] = skills.guard_position(self.model, ball[goalie])
            self.urgent[goalie] = False
        if play_on and n_out and sampled:  # fixed and held roles v the minimal makespan, as the first player sees them
            i = int(outfield_rows[0])
            players = np.ascontiguousarray(beliefs.mate_pos[i][self.outfield])
            role_targets = np.ascontiguousarray(self.targets[i][self.match_roles[i]])
            self.figures.add_sample(*mechanism.makespans(players, role_targets, self._last_followed[i]))
        self._counts = (n_rows, n_out)
        return self.goals if placed else None

    def finish(self, views: PlayerViews, beliefs: TeamBeliefs, votes: VoteBook | None, dash: np.ndarray,
               say_world: bool, digits: np.ndarray) -> tuple[int, int]:
        """The end of the cycle, after the whole brains acted, in one compiled call
        (:func:`~agents.teams.own_view_state.dash_and_say_of`): the dashes of the players
        :meth:`step` positioned into ``dash`` (n, 2) and the role figures; the digits of what
        every player says into ``digits`` (n, 10), its world message (``say_world``) or its
        vote; and the believed role conflicts in play on, returned as (roles two players hold,
        roles nobody holds)."""
        n_rows, n_out = self._counts
        play_on = views.play_mode == PlayMode.PLAY_ON
        switches, mean, largest, far, shared, empty = dash_and_say_of(
            self._state_for(beliefs, votes), n_rows, n_out, play_on, views.position, views.velocity, views.effort,
            views.stamina, views.capacity, views.cycle, views.half, dash, say_world, digits)
        if play_on and n_out:
            self.figures.add(switches, True, mean, largest, far)
        return shared, empty

    def line_up(self, rows: np.ndarray) -> None:
        """Before a kick-off the outfield ``rows`` each take their own role (by shirt number),
        which every player knows without a word; they assign afresh once play starts."""
        self.proposals[rows] = self.followed[rows] = np.arange(self.proposals.shape[1])
        self._assigned_mode[rows] = -1

    def _pick_roles(self, rows: np.ndarray, beliefs: TeamBeliefs) -> None:
        """A smaller side: each player takes, once, the outfield roles it believes nearest the
        outfield players (as :meth:`FormationTeam._pick_roles` does for the whole team)."""
        first = self.brains[0]
        for i in rows.tolist():
            self.match_roles[i] = nearest_roles(self.formation_set, first._outfield_roles, beliefs.ball[i],
                                                beliefs.mate_pos[i][self.outfield])
        self._choose_roles = False

    @staticmethod
    def _situation_of(mode: PlayMode, ours: bool) -> Situation:
        """The formation situation of a play mode other than play on: the set-play formations
        at set plays, a held ball and the pause after a goal; else the normal one."""
        if mode == PlayMode.AFTER_GOAL or mode in SET_PLAYS or mode == PlayMode.GOALIE_HOLDS:
            return Situation.OUR_SET_PLAY if ours else Situation.THEIR_SET_PLAY
        return Situation.NORMAL

    def situation(self, i: int) -> Situation:
        """Player ``i``'s formation situation at its last positioning."""
        if self._mode == PlayMode.PLAY_ON:
            return Situation.ATTACK if self.attacking[i] else Situation.DEFEND
        return self._situation_of(self._mode, self._ours)

    def _state_for(self, beliefs: TeamBeliefs, votes: VoteBook | None) -> PositioningState:
        """The compiled record of this positioning's arrays (:mod:`agents.teams.own_view_state`)
        with ``beliefs``' and ``votes``' arrays, made on the first cycle (again if either changes)."""
        if self._state is not None and self._state_of[0] is beliefs and self._state_of[1] is votes:
            return self._state
        tables = {situation: self.formation_set.formation(situation).query_tables for situation in Situation}
        votes_of = (self._no_votes, self._no_vote_cycles, 0) if votes is None else \
            (votes.votes, votes.vote_cycle, int(votes.horizon))
        values = dict(self._record, ball=beliefs.ball, ball_vel=beliefs.ball_vel, ball_age=beliefs.ball_age,
                      mate_pos=beliefs.mate_pos,
                      opp_pos=beliefs.opp_pos, votes=votes_of[0], vote_cycle=votes_of[1], vote_horizon=votes_of[2],
                      tables_attack=tables[Situation.ATTACK], tables_defend=tables[Situation.DEFEND],
                      tables_our_set_play=tables[Situation.OUR_SET_PLAY],
                      tables_their_set_play=tables[Situation.THEIR_SET_PLAY], tables_normal=tables[Situation.NORMAL])
        self._state, self._state_of = state_of(values), (beliefs, votes)
        return self._state

    def _assign(self, rows: np.ndarray, beliefs: TeamBeliefs, mode: int, cycle: int) -> None:
        """The role assigner on each of the due players ``rows``' own model (module docstring, step 4)."""
        play_on = mode == PlayMode.PLAY_ON
        self._assigned_at[rows], self._assigned_mode[rows] = cycle, mode
        first = self.brains[0]
        if rows.size and self._batches and not (first._leave is not None and play_on):  # all in one call
            players, role_targets = self._problems[0][:rows.size], self._problems[1][:rows.size]
            assignment_problems(rows, self.outfield, beliefs.mate_pos, self.targets, self.match_roles, players,
                                role_targets)
            proposals = first.assigner.assign_rows(players, role_targets, first._context)
            if proposals is not None:
                self.proposals[rows] = proposals
                return
        for i in rows.tolist():
            brain = self.brains[i]
            players = beliefs.mate_pos[i][self.outfield]
            role_targets = self.targets[i][self.match_roles[i]]
            context = self._context(i, brain, beliefs, play_on, cycle)
            proposal = None
            if brain._leave is not None and play_on:
                proposal = brain._leave.assign(players, role_targets, int(self.our_first[i]), self.our_points[i],
                                               self.followed[i], context)
            if proposal is None:
                order = offensive_order(role_targets) if brain.assigner.uses_role_order else None
                proposal = brain.assigner.assign(players, role_targets, order, self.followed[i], context)
            self.proposals[i] = proposal

    def _context(self, i: int, brain: FormationTeam, beliefs: TeamBeliefs, play_on: bool, cycle: int) -> RoleContext:
        """Player ``i``'s :class:`RoleContext` refreshed from its own beliefs."""
        context = brain._context
        context.ball = self.win_point[i] if play_on else beliefs.ball[i]
        context.ball_reach = None
        if brain.assigner.uses_ball_reach and play_on:
            context.ball_reach = ball_reach(self.our_cycles[i], self.outfield, self.model)
        context.opponents = beliefs.opp_pos[i]
        context.cycle = cycle
        context.attacking = bool(self.attacking[i])
        return context

    def _steer(self, rows: np.ndarray, beliefs: TeamBeliefs, play_on: bool, cycle: int) -> None:
        """A steering assigner (potential-field bidding) moves each player not going for the
        ball along its own field rather than straight to its role's target."""
        for i in rows.tolist():
            brain = self.brains[i]
            if not brain._steers or self.urgent[i]:
                continue
            players = beliefs.mate_pos[i][self.outfield]
            role_targets = self.targets[i][self.match_roles[i]]
            followed = self.followed[i]
            context = self._context(i, brain, beliefs, play_on, cycle)
            steps = brain.assigner.steer(players, role_targets, followed, context)
            r = self.rank[i]
            self.goals[i] = steered_goals(players[r:r + 1], steps[r:r + 1], role_targets[followed[r:r + 1]])[0]
