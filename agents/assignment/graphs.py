"""Bipartite graphs of allowed robot-target pairs in compressed sparse row form.

A graph is the tuple ``(indptr, indices, lengths)`` over ``n_rows`` robots:
the pairs of robot ``r`` are ``indices[indptr[r]:indptr[r + 1]]`` (target
indices) with lengths ``lengths[...]``. Within a row the pairs are sorted by
increasing length (ties by target index), so a search restricted to pairs no
longer than a threshold can stop at the first longer pair.
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, nogil=True)
def dense_to_graph(lengths_matrix: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Graph of all finite entries of a dense ``(n, m)`` matrix (``inf`` = no pair)."""
    n, m = lengths_matrix.shape
    indptr = np.zeros(n + 1, dtype=np.int64)
    for i in range(n):
        count = 0
        for j in range(m):
            if lengths_matrix[i, j] < np.inf:
                count += 1
        indptr[i + 1] = indptr[i] + count
    indices = np.empty(indptr[n], dtype=np.int64)
    lengths = np.empty(indptr[n])
    for i in range(n):
        pos = indptr[i]
        if m > _INSERTION_MAX:
            for j in np.argsort(lengths_matrix[i], kind="mergesort"):
                if lengths_matrix[i, j] < np.inf:
                    indices[pos] = j
                    lengths[pos] = lengths_matrix[i, j]
                    pos += 1
            continue
        # Small rows (the per-cycle role problems): a stable insertion sort in place, the
        # same order as the merge sort (ties by target index) without its allocations.
        start = pos
        for j in range(m):
            value = lengths_matrix[i, j]
            if not value < np.inf:
                continue
            k = pos
            while k > start and lengths[k - 1] > value:
                lengths[k] = lengths[k - 1]
                indices[k] = indices[k - 1]
                k -= 1
            lengths[k] = value
            indices[k] = j
            pos += 1
    return indptr, indices, lengths


_INSERTION_MAX = 32
"""Rows of at most this many targets are sorted by insertion (cheaper than a merge sort's
allocations for the 10-odd targets of a role problem); longer ones by merge sort."""


@njit(cache=True, nogil=True)
def sorted_pair_order(n_rows: int, rows: np.ndarray, cols: np.ndarray, lengths: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Return ``(indptr, order)``: ``order`` sorts pairs by row, then length, then target index."""
    indptr = np.zeros(n_rows + 1, dtype=np.int64)
    for e in range(rows.shape[0]):
        indptr[rows[e] + 1] += 1
    for r in range(n_rows):
        indptr[r + 1] += indptr[r]
    fill = indptr[:-1].copy()
    order = np.empty(rows.shape[0], dtype=np.int64)
    for e in range(rows.shape[0]):
        order[fill[rows[e]]] = e
        fill[rows[e]] += 1
    for r in range(n_rows):
        segment = order[indptr[r] : indptr[r + 1]]
        by_col = segment[np.argsort(cols[segment], kind="mergesort")]
        by_length = by_col[np.argsort(lengths[by_col], kind="mergesort")]
        for k in range(by_length.shape[0]):  # a loop, not a slice assignment (slow to compile)
            order[indptr[r] + k] = by_length[k]
    return indptr, order


def pairs_to_graph(
    n_rows: int, rows: np.ndarray, cols: np.ndarray, lengths: np.ndarray, *extra: np.ndarray
) -> tuple[np.ndarray, ...]:
    """Graph from pair lists; ``extra`` per-pair arrays are permuted alongside.

    Returns ``(indptr, indices, lengths, *extra)`` with each row sorted by
    increasing length, ties by target index.
    """
    indptr, order = sorted_pair_order(n_rows, rows, cols, lengths)
    return (indptr, cols[order], lengths[order], *(array[order] for array in extra))


@njit(cache=True, nogil=True)
def edge_rows(indptr: np.ndarray) -> np.ndarray:
    """Row (robot) of every pair of the graph."""
    rows = np.empty(indptr[-1], dtype=np.int64)
    for r in range(indptr.shape[0] - 1):
        for e in range(indptr[r], indptr[r + 1]):
            rows[e] = r
    return rows


@njit(cache=True, nogil=True)
def square_up(
    indptr: np.ndarray,
    indices: np.ndarray,
    lengths: np.ndarray,
    n_cols: int,
    threshold: float,
    pad_length: float,
    col_of_row: np.ndarray,
    row_of_col: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Square graph whose perfect matchings are the complete assignments of a graph with fewer rows.

    For ``n`` rows and ``m > n`` targets the result has ``n + m`` rows and
    ``n + m`` columns: the original rows and targets, one "target copy" row
    ``n + c`` per target ``c`` and one "robot copy" column ``m + r`` per robot
    ``r``. Target copy ``n + c`` is joined to target ``c`` (the target stays
    unused) and to the robot copy ``m + r`` of every robot ``r`` with a pair
    ``(r, c)`` no longer than ``threshold`` (robot ``r`` took it); these padding
    pairs have length ``pad_length``. Every perfect matching restricted to the
    original rows is a complete assignment, and every complete assignment
    extends to one, so the padding costs ``2 * pairs + m`` pairs rather than
    the ``(m - n) * m`` of identical dummy robots joined to every target.

    Returns ``(indptr, indices, lengths, col_of_row, row_of_col)``, the last
    two extending the complete matching ``col_of_row``/``row_of_col``.
    """
    n_rows = indptr.shape[0] - 1
    size = n_rows + n_cols
    n_edges = indptr[-1]
    per_col = np.zeros(n_cols, dtype=np.int64)
    for e in range(n_edges):
        if lengths[e] <= threshold:
            per_col[indices[e]] += 1
    # Loops rather than slice assignments, which take seconds to compile under numba.
    new_indptr = np.empty(size + 1, dtype=np.int64)
    for r in range(n_rows + 1):
        new_indptr[r] = indptr[r]
    for c in range(n_cols):
        new_indptr[n_rows + c + 1] = new_indptr[n_rows + c] + 1 + per_col[c]
    new_indices = np.empty(new_indptr[-1], dtype=np.int64)
    new_lengths = np.full(new_indptr[-1], pad_length)
    for e in range(n_edges):
        new_indices[e] = indices[e]
        new_lengths[e] = lengths[e]
    fill = new_indptr[n_rows:-1].copy()
    for c in range(n_cols):  # the target itself first: lowest index among equal lengths
        new_indices[fill[c]] = c
        fill[c] += 1
    for r in range(n_rows):  # then robot copies in increasing robot order
        for e in range(indptr[r], indptr[r + 1]):
            if lengths[e] <= threshold:
                c = indices[e]
                new_indices[fill[c]] = n_cols + r
                fill[c] += 1
    new_col_of_row = np.empty(size, dtype=np.int64)
    new_row_of_col = np.empty(size, dtype=np.int64)
    for r in range(n_rows):
        new_col_of_row[r] = col_of_row[r]
        new_row_of_col[n_cols + r] = n_rows + col_of_row[r]
    for c in range(n_cols):
        r = row_of_col[c]
        new_row_of_col[c] = r if r >= 0 else n_rows + c
        new_col_of_row[n_rows + c] = n_cols + r if r >= 0 else c
    return new_indptr, new_indices, new_lengths, new_col_of_row, new_row_of_col
