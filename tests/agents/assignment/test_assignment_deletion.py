"""The small dense problems' fast path (:mod:`agents.assignment.deletion`): the lexicographic
bottleneck by deleting pairs longest first, checked against brute force and against the
general method it stands in for (ties included, where the callers fall back)."""

from __future__ import annotations

import numpy as np
import pytest

from agents.assignment.deletion import delete_longest_first
from agents.assignment.geometry import dense_distances
from agents.assignment.scram import (bottleneck_assignment, bottleneck_of_points, mmd_msd2_assignment,
                                     mmd_msd2_points, mmdr_assignment, mmdr_points)
from tests.agents.assignment.assignment_oracle import complete_assignments, lexicographic_key

NO_SCALE = np.empty(0)


@pytest.mark.parametrize("seed", range(4))
def test_distinct_lengths_give_the_brute_force_optimum(seed: int) -> None:
    rng = np.random.default_rng(seed)
    for _ in range(60):
        n = int(rng.integers(1, 6))
        m = int(rng.integers(n, 7))
        lengths = rng.uniform(0.0, 50.0, (n, m))
        best = min(complete_assignments(lengths), key=lambda pair: lexicographic_key(pair[1]))
        col_of_row, bottleneck, tied = delete_longest_first(lengths, True)
        assert not tied
        np.testing.assert_array_equal(col_of_row, best[0])
        assert bottleneck == best[1].max()
        assert delete_longest_first(lengths, False)[1] == bottleneck  # stopped at the bottleneck


def test_a_tie_at_a_visited_length_is_reported_and_the_bottleneck_still_holds() -> None:
    # Two robots equally far from two targets: two optima, the visit's order would choose.
    lengths = np.array([[1.0, 5.0], [5.0, 1.0]])
    _, bottleneck, tied = delete_longest_first(np.array([[5.0, 1.0], [1.0, 5.0]]), True)
    assert bottleneck == 1.0 and tied
    col_of_row, bottleneck, tied = delete_longest_first(lengths, True)
    assert bottleneck == 1.0 and tied and list(col_of_row) == [0, 1]
    _, _, tied = delete_longest_first(np.array([[1.0, 2.0], [3.0, 4.0]]), True)
    assert not tied


@pytest.mark.parametrize("seed", range(3))
def test_point_forms_match_the_general_method_bit_for_bit(seed: int) -> None:
    """mmdr_points, bottleneck_of_points and mmd_msd2_points (which take the fast path when
    nothing ties) give exactly what the general graph method gives, on grids full of ties,
    coinciding targets and scaled robots too."""
    rng = np.random.default_rng(100 + seed)
    for t in range(400):
        n = int(rng.integers(1, 12))
        m = int(rng.integers(n, 13))
        robots, targets = rng.uniform(-50, 50, (n, 2)), rng.uniform(-50, 50, (m, 2))
        if t % 3 == 0:
            robots, targets = np.round(robots / 20) * 20, np.round(targets / 20) * 20
        if t % 7 == 0:
            targets[: min(m, 3)] = targets[0]
        scale = rng.uniform(0.8, 1.2, n) if t % 2 else NO_SCALE
        lengths, squared = dense_distances(robots, targets)
        if scale.size:
            lengths = lengths * scale[:, None]
            squared = lengths * lengths
        np.testing.assert_array_equal(mmdr_points(robots, targets, scale), mmdr_assignment(lengths))
        np.testing.assert_array_equal(mmd_msd2_points(robots, targets, scale), mmd_msd2_assignment(lengths, squared))
        plain = dense_distances(robots, targets)[0]
        assert bottleneck_of_points(robots, targets)[0] == bottleneck_assignment(plain)[0]
