"""SCRAM's two assignment functions (and the plain bottleneck) on dense matrices.

From "SCRAM: Scalable Collision-avoiding Role Assignment with Minimal-makespan
for Formational Positioning" (MacAlpine, Price, Stone):

- MMDR (minimum maximal distance, recursive): the lexicographic bottleneck
  assignment, see :mod:`.lexicographic`.
- MMD+MSD²: the smallest makespan first, then the least sum of squared
  distances among the assignments using only pairs no longer than it.

Inputs: ``lengths`` ``(rows, cols)`` with ``rows <= cols`` and ``inf`` for
forbidden pairs, ``squared`` the squared lengths; a complete assignment must
exist (checked by the caller). Outputs: the target index of every row.
"""

from __future__ import annotations

import numpy as np
from numba import njit
from scipy.optimize import linear_sum_assignment

from .bottleneck import bottleneck_matching
from .deletion import delete_longest_first
from .geometry import dense_distances
from .graphs import dense_to_graph, square_up
from .lexicographic import lexicographic_refine


def bottleneck_assignment(lengths: np.ndarray) -> tuple[float, np.ndarray]:
    """Return ``(makespan, col_of_row)`` of an assignment with the smallest makespan."""
    indptr, indices, pair_lengths = dense_to_graph(lengths)
    value, col_of_row, _ = bottleneck_matching(indptr, indices, pair_lengths, lengths.shape[1])
    return value, col_of_row


def mmd_msd2_assignment(lengths: np.ndarray, squared: np.ndarray) -> np.ndarray:
    """MMD+MSD²: least sum of squares among the assignments of smallest makespan."""
    value, _ = bottleneck_assignment(lengths)
    allowed = np.where(lengths <= value, squared, np.inf)
    return linear_sum_assignment(allowed)[1].astype(np.int64, copy=False)


def mmdr_assignment(lengths: np.ndarray) -> np.ndarray:
    """MMDR: the exact lexicographic bottleneck assignment (bottleneck, then refinement)."""
    n_rows, n_cols = lengths.shape
    indptr, indices, pair_lengths = dense_to_graph(lengths)
    value, col_of_row, row_of_col = bottleneck_matching(indptr, indices, pair_lengths, n_cols)
    return refine_to_lexicographic(indptr, indices, pair_lengths, value, col_of_row, row_of_col)


@njit(cache=True, nogil=True)
def refine_to_lexicographic(
    indptr: np.ndarray,
    indices: np.ndarray,
    lengths: np.ndarray,
    value: float,
    col_of_row: np.ndarray,
    row_of_col: np.ndarray,
) -> np.ndarray:
    """Lexicographic refinement of a bottleneck matching; squares up rectangular problems first."""
    n_rows = indptr.shape[0] - 1
    n_cols = row_of_col.shape[0]
    if n_rows < n_cols:
        indptr, indices, lengths, col_of_row, row_of_col = square_up(
            indptr, indices, lengths, n_cols, value, -np.inf, col_of_row, row_of_col
        )
    lexicographic_refine(indptr, indices, lengths, value, col_of_row, row_of_col)
    return col_of_row[:n_rows]


# Point-to-point forms for per-cycle callers (the soccer role assigners solve a 10 x 10
# problem every cycle): one compiled call each. Without ties the answer is the unique optimum,
# found by deleting pairs longest first (:mod:`.deletion`); with ties, the same steps as above
# (whose graph's short rows are sorted without allocations, see :func:`.graphs.dense_to_graph`),
# so the answer is the same bit for bit either way.


