"""Agreement at sizes beyond brute force: the mmdr algorithms, and the k-d tree path vs dense."""

from __future__ import annotations

import numpy as np
import pytest

from agents.assignment import assign, assign_costs
from agents.assignment.api import SPARSE_MIN_PAIRS
from tests.agents.assignment.assignment_oracle import (
    assert_valid,
    chosen_costs,
    distance_matrix,
    optimum,
    scipy_min_sum,
    threshold_bottleneck,
)


def _sorted_desc(result) -> np.ndarray:
    return np.sort(result.distances[result.target_of >= 0])[::-1]


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize(("n", "m", "side"), [(12, 12, 4), (13, 13, 30), (10, 14, 5), (14, 9, 6)])
def test_fast_bitvector_and_dp_agree(seed, n, m, side):
    rng = np.random.default_rng(seed)
    robots = rng.integers(0, side, (n, 2)).astype(float)
    targets = rng.integers(0, side, (m, 2)).astype(float)
    reference = _sorted_desc(assign(robots, targets, "mmdr", algorithm="dp"))
    for algorithm in ("fast", "bitvector"):
        result = assign(robots, targets, "mmdr", algorithm=algorithm)
        assert_valid(result.target_of, n, m)
        np.testing.assert_array_equal(_sorted_desc(result), reference)


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize(("n", "m", "side", "d"), [(60, 60, 8, 2), (50, 70, 6, 2), (80, 80, 1000, 2), (40, 40, 4, 3)])
def test_fast_matches_bitvector_on_larger_tie_heavy_problems(seed, n, m, side, d):
    rng = np.random.default_rng(seed)
    robots = rng.integers(0, side, (n, d)).astype(float)
    targets = rng.integers(0, side, (m, d)).astype(float)
    fast = assign(robots, targets, "mmdr")
    slow = assign(robots, targets, "mmdr", algorithm="bitvector")
    np.testing.assert_array_equal(_sorted_desc(fast), _sorted_desc(slow))


@pytest.mark.parametrize("seed", range(3))
@pytest.mark.parametrize(
    ("n", "m", "side", "d"),
    [
        (200, 200, 40000, 2),
        (160, 240, 25600, 2),
        (250, 170, 30, 2),
        (200, 200, 12, 2),
        (150, 150, 6, 3),
        (180, 170, 2, 1),  # robots sit on targets: the nearest-neighbour bound is 0
        (5, 4600, 100, 2),
    ],
)
def test_kd_tree_path_matches_dense_path(seed, n, m, side, d):
    """Point input this large uses the k-d tree candidate graph; cost input always uses dense matrices."""
    assert min(n, m) * max(n, m) >= SPARSE_MIN_PAIRS
    rng = np.random.default_rng(seed)
    robots = rng.integers(0, side, (n, d)).astype(float)
    targets = rng.integers(0, side, (m, d)).astype(float)
    costs = distance_matrix(robots, targets)
    for method in ("mmdr", "mmd+msd2", "bottleneck"):
        sparse = assign(robots, targets, method)
        dense = assign_costs(costs, method)
        assert_valid(sparse.target_of, n, m)
        served = sparse.target_of >= 0
        np.testing.assert_allclose(
            sparse.distances[served], costs[np.flatnonzero(served), sparse.target_of[served]], rtol=1e-12
        )
        assert sparse.makespan == pytest.approx(dense.makespan, rel=1e-12)
        if method == "mmdr":
            np.testing.assert_allclose(_sorted_desc(sparse), _sorted_desc(dense), rtol=1e-12)
        if method == "mmd+msd2":
            assert sparse.total_squared == pytest.approx(dense.total_squared, rel=1e-9)


def test_mmd_msd2_is_between_msd2_and_mmdr():
    """Same makespan as mmdr, sum of squares no larger; msd2 has the least sum of squares."""
    rng = np.random.default_rng(5)
    robots, targets = rng.uniform(0, 100, (40, 2)), rng.uniform(0, 100, (40, 2))
    mmdr, mixed, msd2 = (assign(robots, targets, m) for m in ("mmdr", "mmd+msd2", "msd2"))
    assert mixed.makespan == pytest.approx(mmdr.makespan, rel=1e-12)
    assert msd2.total_squared <= mixed.total_squared + 1e-9 <= mmdr.total_squared + 2e-9
    assert msd2.makespan >= mixed.makespan - 1e-12


def _instance(rng: np.random.Generator, n: int, m: int, d: int, kind: str) -> tuple[np.ndarray, np.ndarray]:
    if kind == "float":
        return rng.uniform(0, 100, (n, d)), rng.uniform(0, 100, (m, d))
    side = 6 if kind == "small-grid" else max(n, m) ** 2
    return rng.integers(0, side, (n, d)).astype(float), rng.integers(0, side, (m, d)).astype(float)


def _forbid(rng: np.random.Generator, costs: np.ndarray, fraction: float) -> np.ndarray:
    """Forbid a random fraction of pairs (inf), keeping one complete assignment allowed."""
    n, m = costs.shape
    forbidden = rng.random((n, m)) < fraction
    keep = rng.permutation(max(n, m))
    for k in range(min(n, m)):
        forbidden[(k, keep[k] % m) if n <= m else (keep[k] % n, k)] = False
    return np.where(forbidden, np.inf, costs)


