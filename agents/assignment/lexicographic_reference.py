"""Three more exact lexicographic bottleneck (MMDR) algorithms, for comparison and cross-checks.

All follow "SCRAM: Scalable Collision-avoiding Role Assignment with
Minimal-makespan for Formational Positioning" and take a dense cost matrix
with ``rows <= cols`` (``inf`` = forbidden pair, and at least one complete
assignment must exist); they return the target index of every row.

- :func:`bitvector_assignment`: one sum-assignment problem whose pair weights
  are powers of two, ``2**r`` with ``r`` the position (in the list of all pairs
  sorted by length) of the first pair of the same length. Equal lengths share a
  weight and every weight exceeds the sum of all shorter pairs' weights, so the
  minimum-weight assignment is the lexicographic one. Python's arbitrary
  precision integers play the role of the paper's bit vectors. O(n^3)
  big-integer operations on numbers of up to n*m bits.
- :func:`subset_dp_assignment`: dynamic programming over subsets of targets
  (the best way to serve targets ``T`` with the first ``|T|`` robots is built
  from the best ways for ``T`` minus one target). O(n * m * 2^m); up to 20 targets.
- :func:`brute_force_assignment`: every injective map of rows to columns;
  up to 8! of them. The test oracle.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
from numba import njit

from .errors import AssignmentError

#: Largest number of targets :func:`subset_dp_assignment` accepts (memory ~ 2^m * n * 2 bytes).
DP_MAX_TARGETS = 20
#: Largest number of robot-target pairs :func:`bitvector_assignment` accepts. Its weights are
#: n*m integers of up to n*m bits, so memory grows as (n*m)^2 / 16 bytes: about 0.6 GB here.
BITVECTOR_MAX_PAIRS = 100_000
#: Largest number of complete assignments :func:`brute_force_assignment` enumerates (8!).
BRUTE_FORCE_MAX_ASSIGNMENTS = math.factorial(8)


def bitvector_assignment(costs: np.ndarray) -> np.ndarray:
    """Lexicographic bottleneck assignment via one exact power-of-two-weighted assignment."""
    n, m = costs.shape
    if n * m > BITVECTOR_MAX_PAIRS:
        raise AssignmentError(
            f"algorithm 'bitvector' handles at most {BITVECTOR_MAX_PAIRS:,} robot-target pairs "
            f"(its weights need about (n*m)^2/16 bytes), got {n} x {m}; use algorithm='fast'"
        )
    flat = costs.ravel()
    finite = np.flatnonzero(np.isfinite(flat))
    order = finite[np.argsort(flat[finite], kind="mergesort")]
    sorted_lengths = flat[order]
    # Position of the first pair of the same length, for every pair in sorted order.
    first_of_run = np.flatnonzero(np.r_[True, sorted_lengths[1:] != sorted_lengths[:-1]])
    run_id = np.cumsum(np.r_[True, sorted_lengths[1:] != sorted_lengths[:-1]]) - 1
    rank = np.full(n * m, -1, dtype=np.int64)
    rank[order] = first_of_run[run_id]
    forbidden_weight = 1 << (n * m + n.bit_length() + 1)
    weights = [
        [(1 << int(rank[i * m + j])) if rank[i * m + j] >= 0 else forbidden_weight for j in range(m)]
        for i in range(n)
    ]
    return _hungarian_python_ints(weights, n, m)


def _hungarian_python_ints(weights: list[list[int]], n: int, m: int) -> np.ndarray:
    """Minimum-weight assignment of every row (n <= m) by shortest augmenting paths, exact integers."""
    u = [0] * (n + 1)
    v = [0] * (m + 1)
    row_of = [0] * (m + 1)  # 1-based row matched to each column; column 0 is the virtual start
    way = [0] * (m + 1)
    for i in range(1, n + 1):
        row_of[0] = i
        j0 = 0
        minv: list[float | int] = [math.inf] * (m + 1)
        used = [False] * (m + 1)
        while True:
            used[j0] = True
            i0 = row_of[j0]
            row_weights = weights[i0 - 1]
            u_i0 = u[i0]
            delta: float | int = math.inf
            j1 = 0
            for j in range(1, m + 1):
                if not used[j]:
                    reduced = row_weights[j - 1] - u_i0 - v[j]
                    if reduced < minv[j]:
                        minv[j] = reduced
                        way[j] = j0
                    if minv[j] < delta:
                        delta = minv[j]
                        j1 = j
            for j in range(m + 1):
                if used[j]:
                    u[row_of[j]] += delta
                    v[j] -= delta
                else:
                    minv[j] -= delta
            j0 = j1
            if row_of[j0] == 0:
                break
        while j0:
            j1 = way[j0]
            row_of[j0] = row_of[j1]
            j0 = j1
    col_of_row = np.full(n, -1, dtype=np.int64)
    for j in range(1, m + 1):
        if row_of[j]:
            col_of_row[row_of[j] - 1] = j - 1
    return col_of_row


def subset_dp_assignment(costs: np.ndarray) -> np.ndarray:
    """Lexicographic bottleneck assignment by dynamic programming over subsets of targets."""
    n, m = costs.shape
    if m > DP_MAX_TARGETS:
        raise AssignmentError(
            f"algorithm 'dp' handles at most {DP_MAX_TARGETS} targets (2^m subsets), got {m}"
        )
    finite = np.isfinite(costs)
    ranks = np.zeros((n, m), dtype=np.int16)  # 0 = forbidden, 1.. = rank of the length (ascending)
    ranks[finite] = np.unique(costs[finite], return_inverse=True)[1].astype(np.int16) + 1
    return _subset_dp(ranks)


@njit(cache=True, nogil=True)
def _insert_compare(best: np.ndarray, prefix: np.ndarray, k: int, value: int) -> int:
    """Compare ``insert(value, prefix[:k-1])`` (both sorted descending) with ``best[:k]``: -1, 0 or 1."""
    i = 0  # index into prefix
    inserted = False
    for pos in range(k):
        if not inserted and (i >= k - 1 or value >= prefix[i]):
            x = value
            inserted = True
        else:
            x = prefix[i]
            i += 1
        if x != best[pos]:
            return -1 if x < best[pos] else 1
    return 0


@njit(cache=True, nogil=True)
def _subset_dp(ranks: np.ndarray) -> np.ndarray:
    n, m = ranks.shape
    n_states = 1 << m
    best = np.zeros((n_states, max(n, 1)), dtype=np.int16)
    feasible = np.zeros(n_states, dtype=np.bool_)
    choice = np.full(n_states, -1, dtype=np.int8)
    feasible[0] = True
    for state in range(1, n_states):
        k = 0
        s = state
        while s:
            s &= s - 1
            k += 1
        if k > n:
            continue
        row = k - 1
        for c in range(m):
            bit = 1 << c
            if not (state & bit) or ranks[row, c] == 0:
                continue
            previous = state ^ bit
            if not feasible[previous]:
                continue
            value = ranks[row, c]
            if feasible[state] and _insert_compare(best[state], best[previous], k, value) >= 0:
                continue
            # Store insert(value, best[previous]) as the new best for this state.
            i = 0
            inserted = False
            for pos in range(k):
                if not inserted and (i >= k - 1 or value >= best[previous, i]):
                    best[state, pos] = value
                    inserted = True
                else:
                    best[state, pos] = best[previous, i]
                    i += 1
            feasible[state] = True
            choice[state] = c
    # Best full state among those serving n targets.
    final = -1
    for state in range(n_states):
        if not feasible[state]:
            continue
        k = 0
        s = state
        while s:
            s &= s - 1
            k += 1
        if k != n:
            continue
        if final < 0:
            final = state
            continue
        for pos in range(n):
            if best[state, pos] != best[final, pos]:
                if best[state, pos] < best[final, pos]:
                    final = state
                break
    col_of_row = np.full(n, -1, dtype=np.int64)
    state = final
    for row in range(n - 1, -1, -1):
        c = choice[state]
        col_of_row[row] = c
        state ^= 1 << c
    return col_of_row


def all_injections(n: int, m: int) -> np.ndarray:
    """Every injective map of ``n`` rows into ``m`` columns, one per row of the result."""
    count = math.perm(m, n)
    if count > BRUTE_FORCE_MAX_ASSIGNMENTS:
        raise AssignmentError(
            f"brute force would enumerate {count} assignments; the limit is "
            f"{BRUTE_FORCE_MAX_ASSIGNMENTS} (8 robots and 8 targets)"
        )
    return np.array(list(itertools.permutations(range(m), n)), dtype=np.int64).reshape(count, n)


def brute_force_assignment(costs: np.ndarray) -> np.ndarray:
    """Lexicographic bottleneck assignment by enumerating every complete assignment."""
    n, m = costs.shape
    maps = all_injections(n, m)
    chosen = costs[np.arange(n), maps]  # (count, n)
    descending = -np.sort(-chosen, axis=1)
    # lexsort's last key is the primary one: the largest length, then the next...
    best = np.lexsort(descending.T[::-1])[0]
    return maps[best].copy()
