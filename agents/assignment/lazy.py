"""Minimum-total-cost goal assignment on grid workspaces, with path costs computed on demand.

:func:`assign_on_grid` sends robots to goals on an occupancy grid so that the
sum of shortest obstacle-avoiding path costs is least. Two methods give the
same optimal total:

``"lazy"`` -- after "It Costs to Get Costs! A Heuristic-Based Scalable Goal
    Assignment Algorithm for Multi-Robot Systems": every pair starts with a
    lower bound on its path cost (the obstacle-free grid distance, or the
    Euclidean distance); the minimum-total assignment of the current costs is
    solved (SciPy's ``linear_sum_assignment``), the true costs of its pairs
    that still hold bounds are computed with each robot's resumable A*
    (:class:`~agents.assignment.pathcost.ResumableSearch`), and this repeats
    until every chosen pair's cost is true. The result is optimal: its total
    is exact, and every other assignment costs at least its total under the
    current costs (which never exceed the true ones). As in the paper, the
    assignment is kept between rounds with its dual prices (a shortest
    augmenting path Hungarian method): a pair whose cost rose loses its
    robot, and only those robots are matched again, so a round costs far less
    than a fresh solve; the rounds, searches included, run in one compiled
    call (:class:`~agents.assignment.pathcost.SearchPool` keeps every robot's
    search in arrays). (For more goals than robots each round is solved
    afresh by SciPy's ``linear_sum_assignment``.)
``"all-pairs"`` -- the baseline: Dijkstra from each robot until every goal is
    settled (compiled, on the same heap as the A*), then the Hungarian method on
    the full cost matrix.

Pairs in different free regions of the grid are known unreachable before any
search (no corner cutting makes reachability the axis-connected labelling); a
problem without a complete assignment is refused by name.
"""

from __future__ import annotations

import numpy as np
from numba import njit
from scipy.optimize import linear_sum_assignment

from .errors import AssignmentError
from .grid import HALF, Workspace
from .pathcost import UNREACHABLE, SearchMoves, SearchPool, SearchState, dijkstra_costs, pool_costs
from .result import AssignmentResult

#: Method names accepted by :func:`assign_on_grid`.
GRID_METHODS: tuple[str, ...] = ("lazy", "all-pairs")
#: Lower bounds the lazy method may start from.
LOWER_BOUNDS: tuple[str, ...] = ("octile", "euclidean")
#: Default memory for the lazy method's per-robot search states (bytes); beyond it the
#: least recently used robot's search is dropped (and restarted from scratch if needed again).
DEFAULT_SEARCH_MEMORY = 2 * 1024**3


class GridAssignmentResult(AssignmentResult):
    """An :class:`AssignmentResult` on a grid, with what the path searches cost.

    ``distances`` are path costs in grid units (1 per axis step, 1.5 per planar
    diagonal, 2 per 3-D diagonal).

    Extra attributes:
        pairs_computed: robot-goal pairs whose true path cost was established by
            a search (a query of a resumable A* for ``"lazy"``; every pair in a
            reachable region for ``"all-pairs"``).
        cells_expanded: grid cells expanded (settled) by all searches together.
        rounds: assignment problems solved (1 for ``"all-pairs"``).
    """

    __slots__ = ("pairs_computed", "cells_expanded", "rounds")

    def __init__(self, target_of: np.ndarray, distances: np.ndarray, method: str,
                 pairs_computed: int, cells_expanded: int, rounds: int) -> None:
        super().__init__(target_of, distances, method)
        self.pairs_computed = pairs_computed
        self.cells_expanded = cells_expanded
        self.rounds = rounds

    def __repr__(self) -> str:
        return (
            f"GridAssignmentResult(method={self.method!r}, total={self.total:.6g}, "
            f"pairs_computed={self.pairs_computed}, rounds={self.rounds})"
        )


