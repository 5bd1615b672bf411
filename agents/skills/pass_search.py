"""The compiled search of :func:`agents.skills.passing.best_pass`, in one call.

The passing skill's steps (receivers, targets, kicks, lanes, the receiver's and the
opponents' interceptions, scores; see :mod:`agents.skills.passing`) run here back to back,
through the same kernels in the same order on the same arrays, so the chosen pass is the same
bit for bit as the step-by-step NumPy version's; a pass decision then costs one dispatch
instead of a dozen and no intermediate arrays reach Python. Team frame, metres, m/cycle.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from agents.skills.ball_kernels import beyond_line, deciding_cycles, kick_kernel, lane_arrivals, pass_scores, \
    pass_targets
from agents.skills.interception_kernels import EVERYONE, UNREACHABLE, intercept_kernel

PLAN_FLOATS = 9
"""The floats of a found pass in :func:`best_pass_search`'s ``plan_f``: target (2), receive
point (2), kick (2), ball velocity (2), score."""
PLAN_INTS = 4
"""The integers of a found pass in ``plan_i``: receiver, arrival cycle, receive cycle,
opponent cycle."""


@njit(cache=True, nogil=True)
def pass_receivers(own_pos: np.ndarray, opp_pos: np.ndarray, ball_x: float, offside: bool, passer: int,
                   goalie: int) -> np.ndarray:  # pragma: no cover - compiled
    """:func:`~agents.skills.passing.pass_candidates`: the team-mates not in an offside
    position (``offside``: the rule is on and there are two opponents or more), not the
    ``passer``, not ``goalie`` (-1: the goalkeeper may receive)."""
    n = own_pos.shape[0]
    ok = beyond_line(own_pos, opp_pos, ball_x) if offside else np.zeros(n, dtype=np.bool_)
    count = 0
    out = np.empty(n, dtype=np.int64)
    for i in range(n):
        if not ok[i] and i != passer and i != goalie:
            out[count] = i
            count += 1
    return out[:count]


@njit(cache=True, nogil=True)
def best_pass_search(ball: np.ndarray, ball_vel: np.ndarray, receivers: np.ndarray, passer: int, holder: bool,
                     leads: np.ndarray, speeds: np.ndarray, lanes: tuple, kicking: tuple, ours: tuple, theirs: tuple,
                     search: tuple, scoring: tuple, plan_f: np.ndarray, plan_i: np.ndarray) -> bool:  # pragma: no cover
    """The best safe pass of ``passer`` to one of ``receivers`` into ``plan_f`` (:data:`PLAN_FLOATS`)
    and ``plan_i`` (:data:`PLAN_INTS`); False when there is none.

    ``ball`` and ``ball_vel`` are (1, 2) rows; the tuples hold the kernels' other arguments:
    ``lanes`` (x_max, y_max, min_distance, max_distance, decay, horizon, extra_cycles, min_lead),
    ``kicking`` (:func:`~agents.skills.ball_kernels.kick_kernel`'s model constants),
    ``ours`` and ``theirs`` (the view's checked positions, velocities and efforts, and the
    searches' radii and catch radii: theirs with the opponent margin), ``search``
    (reach, ball travel, player coast, the nine interception constants) and ``scoring``
    (reach, coast, kickable, half length, the four weights)."""
    x_max, y_max, min_distance, max_distance, decay, horizon, extra, min_lead = lanes
    own_pos, own_vel, opp_pos = ours[0], ours[1], theirs[0]
    size = receivers.shape[0] * leads.shape[0] * speeds.shape[0]
    targets, wanted = np.empty((size, 2)), np.empty((size, 2))
    owners = np.empty(size, dtype=np.int64)
    count = pass_targets(own_pos, receivers, leads, speeds, ball[0], x_max, y_max, min_distance, max_distance,
                         decay, targets, owners, wanted)
    if count == 0:
        return False
    targets, owners, wanted = targets[:count], owners[:count], wanted[:count]
    kicks, velocities = np.empty((count, 2)), np.empty((count, 2))
    kick_kernel(own_pos[passer], own_vel[passer], ball[0], ball_vel[0], wanted, kicks, velocities, kicking[0],
                kicking[1], kicking[2], kicking[3], kicking[4], kicking[5], kicking[6], holder)
    arrival = np.empty(count, dtype=np.int64)
    limit = np.empty(count, dtype=np.int64)
    usable = lane_arrivals(targets, wanted, velocities, ball[0], decay, horizon, extra, arrival, limit)
    lanes_n = usable.shape[0]
    if lanes_n == 0:
        return False
    vel_u = np.empty((lanes_n, 2))
    own_u, lim_u, arrival_u = np.empty(lanes_n, dtype=np.int64), np.empty(lanes_n, dtype=np.int64), \
        np.empty(lanes_n, dtype=np.int64)
    targets_u = np.empty((lanes_n, 2))
    for u in range(lanes_n):
        j = usable[u]
        vel_u[u, 0], vel_u[u, 1] = velocities[j, 0], velocities[j, 1]
        targets_u[u, 0], targets_u[u, 1] = targets[j, 0], targets[j, 1]
        own_u[u], lim_u[u], arrival_u[u] = owners[j], limit[j], arrival[j]
    reach, travel, coast, c = search
    # The receiver alone on each lane, then every opponent up to the cycle that can still decide.
    n, m = ours[0].shape[0], theirs[0].shape[0]
    cycles, points = np.empty((lanes_n, n), dtype=np.int64), np.empty((lanes_n, n, 2))
    intercept_kernel(ball, vel_u, ours[0], ours[1], ours[2], ours[3], ours[4], reach, travel, coast, lim_u, own_u,
                     cycles, points, c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], -1.0, 0, False)
    receive = np.empty(lanes_n, dtype=np.int64)
    received_at = np.empty((lanes_n, 2))
    for u in range(lanes_n):
        receive[u] = cycles[u, own_u[u]]
        received_at[u, 0], received_at[u, 1] = points[u, own_u[u], 0], points[u, own_u[u], 1]
    their_cycles, their_points = np.empty((lanes_n, m), dtype=np.int64), np.empty((lanes_n, m, 2))
    intercept_kernel(ball, vel_u, theirs[0], theirs[1], theirs[2], theirs[3], theirs[4], reach, travel, coast,
                     deciding_cycles(receive, arrival_u, lim_u, min_lead), EVERYONE, their_cycles, their_points,
                     c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], 1.0, 1, True)
    first = np.empty(lanes_n, dtype=np.int64)
    for u in range(lanes_n):
        first[u] = UNREACHABLE
        for k in range(m):
            first[u] = min(first[u], their_cycles[u, k])
    score, plan_points = np.empty(lanes_n), np.empty((lanes_n, 2))
    best = pass_scores(targets_u, received_at, receive, first, arrival_u, own_u, own_pos, own_vel, ours[2], opp_pos,
                       ball[0], scoring[0], scoring[1], scoring[2], scoring[3], min_lead, score, plan_points,
                       scoring[4], scoring[5], scoring[6], scoring[7])
    if best < 0:
        return False
    j = usable[best]
    plan_f[0], plan_f[1] = targets[j, 0], targets[j, 1]
    plan_f[2], plan_f[3] = plan_points[best, 0], plan_points[best, 1]
    plan_f[4], plan_f[5] = kicks[j, 0], kicks[j, 1]
    plan_f[6], plan_f[7] = velocities[j, 0], velocities[j, 1]
    plan_f[8] = score[best]
    plan_i[0], plan_i[1], plan_i[2], plan_i[3] = owners[j], arrival[j], receive[best], first[best]
    return True
