"""Agreement at sizes beyond brute force: the mmdr algorithms, and the k-d tree path vs dense."""

from __future__ import annotations

import numpy as np
import pytest

from agents.assignment import assign, assign_costs
from agents.assignment.api import SPARSE_MIN_PAIRS
from assignment_oracle import assert_valid, distance_matrix


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
@pytest.mark.parametrize(("n", "m", "side"), [(200, 200, 40000), (160, 240, 25600), (250, 170, 30), (200, 200, 12)])
def test_kd_tree_path_matches_dense_path(seed, n, m, side):
    """Point input this large uses the k-d tree candidate graph; cost input always uses dense matrices."""
    assert min(n, m) * max(n, m) >= SPARSE_MIN_PAIRS
    rng = np.random.default_rng(seed)
    robots = rng.integers(0, side, (n, 2)).astype(float)
    targets = rng.integers(0, side, (m, 2)).astype(float)
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
