"""Passing: a lane blocked by an opponent is rejected, an open one accepted; the chosen pass
reaches its target at the planned speed; offside team-mates are not passed to."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import MotionModel, SkillContext, best_pass, lane_open, offside_positions, pass_candidates
from agents.skills.passing import PassParams
from tests.agents.skills.skill_views import CONFIG, N, ball_at, make_view

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
PASSER, RECEIVER = 9, 10


def own_rows(extra: dict | None = None) -> dict[int, tuple[float, float]]:
    """Our goalkeeper at home, defenders deep in our half, the passer on the ball at the centre,
    the receiver 15 m ahead."""
    rows = {0: (-50.0, 0.0)}
    for i in range(1, 9):
        rows[i] = (-35.0, -28.0 + 7.0 * i)
    rows[PASSER] = (0.0, 0.0)
    rows[RECEIVER] = (15.0, 0.0)
    rows.update(extra or {})
    return rows


def opp_rows(extra: dict | None = None) -> dict[int, tuple[float, float]]:
    """Opponents deep in their half (their goalkeeper on its line), far from the lane."""
    rows = {0: (51.0, 0.0)}
    for i in range(1, N):
        rows[i] = (40.0, -30.0 + 6.0 * i)
    rows.update(extra or {})
    return rows


def direct_velocity(target, ball=(0.6, 0.0), arrival=0.8) -> np.ndarray:
    delta = np.asarray(target) - np.asarray(ball)
    dist = np.linalg.norm(delta)
    return delta / dist * float(MODEL.ball_speed_for(dist, arrival))


def test_open_lane_is_accepted_and_the_pass_chosen() -> None:
    view = make_view(own=own_rows(), opp=opp_rows(), ball=(0.6, 0.0))
    assert lane_open(CTX, view, view.ball, direct_velocity((15.0, 0.0)), RECEIVER)
    plan = best_pass(CTX, view, PASSER, PassParams(arrival_speeds=(0.8,)))
    assert plan is not None and plan.receiver == RECEIVER
    # The ball, rolled with the model, reaches the target at the planned cycle, at about the
    # planned arrival speed (0.8 m/cycle), and the receiver is there well before any opponent.
    travelled = np.linalg.norm(plan.target - view.ball)
    at_arrival = ball_at(CONFIG, view.ball, plan.ball_vel, plan.arrival_cycle)
    before = ball_at(CONFIG, view.ball, plan.ball_vel, plan.arrival_cycle - 1)
    assert np.linalg.norm(before - view.ball) < travelled <= np.linalg.norm(at_arrival - view.ball) + 1e-9
    speed = np.linalg.norm(plan.ball_vel)
    assert speed == pytest.approx(travelled * (1 - CONFIG.physics.ball_decay) + 0.8)
    assert plan.opponent_cycle - plan.receive_cycle >= PassParams().min_lead
    assert np.linalg.norm(plan.kick) <= CONFIG.physics.kick_speed_max + 1e-9


def test_lane_blocked_by_an_opponent_is_rejected() -> None:
    view = make_view(own=own_rows(), opp=opp_rows({5: (7.5, 0.3)}), ball=(0.6, 0.0))
    assert not lane_open(CTX, view, view.ball, direct_velocity((15.0, 0.0)), RECEIVER)
    plan = best_pass(CTX, view, PASSER)
    assert plan is None or plan.receiver != RECEIVER


def test_lead_pass_goes_in_front_of_a_free_receiver() -> None:
    view = make_view(own=own_rows(), opp=opp_rows(), ball=(0.6, 0.0))
    plan = best_pass(CTX, view, PASSER)
    assert plan.receiver == RECEIVER and plan.target[0] > 15.0  # ahead of the receiver's feet
    assert plan.receive_point[0] > 15.0
    assert plan.receive_cycle <= plan.arrival_cycle + PassParams().extra_cycles


def test_a_marker_in_front_of_the_receiver_blocks_the_lead_pass() -> None:
    view = make_view(own=own_rows(), opp=opp_rows({5: (19.0, 0.0)}), ball=(0.6, 0.0))
    plan = best_pass(CTX, view, PASSER)
    assert plan is not None and plan.receiver == RECEIVER
    assert np.linalg.norm(plan.receive_point - (19.0, 0.0)) > 3.0
    assert plan.opponent_cycle - plan.receive_cycle >= PassParams().min_lead


def test_offside_receivers_are_not_candidates() -> None:
    opp = opp_rows()
    for i in range(1, N):
        opp[i] = (20.0, -30.0 + 6.0 * i)  # the defensive line at x = 20
    view = make_view(own=own_rows({RECEIVER: (30.0, 0.0)}), opp=opp, ball=(0.6, 0.0))
    offside = offside_positions(MODEL, view.own_pos, view.opp_pos, view.ball)
    assert offside[RECEIVER] and offside.sum() == 1
    assert RECEIVER not in pass_candidates(CTX, view, PASSER).tolist()
    assert PASSER not in pass_candidates(CTX, view, PASSER).tolist()
    assert 0 not in pass_candidates(CTX, view, PASSER).tolist()  # the goalkeeper, by default


def test_no_pass_when_every_team_mate_is_marked() -> None:
    own = own_rows()
    opp = {0: (51.0, 0.0)}
    for i in range(1, N):
        if i != PASSER:
            x, y = own[i]
            opp[i] = (x + 0.8, y)  # a marker beside every team-mate
    opp[PASSER] = (40.0, 30.0)
    view = make_view(own=own, opp=opp, ball=(0.6, 0.0))
    assert best_pass(CTX, view, PASSER) is None
