"""Assignment rules other than SCRAM's, for comparison: sums, greedy, random.

All take dense ``(rows, cols)`` matrices with ``rows <= cols`` (``inf`` =
forbidden pair; a complete assignment must exist) and return the target index
of every row. Sum objectives use SciPy's exact shortest-augmenting-path solver
(``linear_sum_assignment``), which takes about a microsecond at 10 x 10.
"""

from __future__ import annotations

import numpy as np
from numba import njit
from scipy.optimize import linear_sum_assignment

from .graphs import dense_to_graph
from .matching import maximum_matching


def min_sum_assignment(costs: np.ndarray) -> np.ndarray:
    """Assignment minimising the sum of ``costs`` (MSD on distances, MSD² on squared ones)."""
    return linear_sum_assignment(costs)[1].astype(np.int64, copy=False)


@njit(cache=True, nogil=True)
def _greedy(lengths: np.ndarray) -> tuple[np.ndarray, np.ndarray, int]:
    n, m = lengths.shape
    flat = lengths.ravel()
    order = np.argsort(flat, kind="mergesort")  # ties: row-major order, i.e. lowest robot then target
    col_of_row = np.full(n, -1, dtype=np.int64)
    row_of_col = np.full(m, -1, dtype=np.int64)
    count = 0
    for idx in order:
        if count == n or flat[idx] == np.inf:
            break
        i = idx // m
        j = idx % m
        if col_of_row[i] < 0 and row_of_col[j] < 0:
            col_of_row[i] = j
            row_of_col[j] = i
            count += 1
    return col_of_row, row_of_col, count


def greedy_assignment(lengths: np.ndarray) -> np.ndarray:
    """Repeatedly take the shortest remaining robot-target pair.

    Ties go to the lower row index, then the lower column index (rows are
    the robots, or the targets when robots outnumber targets and the front
    door transposes the problem). When
    forbidden pairs make the greedy choices a dead end, the few robots left
    over are served by augmenting paths (which may move some greedy choices).
    """
    col_of_row, row_of_col, count = _greedy(lengths)
    if count < lengths.shape[0]:
        indptr, indices, pair_lengths = dense_to_graph(lengths)
        maximum_matching(indptr, indices, pair_lengths, np.inf, col_of_row, row_of_col)
    return col_of_row


def random_assignment(lengths: np.ndarray, rng: np.random.Generator) -> np.ndarray:
    """A random complete assignment drawn from ``rng``.

    Uniform over all assignments when no pair is forbidden; otherwise the
    minimum-sum assignment for independent uniform random pair weights.
    """
    n, m = lengths.shape
    if np.isfinite(lengths).all():
        return rng.permutation(m)[:n].astype(np.int64)
    weights = np.where(np.isfinite(lengths), rng.random((n, m)), np.inf)
    return min_sum_assignment(weights)
