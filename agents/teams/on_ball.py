"""The built-in team's player on the ball in play on: who of ours may play the ball, who
kicks this cycle and what the kick is, and our tackle when an opponent has the ball (team
frame: we attack +x)."""

from __future__ import annotations

import numpy as np

from agents import skills
from agents.skills.tackling import TackleParams, Tackling, player_inertia
from agents.teams.carrying import carry_kick
from agents.teams.finishing import finishing_shot
from soccer_sim.config import MatchConfig
from soccer_sim.team import SideInfo, TeamCommand, TeamView

_SAVE = skills.SaveParams()
_BLOCK = skills.SaveParams(behind_depth=20.0)
"""An outfield player's block of a shot at our goal, or its clearance within ``behind_depth``
(20 m: the penalty area and a few metres beyond) of our goal line with an opponent about to
win the ball: wide of the post and over our goal line (a corner rather than a chance). With
the area's 16.5 m alone, 1.5 corners a match between built-in teams; with 20 m, 1.75."""
_DEEP_PRESSURE = 4
"""Cycles until an opponent controls the ball within which a player of ours deep in our half
counts as pressed (and so puts the ball behind or wide instead of dribbling or clearing across
our goal): a defender closed down near its goal line plays safe, as real ones do."""


def able_players(view: TeamView, eligible: np.ndarray | None) -> np.ndarray | None:
    """(n,) bool: our players who may play the ball (None: all): those of ``eligible`` (None:
    all; e.g. not those offside when our pass in flight was played) that are not frozen after
    a tackle or a foul (the simulator ignores a frozen player's commands)."""
    frozen = view.frozen
    if not np.count_nonzero(frozen):  # (cheaper than .any() on a few players)
        return eligible
    free = frozen == 0
    return free if eligible is None else eligible & free


def make_tackling(model: skills.MotionModel, config: MatchConfig, side_info: SideInfo,
                  params: TackleParams) -> Tackling:
    """The team's tackle decisions for a match (:mod:`agents.skills.tackling`), with each
    player's own type."""
    inertia = player_inertia(model, side_info.player_types, side_info.own_types)
    return Tackling(model, config.tackles, inertia, side_info.goalie_index, params)


def tackle_if_worth(tackling: Tackling, view: TeamView, command: TeamCommand, race: skills.BallRace,
                    ours_last: bool) -> None:
    """None of ours can kick the ball: put our tackle, if the moment calls for one and one is
    worth it (:mod:`agents.skills.tackling`), into ``command``. ``ours_last``: we played the
    ball last (our pass is in flight)."""
    occasion = tackling.occasion(view, race.theirs.first_cycle, race.ours.first_cycle, ours_last)
    if not occasion:
        return
    goalie = tackling.goalie
    tackle = tackling.choose(view, occasion, goalie >= 0 and race.ours.cycles[goalie] >= skills.UNREACHABLE)
    if tackle is None:
        return
    n = view.own_pos.shape[0]
    command.tackle = np.full(n, np.nan)
    command.tackle[tackle.player] = tackle.direction
    if tackle.foul:
        command.foul = np.zeros(n, dtype=bool)
        command.foul[tackle.player] = True


def choose_kicker(view: TeamView, race: skills.BallRace, ball_player: int, kickable: float,
                  eligible: np.ndarray | None) -> int:
    """The one player of ours who kicks this cycle (-1: none can). Only players the race says
    control the ball now are candidates (it already leaves out those offside when we played
    the ball); ``eligible`` (None: everybody), while our pass is in flight, leaves out the
    team-mates who were offside when it was played. The ball player kicks if it can, else the
    nearest player within ``kickable`` (m)."""
    if race.ours.first_cycle != 0:
        return -1
    gaps = np.hypot(*(view.own_pos - view.ball).T)
    if eligible is not None:
        gaps[~eligible] = np.inf  # offside when the ball was played: hands off
    nearest = int(np.argmin(gaps))
    if gaps[nearest] > kickable:
        return -1
    if ball_player >= 0 and gaps[ball_player] <= kickable:
        return ball_player
    return nearest


