"""Interpolation: exact at samples, linear in triangles, continuous everywhere."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import formations
from formations import Formation
from formations.interpolation_kernels import value_kernel


def builtin_formation() -> Formation:
    return formations.load_builtin("4-3-3").formation("attack")


@pytest.fixture(params=["random", "builtin"])
def formation(request, random_formation) -> Formation:
    return random_formation if request.param == "random" else builtin_formation()


def test_every_sample_is_reproduced(formation):
    for ball, expected in zip(formation.balls, formation.sample_positions):
        np.testing.assert_allclose(formation.positions(ball), expected, rtol=0, atol=1e-9)
    np.testing.assert_allclose(formation.positions_many(formation.balls), formation.sample_positions, rtol=0, atol=1e-9)


def test_linear_inside_each_triangle(formation):
    rng = np.random.default_rng(3)
    balls = formation.balls
    values = formation.sample_positions
    for corners in formation.triangles:
        weights = rng.dirichlet((1.0, 1.0, 1.0), size=4)
        points = weights @ balls[corners]
        expected = np.einsum("kc,crd->krd", weights, values[corners])
        got_many = formation.positions_many(points)
        np.testing.assert_allclose(got_many, expected, rtol=0, atol=1e-8)
        for point, want in zip(points, expected):
            np.testing.assert_allclose(formation.positions(point), want, rtol=0, atol=1e-8)


def _edge_normal(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    direction = (b - a) / np.hypot(*(b - a))
    return np.array([-direction[1], direction[0]])


def test_continuous_across_interior_edges(formation):
    hull = {frozenset(e) for e in formation.hull_edges.tolist()}
    edges = {frozenset((t[i], t[j])) for t in formation.triangles.tolist() for i, j in ((0, 1), (1, 2), (0, 2))}
    interior = [tuple(e) for e in edges - hull]
    assert interior
    offset = 1e-7
    for i, j in interior:
        a, b = formation.balls[i], formation.balls[j]
        normal = _edge_normal(a, b)
        for s in (0.25, 0.5, 0.75):
            point = a + s * (b - a)
            left = formation.positions(point + offset * normal)
            right = formation.positions(point - offset * normal)
            # A jump would show as a difference far above Lipschitz * 2e-7.
            assert np.max(np.abs(left - right)) < 1e-4


def test_continuous_across_the_hull_boundary_and_constant_along_outward_normals(formation):
    for i, j in formation.hull_edges.tolist():
        a, b = formation.balls[i], formation.balls[j]
        normal = _edge_normal(a, b)
        centroid = formation.balls.mean(axis=0)
        if np.dot(normal, a - centroid) < 0:
            normal = -normal  # point outwards
        for s in (0.1, 0.5, 0.9):
            point = a + s * (b - a)
            on_edge = (1 - s) * formation.sample_positions[i] + s * formation.sample_positions[j]
            inside = formation.positions(point - 1e-7 * normal)
            outside = formation.positions(point + 1e-7 * normal)
            assert np.max(np.abs(inside - outside)) < 1e-4
            for distance in (0.5, 5.0, 30.0):
                far = point + distance * normal
                np.testing.assert_allclose(formation.positions(far), on_edge, rtol=0, atol=1e-8)
                np.testing.assert_allclose(formation.positions_many(far[None])[0], on_edge, rtol=0, atol=1e-8)


def test_outside_uses_the_nearest_hull_point(random_formation):
    rng = np.random.default_rng(11)
    points = rng.uniform(-300.0, 300.0, (300, 2))
    for point in points:
        projected = random_formation.nearest_covered_ball(point)
        np.testing.assert_allclose(random_formation.positions(point), random_formation.positions(projected), atol=1e-8)


@settings(max_examples=300, deadline=None, derandomize=True)
@given(
    x=st.floats(-90.0, 90.0),
    y=st.floats(-70.0, 70.0),
    dx=st.floats(-1e-6, 1e-6),
    dy=st.floats(-1e-6, 1e-6),
)
def test_single_and_vectorised_agree_and_are_continuous(random_formation, x, y, dx, dy):
    single = random_formation.positions((x, y))
    many = random_formation.positions_many(np.array([[x, y], [x + dx, y + dy]]))
    np.testing.assert_allclose(single, many[0], rtol=0, atol=1e-9)
    assert np.max(np.abs(many[0] - many[1])) < 1e-3


def test_vectorised_matches_single_on_a_large_batch():
    formation = builtin_formation()
    rng = np.random.default_rng(5)
    balls = np.column_stack((rng.uniform(-70, 70, 3000), rng.uniform(-50, 50, 3000)))
    many = formation.positions_many(balls)
    single = np.array([formation.positions(b) for b in balls])
    np.testing.assert_allclose(single, many, rtol=0, atol=1e-9)
    each = np.empty_like(single)
    for ball, out in zip(balls, each):  # the compiled query the decentralised team calls: bit for bit
        value_kernel(ball[0], ball[1], formation.query_tables, out.reshape(-1))
    np.testing.assert_array_equal(each, single)


def test_query_shapes_and_results_are_fresh_arrays(random_formation):
    first = random_formation.positions((1.0, 2.0))
    assert first.shape == (11, 2) and first.dtype == np.float64
    first[:] = 0.0
    assert not np.allclose(random_formation.positions((1.0, 2.0)), 0.0)
    assert random_formation.positions_many(np.zeros((0, 2))).shape == (0, 11, 2)
    assert random_formation.positions_many((3.0, 4.0)).shape == (1, 11, 2)


def test_non_finite_ball_is_rejected(random_formation):
    with pytest.raises(ValueError, match="finite"):
        random_formation.positions((float("nan"), 0.0))
    with pytest.raises(ValueError, match="finite"):
        random_formation.positions_many(np.array([[0.0, 0.0], [np.inf, 1.0]]))
    with pytest.raises(ValueError, match="shape"):
        random_formation.positions_many(np.zeros((3, 3)))
    with pytest.raises(ValueError, match=r"two numbers \(x, y\), got 3"):
        random_formation.positions((1.0, 2.0, 3.0))


def test_far_outside_the_field_is_the_nearest_hull_edge_value():
    formation = builtin_formation()
    far = np.array([[200.0, -150.0], [-1e6, 3e5], [0.0, 1e9]])
    hull_points = np.array([formation.nearest_covered_ball(b) for b in far])
    # The nearest points of the field-shaped hull: a corner, a corner, the touchline.
    np.testing.assert_allclose(hull_points, [[52.5, -34.0], [-52.5, 34.0], [0.0, 34.0]], atol=1e-9)
    np.testing.assert_allclose(formation.positions_many(far), formation.positions_many(hull_points), atol=1e-9)
    for ball, hull_point in zip(far, hull_points):
        np.testing.assert_allclose(formation.positions(ball), formation.positions(hull_point), atol=1e-9)
