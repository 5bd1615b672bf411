"""Goalkeeping: the guard point lies on the ball-goal line inside the goal area, the catch is
asked for only when the referee would grant it, and a held ball is played away from goal."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import MotionModel, SkillContext, distribute, guard_position, should_catch
from soccer_sim.state import PlayMode
from tests.agents.skills.skill_views import CONFIG, HL, make_view

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
FIELD = CONFIG.field
GOAL = np.array([-HL, 0.0])


@pytest.mark.parametrize("ball", [(0.0, 0.0), (-30.0, 20.0), (-45.0, -5.0), (-50.0, 15.0), (-40.0, 0.0),
                                  (-52.0, 30.0), (40.0, -30.0)])
def test_guard_point_lies_on_the_ball_goal_line_inside_the_goal_area(ball) -> None:
    point = guard_position(MODEL, np.array(ball))
    to_ball, to_point = np.asarray(ball) - GOAL, point - GOAL
    assert to_ball[0] * to_point[1] - to_ball[1] * to_point[0] == pytest.approx(0.0, abs=1e-9)
    assert to_point @ to_ball >= 0.0
    assert -HL <= point[0] <= -HL + FIELD.goal_area_length + 1e-9
    assert abs(point[1]) <= FIELD.goal_area_width / 2 + 1e-9


def test_goalkeeper_comes_out_as_the_ball_comes_closer() -> None:
    far = guard_position(MODEL, np.array([10.0, 0.0]))
    near = guard_position(MODEL, np.array([-41.0, 0.0]))  # 11.5 m out: closer than `near` (12 m)
    assert far == pytest.approx([-HL + 1.0, 0.0])  # the default depth when the ball is far
    assert near[0] > far[0]
    assert near == pytest.approx([-HL + FIELD.goal_area_length, 0.0])  # the front of the goal area


def test_guard_point_stays_short_of_a_ball_on_the_goal_area() -> None:
    point = guard_position(MODEL, np.array([-HL + 2.0, 0.0]))
    assert point[0] == pytest.approx(-HL + 1.0)  # 1 m short of the ball


def keeper_view(keeper, ball, **kw):
    return make_view(own={0: keeper}, ball=ball, **kw)


def test_catch_requested_only_when_the_referee_would_grant_it() -> None:
    keeper = (-HL + 3.0, 0.0)
    assert should_catch(CTX, keeper_view(keeper, (-HL + 3.8, 0.5)))
    assert not should_catch(CTX, keeper_view(keeper, (-HL + 4.3, 0.5)))  # 1.39 m: beyond the catch length
    assert not should_catch(CTX, keeper_view(keeper, (-HL + 3.8, 0.5)), teammate_kicked_last=True)
    assert not should_catch(CTX, keeper_view(keeper, (-HL + 3.8, 0.5), play_mode=PlayMode.GOAL_KICK))
    assert not should_catch(CTX, keeper_view(keeper, (-HL + 3.8, 0.5), ball_holder=0))
    edge = -HL + FIELD.penalty_area_length
    assert not should_catch(CTX, keeper_view((edge - 0.3, 0.0), (edge + 0.5, 0.0)))  # ball outside the area


def test_holding_goalkeeper_plays_the_ball_away_from_goal() -> None:
    keeper = np.array([-HL + 4.0, 2.0])
    # Opponents crowd the middle; a team-mate waits free on the left wing.
    opp = {i: (-30.0 + 2.0 * i, -3.0 + 0.6 * i) for i in range(1, 11)}
    view = keeper_view(keeper, keeper, ball_holder=0, play_mode=PlayMode.GOALIE_HOLDS, opp=opp)
    result = distribute(CTX, view)
    assert result.kind in ("pass", "clear")
    assert result.kick[0] > 0.0 and np.linalg.norm(result.kick) <= CONFIG.physics.kick_speed_max + 1e-9
    if result.kind == "clear":
        # Towards a wing, away from the crowd in the middle.
        assert abs(result.plan.direction[1]) > 0.3


def test_with_every_team_mate_marked_the_goalkeeper_clears_to_a_wing() -> None:
    keeper = np.array([-HL + 4.0, 0.0])
    own = {0: keeper}
    opp = {}
    for i in range(1, 11):
        own[i] = (-30.0 + 3.0 * i, -25.0 + 5.0 * i)
        opp[i] = (own[i][0] + 0.7, own[i][1] + 0.3)  # a marker beside every team-mate
    opp[0] = (HL - 1.0, 0.0)
    view = make_view(own=own, opp=opp, ball=keeper, ball_holder=0, play_mode=PlayMode.GOALIE_HOLDS)
    result = distribute(CTX, view)
    assert result.kind == "clear"
    assert result.plan.direction[0] > 0.0 and abs(result.plan.direction[1]) > 0.3
    # A holder kicks at full strength: the ball leaves at the speed limit.
    assert np.linalg.norm(result.plan.ball_vel) == pytest.approx(min(CONFIG.physics.kick_speed_max,
                                                                     CONFIG.physics.ball_speed_max), abs=1e-4)


def test_ball_behind_the_goal_line_keeps_the_goalkeeper_on_its_line() -> None:
    point = guard_position(MODEL, np.array([-HL - 2.0, 6.0]))
    assert point[0] == pytest.approx(-HL) and 0.0 < point[1] <= FIELD.goal_area_width / 2
