"""Shooting: a shot is taken when the goal is open and in range, not from midfield and not
when the angle is blocked; the aim avoids the goalkeeper."""

from __future__ import annotations

import numpy as np

from agents.skills import MotionModel, SkillContext, aim_points, best_shot
from tests.agents.skills.skill_views import CONFIG, HL, ball_at, make_view

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
SHOOTER = 9
GOAL_HALF = CONFIG.field.goal_width / 2


def shooting_view(ball_x: float, ball_y: float = 0.0, keeper=(HL - 0.5, 0.0), others=None):
    """Our shooter just behind the ball; their goalkeeper at ``keeper``; their other players
    along the touchline (or at ``others``)."""
    opp = {0: keeper}
    if others is not None:
        opp.update(others)
    return make_view(own={SHOOTER: (ball_x - 0.5, ball_y)}, opp=opp, ball=(ball_x, ball_y))


def test_aim_points_lie_between_the_posts() -> None:
    aims = aim_points(MODEL)
    assert np.all(aims[:, 0] == HL)
    assert np.all(np.abs(aims[:, 1]) < GOAL_HALF - CONFIG.physics.ball_radius)


def test_open_goal_in_range_is_a_shot() -> None:
    view = shooting_view(HL - 15.0, 0.0, keeper=(HL - 8.0, 12.0))  # the goalkeeper is out of position
    shot = best_shot(CTX, view, SHOOTER)
    assert shot is not None and shot.take
    assert shot.opponent_cycle > shot.cross_cycle
    # The ball really gets to the goal line between the posts by the predicted cycle.
    line = ball_at(CONFIG, view.ball, shot.ball_vel, shot.cross_cycle)
    before = ball_at(CONFIG, view.ball, shot.ball_vel, shot.cross_cycle - 1)
    assert before[0] < HL <= line[0]
    assert abs(line[1]) < GOAL_HALF


def test_close_shot_goes_to_the_side_the_goalkeeper_is_not() -> None:
    view = shooting_view(HL - 10.0, 0.0, keeper=(HL - 1.0, 2.0))
    shot = best_shot(CTX, view, SHOOTER)
    assert shot.take and shot.aim[1] < -3.0
    # From 15 m a goalkeeper standing in the middle of its goal reaches every corner in time.
    view = shooting_view(HL - 15.0, 0.0, keeper=(HL - 1.0, 0.0))
    assert not best_shot(CTX, view, SHOOTER).take


def test_no_shot_from_midfield() -> None:
    assert best_shot(CTX, shooting_view(0.0), SHOOTER) is None


def test_no_shot_when_the_angle_is_blocked() -> None:
    wall = {i: (HL - 12.0, -6.0 + 1.5 * (i - 1)) for i in range(1, 10)}  # y from -6 to 6
    view = shooting_view(HL - 15.0, 0.0, others=wall)
    shot = best_shot(CTX, view, SHOOTER)
    assert shot is not None and not shot.take
    assert shot.opponent_cycle <= shot.cross_cycle


def test_tight_angle_near_the_goal_line_scores_lower() -> None:
    central = best_shot(CTX, shooting_view(HL - 12.0, 0.0), SHOOTER)
    wide = best_shot(CTX, shooting_view(HL - 3.0, 25.0), SHOOTER)
    assert central.score > wide.score
