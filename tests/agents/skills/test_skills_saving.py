"""The goalkeeper comes out only for a ball it wins, and a ball near our goal that can be
kicked but not held is parried wide of the goal (corner rather than goal)."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import (MotionModel, SaveParams, SkillContext, ball_race, comes_out, goalkeeper_kick,
                           guard_position, parry_direction, parry_kick)
from agents.skills.model import SkillInputError
from tests.agents.skills.skill_views import CONFIG, HL, make_view

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
GOAL_HALF = CONFIG.field.goal_width / 2.0


def breakaway(attacker_gap: float):
    """A ball rolling at our goal from 22 m out, our goalkeeper on its guard point, an attacker
    ``attacker_gap`` metres behind the ball and running with it."""
    ball = np.array([-HL + 22.0, 3.0])
    ball_vel = np.array([-1.2, -0.1])
    keeper = np.array(guard_position(MODEL, ball))
    attacker = ball + (attacker_gap, 0.0)
    return make_view(own={0: keeper}, opp={9: attacker}, opp_vel={9: (-0.9, 0.0)}, ball=ball, ball_vel=ball_vel)


def test_the_goalkeeper_stays_when_an_attacker_gets_to_the_ball_first() -> None:
    view = breakaway(attacker_gap=0.5)
    race = ball_race(CTX, view)
    assert race.theirs.first == 9 and race.ours.cycles[0] >= race.theirs.first_cycle
    assert not comes_out(MODEL, race)


def test_the_goalkeeper_comes_out_when_it_wins_the_race() -> None:
    view = breakaway(attacker_gap=9.0)
    race = ball_race(CTX, view)
    assert race.ours.first == 0 and race.ours.cycles[0] < race.theirs.first_cycle
    assert comes_out(MODEL, race)
    # A lead of one cycle is not enough when the goalkeeper asks for more.
    from agents.skills import GoalieParams
    margin = race.theirs.first_cycle - race.ours.cycles[0] + 1
    assert not comes_out(MODEL, race, params=GoalieParams(race_margin=margin))


def test_the_goalkeeper_does_not_leave_its_area_for_a_ball_it_wins() -> None:
    ball = np.array([-HL + 25.0, 0.0])
    view = make_view(own={0: (-HL + 15.0, 0.0)}, ball=ball, ball_vel=(-0.8, 0.0))
    race = ball_race(CTX, view)
    assert race.ours.first == 0 and not MODEL.in_penalty_area(race.ours.points[0])
    assert not comes_out(MODEL, race)


def crossing_y(ball: np.ndarray, direction: np.ndarray) -> float | None:
    """Where a ball moving from ``ball`` along ``direction`` crosses our goal line (None: never)."""
    if direction[0] >= 0.0:
        return None
    t = (-HL - ball[0]) / direction[0]
    return float(ball[1] + t * direction[1])


@pytest.mark.parametrize("ball", [(-HL + 1.5, 0.0), (-HL + 3.0, 2.0), (-HL + 5.0, -4.0), (-HL + 0.6, -1.0),
                                  (-HL + 7.0, 9.0)])
def test_a_parry_near_the_goal_goes_behind_wide_of_the_posts(ball) -> None:
    ball = np.asarray(ball, float)
    direction = parry_direction(CTX, ball)
    assert np.hypot(*direction) == pytest.approx(1.0)
    assert np.sign(direction[1]) == (1.0 if ball[1] > 0.0 else -1.0)  # towards the ball's side
    y = crossing_y(ball, direction)
    # it crosses the goal line wide of the far post (or runs along/away from it), never into the goal
    assert y is None or abs(y) >= GOAL_HALF + SaveParams().wide_gap - 1e-9


def test_a_parry_further_out_goes_towards_the_touchline_and_forwards() -> None:
    direction = parry_direction(CTX, np.array([-HL + 14.0, -3.0]))
    assert direction[0] > 0.0 and direction[1] < -0.9


def test_the_parry_kick_sends_the_ball_the_parry_way() -> None:
    ball = np.array([-HL + 2.0, 1.0])
    view = make_view(own={0: ball + (-0.6, 0.0)}, opp={9: ball + (1.0, 0.0)}, ball=ball)
    kick = parry_kick(CTX, view, 0)
    direction = parry_direction(CTX, ball)
    assert float(kick @ direction) / np.hypot(*kick) == pytest.approx(1.0, abs=1e-6)
    # Pressed, the goalkeeper parries; with nobody near it distributes the ball up the field instead.
    assert np.allclose(goalkeeper_kick(CTX, view, 0, pressure=1), kick)
    free = goalkeeper_kick(CTX, make_view(own={0: ball + (-0.6, 0.0)}, ball=ball), 0, pressure=30)
    assert free[0] > 0.0


def test_save_params_reject_bad_values() -> None:
    with pytest.raises(SkillInputError, match="wide_gap"):
        SaveParams(wide_gap=0.0)
