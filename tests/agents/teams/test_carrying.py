"""Carrying the ball into the box (agents.skills.decision, refinement b): near the opponents' goal a free
player dribbles on instead of passing back, and a pressed one instead of clearing long."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from agents import skills
from agents.skills.decision import CarryParams, carry_kick
from agents.teams.on_ball import on_ball_kick
from agents.teams.style import ATTACKING_DECISIONS
from tests.agents.skills.skill_views import CONFIG, HL, make_view

MODEL = skills.MotionModel.even_sides(CONFIG)
CTX = skills.SkillContext(MODEL)
P = 9
DECISIONS = ATTACKING_DECISIONS


def back_pass_view(distance: float):
    """Our player ``P`` on the ball ``distance`` m in front of the opponents' goal, nobody
    between it and the goal but their goalkeeper, a free team-mate 15 m behind it (the only
    pass), the other team-mates far back and the defenders away on the far wing."""
    x = HL - distance
    own = {i: (-45.0, -30.0 + 6.0 * i) for i in range(11)}
    own[P] = (x - 0.5, 0.0)
    own[7] = (x - 15.0, -2.0)
    opp = {0: (HL - 1.0, 0.0), **{i: (x - 5.0 + i, 30.0) for i in range(1, 11)}}
    return make_view(own=own, opp=opp, ball=(x, 0.0))


def test_near_their_goal_a_free_player_dribbles_on_instead_of_passing_back() -> None:
    view = back_pass_view(28.0)
    passing = replace(DECISIONS, pass_good=-10.0)  # the decision passes whatever the pass's score
    decision = skills.decide_on_ball(CTX, view, P, passing)
    assert decision.action == skills.OnBallAction.PASS and decision.plan.receiver == 7
    carried = carry_kick(CTX, view, P, decision, passing)
    assert carried is not None and carried.action == skills.OnBallAction.DRIBBLE
    kick, dash = carried.kick, carried.dash
    # ball or player goes on towards the goal (one body command a cycle: a kick or a dash)
    assert (kick[0] > 0.0 and not dash.any()) or (dash[0] > 0.0 and not kick.any())
    plan = skills.dribble(CTX, view, P, passing.dribbling)
    np.testing.assert_allclose(kick, plan.kick)
    kick2, dash2, shot = on_ball_kick(CTX, view, P, 0, passing, skills.ball_race(CTX, view), False)
    assert not shot
    np.testing.assert_allclose(kick2, plan.kick)
    np.testing.assert_allclose(dash2, plan.dash)


def test_far_from_goal_or_forwards_the_pass_stands() -> None:
    far = back_pass_view(40.0)
    passing = replace(DECISIONS, pass_good=-10.0)
    decision = skills.decide_on_ball(CTX, far, P, passing)
    assert decision.action == skills.OnBallAction.PASS
    assert carry_kick(CTX, far, P, decision, passing) is None  # beyond carry_range: build up
    near = back_pass_view(28.0)
    decision = skills.decide_on_ball(CTX, near, P, passing)
    forward = replace(decision.plan, receive_point=np.array([HL - 15.0, 3.0]))  # 13 m closer to the goal
    assert carry_kick(CTX, near, P, replace(decision, plan=forward), passing) is None
    assert carry_kick(CTX, near, P, decision, replace(passing, carrying=CarryParams(carry_range=0.0))) is None
    shoot = replace(decision, action=skills.OnBallAction.SHOOT)
    assert carry_kick(CTX, near, P, shoot, passing) is None


def pressed_view(distance: float):
    """Our player ``P`` on the ball ``distance`` m in front of the opponents' goal line, closed
    down by two defenders, team-mates far back (no pass)."""
    x = HL - distance
    own = {i: (-48.0, -30.0 + 6.0 * i) for i in range(11)}
    own[P] = (x - 0.5, 5.0)
    opp = {0: (HL - 1.0, 0.0), 3: (x + 1.6, 5.8), 4: (x + 1.2, 3.8)}
    return make_view(own=own, opp=opp, ball=(x, 5.0))


def test_a_pressed_player_in_the_attacking_zone_dribbles_rather_than_clears() -> None:
    for distance in (50.0, 38.0, 29.0):  # midfield, beyond and within carry_range: no pass, never a clearance
        view = pressed_view(distance)
        decision = skills.decide_on_ball(CTX, view, P, DECISIONS)
        assert decision.action == skills.OnBallAction.DRIBBLE
        np.testing.assert_allclose(decision.kick, skills.dribble(CTX, view, P, DECISIONS.dribbling).kick)
        assert carry_kick(CTX, view, P, decision, DECISIONS) is None  # a dribble needs no carrying


def test_a_pressed_player_deep_in_our_half_passes_rather_than_dribbles() -> None:
    view = pressed_view(2 * HL - 10.0)  # 10 m from our own goal line, team-mates behind
    decision = skills.decide_on_ball(CTX, view, P, DECISIONS)
    assert decision.action == skills.OnBallAction.PASS


def test_carry_params_reject_bad_values() -> None:
    with pytest.raises(ValueError, match="carry_range"):
        CarryParams(carry_range=-1.0)
    with pytest.raises(ValueError, match="pass_gain"):
        CarryParams(pass_gain=-1.0)
