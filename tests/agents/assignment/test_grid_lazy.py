"""Lazy path-cost assignment on grids: optimal totals, exact A* costs, refused bad input."""

import time
from pathlib import Path

import numpy as np
import pytest
from scipy import ndimage

from agents.assignment import AssignmentError, assign_on_grid
from agents.assignment.grid import Workspace, load_movingai_map, random_instance
from agents.assignment.pathcost import ResumableSearch, dijkstra_costs

DATA = Path(__file__).parent / "data"


def test_lazy_total_equals_all_pairs_on_random_workspaces():
    rng = np.random.default_rng(5)
    lazy_pairs = all_pairs = 0
    for trial in range(300):
        shape = (int(rng.integers(6, 16)), int(rng.integers(6, 16)))
        if trial % 5 == 0:
            shape = (5, 5, 5)
        n, m = int(rng.integers(1, 7)), int(rng.integers(1, 7))
        grid, robots, goals = random_instance(shape, float(rng.uniform(0.1, 0.25)), n, m, rng)
        lazy = assign_on_grid(grid, robots, goals, lower_bound="octile" if trial % 2 else "euclidean")
        full = assign_on_grid(grid, robots, goals, method="all-pairs")
        assert lazy.total == pytest.approx(full.total, abs=1e-9)
        assert (lazy.target_of >= 0).sum() == min(n, m)
        lazy_pairs += lazy.pairs_computed
        all_pairs += full.pairs_computed
    assert lazy_pairs < all_pairs


def test_resumable_astar_matches_dijkstra_in_2d_and_3d():
    rng = np.random.default_rng(9)
    for shape in [(12, 9), (6, 5, 7)]:
        grid = rng.random(shape) < 0.25
        ws = Workspace(grid)
        free = np.argwhere(~grid)
        targets = ws.flat(free)
        source = int(targets[0])
        exact, _ = dijkstra_costs(ws, source, targets)
        search = ResumableSearch(ws, source)
        for k in rng.permutation(len(targets)):
            assert search.cost_to(int(targets[k])) == exact[k]


def test_step_costs_and_no_corner_cutting():
    grid = np.array([[0, 1], [0, 0]], dtype=bool)
    # (0,0) -> (1,1): the diagonal would cut the obstacle's corner, so two straight steps.
    assert assign_on_grid(grid, [[0, 0]], [[1, 1]]).total == 2.0
    assert assign_on_grid(np.zeros((2, 2), bool), [[0, 0]], [[1, 1]]).total == 1.5
    assert assign_on_grid(np.zeros((2, 2, 2), bool), [[0, 0, 0]], [[1, 1, 1]]).total == 2.0


def test_walled_off_goal_and_robot_are_named():
    grid = np.zeros((5, 5), dtype=bool)
    grid[:, 2] = True
    with pytest.raises(AssignmentError, match="robot 1"):
        assign_on_grid(grid, [[0, 0], [0, 4]], [[1, 0], [2, 1]])
    with pytest.raises(AssignmentError, match="goal 0"):
        assign_on_grid(grid, [[0, 0], [1, 0], [2, 0]], [[4, 4], [3, 0]])


def test_cells_off_grid_or_on_obstacles_are_refused_by_index():
    grid = np.zeros((4, 4), dtype=bool)
    grid[1, 1] = True
    with pytest.raises(AssignmentError, match=r"robots\[1\].*outside"):
        assign_on_grid(grid, [[0, 0], [4, 0]], [[2, 2], [3, 3]])
    with pytest.raises(AssignmentError, match=r"goals\[0\].*obstacle"):
        assign_on_grid(grid, [[0, 0]], [[1, 1]])
    with pytest.raises(AssignmentError, match="unknown grid assignment method"):
        assign_on_grid(grid, [[0, 0]], [[2, 2]], method="fast")


def test_movingai_map_loads_and_bad_map_names_file_and_line():
    grid = load_movingai_map(DATA / "small.map")
    assert grid.shape == (3, 4) and grid[1, 1] and grid[1, 2] and grid.sum() == 2
    with pytest.raises(AssignmentError, match=r"bad_letter\.map, line 6: unknown terrain 'X'"):
        load_movingai_map(DATA / "bad_letter.map")


