"""Crossing (:mod:`agents.skills.crossing`) and the decision's preference for a cross from
wide in the final third, in hand-made situations (team frame, we attack +x)."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import (CrossParams, DecisionParams, MotionModel, OnBallAction, SkillContext, SkillInputError,
                           best_cross, decide_on_ball, in_crossing_zone)
from tests.agents.skills.skill_views import CONFIG, HL, make_view

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
W = 7  # the winger on the ball
STRIKER = 9


def _wide_view(striker=(HL - 9.0, 2.0), opp=None, ball=(HL - 14.0, 26.0)):
    """Our winger on the ball wide in the final third, a striker in the box, their keeper on
    its line, a defender on the far side keeping the striker onside, and the other opponents
    out of the way (unless ``opp`` places some)."""
    opp = {0: (HL - 1.0, 0.0), 1: (HL - 7.0, -18.0), **(opp or {})}
    return make_view(own={W: (ball[0] - 0.5, ball[1]), STRIKER: striker}, opp=opp, ball=ball)


def test_a_winger_wide_in_the_final_third_crosses_to_the_striker_in_the_box() -> None:
    view = _wide_view()
    plan = best_cross(CTX, view, W)
    assert plan is not None
    assert plan.receiver == STRIKER
    assert plan.receive_point[0] > HL - MODEL.penalty_area_length
    assert abs(plan.receive_point[1]) < MODEL.penalty_area_half_width
    assert plan.opponent_cycle - plan.receive_cycle >= CrossParams().min_lead
    # the kick sends the ball towards the box: forward-ish and inwards (to -y from +y)
    assert plan.ball_vel[1] < -0.5


def test_no_cross_outside_the_zone_or_into_a_crowded_box() -> None:
    assert not in_crossing_zone(MODEL, np.array([HL - 14.0, 5.0]))  # central
    assert not in_crossing_zone(MODEL, np.array([5.0, 26.0]))  # not in the final third
    assert best_cross(CTX, _wide_view(ball=(5.0, 26.0)), W) is None
    # A wall of defenders between the ball and the box: every cross is cut out.
    crowd = {i: (HL - 19.0 + 2.0 * i, 22.0) for i in range(1, 11)}
    assert best_cross(CTX, _wide_view(opp=crowd), W) is None


def test_the_decision_prefers_the_cross_to_a_pass_and_can_be_told_not_to_cross() -> None:
    # A free team-mate behind the winger would take a safe pass.
    view = make_view(own={W: (HL - 14.5, 26.0), STRIKER: (HL - 9.0, 2.0), 8: (HL - 30.0, 20.0)},
                     opp={0: (HL - 1.0, 0.0), 1: (HL - 7.0, -18.0)}, ball=(HL - 14.0, 26.0))
    decision = decide_on_ball(CTX, view, W, DecisionParams())
    assert decision.action == OnBallAction.CROSS
    assert decision.plan.receiver == STRIKER
    without = decide_on_ball(CTX, view, W, DecisionParams(crossing=None))
    assert without.action != OnBallAction.CROSS


def test_bad_cross_parameters_are_named() -> None:
    with pytest.raises(SkillInputError, match="arrival_speed"):
        CrossParams(arrival_speed=0.0)
    with pytest.raises(SkillInputError, match="space_points"):
        CrossParams(space_points=((1.0,),))
