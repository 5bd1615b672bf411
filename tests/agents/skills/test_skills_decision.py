"""The on-ball decision in hand-made situations: shoot, pass, dribble, clear."""

from __future__ import annotations

import numpy as np

from agents.skills import MotionModel, OnBallAction, PassParams, SkillContext, decide_on_ball
from tests.agents.skills.skill_views import CONFIG, HL, make_view

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
P = 9


def test_open_goal_in_range_is_shot() -> None:
    view = make_view(own={P: (HL - 11.0, 0.0)}, opp={0: (HL - 6.0, 14.0)}, ball=(HL - 10.5, 0.0))
    decision = decide_on_ball(CTX, view, P)
    assert decision.action == OnBallAction.SHOOT
    assert decision.kick[0] > 0.0 and decision.dash is None


def test_pressed_in_midfield_with_a_free_team_mate_passes() -> None:
    """Pressed at the halfway line with every team-mate unmarked, the passer plays the ball
    forward to a team-mate who gets it well before any opponent, into open space (which one
    is a matter of score: the one ahead at (15, 5) and the winger on the far touchline are
    worth about the same)."""
    view = make_view(own={P: (0.0, 0.0), 10: (15.0, 5.0)}, opp={0: (HL - 1.0, 0.0), 3: (1.8, 0.8)},
                     ball=(0.6, 0.0))
    decision = decide_on_ball(CTX, view, P)
    assert decision.pressure <= 3
    assert decision.action == OnBallAction.PASS
    plan = decision.plan
    assert plan.receiver not in (P, MODEL.goalie_index)
    assert plan.opponent_cycle >= plan.receive_cycle + PassParams().min_lead
    assert plan.receive_point[0] > view.ball[0] + 10.0  # forward
    assert np.min(np.hypot(*(view.opp_pos - plan.receive_point).T)) > 10.0  # in open space


def test_pressed_in_midfield_passes_to_the_only_free_team_mate() -> None:
    """The same, with every other team-mate marked from a metre away: the pass goes to the
    free one ahead (receiver 10)."""
    own = {P: (0.0, 0.0), 10: (15.0, 5.0)}
    opp = {0: (HL - 1.0, 0.0), 3: (1.8, 0.8)}
    markers = [i for i in range(1, 11) if i != 3]
    for mate, marker in zip(range(1, 9), markers):
        x, y = -40.0 + 8.0 * mate, -25.0 + 3.0 * mate
        own[mate] = (x, y)
        opp[marker] = (x + 0.7, y + 0.7)
    view = make_view(own=own, opp=opp, ball=(0.6, 0.0))
    decision = decide_on_ball(CTX, view, P)
    assert decision.action == OnBallAction.PASS and decision.plan.receiver == 10


def test_alone_in_space_dribbles_forward() -> None:
    own = {i: (-45.0, -30.0 + 6.0 * i) for i in range(11)}  # team-mates all far behind
    own[P] = (0.0, 0.0)
    view = make_view(own=own, opp={0: (HL - 1.0, 0.0)}, ball=(0.6, 0.0))
    decision = decide_on_ball(CTX, view, P)
    assert decision.action == OnBallAction.DRIBBLE
    assert decision.dash is not None and decision.plan.direction[0] > 0.9


def test_pressed_in_our_third_without_a_pass_clears() -> None:
    own = {0: (-HL + 1.0, 0.0), P: (-40.0, 0.0)}
    opp = {0: (HL - 1.0, 0.0), 1: (-39.0, 0.9), 2: (-38.5, -1.0)}
    for i in range(1, 11):
        if i != P:
            own[i] = (-30.0 + 4.0 * i, -25.0 + 5.0 * i)
            opp[i if i > 2 else i + 8] = (own[i][0] + 0.6, own[i][1] + 0.4)  # everyone marked
    view = make_view(own=own, opp=opp, ball=(-39.5, 0.0))
    decision = decide_on_ball(CTX, view, P)
    assert decision.action == OnBallAction.CLEAR
    assert decision.kick[0] > 0.0
    speed = np.linalg.norm(decision.plan.ball_vel)
    assert speed > 1.5  # a hard kick


def test_goalkeeper_on_the_ball_never_dribbles() -> None:
    own = {i: (-45.0, -30.0 + 6.0 * i) for i in range(11)}
    own[0] = (-HL + 5.0, 0.0)
    view = make_view(own=own, opp={0: (HL - 1.0, 0.0)}, ball=(-HL + 5.6, 0.0))
    decision = decide_on_ball(CTX, view, 0)
    assert decision.action in (OnBallAction.PASS, OnBallAction.CLEAR)
    assert decision.kick[0] > 0.0


def test_a_contested_ball_sent_wide_stops_inside_the_field_even_with_the_mirror_kick() -> None:
    from agents.skills.decision import SafetyParams, wing_kick
    from agents.skills.kicking import kick_effectiveness
    params = SafetyParams()
    decay, half_width = MODEL.ball_decay, MODEL.half_width
    for ball_y in (0.0, 8.0, -15.0, 25.0):
        player = np.array([-1.0, ball_y])
        view = make_view(own={5: tuple(player)}, ball=(-0.5, ball_y))
        kick = wing_kick(MODEL, view, 5, params)
        velocity = kick * kick_effectiveness(MODEL, player, view.ball, kick)  # the ball was at rest
        travel_y = 2.0 * abs(velocity[1]) / (1.0 - decay)  # with an opponent's equal kick to the same side
        assert np.sign(velocity[1]) == (1.0 if ball_y >= 0.0 else -1.0) and velocity[0] > 0.0
        room = half_width - abs(ball_y) - params.wing_margin
        assert travel_y <= room + 1e-6 or np.hypot(*velocity) <= params.wing_min_speed + 1e-6
