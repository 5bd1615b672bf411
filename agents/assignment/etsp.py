"""A closed tour through points in the plane, at most twice the shortest (Euclidean TSP).

ETSP ASSGMT ("Monotonic Target Assignment for Robotic Networks", Smith and
Bullo) turns the cloud of targets into a ring by a constant-factor
approximation of the shortest closed tour; every agent must compute the same
ring, so the tour here is a deterministic function of the point array.

Construction: the Euclidean minimum spanning tree (a subgraph of the Delaunay
triangulation, so only O(n) candidate edges) walked in depth-first preorder
from point 0 gives a tour no longer than twice the optimum (each tree edge is
walked at most twice, and shortcuts only shorten by the triangle inequality).
It is then improved by 2-opt moves restricted to each point's nearest
neighbours; a move is taken only when it shortens the tour, so the factor-two
guarantee is kept.
"""

from __future__ import annotations

import numpy as np
from numba import njit

#: Nearest neighbours examined per point by the 2-opt improvement.
TWO_OPT_NEIGHBOURS = 10
#: Full 2-opt passes at most (each pass is O(n k) plus the segment reversals).
TWO_OPT_MAX_PASSES = 50


def tour_length(points: np.ndarray, order: np.ndarray) -> float:
    """Length of the closed tour visiting ``points[order]`` in turn and returning to the start."""
    if order.shape[0] < 2:
        return 0.0
    ring = points[order]
    return float(np.sqrt(((ring - np.roll(ring, -1, axis=0)) ** 2).sum(axis=1)).sum())


def etsp_tour(points: np.ndarray) -> np.ndarray:
    """Order of ``points`` (``(n, 2)`` float array, distinct points) along a short closed tour.

    Returns a permutation of ``range(n)`` starting with 0. The tour is at most
    twice as long as the shortest one (see the module docstring).
    """
    points = np.ascontiguousarray(points, dtype=np.float64)
    n = points.shape[0]
    if n <= 3:
        return np.arange(n, dtype=np.int64)
    order = _spanning_tree_preorder(points)
    neighbours = _nearest_neighbours(points, min(TWO_OPT_NEIGHBOURS, n - 1))
    return _two_opt(points, order.astype(np.int64), neighbours, TWO_OPT_MAX_PASSES)


def _spanning_tree_preorder(points: np.ndarray) -> np.ndarray:
    """Depth-first preorder from point 0 of the Euclidean minimum spanning tree."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import depth_first_order, minimum_spanning_tree

    rows, cols = _delaunay_edges(points)
    lengths = np.sqrt(((points[rows] - points[cols]) ** 2).sum(axis=1))
    n = points.shape[0]
    graph = coo_matrix((lengths, (rows, cols)), shape=(n, n)).tocsr()
    tree = minimum_spanning_tree(graph)
    order, _ = depth_first_order(tree, 0, directed=False, return_predecessors=True)
    return order


def _delaunay_edges(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Edges of the Delaunay triangulation; collinear or otherwise degenerate inputs are
    triangulated with joggled input (every point stays a vertex, the graph stays connected)."""
    from scipy.spatial import Delaunay, QhullError

    try:
        triangulation = Delaunay(points)
        if triangulation.coplanar.size:  # points left out of the triangulation
            raise QhullError("coplanar points")
    except QhullError:
        triangulation = Delaunay(points, qhull_options="QJ Qbb Qc")
    simplices = triangulation.simplices
    rows = np.concatenate([simplices[:, 0], simplices[:, 1], simplices[:, 2]])
    cols = np.concatenate([simplices[:, 1], simplices[:, 2], simplices[:, 0]])
    return rows, cols


def _nearest_neighbours(points: np.ndarray, k: int) -> np.ndarray:
    """``(n, k)`` indices of each point's k nearest other points, nearest first."""
    from scipy.spatial import cKDTree

    _, index = cKDTree(points).query(points, k=k + 1)
    return np.ascontiguousarray(index[:, 1:], dtype=np.int64)


@njit(cache=True, nogil=True)
def _dist(points: np.ndarray, a: int, b: int) -> float:
    dx = points[a, 0] - points[b, 0]
    dy = points[a, 1] - points[b, 1]
    return np.sqrt(dx * dx + dy * dy)


@njit(cache=True, nogil=True)
def _reverse(tour: np.ndarray, pos: np.ndarray, i: int, j: int) -> None:
    """Reverse the cyclic stretch of positions ``i .. j`` (inclusive, going forward); reverses
    the complementary stretch instead when that is shorter (same cyclic tour)."""
    n = tour.shape[0]
    length = (j - i) % n + 1
    if 2 * length > n:
        i, j = (j + 1) % n, (i - 1) % n
        length = n - length
    for _ in range(length // 2):
        a = tour[i]
        b = tour[j]
        tour[i] = b
        pos[b] = i
        tour[j] = a
        pos[a] = j
        i = (i + 1) % n
        j = (j - 1) % n


@njit(cache=True, nogil=True)
def _two_opt(points: np.ndarray, order: np.ndarray, neighbours: np.ndarray, max_passes: int) -> np.ndarray:
    """2-opt restricted to nearest-neighbour candidate edges; returns the tour rotated to start at 0."""
    n = order.shape[0]
    tour = order.copy()
    pos = np.empty(n, dtype=np.int64)
    for p in range(n):
        pos[tour[p]] = p
    for _ in range(max_passes):
        improved = False
        for a in range(n):
            for direction in range(2):
                pa = pos[a]
                # direction 0: edge (a, succ a); direction 1: edge (pred a, a)
                b = tour[(pa + 1) % n] if direction == 0 else tour[(pa - 1) % n]
                d_ab = _dist(points, a, b)
                for t in range(neighbours.shape[1]):
                    c = neighbours[a, t]
                    d_ac = _dist(points, a, c)
                    if d_ac >= d_ab:
                        break
                    pc = pos[c]
                    d = tour[(pc + 1) % n] if direction == 0 else tour[(pc - 1) % n]
                    if c == b or d == a:
                        continue
                    gain = d_ab + _dist(points, c, d) - d_ac - _dist(points, b, d)
                    if gain > 1e-12 * (d_ab + 1.0):
                        if direction == 0:
                            _reverse(tour, pos, pos[b], pos[c])
                        else:
                            _reverse(tour, pos, pos[c], pos[b])
                        improved = True
                        pa = pos[a]
                        b = tour[(pa + 1) % n] if direction == 0 else tour[(pa - 1) % n]
                        d_ab = _dist(points, a, b)
        if not improved:
            break
    start = pos[0]
    out = np.empty(n, dtype=np.int64)
    for p in range(n):
        out[p] = tour[(start + p) % n]
    return out
