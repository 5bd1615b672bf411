"""Ball lanes: can a kicked ball get along its path before an opponent gets to it?

Our own players are told of the kick by the team in the cycle it is made, so they start at
once; opponents see the kicked ball only in the next cycle's view, so they start one cycle
late (``reaction``).

A lane is a ball trajectory that starts at the ball with the velocity a kick gives it. For
each lane the opponents' earliest interception cycle (:mod:`agents.skills.interception`,
the ball rolled forward with its decay) is compared with the cycle at which the ball
reaches its destination, or with the cycle at which the intended team-mate controls it.
Passing and shooting both build on these two calls.
"""

from __future__ import annotations

import numpy as np

from agents.skills.interception import UNREACHABLE, control_radii, intercept_many
from agents.skills.model import MotionModel, view_effort


def opponent_cycles(model: MotionModel, view: object, ball: np.ndarray, velocities: np.ndarray,
                    limit: np.ndarray | None = None, extra_radius: float = 0.0,
                    reaction: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Earliest cycle any opponent controls the ball on each lane, and who.

    ``velocities`` (P, 2): the ball's velocity right after the kick, one row per lane;
    ``limit`` (P,) int: last cycle searched per lane (None: the horizon); ``extra_radius``
    (m) widens every opponent's control distance (a safety margin for noise); ``reaction``
    (cycles) is how late the opponents start to chase: they see our kick only in the next
    cycle's view, so 1. Opponents are taken at full effort; their goalkeeper (same index as
    ours) catches in its penalty area.
    Returns (cycles (P,) int, :data:`UNREACHABLE` when nobody gets there; opponent (P,) int,
    -1 when nobody).
    """
    velocities = np.ascontiguousarray(velocities, dtype=np.float64).reshape(-1, 2)
    starts = np.broadcast_to(np.asarray(ball, np.float64), velocities.shape)
    radius, catch = control_radii(model, model.goalie_index)
    if extra_radius:
        radius = radius + extra_radius
        catch = catch + extra_radius
    cycles, _ = intercept_many(model, starts, velocities, view.opp_pos, view.opp_vel, None, radius, catch, 1.0, limit,
                               reaction, first_only=True)
    if cycles.shape[1] == 0:
        return np.full(len(velocities), UNREACHABLE, dtype=np.int64), np.full(len(velocities), -1, dtype=np.int64)
    who = np.argmin(cycles, axis=1)
    first = cycles[np.arange(len(velocities)), who]
    who = np.where(first >= UNREACHABLE, -1, who)
    return first, who


def teammate_cycles(model: MotionModel, view: object, ball: np.ndarray, velocities: np.ndarray,
                    limit: np.ndarray | None = None, receivers: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Each of our players' interception cycle and point on each lane: ((P, n) int, (P, n, 2)).

    ``receivers`` (P,) int: search only that team-mate on each lane (the others get
    UNREACHABLE), which is much cheaper. The kicker's own column is meaningless (it is at the
    ball at cycle 0).
    """
    velocities = np.ascontiguousarray(velocities, dtype=np.float64).reshape(-1, 2)
    starts = np.broadcast_to(np.asarray(ball, np.float64), velocities.shape)
    n = model.players_per_team
    radius, catch = control_radii(model, model.goalie_index)
    return intercept_many(model, starts, velocities, view.own_pos, view.own_vel, view_effort(view, n), radius,
                          catch, -1.0, limit, only=receivers)


def lane_open(model: MotionModel, view: object, ball: np.ndarray, velocity: np.ndarray, receiver: int,
              min_lead: int = 1, extra_radius: float = 0.0) -> bool:
    """True when our ``receiver`` controls the ball kicked to ``velocity`` (2,) at least
    ``min_lead`` cycles before any opponent can (and can control it at all)."""
    velocity = np.asarray(velocity, np.float64).reshape(1, 2)
    ours, _ = teammate_cycles(model, view, ball, velocity, None, np.array([receiver]))
    theirs, _ = opponent_cycles(model, view, ball, velocity, None, extra_radius)
    mine = int(ours[0, receiver])
    return mine < UNREACHABLE and int(theirs[0]) - mine >= min_lead
