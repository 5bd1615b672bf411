"""Clearing: kick the ball hard, away from danger, where the opponents get to it last.

Directions are tried in a fan around +x (``± spread_deg``), each with the fastest ball one
kick gives. For each the opponents' and our earliest interceptions on the ball's path are
found (:mod:`agents.skills.lanes`); the score of a direction is

    ``w_ours * [a team-mate gets there first] + w_time * min(their cycle, time_cap) / time_cap
      + w_forward * cos(angle) + w_wing * |sin(angle)| - w_out * [the ball leaves the field]``

so a clearance prefers a team-mate, then a long run before any opponent, upfield and (for
the goalkeeper) towards the wings, and not out of play. A ball the opponents' goalkeeper
controls first is a ball given away: its time term is 0 (``ClearParams.keeper_gets_it``);
one that leaves the field is given away where it crosses the line
(``ClearParams.out_gives_it_away``).
The weights are :class:`ClearParams`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from agents.skills.context import SkillContext
from agents.skills.interception import UNREACHABLE
from agents.skills.kicking import kick_for_velocity
from agents.skills.lanes import opponent_cycles, teammate_cycles
from agents.skills.model import check_params, check_player
from soccer_sim.team import TeamView


@dataclass(frozen=True)
class ClearParams:
    """Tunable choices of the clearance (degrees, cycles, weights)."""

    fan: int = 15
    spread_deg: float = 75.0
    """Directions span ± this angle around +x."""
    time_cap: int = 30
    """Opponent cycles beyond this count no more."""
    weight_ours: float = 1.0
    weight_time: float = 1.0
    weight_forward: float = 0.5
    weight_wing: float = 0.0
    """Preference for the wings (the goalkeeper's clearance raises it)."""
    weight_out: float = 0.8
    keeper_gets_it: bool = True
    """A direction whose ball the opponents' goalkeeper is the first to control scores no
    time at all (however late it gets there: it holds the ball, a clearance given away) rather
    than the long run before an opponent that would otherwise make a ball rolling towards
    their goal look the safest: those balls ended most clearances in the opponents' half in
    the goalkeeper's hands (about 9 catches a match between built-in teams)."""
    out_gives_it_away: bool = True
    """The time term of a ball that leaves the field counts only the cycles until it crosses
    the line (then the opponents have it: a kick-in or a goal kick), not the unhindered roll
    beyond: otherwise a ball nobody reaches before it goes out scores the most time, and
    clearances rolled out over the opponents' goal line for goal kicks."""

    def __post_init__(self) -> None:
        check_params(self, non_negative=("spread_deg", "weight_ours", "weight_time", "weight_forward", "weight_wing",
                                         "weight_out"), counts=("fan", "time_cap"))


@dataclass(frozen=True)
class ClearPlan:
    direction: np.ndarray
    """(2,) unit vector of the clearance."""
    kick: np.ndarray
    """(2,) kick request."""
    ball_vel: np.ndarray
    """(2,) ball velocity right after the kick."""
    opponent_cycle: int
    teammate_cycle: int
    score: float


def best_clearance(ctx: SkillContext, view: TeamView, kicker: int, params: ClearParams = ClearParams(),
                   holder: bool = False) -> ClearPlan:
    """The best clearance kick for ``kicker`` (see the module docstring)."""
    lanes = _Lanes(ctx, view, kicker, params, holder)
    return lanes.plan(int(np.argmax(lanes.score)))


def goal_kick_clearance(ctx: SkillContext, view: TeamView, kicker: int, params: ClearParams = ClearParams(),
                        avoid: tuple[np.ndarray, ...] = (), avoid_deg: float = 20.0) -> ClearPlan:
    """The kick of a goal kick taken by ``kicker``: the best clearance (the module's score)
    among the directions whose ball leaves our penalty area before any other player of
    either team could reach it, so that nobody plays it early and the goal kick is never
    retaken. Directions within ``avoid_deg`` of one of ``avoid`` (unit vectors of kicks that
    were retaken) rank after every other; when every direction is blocked the best blocked
    one is taken."""
    model = ctx.model
    lanes = _Lanes(ctx, view, kicker, params, False)
    velocities = lanes.velocities
    points = lanes.ball + model.ball_travel[None, :, None] * velocities[:, None, :]  # (P, horizon + 1, 2)
    inside = model.in_penalty_area(points)
    leaves = np.where(inside.all(axis=1), UNREACHABLE, np.argmin(inside, axis=1))
    blocked = (lanes.theirs <= leaves) | (lanes.our_first <= leaves)
    avoided = np.zeros(len(velocities), dtype=bool)
    cos_limit = np.cos(np.radians(avoid_deg))
    for direction in avoid:
        avoided |= lanes.dirs @ np.asarray(direction, float) >= cos_limit
    # The score lies within a few units: these penalties order whole classes of directions.
    rank = lanes.score - 100.0 * blocked - 10.0 * avoided
    return lanes.plan(int(np.argmax(rank)))


class _Lanes:
    """The fan of clearance directions of one kick: kicks, ball velocities, both teams'
    first interception cycles and the module's score per direction."""

    def __init__(self, ctx: SkillContext, view: TeamView, kicker: int, params: ClearParams, holder: bool) -> None:
        model = ctx.model
        kicker = check_player(kicker, model.players_per_team, "kicker")
        angles = np.radians(np.linspace(-params.spread_deg, params.spread_deg, params.fan)) if params.fan > 1 \
            else np.zeros(1)
        self.dirs = np.column_stack([np.cos(angles), np.sin(angles)])
        self.ball = ball = np.asarray(view.ball, float)
        self.kicks, self.velocities = kick_for_velocity(model, view.own_pos[kicker], ball, view.ball_vel,
                                                        self.dirs * model.ball_speed_max, holder,
                                                        view.own_vel[kicker])
        self.theirs, who = opponent_cycles(ctx, view, ball, self.velocities)
        ours, _ = teammate_cycles(ctx, view, ball, self.velocities)
        ours = ours.copy()
        ours[:, kicker] = UNREACHABLE
        self.our_first = ours.min(axis=1)
        rest = ball + self.velocities * model.ball_travel[-1]
        out = ~model.in_field(rest) & ~((rest[:, 0] > model.half_length)
                                        & (np.abs(rest[:, 1]) < model.goal_half_width))
        given = self.theirs
        if params.out_gives_it_away:
            path = ball + model.ball_travel[None, :, None] * self.velocities[:, None, :]  # (P, horizon + 1, 2)
            inside = model.in_field(path) | ((path[..., 0] > model.half_length)
                                             & (np.abs(path[..., 1]) < model.goal_half_width))
            given = np.minimum(given, np.where(inside.all(axis=1), UNREACHABLE, np.argmin(inside, axis=1)))
        self.score = (params.weight_ours * (self.our_first < self.theirs)
                      + params.weight_time * np.minimum(given, params.time_cap) / params.time_cap
                      * ~(params.keeper_gets_it & (who == model.opponent_goalie_index))
                      + params.weight_forward * np.cos(angles) + params.weight_wing * np.abs(np.sin(angles))
                      - params.weight_out * out)

    def plan(self, best: int) -> ClearPlan:
        return ClearPlan(direction=self.dirs[best].copy(), kick=self.kicks[best].copy(),
                         ball_vel=self.velocities[best].copy(), opponent_cycle=int(self.theirs[best]),
                         teammate_cycle=int(self.our_first[best]), score=float(self.score[best]))
