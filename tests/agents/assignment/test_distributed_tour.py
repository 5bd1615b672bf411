"""The building blocks of ETSP ASSGMT: the short closed tour and the packed availability bits."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from scipy.sparse.csgraph import minimum_spanning_tree
from scipy.spatial.distance import cdist

from agents.assignment.bitset import clear_bit, clear_cyclic, full_rows, next_set_cyclic, prev_set_cyclic, set_bit
from agents.assignment.etsp import etsp_tour, tour_length


def _mst_weight(points: np.ndarray) -> float:
    return float(minimum_spanning_tree(cdist(points, points)).sum())


@pytest.mark.parametrize("n", [1, 2, 3, 4, 7, 50, 400])
def test_tour_is_a_permutation_from_zero_within_twice_the_spanning_tree(n):
    points = np.random.default_rng(n).uniform(0, 100, (n, 2))
    order = etsp_tour(points)
    assert sorted(order.tolist()) == list(range(n))
    assert order[0] == 0
    if n > 1:
        # The minimum spanning tree is shorter than the optimal tour, so this is "within 2 x optimal".
        assert tour_length(points, order) <= 2 * _mst_weight(points) + 1e-9


def test_tour_is_optimal_on_small_instances_often_and_never_worse_than_twice():
    rng = np.random.default_rng(3)
    optimal_hits = 0
    for _ in range(30):
        points = rng.uniform(0, 10, (7, 2))
        best = min(tour_length(points, np.array((0,) + p)) for p in itertools.permutations(range(1, 7)))
        found = tour_length(points, etsp_tour(points))
        assert found <= 2 * best + 1e-9
        optimal_hits += found <= best + 1e-9
    assert optimal_hits >= 20


def test_points_in_convex_position_get_their_polygon():
    angles = np.random.default_rng(0).permutation(np.linspace(0, 2 * np.pi, 60, endpoint=False))
    points = np.c_[np.cos(angles), np.sin(angles)] * 50 + 50
    order = etsp_tour(points)
    polygon = np.argsort(angles)
    assert tour_length(points, order) == pytest.approx(tour_length(points, polygon))


def test_collinear_points_are_toured_end_to_end_and_back():
    points = np.c_[np.random.default_rng(1).permutation(np.arange(30.0)), np.full(30, 5.0)]
    assert tour_length(points, etsp_tour(points)) == pytest.approx(2 * 29.0)


def test_tour_is_deterministic():
    points = np.random.default_rng(8).uniform(0, 1, (300, 2))
    np.testing.assert_array_equal(etsp_tour(points), etsp_tour(points.copy()))


@pytest.mark.parametrize("width", [1, 5, 63, 64, 65, 200])
def test_packed_bits_match_a_boolean_reference(width):
    rng = np.random.default_rng(width)
    bits, counts = full_rows(2, width)
    reference = np.ones((2, width), dtype=bool)
    for _ in range(300):
        row = int(rng.integers(2))
        op = rng.integers(3)
        j = int(rng.integers(width))
        if op == 0:
            length = int(rng.integers(0, width + 1))
            clear_cyclic(bits, counts, row, j, length, width)
            reference[row, (j + np.arange(length)) % width] = False
        elif op == 1:
            clear_bit(bits, counts, row, j)
            reference[row, j] = False
        else:
            set_bit(bits, counts, row, j)
            reference[row, j] = True
        assert counts[row] == reference[row].sum()
        start = int(rng.integers(width))
        ahead = [(start + s) % width for s in range(width) if reference[row, (start + s) % width]]
        behind = [(start - s) % width for s in range(width) if reference[row, (start - s) % width]]
        assert next_set_cyclic(bits, row, start, width) == (ahead[0] if ahead else -1)
        assert prev_set_cyclic(bits, row, start, width) == (behind[0] if behind else -1)
