"""Shortest path costs on grid workspaces: full Dijkstra and a resumable A* per robot.

Both searches run compiled (numba) over the flat cell indices of a
:class:`~agents.assignment.grid.Workspace`'s padded grid, with integer
half-unit costs (exact, see :mod:`agents.assignment.grid`) and the same binary
heap: ``(int64 key, cell)`` pairs side by side in one int64 array.

* :func:`dijkstra_costs` settles cells from one source in order of distance
  until every requested target is settled (or the source's region is
  exhausted): the all-pairs baseline runs it once per robot.
* :class:`SearchPool` answers "cost from this robot to that goal" again and
  again for many robots, never repeating work: the forward resumable A* of
  "It Costs to Get Costs! A Heuristic-Based Scalable Goal Assignment Algorithm
  for Multi-Robot Systems" (after Silver's reverse resumable A*), one search per
  robot, a whole batch of queries in one compiled call (:func:`pool_costs`).
  :class:`ResumableSearch` is the search of one robot.

What the resumable search keeps between queries, and why the answers stay exact:

- One state per cell: 0 if not reached yet, ``g + 1`` if reached but not
  expanded, ``-(g + 1)`` if expanded, where ``g`` is the cost of the best path
  found so far from the robot (see :func:`state_dtype`); and the open list (a
  heap of the reached cells keyed by ``f`` then larger ``g``, with stale
  entries left behind when a cell's ``g`` improves).
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
  ``h_new``. A goal already expanded is answered at once from its state.
"""

from __future__ import annotations

import mmap
from typing import NamedTuple

import numpy as np
from numba import njit
from numba.typed import List

from .grid import Workspace

#: Cost returned for a goal that cannot be reached (half units).
UNREACHABLE = -1
_G_BITS = 31
_G_MASK = (1 << _G_BITS) - 1


@njit(cache=True, nogil=True)
def _sift_down(heap, start, size):
    """Restore the heap below entry ``start`` (a min-heap on the keys)."""
    pos = start
    key = heap[2 * pos]
    value = heap[2 * pos + 1]
    while True:
        child = 2 * pos + 1
        if child >= size:
            break
        if child + 1 < size and heap[2 * child + 2] < heap[2 * child]:
            child += 1
        if heap[2 * child] >= key:
            break
        heap[2 * pos] = heap[2 * child]
        heap[2 * pos + 1] = heap[2 * child + 1]
        pos = child
    heap[2 * pos] = key
    heap[2 * pos + 1] = value


@njit(cache=True, nogil=True)
def _grown(heap, size):
    """A copy of ``heap``'s ``size`` entries with room for as many again (and a few)."""
    bigger = np.empty(4 * size + 32, dtype=np.int64)
    bigger[:2 * size] = heap[:2 * size]
    return bigger


@njit(cache=True, nogil=True)
def _push(heap, size, key, value):
    """Add ``(key, value)`` to a heap with room for it; returns the new size.

    The caller makes the room (``heap = _grown(heap, size)`` when ``2 * size`` fills it):
    returning no array, the hot loops take and drop no references.
    """
    pos = size
    while pos > 0:
        parent = (pos - 1) >> 1
        if heap[2 * parent] <= key:
            break
        heap[2 * pos] = heap[2 * parent]
        heap[2 * pos + 1] = heap[2 * parent + 1]
        pos = parent
    heap[2 * pos] = key
    heap[2 * pos + 1] = value
    return size + 1


@njit(cache=True, nogil=True)
def _pop(heap, size):
    """Remove the entry of the smallest key; returns ``(key, value, new size)``."""
    key = heap[0]
    value = heap[1]
    size -= 1
    if size > 0:
        heap[0] = heap[2 * size]
        heap[1] = heap[2 * size + 1]
        _sift_down(heap, 0, size)
    return key, value, size


