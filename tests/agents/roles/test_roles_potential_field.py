"""Each potential-field term: its gradient against a finite difference of its potential, its
direction where the soccer sense is plain, its bound and its reach; then the composed field
and the descent step."""

from __future__ import annotations

import numpy as np
import pytest

from agents.roles import FieldParams, RoleError
from agents.roles import potential_field as pf
from tests.agents.roles.role_situations import HALF_LENGTH, HALF_WIDTH, OPP_GOAL, OWN_GOAL, random_field_points

BALL = np.array([10.0, 5.0])
AREA = (16.5, 20.16)
SIDES = np.array([1.0, -1.0, 0.0, 1.0, -1.0, 1.0])

# name -> (term of points, bound on the gradient's norm per player)
TERMS = {
    "walls": (lambda p: pf.walls(p, HALF_LENGTH, HALF_WIDTH, 3.0, 3.0), np.sqrt(2) * 3.0 / 3.0),
    "own_area": (lambda p: pf.own_area(p, HALF_LENGTH, *AREA, 3.0, 2.0), 3.0 / 2.0),
    "teammates": (lambda p: pf.teammates(p, 2.0, 5.0), 5 * 2.0 / 5.0),
    "ball_distance": (lambda p: pf.ball_distance(p, BALL, 0.4, 12.0, 2.0), 0.4),
    "forward_bias": (lambda p: pf.forward_bias(p, BALL, 0.5, 3.0), 0.5),
    "defensive_bias": (lambda p: pf.defensive_bias(p, BALL, 0.5, 5.0), 0.5),
    "corridor_clear": (lambda p: pf.corridor_clear(p, BALL, OPP_GOAL, 3.0, 4.0), 3.0 / 4.0),
    "corridor_block": (lambda p: pf.corridor_block(p, BALL, OWN_GOAL, 0.3, 1.0), 0.3),
    "side": (lambda p: pf.side(p, SIDES, 0.3), 0.3),
    "anchor": (lambda p: pf.anchor(p, ANCHORS, 0.5, 2.0), 0.5),
}
ANCHORS = np.array([[0.0, 20.0], [-20.0, -15.0], [15.0, 0.0], [30.0, 25.0], [-40.0, 3.0], [12.5, 6.0]])


def sample_points(rng: np.random.Generator) -> np.ndarray:
    """Six points: four where terms are active (area, corner, near ball and team-mate, in the
    shooting lane) and two anywhere."""
    pts = random_field_points(rng, 6)
    pts[0] = (-50.5 + rng.uniform(-1, 1), 2.0 + rng.uniform(-1, 1))  # inside our penalty area
    pts[1] = (51.0 + rng.uniform(-1, 1), 33.0 + rng.uniform(-2, 0.5))  # near a corner
    pts[2] = (12.0 + rng.uniform(-1, 1), 6.0 + rng.uniform(-1, 1))  # near the ball
    pts[3] = pts[2] + rng.uniform(-2, 2, 2)  # near a team-mate
    pts[4] = (30.0 + rng.uniform(-1, 1), 2.5 + rng.uniform(-2, 2))  # in the shooting corridor
    return pts


def numeric_gradient(term, points: np.ndarray, h: float = 1e-6) -> np.ndarray:
    """Central differences of each player's potential in its own coordinates."""
    grad = np.empty_like(points)
    for i in range(points.shape[0]):
        for axis in range(2):
            plus, minus = points.copy(), points.copy()
            plus[i, axis] += h
            minus[i, axis] -= h
            grad[i, axis] = (term(plus)[0][i] - term(minus)[0][i]) / (2 * h)
    return grad


@pytest.mark.parametrize("name", list(TERMS))
def test_gradient_matches_a_finite_difference_and_stays_bounded(name: str) -> None:
    term, bound = TERMS[name]
    rng = np.random.default_rng(7)
    active = 0
    for _ in range(40):
        points = sample_points(rng)
        pot, grad = term(points)
        assert pot.shape == (6,) and grad.shape == (6, 2)
        assert grad == pytest.approx(numeric_gradient(term, points), abs=1e-5)
        assert (np.hypot(*grad.T) <= bound + 1e-12).all()
        assert (pot >= 0.0).all()
        active += int(np.count_nonzero(np.hypot(*grad.T)))
    assert active > 0, "the sample never reaches the term"


def test_walls_push_inwards_near_the_lines_and_nowhere_else() -> None:
    pot, grad = pf.walls(np.array([[51.5, 33.5], [-51.0, 0.0], [0.0, -32.0], [0.0, 0.0]]), HALF_LENGTH, HALF_WIDTH,
                         3.0, 3.0)
    assert grad[0, 0] > 0 and grad[0, 1] > 0  # descending moves away from both lines at the corner
    assert grad[1].tolist() == [-1.0, 0.0] and grad[2].tolist() == [0.0, -1.0]
    assert pot[1] == pytest.approx(3.0 * (1 - 1.5 / 3.0))
    assert pot[3] == 0.0 and grad[3].tolist() == [0.0, 0.0]