def assign_on_grid(
    grid: object,
    robots: object,
    goals: object,
    method: str = "lazy",
    *,
    lower_bound: str = "octile",
    search_memory: int = DEFAULT_SEARCH_MEMORY,
) -> GridAssignmentResult:
    """Assign robots to goals on a grid, minimising the total shortest-path cost.

    Args:
        grid: boolean occupancy array, ``True`` = obstacle; 2-D (8-connected
            moves) or 3-D (26-connected), see :mod:`agents.assignment.grid`.
        robots: ``(n, d)`` integer cell indices of the robots (d = grid dimension).
        goals: ``(m, d)`` integer cell indices of the goals.
        method: ``"lazy"`` (true costs only where the assignment needs them) or
            ``"all-pairs"`` (Dijkstra from every robot, then the Hungarian method).
        lower_bound: for ``"lazy"``, the starting cost of unsearched pairs:
            ``"octile"`` (obstacle-free grid distance, the tighter bound) or
            ``"euclidean"`` (as in the paper).
        search_memory: for ``"lazy"``, bytes of search state kept across queries.

    When ``n <= m`` every robot gets a goal; otherwise every goal gets a robot
    and the others get ``-1``. Both methods return the same optimal total
    (the assignments themselves may differ between equally good ones).

    Raises:
        AssignmentError: a grid that is not a 2-D/3-D 0/1 array; a robot or goal
            that is not an integer cell, lies outside the grid or on an
            obstacle (named by index); a robot or goal walled off so that no
            complete assignment exists (named by index); an unknown method or
            lower bound.
    """
    if method not in GRID_METHODS:
        raise AssignmentError(f"unknown grid assignment method {method!r}; valid methods: {', '.join(GRID_METHODS)}")
    if lower_bound not in LOWER_BOUNDS:
        raise AssignmentError(f"unknown lower bound {lower_bound!r}; valid: {', '.join(LOWER_BOUNDS)}")
    workspace = Workspace(grid)
    robot_cells = workspace.cells(robots, "robots")
    goal_cells = workspace.cells(goals, "goals")
    n, m = len(robot_cells), len(goal_cells)
    if n == 0 or m == 0:
        return GridAssignmentResult(np.full(n, -1, dtype=np.int64), np.full(n, np.nan), method, 0, 0, 0)
    robot_flat = workspace.flat(robot_cells)
    goal_flat = workspace.flat(goal_cells)
    reachable = _check_regions(workspace, robot_cells, goal_cells, robot_flat, goal_flat)
    if method == "all-pairs":
        return _all_pairs(workspace, robot_flat, goal_flat, reachable)
    bounds = _lower_bounds(robot_cells, goal_cells, lower_bound)
    return _lazy(workspace, robot_flat, goal_flat, reachable, bounds, search_memory)


def _check_regions(workspace: Workspace, robot_cells: np.ndarray, goal_cells: np.ndarray,
                   robot_flat: np.ndarray, goal_flat: np.ndarray) -> np.ndarray:
    """``(n, m)`` same-region mask; raises unless a complete assignment exists.

    Within one free region every robot reaches every goal, so a complete
    assignment exists exactly when no region holds more robots than goals
    (when ``n <= m``) or more goals than robots (when ``n >= m``). A robot
    or goal that nothing can reach at all is named before any region that
    is merely short, since it is the likelier mistake.
    """
    labels = workspace.component.ravel()
    robot_region = labels[robot_flat]
    goal_region = labels[goal_flat]
    n, m = len(robot_flat), len(goal_flat)
    size = int(max(robot_region.max(), goal_region.max())) + 1
    robots_in = np.bincount(robot_region, minlength=size)
    goals_in = np.bincount(goal_region, minlength=size)
    sides = []  # (name, cells, regions, own count per region, other count per region, what it lacks)
    if n <= m:
        sides.append(("robot", robot_cells, robot_region, robots_in, goals_in, "goal"))
    if n >= m:
        sides.append(("goal", goal_cells, goal_region, goals_in, robots_in, "robot"))
    for name, cells, region, own, other, lacks in sides:
        alone = other[region] == 0
        if alone.any():
            i = int(np.argmax(alone))
            reach = f"reach any {lacks}" if name == "robot" else f"be reached by any {lacks}"
            raise AssignmentError(f"{name} {i} at cell {cells[i].tolist()} cannot {reach}: obstacles wall it off")
    for name, cells, region, own, other, lacks in sides:
        short = own[region] > other[region]
        if short.any():
            i = int(np.argmax(short))
            r = region[i]
            raise AssignmentError(
                f"{name} {i} at cell {cells[i].tolist()} cannot be given a {lacks}: obstacles wall off its "
                f"region, which holds {own[r]} {name}s but only {other[r]} {lacks}{'' if other[r] == 1 else 's'}"
            )
    return robot_region[:, None] == goal_region[None, :]


