"""The compiled search machinery of the lazy grid assignment: the pool of resumable A*
searches within a memory budget, the width of its cell states, and the workspace's moves
and free regions."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from scipy import ndimage

from agents.assignment import assign_on_grid
from agents.assignment.grid import Workspace, random_instance
from agents.assignment.pathcost import ResumableSearch, SearchPool, dijkstra_costs, state_dtype


def _row_bytes(workspace: Workspace) -> int:
    return workspace.moves.allowed.shape[0] * state_dtype(workspace).itemsize


@pytest.mark.parametrize("rows_of_budget", [0, 1.5, 2.5, 100])
def test_a_pool_within_any_budget_answers_every_query_exactly(rows_of_budget):
    rng = np.random.default_rng(3)
    grid, robots, goals = random_instance((30, 30), 0.25, 12, 40, rng)
    ws = Workspace(grid)
    robot_flat, goal_flat = ws.flat(robots), ws.flat(goals)
    exact = np.array([dijkstra_costs(ws, int(s), goal_flat)[0] for s in robot_flat])
    budget = int(rows_of_budget * _row_bytes(ws))
    pool = SearchPool(ws, robot_flat, budget)
    unlimited = SearchPool(ws, robot_flat, 2**40)
    for _ in range(6):  # batches of queries, robots coming back to earlier goals too
        who = rng.integers(0, len(robot_flat), 30)
        which = rng.integers(0, len(goal_flat), 30)
        assert pool.costs_to(who, goal_flat[which]).tolist() == exact[who, which].tolist()
        unlimited.costs_to(who, goal_flat[which])
        assert pool.nbytes <= budget or pool.live == 1  # the last search is never dropped
    if rows_of_budget < 12:
        assert pool.expanded >= unlimited.expanded  # dropped searches started again
    else:
        assert pool.expanded == unlimited.expanded


def test_the_lazy_method_with_little_search_memory_keeps_its_total():
    rng = np.random.default_rng(8)
    for _ in range(4):
        grid, robots, goals = random_instance((40, 40), 0.2, 25, 25, rng)
        full = assign_on_grid(grid, robots, goals, method="all-pairs")
        for memory in (1, 3 * 42 * 42 * 2, 2**31):
            lazy = assign_on_grid(grid, robots, goals, search_memory=memory)
            assert lazy.total == full.total


def _serpentine(rows: int, cols: int) -> np.ndarray:
    """Walls on every other row, open at alternate ends: one corridor through the whole grid."""
    grid = np.zeros((rows, cols), dtype=bool)
    for r in range(1, rows, 2):
        grid[r, :] = True
        grid[r, -1 if (r // 2) % 2 == 0 else 0] = False
    return grid


@pytest.mark.parametrize("side, dtype", [(140, np.int16), (150, np.int32)])
def test_cell_states_are_wide_enough_for_the_longest_path(side, dtype):
    """The longest shortest path of a grid runs through nearly all its free cells."""
    grid = _serpentine(side, side)
    ws = Workspace(grid)
    assert state_dtype(ws) == dtype
    free = np.argwhere(~grid)
    targets = ws.flat(free)
    start = ws.flat(np.array([[0, 0]]))[0]
    exact, _ = dijkstra_costs(ws, int(start), targets)
    search = ResumableSearch(ws, int(start))
    assert search.cost_to(int(targets[np.argmax(exact)])) == exact.max() > 19000
    picks = np.random.default_rng(0).choice(len(targets), 50, replace=False)
    assert [search.cost_to(int(targets[k])) for k in picks] == exact[picks].tolist()


def _legal(padded_free: np.ndarray, cell: tuple[int, ...], step: tuple[int, ...]) -> bool:
    """A move is legal when every cell of its box is free (source included)."""
    parts = itertools.product(*[(0, d) if d else (0,) for d in step])
    return all(padded_free[tuple(c + p for c, p in zip(cell, part))] for part in parts)


@pytest.mark.parametrize("shape", [(9, 13), (1, 6), (5, 4, 6), (2, 1, 3)])
def test_moves_and_regions_agree_with_a_cell_by_cell_check(shape):
    rng = np.random.default_rng(len(shape) * 10 + shape[0])
    for density in (0.0, 0.3, 0.6):
        grid = rng.random(shape) < density
        ws = Workspace(grid)
        padded_free = ~np.pad(grid, 1, constant_values=True)
        steps = [d for d in itertools.product((-1, 0, 1), repeat=grid.ndim) if any(d)]
        assert ws.moves.offsets.tolist() == [int(np.dot(d, ws.strides)) for d in steps]
        assert ws.moves.costs.tolist() == [1 + sum(map(abs, d)) for d in steps]
        allowed = ws.moves.allowed.reshape(ws.padded_shape)
        for cell in itertools.product(*[range(1, s + 1) for s in shape]):
            expected = sum(1 << m for m, d in enumerate(steps) if _legal(padded_free, cell, d))
            assert allowed[cell] == expected
        labels, _ = ndimage.label(padded_free)
        ours = ws.component
        assert ((ours == 0) == (labels == 0)).all()
        assert len(set(zip(ours.ravel(), labels.ravel()))) == len(np.unique(labels))  # the same partition
