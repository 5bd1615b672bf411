"""Incremental assignment with a tunable diagonal scaling (Liu and Shell's routing by Hungarian stages)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.optimize import linear_sum_assignment
from scipy.sparse import csr_matrix
from scipy.sparse.csgraph import dijkstra

from agents.assignment import AssignmentError, IncrementalAssignment


def _optimum(utilities: np.ndarray) -> float:
    """Largest total utility of a perfect matching (full re-solve); -inf entries are forbidden."""
    costs = np.where(np.isfinite(utilities), -utilities, np.inf)
    rows, cols = linear_sum_assignment(costs)
    return float(utilities[rows, cols].sum())


def _dense_scaled(positions: np.ndarray, targets: np.ndarray, home: np.ndarray, lam: float) -> np.ndarray:
    """The paper's scaled utility matrix on the complete graph, built independently of the library."""
    utilities = -np.linalg.norm(positions[:, None, :] - targets[None, :, :], axis=2)
    for robot, own in enumerate(home):
        if own >= 0:
            others = np.delete(utilities[robot], own)
            utilities[robot, own] = lam * others.max()
    return utilities


def _deployed(n: int, seed: int, lam: float, degree: int | None) -> tuple[IncrementalAssignment, np.random.Generator]:
    rng = np.random.default_rng(seed)
    sites = rng.random((n, 2)) * 100.0
    return IncrementalAssignment(sites, sites, lam=lam, degree=degree), rng


@pytest.mark.parametrize("lam", [0.0, 0.25, 0.5, 0.8, 1.0])
def test_every_stage_on_the_complete_graph_matches_a_full_resolve(lam: float) -> None:
    for seed in range(4):
        team, rng = _deployed(25, seed, lam, None)
        for _ in range(4):
            robot, target = rng.random(2) * 100.0, rng.random(2) * 100.0
            home = np.concatenate([team.target_of, [-1]])
            matrix = _dense_scaled(np.vstack([team.positions, robot]), np.vstack([team.targets, target]), home, lam)
            step = team.add(robot, target)
            assert step.scaled_utility == pytest.approx(_optimum(matrix), rel=1e-9, abs=1e-9)
            chosen = matrix[np.arange(len(team.target_of)), team.target_of]
            assert chosen.sum() == pytest.approx(step.scaled_utility, rel=1e-9, abs=1e-9)


@pytest.mark.parametrize("lam", [0.0, 0.4, 1.0])
@pytest.mark.parametrize("degree", [3, 6, 10])
def test_every_stage_on_sparse_graphs_matches_a_full_resolve(lam: float, degree: int) -> None:
    for seed in range(3):
        team, rng = _deployed(40, 10 + seed, lam, degree)
        for _ in range(5):
            robot, target = rng.random(2) * 100.0, rng.random(2) * 100.0
            matrix = team.scaled_problem(robot[None], target[None]).dense()
            assert np.isinf(matrix).any()  # a sparse graph: most pairs are forbidden
            step = team.add(robot, target)
            assert step.scaled_utility == pytest.approx(_optimum(matrix), rel=1e-9, abs=1e-9)
            assert np.isfinite(matrix[np.arange(len(team.target_of)), team.target_of]).all()


def test_several_pairs_at_once_are_globally_optimal_and_every_target_is_taken() -> None:
    team, rng = _deployed(30, 3, 0.6, 5)
    robots, targets = rng.random((3, 2)) * 100.0, rng.random((3, 2)) * 100.0
    matrix = team.scaled_problem(robots, targets).dense()
    step = team.add_pairs(robots, targets)
    assert step.scaled_utility == pytest.approx(_optimum(matrix), rel=1e-9)
    assert sorted(team.target_of.tolist()) == list(range(33))
    assert set(range(30, 33)) <= set(step.robots.tolist())


def test_initial_deployment_is_the_least_total_distance_assignment() -> None:
    rng = np.random.default_rng(5)
    robots, targets = rng.random((30, 2)), rng.random((30, 2))
    team = IncrementalAssignment(robots, targets, lam=0.5)
    lengths = np.linalg.norm(robots[:, None] - targets[None], axis=2)
    rows, cols = linear_sum_assignment(lengths)
    assert team.total_travel == pytest.approx(lengths[rows, cols].sum(), rel=1e-12)
    np.testing.assert_allclose(team.positions, targets[team.target_of])


def test_lambda_zero_on_the_complete_graph_sends_the_new_robot_straight_to_the_new_target() -> None:
    team, rng = _deployed(50, 7, 0.0, None)
    for _ in range(5):
        robot, target = rng.random(2) * 100.0, rng.random(2) * 100.0
        step = team.add(robot, target)
        assert step.moved == 1 and step.reassigned == 0
        assert step.total == pytest.approx(np.linalg.norm(robot - target))


def _shortest_route(team: IncrementalAssignment, robot: np.ndarray, target: np.ndarray) -> float:
    """Dijkstra from the new robot to the new target over the graph's real edges (robots stand on targets)."""
    problem = team.scaled_problem(robot[None], target[None])
    n = problem.n_targets  # nodes: targets 0..n-1, the new robot's start is node n
    real = problem.utilities < 0
    start = np.where(problem.rows == n - 1, n, team.target_of[np.minimum(problem.rows, n - 2)])
    graph = csr_matrix((-problem.utilities[real], (start[real], problem.cols[real])), shape=(n + 1, n + 1))
    return float(dijkstra(graph, indices=n)[n - 1])


