"""Shots from the edge of the box: taken through a lane no outfield defender can close (the
goalkeeper left to save), not through a blocked one, not from too far, and only when the
shooter is being closed down when the params ask for it."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import MotionModel, ShotParams, SkillContext, best_shot, decide_on_ball, guard_position
from agents.skills.model import SkillInputError
from agents.teams.style import ATTACKING_DECISIONS
from tests.agents.skills.skill_views import CONFIG, HL, ball_at, make_view

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
SHOOTER = 9
GOAL_HALF = CONFIG.field.goal_width / 2
LANE = ShotParams(threshold=0.2, lane_range=20.0)


def edge_view(distance: float, y: float = 0.0, wall: bool = False, marker: float | None = None):
    """Our shooter behind the ball ``distance`` metres from their goal centre; their goalkeeper
    on its guard point; ``wall``: five defenders 3 m in front of the ball across the shot;
    ``marker``: a defender that many metres behind the shooter."""
    ball = np.array([HL - distance, y])
    guard = guard_position(MODEL, -ball)  # their goalkeeper guards their goal (mirrored frame)
    opp = {0: (-guard[0], -guard[1])}
    if wall:
        opp.update({k: (ball[0] + 3.0, y - 3.0 + 1.5 * (k - 1)) for k in range(1, 6)})
    if marker is not None:
        opp[6] = (ball[0] - 0.5 - marker, y)
    return make_view(own={SHOOTER: (ball[0] - 0.5, y)}, opp=opp, ball=ball)


@pytest.mark.parametrize("y", [0.0, 6.0])
def test_a_shot_from_18_m_through_an_open_lane_is_taken(y: float) -> None:
    view = edge_view(18.0, y)
    plain = best_shot(CTX, view, SHOOTER, ShotParams(threshold=0.2))
    assert plain is not None and not plain.take  # the goalkeeper covers it: no shot for its score alone
    shot = best_shot(CTX, view, SHOOTER, LANE)
    assert shot.take and shot.open_lane
    # It is on target: the unhindered ball crosses the goal line between the posts.
    line = ball_at(CONFIG, view.ball, shot.ball_vel, shot.cross_cycle)
    before = ball_at(CONFIG, view.ball, shot.ball_vel, shot.cross_cycle - 1)
    assert before[0] < HL <= line[0]
    t = (HL - before[0]) / (line[0] - before[0])
    assert abs(before[1] + t * (line[1] - before[1])) < GOAL_HALF


def test_no_shot_through_a_blocked_lane() -> None:
    shot = best_shot(CTX, edge_view(18.0, 0.0, wall=True), SHOOTER, LANE)
    assert shot is not None and not shot.take and not shot.open_lane


def test_no_open_lane_shot_beyond_its_range() -> None:
    shot = best_shot(CTX, edge_view(23.0, 0.0), SHOOTER, LANE)
    assert shot is not None and not shot.take


def test_an_open_lane_shot_waits_for_pressure_when_asked() -> None:
    view = edge_view(18.0, 0.0)
    params = ShotParams(threshold=0.2, lane_range=20.0, lane_pressure=4)
    assert not best_shot(CTX, view, SHOOTER, params, pressure=12).take  # left alone: carry it closer
    assert best_shot(CTX, view, SHOOTER, params, pressure=3).take


def test_the_team_shoots_from_the_edge_of_the_box_when_closed_down() -> None:
    pressed = decide_on_ball(CTX, edge_view(18.0, 0.0, marker=1.5), SHOOTER, ATTACKING_DECISIONS)
    assert pressed.action == "shoot" and pressed.plan.open_lane
    free = decide_on_ball(CTX, edge_view(18.0, 0.0), SHOOTER, ATTACKING_DECISIONS)
    assert free.action != "shoot"


def test_lane_params_are_checked() -> None:
    with pytest.raises(SkillInputError, match="lane_range"):
        ShotParams(lane_range=-1.0)
    with pytest.raises(SkillInputError, match="lane_score"):
        ShotParams(lane_score=1.5)