def _check_objectives(costs: np.ndarray, solve) -> None:
    """msd, msd2, bottleneck and mmd+msd2 against the SciPy references."""
    n, m = costs.shape
    results = {method: solve(method) for method in ("msd", "msd2", "bottleneck", "mmd+msd2")}
    for result in results.values():
        assert_valid(result.target_of, n, m)
        assert np.isfinite(chosen_costs(result.target_of, costs)).all()
    assert chosen_costs(results["msd"].target_of, costs).sum() == pytest.approx(scipy_min_sum(costs), rel=1e-9)
    squares = chosen_costs(results["msd2"].target_of, costs) ** 2
    assert squares.sum() == pytest.approx(scipy_min_sum(costs**2), rel=1e-9)
    bottleneck = threshold_bottleneck(costs)
    assert chosen_costs(results["bottleneck"].target_of, costs).max() == bottleneck
    mixed = chosen_costs(results["mmd+msd2"].target_of, costs)
    assert mixed.max() == bottleneck
    restricted = np.where(costs <= bottleneck, costs**2, np.inf)
    assert (mixed**2).sum() == pytest.approx(scipy_min_sum(restricted), rel=1e-9)


@pytest.mark.parametrize("seed", range(2))
@pytest.mark.parametrize(
    ("n", "m", "d", "kind"),
    [(90, 90, 2, "float"), (70, 110, 3, "small-grid"), (120, 50, 2, "grid"), (40, 40, 2, "small-grid")],
)
def test_objectives_match_scipy_references_beyond_brute_force(seed, n, m, d, kind):
    """Points (square and rectangular, 2-D and 3-D) and cost matrices with forbidden pairs."""
    rng = np.random.default_rng(seed)
    robots, targets = _instance(rng, n, m, d, kind)
    costs = distance_matrix(robots, targets)
    _check_objectives(costs, lambda method: assign(robots, targets, method))
    forbidden = _forbid(rng, np.round(costs) if kind != "float" else costs, 0.6)
    _check_objectives(forbidden, lambda method: assign_costs(forbidden, method))
    if max(n, m) <= 70:
        fast = assign_costs(forbidden, "mmdr")
        slow = assign_costs(forbidden, "mmdr", algorithm="bitvector")
        np.testing.assert_array_equal(_sorted_desc(fast), _sorted_desc(slow))


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(200))
def test_objectives_match_scipy_references_many_sizes(seed):
    rng = np.random.default_rng(1000 + seed)
    n = int(rng.integers(30, 301))
    m = n if seed % 2 else int(rng.integers(30, 301))
    d = int(rng.choice([2, 3]))
    kind = str(rng.choice(["float", "small-grid", "grid"]))
    robots, targets = _instance(rng, n, m, d, kind)
    costs = distance_matrix(robots, targets)
    _check_objectives(costs, lambda method: assign(robots, targets, method))
    forbidden = _forbid(rng, np.round(costs) if kind != "float" else costs, float(rng.choice([0.3, 0.9])))
    _check_objectives(forbidden, lambda method: assign_costs(forbidden, method))
    if max(n, m) <= 60:
        for matrix in (costs, forbidden):
            fast = assign_costs(matrix, "mmdr")
            slow = assign_costs(matrix, "mmdr", algorithm="bitvector")
            np.testing.assert_array_equal(_sorted_desc(fast), _sorted_desc(slow))


@pytest.mark.parametrize("transpose", [False, True])
def test_few_robots_many_targets(transpose):
    """3 robots, 30000 targets (or the reverse): squaring up must not cost (m - n) * m pairs.

    In an optimal assignment of any of these objectives each robot uses one of its
    3 nearest targets (otherwise one of those is free and strictly better), so brute
    force over the union of those targets is the reference.
    """
    rng = np.random.default_rng(4)
    robots = rng.integers(0, 1000, (3, 2)).astype(float)
    targets = rng.integers(0, 1000, (30000, 2)).astype(float)
    costs = distance_matrix(robots, targets)
    near = np.unique(np.argsort(costs, axis=1, kind="stable")[:, :3])
    small = costs[:, near]
    for method in ("mmdr", "mmd+msd2", "bottleneck", "msd2"):
        if transpose:
            result = assign(targets, robots, method)
            assert_valid(result.target_of, 30000, 3)
            target_of = np.full(3, -1)
            target_of[result.target_of[result.target_of >= 0]] = np.flatnonzero(result.target_of >= 0)
        else:
            result = assign(robots, targets, method)
            assert_valid(result.target_of, 3, 30000)
            target_of = result.target_of
        chosen = costs[np.arange(3), target_of]
        assert result.makespan == pytest.approx(optimum(small, "bottleneck"), rel=1e-12)
        if method == "mmdr":
            np.testing.assert_allclose(np.sort(chosen)[::-1], optimum(small, "mmdr"), rtol=1e-12)
        if method == "mmd+msd2":
            assert (chosen**2).sum() == pytest.approx(optimum(small, "mmd+msd2")[1], rel=1e-12)
        if method == "msd2":
            assert (chosen**2).sum() == pytest.approx(optimum(small, "msd2"), rel=1e-12)
    dense = assign_costs(costs, "mmdr")  # the dense path squares up the same way
    np.testing.assert_allclose(_sorted_desc(dense), optimum(small, "mmdr"), rtol=1e-12)
