"""Exact lexicographic bottleneck assignment (SCRAM's MMDR), polynomial and fast.

Problem: among complete assignments, find one whose pair lengths, sorted in
decreasing order, form the lexicographically smallest tuple. Equivalently,
with the distinct lengths ``l_1 > l_2 > ...``, minimise the number of pairs of
length ``l_1``, then of length ``l_2`` among those, and so on.

Method (after "Lexicographic bottleneck combinatorial problems", Sokkalingam
and Aneja, and the MMDR section of "SCRAM: Scalable Collision-avoiding Role
Assignment with Minimal-makespan for Formational Positioning"): start from the
pairs no longer than the bottleneck and a perfect matching ``M`` in them, then
visit the lengths from the longest down. For each length ``l`` the current
graph's perfect matchings are exactly the assignments that are optimal for all
longer lengths, and we shrink it to those that also use the fewest pairs of
length ``l``:

1. If ``M`` uses no pair of length ``l``, none is needed: delete them all.
2. Otherwise delete them and try to repair ``M`` with augmenting paths over the
   remaining pairs. If every robot is matched again, none is needed either.
3. If some robots stay unmatched and the length-``l`` pairs that ``M`` used are
   the only ones left, every optimal assignment uses all of them: fix them.
4. Otherwise (ties) solve the 0/1 assignment problem "cost 1 for a pair of
   length ``l``, 0 for the others" by shortest augmenting paths started from
   the repaired partial matching, then keep only the pairs that are tight for
   the resulting optimal dual potentials. By linear-programming complementary
   slackness the perfect matchings of the tight pairs are exactly the optimal
   ones, so the graph now encodes "minimal number of length-``l`` pairs".

Cases 1-3 cost one augmenting-path search per matched pair visited; with
distinct lengths (real-valued positions) case 4 never happens, and with
integer grids it stays rare for long lengths. Integer potentials make the
tightness test exact.
"""

from __future__ import annotations

import heapq
from typing import NamedTuple

import numpy as np
from numba import njit

from .graphs import edge_rows

_INF_INT = np.iinfo(np.int64).max // 4


@njit(cache=True, nogil=True)
def _flip_path(
    end_col: int,
    start: int,
    pred_edge: np.ndarray,
    rows_of_edge: np.ndarray,
    col_of_row: np.ndarray,
    edge_of_row: np.ndarray,
    row_of_col: np.ndarray,
) -> None:
    """Augment along the path found by a search from free row ``start`` to free target ``end_col``.

    ``pred_edge[c]`` is the pair by which the search reached target ``c``;
    walking back from ``end_col``, every row on the path takes that target.
    """
    c = end_col
    while True:
        e_in = pred_edge[c]
        row = rows_of_edge[e_in]
        previous = col_of_row[row]
        col_of_row[row] = c
        edge_of_row[row] = e_in
        row_of_col[c] = row
        if row == start:
            return
        c = previous


class PairGraph(NamedTuple):
    """The candidate pairs as CSR lists: row r's pairs are ``indptr[r]:indptr[r + 1]``, each
    pair's column in ``indices`` and its row in ``rows_of_edge``."""

    indptr: np.ndarray
    indices: np.ndarray
    rows_of_edge: np.ndarray


class Matching(NamedTuple):
    """A matching: each row's column and pair (-1 unmatched), each column's row (-1 unmatched)."""

    col_of_row: np.ndarray
    edge_of_row: np.ndarray
    row_of_col: np.ndarray


class PathScratch(NamedTuple):
    """Scratch of the augmenting-path search: each column's last visit stamp and the pair it was
    reached by, and the queue of rows."""

    col_seen: np.ndarray
    pred_edge: np.ndarray
    queue: np.ndarray