def on_ball_kick(ctx: skills.SkillContext, view: TeamView, kicker: int, goalie: int,
                 decision_params: skills.DecisionParams, race: skills.BallRace,
                 contested: bool, shot_at_us: bool = False) -> tuple[np.ndarray, np.ndarray | None, bool]:
    """``kicker``'s kick: (kick, the dribbler's dash or None, whether it is a shot).

    The goalkeeper, which may kick but not catch here, parries when pressed and otherwise
    distributes. An outfield player decides with :func:`agents.skills.decide_on_ball`; against
    an opponent who kicks the ball too, a dribble or a clearance up the field would meet its
    mirror image and the two kicks cancel, so it kicks towards the nearer touchline instead
    (both teams doing so add up); pressed in our box, it kicks wide of the goal and behind
    (a corner rather than a chance); pressed near their goal, it shoots
    (:mod:`agents.teams.finishing`), and there it carries the ball on rather than passing back
    or clearing (:mod:`agents.teams.carrying`). ``shot_at_us``: the ball is the opponents' shot heading into our
    goal; an outfield player blocks it wide (:data:`_BLOCK`)."""
    model = ctx.model
    if kicker == goalie:
        return skills.goalkeeper_kick(ctx, view, kicker, race.theirs.first_cycle), None, False
    if shot_at_us:
        return skills.parry_kick(ctx, view, kicker, _BLOCK), None, False
    decision = skills.decide_on_ball(ctx, view, kicker, decision_params, pressure=race.theirs.first_cycle)
    finish = finishing_shot(ctx, view, kicker, decision, contested, decision_params.shot)
    if finish is not None:  # pressed near their goal: shoot (agents.teams.finishing)
        return finish, None, True
    carry = None if contested else carry_kick(ctx, view, kicker, decision, decision_params)
    if carry is not None:  # near their goal: dribble on rather than pass back or clear
        return carry[0], carry[1], False
    # Within the block's depth of our goal line (any width), a pressed player puts the ball
    # behind or wide rather than across our goal.
    deep = float(view.ball[0]) < _BLOCK.behind_depth - model.half_length
    pressed = race.theirs.first_cycle <= _DEEP_PRESSURE and deep
    if (contested or pressed) and decision.action in (skills.OnBallAction.DRIBBLE, skills.OnBallAction.CLEAR):
        kick = skills.parry_kick(ctx, view, kicker, _BLOCK) if deep else wing_kick(model, view, kicker)
        return kick, None, False
    return decision.kick, decision.dash, decision.action == skills.OnBallAction.SHOOT


def wing_kick(model: skills.MotionModel, view: TeamView, kicker: int) -> np.ndarray:
    """The kick sending the ball hard towards the nearer touchline, a little forwards."""
    side = 1.0 if view.ball[1] >= 0.0 else -1.0
    direction = np.array([0.3, side]) / np.hypot(0.3, 1.0)
    kick, _ = skills.kick_for_velocity(model, view.own_pos[kicker], view.ball, view.ball_vel,
                                       direction * model.kick_speed_max, player_vel=view.own_vel[kicker])
    return kick


def ball_reach(our_cycles: np.ndarray, outfield: np.ndarray, model: skills.MotionModel) -> np.ndarray:
    """How far (m) each outfield player effectively is from controlling the ball: the cycles
    its interception takes (``our_cycles``, a ball race's per player) times the top speed, inf
    for a player who cannot intercept (:attr:`agents.roles.RoleContext.ball_reach`, what
    bidding's ball role bids with instead of the straight distance to the formation's query
    point)."""
    cycles = our_cycles[outfield].astype(np.float64)
    cycles[our_cycles[outfield] >= skills.UNREACHABLE] = np.inf
    return cycles * model.top_speed


def ball_player(named: int | None, race: skills.BallRace, goalie: int, outfield: np.ndarray,
                model: skills.MotionModel, stationary: bool) -> int:
    """Our player who goes for the ball (-1: none can reach it in time): the assigner's
    ``named`` outfield player (index among ``outfield``) if it names one, unless our goalkeeper
    wins the ball in its area; else the first of ours to reach it, the goalkeeper only for a
    ball it wins in its area (an outfield player goes instead); statues (``stationary``) only
    for a ball that comes to them."""
    first = race.ours.first
    keeper = first == goalie >= 0 and skills.comes_out(model, race, goalie)
    if named is not None and not stationary and not keeper:  # (a ball our keeper wins is its own)
        return int(outfield[named])
    if first < 0:
        return -1
    if stationary:
        return first if race.ours.cycles[first] <= 2 else -1
    if first == goalie and not skills.comes_out(model, race, goalie):
        cycles = race.ours.cycles[outfield]
        if not cycles.size:  # a lone goalkeeper stays in its area
            return -1
        best = int(np.argmin(cycles))
        return int(outfield[best]) if cycles[best] < skills.UNREACHABLE else -1
    return int(first)
