"""Finishing under pressure (agents.skills.decision, refinement a): a pressed player near the opponents'
goal shoots instead of dribbling into the defender or clearing blind."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from agents import skills
from agents.skills.decision import FinishParams, finishing_shot
from agents.teams.on_ball import on_ball_kick
from agents.teams.style import ATTACKING_DECISIONS
from tests.agents.skills.skill_views import CONFIG, HL, make_view

MODEL = skills.MotionModel.even_sides(CONFIG)
CTX = skills.SkillContext(MODEL)
P = 9
DECISIONS = replace(ATTACKING_DECISIONS, shot=replace(ATTACKING_DECISIONS.shot, lane_range=0.0))
"""The built-in team's decisions without the open-lane shot (which would already shoot here)."""
SHOT = DECISIONS.shot


def pressed_view(distance: float, y: float = 4.0):
    """Our player ``P`` on the ball ``distance`` m in front of the opponents' goal line, two
    defenders a metre or two in front of it (closing it down), their goalkeeper in goal, our
    team-mates far back (no pass)."""
    x = HL - distance
    own = {i: (-45.0, -30.0 + 6.0 * i) for i in range(11)}
    own[P] = (x - 0.5, y)
    opp = {0: (HL - 1.0, 0.0), 3: (x + 1.5, y + 0.8), 4: (x + 1.0, y - 1.2)}
    return make_view(own=own, opp=opp, ball=(x, y))


def test_pressed_at_the_edge_of_the_box_without_a_shot_it_shoots_instead() -> None:
    view = pressed_view(18.0)
    decision = skills.decide_on_ball(CTX, view, P, DECISIONS)
    assert decision.action in (skills.OnBallAction.DRIBBLE, skills.OnBallAction.CLEAR)
    assert decision.pressure <= FinishParams().pressure_cycles
    kick = finishing_shot(CTX, view, P, decision, False, DECISIONS).kick
    plan = skills.best_shot(CTX, view, P, SHOT, pressure=decision.pressure)
    assert kick is not None and plan is not None
    np.testing.assert_allclose(kick, plan.kick)
    assert abs(plan.aim[1]) < MODEL.goal_half_width and plan.aim[0] == pytest.approx(HL)
    assert np.hypot(*plan.ball_vel) > 0.8 * MODEL.ball_speed_max  # hard (as hard as one kick gives)
    kick, dash, shot = on_ball_kick(CTX, view, P, 0, DECISIONS, skills.ball_race(CTX, view), False)
    assert shot and dash is None
    np.testing.assert_allclose(kick, plan.kick)


def test_out_of_range_free_or_with_a_pass_it_does_what_the_decision_says() -> None:
    far = pressed_view(30.0)
    decision = skills.decide_on_ball(CTX, far, P, DECISIONS)
    assert decision.action in (skills.OnBallAction.DRIBBLE, skills.OnBallAction.CLEAR)
    assert finishing_shot(CTX, far, P, decision, True, DECISIONS) is None
    near = pressed_view(18.0)
    decision = skills.decide_on_ball(CTX, near, P, DECISIONS)
    free = replace(decision, pressure=FinishParams().pressure_cycles + 1)
    assert finishing_shot(CTX, near, P, free, False, DECISIONS) is None
    assert finishing_shot(CTX, near, P, free, True, DECISIONS) is not None  # a defender on it
    passing = replace(decision, action=skills.OnBallAction.PASS)
    assert finishing_shot(CTX, near, P, passing, True, DECISIONS) is None
    off = replace(DECISIONS, finishing=FinishParams(shot_range=0.0))
    assert finishing_shot(CTX, near, P, decision, True, off) is None


def test_finish_params_reject_bad_values() -> None:
    with pytest.raises(ValueError, match="shot_range"):
        FinishParams(shot_range=-1.0)
    with pytest.raises(ValueError, match="pressure_cycles"):
        FinishParams(pressure_cycles=-1)
