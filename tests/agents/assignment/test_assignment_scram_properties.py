"""The properties SCRAM proves, checked on random instances, and counter-examples for the baselines.

Robots move in straight lines at the same constant speed and wait at their
targets. No two robots start at the same point and no two targets coincide.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from agents.assignment import assign
from tests.agents.assignment.assignment_oracle import has_collision, paths_meet, position_at

SETTINGS = settings(max_examples=300, deadline=None, derandomize=True)


def _distinct_points(rng: np.random.Generator, count: int, side: int, d: int) -> np.ndarray:
    """``count`` distinct integer points of the grid ``[0, side)^d``."""
    flat = rng.choice(side**d, size=count, replace=False)
    return np.stack(np.unravel_index(flat, (side,) * d), axis=1).astype(float)


@st.composite
def square_instances(draw, max_robots: int = 7):
    """Crowded small grids (where paths often cross) or random reals; 2-D or 3-D."""
    n = draw(st.integers(2, max_robots))
    d = draw(st.sampled_from([2, 2, 3]))
    rng = np.random.default_rng(draw(st.integers(0, 2**32 - 1)))
    if draw(st.booleans()):
        side = draw(st.sampled_from([3, 5, 8]))
        return _distinct_points(rng, n, side, d), _distinct_points(rng, n, side, d)
    return rng.uniform(0, 10, (n, d)), rng.uniform(0, 10, (n, d))


@pytest.mark.parametrize("method", ["mmdr", "mmd+msd2", "msd2"])
@SETTINGS
@given(instance=square_instances())
def test_scram_methods_are_collision_free(method, instance):
    robots, targets = instance
    result = assign(robots, targets, method=method)
    assert not has_collision(robots, targets, result.target_of)


def test_collision_check_is_not_vacuous_on_these_instances():
    """On the same kind of crowded grids, greedy paths do collide regularly."""
    rng = np.random.default_rng(0)
    collisions = 0
    for _ in range(300):
        robots, targets = _distinct_points(rng, 6, 5, 2), _distinct_points(rng, 6, 5, 2)
        collisions += has_collision(robots, targets, assign(robots, targets, "greedy").target_of)
        assert not has_collision(robots, targets, assign(robots, targets, "mmdr").target_of)
    assert collisions >= 10


def _advance(robots: np.ndarray, targets: np.ndarray, target_of: np.ndarray, t: float) -> np.ndarray:
    return np.array([position_at(robots[i], targets[target_of[i]], t) for i in range(len(robots))])


@SETTINGS
@given(instance=square_instances(max_robots=8), fraction=st.sampled_from([0.05, 0.3, 0.5, 0.8, 0.99, 1.0]))
def test_mmdr_is_dynamically_consistent(instance, fraction):
    robots, targets = instance
    first = assign(robots, targets, "mmdr")
    moved = _advance(robots, targets, first.target_of, fraction * first.makespan)
    again = assign(moved, targets, "mmdr")
    np.testing.assert_array_equal(again.target_of, first.target_of)


def test_msd2_is_not_dynamically_consistent():
    """The counter-example of the SCRAM paper's appendix: msd2 switches after 2 units of travel."""
    robots = np.array([[3.0, 0.0], [2.0, 999.0]])
    targets = np.array([[0.0, 0.0], [1.0, 0.0]])
    first = assign(robots, targets, "msd2")
    assert first.target_of.tolist() == [1, 0]  # sum of squares 998009 < 998011
    moved = _advance(robots, targets, first.target_of, 2.0)
    np.testing.assert_allclose(moved[0], [1.0, 0.0])
    assert assign(moved, targets, "msd2").target_of.tolist() == [0, 1]  # 994011 < 994013
    # MMDR keeps its choice on the same instance.
    mmdr = assign(robots, targets, "mmdr")
    moved = _advance(robots, targets, mmdr.target_of, 2.0)
    assert assign(moved, targets, "mmdr").target_of.tolist() == mmdr.target_of.tolist()


def test_greedy_collides_where_mmdr_does_not():
    robots = np.array([[6.0, 1.0], [2.0, 3.0]])
    targets = np.array([[4.0, 3.0], [1.0, 6.0]])
    greedy = assign(robots, targets, "greedy")
    # Shortest pair first: robot 1 -> target 0 (length 2) leaves robot 0 the long diagonal
    # (6,1) -> (1,6), which passes through target 0 after robot 1 has parked there.
    assert greedy.target_of.tolist() == [1, 0]
    assert paths_meet(robots[0], targets[1], robots[1], targets[0])
    assert has_collision(robots, targets, greedy.target_of)
    mmdr = assign(robots, targets, "mmdr")
    assert mmdr.target_of.tolist() == [0, 1]
    assert not has_collision(robots, targets, mmdr.target_of)
    assert mmdr.makespan < greedy.makespan


def test_msd_collides_on_a_collinear_tie():
    """Both assignments have total distance 5; msd returns the one that drives through a robot."""
    robots = np.array([[2.0, 4.0], [2.0, 6.0]])
    targets = np.array([[2.0, 4.0], [2.0, 1.0]])
    msd = assign(robots, targets, "msd")
    assert msd.total == pytest.approx(5.0)
    assert msd.target_of.tolist() == [0, 1]
    assert has_collision(robots, targets, msd.target_of)
    for method in ("mmdr", "mmd+msd2", "msd2"):
        result = assign(robots, targets, method)
        assert result.target_of.tolist() == [1, 0]
        assert not has_collision(robots, targets, result.target_of)


def test_paths_meet_detects_crossing_and_passing():
    assert paths_meet([0, 0], [2, 2], [2, 0], [0, 2])  # cross at (1, 1) at the same time
    assert not paths_meet([0, 0], [2, 2], [3, 0], [5, 2])  # parallel
    assert not paths_meet([0, 0], [4, 0], [2, 1], [2, -3])  # same point (2, 0) at times 2 and 1
    assert paths_meet([0, 0], [4, 0], [2, 2], [2, -3])  # same point (2, 0) at time 2
    assert paths_meet([0, 0], [4, 0], [3, 1], [2, 0])  # drives through a robot parked at (2, 0)