def test_kept_assignment_stays_optimal_as_chosen_costs_rise():
    """The lazy method's incremental Hungarian rounds: after raising the costs of the chosen
    pairs and re-matching only their rows, the matching is as cheap as a fresh solve."""
    from scipy.optimize import linear_sum_assignment

    from agents.assignment.lazy import _augment_rows

    rng = np.random.default_rng(2)
    for trial in range(40):
        n = int(rng.integers(2, 25))
        costs = rng.integers(0, 20, (n, n)).astype(float) * 0.5
        costs[rng.random((n, n)) < 0.2] = np.inf
        np.fill_diagonal(costs, np.where(np.isinf(np.diag(costs)), 30.0, np.diag(costs)))  # feasible
        u, v = np.zeros(n), np.zeros(n + 1)
        col_of_row, row_of_col = np.full(n, -1), np.full(n + 1, -1)
        free = np.arange(n)
        for _ in range(6):
            assert _augment_rows(costs, u, v, col_of_row, row_of_col, free)
            rows, cols = linear_sum_assignment(costs)
            assert costs[np.arange(n), col_of_row].sum() == costs[rows, cols].sum()
            assert sorted(col_of_row.tolist()) == list(range(n))
            free = rng.choice(n, int(rng.integers(1, n + 1)), replace=False)
            costs[free, col_of_row[free]] += rng.integers(1, 10, len(free)) * 0.5
            row_of_col[col_of_row[free]] = -1
            col_of_row[free] = -1


@pytest.mark.parametrize("shape, robots", [((40, 40), 30), ((12, 12, 12), 25)])
def test_lazy_equals_all_pairs_with_as_many_goals_as_robots(shape, robots):
    rng = np.random.default_rng(11)
    for _ in range(8):
        grid, r, g = random_instance(shape, float(rng.uniform(0.1, 0.25)), robots, robots, rng)
        lazy = assign_on_grid(grid, r, g)
        full = assign_on_grid(grid, r, g, method="all-pairs")
        assert lazy.total == full.total
        assert sorted(lazy.target_of.tolist()) == list(range(robots))
        assert lazy.pairs_computed < full.pairs_computed


def test_a_map_of_our_own_loads_and_both_methods_agree_on_it():
    """spiral.map: corridors winding between walls, a closed pocket around a tree (T) in the
    middle, and the other obstacle letters (W, O) in the bottom-left corner."""
    grid = load_movingai_map(DATA / "spiral.map")
    assert grid.shape == (16, 16) and grid[14, 0] and grid[15, 1] and grid[7, 7] and not grid[7, 6]
    robots = [[0, 0], [15, 15], [12, 2], [10, 4]]
    goals = [[2, 2], [14, 9], [4, 4], [0, 15]]
    lazy = assign_on_grid(grid, robots, goals)
    full = assign_on_grid(grid, robots, goals, method="all-pairs")
    assert lazy.total == full.total
    assert lazy.pairs_computed < full.pairs_computed
    # (4, 4) lies deep inside the walls: close to (0, 0) as the crow flies (6 grid units), far by path
    around = assign_on_grid(grid, [[0, 0]], [[4, 4]])
    assert around.total == assign_on_grid(grid, [[0, 0]], [[4, 4]], method="all-pairs").total > 30.0
    with pytest.raises(AssignmentError, match=r"goal 3 at cell \[7, 6\] cannot be reached by any robot"):
        assign_on_grid(grid, robots, [[2, 2], [14, 9], [4, 4], [7, 6]])
    with pytest.raises(AssignmentError, match=r"goals\[1\] = \[14, 7\] is on an obstacle"):  # a tree
        assign_on_grid(grid, robots, [[2, 2], [14, 7], [4, 4], [0, 15]])


def test_lazy_equals_all_pairs_when_walls_split_the_workspace_into_regions():
    """Pairs in different regions are forbidden from the start; the kept matching must still be optimal."""
    rng = np.random.default_rng(17)
    for trial in range(60):
        grid = rng.random((14, 14)) < 0.15
        grid[:, 6] = True  # a wall: left and right halves never meet
        grid[7, :6] = True  # and the left half cut again
        labels, _ = ndimage.label(~grid)
        regions = [np.argwhere(labels == k) for k in np.unique(labels[labels > 0])]
        robots, goals = [], []
        for cells in regions:
            if len(cells) < 8:
                continue
            k = int(rng.integers(1, 4))
            extra = int(rng.integers(0, 2)) if trial % 2 else 0  # odd trials: more goals than robots
            pick = rng.choice(len(cells), 2 * k + extra, replace=False)
            robots += cells[pick[:k]].tolist()
            goals += cells[pick[k:]].tolist()
        lazy = assign_on_grid(grid, robots, goals)
        full = assign_on_grid(grid, robots, goals, method="all-pairs")
        assert lazy.total == pytest.approx(full.total, abs=1e-9)
        assert (lazy.target_of >= 0).all()
        assert len(set(lazy.target_of.tolist())) == len(robots)


@pytest.mark.slow
def test_200_robots_on_a_400_square_map_take_under_5_seconds():
    rng = np.random.default_rng(400)
    grid, robots, goals = random_instance((12, 12), 0.2, 4, 4, rng)
    assign_on_grid(grid, robots, goals)  # load the compiled kernels first
    for _ in range(2):
        grid, robots, goals = random_instance((400, 400), 0.2, 200, 200, rng)
        start = time.perf_counter()
        result = assign_on_grid(grid, robots, goals)
        assert time.perf_counter() - start < 5.0
        assert sorted(result.target_of.tolist()) == list(range(200))
        assert result.pairs_computed < 0.1 * 200 * 200
