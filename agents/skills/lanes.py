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

import math

import numpy as np
from numba import njit

from agents.skills.interception import UNREACHABLE, intercept_many, opponent_radii, team_radii
from agents.skills.model import MotionModel, check_player, view_effort


def opponent_cycles(model: MotionModel, view: object, ball: np.ndarray, velocities: np.ndarray,
                    limit: np.ndarray | None = None, extra_radius: float = 0.0,
                    reaction: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Earliest cycle any opponent controls the ball on each lane, and who.

    ``velocities`` (P, 2): the ball's velocity right after the kick, one row per lane;
    ``limit`` (P,) int: last cycle searched per lane (None: the horizon); ``extra_radius``
    (m) widens every opponent's control distance (a safety margin for noise); ``reaction``
    (cycles) is how late the opponents start to chase: they see our kick only in the next
    cycle's view, so 1. Opponents are taken at full effort; their goalkeeper
    (``model.opponent_goalie_index``) catches in its penalty area.
    Returns (cycles (P,) int, :data:`UNREACHABLE` when nobody gets there; opponent (P,) int,
    -1 when nobody).
    """
    velocities = np.ascontiguousarray(velocities, dtype=np.float64).reshape(-1, 2)
    radius, catch = opponent_radii(model, extra_radius)
    cycles, _ = intercept_many(model, np.asarray(ball, np.float64), velocities, view.opp_pos, view.opp_vel, None,
                               radius, catch, 1.0, limit, reaction, first_only=True)
    if cycles.shape[1] == 0:
        return np.full(len(velocities), UNREACHABLE, dtype=np.int64), np.full(len(velocities), -1, dtype=np.int64)
    who = np.argmin(cycles, axis=1)
    first = cycles[np.arange(len(velocities)), who]
    who = np.where(first >= UNREACHABLE, -1, who)
    return first, who


def teammate_cycles(model: MotionModel, view: object, ball: np.ndarray, velocities: np.ndarray,
                    limit: np.ndarray | None = None,
                    receivers: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Each of our players' interception cycle and point on each lane: ((P, n) int, (P, n, 2)).

    ``receivers`` (P,) int: search only that team-mate on each lane (the others get
    UNREACHABLE), which is much cheaper. The kicker's own column is meaningless (it is at the
    ball at cycle 0).
    """
    velocities = np.ascontiguousarray(velocities, dtype=np.float64).reshape(-1, 2)
    n = model.players_per_team
    radius, catch = team_radii(model, 0.0)
    return intercept_many(model, np.asarray(ball, np.float64), velocities, view.own_pos, view.own_vel,
                          view_effort(view, n), radius, catch, -1.0, limit, only=receivers)


def lane_open(model: MotionModel, view: object, ball: np.ndarray, velocity: np.ndarray, receiver: int,
              min_lead: int = 1, extra_radius: float = 0.0) -> bool:
    """True when our ``receiver`` controls the ball kicked to ``velocity`` (2,) at least
    ``min_lead`` cycles before any opponent can (and can control it at all)."""
    receiver = check_player(receiver, model.players_per_team, "receiver")
    velocity = np.asarray(velocity, np.float64).reshape(1, 2)
    ours, _ = teammate_cycles(model, view, ball, velocity, None, np.array([receiver]))
    theirs, _ = opponent_cycles(model, view, ball, velocity, None, extra_radius)
    mine = int(ours[0, receiver])
    return mine < UNREACHABLE and int(theirs[0]) - mine >= min_lead


@njit(cache=True, nogil=True)
def lane_arrivals(targets: np.ndarray, wanted: np.ndarray, velocities: np.ndarray, ball: np.ndarray, decay: float,
                  horizon: int, extra: int, arrival: np.ndarray, limit: np.ndarray) -> np.ndarray:  # pragma: no cover
    """Which lanes work, and when the ball gets to the end of each (compiled).

    Row i: a ball at ``ball`` meant to reach ``targets[i]`` with the velocity ``wanted[i]``
    gets ``velocities[i]`` from the kick. Returns the rows whose kick keeps the intended line
    (within 1 %) and brings the ball to the target within ``horizon`` cycles, and writes their
    ``arrival`` cycle (rounded up) and search ``limit`` (arrival + ``extra``, at most the
    horizon)."""
    keep = np.empty(targets.shape[0], dtype=np.int64)
    count = 0
    for i in range(targets.shape[0]):
        wx, wy = wanted[i, 0], wanted[i, 1]
        norm = math.sqrt(wx * wx + wy * wy)
        vx, vy = velocities[i, 0], velocities[i, 1]
        speed = (vx * wx + vy * wy) / norm  # along the intended line
        if speed <= 0.99 * math.sqrt(vx * vx + vy * vy):
            continue
        dist = math.sqrt((targets[i, 0] - ball[0]) ** 2 + (targets[i, 1] - ball[1]) ** 2)
        left = 1.0 - dist * (1.0 - decay) / speed
        if left <= 0.0:
            continue
        cycles = math.ceil(math.log(left) / math.log(decay) - 1e-9)
        if cycles > horizon:
            continue
        arrival[i] = cycles
        limit[i] = min(cycles + extra, horizon)
        keep[count] = i
        count += 1
    return keep[:count]