def _lower_bounds(robot_cells: np.ndarray, goal_cells: np.ndarray, kind: str) -> np.ndarray:
    """``(n, m)`` lower bounds on the path costs, in grid units."""
    return _bounds(robot_cells, goal_cells, kind == "euclidean")


@njit(cache=True, nogil=True)
def _bounds(robot_cells: np.ndarray, goal_cells: np.ndarray, euclidean: bool) -> np.ndarray:  # pragma: no cover
    """:func:`_lower_bounds`: the Euclidean distances, or the obstacle-free grid costs
    ((largest + sum of the coordinate differences) half units)."""
    n, m, ndim = robot_cells.shape[0], goal_cells.shape[0], robot_cells.shape[1]
    out = np.empty((n, m))
    for i in range(n):
        for j in range(m):
            total = 0
            largest = 0
            squares = 0
            for axis in range(ndim):
                d = abs(robot_cells[i, axis] - goal_cells[j, axis])
                total += d
                largest = max(largest, d)
                squares += d * d
            out[i, j] = np.sqrt(np.float64(squares)) if euclidean else (largest + total) * HALF
    return out


def _solve(costs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    return linear_sum_assignment(costs)


def _result(rows: np.ndarray, cols: np.ndarray, costs: np.ndarray, n: int, method: str,
            pairs: int, expanded: int, rounds: int) -> GridAssignmentResult:
    target_of = np.full(n, -1, dtype=np.int64)
    target_of[rows] = cols
    distances = np.full(n, np.nan)
    distances[rows] = costs[rows, cols]
    return GridAssignmentResult(target_of, distances, method, pairs, expanded, rounds)


def _all_pairs(workspace: Workspace, robot_flat: np.ndarray, goal_flat: np.ndarray,
               reachable: np.ndarray) -> GridAssignmentResult:
    """Dijkstra from every robot (stopping once all its goals are settled), then one assignment."""
    n = len(robot_flat)
    costs = np.full(reachable.shape, np.inf)
    expanded = 0
    for i in range(n):
        goals = np.flatnonzero(reachable[i])
        half, settled = dijkstra_costs(workspace, int(robot_flat[i]), goal_flat[goals])
        costs[i, goals] = half * HALF
        expanded += settled
    rows, cols = _solve(costs)
    return _result(rows, cols, costs, n, "all-pairs", int(reachable.sum()), expanded, 1)


def _lazy(workspace: Workspace, robot_flat: np.ndarray, goal_flat: np.ndarray, reachable: np.ndarray,
          bounds: np.ndarray, budget: int) -> GridAssignmentResult:
    """Solve on bounds, search the chosen pairs still on bounds, repeat until all chosen costs are true."""
    n = len(robot_flat)
    costs = np.where(reachable, bounds, np.inf)
    exact = ~reachable
    pool = SearchPool(workspace, robot_flat, budget)
    if costs.shape[0] == costs.shape[1]:
        cols, rounds, pairs, bad_robot, bad_goal = _lazy_square(costs, exact, goal_flat, pool.moves, pool.searches)
        if bad_robot == _NO_ASSIGNMENT:  # excluded by the region check
            raise AssignmentError("no complete assignment exists")
        rows = np.arange(n)
    else:
        pairs = rounds = 0
        bad_robot = _NONE
        while True:
            rows, cols = _solve(costs)
            rounds += 1
            pending = ~exact[rows, cols]
            if not pending.any():
                break
            rows_pending, cols_pending = rows[pending], cols[pending]
            halves = pool.costs_to(rows_pending, goal_flat[cols_pending])
            if (halves == UNREACHABLE).any():
                failed = int(np.argmax(halves == UNREACHABLE))
                bad_robot, bad_goal = int(rows_pending[failed]), int(cols_pending[failed])
                break
            costs[rows_pending, cols_pending] = halves * HALF
            exact[rows_pending, cols_pending] = True
            pairs += len(rows_pending)
    if bad_robot >= 0:  # cannot happen within one region; kept as a guard
        raise AssignmentError(f"goal {bad_goal} cannot be reached from robot {bad_robot}")
    return _result(rows, cols, costs, n, "lazy", int(pairs), pool.expanded, int(rounds))


#: ``_lazy_square``'s failure codes in place of a robot index.
_NONE = -1
_NO_ASSIGNMENT = -2


@njit(cache=True, nogil=True, inline="always")
def _settle_pairs(costs: np.ndarray, exact: np.ndarray, rows: np.ndarray, cols: np.ndarray, goal_flat: np.ndarray,
                  moves: SearchMoves, searches: SearchState) -> int:  # pragma: no cover - compiled
    """Search the true cost of each pair ``(rows[k], cols[k])`` in order and write it into ``costs``
    (marking it in ``exact``). Returns -1, or the first ``k`` whose goal cannot be reached."""
    goals = np.empty(rows.shape[0], dtype=np.int64)
    for k in range(rows.shape[0]):
        goals[k] = goal_flat[cols[k]]
    halves = pool_costs(moves, searches, rows, goals)
    for k in range(rows.shape[0]):
        if halves[k] < 0:
            return k
        costs[rows[k], cols[k]] = halves[k] * HALF
        exact[rows[k], cols[k]] = True
    return -1


@njit(cache=True, nogil=True)
def _lazy_square(costs: np.ndarray, exact: np.ndarray, goal_flat: np.ndarray, moves: SearchMoves,
                 searches: SearchState) -> tuple:  # pragma: no cover - compiled
    """The lazy rounds for as many goals as robots, in one compiled call.

    Each round matches the free robots (:func:`_augment_rows`, keeping the prices), searches
    the chosen pairs still on bounds in robot order and frees their robots. ``moves`` and
    ``searches``: a :class:`SearchPool`'s. Returns ``(goal of each robot, rounds,
    pairs searched, robot, goal)``: robot is ``_NONE``, or ``_NO_ASSIGNMENT`` when the
    matching fails, or the robot whose goal (the last field) cannot be reached.
    """
    n = costs.shape[0]
    u, v = np.zeros(n), np.zeros(n + 1)
    col_of_row = np.full(n, -1, dtype=np.int64)
    row_of_col = np.full(n + 1, -1, dtype=np.int64)
    free = np.arange(n)
    pending = np.empty(n, dtype=np.int64)
    rounds = pairs = 0
    while True:
        if not _augment_rows(costs, u, v, col_of_row, row_of_col, free):
            return col_of_row, rounds, pairs, _NO_ASSIGNMENT, -1
        rounds += 1
        count = 0
        for i in range(n):
            if not exact[i, col_of_row[i]]:
                pending[count] = i
                count += 1
        if count == 0:
            return col_of_row, rounds, pairs, _NONE, -1
        free = pending[:count].copy()
        cols = col_of_row[free]
        failed = _settle_pairs(costs, exact, free, cols, goal_flat, moves, searches)
        if failed >= 0:
            return col_of_row, rounds, pairs, free[failed], cols[failed]
        pairs += count
        # The costs only rose, so the prices stay feasible; the robots of the pairs that
        # are no longer tight are let go and matched again on the next round.
        row_of_col[cols] = -1
        col_of_row[free] = -1


@njit(cache=True, nogil=True, inline="always")
def _relax_row(row_costs: np.ndarray, base: float, v: np.ndarray, shortest: np.ndarray, came_from: np.ndarray,
               row: int) -> None:  # pragma: no cover - compiled
    """Lower ``shortest[j]`` to ``base + row_costs[j] - v[j]`` where that is shorter, noting
    ``row`` as where column ``j`` came from. Selects instead of branches: the loop vectorises."""
    for j in range(shortest.shape[0]):
        length = base + row_costs[j] - v[j]
        shorter = length < shortest[j]
        came_from[j] = row if shorter else came_from[j]
        shortest[j] = length if shorter else shortest[j]


@njit(cache=True, nogil=True, inline="always")
def _first_least(values: np.ndarray) -> int:  # pragma: no cover - compiled
    """Index of the first least of ``values`` (no NaN), -1 if all are ``inf``.

    The minimum is taken in four independent running minima (a single one would make
    each step wait for the previous comparison), then its first position is looked up.
    """
    n = values.shape[0]
    m0 = m1 = m2 = m3 = np.inf
    j = 0
    while j + 4 <= n:
        m0 = values[j] if values[j] < m0 else m0
        m1 = values[j + 1] if values[j + 1] < m1 else m1
        m2 = values[j + 2] if values[j + 2] < m2 else m2
        m3 = values[j + 3] if values[j + 3] < m3 else m3
        j += 4
    while j < n:
        m0 = values[j] if values[j] < m0 else m0
        j += 1
    least = min(min(m0, m1), min(m2, m3))
    if least == np.inf:
        return -1
    j = 0
    while values[j] != least:
        j += 1
    return j


@njit(cache=True, nogil=True)
def _augment_rows(costs: np.ndarray, u: np.ndarray, v: np.ndarray, col_of_row: np.ndarray,
                  row_of_col: np.ndarray, rows: np.ndarray) -> bool:  # pragma: no cover - compiled
    """Match each of ``rows`` (free) by a shortest augmenting path in the reduced costs
    ``costs[i, j] - u[i] - v[j]``, updating the prices so that every reduced cost stays
    non-negative and every matched pair's is zero: the matching stays a minimum-cost one for
    its rows. Square ``(n, n)`` costs, ``inf`` for forbidden pairs; ``v`` and ``row_of_col``
    have one extra slot (index n, left alone). False if some row cannot be matched.

    Dijkstra over the columns from the free row: ``shortest[j]`` is the length of the
    shortest alternating path to column ``j`` found so far. A settled column's price is
    parked at ``-inf`` during the search (so that no path reaches it again, without a
    branch in the scan), and every price is updated once the path to a free column is
    found, by how much shorter than that path each settled column was reached.
    """
    n = costs.shape[1]
    shortest = np.empty(n)
    came_from = np.empty(n, dtype=np.int64)  # the row before each column on its path
    order = np.empty(n, dtype=np.int64)  # the columns in the order they were settled
    length_of = np.empty(n)  # and the lengths of their paths
    price_of = np.empty(n)  # and their prices
    for start in rows:
        shortest[:] = np.inf
        reached = 0.0  # length of the path to the last settled column
        i = start
        settled = 0
        while True:
            base = reached - u[i]
            _relax_row(costs[i], base, v, shortest, came_from, i)
            nearest = _first_least(shortest)
            if nearest < 0:
                for k in range(settled):
                    v[order[k]] = price_of[k]
                return False
            reached = shortest[nearest]
            order[settled] = nearest
            length_of[settled] = reached
            price_of[settled] = v[nearest]
            settled += 1
            v[nearest] = -np.inf
            shortest[nearest] = np.inf
            if row_of_col[nearest] < 0:
                break
            i = row_of_col[nearest]
        u[start] += reached
        for k in range(settled):  # the sink (last) changes by nothing
            j = order[k]
            gain = reached - length_of[k]
            v[j] = price_of[k] - gain
            if k < settled - 1:
                u[row_of_col[j]] += gain
        j = order[settled - 1]
        while True:  # flip the path back to the start row
            i = came_from[j]
            row_of_col[j] = i
            j, col_of_row[i] = col_of_row[i], j
            if i == start:
                break
    return True