def test_own_area_pushes_out_through_the_nearer_exit_even_deep_inside() -> None:
    points = np.array([[-37.0, 0.0], [-50.0, 19.0], [-50.0, 1.0], [-35.0, 0.0], [-20.0, 0.0]])
    pot, grad = pf.own_area(points, HALF_LENGTH, *AREA, 3.0, 2.0)
    assert grad[0].tolist() == [-1.5, 0.0]  # 1 m inside the front line: out through the front
    assert grad[1, 1] < 0 and grad[1, 0] == 0  # near the flank: out sideways
    assert np.hypot(*grad[2]) == pytest.approx(1.5)  # deep inside: still pushed out
    assert pot[2] > pot[0] > pot[3] > 0  # the deeper, the higher; 1 m outside still in reach
    assert pot[4] == 0.0 and grad[4].tolist() == [0.0, 0.0]


def test_teammates_repel_within_reach_only_and_separate_players_on_one_spot() -> None:
    pot, grad = pf.teammates(np.array([[0.0, 0.0], [1.0, 0.0], [20.0, 0.0]]), 2.0, 5.0)
    assert grad[0, 0] > 0 > grad[1, 0]  # descending moves 0 to -x and 1 to +x
    assert pot[0] == pytest.approx(2.0 * 0.8) and pot[2] == 0.0
    _, grad = pf.teammates(np.array([[3.0, 3.0], [3.0, 3.0]]), 2.0, 5.0)
    assert grad[0, 1] < 0 < grad[1, 1]  # the lower row steps to +y, the other to -y


def test_attractions_fade_at_their_attractor() -> None:
    anchors = np.array([[0.0, 0.0], [0.0, 0.0], [0.0, 0.0]])
    points = np.array([[0.5, 0.0], [10.0, 0.0], [0.0, 0.0]])
    _, grad = pf.anchor(points, anchors, 0.5, 2.0)
    assert grad[0, 0] == pytest.approx(0.5 * 0.5 / 2.0)  # inside the soft radius: proportional
    assert grad[1, 0] == pytest.approx(0.5)  # far: the full weight
    assert grad[2].tolist() == [0.0, 0.0]
    _, grad = pf.ball_distance(np.array([[22.0, 5.0], [15.0, 5.0], [40.0, 5.0]]), BALL, 0.4, 12.0, 2.0)
    assert grad[0].tolist() == [0.0, 0.0]  # on the equilibrium circle
    assert grad[1, 0] < 0 < grad[2, 0]  # too close: step away from the ball; too far: towards it


def test_biases_and_corridors_point_the_soccer_way() -> None:
    _, grad = pf.forward_bias(np.array([[5.0, 0.0], [20.0, 0.0]]), BALL, 0.5, 3.0)
    assert grad[:, 0].tolist() == [-0.5, 0.0]  # behind ball_x + 3: step forwards
    _, grad = pf.defensive_bias(np.array([[8.0, 0.0], [0.0, 0.0]]), BALL, 0.5, 5.0)
    assert grad[:, 0].tolist() == [0.5, 0.0]  # upfield of ball_x - 5: step back
    _, grad = pf.corridor_clear(np.array([[30.0, 3.0], [30.0, 20.0]]), BALL, OPP_GOAL, 3.0, 4.0)
    assert grad[0, 1] < 0  # in the lane, on its +y side (the lane is at y ~ 2.7 there): step to +y
    assert grad[1].tolist() == [0.0, 0.0]
    _, grad = pf.corridor_block(np.array([[-20.0, 10.0], [-20.0, -10.0]]), BALL, OWN_GOAL, 0.3, 1.0)
    assert grad[0, 1] > 0 > grad[1, 1]  # step down onto the ball-goal line from either side


def test_side_keeps_a_supporter_on_its_half_and_the_sides_follow_anchors_then_the_ball() -> None:
    _, grad = pf.side(np.array([[0.0, -3.0], [0.0, 3.0], [0.0, 3.0]]), np.array([1.0, 1.0, 0.0]), 0.3)
    assert grad[:, 1].tolist() == [-0.3, 0.0, 0.0]
    anchors = np.array([[0.0, 10.0], [0.0, -10.0], [20.0, 1.0], [-20.0, 1.0]])
    offensive = np.array([True, False, True, False])
    assert pf.supporter_sides(anchors, offensive, np.array([0.0, 12.0]), 5.0).tolist() == [1, -1, -1, 0]
    assert pf.supporter_sides(anchors, offensive, np.array([0.0, -12.0]), 5.0).tolist() == [1, -1, 1, 0]
    assert pf.supporter_sides(anchors, offensive, np.array([0.0, 2.0]), 5.0).tolist() == [1, -1, 0, 0]