@pytest.mark.parametrize("degree", [4, 8])
def test_lambda_zero_on_a_sparse_graph_routes_along_dijkstras_shortest_path(degree: int) -> None:
    team, rng = _deployed(80, 2, 0.0, degree)
    for _ in range(4):
        robot, target = np.array([0.0, 0.0]) + rng.random(2), np.array([100.0, 100.0]) - rng.random(2)
        expected = _shortest_route(team, robot, target)
        assert team.shortest_route(robot, target) == pytest.approx(expected, rel=1e-12)
        step = team.add(robot, target)
        assert step.total == pytest.approx(expected, rel=1e-9)


def test_raising_lambda_never_shortens_the_route_and_lambda_one_moves_the_most_robots() -> None:
    for seed in range(5):
        totals, moved, finish = [], [], []
        for lam in np.linspace(0.0, 1.0, 6):
            team, _ = _deployed(120, 100 + seed, float(lam), 8)
            step = team.add([0.5, 0.5], [99.5, 99.5])
            totals.append(step.total)
            moved.append(step.moved)
            finish.append(step.finishing_time)
        assert all(b >= a - 1e-9 for a, b in zip(totals, totals[1:]))
        assert moved[-1] >= moved[0] and moved[-1] > 2
        assert finish[-1] < finish[0]


def test_reassignment_lists_the_route_in_order() -> None:
    team, _ = _deployed(60, 4, 1.0, 6)
    before = team.target_of
    step = team.add([0.0, 0.0], [100.0, 100.0])
    assert step.robots[0] == 60 and step.from_targets[0] == -1
    assert step.to_targets[-1] == 60
    # each robot takes the target the next robot on the route leaves
    np.testing.assert_array_equal(step.to_targets[:-1], before[step.robots[1:]])
    assert step.finishing_time == pytest.approx(step.distances.max())
    assert team.reassignments == step.reassigned == step.moved - 1
    assert team.travelled[step.robots] == pytest.approx(step.distances)


@pytest.mark.parametrize("lam", [-0.1, 1.5, float("nan"), float("inf"), "0.5", True, None])
def test_lambda_outside_zero_one_is_refused(lam: object) -> None:
    with pytest.raises(AssignmentError, match="lam"):
        IncrementalAssignment([[0.0, 0.0]], [[1.0, 1.0]], lam=lam)


@pytest.mark.parametrize("degree", [0, -2, 2.5, "3"])
def test_bad_degree_is_refused(degree: object) -> None:
    with pytest.raises(AssignmentError, match="degree"):
        IncrementalAssignment([[0.0, 0.0]], [[1.0, 1.0]], degree=degree)


def test_bad_positions_and_counts_are_refused() -> None:
    with pytest.raises(AssignmentError, match="as many robots as targets"):
        IncrementalAssignment([[0.0, 0.0]], [[1.0, 1.0], [2.0, 2.0]])
    team = IncrementalAssignment([[0.0, 0.0], [1.0, 0.0]], [[0.0, 1.0], [1.0, 1.0]])
    with pytest.raises(AssignmentError, match="new robots"):
        team.add([float("nan"), 0.0], [1.0, 1.0])
    with pytest.raises(AssignmentError, match="3-dimensional"):
        team.add([0.0, 0.0, 0.0], [1.0, 1.0, 1.0])
    with pytest.raises(AssignmentError, match="as many new robots"):
        team.add_pairs([[0.0, 0.0], [1.0, 1.0]], [[2.0, 2.0]])


def test_a_sparse_graph_without_a_complete_assignment_is_refused() -> None:
    # two clusters: three robots far left, three targets far right, one edge each across
    robots = np.array([[0.0, 0.0], [0.0, 1.0], [0.0, 2.0], [100.0, 0.0]])
    targets = np.array([[100.0, 1.0], [100.0, 2.0], [100.0, 3.0], [0.0, 3.0]])
    with pytest.raises(AssignmentError, match="no complete assignment on the degree-1 graph"):
        IncrementalAssignment(robots, targets, degree=1)


def test_a_new_pair_out_of_reach_is_refused_and_leaves_the_team_unchanged() -> None:
    # two far apart groups; with degree 1 the new robot's only edge leads into the group
    # that cannot reach the new target
    sites = np.array([[0.0, 0.0], [1.0, 0.0], [50.0, 0.0], [51.0, 0.0]])
    team = IncrementalAssignment(sites, sites, lam=0.5, degree=1)
    before = team.target_of
    with pytest.raises(AssignmentError, match="no route for new robot 4"):
        team.add([-1.0, 0.0], [51.5, 0.0])
    np.testing.assert_array_equal(team.target_of, before)
    assert team.history == [] and len(team.targets) == 4


def test_an_empty_team_grows_pair_by_pair_in_three_dimensions() -> None:
    team = IncrementalAssignment([], [], lam=1.0)
    assert team.add([0.0, 0.0, 0.0], [3.0, 4.0, 0.0]).total == pytest.approx(5.0)
    # staying is worth exactly the 1 m hop to the new target, so robot 0 hops and robot 1 takes its place
    step = team.add([1.0, 0.0, 0.0], [3.0, 5.0, 0.0])
    assert step.robots.tolist() == [1, 0] and team.target_of.tolist() == [1, 0]
    assert team.total_travel == pytest.approx(5.0 + np.hypot(2.0, 4.0) + 1.0)
