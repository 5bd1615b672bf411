"""Each potential-field term's gradient against a finite difference of its potential, and its
direction and bounds where the soccer sense is plain."""

from __future__ import annotations

import numpy as np
import pytest

from agents.roles import potential_field as pf

BALL = np.array([10.0, 5.0])
OWN_GOAL, OPP_GOAL = np.array([-52.5, 0.0]), np.array([52.5, 0.0])
ANCHORS = np.array([[0.0, 20.0], [-20.0, -15.0], [15.0, 0.0], [30.0, 25.0], [-40.0, 3.0]])

TERMS = {
    "walls": lambda p: pf.walls(p, 52.5, 34.0, 3.0, 3.0),
    "own_area": lambda p: pf.own_area(p, 52.5, 16.5, 20.16, 3.0, 2.0),
    "teammates": lambda p: pf.teammates(p, 2.0, 5.0),
    "ball_distance": lambda p: pf.ball_distance(p, BALL, 0.4, 12.0),
    "forward_bias": lambda p: pf.forward_bias(p, BALL, 0.5, 3.0),
    "defensive_bias": lambda p: pf.defensive_bias(p, BALL, 0.5, 5.0),
    "corridor_clear": lambda p: pf.corridor_clear(p, BALL, OPP_GOAL, 1.0, 4.0),
    "corridor_block": lambda p: pf.corridor_block(p, BALL, OWN_GOAL, 0.3),
    "side": lambda p: pf.side(p, ANCHORS, 0.3, 5.0),
    "anchor": lambda p: pf.anchor(p, ANCHORS, 1.0),
}


def sample_points(rng: np.random.Generator) -> np.ndarray:
    pts = np.column_stack((rng.uniform(-52, 52, 5), rng.uniform(-33.5, 33.5, 5)))
    pts[0] = (-50.5, 2.0)  # inside our penalty area, near the goal line
    pts[1] = (51.0, 33.0)  # near a corner
    pts[2] = (12.0, 6.0)  # near the ball
    pts[3] = (13.2, 6.5)  # near a team-mate (off the forward bias's kink at x = 13)
    return pts


@pytest.mark.parametrize("name", list(TERMS))
def test_gradient_matches_a_finite_difference(name: str) -> None:
    term = TERMS[name]
    rng = np.random.default_rng(7)
    h = 1e-5
    for _ in range(20):
        points = sample_points(rng)
        _, grad = term(points)
        for axis in (0, 1):
            step = np.zeros_like(points)
            step[:, axis] = h
            if name == "teammates":  # the potential of player i depends on the others too: move one at a time
                numeric = np.empty(points.shape[0])
                for i in range(points.shape[0]):
                    plus, minus = points.copy(), points.copy()
                    plus[i, axis] += h
                    minus[i, axis] -= h
                    numeric[i] = (term(plus)[0][i] - term(minus)[0][i]) / (2 * h)
            else:
                numeric = (term(points + step)[0] - term(points - step)[0]) / (2 * h)
            assert grad[:, axis] == pytest.approx(numeric, abs=1e-4)


def test_terms_push_the_right_way_and_stay_bounded() -> None:
    corner = np.array([[51.5, 33.5]])
    pot, grad = pf.walls(corner, 52.5, 34.0, 3.0, 3.0)
    assert grad[0, 0] > 0 and grad[0, 1] > 0  # descending moves away from both lines
    assert pot[0] <= 2 * 3.0
    inside = np.array([[-50.0, 1.0]])
    pot, grad = pf.own_area(inside, 52.5, 16.5, 20.16, 3.0, 2.0)
    assert pot[0] == pytest.approx(6.0) and grad[0].tolist() == [0.0, 0.0]  # capped deep inside
    edge = np.array([[-37.0, 0.0]])  # 1 m inside the front line
    _, grad = pf.own_area(edge, 52.5, 16.5, 20.16, 3.0, 2.0)
    assert grad[0, 0] < 0  # descending moves out through the front
    close = np.array([[0.0, 0.0], [1.0, 0.0]])
    pot, grad = pf.teammates(close, 2.0, 5.0)
    assert grad[0, 0] > 0 > grad[1, 0] and pot.max() <= 2.0
    lane = np.array([[30.0, 3.0]])
    _, grad = pf.corridor_clear(lane, BALL, OPP_GOAL, 1.0, 4.0)
    assert grad[0, 1] < 0  # step away from the shooting lane (towards +y)
    _, grad = pf.corridor_block(np.array([[-20.0, 10.0]]), BALL, OWN_GOAL, 0.3)
    assert grad[0, 1] > 0  # step down towards the ball-goal line


def test_descend_steps_downhill_and_no_further_than_max_step() -> None:
    params = pf.FieldParams()
    points = np.array([[0.0, 0.0], [10.0, 10.0]])
    anchors = np.array([[30.0, 0.0], [16.0, 10.0]])
    pot, grad = pf.anchor(points, anchors, 1.0)
    moved = pf.descend(points, grad, params)
    after, _ = pf.anchor(moved, anchors, 1.0)
    assert (after < pot).all()
    assert np.hypot(*(moved - points).T).max() <= params.max_step + 1e-12
