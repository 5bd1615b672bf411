"""The compiled loops of the role assigners (numba), in one place; the assigner modules hold
the Python logic around them, :mod:`agents.roles.field_terms` the supporters' potential field.

Each kernel runs every cycle on about ten players, where numpy's per-call overhead (or plain
Python's per-item cost) would dominate. Bidding's weights and hysteresis travel as a named
record, a one-element :data:`~agents.roles.bidding.BIDDING_DTYPE` array read by name
(``params[0].ball_cap``, :meth:`~agents.roles.bidding.BiddingParams.as_record`).

Users: :mod:`agents.roles.base` (the offensive order, the permutation check),
:mod:`agents.roles.matching` (greedy-offense, the finiteness check) and
:mod:`agents.roles.bidding` (bid costs, the auction, the covered role, one bidding round).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit


# The two small kernels below run every cycle; compiled, a call costs less than half of its numpy
# or plain-Python equivalent (0.5 against 1.2 us for the order, 0.2 against 0.6 us for the check).
@njit(cache=True, nogil=True)
def descending_x(targets: np.ndarray):  # pragma: no cover - compiled
    """Rows by x descending, ties by row (a stable insertion sort: k is about ten), or None
    when an x is not finite (numpy's argsort orders those)."""
    k = targets.shape[0]
    order = np.empty(k, dtype=np.int64)
    for i in range(k):
        x = targets[i, 0]
        if not math.isfinite(x):
            return None
        j = i
        while j > 0 and targets[order[j - 1], 0] < x:
            order[j] = order[j - 1]
            j -= 1
        order[j] = i
    return order


@njit(cache=True, nogil=True)
def is_permutation(order: np.ndarray, k: int) -> bool:  # pragma: no cover - compiled
    """Whether ``order`` (k,) holds every index of ``range(k)`` exactly once."""
    if order.shape[0] != k:
        return False
    seen = np.zeros(k, dtype=np.bool_)
    for r in order:
        if r < 0 or r >= k or seen[r]:
            return False
        seen[r] = True
    return True


@njit(cache=True, nogil=True)
def greedy_in_order(players: np.ndarray, targets: np.ndarray, order: np.ndarray,
                    scale: np.ndarray) -> np.ndarray:  # pragma: no cover - compiled
    """For each role in ``order``, the nearest player not yet taken (ties: lower row); with a
    non-empty ``scale`` (k,) the one with the least ``distance * scale[i]`` (time cost)."""
    k = players.shape[0]
    role_of_player = np.full(k, -1, dtype=np.int64)
    for r in order:
        best, best_d = -1, math.inf
        tx, ty = targets[r, 0], targets[r, 1]
        for i in range(k):
            if role_of_player[i] < 0:
                d = (players[i, 0] - tx) ** 2 + (players[i, 1] - ty) ** 2
                if scale.shape[0]:
                    d *= scale[i] * scale[i]
                if d < best_d or best < 0:  # the first free player stands in for NaN distances
                    best, best_d = i, d
        role_of_player[best] = r
    return role_of_player


# Compiled because it runs every cycle: 0.3 us a call against 1.7 us for np.isfinite(...).all() twice.
@njit(cache=True, nogil=True)
def all_finite(a: np.ndarray, b: np.ndarray) -> bool:  # pragma: no cover - compiled
    """Whether every entry of the two C-contiguous arrays is finite (one call, no temporaries)."""
    for x in a.ravel():
        if not math.isfinite(x):
            return False
    for x in b.ravel():
        if not math.isfinite(x):
            return False
    return True


@njit(cache=True, nogil=True)
def bid_costs(players: np.ndarray, targets: np.ndarray, ball: np.ndarray, goal: np.ndarray, reach: np.ndarray,
              params: np.ndarray, scale: np.ndarray) -> np.ndarray:  # pragma: no cover - compiled
    """The bid costs of :mod:`agents.roles.bidding`'s docstring; ``reach`` (k,) the ball reach
    of every player, or empty for the straight distance; ``scale`` (k,) each player's time
    factor (its formation-role costs and straight ball distance are multiplied by it), or
    empty for none; ``params`` is
    :meth:`~agents.roles.bidding.BiddingParams.as_record` (the bid weights are read from it).
    Returns (k, k + 1): formation roles, then the ball role."""
    k = players.shape[0]
    p = params[0]
    cap, angle_weight, goal_side = p.ball_cap, p.angle_weight, p.goal_side_weight
    costs = np.empty((k, k + 1))
    gx, gy = goal[0] - ball[0], goal[1] - ball[1]
    goal_dist = math.hypot(gx, gy)
    for i in range(k):
        px, py = players[i, 0], players[i, 1]
        for r in range(k):
            c = math.hypot(px - targets[r, 0], py - targets[r, 1])
            if targets[r, 0] < ball[0] and px > targets[r, 0]:
                c += goal_side * (px - targets[r, 0])
            if scale.shape[0]:
                c *= scale[i]
            costs[i, r] = c
        bx, by = ball[0] - px, ball[1] - py
        d = math.hypot(bx, by)
        theta = 0.0
        if d > 1e-9 and goal_dist > 1e-9:
            theta = math.acos(min(max((bx * gx + by * gy) / (d * goal_dist), -1.0), 1.0))
        near = d
        if scale.shape[0]:
            near = d * scale[i]
        if reach.shape[0] and math.isinf(reach[i]):  # cannot intercept: after every player who can
            costs[i, k] = cap + angle_weight * math.pi + min(near, cap) + angle_weight * theta
            continue
        if reach.shape[0]:
            near = reach[i]
        costs[i, k] = min(near, cap) + angle_weight * theta
    return costs


@njit(cache=True, nogil=True)
def auction(costs: np.ndarray, priority: np.ndarray, taken: np.ndarray, holder: np.ndarray, since: np.ndarray,
            cycle: int, min_hold: int, margin: float, winners: np.ndarray) -> None:  # pragma: no cover - compiled
    """Auction the roles (columns of ``costs``) in ``priority`` order, each to the best bidder
    not ``taken`` (ties: lower row), with the hysteresis of :mod:`agents.roles.bidding`'s
    docstring. Marks the winners taken, writes them into ``winners[role]`` and updates
    ``holder`` and ``since``."""
    k = costs.shape[0]
    for role in priority:
        best, best_cost = -1, math.inf
        for i in range(k):
            if not taken[i] and (best < 0 or costs[i, role] < best_cost):
                best, best_cost = i, costs[i, role]
        incumbent = holder[role]
        if 0 <= incumbent < k and not taken[incumbent] and incumbent != best:
            if cycle - since[role] < min_hold or costs[incumbent, role] - margin <= best_cost:
                best = incumbent
        if best != incumbent:
            holder[role] = best
            since[role] = cycle
        winners[role] = best
        taken[best] = True


@njit(cache=True, nogil=True)
def covered_role(targets: np.ndarray, order: np.ndarray, ball: np.ndarray, kept: int,
                 slack: float) -> int:  # pragma: no cover - compiled
    """The formation role the ball player covers: ``kept`` (its role so far, -1: none) if that
    role's target is at most ``slack`` metres farther from the ball than the nearest target,
    else the role whose target is nearest the ball (ties: the more offensive)."""
    nearest, gap = -1, math.inf
    for r in order:
        d = math.hypot(targets[r, 0] - ball[0], targets[r, 1] - ball[1])
        if nearest < 0 or d < gap:
            nearest, gap = r, d
    if kept >= 0 and math.hypot(targets[kept, 0] - ball[0], targets[kept, 1] - ball[1]) <= gap + slack:
        return kept
    return nearest


@njit(cache=True, nogil=True)
def bidding_round(players: np.ndarray, targets: np.ndarray, order: np.ndarray, ball: np.ndarray,
                  goal: np.ndarray, reach: np.ndarray, params: np.ndarray, holder: np.ndarray, since: np.ndarray,
                  last_role: np.ndarray, cycle: int,
                  scale: np.ndarray) -> tuple[np.ndarray, int, int]:  # pragma: no cover - compiled
    """One cycle of bidding with ``params``
    (:meth:`~agents.roles.bidding.BiddingParams.as_record`): (role_of_player, the ball player,
    the covered formation role); updates the hysteresis memory (``holder``, ``since``) and
    ``last_role`` (each player's role); ``scale`` as :func:`bid_costs`. A ball-role holder
    whose ``reach`` is inf while another player's is finite loses its hold first."""
    k = players.shape[0]
    p = params[0]
    min_hold, margin, slack = p.min_hold, p.switch_margin, p.cover_slack
    costs = bid_costs(players, targets, ball, goal, reach, params, scale)
    if reach.shape[0] and 0 <= holder[k] < k and math.isinf(reach[holder[k]]):
        for i in range(k):
            if not math.isinf(reach[i]):  # the holder cannot intercept, another player can
                holder[k] = -1
                break
    taken = np.zeros(k, dtype=np.bool_)
    winners = np.full(k + 1, -1, dtype=np.int64)
    auction(costs, np.array([k]), taken, holder, since, cycle, min_hold, margin, winners)
    ball_player = winners[k]
    covered = covered_role(targets, order, ball, last_role[ball_player], slack)
    priority = np.empty(k - 1, dtype=np.int64)
    n = 0
    for r in order:
        if r != covered:
            priority[n] = r
            n += 1
    auction(costs, priority, taken, holder, since, cycle, min_hold, margin, winners)
    for r in range(k):
        if r != covered:
            last_role[winners[r]] = r
    last_role[ball_player] = covered
    if holder[covered] != ball_player:
        holder[covered] = ball_player
        since[covered] = cycle
    return last_role.copy(), ball_player, covered