@njit(cache=True, nogil=True)
def _scaled_distances(robots: np.ndarray, targets: np.ndarray, scale: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The Euclidean problem's lengths and squared lengths; a non-empty ``scale`` (n,)
    multiplies robot i's lengths by ``scale[i]`` first (travel times of robots of different
    speeds, in the unit of a reference speed)."""
    lengths, squared = dense_distances(robots, targets)
    if scale.shape[0]:
        for i in range(lengths.shape[0]):
            for j in range(lengths.shape[1]):
                lengths[i, j] *= scale[i]
                squared[i, j] = lengths[i, j] * lengths[i, j]
    return lengths, squared


@njit(cache=True, nogil=True)
def _bottleneck_value(lengths: np.ndarray) -> float:
    """The smallest makespan of ``lengths`` (n, m), ``n <= m``, all finite."""
    if lengths.shape[0] > 0:
        return delete_longest_first(lengths, False)[1]
    indptr, indices, pair_lengths = dense_to_graph(lengths)
    return bottleneck_matching(indptr, indices, pair_lengths, lengths.shape[1])[0]


@njit(cache=True, nogil=True)
def bottleneck_of_points(robots: np.ndarray, targets: np.ndarray) -> tuple[float, np.ndarray]:
    """``(b, lengths)``: the smallest makespan ``b`` of any assignment of ``robots`` (n, d) to
    ``targets`` (m, d), ``n <= m``, all finite, and the Euclidean distance matrix it was found
    on (so a caller compares other assignments' lengths with ``b`` bit for bit)."""
    lengths, _ = dense_distances(robots, targets)
    return _bottleneck_value(lengths), lengths


@njit(cache=True, nogil=True)
def mmdr_points(robots: np.ndarray, targets: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """:func:`mmdr_assignment` of the Euclidean distances between ``robots`` (n, d) and
    ``targets`` (m, d), ``n <= m``, all finite (robot i's times ``scale[i]`` when ``scale``
    is not empty): the target index of every robot."""
    lengths, _ = _scaled_distances(robots, targets, scale)
    if lengths.shape[0] > 0:
        col_of_row, _, tied = delete_longest_first(lengths, True)
        if not tied:
            return col_of_row
    indptr, indices, pair_lengths = dense_to_graph(lengths)
    value, col_of_row, row_of_col = bottleneck_matching(indptr, indices, pair_lengths, lengths.shape[1])
    return refine_to_lexicographic(indptr, indices, pair_lengths, value, col_of_row, row_of_col)


@njit(cache=True, nogil=True)
def bottleneck_squares(robots: np.ndarray, targets: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """The squared distances between ``robots`` and ``targets`` (scaled as :func:`mmdr_points`),
    ``inf`` for pairs longer than the bottleneck value: MMD+MSD²'s second-stage costs."""
    lengths, squared = _scaled_distances(robots, targets, scale)
    value = _bottleneck_value(lengths)
    for i in range(lengths.shape[0]):
        for j in range(lengths.shape[1]):
            if not lengths[i, j] <= value:
                squared[i, j] = np.inf
    return squared


def mmd_msd2_points(robots: np.ndarray, targets: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """:func:`mmd_msd2_assignment` of the Euclidean distances between ``robots`` and ``targets``
    (scaled as :func:`mmdr_points`)."""
    return linear_sum_assignment(bottleneck_squares(robots, targets, scale))[1].astype(np.int64, copy=False)


@njit(cache=True, nogil=True)
def mmdr_rows(robots: np.ndarray, targets: np.ndarray, scale: np.ndarray, out: np.ndarray) -> None:
    """:func:`mmdr_points` of many independent problems in one call: ``robots[r]`` (n, d) to
    ``targets[r]`` (m, d) into ``out[r]`` (n,), every problem with the same ``scale``."""
    for r in range(robots.shape[0]):
        out[r] = mmdr_points(robots[r], targets[r], scale)


@njit(cache=True, nogil=True)
def bottleneck_squares_rows(robots: np.ndarray, targets: np.ndarray, scale: np.ndarray,
                            out: np.ndarray) -> None:
    """:func:`bottleneck_squares` of many independent problems in one call (into ``out[r]``)."""
    for r in range(robots.shape[0]):
        out[r] = bottleneck_squares(robots[r], targets[r], scale)


def mmd_msd2_rows(robots: np.ndarray, targets: np.ndarray, scale: np.ndarray) -> np.ndarray:
    """:func:`mmd_msd2_points` of many independent problems: (problems, n) target indices."""
    squares = np.empty((robots.shape[0], robots.shape[1], targets.shape[1]))
    bottleneck_squares_rows(robots, targets, scale, squares)
    out = np.empty(robots.shape[:2], dtype=np.int64)
    for r in range(squares.shape[0]):
        out[r] = linear_sum_assignment(squares[r])[1]
    return out