@njit(cache=True, nogil=True)
def _coordinates(cell, strides, out):
    """Write the coordinates in the padded grid of flat cell ``cell`` into ``out`` (one per axis)."""
    last = strides.shape[0] - 1
    for axis in range(last):
        q = cell // strides[axis]
        out[axis] = q
        cell -= q * strides[axis]
    out[last] = cell  # the last stride is 1


@njit(cache=True, nogil=True)
def _heuristic(cell, goal_at, strides):
    """Obstacle-free grid distance in half units from flat cell ``cell`` to the goal at coordinates ``goal_at``."""
    total = 0
    largest = 0
    last = strides.shape[0] - 1
    for axis in range(last + 1):
        if axis < last:
            q = cell // strides[axis]
            cell -= q * strides[axis]
        else:
            q = cell  # the last stride is 1
        d = abs(q - goal_at[axis])
        total += d
        if d > largest:
            largest = d
    return total + largest


#: What a search step returns when the open list may lack room for the next cell's moves.
_NEEDS_ROOM = -2


@njit(cache=True, nogil=True)
def _settle(allowed, offsets, costs, dist, done, wanted, heap, size, remaining):
    """Dijkstra's loop: settle cells until no wanted cell ``remains``, the heap empties, or
    it may lack room for the next cell's moves (then ``remaining`` comes back as is, with
    ``_NEEDS_ROOM`` as the first value). The heap is never reallocated here, so the loop
    takes no references. Returns ``(_NEEDS_ROOM or 0, size, remaining, cells settled)``.
    """
    settled = 0
    moves = offsets.shape[0]
    room = heap.shape[0] // 2 - moves
    while size > 0 and remaining > 0:
        if size > room:
            return _NEEDS_ROOM, size, remaining, settled
        key, cell, size = _pop(heap, size)
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
                    size = _push(heap, size, (nd << 32) | nb, nb)
    return 0, size, remaining, settled


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
    heap = np.empty(2048, dtype=np.int64)
    dist[source] = 0
    size = _push(heap, 0, np.int64(source), source)
    settled = 0
    while True:
        status, size, remaining, count = _settle(allowed, offsets, costs, dist, done, wanted, heap, size, remaining)
        settled += count
        if status != _NEEDS_ROOM:
            break
        heap = _grown(heap, size)
    out = np.empty(targets.shape[0], dtype=np.int64)
    for i in range(targets.shape[0]):
        out[i] = dist[targets[i]] if done[targets[i]] else -1
    return out, settled


