"""The built-in team's player on the ball in play on: who of ours may play the ball, who
kicks this cycle and what the kick is, and our tackle when an opponent has the ball (team
frame: we attack +x)."""

from __future__ import annotations

import numpy as np

from agents import skills
from agents.skills.tackling import TackleParams, Tackling, player_inertia
from soccer_sim.config import MatchConfig
from soccer_sim.team import SideInfo, TeamCommand, TeamView

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
    """``kicker``'s kick in play on: (kick, the dribbler's dash or None, whether it is a shot).

    The goalkeeper, which may kick but not catch here, parries when pressed and otherwise
    distributes (:func:`agents.skills.goalkeeper_kick`); an outfield player blocks the
    opponents' shot heading into our goal (``shot_at_us``) wide of the post
    (``decision_params.safety.block``), and otherwise decides with
    :func:`agents.skills.decide_on_ball` in play on (``contested``: an opponent can kick the
    ball too), the one place where the team shoots, crosses, passes, dribbles, clears or puts
    the ball out of danger."""
    if kicker == goalie:
        return skills.goalkeeper_kick(ctx, view, kicker, race.theirs.first_cycle), None, False
    if shot_at_us:
        return skills.parry_kick(ctx, view, kicker, decision_params.safety.block), None, False
    decision = skills.decide_on_ball(ctx, view, kicker, decision_params, pressure=race.theirs.first_cycle,
                                     in_play=True, contested=contested)
    return decision.kick, decision.dash, decision.action == skills.OnBallAction.SHOOT


def ball_reach(our_cycles: np.ndarray, outfield: np.ndarray, model: skills.MotionModel) -> np.ndarray:
    """How far (m) each outfield player effectively is from controlling the ball: the cycles
    its interception takes (``our_cycles``, a ball race's per player) times the top speed, inf
    for a player who cannot intercept (:attr:`agents.roles.RoleContext.ball_reach`, what
    bidding's ball role bids with instead of the straight distance to the formation's query
    point)."""
    cycles = our_cycles[outfield].astype(np.float64)
    cycles[our_cycles[outfield] >= skills.UNREACHABLE] = np.inf
    return cycles * model.top_speed