def _distinct_params() -> FieldParams:
    """Every parameter a different value, so a kernel reading the wrong one cannot go unnoticed."""
    from dataclasses import fields

    return FieldParams(**{f.name: 0.7 + 0.31 * i for i, f in enumerate(fields(FieldParams))})


def test_the_kernels_read_each_parameter_by_its_name() -> None:
    from dataclasses import astuple, fields

    for params in (FieldParams(), _distinct_params()):
        record = params.as_record()
        assert record.shape == (1,) and record.dtype.names == tuple(f.name for f in fields(FieldParams))
        assert tuple(record[0].tolist()) == astuple(params)


@pytest.mark.parametrize("params", [FieldParams(), _distinct_params()], ids=["defaults", "distinct"])
def test_the_field_sums_the_terms_of_each_supporters_kind_and_situation(params: FieldParams) -> None:
    rng = np.random.default_rng(3)
    arr = params.as_record()
    points = sample_points(rng)
    offensive = np.array([True, False, True, False, True, False])
    for attacking in (True, False):
        pot, grad = pf.supporter_field(points, ANCHORS, offensive, attacking, BALL, OWN_GOAL, OPP_GOAL,
                                       HALF_LENGTH, HALF_WIDTH, *AREA, arr)
        p = params
        common = [
            pf.walls(points, HALF_LENGTH, HALF_WIDTH, p.wall_weight, p.wall_reach),
            pf.own_area(points, HALF_LENGTH, *AREA, p.area_weight, p.area_reach),
            pf.teammates(points, p.teammate_weight, p.teammate_reach),
            pf.side(points, pf.supporter_sides(ANCHORS, offensive, BALL, p.side_threshold), p.side_weight),
            pf.anchor(points, ANCHORS, p.anchor_weight, p.anchor_soft),
        ]
        attack = [pf.ball_distance(points, BALL, p.ball_weight, p.ball_distance, p.ball_soft),
                  pf.forward_bias(points, BALL, p.forward_weight, p.forward_offset)]
        defend = [pf.defensive_bias(points, BALL, p.defensive_weight, p.defensive_offset)]
        if attacking:
            attack.append(pf.corridor_clear(points, BALL, OPP_GOAL, p.corridor_clear_weight, p.corridor_width))
        else:
            defend.append(pf.corridor_block(points, BALL, OWN_GOAL, p.corridor_block_weight, p.corridor_block_soft))
        want_pot = sum(t[0] for t in common) + np.where(offensive, sum(t[0] for t in attack),
                                                        sum(t[0] for t in defend))
        want_grad = sum(t[1] for t in common) + np.where(offensive[:, None], sum(t[1] for t in attack),
                                                         sum(t[1] for t in defend))
        assert pot == pytest.approx(want_pot) and grad == pytest.approx(want_grad)


def test_descend_steps_downhill_no_further_than_max_step_and_stays_in_the_field() -> None:
    arr = FieldParams(lookahead=3.0, max_step=5.0, field_margin=1.0).as_record()
    points = np.array([[0.0, 0.0], [10.0, 10.0], [3.0, 3.0], [51.8, 0.0]])
    anchors = np.array([[30.0, 0.0], [10.5, 10.0], [3.0, 3.0], [60.0, 0.0]])
    pot, grad = pf.anchor(points, anchors, 1.0, 2.0)
    moved = pf.descend(points, grad, HALF_LENGTH, HALF_WIDTH, arr)
    after, _ = pf.anchor(moved, anchors, 1.0, 2.0)
    assert after[0] < pot[0] and after[1] < pot[1]
    steps = np.hypot(*(moved - points).T)
    assert steps[0] == pytest.approx(3.0)  # gradient 1 x lookahead 3 m, towards the anchor
    assert moved[0, 0] == pytest.approx(3.0)
    assert steps[1] == pytest.approx(3.0 * 0.25)  # inside the soft radius: gradient 0.25
    assert steps[2] == 0.0  # no gradient, no step
    assert moved[3, 0] == pytest.approx(HALF_LENGTH - 1.0)  # kept a metre inside the goal line
    steep = pf.descend(np.zeros((1, 2)), np.array([[0.0, -4.0]]), HALF_LENGTH, HALF_WIDTH, arr)
    assert steep.tolist() == [[0.0, 5.0]]  # 4 x 3 m = 12 m, capped at max_step


def test_field_parameters_are_checked() -> None:
    with pytest.raises(RoleError, match="FieldParams.anchor_weight must be a finite number >= 0"):
        FieldParams(anchor_weight=-1.0)
    with pytest.raises(RoleError, match="FieldParams.corridor_width must be > 0"):
        FieldParams(corridor_width=0.0)
    assert FieldParams().as_record().dtype.names == tuple(FieldParams.__dataclass_fields__)
