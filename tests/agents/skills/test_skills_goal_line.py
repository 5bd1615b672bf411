"""The goal-line guard (agents.skills.goal_line): a few metres off the line with the ball in
front, at the near post on a wide ball, never outside the posts or beyond the ball."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import GoalLineParams, MotionModel, goal_line_guard
from tests.agents.skills.skill_views import CONFIG, HL

MODEL = MotionModel.even_sides(CONFIG)
P = GoalLineParams()
POST = MODEL.goal_half_width - P.post_margin


def test_ball_in_front_of_goal_keeper_stands_depth_out_on_the_axis() -> None:
    for bx in (0.0, -30.0, -HL + 12.0):
        x, y = goal_line_guard(MODEL, np.array([bx, 0.0]))
        assert x == pytest.approx(-HL + P.depth) and y == pytest.approx(0.0)


def test_wide_close_ball_puts_the_keeper_at_the_near_post_and_deep() -> None:
    x, y = goal_line_guard(MODEL, np.array([-HL + 3.0, 20.0]))
    assert y == pytest.approx(POST)  # near post, inside it
    assert x == pytest.approx(-HL + P.min_depth)
    x2, y2 = goal_line_guard(MODEL, np.array([-HL + 3.0, -20.0]))
    assert (x2, y2) == pytest.approx((x, -y))  # mirrored


def test_guard_lies_on_the_line_from_the_ball_to_the_pivot_behind_the_goal() -> None:
    ball = np.array([-HL + 20.0, 8.0])
    x, y = goal_line_guard(MODEL, ball)
    pivot = np.array([-HL - P.pivot_behind, 0.0])
    to_ball, to_point = ball - pivot, np.array([x, y]) - pivot
    assert to_ball[0] * to_point[1] - to_ball[1] * to_point[0] == pytest.approx(0.0, abs=1e-9)
    assert -HL + P.min_depth <= x < -HL + P.depth  # shallower than with the ball straight in front
    assert 0.0 < y < POST
    # It covers the near post better than the straight ball-goal line at the same depth would.
    assert y > ball[1] * (x + HL) / (ball[0] + HL)


@pytest.mark.parametrize("ball", [(-HL + 1.5, 0.0), (-HL + 0.5, 3.0), (-HL - 1.0, -4.0), (40.0, 30.0), (-HL, 0.0)])
def test_guard_stays_inside_the_posts_and_short_of_the_ball(ball) -> None:
    x, y = goal_line_guard(MODEL, np.array(ball))
    assert abs(y) <= POST + 1e-9
    assert -HL <= x <= -HL + P.depth + 1e-9
    if ball[0] > -HL + P.ball_gap:
        assert x <= ball[0] - P.ball_gap + 1e-9


def test_goal_line_params_reject_bad_values() -> None:
    with pytest.raises(ValueError, match="pivot_behind"):
        GoalLineParams(pivot_behind=-1.0)
    with pytest.raises(ValueError, match="ball"):
        goal_line_guard(MODEL, np.array([1.0, 2.0, 3.0]))