@njit(cache=True, nogil=True)
def _repair(start: int, graph: PairGraph, alive: np.ndarray, fixed_col: np.ndarray, matching: Matching,
            scratch: PathScratch, stamp: int) -> bool:
    """Breadth-first augmenting path from free row ``start`` over alive pairs not into a fixed
    column; flip it in ``matching`` if found (columns visited are stamped ``stamp``)."""
    indptr, indices, rows_of_edge = graph.indptr, graph.indices, graph.rows_of_edge
    col_of_row, edge_of_row, row_of_col = matching.col_of_row, matching.edge_of_row, matching.row_of_col
    col_seen, pred_edge, queue = scratch.col_seen, scratch.pred_edge, scratch.queue
    head = 0
    tail = 1
    queue[0] = start
    while head < tail:
        r = queue[head]
        head += 1
        for e in range(indptr[r], indptr[r + 1]):
            if not alive[e]:
                continue
            c = indices[e]
            if fixed_col[c] or col_seen[c] == stamp:
                continue
            col_seen[c] = stamp
            pred_edge[c] = e
            r2 = row_of_col[c]
            if r2 < 0:
                _flip_path(c, start, pred_edge, rows_of_edge, col_of_row, edge_of_row, row_of_col)
                return True
            queue[tail] = r2
            tail += 1
    return False


@njit(cache=True, nogil=True)
def _min_count_matching(
    level: float,
    indptr: np.ndarray,
    indices: np.ndarray,
    lengths: np.ndarray,
    rows_of_edge: np.ndarray,
    alive: np.ndarray,
    fixed_row: np.ndarray,
    fixed_col: np.ndarray,
    col_of_row: np.ndarray,
    edge_of_row: np.ndarray,
    row_of_col: np.ndarray,
) -> None:
    """Case 4: complete the matching with fewest pairs of length ``level``; keep tight pairs only.

    Costs are 1 for pairs of length ``level`` and 0 otherwise; the current
    partial matching must use only cost-0 pairs (so zero potentials are
    feasible dual values for it). Rows are added one by one along shortest
    augmenting paths (Dijkstra on reduced costs), which keeps the potentials
    ``u`` (rows) and ``v`` (targets) dual feasible with every matched pair tight.
    """
    n_rows = indptr.shape[0] - 1
    n_cols = row_of_col.shape[0]
    u = np.zeros(n_rows, dtype=np.int64)
    v = np.zeros(n_cols, dtype=np.int64)
    dist = np.empty(n_cols, dtype=np.int64)
    seen = np.zeros(n_cols, dtype=np.int64)
    done = np.zeros(n_cols, dtype=np.int64)
    pred_edge = np.empty(n_cols, dtype=np.int64)
    settled = np.empty(n_cols, dtype=np.int64)
    stamp = 0
    for start in range(n_rows):
        if fixed_row[start] or col_of_row[start] >= 0:
            continue
        stamp += 1
        heap = [(np.int64(0), np.int64(0))]
        heap.pop()
        n_settled = 0
        row = start
        base = np.int64(0)
        final = -1
        final_dist = np.int64(0)
        while True:
            for e in range(indptr[row], indptr[row + 1]):
                if not alive[e]:
                    continue
                c = indices[e]
                if fixed_col[c] or done[c] == stamp:
                    continue
                cost = np.int64(1) if lengths[e] == level else np.int64(0)
                candidate = base + cost - u[row] - v[c]
                if seen[c] != stamp or candidate < dist[c]:
                    seen[c] = stamp
                    dist[c] = candidate
                    pred_edge[c] = e
                    heapq.heappush(heap, (candidate, c))
            found_next = False
            while len(heap) > 0:
                d, c = heapq.heappop(heap)
                if done[c] == stamp or d > dist[c]:
                    continue
                done[c] = stamp
                settled[n_settled] = c
                n_settled += 1
                if row_of_col[c] < 0:
                    final = c
                    final_dist = d
                else:
                    row = row_of_col[c]
                    base = d
                found_next = True
                break
            if not found_next or final >= 0:
                break
        if final < 0:
            raise RuntimeError("lexicographic bottleneck: lost the perfect matching (internal error)")
        # Dual update: settled targets move by (final_dist - dist), and so do their rows.
        for k in range(n_settled):
            c = settled[k]
            delta = final_dist - dist[c]
            v[c] -= delta
            if c != final:
                u[row_of_col[c]] += delta
        u[start] += final_dist
        _flip_path(final, start, pred_edge, rows_of_edge, col_of_row, edge_of_row, row_of_col)
    # Keep only tight pairs: their perfect matchings are exactly the optimal ones.
    for e in range(alive.shape[0]):
        if alive[e]:
            r = rows_of_edge[e]
            c = indices[e]
            if fixed_row[r] or fixed_col[c]:
                continue
            cost = np.int64(1) if lengths[e] == level else np.int64(0)
            if cost - u[r] - v[c] != 0:
                alive[e] = False


