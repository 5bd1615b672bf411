"""Every method against brute force on its own objective, over many small random instances."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from agents.assignment import MMDR_ALGORITHMS, assign, assign_costs
from tests.agents.assignment.assignment_oracle import (
    assert_valid,
    distance_matrix,
    greedy_reference,
    lexicographic_key,
    optimum,
)

SETTINGS = settings(max_examples=250, deadline=None, derandomize=True)


@st.composite
def point_instances(draw, max_points: int = 6):
    """Robots and targets: float or integer-grid coordinates (grids tie a lot), 2-D or 3-D."""
    n = draw(st.integers(1, max_points))
    m = draw(st.integers(1, max_points))
    d = draw(st.sampled_from([2, 3]))
    kind = draw(st.sampled_from(["float", "small-grid", "grid"]))
    seed = draw(st.integers(0, 2**32 - 1))
    rng = np.random.default_rng(seed)
    if kind == "float":
        robots, targets = rng.uniform(-50, 50, (n, d)), rng.uniform(-50, 50, (m, d))
    else:
        side = 4 if kind == "small-grid" else 100
        robots = rng.integers(0, side, (n, d)).astype(float)
        targets = rng.integers(0, side, (m, d)).astype(float)
    return robots, targets


def _check_against_oracle(result, costs: np.ndarray, method: str) -> None:
    n, m = costs.shape
    assert_valid(result.target_of, n, m)
    served = result.target_of >= 0
    chosen = costs[np.flatnonzero(served), result.target_of[served]]
    np.testing.assert_allclose(result.distances[served], chosen, rtol=1e-12)
    assert np.isnan(result.distances[~served]).all()
    if method == "mmdr":
        np.testing.assert_allclose(lexicographic_key(chosen), optimum(costs, "mmdr"), rtol=1e-12, atol=1e-12)
    elif method == "mmd+msd2":
        makespan, squares = optimum(costs, "mmd+msd2")
        assert result.makespan == pytest.approx(makespan, rel=1e-12, abs=1e-12)
        assert result.total_squared == pytest.approx(squares, rel=1e-9, abs=1e-9)
    elif method == "bottleneck":
        assert result.makespan == pytest.approx(optimum(costs, "bottleneck"), rel=1e-12, abs=1e-12)
    elif method == "msd":
        assert result.total == pytest.approx(optimum(costs, "msd"), rel=1e-9, abs=1e-9)
    elif method == "msd2":
        assert result.total_squared == pytest.approx(optimum(costs, "msd2"), rel=1e-9, abs=1e-9)
    elif method == "greedy":
        if n <= m:
            np.testing.assert_array_equal(result.target_of, greedy_reference(costs))
        else:  # targets choose: the transposed problem, read back
            by_target = greedy_reference(costs.T)
            expected = np.full(n, -1)
            expected[by_target] = np.arange(m)
            np.testing.assert_array_equal(result.target_of, expected)


@pytest.mark.parametrize("method", ["mmdr", "mmd+msd2", "msd", "msd2", "bottleneck", "greedy"])
@SETTINGS
@given(instance=point_instances())
def test_points_match_brute_force(method, instance):
    robots, targets = instance
    result = assign(robots, targets, method=method)
    _check_against_oracle(result, distance_matrix(robots, targets), method)


@pytest.mark.parametrize("algorithm", MMDR_ALGORITHMS)
@SETTINGS
@given(instance=point_instances())
def test_every_mmdr_algorithm_matches_brute_force(algorithm, instance):
    robots, targets = instance
    result = assign(robots, targets, method="mmdr", algorithm=algorithm)
    _check_against_oracle(result, distance_matrix(robots, targets), "mmdr")


@st.composite
def cost_instances(draw):
    """Cost matrices with ties and forbidden pairs (inf) that still allow a complete assignment."""
    n = draw(st.integers(1, 6))
    m = draw(st.integers(1, 6))
    seed = draw(st.integers(0, 2**32 - 1))
    rng = np.random.default_rng(seed)
    costs = rng.integers(0, draw(st.sampled_from([3, 10, 1000])), (n, m)).astype(float)
    forbidden = rng.random((n, m)) < draw(st.sampled_from([0.0, 0.3, 0.6]))
    # Keep one guaranteed complete assignment so the instance stays feasible.
    keep = rng.permutation(max(n, m))
    for k in range(min(n, m)):
        i, j = (k, keep[k] % m) if n <= m else (keep[k] % n, k)
        forbidden[i, j] = False
    costs[forbidden] = np.inf
    return costs


@pytest.mark.parametrize("method", ["mmdr", "mmd+msd2", "msd", "msd2", "bottleneck", "greedy", "random"])
@SETTINGS
@given(costs=cost_instances())
def test_cost_matrices_with_forbidden_pairs(method, costs):
    result = assign_costs(costs, method=method, rng=7 if method == "random" else None)
    served = result.target_of >= 0
    assert np.isfinite(costs[np.flatnonzero(served), result.target_of[served]]).all()
    if method == "greedy" and not np.isfinite(costs).all():
        assert_valid(result.target_of, *costs.shape)  # greedy may need repairs around forbidden pairs
    elif method == "random":
        assert_valid(result.target_of, *costs.shape)
    else:
        _check_against_oracle(result, costs, method)


@pytest.mark.parametrize("algorithm", ["bitvector", "dp", "brute"])
@SETTINGS
@given(costs=cost_instances())
def test_mmdr_algorithms_on_cost_matrices(algorithm, costs):
    _check_against_oracle(assign_costs(costs, "mmdr", algorithm=algorithm), costs, "mmdr")
