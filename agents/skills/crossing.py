"""Crossing: from wide in the final third, the ball into the opponents' box.

A player on the ball wide in the final third (ball x beyond ``final_third`` of the half
length from the centre, |y| at least ``min_width``) tries a few targets in the box: each
team-mate who stands in the penalty area (a little ahead of it, ``lead`` metres towards the
goal) and fixed points of space in front of goal (``space_points``: near post, far post,
penalty spot, taken on the ball's side first). Each is kicked to arrive at
``arrival_speed`` (capped at what one kick gives). A cross **works** when one of our players
(not the crosser, not offside, not the goalkeeper) takes the ball inside the penalty area at
least ``min_lead`` cycles before any opponent can (the lanes of :mod:`agents.skills.lanes`;
opponents react one cycle late). Among crosses that work, the one received nearest the
middle of the goal wins (ties: the bigger lead).

The on-ball decision (:mod:`agents.skills.decision`) prefers a working cross to a pass; a
cross into a crowded box that does not work is not made.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from agents.skills.ball_kernels import lane_arrivals
from agents.skills.context import SkillContext
from agents.skills.interception import UNREACHABLE
from agents.skills.kicking import kick_for_velocity
from agents.skills.lanes import opponent_cycles, teammate_cycles
from agents.skills.model import MotionModel, SkillInputError, check_params, check_player
from agents.skills.passing import offside_positions
from soccer_sim.team import TeamView


@dataclass(frozen=True)
class CrossParams:
    """Where a cross is tried and what it needs to work (metres, cycles, m/cycle)."""

    final_third: float = 1.0 / 3.0
    """Crosses only with the ball's x beyond this share of the half length (the final third)."""
    min_width: float = 14.0
    """... and its |y| at least this (outside the goal area's width plus a few metres: wide)."""
    space_points: tuple[tuple[float, float], ...] = ((6.0, 3.0), (6.0, -3.0), (11.0, 0.0))
    """Points of space tried as targets, as (metres in front of the goal line, y on the ball's
    side): near post, far post, penalty spot."""
    lead: float = 1.5
    """A team-mate in the box is crossed to this far in front of it, towards the goal."""
    arrival_speed: float = 1.2
    """Ball speed wanted at the target (m/cycle): driven, so the lane is short-lived for
    defenders, slow enough to be controlled."""
    min_lead: int = 1
    """Cycles by which our receiver must beat every opponent to the ball."""
    opponent_margin: float = 0.2
    """Extra control distance given to opponents (m), for noise."""
    extra_cycles: int = 8
    """Cycles searched beyond the ball's arrival at the target."""

    def __post_init__(self) -> None:
        check_params(self, positive=("arrival_speed",), non_negative=("min_width", "lead", "opponent_margin"),
                     finite=("final_third",), whole=("min_lead", "extra_cycles"))
        points = np.asarray(self.space_points, dtype=float)
        if points.ndim != 2 or points.shape[1] != 2 or not np.isfinite(points).all():
            raise SkillInputError(f"CrossParams.space_points must be a sequence of (x, y) points, "
                                  f"got {self.space_points!r}")


@dataclass(frozen=True)
class CrossPlan:
    """A chosen cross: ``kick`` is the crosser's kick request."""

    receiver: int
    """Our player predicted to take the ball."""
    target: np.ndarray
    """(2,) point the ball is sent to (m)."""
    receive_point: np.ndarray
    """(2,) where the receiver takes it (m, inside the penalty area)."""
    kick: np.ndarray
    ball_vel: np.ndarray
    receive_cycle: int
    opponent_cycle: int
    """Earliest cycle an opponent controls the ball (UNREACHABLE: none in the searched cycles)."""


def in_crossing_zone(model: MotionModel, ball: np.ndarray, params: CrossParams = CrossParams()) -> bool:
    """Whether the ball is wide in the final third (where :func:`best_cross` tries crosses)."""
    return float(ball[0]) > params.final_third * model.half_length and abs(float(ball[1])) >= params.min_width


