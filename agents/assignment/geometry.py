"""Euclidean distances between robots and targets, dense or for chosen pairs.

Every distance in the library is computed by the two kernels below with the
same arithmetic (squared coordinate differences summed in coordinate order,
then one square root), so a pair has bit-identical length whether it comes from
the dense matrix or from the k-d tree candidate search; ties between equal
lengths are therefore seen identically by every method.
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, nogil=True)
def dense_distances(robots: np.ndarray, targets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return ``(distance, squared_distance)`` matrices of shape ``(n, m)``."""
    n, d = robots.shape
    m = targets.shape[0]
    squared = np.empty((n, m))
    distance = np.empty((n, m))
    for i in range(n):
        for j in range(m):
            acc = 0.0
            for k in range(d):
                diff = robots[i, k] - targets[j, k]
                acc += diff * diff
            squared[i, j] = acc
            distance[i, j] = np.sqrt(acc)
    return distance, squared


@njit(cache=True, nogil=True)
def pair_squared_distances(
    robots: np.ndarray, targets: np.ndarray, rows: np.ndarray, cols: np.ndarray
) -> np.ndarray:
    """Squared distance between ``robots[rows[e]]`` and ``targets[cols[e]]`` for every ``e``."""
    d = robots.shape[1]
    out = np.empty(rows.shape[0])
    for e in range(rows.shape[0]):
        acc = 0.0
        for k in range(d):
            diff = robots[rows[e], k] - targets[cols[e], k]
            acc += diff * diff
        out[e] = acc
    return out


def candidate_pairs(
    robots: np.ndarray, targets: np.ndarray, radius: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """All robot-target pairs no longer than ``radius``, found with k-d trees.

    Returns ``(rows, cols, distance, squared_distance)``. The trees are queried
    with a slightly enlarged radius and the pairs are then filtered with this
    module's own distances, so the result is exactly the set of pairs whose
    library distance is ``<= radius``.
    """
    from scipy.spatial import cKDTree

    robot_tree = cKDTree(robots)
    target_tree = cKDTree(targets)
    found = robot_tree.sparse_distance_matrix(
        target_tree, radius * (1.0 + 1e-9) + 1e-300, output_type="ndarray"
    )
    rows = found["i"].astype(np.int64)
    cols = found["j"].astype(np.int64)
    squared = pair_squared_distances(robots, targets, rows, cols)
    distance = np.sqrt(squared)
    keep = distance <= radius
    return rows[keep], cols[keep], distance[keep], squared[keep]


def nearest_neighbour_bound(robots: np.ndarray, targets: np.ndarray) -> float:
    """A lower bound on the bottleneck (minimal makespan) of a geometric problem.

    Every robot must travel at least to its nearest target; when there are as
    many targets as robots, every target must also be reached by at least its
    nearest robot. Requires ``len(robots) <= len(targets)``.
    """
    from scipy.spatial import cKDTree

    bound = float(cKDTree(targets).query(robots, k=1)[0].max())
    if robots.shape[0] == targets.shape[0]:
        bound = max(bound, float(cKDTree(robots).query(targets, k=1)[0].max()))
    return bound