@njit(cache=True, nogil=True)
def lexicographic_refine(
    indptr: np.ndarray,
    indices: np.ndarray,
    lengths: np.ndarray,
    threshold: float,
    col_of_row: np.ndarray,
    row_of_col: np.ndarray,
) -> None:
    """Turn a perfect matching into a lexicographic bottleneck one, in place.

    The graph must be square (square up rectangular problems with
    :func:`.graphs.square_up`, padding length ``-inf``), ``col_of_row``/``row_of_col`` a perfect matching using
    pairs no longer than ``threshold`` (normally the bottleneck value); only
    those pairs are considered. Lengths of ``-inf`` are never refined.
    """
    n_rows = indptr.shape[0] - 1
    n_cols = row_of_col.shape[0]
    n_edges = indices.shape[0]
    rows_of_edge = edge_rows(indptr)
    alive = lengths <= threshold
    edge_of_row = np.empty(n_rows, dtype=np.int64)
    for r in range(n_rows):
        c = col_of_row[r]
        for e in range(indptr[r], indptr[r + 1]):
            if indices[e] == c and alive[e]:
                edge_of_row[r] = e
                break
    fixed_row = np.zeros(n_rows, dtype=np.bool_)
    fixed_col = np.zeros(n_cols, dtype=np.bool_)
    col_seen = np.zeros(n_cols, dtype=np.int64)
    pred_edge = np.empty(n_cols, dtype=np.int64)
    queue = np.empty(n_rows, dtype=np.int64)
    group = np.empty(n_edges, dtype=np.int64)
    freed = np.empty(n_rows, dtype=np.int64)
    graph = PairGraph(indptr, indices, rows_of_edge)
    matching = Matching(col_of_row, edge_of_row, row_of_col)
    scratch = PathScratch(col_seen, pred_edge, queue)
    stamp = 0
    n_fixed = 0
    order = np.argsort(-lengths, kind="mergesort")
    position = 0
    while position < n_edges and n_fixed < n_rows:
        level = lengths[order[position]]
        end = position
        while end < n_edges and lengths[order[end]] == level:
            end += 1
        if level == -np.inf:
            break
        # Live pairs of this length, and those the current matching uses.
        n_group = 0
        n_freed = 0
        for k in range(position, end):
            e = order[k]
            if not alive[e]:
                continue
            r = rows_of_edge[e]
            if fixed_row[r] or fixed_col[indices[e]]:
                continue
            group[n_group] = e
            n_group += 1
            alive[e] = False
            if edge_of_row[r] == e:
                freed[n_freed] = r
                n_freed += 1
        position = end
        if n_freed == 0:
            continue  # case 1
        for k in range(n_freed):
            r = freed[k]
            row_of_col[col_of_row[r]] = -1
            col_of_row[r] = -1
        unmatched = 0
        for k in range(n_freed):
            stamp += 1
            if not _repair(freed[k], graph, alive, fixed_col, matching, scratch, stamp):
                unmatched += 1
        if unmatched == 0:
            continue  # case 2
        for k in range(n_group):
            alive[group[k]] = True
        if unmatched == n_freed and n_freed == n_group:
            # Case 3: the matching was untouched; all its pairs of this length are forced.
            for k in range(n_group):
                e = group[k]
                r = rows_of_edge[e]
                c = indices[e]
                col_of_row[r] = c
                row_of_col[c] = r
                edge_of_row[r] = e
                fixed_row[r] = True
                fixed_col[c] = True
                n_fixed += 1
            continue
        _min_count_matching(
            level, indptr, indices, lengths, rows_of_edge, alive, fixed_row, fixed_col,
            col_of_row, edge_of_row, row_of_col,
        )
