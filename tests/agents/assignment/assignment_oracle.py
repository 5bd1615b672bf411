"""Independent brute-force oracle and motion helpers for the assignment tests.

Nothing here uses the library's solvers: every complete assignment is
enumerated with itertools and scored directly.
"""

from __future__ import annotations

import itertools

import numpy as np

TOL = 1e-9


def distance_matrix(robots: np.ndarray, targets: np.ndarray) -> np.ndarray:
    robots = np.asarray(robots, dtype=float)
    targets = np.asarray(targets, dtype=float)
    return np.sqrt(((robots[:, None, :] - targets[None, :, :]) ** 2).sum(axis=-1))


def complete_assignments(costs: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
    """Every complete assignment avoiding inf pairs, as (target_of, chosen costs).

    With n <= m every robot is assigned; with n > m every target gets a robot.
    """
    n, m = costs.shape
    out = []
    if n <= m:
        for perm in itertools.permutations(range(m), n):
            target_of = np.array(perm, dtype=int)
            chosen = costs[np.arange(n), target_of]
            if np.isfinite(chosen).all():
                out.append((target_of, chosen))
    else:
        for perm in itertools.permutations(range(n), m):
            target_of = np.full(n, -1)
            target_of[list(perm)] = np.arange(m)
            chosen = costs[list(perm), np.arange(m)]
            if np.isfinite(chosen).all():
                out.append((target_of, chosen))
    return out


def lexicographic_key(chosen: np.ndarray) -> tuple[float, ...]:
    return tuple(sorted(chosen.tolist(), reverse=True))


def optimum(costs: np.ndarray, objective: str) -> object:
    """Optimal objective value over all complete assignments."""
    candidates = complete_assignments(costs)
    if objective == "mmdr":
        return min(lexicographic_key(c) for _, c in candidates)
    if objective == "bottleneck":
        return min(c.max() for _, c in candidates)
    if objective == "msd":
        return min(c.sum() for _, c in candidates)
    if objective == "msd2":
        return min((c**2).sum() for _, c in candidates)
    if objective == "mmd+msd2":
        makespan = min(c.max() for _, c in candidates)
        return makespan, min((c**2).sum() for _, c in candidates if c.max() <= makespan * (1 + 1e-12))
    raise ValueError(objective)


def greedy_reference(costs: np.ndarray) -> np.ndarray:
    """Shortest pair first; ties by robot index then target index."""
    n, m = costs.shape
    pairs = sorted((costs[i, j], i, j) for i in range(n) for j in range(m) if np.isfinite(costs[i, j]))
    target_of = np.full(n, -1)
    taken = set()
    for _, i, j in pairs:
        if target_of[i] < 0 and j not in taken:
            target_of[i] = j
            taken.add(j)
    return target_of


def assert_valid(target_of: np.ndarray, n: int, m: int) -> None:
    """Complete assignment: injective; all robots served if n <= m, all targets if n > m."""
    assigned = target_of[target_of >= 0]
    assert target_of.shape == (n,)
    assert len(set(assigned.tolist())) == assigned.size
    assert ((target_of >= -1) & (target_of < m)).all()
    assert assigned.size == min(n, m)


def position_at(start: np.ndarray, goal: np.ndarray, t: float) -> np.ndarray:
    """Straight line at unit speed, then wait at the goal."""
    length = np.linalg.norm(goal - start)
    if length == 0 or t >= length:
        return goal.copy()
    return start + (goal - start) * (t / length)


def paths_meet(a1, p1, a2, p2, tol: float = 1e-7) -> bool:
    """Do two unit-speed straight-line movers (waiting at their goals) ever share a point?

    Splits time at the arrival instants; on each piece both positions are
    affine in t, so the squared gap is a quadratic whose minimum is exact.
    """
    a1, p1, a2, p2 = (np.asarray(x, dtype=float) for x in (a1, p1, a2, p2))
    l1, l2 = np.linalg.norm(p1 - a1), np.linalg.norm(p2 - a2)
    breaks = sorted({0.0, l1, l2})
    for t0, t1 in zip(breaks, breaks[1:] + [breaks[-1] + 1.0]):
        x0 = position_at(a1, p1, t0) - position_at(a2, p2, t0)
        x1 = position_at(a1, p1, t1) - position_at(a2, p2, t1)
        velocity = (x1 - x0) / (t1 - t0)
        denom = velocity @ velocity
        s = 0.0 if denom == 0 else min(max(-(x0 @ velocity) / denom, 0.0), t1 - t0)
        if np.linalg.norm(x0 + s * velocity) <= tol:
            return True
    return False


def has_collision(robots: np.ndarray, targets: np.ndarray, target_of: np.ndarray) -> bool:
    movers = [i for i in range(len(robots)) if target_of[i] >= 0]
    for x, y in itertools.combinations(movers, 2):
        if paths_meet(robots[x], targets[target_of[x]], robots[y], targets[target_of[y]]):
            return True
    return False


# References for sizes beyond brute force, built on SciPy's dense solver only.


def _rows_fewer(costs: np.ndarray) -> np.ndarray:
    return costs.T if costs.shape[0] > costs.shape[1] else costs


def scipy_min_sum(costs: np.ndarray) -> float:
    """Least total of a complete assignment (inf = forbidden), by linear_sum_assignment."""
    from scipy.optimize import linear_sum_assignment

    matrix = _rows_fewer(costs)
    rows, cols = linear_sum_assignment(matrix)
    return float(matrix[rows, cols].sum())


def threshold_bottleneck(costs: np.ndarray) -> float:
    """Smallest makespan of a complete assignment: binary search over the distinct costs,
    each threshold tested by a 0/1 linear_sum_assignment (optimum 0 iff a complete
    assignment uses only pairs no longer than the threshold)."""
    from scipy.optimize import linear_sum_assignment

    matrix = _rows_fewer(costs)
    values = np.unique(matrix[np.isfinite(matrix)])
    lo, hi = 0, values.size - 1
    while lo < hi:
        mid = (lo + hi) // 2
        over = (matrix > values[mid]).astype(float)
        rows, cols = linear_sum_assignment(over)
        if over[rows, cols].sum() == 0:
            hi = mid
        else:
            lo = mid + 1
    return float(values[lo])


def chosen_costs(target_of: np.ndarray, costs: np.ndarray) -> np.ndarray:
    served = target_of >= 0
    return costs[np.flatnonzero(served), target_of[served]]
