"""Shortest path costs on grid workspaces: full Dijkstra and a resumable A* per robot.

Both searches run compiled (numba) over the flat cell indices of a
:class:`~agents.assignment.grid.Workspace`'s padded grid, with a binary heap
of int64 keys and integer half-unit costs (exact, see
:mod:`agents.assignment.grid`).

* :func:`dijkstra_costs` settles cells from one source in order of distance
  until every requested target is settled (or the source's region is
  exhausted): the all-pairs baseline runs it once per robot.
* :class:`ResumableSearch` answers "cost from this robot to that goal" again
  and again for one robot, never repeating work: the forward resumable A* of
  "It Costs to Get Costs! A Heuristic-Based Scalable Goal Assignment Algorithm
  for Multi-Robot Systems" (after Silver's reverse resumable A*).

What the resumable search keeps between queries, and why the answers stay exact:

- ``g`` (cost of the best path found so far from the robot to every reached
  cell), the ``closed`` flags of the cells already expanded, and the open list
  (a heap of the reached but not expanded cells).
- The heuristic is ``h(c) = max_i |c_i - t_i| + sum_i |c_i - t_i|`` half units
  for goal ``t``: exactly the obstacle-free path cost on the grid (8- or
  26-connected with the costs above), hence admissible, and consistent
  because one move changes it by at most the move's cost (the maximum by at
  most 1, the sum by at most the number of coordinates moved; 1 + 1 = 2,
  1 + 2 = 3, 1 + 3 = 4 half units).
- With a consistent heuristic every expanded cell's ``g`` is its true
  distance from the robot, whichever goal the heuristic aimed at; the open
  list always holds every unexpanded neighbour of an expanded cell with the
  best ``g`` through expanded cells (a cell is expanded even when it is the
  goal, so this holds between queries). For a new goal the open list is
  re-keyed with the new heuristic (``f = g + h_new``) and the search simply
  continues: the standard A* argument (the first unexpanded cell on an
  optimal path to the popped cell has an exact ``g`` and no larger ``f``)
  only needs these two facts, not that the earlier expansions followed
  ``h_new``. A goal already expanded is answered at once from ``g``.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .grid import Workspace

#: Cost returned for a goal that cannot be reached (half units).
UNREACHABLE = -1
_G_BITS = 31
_G_MASK = (1 << _G_BITS) - 1


@njit(cache=True, nogil=True)
def _sift_down(keys, cells, start, size):
    """Restore the heap below position ``start`` (min-heap on ``keys``)."""
    pos = start
    key = keys[pos]
    cell = cells[pos]
    while True:
        child = 2 * pos + 1
        if child >= size:
            break
        if child + 1 < size and keys[child + 1] < keys[child]:
            child += 1
        if keys[child] >= key:
            break
        keys[pos] = keys[child]
        cells[pos] = cells[child]
        pos = child
    keys[pos] = key
    cells[pos] = cell


@njit(cache=True, nogil=True)
def _push(keys, cells, size, key, cell):
    """Push ``(key, cell)``; returns the (possibly grown) arrays and the new size."""
    if size == keys.shape[0]:
        bigger_keys = np.empty(2 * size + 16, dtype=np.int64)
        bigger_cells = np.empty(2 * size + 16, dtype=np.int64)
        bigger_keys[:size] = keys[:size]
        bigger_cells[:size] = cells[:size]
        keys = bigger_keys
        cells = bigger_cells
    pos = size
    while pos > 0:
        parent = (pos - 1) >> 1
        if keys[parent] <= key:
            break
        keys[pos] = keys[parent]
        cells[pos] = cells[parent]
        pos = parent
    keys[pos] = key
    cells[pos] = cell
    return keys, cells, size + 1


@njit(cache=True, nogil=True)
def _pop(keys, cells, size):
    """Remove the smallest entry; returns ``(key, cell, new size)``."""
    key = keys[0]
    cell = cells[0]
    size -= 1
    if size > 0:
        keys[0] = keys[size]
        cells[0] = cells[size]
        _sift_down(keys, cells, 0, size)
    return key, cell, size


@njit(cache=True, nogil=True)
def _heuristic(cell, goal, strides):
    """Obstacle-free grid distance in half units between flat cells ``cell`` and ``goal``."""
    total = 0
    largest = 0
    a = cell
    b = goal
    for axis in range(strides.shape[0]):
        s = strides[axis]
        qa = a // s
        qb = b // s
        a -= qa * s
        b -= qb * s
        d = abs(qa - qb)
        total += d
        if d > largest:
            largest = d
    return total + largest


@njit(cache=True, nogil=True)
def _dijkstra(allowed, offsets, costs, source, targets):
    """Half-unit distances from ``source`` to every flat cell in ``targets`` (-1 if unreachable).

    Stops as soon as every target is settled. Returns ``(distances, cells settled)``.
    """
    n = allowed.shape[0]
    dist = np.full(n, np.int64(-1))
    done = np.zeros(n, dtype=np.uint8)
    wanted = np.zeros(n, dtype=np.uint8)
    remaining = 0
    for t in targets:
        if wanted[t] == 0:
            wanted[t] = 1
            remaining += 1
    keys = np.empty(1024, dtype=np.int64)
    dummy = np.empty(1024, dtype=np.int64)
    dist[source] = 0
    keys, dummy, size = _push(keys, dummy, 0, np.int64(source), np.int64(0))
    settled = 0
    moves = offsets.shape[0]
    while size > 0 and remaining > 0:
        key, _unused, size = _pop(keys, dummy, size)
        cell = key & 0xFFFFFFFF
        d = key >> 32
        if done[cell]:
            continue
        done[cell] = 1
        settled += 1
        if wanted[cell]:
            remaining -= 1
        mask = allowed[cell]
        for m in range(moves):
            if (mask >> m) & 1:
                nb = cell + offsets[m]
                nd = d + costs[m]
                if done[nb] == 0 and (dist[nb] < 0 or nd < dist[nb]):
                    dist[nb] = nd
                    keys, dummy, size = _push(keys, dummy, size, (nd << 32) | nb, np.int64(0))
    out = np.empty(targets.shape[0], dtype=np.int64)
    for i in range(targets.shape[0]):
        out[i] = dist[targets[i]] if done[targets[i]] else -1
    return out, settled


@njit(cache=True, nogil=True)
def _rekey(keys, cells, size, g, closed, goal, strides):
    """Re-key the open list for a new goal: drop stale and duplicate entries, heapify. Returns the size."""
    kept = 0
    for i in range(size):
        cell = cells[i]
        entry_g = _G_MASK - (keys[i] & _G_MASK)
        if closed[cell] != 0 or entry_g != g[cell]:
            continue
        closed[cell] = 2  # temporary mark: this cell already has its one entry
        f = g[cell] + _heuristic(cell, goal, strides)
        keys[kept] = (f << _G_BITS) | (_G_MASK - g[cell])
        cells[kept] = cell
        kept += 1
    for i in range(kept):
        closed[cells[i]] = 0
    for start in range(kept // 2 - 1, -1, -1):
        _sift_down(keys, cells, start, kept)
    return kept


@njit(cache=True, nogil=True)
def _resume(allowed, offsets, costs, strides, g, closed, keys, cells, size, aim, goal):
    """Continue one robot's A* until ``goal`` is expanded.

    ``aim`` is the goal the open list's keys were computed for. Returns
    ``(cost in half units or -1, keys, cells, size, cells expanded)``.
    """
    if closed[goal]:
        return g[goal], keys, cells, size, 0
    if aim != goal:
        size = _rekey(keys, cells, size, g, closed, goal, strides)
    expanded = 0
    moves = offsets.shape[0]
    while size > 0:
        key, cell, size = _pop(keys, cells, size)
        if closed[cell]:
            continue
        gc = _G_MASK - (key & _G_MASK)
        if gc != g[cell]:
            continue
        closed[cell] = 1
        expanded += 1
        mask = allowed[cell]
        for m in range(moves):
            if (mask >> m) & 1:
                nb = cell + offsets[m]
                ng = gc + costs[m]
                if closed[nb] == 0 and (g[nb] < 0 or ng < g[nb]):
                    g[nb] = ng
                    f = ng + _heuristic(nb, goal, strides)
                    keys, cells, size = _push(keys, cells, size, (f << _G_BITS) | (_G_MASK - ng), nb)
        if cell == goal:
            return gc, keys, cells, size, expanded
    return -1, keys, cells, size, expanded


def dijkstra_costs(workspace: Workspace, source: int, targets: np.ndarray) -> tuple[np.ndarray, int]:
    """Half-unit path costs from flat padded cell ``source`` to each flat cell of ``targets``.

    Returns ``(costs, settled)``: int64 costs (``UNREACHABLE`` where no path
    exists) and the number of cells the search settled.
    """
    moves = workspace.moves
    out, settled = _dijkstra(moves.allowed, moves.offsets, moves.costs, np.int64(source),
                             np.ascontiguousarray(targets, dtype=np.int64))
    return out, int(settled)


class ResumableSearch:
    """One robot's forward resumable A*: path costs to goal after goal, no work repeated.

    ``cost_to(goal)`` returns the exact half-unit cost from the robot's cell to
    flat padded cell ``goal`` (``UNREACHABLE`` if none); see the module
    docstring for what is kept between calls and why the answers are exact.

    Attributes:
        expanded: cells expanded so far over all queries.
        nbytes: memory held by the search state (bytes).
    """

    def __init__(self, workspace: Workspace, source: int) -> None:
        self._workspace = workspace
        cells = workspace.moves.allowed.shape[0]
        self._g = np.full(cells, -1, dtype=np.int32)
        self._closed = np.zeros(cells, dtype=np.uint8)
        self._keys = np.empty(256, dtype=np.int64)
        self._cells = np.empty(256, dtype=np.int64)
        self._g[source] = 0
        self._keys[0] = _G_MASK  # f = 0, g = 0
        self._cells[0] = source
        self._size = 1
        self._aim = source
        self.expanded = 0

    @property
    def nbytes(self) -> int:
        return self._g.nbytes + self._closed.nbytes + self._keys.nbytes + self._cells.nbytes

    def cost_to(self, goal: int) -> int:
        """Exact half-unit path cost to flat padded cell ``goal`` (``UNREACHABLE`` if none)."""
        moves = self._workspace.moves
        cost, self._keys, self._cells, self._size, expanded = _resume(
            moves.allowed, moves.offsets, moves.costs, self._workspace.strides, self._g, self._closed,
            self._keys, self._cells, self._size, np.int64(self._aim), np.int64(goal),
        )
        self._aim = goal
        self.expanded += int(expanded)
        return int(cost)

    def known_costs(self, goals: np.ndarray) -> np.ndarray:
        """Half-unit costs to the flat cells ``goals`` already expanded, ``UNREACHABLE`` elsewhere."""
        return np.where(self._closed[goals] == 1, self._g[goals], UNREACHABLE)
