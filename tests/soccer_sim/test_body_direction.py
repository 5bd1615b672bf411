"""The one body-direction model (soccer_sim.body): at rest a player faces the ball; moving, it
faces its motion turned towards the ball by at most rcssserver's largest turn at its speed."""

from __future__ import annotations

import math

import pytest

from soccer_sim.body import DEFAULT_INERTIA_MOMENT, ball_angle_to_body, facing

MU = DEFAULT_INERTIA_MOMENT


def angle_of(vector: tuple[float, float]) -> float:
    return math.degrees(math.atan2(vector[1], vector[0]))


def test_a_player_at_rest_faces_the_ball():
    assert angle_of(facing(0.0, 0.0, 0.0, 1.0, MU)) == pytest.approx(90.0)
    assert angle_of(facing(0.0, 0.0, -1.0, 0.0, MU)) == pytest.approx(180.0)
    assert ball_angle_to_body(0.0, 0.0, -0.5, 0.3, MU) == pytest.approx(0.0, abs=1e-12)


def test_a_slow_player_turns_all_the_way_to_the_ball():
    # at 0.1 m/cycle the largest turn is 180 / 1.5 = 120 degrees: a ball 90 degrees off is faced
    assert angle_of(facing(0.1, 0.0, 0.0, 1.0, MU)) == pytest.approx(90.0)


def test_a_sprinter_turns_only_as_far_as_its_speed_allows():
    # at 1.0 m/cycle the largest turn is 180 / 6 = 30 degrees, towards the ball's side
    assert angle_of(facing(1.0, 0.0, 0.0, 1.0, MU)) == pytest.approx(30.0)
    assert angle_of(facing(1.0, 0.0, 0.0, -1.0, MU)) == pytest.approx(-30.0)
    assert math.degrees(ball_angle_to_body(1.0, 0.0, -1.0, 0.0, MU)) == pytest.approx(150.0)


def test_the_direction_is_a_unit_vector_and_defined_on_the_ball():
    fx, fy = facing(0.3, -0.4, 0.7, 0.2, MU)
    assert math.hypot(fx, fy) == pytest.approx(1.0)
    assert facing(0.0, 0.0, 0.0, 0.0, MU) == (1.0, 0.0)
    assert facing(0.0, 0.5, 0.0, 0.0, MU) == pytest.approx((0.0, 1.0))
    assert ball_angle_to_body(1.0, 0.0, 0.0, 0.0, MU) == 0.0