def cross_targets(model: MotionModel, view: TeamView, crosser: int, params: CrossParams = CrossParams()) -> np.ndarray:
    """(k, 2) points a cross from the ball aims at: team-mates in the penalty area (led towards
    the goal) and the space points (mirrored to the ball's side)."""
    side = 1.0 if float(view.ball[1]) >= 0.0 else -1.0
    goal_x = model.half_length
    space = np.asarray(params.space_points, dtype=np.float64).reshape(-1, 2)
    points = np.column_stack([goal_x - space[:, 0], side * space[:, 1]])
    own = view.own_pos
    in_box = (own[:, 0] > goal_x - model.penalty_area_length) & (np.abs(own[:, 1]) < model.penalty_area_half_width)
    in_box[crosser] = False
    if model.goalie_index >= 0:
        in_box[model.goalie_index] = False
    mates = own[in_box]
    if len(mates):
        to_goal = np.array([goal_x, 0.0]) - mates
        norm = np.maximum(np.hypot(*to_goal.T), 1e-9)[:, None]
        mates = mates + to_goal / norm * np.minimum(params.lead, norm)
        points = np.vstack([mates, points])
    return points


def best_cross(ctx: SkillContext, view: TeamView, crosser: int, params: CrossParams = CrossParams(),
               holder: bool = False) -> CrossPlan | None:
    """The best working cross for ``crosser`` (who can kick the ball) when the ball is in the
    crossing zone; None otherwise or when no cross works."""
    model = ctx.model
    crosser = check_player(crosser, model.players_per_team, "crosser")
    ball = np.asarray(view.ball, np.float64)
    if not in_crossing_zone(model, ball, params):
        return None
    targets = cross_targets(model, view, crosser, params)
    offsets = targets - ball
    dist = np.maximum(np.hypot(*offsets.T), 1e-9)
    speeds = dist * (1.0 - model.ball_decay) + params.arrival_speed
    wanted = offsets / dist[:, None] * speeds[:, None]
    kicks, velocities = kick_for_velocity(model, view.own_pos[crosser], ball, view.ball_vel, wanted, holder,
                                          view.own_vel[crosser])
    arrival = np.empty(len(targets), dtype=np.int64)
    limit = np.empty(len(targets), dtype=np.int64)
    usable = lane_arrivals(targets, wanted, velocities, ball, model.ball_decay, model.horizon, params.extra_cycles,
                           arrival, limit)
    if usable.size == 0:
        return None
    vel_u = np.ascontiguousarray(velocities[usable])
    ours, points = teammate_cycles(ctx, view, ball, vel_u, limit[usable])
    ours = ours.astype(np.int64, copy=True)
    barred = offside_positions(model, view.own_pos, view.opp_pos, ball)
    barred[crosser] = True
    if model.goalie_index >= 0:
        barred[model.goalie_index] = True
    ours[:, barred] = UNREACHABLE
    rows = np.arange(usable.size)
    receiver = np.argmin(ours, axis=1)
    receive = ours[rows, receiver]
    received_at = points[rows, receiver]
    theirs, _ = opponent_cycles(ctx, view, ball, vel_u, limit[usable], params.opponent_margin)
    in_box = ((received_at[:, 0] > model.half_length - model.penalty_area_length)
              & (np.abs(received_at[:, 1]) < model.penalty_area_half_width))
    works = (receive < UNREACHABLE) & (theirs - receive >= params.min_lead) & in_box
    if not works.any():
        return None
    # Nearest the middle of the goal first, then the larger lead.
    to_goal = np.hypot(received_at[:, 0] - model.half_length, received_at[:, 1])
    score = np.where(works, -to_goal + 0.01 * np.minimum(theirs - receive, 50), -np.inf)
    best = int(np.argmax(score))
    j = int(usable[best])
    return CrossPlan(receiver=int(receiver[best]), target=targets[j].copy(), receive_point=received_at[best].copy(),
                     kick=kicks[j].copy(), ball_vel=velocities[j].copy(), receive_cycle=int(receive[best]),
                     opponent_cycle=int(theirs[best]))
