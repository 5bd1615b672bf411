"""SCRAM's methods for many robots in the plane or in space, without an n x n matrix.

Once the bottleneck value ``b`` is known, only pairs no longer than ``b`` can
appear in an MMDR or MMD+MSD² assignment; for random points that is a few tens
of pairs per robot. A k-d tree finds the pairs within a radius; the radius
starts at 1.5 times a lower bound of ``b`` (nearest-neighbour distances) and
grows (by 25 %, then faster) until the pairs within it admit a complete
assignment, whose bottleneck is then the global one (every pair shorter than it
is in the candidate set).

The restricted MMD+MSD² problem is solved by the sparse Jonker-Volgenant solver
``lapmod`` of the ``lap`` package: a few seconds at n = 10000, where dense
solvers need minutes and SciPy's sparse matching can stall. ``lapmod`` only
solves square problems; fewer robots than targets are squared up with
:func:`.graphs.square_up`.
"""

from __future__ import annotations

import numpy as np

from .bottleneck import bottleneck_matching
from .geometry import candidate_pairs, nearest_neighbour_bound
from .graphs import pairs_to_graph, square_up
from .scram import refine_to_lexicographic

#: First candidate radius, as a multiple of the nearest-neighbour lower bound (for
#: uniformly random points the bottleneck is typically 1.25-1.8 times that bound).
INITIAL_RADIUS_FACTOR = 1.5
#: First growth factor of the candidate radius while it admits no complete assignment; the
#: factor squares after every failure, so a poor first radius (for instance a zero lower
#: bound when robots sit on targets) costs a handful of k-d tree searches, not dozens.
RADIUS_GROWTH = 1.25


class CandidateGraph:
    """Pairs no longer than a radius that contains the bottleneck, sorted per robot by length."""

    __slots__ = ("indptr", "indices", "lengths", "squared", "bottleneck", "col_of_row", "row_of_col")

    def __init__(self, robots: np.ndarray, targets: np.ndarray) -> None:
        n, m = robots.shape[0], targets.shape[0]
        radius = nearest_neighbour_bound(robots, targets) * INITIAL_RADIUS_FACTOR
        spread = float(np.ptp(np.vstack([robots, targets]), axis=0).max())
        growth = RADIUS_GROWTH
        while True:
            rows, cols, lengths, squared = candidate_pairs(robots, targets, radius)
            self.indptr, self.indices, self.lengths, self.squared = pairs_to_graph(n, rows, cols, lengths, squared)
            self.bottleneck, self.col_of_row, self.row_of_col = bottleneck_matching(
                self.indptr, self.indices, self.lengths, m
            )
            if self.bottleneck < np.inf:
                return
            # The complete graph always admits an assignment, so this terminates.
            radius = radius * growth if radius > 0 else max(spread, 1.0) * 1e-6
            growth *= growth

    def assigned_lengths(self, col_of_row: np.ndarray) -> np.ndarray:
        """Length of the pair ``(r, col_of_row[r])`` for every robot ``r``."""
        rows = np.repeat(np.arange(self.indptr.shape[0] - 1), np.diff(self.indptr))
        hit = self.indices == col_of_row[rows]
        out = np.full(col_of_row.shape[0], np.nan)
        out[rows[hit]] = self.lengths[hit]
        return out


def sparse_bottleneck(robots: np.ndarray, targets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """A smallest-makespan assignment: ``(col_of_row, length_of_row)``."""
    graph = CandidateGraph(robots, targets)
    return graph.col_of_row, graph.assigned_lengths(graph.col_of_row)


def sparse_mmdr(robots: np.ndarray, targets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """MMDR on the candidate graph: ``(col_of_row, length_of_row)``."""
    graph = CandidateGraph(robots, targets)
    col_of_row = refine_to_lexicographic(
        graph.indptr, graph.indices, graph.lengths, graph.bottleneck, graph.col_of_row, graph.row_of_col
    )
    return col_of_row, graph.assigned_lengths(col_of_row)


def sparse_mmd_msd2(robots: np.ndarray, targets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """MMD+MSD² on the candidate graph with ``lap.lapmod``: ``(col_of_row, length_of_row)``."""
    from lap import lapmod

    graph = CandidateGraph(robots, targets)
    n, m = robots.shape[0], targets.shape[0]
    keep = graph.lengths <= graph.bottleneck
    indptr = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(np.bincount(np.repeat(np.arange(n), np.diff(graph.indptr))[keep], minlength=n), out=indptr[1:])
    indices, costs = graph.indices[keep], graph.squared[keep]
    size = n
    if n < m:  # square up: target copies and robot copies joined at zero cost
        indptr, indices, costs, _, _ = square_up(
            indptr, indices, costs, m, np.inf, 0.0, graph.col_of_row, graph.row_of_col
        )
        size = n + m
    # lapmod wants each row's entries sorted by target index, and costs below its
    # LARGE constant (1e6); scaling by a power of two is exact.
    rows = np.repeat(np.arange(size), np.diff(indptr))
    order = np.lexsort((indices, rows))
    top = float(costs.max()) if costs.size else 0.0
    scale = 2.0 ** -np.ceil(np.log2(top)) if top > 0 else 1.0
    col_of_row = lapmod(size, costs[order] * scale, indptr, indices[order], fast=True, return_cost=False)[0]
    col_of_row = np.asarray(col_of_row[:n], dtype=np.int64)
    lengths = graph.assigned_lengths(col_of_row)
    if not (lengths <= graph.bottleneck).all() or np.unique(col_of_row).shape[0] != n:
        raise RuntimeError("lapmod returned an assignment outside the candidate pairs")
    return col_of_row, lengths