@njit(cache=True, nogil=True)
def _rekey(heap, size, state, goal_at, strides):
    """Re-key the open list for the goal at ``goal_at``: drop stale entries, heapify. Returns the size.

    A cell is pushed only when its ``g`` strictly improves, so exactly one entry of an
    open cell carries its current ``g``: the kept entries are one per open cell.
    """
    kept = 0
    for i in range(size):
        cell = heap[2 * i + 1]
        g = _G_MASK - (heap[2 * i] & _G_MASK)
        if state[cell] != g + 1:  # expanded since, or a stale entry
            continue
        heap[2 * kept] = ((g + _heuristic(cell, goal_at, strides)) << _G_BITS) | (_G_MASK - g)
        heap[2 * kept + 1] = cell
        kept += 1
    for start in range(kept // 2 - 1, -1, -1):
        _sift_down(heap, start, kept)
    return kept


@njit(cache=True, nogil=True)
def _expand(allowed, offsets, costs, strides, state, heap, size, goal, goal_at):
    """A*'s loop: expand cells until ``goal`` is expanded, the open list empties, or the heap
    may lack room for the next cell's moves. The heap is never reallocated here, so the
    loop takes no references. Returns ``(cost in half units, -1 or _NEEDS_ROOM; size;
    cells expanded)``.
    """
    expanded = 0
    moves = offsets.shape[0]
    room = heap.shape[0] // 2 - moves
    while size > 0:
        if size > room:
            return _NEEDS_ROOM, size, expanded
        key, cell, size = _pop(heap, size)
        gc = _G_MASK - (key & _G_MASK)
        if state[cell] != gc + 1:  # expanded already, or a stale entry
            continue
        state[cell] = -(gc + 1)
        expanded += 1
        mask = allowed[cell]
        for m in range(moves):
            if (mask >> m) & 1:
                nb = cell + offsets[m]
                ng = gc + costs[m]
                reached = state[nb]
                if reached == 0 or ng + 1 < reached:  # never for an expanded cell (negative state)
                    state[nb] = ng + 1
                    f = ng + _heuristic(nb, goal_at, strides)
                    size = _push(heap, size, (f << _G_BITS) | (_G_MASK - ng), nb)
        if cell == goal:
            return gc, size, expanded
    return -1, size, expanded


@njit(cache=True, nogil=True, inline="always")
def _resume(allowed, offsets, costs, strides, state, heap, size, aim, goal, goal_at):
    """Continue one robot's A* until ``goal`` is expanded.

    ``state`` is the search's cell states and ``heap`` its open list (see the module
    docstring), ``aim`` the goal the open list's keys were computed for; ``goal_at`` is
    room for the goal's coordinates. Returns ``(cost in half units or -1, heap, size,
    cells expanded)``.
    """
    if state[goal] < 0:
        return -np.int64(state[goal]) - 1, heap, size, 0
    _coordinates(goal, strides, goal_at)
    if aim != goal:
        size = _rekey(heap, size, state, goal_at, strides)
    expanded = 0
    while True:
        cost, size, count = _expand(allowed, offsets, costs, strides, state, heap, size, goal, goal_at)
        expanded += count
        if cost != _NEEDS_ROOM:
            return cost, heap, size, expanded
        heap = _grown(heap, size)


def dijkstra_costs(workspace: Workspace, source: int, targets: np.ndarray) -> tuple[np.ndarray, int]:
    """Half-unit path costs from flat padded cell ``source`` to each flat cell of ``targets``.

    Returns ``(costs, settled)``: int64 costs (``UNREACHABLE`` where no path
    exists) and the number of cells the search settled.
    """
    moves = workspace.moves
    out, settled = _dijkstra(moves.allowed, moves.offsets, moves.costs, np.int64(source),
                             np.ascontiguousarray(targets, dtype=np.int64))
    return out, int(settled)


class SearchMoves(NamedTuple):
    """A workspace's moves as the searches take them: which moves each flat cell allows, the
    flat offset and half-unit cost of each move, and the grid's strides
    (:class:`~agents.assignment.grid.Moves`, :attr:`~agents.assignment.grid.Workspace.strides`)."""

    allowed: np.ndarray
    offsets: np.ndarray
    costs: np.ndarray
    strides: np.ndarray


class SearchState(NamedTuple):
    """The state of a :class:`SearchPool`'s searches, as compiled code takes it."""

    states: np.ndarray
    """(rows, cells) the cell states of the live searches, one row each."""
    heaps: object
    """A typed list of each robot's open list (int64 key and cell pairs)."""
    record: np.ndarray
    """(robots, 4) per robot its open-list size, the goal its keys aim at, its last use and its
    row (-1 when not live): columns ``_SIZE``, ``_AIM``, ``_LAST_USE``, ``_SLOT``."""
    totals: np.ndarray
    """(5,) bytes held, cells expanded, queries, live searches, free rows (``_BYTES`` ...)."""
    free_slots: np.ndarray
    """The stack of free rows."""
    dirty: np.ndarray
    """(rows,) uint8 which rows were used before (cleared before reuse)."""
    sources: np.ndarray
    """(robots,) each robot's flat cell."""
    budget: int
    """Bytes of search state past which the least recently used searches are dropped."""


# Columns of a pool's per-robot record, and entries of its totals.
_SIZE, _AIM, _LAST_USE, _SLOT = 0, 1, 2, 3
_BYTES, _EXPANDED, _CLOCK, _LIVE_COUNT, _FREE_SLOTS = 0, 1, 2, 3, 4
#: Entries a new search's open list has room for.
_FIRST_HEAP = 256


@njit(cache=True, nogil=True)
def _empty_heaps(n):
    """A typed list of ``n`` empty open lists."""
    heaps = List()
    for _ in range(n):
        heaps.append(np.empty(0, dtype=np.int64))
    return heaps


@njit(cache=True, nogil=True)
def _held(searches, robot):
    """Bytes held by ``robot``'s (live) search: its row of cell states and its open list."""
    return searches.states.shape[1] * searches.states.itemsize + searches.heaps[robot].nbytes


@njit(cache=True, nogil=True)
def _drop(searches, robot):
    """Free ``robot``'s search state; its row of cell states goes back to the free rows."""
    heaps, record, totals, free_slots = searches.heaps, searches.record, searches.totals, searches.free_slots
    totals[_BYTES] -= _held(searches, robot)
    heaps[robot] = np.empty(0, dtype=np.int64)
    free_slots[totals[_FREE_SLOTS]] = record[robot, _SLOT]
    totals[_FREE_SLOTS] += 1
    record[robot, _SLOT] = -1
    totals[_LIVE_COUNT] -= 1


@njit(cache=True, nogil=True)
def _drop_oldest(searches):
    """Drop the least recently used live search."""
    record = searches.record
    oldest = -1
    for other in range(record.shape[0]):
        if record[other, _SLOT] >= 0 and (oldest < 0 or record[other, _LAST_USE] < record[oldest, _LAST_USE]):
            oldest = other
    _drop(searches, oldest)


@njit(cache=True, nogil=True)
def _start(searches, robot):
    """Start ``robot``'s search in a free row (dropping the least recently used search when
    none is free: the pool would be over its budget after this query and drop it then)."""
    states, heaps, record, totals = searches.states, searches.heaps, searches.record, searches.totals
    free_slots, dirty, sources = searches.free_slots, searches.dirty, searches.sources
    if totals[_FREE_SLOTS] == 0:
        _drop_oldest(searches)
    totals[_FREE_SLOTS] -= 1
    slot = free_slots[totals[_FREE_SLOTS]]
    if dirty[slot]:
        states[slot, :] = 0
    dirty[slot] = 1
    source = sources[robot]
    states[slot, source] = 1  # reached with g = 0
    heap = np.empty(2 * _FIRST_HEAP, dtype=np.int64)
    heap[0] = _G_MASK  # f = 0, g = 0
    heap[1] = source
    heaps[robot] = heap
    record[robot, _SIZE] = 1
    record[robot, _AIM] = source
    record[robot, _SLOT] = slot
    totals[_LIVE_COUNT] += 1
    totals[_BYTES] += _held(searches, robot)


@njit(cache=True, nogil=True, inline="always")
def pool_costs(moves, searches, robots, goals):
    """Exact half-unit costs (or -1) from each of ``robots`` to the flat cell of ``goals`` at the
    same place, by each robot's resumable A*, queried in order.

    ``moves`` and ``searches`` are a :class:`SearchPool`'s :class:`SearchMoves` and :class:`SearchState`: compiled
    code that holds them calls this directly. A robot's search starts on first use; after
    each query the least recently used searches are dropped while the pool holds more than
    its budget (never the last one).
    """
    allowed, offsets, step_costs, strides = moves.allowed, moves.offsets, moves.costs, moves.strides
    states, heaps, record, totals, budget = (searches.states, searches.heaps, searches.record, searches.totals,
                                             searches.budget)
    out = np.empty(robots.shape[0], dtype=np.int64)
    goal_at = np.empty(strides.shape[0], dtype=np.int64)
    for k in range(robots.shape[0]):
        robot, goal = robots[k], goals[k]
        if record[robot, _SLOT] < 0:
            _start(searches, robot)
        heap = heaps[robot]
        held = heap.nbytes
        out[k], heap, size, expanded = _resume(allowed, offsets, step_costs, strides, states[record[robot, _SLOT]],
                                               heap, record[robot, _SIZE], record[robot, _AIM], goal, goal_at)
        if heap.nbytes != held:  # the open list grew
            heaps[robot] = heap
            totals[_BYTES] += heap.nbytes - held
        record[robot, _SIZE] = size
        record[robot, _AIM] = goal
        record[robot, _LAST_USE] = totals[_CLOCK]
        totals[_CLOCK] += 1
        totals[_EXPANDED] += expanded
        while totals[_BYTES] > budget and totals[_LIVE_COUNT] > 1:
            _drop_oldest(searches)
    return out


@njit(cache=True, nogil=True)
def _pool_costs(moves, searches, robots, goals):
    """:func:`pool_costs` called from Python (it is inlined into its compiled callers)."""
    return pool_costs(moves, searches, robots, goals)


#: Largest block of cell states taken from the C allocator (bytes); larger ones are mapped directly.
_ALLOCATED_BLOCK = 32 * 1024**2


@njit(cache=True, nogil=True)
def _allocated_zeros(rows, cells, like):
    """A zeroed ``(rows, cells)`` block of ``like``'s dtype from the C allocator."""
    return np.zeros((rows, cells), dtype=like.dtype)


def _zeroed_rows(rows: int, cells: int, dtype: np.dtype) -> np.ndarray:
    """A zeroed ``(rows, cells)`` block of ``dtype`` for the cell states of a :class:`SearchPool`.

    Blocks up to ``_ALLOCATED_BLOCK`` come from the C allocator, which (on glibc) keeps
    such blocks' memory for the next call: cleared in place, no page is faulted in again.
    Larger blocks are always fresh memory there, so they are mapped from the operating
    system directly: zero pages handed out as the searches first touch them, which are
    few of a large grid's cells. (Not through numpy, which asks for huge pages on large
    arrays: their compaction can stall for long on a fragmented memory.)
    """
    size = rows * cells * dtype.itemsize
    if size <= _ALLOCATED_BLOCK:
        return _allocated_zeros(rows, cells, np.empty(0, dtype=dtype))
    return np.frombuffer(mmap.mmap(-1, size), dtype=dtype).reshape(rows, cells)


def state_dtype(workspace: Workspace) -> np.dtype:
    """The narrowest signed integer type that holds every cell state of a search on ``workspace``.

    A state is at most ``g + 1`` in magnitude. An expanded cell's ``g`` is its distance, at
    most the dearest move times the free cells less one (a shortest path visits no cell
    twice), and a reached cell's ``g`` is an expanded neighbour's plus one move: so ``g``
    is at most the dearest move times the free cells. int16 for small grids (a 100 x 100
    grid needs 3 * 10000 + 1 < 2**15), int32 beyond: half the bytes for the states that
    every robot's search keeps.
    """
    free = int(np.count_nonzero(~workspace.blocked))
    largest = int(workspace.moves.costs.max()) * free + 1
    return np.dtype(np.int16) if largest <= np.iinfo(np.int16).max else np.dtype(np.int32)


class SearchPool:
    """The resumable A* searches of many robots on one workspace, within a memory budget.

    Each robot's search (see the module docstring) is created on its first query and
    kept; past ``budget`` bytes of search state the least recently used searches are
    dropped (a dropped robot's search starts afresh if queried again). The state lives
    in arrays and a typed list, so compiled code can run many queries in one call:
    ``moves`` and ``searches`` are the arguments of :func:`pool_costs`.

    The cell states of the live searches are rows of one zeroed block (of
    :func:`state_dtype`), as many rows as the budget allows searches at once (at most
    one per robot), instead of every search allocating and clearing a grid of its own.

    Attributes:
        moves: the workspace's :class:`SearchMoves`.
        searches: the :class:`SearchState` of the searches.
    """

    def __init__(self, workspace: Workspace, sources: np.ndarray, budget: int) -> None:
        moves = workspace.moves
        self.moves = SearchMoves(allowed=moves.allowed, offsets=moves.offsets, costs=moves.costs,
                                 strides=workspace.strides)
        sources = np.ascontiguousarray(sources, dtype=np.int64)
        n = len(sources)
        cells = moves.allowed.shape[0]
        budget = min(budget, 2**62)
        dtype = state_dtype(workspace)
        rows = max(1, min(n, budget // (cells * dtype.itemsize)))
        record = np.zeros((n, 4), dtype=np.int64)
        record[:, _SLOT] = -1
        totals = np.zeros(5, dtype=np.int64)
        totals[_FREE_SLOTS] = rows
        self.searches = SearchState(states=_zeroed_rows(rows, cells, dtype), heaps=_empty_heaps(n), record=record,
                                    totals=totals, free_slots=np.arange(rows - 1, -1, -1, dtype=np.int64),
                                    dirty=np.zeros(rows, dtype=np.uint8), sources=sources, budget=np.int64(budget))

    def costs_to(self, robots: np.ndarray, goals: np.ndarray) -> np.ndarray:
        """Half-unit costs from each of ``robots`` (indices) to the flat cell ``goals`` at the same
        place (``UNREACHABLE`` if none), queried in order."""
        return _pool_costs(self.moves, self.searches, np.ascontiguousarray(robots, dtype=np.int64),
                           np.ascontiguousarray(goals, dtype=np.int64))

    @property
    def expanded(self) -> int:
        """Cells expanded by all queries so far (a restarted search counts its cells again)."""
        return int(self.searches.totals[_EXPANDED])

    @property
    def nbytes(self) -> int:
        """Memory held by the live searches (bytes): their rows of cell states and open lists."""
        return int(self.searches.totals[_BYTES])

    @property
    def live(self) -> int:
        """Searches kept (not dropped, or started again since)."""
        return int(self.searches.totals[_LIVE_COUNT])

    def known_costs(self, robot: int, goals: np.ndarray) -> np.ndarray:
        """Half-unit costs from ``robot`` to the flat cells ``goals`` its search has already
        expanded, ``UNREACHABLE`` elsewhere (and everywhere if its search is not live)."""
        slot = self.searches.record[robot, _SLOT]
        if slot < 0:
            return np.full(len(goals), UNREACHABLE, dtype=np.int64)
        reached = self.searches.states[slot, goals].astype(np.int64)
        return np.where(reached < 0, -reached - 1, UNREACHABLE)


class ResumableSearch:
    """One robot's forward resumable A*: path costs to goal after goal, no work repeated.

    ``cost_to(goal)`` returns the exact half-unit cost from the robot's cell to
    flat padded cell ``goal`` (``UNREACHABLE`` if none); see the module
    docstring for what is kept between calls and why the answers are exact.
    A :class:`SearchPool` of one robot with no memory limit.
    """

    def __init__(self, workspace: Workspace, source: int) -> None:
        self._pool = SearchPool(workspace, np.array([source]), 2**62)

    @property
    def expanded(self) -> int:
        """Cells expanded so far over all queries."""
        return self._pool.expanded

    @property
    def nbytes(self) -> int:
        """Memory held by the search state (bytes)."""
        return self._pool.nbytes

    def cost_to(self, goal: int) -> int:
        """Exact half-unit path cost to flat padded cell ``goal`` (``UNREACHABLE`` if none)."""
        return int(self._pool.costs_to(np.zeros(1, dtype=np.int64), np.array([goal]))[0])

    def known_costs(self, goals: np.ndarray) -> np.ndarray:
        """Half-unit costs to the flat cells ``goals`` already expanded, ``UNREACHABLE`` elsewhere."""
        return self._pool.known_costs(0, goals)
