"""The built-in team: formation positioning with a pluggable role assigner, plus soccer skills.

Every cycle (team frame: we attack +x, our goal at x = -half_length):

1. **Who wins the ball.** :func:`agents.skills.ball_race` rolls the ball forward and finds, for
   both teams, the first player that can control it and where.
2. **Situation and formation.** Set plays (ours or theirs, kick-offs and the pause after a
   goal included) use the set-play formations; in play on we *attack* or *defend* as the race
   says, with hysteresis, and query the formation where the ball will be controlled (the
   race's interception point); a style may shift the outfield block. :mod:`agents.teams.shape`
   moves all this at a running pace, keeps a rest defence, makes support spots role targets
   and sends follow-ups.
3. **Roles.** The role assigner (``mmdr``, ``mmd+msd2``, ``static``, ``greedy``, ...; see
   :mod:`agents.roles`) maps the ten outfield players to the ten outfield role targets; it
   may also steer the players (potential-field bidding) and name the ball player. This is
   the only thing that differs between the assigner variants of the team.
4. **The ball.** In play on the player who reaches the ball first (or the assigner's ball
   player) runs to the interception point; a style may send a second presser when defending.
   A player who can kick decides with :func:`agents.skills.decide_on_ball` (shoot, pass,
   dribble or clear). At our set plays the player nearest the ball takes it after the others
   had ``set_play_wait`` cycles to take their places (see :mod:`agents.teams.set_plays`:
   taken in time, retaken set plays by another player and another kick); the goalkeeper
   distributes a held ball.
5. **Everybody else** runs to their targets (attackers kept onside), sprinting only when it
   matters and otherwise at a pace the stamina recovery pays for (:func:`agents.skills.paced_dashes`,
   the stamina policy of :mod:`agents.skills.pacing`); the goalkeeper guards the line between ball and
   goal and catches (never a back-pass).

**Smaller sides** (a scenario's 0 to 11 players, the goalkeeper optional): the goalkeeper, if
any, keeps the goalkeeper role, and the outfield players take as many of the formation's
outfield roles, those whose targets lie nearest them when play starts (a minimal-total-distance
matching on the first cycle), for the whole match; a side of no players does nothing.

The team reports per-match figures through :meth:`FormationTeam.statistics`
(:mod:`agents.teams.reporting`) and what it would like drawn through
:meth:`FormationTeam.drawing` (a :class:`soccer_sim.team_hooks.Drawing`). Its style is a
:class:`~agents.teams.style.TeamStyle`; its compiled kernels are in
:mod:`agents.teams.role_kernels`.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

import formations
from agents import skills
from agents.roles import RoleAssigner, RoleContext, make_assigner, offensive_order
from agents.teams import mechanism
from agents.teams.ball_role import LeaveMatching, check_ball_role
from agents.teams.decentralised import DecentralisedPlay
from agents.teams.on_ball import (able_players, ball_player, ball_reach, choose_kicker, make_tackling, on_ball_kick,
                                  tackle_if_worth)
from agents.teams.positions import current_labels, nearest_roles, position_labels
from agents.teams.reporting import RoleFigures, team_drawing
from agents.teams.role_behaviours import RoleBehaviours
from agents.teams.role_kernels import pull_onside, settle_roles, shape_targets, steered_goals
from agents.teams.set_plays import SetPlays
from agents.teams.shape import Shape
from agents.teams.style import ATTACKING_DECISIONS, TeamStyle
from agents.teams.type_choice import choose_types, time_scales
from formations.formation_set import Situation
from soccer_sim.config import MatchConfig
from soccer_sim.state import SET_PLAYS, PlayMode
from soccer_sim.perception.views import PlayerViews
from soccer_sim.team import SideInfo, TeamCommand, TeamView
from soccer_sim.team_hooks import Drawing

__all__ = ["ATTACKING_DECISIONS", "FormationTeam", "TeamStyle"]

_PLAY_ON = PlayMode.PLAY_ON
_KICK_OFF = PlayMode.KICK_OFF
_AFTER_GOAL = PlayMode.AFTER_GOAL
_GOALIE_HOLDS = PlayMode.GOALIE_HOLDS


class FormationTeam:
    """The built-in team (see the module docstring) with role assigner ``assigner`` and style
    ``style``; ``name`` is how it reports itself (defaults to the assigner's name). Under partial
    observation each player decides on its own (:mod:`agents.teams.decentralised`)."""

    observation_modes = ("full", "partial")

    def __init__(self, assigner: str = "mmd+msd2", style: TeamStyle | None = None, name: str | None = None,
                 **assigner_params: object) -> None:
        self.style = style or TeamStyle()
        self.assigner_name = assigner
        self.assigner = make_assigner(assigner, **assigner_params)
        self._steers = type(self.assigner).steer is not RoleAssigner.steer
        """Whether the assigner moves players elsewhere than their role targets (bidding)."""
        self.name = name or assigner
        self.formation_set = formations.load_builtin(self.style.system)
        kinds = [role.kind for role in self.formation_set.roles]
        self._role_labels = position_labels(self.formation_set)
        if kinds.count("goalkeeper") != 1:
            raise ValueError(f"formation set {self.style.system!r} needs exactly one goalkeeper role")
        self._goalie_role = kinds.index("goalkeeper")
        self._outfield_roles = np.array([r for r in range(len(kinds)) if r != self._goalie_role], dtype=np.int64)
        self._forward_roles = np.array([r for r in range(len(kinds)) if kinds[r] == "forward"], dtype=np.int64)
        leave = check_ball_role(self.style.ball_role, assigner) == "leave"
        self._leave = LeaveMatching(assigner, assigner_params) if leave else None  # (agents.teams.ball_role)
        self._brain = lambda: type(self)(assigner, style, name, **assigner_params)
        self.role_filter: Callable[[np.ndarray], np.ndarray] | None = None
        """A hook from the assignment computed to the one followed (a player's votes); None: it."""
        self.players: DecentralisedPlay | None = None
        """Under partial observation: the players deciding on their own (else None)."""

    def choose_player_types(self, types: tuple, side_info: SideInfo) -> list[int]:
        """Each player's type, by its role (:mod:`agents.teams.type_choice`)."""
        return choose_types(types, self.formation_set, self._outfield_roles, side_info.players_per_team,
                            side_info.goalie_index)

    # ------------------------------------------------------------------ match lifecycle
    def reset(self, side_info: SideInfo, config: MatchConfig, rng: np.random.Generator) -> None:
        self.players = None
        if config.observation.partial and self.role_filter is None:  # (a player's own brain has a filter)
            self.players = DecentralisedPlay(self._brain, side_info, config, rng)
            return
        n = side_info.players_per_team
        roles = len(self.formation_set.roles)
        goalie = side_info.goalie_index
        outfield_count = n - (1 if 0 <= goalie < n else 0)
        if n > roles or outfield_count > len(self._outfield_roles):
            raise ValueError(f"{type(self).__name__} plays at most {roles} players per side, "
                             f"{len(self._outfield_roles)} of them outfield (formation {self.style.system!r}), "
                             f"not {n} with {outfield_count} outfield")
        self.skills = skills.SkillContext.for_match(config, side_info)
        self.model = model = self.skills.model
        self.config = config
        self.n = n
        self.goalie = goalie
        """Our goalkeeper's index, -1 when we have none."""
        self.outfield = np.array([i for i in range(n) if i != self.goalie], dtype=np.int64)
        self._has_outfield = len(self.outfield) > 0
        self._out = _as_slice(self.outfield)
        """The outfield rows, as a slice when they are contiguous (cheaper than fancy indexing)."""
        self._match_roles = self._outfield_roles
        """The outfield roles this match fills (all of them, or those chosen on the first cycle)."""
        self._choose_roles = outfield_count < len(self._outfield_roles)
        self._out_roles = _as_slice(self._outfield_roles)
        if len(self.outfield):  # (a goalkeeper alone, or nobody, has no roles to assign)
            self.assigner.reset(len(self.outfield), rng)
            if self._leave is not None:
                self._leave.reset(self.outfield, n, rng)
        self._ball_row, self._ball_row_cycle = -1, -1  # the ball player chosen before the matching, its cycle
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))
        self.goals = np.zeros((n, 2))
        self.targets = np.zeros((roles, 2))
        self.role_of_player: np.ndarray | None = None
        self.kick_off_spots = self._kick_off_spots()
        self._half_length = model.half_length
        self._context = RoleContext(
            ball=np.zeros(2), own_goal=model.goal_centre(ours=True), opp_goal=model.goal_centre(ours=False),
            opponents=np.zeros((n, 2)), field_half_length=model.half_length, field_half_width=model.half_width,
            cycle=0, attacking=False, penalty_area_length=model.penalty_area_length,
            penalty_area_half_width=model.penalty_area_half_width,
            time_scale=time_scales(side_info.player_types, side_info.own_types, self.outfield, config),
        )
        """What the assigner sees besides positions; one object per match, refreshed every cycle."""
        self._kickable = model.kickable_distance
        self._mode_key: tuple[int, bool] = (-1, False)
        self._mode_since = 0
        self._our_pass_in_flight = False
        self._situation = Situation.NORMAL
        self._dribble_dash: np.ndarray | None = None
        self._kicker_row = -1
        self._woken_since: int | None = None
        self._eligible = np.ones(n, dtype=bool)
        self.set_plays = SetPlays(self.skills, config, self.style, self.outfield)
        """Our set plays: takers, retakes, kick-off placement, the goalkeeper's held ball."""
        self.figures = RoleFigures(config, len(self.outfield))
        """The per-match figures :meth:`statistics` reports."""
        self.role_behaviours = RoleBehaviours(self.formation_set, model.half_length, model.half_width)
        """Each position's own moves of its role target in open play (:mod:`agents.teams.role_behaviours`)."""
        self.shape = Shape(self.style.shape, [role.kind for role in self.formation_set.roles], self.style.depth,
                           self.style.attack_push, model.half_length, model.half_width)
        """The team's shape in open play: attack/defend switch, pace, rest defence, support."""
        self.tackling = make_tackling(model, config, side_info, self.style.tackling)
        """Our tackles (:mod:`agents.skills.tackling`)."""

    def _kick_off_spots(self) -> np.ndarray:
        """(n, 2) where each role stands at our kick-off (team frame)."""
        return self.formation_set.positions((0.0, 0.0), Situation.OUR_SET_PLAY)

    def _pick_roles(self, view: TeamView) -> None:
        """A smaller side's outfield players take the outfield roles whose targets (for the ball
        where it is now) are nearest them, one each (:func:`~agents.teams.positions.nearest_roles`)."""
        self._match_roles = nearest_roles(self.formation_set, self._outfield_roles, view.ball,
                                          view.own_pos[self.outfield])
        self._out_roles = _as_slice(self._match_roles)
        self._choose_roles = False

    # ------------------------------------------------------------------ one cycle
    def act(self, view: TeamView | PlayerViews) -> TeamCommand:
        if self.players is not None:
            return self.players.act(view)
        command = self.command
        if self.n == 0:
            return command
        if self._choose_roles:
            self._pick_roles(view)
        command.kick[:] = 0.0
        command.catch = False
        command.move = None
        command.tackle = command.foul = None
        mode = view.play_mode
        key = (int(mode), bool(view.mode_ours))
        set_plays = self.set_plays
        # Our set-play kick of the last cycle leaves a set play only when the referee restarted
        # it at once (a touch in the kick's cycle): that is a new set play too.
        restarted = mode != _PLAY_ON and set_plays.kicked_last_cycle(view)
        if key != self._mode_key or restarted:
            if mode != _PLAY_ON:
                set_plays.begin(view)
            self._mode_key, self._mode_since = key, view.cycle if self._woken_since is None else self._woken_since
        self._woken_since = None
        ctx, model = self.skills, self.model
        race = skills.ball_race(ctx, view, able_players(view, self._eligible if self._our_pass_in_flight else None),
                                their_first_only=True)
        situation, ball_ref = self._situation_and_ball(view, race)
        self._situation = situation
        targets = self.targets
        targets[:] = self.formation_set.positions(ball_ref, situation)
        style = self.style
        shift = self.shape.shift
        shifted = mode == _PLAY_ON and shift != 0.0
        narrowed = situation == Situation.ATTACK and ball_ref[0] > self._half_length / 3.0 and style.box_narrowing
        if shifted or narrowed:
            shape_targets(targets, self._match_roles, shift, shifted, self._half_length - 2.0,
                          self._forward_roles, 1.0 - style.box_narrowing, bool(narrowed))
        if mode == _PLAY_ON and situation != Situation.NORMAL:
            self.role_behaviours.adjust(targets, situation == Situation.ATTACK, ball_ref, view.opp_pos)
        if not style.stationary:
            self.shape.settle(view, targets, mode == _PLAY_ON)
            if mode == _PLAY_ON:  # support spots are role targets: the assigner picks who goes
                self.shape.support(view, race, self._ball_player(view, race), self.outfield, self._match_roles,
                                   self.role_of_player, targets)
        self._assign_roles(view, targets, ball_ref, race)
        urgent = np.zeros(self.n, dtype=bool)
        if mode == _PLAY_ON:
            self._play_on(view, race, urgent)
        elif mode in (_KICK_OFF, _AFTER_GOAL):
            set_plays.kick_off(view, self.goals, command, urgent, self._mode_since)
        elif mode == _GOALIE_HOLDS:
            set_plays.goalie_holds(view, self.goals, command, self._mode_since)
        else:
            set_plays.set_play(view, self.goals, command, urgent, self._mode_since)
        # Urgent players (the ball's, pressers, our set-play taker) sprint down to the stamina
        # floor, the others pace themselves (agents.skills.pacing).
        attacking = situation == Situation.ATTACK if mode == _PLAY_ON else None
        skills.paced_dashes(ctx, view, self.goals, urgent, command.dash, attacking=attacking)
        if mode != _PLAY_ON and view.mode_ours:
            set_plays.run_if_held_back(view, self.goals, command.dash)
        if self._dribble_dash is not None:  # the dribbler runs with the ball, not to a point
            command.dash[self._kicker_row] = self._dribble_dash
            self._dribble_dash = None
        if np.count_nonzero(command.kick):
            # Team-mates in an offside position when we play the ball must keep off it.
            self._our_pass_in_flight = True
            self._eligible = ~skills.offside_positions(model, view.own_pos, view.opp_pos, view.ball)
            self._eligible[np.flatnonzero(command.kick.any(axis=1))] = True
        elif mode != _PLAY_ON:
            self._our_pass_in_flight = False
        return command

    def wake(self, mode_since: int) -> None:
        """This brain did not act last cycle (a player's own, under partial observation): forget
        what holds only from cycle to cycle; the play mode began at ``mode_since``."""
        self._our_pass_in_flight = False
        self._dribble_dash = None
        self.shape.restart()
        self._mode_key = (-1, False)
        self._woken_since = mode_since

    def _situation_and_ball(self, view: TeamView, race: skills.BallRace) -> tuple[Situation, np.ndarray]:
        """The formation situation and the ball position to query it at."""
        mode = view.play_mode
        if mode == _PLAY_ON:
            return self.shape.play_on(view, race)
        if mode == _AFTER_GOAL:
            return (Situation.OUR_SET_PLAY if view.mode_ours else Situation.THEIR_SET_PLAY), np.zeros(2)
        if mode in SET_PLAYS or mode == _GOALIE_HOLDS:
            return (Situation.OUR_SET_PLAY if view.mode_ours else Situation.THEIR_SET_PLAY), view.ball
        return Situation.NORMAL, view.ball

    def _assign_roles(self, view: TeamView, targets: np.ndarray, ball_ref: np.ndarray,
                      race: skills.BallRace) -> None:
        """Outfield players -> outfield roles (the assigner; with ``ball_role="leave"`` in play
        on, the ball player out of the matching), and everybody's goal point."""
        outfield = self._out
        role_targets = targets[self._out_roles]
        players = view.own_pos[outfield]
        if not self._has_outfield:
            self.goals[self.goalie] = skills.guard_position(self.model, view.ball)
            return
        if self.style.stationary:
            role_of_player = np.arange(len(self.outfield))
            goals = self.kick_off_spots[self._match_roles]
        else:
            context, assigner, play_on = self._context, self.assigner, view.play_mode == _PLAY_ON
            context.ball = self.shape.ball_point if play_on else ball_ref  # (not the block's paced query point)
            context.ball_reach = ball_reach(race.ours.cycles, self.outfield, self.model) \
                if assigner.uses_ball_reach and play_on else None
            context.opponents = view.opp_pos
            context.cycle = view.cycle
            context.attacking = self._situation == Situation.ATTACK
            role_of_player = self._ball_row_cycle = None
            if self._leave is not None and view.play_mode == _PLAY_ON:
                self._ball_row, self._ball_row_cycle = self._ball_player(view, race), view.cycle
                role_of_player = self._leave.assign(players, role_targets, self._ball_row, race.ours.points,
                                                    self.role_of_player, context)
            if role_of_player is None:
                order = offensive_order(role_targets) if assigner.uses_role_order else None
                role_of_player = assigner.assign(players, role_targets, order, self.role_of_player, context)
            if self.role_filter is not None:
                role_of_player = self.role_filter(role_of_player)
            # (a default steer sends each player to its role's target: the kernel below does that)
            goals = None
            if self._steers:
                goals = steered_goals(players, assigner.steer(players, role_targets, role_of_player, context),
                                      role_targets[role_of_player])
        previous = self.role_of_player if self.role_of_player is not None else role_of_player
        measured = view.play_mode == _PLAY_ON
        switches, mean, largest, unfilled = settle_roles(self.goals, self.outfield, role_targets, role_of_player,
                                                         goals, players, previous, self.style.unfilled_distance,
                                                         measured)
        self.figures.add(switches, measured, mean, largest, unfilled)
        if measured and mechanism.sampled(view.cycle):  # fixed roles v the minimal makespan
            self.figures.add_sample(*mechanism.makespans(players, role_targets, previous))
        self.role_of_player = role_of_player
        if self.goalie >= 0:
            self.goals[self.goalie] = skills.guard_position(self.model, view.ball)

    # ------------------------------------------------------------------ play on
    def _play_on(self, view: TeamView, race: skills.BallRace, urgent: np.ndarray) -> None:
        ctx, model, command, goals = self.skills, self.model, self.command, self.goals
        set_plays = self.set_plays
        if set_plays.goal_kick_leaving:
            if model.in_penalty_area(view.ball):
                return  # our goal kick is on its way out: with proper goal kicks nobody may play it yet
            set_plays.goal_kick_leaving = False
        ball_player = self._ball_player(view, race)
        if not self.style.stationary:  # goals beyond the offside line go back behind it by offside_margin
            pull_onside(self.goals, self.outfield, view.opp_pos, float(view.ball[0]), self.style.offside_margin)
        if ball_player >= 0:
            goals[ball_player] = race.ours.points[ball_player]
            urgent[ball_player] = True
        if not race.we_win and self.style.pressers > 1 and not self.style.stationary:
            order = np.argsort(race.ours.cycles[self.outfield], kind="stable")
            for row in self.outfield[order][: self.style.pressers]:
                if row != ball_player:
                    goals[row] = race.ours.points[row] if race.ours.cycles[row] < skills.UNREACHABLE else view.ball
                    urgent[row] = True
        if not self.style.stationary and self.role_of_player is not None:
            self.shape.follow_up(view, race, ball_player, self.outfield, self._match_roles, self.role_of_player,
                                 goals, urgent)
        # An opponent on the ball ends our pass (for the back-pass rule) and contests it.
        contested = race.theirs.first_cycle == 0
        if contested:
            self._our_pass_in_flight = False
        kicker = choose_kicker(view, race, ball_player, self._kickable,
                               able_players(view, self._eligible if self._our_pass_in_flight else None))
        goalie_near = self.goalie >= 0 and race.ours.cycles[self.goalie] <= 1
        if kicker >= 0 and kicker == self.goalie and skills.should_catch(
                ctx, view, self.goalie, teammate_kicked_last=self._our_pass_in_flight):
            command.catch = True  # a held ball is safer than a kick
            kicker = -1
        self._kicker_row = kicker
        if kicker >= 0:
            blocking = self.tackling.shot_at_us(view, self._our_pass_in_flight)
            kick, self._dribble_dash, shot = on_ball_kick(ctx, view, kicker, self.goalie, self.style.decision, race,
                                                          contested, blocking)
            command.kick[kicker] = kick
            if shot:
                self.shape.shot(view.cycle, view.ball)
        elif goalie_near and not command.catch and skills.should_catch(
                ctx, view, self.goalie, teammate_kicked_last=self._our_pass_in_flight):
            command.catch = True
        elif not command.catch:
            tackle_if_worth(self.tackling, view, command, race, self._our_pass_in_flight)

    def _ball_player(self, view: TeamView, race: skills.BallRace) -> int:
        """Our player who goes for the ball (-1: none can reach it in time)."""
        if self._ball_row_cycle == view.cycle:  # chosen before the matching this cycle
            return self._ball_row
        return ball_player(self.assigner.ball_player(), race, self.goalie, self.outfield, self.model,
                           self.style.stationary)

    # ------------------------------------------------------------------ reporting
    def statistics(self) -> dict[str, float]:
        """Per-match figures (play-on cycles only): role switches per minute of play, the mean
        and the largest distance from the outfield players to their role targets (averaged over
        cycles: the largest is the assignment's makespan), and the share of role-cycles a role
        was unfilled (its player farther than ``unfilled_distance``)."""
        return self.players.statistics() if self.players is not None else self.figures.statistics()

    def role_labels(self) -> list[str]:
        """Each player's current position (row order; :func:`~agents.teams.positions.current_labels`)."""
        if self.players is not None:
            return self.players.role_labels()
        return current_labels(self._role_labels, self.n, self.outfield, self._match_roles, self.role_of_player,
                              self.goalie, self._goalie_role)

    def drawing(self) -> Drawing:
        """What a replay may draw (team frame): each role's target, where each player is
        going, the outfield players and their roles and role targets (None before the first
        assignment), and the current formation's sample balls and triangles (under partial
        observation: the roles as the first outfield player believes them)."""
        if self.players is not None:
            return self.players.drawing()
        return team_drawing(self.formation_set.formation(self._situation), self.targets, self._out_roles,
                            self.goals, self.outfield, self.role_of_player)


def _as_slice(indices: np.ndarray) -> slice | np.ndarray:
    """``indices`` as a slice when they are consecutive, else unchanged."""
    if indices.size and np.array_equal(indices, np.arange(indices[0], indices[0] + indices.size)):
        return slice(int(indices[0]), int(indices[0]) + indices.size)
    return indices
