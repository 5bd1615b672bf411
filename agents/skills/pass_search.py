"""The compiled search of :func:`agents.skills.passing.best_pass`, in one call.

The passing skill's steps (receivers, targets, kicks, lanes, the receiver's and the
opponents' interceptions, scores; see :mod:`agents.skills.passing`) run here back to back,
through the same kernels in the same order on the same arrays, so the chosen pass is the same
bit for bit as the step-by-step NumPy version's; a pass decision then costs one dispatch
instead of a dozen and no intermediate arrays reach Python. Team frame, metres, m/cycle.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from agents.skills.ball_kernels import PassLanes, beyond_line, deciding_cycles, kick_kernel, lane_arrivals, \
    pass_scores, pass_targets
from agents.skills.interception_kernels import EVERYONE, UNREACHABLE, MotionTables, Runners, intercept_kernel

PASS_PLAN = np.dtype([(name, np.int64) for name in ("receiver", "arrival_cycle", "receive_cycle", "opponent_cycle")]
                     + [(name, np.float64) for name in ("target_x", "target_y", "receive_x", "receive_y", "kick_x",
                                                        "kick_y", "ball_vx", "ball_vy", "score")])
"""A found pass as :func:`best_pass_search` writes it (the fields of
:class:`~agents.skills.passing.PassPlan`, which documents them)."""


class PassSearch(NamedTuple):
    """What :func:`best_pass_search` needs besides the view, fixed for a match and one
    :class:`~agents.skills.passing.PassParams` (made once, :func:`agents.skills.passing.best_pass`)."""

    leads: np.ndarray
    """(L, 2) offsets of the targets from the receivers (m)."""
    speeds: np.ndarray
    """(S,) the ball's speeds on arrival (m/cycle)."""
    params: np.ndarray
    """A :data:`~agents.skills.ball_kernels.PASS_PARAMS` record."""
    kick: np.ndarray
    """A :data:`~agents.skills.ball_kernels.KICK_MODEL` record."""
    intercept: np.ndarray
    """An :data:`~agents.skills.interception_kernels.INTERCEPT_PARAMS` record."""
    tables: MotionTables
    """The motion model's tables."""


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
                     ours: Runners, theirs: Runners, search: PassSearch,
                     plan: np.ndarray) -> bool:  # pragma: no cover - compiled
    """The best safe pass of ``passer`` to one of ``receivers`` into ``plan`` (a :data:`PASS_PLAN`
    record); False when there is none.

    ``ball`` and ``ball_vel`` are (1, 2) rows; ``ours`` and ``theirs`` the view's checked players
    with the searches' radii and catch radii (theirs with the opponent margin); ``holder``: the
    passer is our goalkeeper holding the ball."""
    p = search.params[0]
    decay, horizon, extra, min_lead = p.decay, p.horizon, p.extra_cycles, p.min_lead
    leads, speeds, tables = search.leads, search.speeds, search.tables
    own_pos, own_vel, opp_pos = ours.pos, ours.vel, theirs.pos
    size = receivers.shape[0] * leads.shape[0] * speeds.shape[0]
    targets, wanted = np.empty((size, 2)), np.empty((size, 2))
    owners = np.empty(size, dtype=np.int64)
    count = pass_targets(own_pos, receivers, leads, speeds, ball[0], search.params, targets, owners, wanted)
    if count == 0:
        return False
    targets, owners, wanted = targets[:count], owners[:count], wanted[:count]
    kicks, velocities = np.empty((count, 2)), np.empty((count, 2))
    kick_kernel(own_pos[passer], own_vel[passer], ball[0], ball_vel[0], wanted, kicks, velocities, search.kick, holder)
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
    # The receiver alone on each lane, then every opponent up to the cycle that can still decide.
    n, m = own_pos.shape[0], opp_pos.shape[0]
    cycles, points = np.empty((lanes_n, n), dtype=np.int64), np.empty((lanes_n, n, 2))
    intercept_kernel(ball, vel_u, ours, tables, lim_u, own_u, cycles, points, search.intercept, -1.0, 0, False)
    receive = np.empty(lanes_n, dtype=np.int64)
    received_at = np.empty((lanes_n, 2))
    for u in range(lanes_n):
        receive[u] = cycles[u, own_u[u]]
        received_at[u, 0], received_at[u, 1] = points[u, own_u[u], 0], points[u, own_u[u], 1]
    their_cycles, their_points = np.empty((lanes_n, m), dtype=np.int64), np.empty((lanes_n, m, 2))
    intercept_kernel(ball, vel_u, theirs, tables, deciding_cycles(receive, arrival_u, lim_u, min_lead), EVERYONE,
                     their_cycles, their_points, search.intercept, 1.0, 1, True)
    first = np.empty(lanes_n, dtype=np.int64)
    for u in range(lanes_n):
        first[u] = UNREACHABLE
        for k in range(m):
            first[u] = min(first[u], their_cycles[u, k])
    score, plan_points = np.empty(lanes_n), np.empty((lanes_n, 2))
    best = pass_scores(PassLanes(targets_u, own_u, arrival_u, receive, received_at, first), own_pos, own_vel,
                       ours.effort, opp_pos, ball[0], tables.reach, search.params, score, plan_points)
    if best < 0:
        return False
    j = usable[best]
    out = plan[0]
    out.receiver, out.arrival_cycle, out.receive_cycle, out.opponent_cycle = owners[j], arrival[j], receive[best], \
        first[best]
    out.target_x, out.target_y = targets[j, 0], targets[j, 1]
    out.receive_x, out.receive_y = plan_points[best, 0], plan_points[best, 1]
    out.kick_x, out.kick_y = kicks[j, 0], kicks[j, 1]
    out.ball_vx, out.ball_vy = velocities[j, 0], velocities[j, 1]
    out.score = score[best]
    return True
