"""A defender pressed near our goal (agents.skills.decision, refinement c) puts the ball behind, wide of the
post, from anywhere within the block's depth of our goal line, not only inside the area."""

from __future__ import annotations

import numpy as np

from agents import skills
from agents.teams import on_ball
from tests.agents.skills.skill_views import CONFIG, HL, make_view

MODEL = skills.MotionModel.even_sides(CONFIG)
BLOCK = skills.DecisionParams().safety.block
CTX = skills.SkillContext(MODEL)
P = 4


def pressed_defender(depth: float):
    """Our defender ``P`` on the ball ``depth`` m from our goal line, 10 m off the middle, two
    opponents on it, every team-mate marked (no pass)."""
    ball = (-HL + depth, 10.0)
    own = {0: (-HL + 1.0, 0.0), P: (ball[0] - 0.5, ball[1])}
    opp = {0: (HL - 1.0, 0.0), 1: (ball[0] + 0.9, ball[1] + 0.6), 2: (ball[0] + 1.0, ball[1] - 0.8)}
    for i in range(1, 11):
        if i != P:
            own[i] = (-30.0 + 4.0 * i, -25.0 + 5.0 * i)
            opp[i if i > 2 else i + 8] = (own[i][0] + 0.6, own[i][1] + 0.4)
    return make_view(own=own, opp=opp, ball=ball)


def test_pressed_just_outside_our_area_the_defender_puts_it_behind() -> None:
    depth = 19.0  # outside the penalty area (16.5 m), within the block's depth
    assert MODEL.penalty_area_length < depth < BLOCK.behind_depth
    view = pressed_defender(depth)
    race = skills.ball_race(CTX, view)
    decision = skills.decide_on_ball(CTX, view, P, pressure=race.theirs.first_cycle)
    assert decision.action in (skills.OnBallAction.CLEAR, skills.OnBallAction.DRIBBLE)
    kick, dash, shot = on_ball.on_ball_kick(CTX, view, P, 0, skills.DecisionParams(), race, False)
    assert not shot and dash is None
    np.testing.assert_allclose(kick, skills.parry_kick(CTX, view, P, BLOCK))
    direction = skills.parry_direction(CTX, view.ball, BLOCK)
    assert direction[0] < 0.0  # towards our goal line ...
    cross_y = view.ball[1] + direction[1] / direction[0] * (-HL - view.ball[0])
    assert abs(cross_y) > MODEL.goal_half_width + 1.0  # ... wide of the post: a corner


def test_further_out_the_pressed_defender_clears_as_before() -> None:
    view = pressed_defender(BLOCK.behind_depth + 6.0)
    race = skills.ball_race(CTX, view)
    decision = skills.decide_on_ball(CTX, view, P, pressure=race.theirs.first_cycle)
    kick, _, _ = on_ball.on_ball_kick(CTX, view, P, 0, skills.DecisionParams(), race, False)
    np.testing.assert_allclose(kick, decision.kick)
