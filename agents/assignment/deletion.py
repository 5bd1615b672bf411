"""The lexicographic bottleneck assignment of a small dense problem, by deleting pairs longest first.

For the per-cycle soccer problems (10 players x 10 roles, every pair allowed) the general
method of :mod:`.lexicographic` spends most of its time building a sorted sparse graph and a
bottleneck matching. When no two pair lengths are equal a plainer method gives the same
answer, because the optimum is then unique (two assignments with the same sorted lengths use
the same pairs). Think of visiting the pairs from the longest down and deleting each one
unless no complete matching is left without it (then every optimal assignment uses it and it
stays). Deleting a pair outside the current complete matching ``M`` costs nothing, so only
``M``'s pairs need a visit:

1. Start from the greedy ``M``: each row in turn takes its nearest free column.
2. Take ``M``'s longest pair not yet found needed, of length ``t``; every other pair of length
   ``t`` or more is deleted by now, unless it is needed. Unmatch its row and look for a
   breadth-first augmenting path over the pairs shorter than ``t`` and the needed ones.
3. If one is found, flip it (``M`` no longer uses the pair, and all its pairs are shorter);
   otherwise the pair is needed and stays. Repeat until every row's pair is needed.

The needed pairs are the optimum's; the first one found needed has the bottleneck length (the
smallest makespan) whatever the ties. When another pair has the length of a visited one, the
order among equal lengths could change the answer, so :func:`delete_longest_first` reports a
tie and the caller solves the problem the general way.
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, nogil=True)
def _rematch_below(start: int, lengths: np.ndarray, limit: float, needed: np.ndarray, col_of_row: np.ndarray,
                   row_of_col: np.ndarray, pred_row: np.ndarray, queue: np.ndarray,
                   seen: np.ndarray) -> bool:  # pragma: no cover - compiled
    """Breadth-first augmenting path from the unmatched row ``start`` over the pairs shorter
    than ``limit`` and the ``needed`` rows' own pairs; flip it and return True when one reaches
    a free column. (A path through a needed pair never completes: every complete matching left
    uses it.)"""
    n_cols = lengths.shape[1]
    seen[:] = False
    queue[0] = start
    head, tail = 0, 1
    while head < tail:
        r = queue[head]
        head += 1
        for c in range(n_cols):
            if seen[c] or not (lengths[r, c] < limit or (needed[r] and col_of_row[r] == c)):
                continue
            seen[c] = True
            pred_row[c] = r
            owner = row_of_col[c]
            if owner < 0:  # flip the path back to start
                while True:
                    row = pred_row[c]
                    previous = col_of_row[row]
                    col_of_row[row] = c
                    row_of_col[c] = row
                    if row == start:
                        return True
                    c = previous
            queue[tail] = owner
            tail += 1
    return False


@njit(cache=True, nogil=True)
def delete_longest_first(lengths: np.ndarray, whole: bool) -> tuple[np.ndarray, float, bool]:  # pragma: no cover
    """``(col_of_row, bottleneck, tied)`` of the finite ``lengths`` (n, m), ``0 < n <= m``, by
    the method of the module docstring. With ``whole`` False it stops at the bottleneck
    (``col_of_row`` is then only some complete matching, and ties are not looked for).
    ``tied``: a visited pair's length is another pair's too, so ``col_of_row`` may be one
    optimum of several (the bottleneck is right either way)."""
    n, m = lengths.shape
    col_of_row = np.full(n, -1, dtype=np.int64)
    row_of_col = np.full(m, -1, dtype=np.int64)
    for i in range(n):
        best, best_length = -1, np.inf
        for c in range(m):
            if row_of_col[c] < 0 and (best < 0 or lengths[i, c] < best_length):
                best, best_length = c, lengths[i, c]
        col_of_row[i], row_of_col[best] = best, i
    needed = np.zeros(n, dtype=np.bool_)
    pred_row = np.empty(m, dtype=np.int64)
    queue = np.empty(n, dtype=np.int64)
    seen = np.empty(m, dtype=np.bool_)
    bottleneck = np.nan
    tied = False
    fixed = 0
    while fixed < n:
        i, t = -1, -np.inf
        for r in range(n):
            if not needed[r] and (i < 0 or lengths[r, col_of_row[r]] > t):
                i, t = r, lengths[r, col_of_row[r]]
        if whole and not tied:  # (the bottleneck alone is right whatever the ties)
            same = 0
            for r in range(n):
                for c in range(m):
                    same += lengths[r, c] == t
            tied = same > 1
        c = col_of_row[i]
        col_of_row[i] = -1
        row_of_col[c] = -1
        if _rematch_below(i, lengths, t, needed, col_of_row, row_of_col, pred_row, queue, seen):
            continue
        col_of_row[i], row_of_col[c] = c, i
        needed[i] = True
        fixed += 1
        if np.isnan(bottleneck):
            bottleneck = t
            if not whole:
                break
    return col_of_row, bottleneck, tied
