"""The built-in team: formation positioning with a pluggable role assigner, plus soccer skills.

Every cycle (team frame: we attack +x, our goal at x = -half_length):

1. **Who wins the ball.** :func:`agents.skills.ball_race` rolls the ball forward and finds, for
   both teams, the first player that can control it and where.
2. **Situation and formation.** Set plays (ours or theirs, kick-offs and the pause after a
   goal included) use the set-play formations; in play on we *attack* when we win the race
   and *defend* otherwise. The formation is queried at the point where the ball will be
   controlled (the race's interception point), not where it is now, so the team moves to
   where play is going. A style may shift the whole outfield block forwards or back.
3. **Roles.** The role assigner (``mmdr``, ``mmd+msd2``, ``static``, ``greedy``, ...; see
   :mod:`agents.roles`) maps the ten outfield players to the ten outfield role targets; it
   may also steer the players (potential-field bidding) and name the ball player. This is
   the only thing that differs between the assigner variants of the team.
4. **The ball.** In play on the player who reaches the ball first (or the assigner's ball
   player) runs to the interception point; a style may send a second presser when defending.
   A player who can kick decides with :func:`agents.skills.decide_on_ball` (shoot, pass,
   dribble or clear). At our set plays the player nearest the ball takes it after the others
   had ``set_play_wait`` cycles to take their places (see :meth:`FormationTeam._take_set_play`:
   taken in time, retaken set plays by another player and another kick); the goalkeeper
   distributes a held ball.
5. **Everybody else** runs to their targets (attackers kept onside), sprinting only when it
   matters (:func:`agents.skills.speed_caps`); the goalkeeper guards the line between ball and
   goal and catches (never a back-pass).

**Smaller sides** (a scenario's 0 to 11 players, the goalkeeper optional): the goalkeeper, if
any, keeps the goalkeeper role, and the outfield players take as many of the formation's
outfield roles, those whose targets lie nearest them when play starts (a minimal-total-distance
matching on the first cycle), for the whole match; a side of no players does nothing.

The team reports per-match figures through :meth:`FormationTeam.statistics` and what it would
like drawn through :meth:`FormationTeam.drawing`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numba import njit

import formations
from agents import skills
from agents.roles import RoleAssigner, RoleContext, make_assigner, offensive_order
from agents.skills.ball_kernels import offside_line
from formations.formation_set import Situation
from soccer_sim.config import MatchConfig
from soccer_sim.state import SET_PLAYS, PlayMode
from soccer_sim.team import SideInfo, TeamCommand, TeamView

_PLAY_ON = PlayMode.PLAY_ON
_KICK_OFF = PlayMode.KICK_OFF
_AFTER_GOAL = PlayMode.AFTER_GOAL
_GOALIE_HOLDS = PlayMode.GOALIE_HOLDS
_RETAKE_WINDOW = 50
"""A set play of ours given again at the same spot within this many cycles of our kick is
that set play retaken."""
_CYCLES_PER_MINUTE = 600
"""Cycles of 100 ms in a minute of game time."""


ATTACKING_DECISIONS = skills.DecisionParams(
    shot=skills.ShotParams(threshold=0.2),
    dribbling=skills.DribbleParams(goal_weight=2.0, speed_fraction=0.85),
)
"""The built-in team's on-ball choices: shoot when a shot has a fair chance (the skill's own
threshold waits for a near-certain one, which against a goalkeeper almost never comes) and
dribble towards the goal rather than along the wings."""


@dataclass(frozen=True)
class TeamStyle:
    """How a team plays, apart from its role assigner."""

    system: str = "4-3-3"
    """Built-in formation set (``formations.builtin_names()``)."""
    depth: float = 0.0
    """Metres the outfield block is shifted towards the opponents' goal in open play (negative:
    a deeper block)."""
    attack_push: float = 14.0
    """Extra metres the outfield block moves up when we attack (win the race for the ball)."""
    box_narrowing: float = 0.5
    """When we attack with the ball in the final third, the forwards' targets move this share
    of the way towards the middle of the field (so that there are players in the box)."""
    pressers: int = 1
    """Players sent at the ball when the opponents win the race (1: just the fastest)."""
    decision: skills.DecisionParams = field(default_factory=lambda: ATTACKING_DECISIONS)
    """Thresholds of the on-ball decision (shoot, pass, dribble, clear)."""
    offside_margin: float = 1.0
    """Attackers without the ball stay this far behind the offside line (m)."""
    set_play_wait: int = 15
    """Cycles our set-play taker waits before kicking, so the others can take their places."""
    stationary: bool = False
    """Outfield players hold their kick-off spots and only kick a ball that comes to them (the
    baseline against which positioning is measured)."""
    unfilled_distance: float = 10.0
    """A role counts as unfilled while the player assigned to it is farther than this (m)."""


class FormationTeam:
    """The built-in team (see the module docstring) with role assigner ``assigner`` and style
    ``style``; ``name`` is how it reports itself (defaults to the assigner's name)."""

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
        if kinds.count("goalkeeper") != 1:
            raise ValueError(f"formation set {self.style.system!r} needs exactly one goalkeeper role")
        self._goalie_role = kinds.index("goalkeeper")
        self._outfield_roles = np.array([r for r in range(len(kinds)) if r != self._goalie_role], dtype=np.int64)
        self._forward_roles = np.array([r for r in range(len(kinds)) if kinds[r] == "forward"], dtype=np.int64)

    # ------------------------------------------------------------------ match lifecycle
    def reset(self, side_info: SideInfo, config: MatchConfig, rng: np.random.Generator) -> None:
        n = side_info.players_per_team
        roles = len(self.formation_set.roles)
        goalie = side_info.goalie_index
        outfield_count = n - (1 if 0 <= goalie < n else 0)
        if n > roles or outfield_count > len(self._outfield_roles):
            raise ValueError(f"{type(self).__name__} plays at most {roles} players per side, "
                             f"{len(self._outfield_roles)} of them outfield (formation {self.style.system!r}), "
                             f"not {n} with {outfield_count} outfield")
        self.skills = skills.SkillContext.for_match(config, side_info)
        """The skills' per-match context (motion model, tables, the view's checked arrays)."""
        self.model = self.skills.model
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
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))
        self.goals = np.zeros((n, 2))
        self.targets = np.zeros((roles, 2))
        self.role_of_player: np.ndarray | None = None
        self.kick_off_spots = self._kick_off_spots()
        self._half_length = config.field.half_length
        self._half_width = config.field.half_width
        self._own_goal = np.array([-self._half_length, 0.0])
        self._opp_goal = np.array([self._half_length, 0.0])
        self._context = RoleContext(
            ball=np.zeros(2), own_goal=self._own_goal, opp_goal=self._opp_goal, opponents=np.zeros((n, 2)),
            field_half_length=self._half_length, field_half_width=self._half_width, cycle=0, attacking=False,
            penalty_area_length=config.field.penalty_area_length,
            penalty_area_half_width=config.field.penalty_area_width / 2.0,
        )
        """What the assigner sees besides positions; one object per match, refreshed every cycle."""
        self._kickable = config.physics.kickable_distance
        self._mode_key: tuple[int, bool] = (-1, False)
        self._mode_since = 0
        self._our_pass_in_flight = False
        self._situation = Situation.NORMAL
        self._dribble_dash: np.ndarray | None = None
        self._kicker_row = -1
        self._goal_kick_leaving = False
        self._set_play_taker = -1
        """Our taker of the current set play (-1: not chosen yet)."""
        self._sprinter = -1
        """The player who runs flat out this cycle whatever its stamina (our set-play taker)."""
        self._taken: tuple[int, float, float, int] | None = None
        """(mode, ball x, ball y, cycle) of the last set play we kicked."""
        self._tried_takers: list[int] = []
        self._tried_kicks: list[np.ndarray] = []
        """Takers and kick directions of the current set play's attempts (a retake tries others)."""
        self._patience = max(self.style.set_play_wait, config.rules.set_play_timeout // 2)
        """Cycles of a set play after which whoever of ours can kick the ball takes it."""
        self._kick_off_gap = config.physics.player_radius + config.physics.ball_radius + 0.1
        """How far behind the ball our kick-off taker is placed (m)."""
        self._goal_centre_guard = np.array([-self._half_length + skills.GoalieParams().depth_far, 0.0])
        """Where our goalkeeper waits at our goal kicks: in front of the goal's centre, away
        from the spot on the goal area's corner and from every kick out of it."""
        self._eligible = np.ones(n, dtype=bool)
        # Per-match figures.
        self._cycles = 0
        self._switches = 0
        self._assigned_cycles = 0
        self._distance_sum = 0.0
        self._makespan_sum = 0.0
        self._unfilled_role_cycles = 0

    def _kick_off_spots(self) -> np.ndarray:
        """(n, 2) where each role stands at our kick-off (team frame)."""
        return self.formation_set.positions((0.0, 0.0), Situation.OUR_SET_PLAY)

    def _pick_roles(self, view: TeamView) -> None:
        """A smaller side's outfield players take the outfield roles whose targets (for the ball
        where it is now) are nearest them, one each (minimal total distance)."""
        from scipy.optimize import linear_sum_assignment

        targets = self.formation_set.positions(view.ball, Situation.NORMAL)[self._outfield_roles]
        players = view.own_pos[self.outfield]
        cost = np.hypot(players[:, None, 0] - targets[None, :, 0], players[:, None, 1] - targets[None, :, 1])
        _, chosen = linear_sum_assignment(cost)
        self._match_roles = np.sort(self._outfield_roles[chosen])
        self._out_roles = _as_slice(self._match_roles)
        self._choose_roles = False

    # ------------------------------------------------------------------ one cycle
    def act(self, view: TeamView) -> TeamCommand:
        command = self.command
        if self.n == 0:
            return command
        if self._choose_roles:
            self._pick_roles(view)
        command.kick[:] = 0.0
        command.catch = False
        command.move = None
        mode = view.play_mode
        key = (int(mode), bool(view.mode_ours))
        # Our set-play kick of the last cycle leaves a set play only when the referee restarted
        # it at once (a touch in the kick's cycle): that is a new set play too.
        restarted = mode != _PLAY_ON and self._taken is not None and self._taken[3] == view.cycle - 1
        if key != self._mode_key or restarted:
            if mode != _PLAY_ON:
                self._goal_kick_leaving = False
                self._begin_set_play(view)
            self._mode_key, self._mode_since = key, view.cycle
        ctx, model = self.skills, self.model
        race = skills.ball_race(ctx, view, self._eligible if self._our_pass_in_flight else None,
                                their_first_only=True)
        situation, ball_ref = self._situation_and_ball(view, race)
        self._situation = situation
        targets = self.targets
        targets[:] = self.formation_set.positions(ball_ref, situation)
        style = self.style
        shift = style.depth + (style.attack_push if situation == Situation.ATTACK else 0.0)
        shifted = mode == _PLAY_ON and shift != 0.0
        narrowed = situation == Situation.ATTACK and ball_ref[0] > self._half_length / 3.0 and style.box_narrowing
        if shifted or narrowed:
            _shape_targets(targets, self._match_roles, shift, shifted, self._half_length - 2.0,
                           self._forward_roles, 1.0 - style.box_narrowing, bool(narrowed))
        self._assign_roles(view, targets, ball_ref)
        urgent = np.zeros(self.n, dtype=bool)
        self._sprinter = -1
        if mode == _PLAY_ON:
            self._play_on(view, race, urgent)
        elif mode in (_KICK_OFF, _AFTER_GOAL):
            self._kick_off(view, urgent)
        elif mode == _GOALIE_HOLDS:
            self._goalie_holds(view)
        else:
            self._set_play(view, urgent)
        ours = ctx.arrays(view).ours
        caps = skills.speed_caps(ctx, view, urgent)
        skills.dash_to_points(model, ours.pos, ours.vel, self.goals, ours.effort, caps, out=command.dash)
        if self._sprinter >= 0:
            # Our set-play taker runs flat out whatever its stamina: a set play not taken in
            # time is lost (the ball is dropped).
            r = slice(self._sprinter, self._sprinter + 1)
            skills.dash_to_points(model, ours.pos[r], ours.vel[r], self.goals[r], ours.effort[r],
                                  out=command.dash[r])
        if self._dribble_dash is not None:  # the dribbler runs with the ball, not to a point
            command.dash[self._kicker_row] = self._dribble_dash
            self._dribble_dash = None
        if _any_nonzero(command.kick):
            # Team-mates in an offside position when we play the ball must keep off it.
            self._our_pass_in_flight = True
            self._eligible = ~skills.offside_positions(model, view.own_pos, view.opp_pos, view.ball)
            self._eligible[np.flatnonzero(command.kick.any(axis=1))] = True
        elif mode != _PLAY_ON:
            self._our_pass_in_flight = False
        return command

    def _situation_and_ball(self, view: TeamView, race: skills.BallRace) -> tuple[Situation, np.ndarray]:
        """The formation situation and the ball position to query it at."""
        mode = view.play_mode
        if mode == _PLAY_ON:
            if race.we_win and race.ours.first >= 0:
                return Situation.ATTACK, race.ours.points[race.ours.first]
            if race.theirs.first >= 0:
                return Situation.DEFEND, race.theirs.points[race.theirs.first]
            return Situation.NORMAL, view.ball
        if mode == _AFTER_GOAL:
            return (Situation.OUR_SET_PLAY if view.mode_ours else Situation.THEIR_SET_PLAY), np.zeros(2)
        if mode in SET_PLAYS or mode == _GOALIE_HOLDS:
            return (Situation.OUR_SET_PLAY if view.mode_ours else Situation.THEIR_SET_PLAY), view.ball
        return Situation.NORMAL, view.ball

    def _assign_roles(self, view: TeamView, targets: np.ndarray, ball_ref: np.ndarray) -> None:
        """Outfield players -> outfield roles (the assigner), and everybody's goal point."""
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
            context = self._context
            context.ball = ball_ref
            context.opponents = view.opp_pos
            context.cycle = view.cycle
            context.attacking = self._situation == Situation.ATTACK
            assigner = self.assigner
            order = offensive_order(role_targets) if assigner.uses_role_order else None
            role_of_player = assigner.assign(players, role_targets, order, self.role_of_player, context)
            # An assigner that keeps the default steer sends each player to its role's target:
            # the kernel below places those goals itself.
            goals = assigner.steer(players, role_targets, role_of_player, context) if self._steers else None
        previous = self.role_of_player if self.role_of_player is not None else role_of_player
        measured = view.play_mode == _PLAY_ON
        switches, mean, largest, unfilled = _settle_roles(self.goals, self.outfield, role_targets, role_of_player,
                                                          goals, players, previous, self.style.unfilled_distance,
                                                          measured)
        self._switches += switches
        if measured:
            self._cycles += 1
            self._distance_sum += mean
            self._makespan_sum += largest
            self._unfilled_role_cycles += unfilled
        self.role_of_player = role_of_player
        if self.goalie >= 0:
            self.goals[self.goalie] = skills.guard_position(self.model, view.ball)

    # ------------------------------------------------------------------ play on
    def _play_on(self, view: TeamView, race: skills.BallRace, urgent: np.ndarray) -> None:
        ctx, model, command, goals = self.skills, self.model, self.command, self.goals
        if self._goal_kick_leaving:
            if model.in_penalty_area(view.ball):
                return  # our goal kick is on its way out: with proper goal kicks nobody may play it yet
            self._goal_kick_leaving = False
        ball_player = self._ball_player(view, race)
        if not self.style.stationary:
            self._keep_onside(view, ball_player)
        if ball_player >= 0:
            goals[ball_player] = race.ours.points[ball_player]
            urgent[ball_player] = True
        if not race.we_win and self.style.pressers > 1 and not self.style.stationary:
            order = np.argsort(race.ours.cycles[self.outfield], kind="stable")
            for row in self.outfield[order][: self.style.pressers]:
                if row != ball_player:
                    goals[row] = race.ours.points[row] if race.ours.cycles[row] < skills.UNREACHABLE else view.ball
                    urgent[row] = True
        # An opponent on the ball ends our pass (for the back-pass rule) and contests it.
        contested = race.theirs.first_cycle == 0
        if contested:
            self._our_pass_in_flight = False
        kicker = self._kicker(view, race, ball_player)
        goalie_near = self.goalie >= 0 and race.ours.cycles[self.goalie] <= 1
        if kicker >= 0 and kicker == self.goalie and skills.should_catch(
                ctx, view, self.goalie, teammate_kicked_last=self._our_pass_in_flight):
            command.catch = True  # a held ball is safer than a kick
            kicker = -1
        self._kicker_row = kicker
        if kicker >= 0:
            if kicker == self.goalie:
                command.kick[kicker] = skills.distribute(ctx, view, kicker).kick
            else:
                decision = skills.decide_on_ball(ctx, view, kicker, self.style.decision,
                                                 pressure=race.theirs.first_cycle)
                if contested and decision.action in (skills.OnBallAction.DRIBBLE, skills.OnBallAction.CLEAR):
                    # Against an opponent who kicks the ball too, a dribble or a clearance up the
                    # field meets its mirror image and the two kicks cancel: kick it towards
                    # the nearer touchline instead (both teams doing so add up).
                    command.kick[kicker] = self._wing_kick(view, kicker)
                else:
                    command.kick[kicker] = decision.kick
                    if decision.dash is not None:
                        self._dribble_dash = decision.dash
        elif goalie_near and not command.catch and skills.should_catch(
                ctx, view, self.goalie, teammate_kicked_last=self._our_pass_in_flight):
            command.catch = True

    def _wing_kick(self, view: TeamView, kicker: int) -> np.ndarray:
        """The kick sending the ball hard towards the nearer touchline, a little forwards."""
        side = 1.0 if view.ball[1] >= 0.0 else -1.0
        direction = np.array([0.3, side]) / np.hypot(0.3, 1.0)
        kick, _ = skills.kick_for_velocity(self.model, view.own_pos[kicker], view.ball, view.ball_vel,
                                           direction * self.model.kick_speed_max)
        return kick

    def _ball_player(self, view: TeamView, race: skills.BallRace) -> int:
        """Our player who goes for the ball (-1: none can reach it in time)."""
        named = self.assigner.ball_player()
        if named is not None and not self.style.stationary:
            return int(self.outfield[named])
        first = race.ours.first
        if first < 0:
            return -1
        if self.style.stationary:
            # Statues only step in for a ball that comes to them.
            return first if race.ours.cycles[first] <= 2 else -1
        if first == self.goalie and not self.model.in_penalty_area(race.ours.points[first]):
            cycles = race.ours.cycles[self.outfield]
            if not cycles.size:  # a lone goalkeeper stays in its area
                return -1
            best = int(np.argmin(cycles))
            return int(self.outfield[best]) if cycles[best] < skills.UNREACHABLE else -1
        return int(first)

    def _kicker(self, view: TeamView, race: skills.BallRace, ball_player: int) -> int:
        """The one player of ours who kicks this cycle (-1: none can). Only players the race
        says control the ball now are candidates (it already leaves out those offside when we
        played the ball)."""
        if race.ours.first_cycle != 0:
            return -1
        gaps = np.hypot(*(view.own_pos - view.ball).T)
        if self._our_pass_in_flight:
            gaps[~self._eligible] = np.inf  # offside when the ball was played: hands off
        nearest = int(np.argmin(gaps))
        if gaps[nearest] > self._kickable:
            return -1
        if ball_player >= 0 and gaps[ball_player] <= self._kickable:
            return ball_player
        return nearest

    def _keep_onside(self, view: TeamView, ball_player: int) -> None:
        """Outfield goals beyond the offside line (the second-last opponent or the ball, in
        their half) are pulled back behind it by ``offside_margin``."""
        _pull_onside(self.goals, self.outfield, view.opp_pos, float(view.ball[0]), self.style.offside_margin)

    # ------------------------------------------------------------------ set plays
    def _begin_set_play(self, view: TeamView) -> None:
        """A new play mode other than play on: forget the taker; at a set play of ours that is
        the one we just kicked given again (a retake), remember who took it and how, so that
        another player takes it another way."""
        self._set_play_taker = -1
        taken = self._taken
        retake = (view.mode_ours and taken is not None and taken[0] == int(view.play_mode)
                  and view.cycle - taken[3] <= _RETAKE_WINDOW
                  and taken[1] == float(view.ball[0]) and taken[2] == float(view.ball[1]))
        if not retake:
            self._tried_takers.clear()
            self._tried_kicks.clear()

    def _taker(self, view: TeamView) -> int:
        """The outfield player nearest the ball that has not tried this set play yet (a lone
        goalkeeper takes it)."""
        candidates = self.outfield if len(self.outfield) else np.arange(self.n)
        fresh = np.setdiff1d(candidates, self._tried_takers)
        if fresh.size:
            candidates = fresh
        gaps = np.hypot(*(view.own_pos[candidates] - view.ball).T)
        return int(candidates[int(np.argmin(gaps))])

    def _kick_off(self, view: TeamView, urgent: np.ndarray) -> None:
        """Before a kick-off (and in the pause after a goal) place everybody on the set-play
        formation; at our kick-off the taker is placed just behind the ball and plays it once
        the wait is over."""
        taker = self._take_set_play(view, urgent) if view.play_mode == _KICK_OFF and view.mode_ours else -1
        move = self.goals.copy()
        if taker >= 0:
            move[taker] = (view.ball[0] - self._kick_off_gap, view.ball[1])
        self.command.move = move

    def _set_play(self, view: TeamView, urgent: np.ndarray) -> None:
        if not view.mode_ours:
            return
        if view.play_mode == PlayMode.GOAL_KICK and self.goalie >= 0:
            self.goals[self.goalie] = self._goal_centre_guard
        self._take_set_play(view, urgent)

    def _take_set_play(self, view: TeamView, urgent: np.ndarray) -> int:
        """Our set play: the taker (chosen once per set play) runs to the ball and, the wait
        over, kicks it; if it is not there after ``_patience`` cycles, whoever of ours can kick
        the ball takes it, so a set play is always taken well within the referee's timeout.
        Returns the taker."""
        taker = self._set_play_taker
        if taker < 0:
            taker = self._set_play_taker = self._taker(view)
        self.goals[taker] = view.ball
        urgent[taker] = True
        self._sprinter = taker
        waited = view.cycle - self._mode_since
        if waited < self.style.set_play_wait:
            return taker
        gaps = np.hypot(*(view.own_pos - view.ball).T)
        kicker = taker
        if gaps[taker] > self._kickable:
            kicker = int(np.argmin(gaps))
            if waited < self._patience or gaps[kicker] > self._kickable:
                return taker
        self._kick_set_play(view, kicker)
        return taker

    def _kick_set_play(self, view: TeamView, kicker: int) -> None:
        """``kicker`` takes our set play. A goal kick is cleared along a path nobody else can
        reach before the ball leaves our penalty area (the kicks of earlier attempts avoided);
        other set plays are played as in open play, or cleared when retaken."""
        ctx = self.skills
        if view.play_mode == PlayMode.GOAL_KICK:
            plan = skills.goal_kick_clearance(ctx, view, kicker, avoid=tuple(self._tried_kicks))
            kick, direction = plan.kick, plan.direction
            # With proper goal kicks our own players must keep off the ball until it is out of
            # the area (see _play_on).
            self._goal_kick_leaving = self.config.rules.proper_goal_kicks
        else:
            kick = None
            if not self._tried_kicks:
                kick = skills.decide_on_ball(ctx, view, kicker, self.style.decision).kick
            if kick is None or not kick.any():
                kick = skills.best_clearance(ctx, view, kicker).kick
            speed = float(np.hypot(*kick))
            direction = kick / speed if speed > 0.0 else np.array([1.0, 0.0])
        self.command.kick[kicker] = kick
        self._taken = (int(view.play_mode), float(view.ball[0]), float(view.ball[1]), view.cycle)
        self._tried_takers.append(kicker)
        self._tried_kicks.append(direction)

    def _goalie_holds(self, view: TeamView) -> None:
        if self.goalie < 0:
            return
        if view.ball_holder == self.goalie and view.cycle - self._mode_since >= self.style.set_play_wait:
            self.command.kick[self.goalie] = skills.distribute(self.skills, view, self.goalie).kick
        self.goals[self.goalie] = view.own_pos[self.goalie]

    # ------------------------------------------------------------------ reporting
    def statistics(self) -> dict[str, float]:
        """Per-match figures (play-on cycles only): role switches per minute of play, the mean
        and the largest distance from the outfield players to their role targets (averaged over
        cycles: the largest is the assignment's makespan), and the share of role-cycles a role
        was unfilled (its player farther than ``unfilled_distance``)."""
        cycles = max(self._cycles, 1)
        roles = max(len(self.outfield), 1)
        return {
            "role_switches_per_minute": self._switches / max(self._cycles / _CYCLES_PER_MINUTE, 1e-9)
            if self._cycles else 0.0,
            "target_distance_mean": self._distance_sum / cycles,
            "target_distance_max": self._makespan_sum / cycles,
            "role_unfilled_share": self._unfilled_role_cycles / (cycles * roles),
        }

    def drawing(self) -> dict[str, object]:
        """What a replay may draw (team frame): ``targets`` (n, 2) each role's target, ``goals``
        (n, 2) where each player is going, ``role_of_player`` (outfield player -> outfield role),
        ``outfield`` (the outfield players' indices), ``assigned_targets`` (one row per outfield
        player: its role's target; None before the first assignment), and the current
        formation's sample balls and triangles (``formation_balls`` (m, 2),
        ``formation_triangles`` (t, 3))."""
        formation = self.formation_set.formation(self._situation)
        role_of_player = self.role_of_player
        assigned = None if role_of_player is None else self.targets[self._out_roles][role_of_player]
        return {
            "targets": self.targets.copy(), "goals": self.goals.copy(), "outfield": self.outfield.copy(),
            "role_of_player": None if role_of_player is None else role_of_player.copy(),
            "assigned_targets": assigned,
            "formation_balls": formation.balls, "formation_triangles": formation.triangles,
        }


@njit(cache=True, nogil=True)
def _settle_roles(goals: np.ndarray, rows: np.ndarray, targets: np.ndarray, role_of_player: np.ndarray,
                  steered: np.ndarray | None, players: np.ndarray, previous: np.ndarray, unfilled: float,
                  measured: bool) -> tuple[int, float, float, int]:  # pragma: no cover - compiled
    """Write the outfield players' goals (row ``rows[i]`` of ``goals``: ``steered[i]``, or its
    role's target when ``steered`` is None) and return the cycle's figures: role switches
    since ``previous``, and when ``measured`` the mean and the largest distance from a player
    to its role's target and the roles whose player is farther than ``unfilled`` (zeros when
    not measured)."""
    k = players.shape[0]
    switches, total, largest, far = 0, 0.0, 0.0, 0
    for i in range(k):
        t = role_of_player[i]
        if steered is None:
            goals[rows[i], 0] = targets[t, 0]
            goals[rows[i], 1] = targets[t, 1]
        else:
            goals[rows[i], 0] = steered[i, 0]
            goals[rows[i], 1] = steered[i, 1]
        if t != previous[i]:
            switches += 1
        if measured:
            d = math.hypot(players[i, 0] - targets[t, 0], players[i, 1] - targets[t, 1])
            total += d
            if d > largest:
                largest = d
            if d > unfilled:
                far += 1
    return switches, total / max(k, 1), largest, far


@njit(cache=True, nogil=True)
def _shape_targets(targets: np.ndarray, rows: np.ndarray, shift: float, shifted: bool, x_limit: float,
                   forwards: np.ndarray, narrowing: float, narrowed: bool) -> None:  # pragma: no cover - compiled
    """The style's changes to the formation's targets (team frame, in place): ``rows`` moved
    ``shift`` metres up the field and kept within ``|x| <= x_limit`` when ``shifted``; the
    ``forwards``' y scaled by ``narrowing`` when ``narrowed``."""
    if shifted:
        for r in rows:
            targets[r, 0] = min(max(targets[r, 0] + shift, -x_limit), x_limit)
    if narrowed:
        for r in forwards:
            targets[r, 1] *= narrowing


@njit(cache=True, nogil=True)
def _any_nonzero(values: np.ndarray) -> bool:  # pragma: no cover - compiled
    """Whether any entry of ``values`` is non-zero (``values.any()`` without its overhead)."""
    for x in values.ravel():
        if x != 0.0:
            return True
    return False


def _as_slice(indices: np.ndarray) -> slice | np.ndarray:
    """``indices`` as a slice when they are consecutive, else unchanged."""
    if indices.size and np.array_equal(indices, np.arange(indices[0], indices[0] + indices.size)):
        return slice(int(indices[0]), int(indices[0]) + indices.size)
    return indices


@njit(cache=True, nogil=True)
def _pull_onside(goals: np.ndarray, rows: np.ndarray, opp_pos: np.ndarray, ball_x: float,
                 margin: float) -> None:  # pragma: no cover - compiled
    """Goals of ``rows`` beyond the offside line (the second-last opponent or the ball, never
    in our half) are pulled back to ``margin`` behind it (but not into our half)."""
    limit = offside_line(opp_pos, ball_x) - margin
    for r in rows:
        if goals[r, 0] > limit:
            goals[r, 0] = max(limit, 0.0)
