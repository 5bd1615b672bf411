"""Potential-field bidding: the bids, the auction's priority order and its hysteresis."""

from __future__ import annotations

import numpy as np
import pytest

from agents.roles import BiddingAssigner, BiddingParams, RoleContext

TARGETS = np.array([[-30.0, -10.0], [-30.0, 10.0], [0.0, 0.0], [20.0, 0.0]])


def context(ball, cycle=0):
    return RoleContext(ball=np.asarray(ball, float), own_goal=np.array([-52.5, 0.0]),
                       opp_goal=np.array([52.5, 0.0]), opponents=np.zeros((4, 2)), field_half_length=52.5,
                       field_half_width=34.0, cycle=cycle, attacking=True)


def ready(**params) -> BiddingAssigner:
    assigner = BiddingAssigner(BiddingParams(**params))
    assigner.reset(4, np.random.default_rng(0))
    return assigner


def test_the_ball_role_goes_to_the_player_lined_up_behind_the_ball() -> None:
    players = np.array([[-31.0, -10.0], [-31.0, 10.0], [13.0, 0.0], [17.0, 0.0]])
    # Players 2 and 3 are each 2 m from the ball at (15, 0); player 2 is behind it (facing the
    # goal), player 3 beyond it, so player 2 wins the ball role.
    assigner = ready()
    roles = assigner.assign(players, TARGETS, np.arange(4), None, context((15.0, 0.0)))
    assert assigner.ball_player() == 2
    # The ball player takes the place of the role nearest the ball (role 3 at x = 20); the
    # others fill the rest, player 3 taking role 2.
    assert roles.tolist() == [0, 1, 3, 2]


def test_roles_are_auctioned_in_priority_order() -> None:
    # One player is the best bidder for both role 0 and role 1 (priority: 0 first).
    players = np.array([[-30.0, 0.0], [-30.0, 30.0], [40.0, 0.0], [0.0, 1.0]])
    assigner = ready()
    roles = assigner.assign(players, TARGETS, np.arange(4), None, context((39.0, 0.0)))
    assert roles[0] == 0 and roles[1] == 1


def test_a_role_is_held_for_min_hold_cycles_then_taken_by_a_clearly_better_bidder() -> None:
    assigner = ready(min_hold=5, switch_margin=1.0)
    ball = (15.0, 0.0)
    players = np.array([[-30.0, -10.0], [-30.0, 10.0], [14.0, 0.0], [-5.0, 0.0]])
    assigner.assign(players, TARGETS, np.arange(4), None, context(ball, 0))
    assert assigner.ball_player() == 2
    # Player 3 now stands right behind the ball, player 2 has wandered off.
    players = np.array([[-30.0, -10.0], [-30.0, 10.0], [10.0, 8.0], [14.5, 0.0]])
    for cycle in range(1, 5):
        assigner.assign(players, TARGETS, np.arange(4), None, context(ball, cycle))
        assert assigner.ball_player() == 2  # held
    assigner.assign(players, TARGETS, np.arange(4), None, context(ball, 5))
    assert assigner.ball_player() == 3  # released, and player 3 bids far better


def test_after_the_hold_a_marginally_better_bidder_does_not_take_the_role() -> None:
    assigner = ready(min_hold=0, switch_margin=2.0)
    ball = (15.0, 0.0)
    players = np.array([[-30.0, -10.0], [-30.0, 10.0], [13.0, 0.0], [-5.0, 0.0]])
    assigner.assign(players, TARGETS, np.arange(4), None, context(ball, 0))
    players = np.array([[-30.0, -10.0], [-30.0, 10.0], [13.0, 0.0], [13.5, 0.0]])  # 0.5 m better
    assigner.assign(players, TARGETS, np.arange(4), None, context(ball, 1))
    assert assigner.ball_player() == 2


def test_steer_moves_supporters_down_the_field_and_sends_the_ball_player_to_its_anchor() -> None:
    assigner = ready()
    targets = np.array([[-30.0, -10.0], [-30.0, 10.0], [30.0, 0.0], [20.0, 0.0]])
    players = np.array([[-30.0, -10.0], [-30.0, 10.0], [13.0, 0.0], [30.0, 0.5]])
    ctx = context((15.0, 0.0))
    roles = assigner.assign(players, targets, np.arange(4), None, ctx)
    assert assigner.ball_player() == 2 and roles[3] == 2
    goals = assigner.steer(players, targets, roles, ctx)
    assert goals[2].tolist() == targets[roles[2]].tolist()
    # Player 3 stands in the shooting lane between the ball and the goal: it steps out of it.
    assert abs(goals[3, 1]) > abs(players[3, 1])
    supporters = [0, 1, 3]
    assert np.hypot(*(goals - players)[supporters].T).max() <= BiddingParams().field.max_step + 1e-9
