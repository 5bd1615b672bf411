"""The bottleneck assignment: the smallest makespan any complete assignment can have.

The makespan of a complete assignment is its longest pair; the bottleneck value
``b`` is the smallest threshold such that the pairs no longer than ``b`` still
contain a matching that gives every robot a target. It is found by galloping
then binary search over the sorted distinct pair lengths, starting from a lower
bound (every robot needs at least its shortest pair), with a maximum-matching
test at each probe. Each probe starts from the matching of the largest
threshold known to fail, which stays valid at any larger threshold, so later
probes only add the few missing augmenting paths.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .matching import maximum_matching


@njit(cache=True, nogil=True)
def _distinct_sorted(values: np.ndarray) -> np.ndarray:
    """Sorted distinct values (``np.unique`` without its long compile time under numba)."""
    out = np.sort(values)
    count = 0
    for k in range(out.shape[0]):
        if count == 0 or out[k] != out[count - 1]:
            out[count] = out[k]
            count += 1
    return out[:count]


@njit(cache=True, nogil=True)
def bottleneck_matching(
    indptr: np.ndarray, indices: np.ndarray, lengths: np.ndarray, n_cols: int
) -> tuple[float, np.ndarray, np.ndarray]:
    """Return ``(b, col_of_row, row_of_col)``: bottleneck value and a matching attaining it.

    Every row is matched by pairs no longer than ``b``. Requires
    ``rows <= n_cols`` and rows sorted by increasing length. When no complete
    matching exists at all, ``b`` is ``inf`` and the returned matching is a
    maximum one (so the caller can report how many robots could be served).
    """
    n_rows = indptr.shape[0] - 1
    fail_col = np.full(n_rows, -1, dtype=np.int64)
    fail_row = np.full(n_cols, -1, dtype=np.int64)
    if n_rows == 0:
        return 0.0, fail_col, fail_row
    lower = -np.inf
    for r in range(n_rows):
        if indptr[r] == indptr[r + 1]:
            maximum_matching(indptr, indices, lengths, np.inf, fail_col, fail_row)
            return np.inf, fail_col, fail_row
        lower = max(lower, lengths[indptr[r]])
    if n_rows == n_cols:
        column_min = np.full(n_cols, np.inf)
        for e in range(lengths.shape[0]):
            if lengths[e] < column_min[indices[e]]:
                column_min[indices[e]] = lengths[e]
        for c in range(n_cols):
            lower = max(lower, column_min[c])
    values = _distinct_sorted(lengths[lengths >= lower])
    best_col = fail_col
    best_row = fail_row
    # Invariant: probes at index <= lo fail (lo = -1: nothing known), hi succeeds (hi = len: unknown).
    lo = -1
    hi = values.shape[0]
    step = 1
    probe = 0
    while hi - lo > 1:
        # (Copies, not slice assignments: those cost seconds of numba compile time.)
        work_col = fail_col.copy()
        work_row = fail_row.copy()
        size = maximum_matching(indptr, indices, lengths, values[probe], work_col, work_row)
        if size == n_rows:
            hi = probe
            best_col, best_row = work_col, work_row
        else:
            lo = probe
            fail_col, fail_row = work_col, work_row
        if hi == values.shape[0]:  # still galloping upwards
            step *= 2
            probe = min(lo + step, values.shape[0] - 1)
            if probe == lo:  # the longest pair failed: no complete assignment
                return np.inf, fail_col, fail_row
        else:
            probe = (lo + hi) // 2
    return values[hi], best_col, best_row
