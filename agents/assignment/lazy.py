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
    than a fresh solve. (For more goals than robots each round is solved
    afresh by SciPy's ``linear_sum_assignment``.)
``"all-pairs"`` -- the baseline: Dijkstra from each robot until every goal is
    settled, then the Hungarian method on the full cost matrix.

Pairs in different free regions of the grid are known unreachable before any
search (no corner cutting makes reachability the axis-connected labelling); a
problem without a complete assignment is refused by name.
"""

from __future__ import annotations

from collections import OrderedDict

import numpy as np
from numba import njit
from scipy.optimize import linear_sum_assignment

from .errors import AssignmentError
from .grid import HALF, Workspace
from .pathcost import UNREACHABLE, ResumableSearch, dijkstra_costs
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
    diff = np.abs(robot_cells[:, None, :] - goal_cells[None, :, :]).astype(np.float64)
    if kind == "euclidean":
        return np.sqrt((diff * diff).sum(axis=2))
    # Obstacle-free cost of the 8/26-connected grid: (max + sum) half units.
    return (diff.max(axis=2) + diff.sum(axis=2)) * HALF


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


class _Searches:
    """The robots' resumable searches, created on first use, least recently used dropped past a memory budget."""

    def __init__(self, workspace: Workspace, robot_flat: np.ndarray, budget: int) -> None:
        self._workspace = workspace
        self._robot_flat = robot_flat
        self._budget = budget
        self._live: OrderedDict[int, ResumableSearch] = OrderedDict()
        self._bytes = 0
        self.expanded = 0

    def cost(self, robot: int, goal_cell: int) -> int:
        search = self._live.get(robot)
        if search is None:
            search = ResumableSearch(self._workspace, int(self._robot_flat[robot]))
            self._live[robot] = search
        else:
            self._live.move_to_end(robot)
            self._bytes -= search.nbytes
        before = search.expanded
        half = search.cost_to(goal_cell)
        self.expanded += search.expanded - before
        self._bytes += search.nbytes
        while self._bytes > self._budget and len(self._live) > 1:
            _, dropped = self._live.popitem(last=False)
            self._bytes -= dropped.nbytes
        return half


def _lazy(workspace: Workspace, robot_flat: np.ndarray, goal_flat: np.ndarray, reachable: np.ndarray,
          bounds: np.ndarray, budget: int) -> GridAssignmentResult:
    """Solve on bounds, search the chosen pairs still on bounds, repeat until all chosen costs are true."""
    n = len(robot_flat)
    costs = np.where(reachable, bounds, np.inf)
    exact = ~reachable
    searches = _Searches(workspace, robot_flat, budget)
    pairs = 0
    rounds = 0
    square = costs.shape[0] == costs.shape[1]
    if square:
        u, v = np.zeros(n), np.zeros(n + 1)
        col_of_row, row_of_col = np.full(n, -1, dtype=np.int64), np.full(n + 1, -1, dtype=np.int64)
        free = np.arange(n, dtype=np.int64)
    while True:
        if square:
            if not _augment_rows(costs, u, v, col_of_row, row_of_col, free):
                raise AssignmentError("no complete assignment exists")  # excluded by the region check
            rows, cols = np.arange(n), col_of_row.copy()
        else:
            rows, cols = _solve(costs)
        rounds += 1
        pending = ~exact[rows, cols]
        if not pending.any():
            break
        for i, j in zip(rows[pending].tolist(), cols[pending].tolist()):
            half = searches.cost(i, int(goal_flat[j]))
            if half == UNREACHABLE:  # cannot happen within one region; kept as a guard
                raise AssignmentError(f"goal {j} cannot be reached from robot {i}")
            costs[i, j] = half * HALF
            exact[i, j] = True
            pairs += 1
        if square:
            # The costs only rose, so the prices stay feasible; the robots of the pairs that
            # are no longer tight are let go and matched again on the next round.
            free = rows[pending].astype(np.int64)
            row_of_col[col_of_row[free]] = -1
            col_of_row[free] = -1
    return _result(rows, cols, costs, n, "lazy", pairs, searches.expanded, rounds)


@njit(cache=True, nogil=True)
def _augment_rows(costs: np.ndarray, u: np.ndarray, v: np.ndarray, col_of_row: np.ndarray,
                  row_of_col: np.ndarray, rows: np.ndarray) -> bool:  # pragma: no cover - compiled
    """Match each of ``rows`` (free) by a shortest augmenting path in the reduced costs
    ``costs[i, j] - u[i] - v[j]``, updating the prices so that every reduced cost stays
    non-negative and every matched pair's is zero: the matching stays a minimum-cost one for
    its rows. Square ``(n, n)`` costs, ``inf`` for forbidden pairs; ``v`` and ``row_of_col``
    have one extra slot (index n) for the search's root. False if some row cannot be matched.
    """
    n = costs.shape[1]
    root = n
    shortest = np.empty(n + 1)
    visited = np.zeros(n + 1, dtype=np.bool_)
    came_from = np.empty(n + 1, dtype=np.int64)
    for start in rows:
        row_of_col[root] = start
        shortest[:] = np.inf
        visited[:] = False
        col = root
        while True:
            visited[col] = True
            i = row_of_col[col]
            delta = np.inf
            nearest = -1
            for j in range(n):
                if not visited[j]:
                    reduced = costs[i, j] - u[i] - v[j]
                    if reduced < shortest[j]:
                        shortest[j] = reduced
                        came_from[j] = col
                    if shortest[j] < delta:
                        delta = shortest[j]
                        nearest = j
            if nearest < 0:
                return False
            for j in range(n + 1):
                if visited[j]:
                    u[row_of_col[j]] += delta
                    v[j] -= delta
                else:
                    shortest[j] -= delta
            col = nearest
            if row_of_col[col] < 0:
                break
        while col != root:  # flip the path back to the root
            previous = came_from[col]
            row_of_col[col] = row_of_col[previous]
            col_of_row[row_of_col[col]] = col
            col = previous
    return True
