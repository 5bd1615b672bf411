"""Maximum-cardinality bipartite matching (Hopcroft-Karp) on a threshold graph.

Only pairs no longer than ``threshold`` are used. The matching is improved in
place from whatever partial matching the caller passes in, which is how the
bottleneck search reuses work between thresholds. Dead ends are marked during
each phase's depth-first search, so every phase costs O(pairs) and the whole
run O(pairs * sqrt(robots)) (without that marking the search can take
exponential time on geometric graphs).
"""

from __future__ import annotations

import numpy as np
from numba import njit

_UNREACHED = np.iinfo(np.int64).max


@njit(cache=True, nogil=True)
def maximum_matching(
    indptr: np.ndarray,
    indices: np.ndarray,
    lengths: np.ndarray,
    threshold: float,
    col_of_row: np.ndarray,
    row_of_col: np.ndarray,
) -> int:
    """Grow ``col_of_row``/``row_of_col`` (``-1`` = unmatched) to a maximum matching.

    Rows must be sorted by increasing length (see :mod:`.graphs`). Returns the
    number of matched rows.
    """
    n_rows = indptr.shape[0] - 1
    layer = np.empty(n_rows, dtype=np.int64)
    queue = np.empty(n_rows, dtype=np.int64)
    cursor = np.empty(n_rows, dtype=np.int64)
    stack = np.empty(n_rows, dtype=np.int64)
    size = 0
    for r in range(n_rows):
        if col_of_row[r] >= 0:
            size += 1
    # Cheap start: give every free row its shortest free target.
    for r in range(n_rows):
        if col_of_row[r] < 0:
            for e in range(indptr[r], indptr[r + 1]):
                if lengths[e] > threshold:
                    break
                c = indices[e]
                if row_of_col[c] < 0:
                    col_of_row[r] = c
                    row_of_col[c] = r
                    size += 1
                    break
    while size < n_rows:
        # Breadth-first layering from all free rows.
        head = 0
        tail = 0
        for r in range(n_rows):
            if col_of_row[r] < 0:
                layer[r] = 0
                queue[tail] = r
                tail += 1
            else:
                layer[r] = _UNREACHED
        found = False
        while head < tail:
            r = queue[head]
            head += 1
            for e in range(indptr[r], indptr[r + 1]):
                if lengths[e] > threshold:
                    break
                r2 = row_of_col[indices[e]]
                if r2 < 0:
                    found = True
                elif layer[r2] == _UNREACHED:
                    layer[r2] = layer[r] + 1
                    queue[tail] = r2
                    tail += 1
        if not found:
            break
        # Depth-first search for vertex-disjoint augmenting paths along the layers.
        for r in range(n_rows):
            cursor[r] = indptr[r]
        for start in range(n_rows):
            if col_of_row[start] >= 0 or layer[start] != 0:
                continue
            depth = 0
            stack[0] = start
            while depth >= 0:
                r = stack[depth]
                advanced = False
                augmented = False
                while cursor[r] < indptr[r + 1]:
                    e = cursor[r]
                    if lengths[e] > threshold:
                        cursor[r] = indptr[r + 1]
                        break
                    r2 = row_of_col[indices[e]]
                    if r2 < 0:
                        augmented = True
                        break
                    if layer[r2] == layer[r] + 1:
                        depth += 1
                        stack[depth] = r2
                        advanced = True
                        break
                    cursor[r] += 1
                if augmented:
                    # Flip the path: each row on the stack takes the target its cursor points at.
                    for k in range(depth, -1, -1):
                        row = stack[k]
                        c = indices[cursor[row]]
                        col_of_row[row] = c
                        row_of_col[c] = row
                        layer[row] = _UNREACHED
                    size += 1
                    break
                if not advanced:
                    layer[r] = _UNREACHED  # dead end for the rest of this phase
                    depth -= 1
                    if depth >= 0:
                        cursor[stack[depth]] += 1
    return size
