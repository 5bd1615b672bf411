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
        order = np.argsort(lengths_matrix[i], kind="mergesort")
        pos = indptr[i]
        for j in order:
            if lengths_matrix[i, j] < np.inf:
                indices[pos] = j
                lengths[pos] = lengths_matrix[i, j]
                pos += 1
    return indptr, indices, lengths


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
        order[indptr[r] : indptr[r + 1]] = by_col[np.argsort(lengths[by_col], kind="mergesort")]
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
def pad_with_dummy_rows(
    indptr: np.ndarray, indices: np.ndarray, lengths: np.ndarray, n_cols: int, dummy_length: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Append ``n_cols - n_rows`` dummy rows joined to every target by ``dummy_length``.

    Turns a problem with fewer robots than targets into a square one whose
    perfect matchings are exactly the original complete assignments plus dummy
    robots parked on the unused targets.
    """
    n_rows = indptr.shape[0] - 1
    extra = n_cols - n_rows
    n_edges = indptr[-1]
    new_indptr = np.empty(n_cols + 1, dtype=np.int64)
    new_indptr[: n_rows + 1] = indptr
    for k in range(extra):
        new_indptr[n_rows + 1 + k] = n_edges + (k + 1) * n_cols
    new_indices = np.empty(n_edges + extra * n_cols, dtype=np.int64)
    new_lengths = np.empty(n_edges + extra * n_cols)
    new_indices[:n_edges] = indices
    new_lengths[:n_edges] = lengths
    for k in range(extra):
        for j in range(n_cols):
            new_indices[n_edges + k * n_cols + j] = j
            new_lengths[n_edges + k * n_cols + j] = dummy_length
    return new_indptr, new_indices, new_lengths
