"""Potential-field bidding: the bids, the auction's priority order, the covered role, the
hysteresis and the supporters' steering."""

from __future__ import annotations

import math

import numpy as np
import pytest

from agents.roles import BiddingAssigner, BiddingParams, RoleError, offensive_order
from tests.agents.roles.role_situations import HALF_LENGTH, HALF_WIDTH, context


def ready(k: int, **params) -> BiddingAssigner:
    assigner = BiddingAssigner(**params)
    assigner.reset(k, np.random.default_rng(0))
    return assigner


def assign(assigner, players, targets, ctx, order=None):
    players, targets = np.asarray(players, float), np.asarray(targets, float)
    order = offensive_order(targets) if order is None else np.asarray(order)
    return assigner.assign(players, targets, order, None, ctx).tolist()


def test_ball_bid_is_capped_distance_plus_misalignment() -> None:
    ball = np.array([10.0, 0.0])
    players = np.array([[8.0, 0.0], [12.0, 0.0], [10.0, 3.0], [-20.0, 0.0], [-30.0, 0.0], [10.0, 0.0]])
    costs = ready(6).bids(players, np.zeros((6, 2)), context(ball))
    # Behind the ball facing the goal: only the distance; beyond it: the distance plus pi * 3.
    assert costs[0, 6] == pytest.approx(2.0)
    assert costs[1, 6] == pytest.approx(2.0 + 3.0 * math.pi)
    assert costs[2, 6] == pytest.approx(3.0 + 3.0 * math.pi / 2)
    # Distances beyond the cap (20 m) bid alike; a player on the ball is lined up.
    assert costs[3, 6] == pytest.approx(20.0) and costs[4, 6] == pytest.approx(20.0)
    assert costs[5, 6] == pytest.approx(0.0)


def test_formation_bid_is_the_distance_plus_the_goal_side_term_of_defensive_roles() -> None:
    ball = np.array([0.0, 0.0])
    targets = np.array([[-20.0, 0.0], [10.0, 0.0]])  # role 0 behind the ball (defensive), role 1 ahead
    players = np.array([[-10.0, 0.0], [-30.0, 0.0]])
    costs = ready(2, goal_side_weight=0.5).bids(players, targets, context(ball))
    assert costs[0, 0] == pytest.approx(10.0 + 0.5 * 10.0)  # 10 m upfield of a defensive target
    assert costs[1, 0] == pytest.approx(10.0)  # already goal-side: no extra
    assert costs[0, 1] == pytest.approx(20.0) and costs[1, 1] == pytest.approx(40.0)  # offensive: distance only


# Ball at (40, -25); role 2's target (30, -20) is the nearest to it (the covered role). Player 0
# stands 2 m behind the ball on the ball-goal line; player 1 is the best bidder for both roles 1
# and 0; player 2 is the second best for both.
BALL = np.array([40.0, -25.0])
_U = (np.array([HALF_LENGTH, 0.0]) - BALL) / np.hypot(*(np.array([HALF_LENGTH, 0.0]) - BALL))
PRIORITY_TARGETS = [[-20.0, 0.0], [10.0, 5.0], [30.0, -20.0]]
PRIORITY_PLAYERS = [BALL - 2.0 * _U, [-8.0, 3.0], [-30.0, 20.0]]


def test_roles_are_auctioned_ball_role_first_then_in_the_given_offensive_order() -> None:
    memoryless = dict(min_hold=0, switch_margin=0.0)
    assigner = ready(3, **memoryless)
    # Offensive order 2, 1, 0: role 1 (x = 10) comes before role 0 and takes player 1.
    assert assign(assigner, PRIORITY_PLAYERS, PRIORITY_TARGETS, context(BALL)) == [2, 1, 0]
    assert assigner.ball_player() == 0 and assigner.covered == 2
    # Given the order 0, 1, 2 instead, role 0 is auctioned first and takes player 1.
    assigner = ready(3, **memoryless)
    assert assign(assigner, PRIORITY_PLAYERS, PRIORITY_TARGETS, context(BALL), order=[0, 1, 2]) == [2, 0, 1]


def test_the_best_bidder_for_the_ball_role_takes_it_even_when_it_is_also_best_for_a_formation_role() -> None:
    targets = [[-20.0, 0.0], [3.0, 0.0], [-2.0, 6.0]]  # role 1 is nearest the ball (covered)
    players = [[-25.0, 0.0], [-2.0, 1.0], [-2.0, 12.5]]  # player 1: best for the ball role and for role 2
    assigner = ready(3, min_hold=0, switch_margin=0.0)
    costs = assigner.bids(np.asarray(players), np.asarray(targets), context((0.0, 0.0)))
    assert costs[:, 3].argmin() == 1 and costs[:, 2].argmin() == 1
    assert assign(assigner, players, targets, context((0.0, 0.0))) == [0, 1, 2]
    assert assigner.ball_player() == 1 and assigner.covered == 1


HOLD_TARGETS = [[-30.0, -10.0], [-30.0, 10.0], [20.0, 0.0], [-2.0, 0.0]]
HOLD_BALL = (15.0, 0.0)


def test_the_ball_role_is_held_for_min_hold_cycles_then_released_to_a_better_bidder() -> None:
    assigner = ready(4, min_hold=5, switch_margin=3.0)
    players = [[-30.0, -10.0], [-30.0, 10.0], [14.0, 0.0], [-5.0, 0.0]]
    assert assign(assigner, players, HOLD_TARGETS, context(HOLD_BALL, 0)) == [0, 1, 2, 3]
    assert assigner.ball_player() == 2
    # Player 3 now stands right behind the ball; player 2 has wandered off to the side.
    players = [[-30.0, -10.0], [-30.0, 10.0], [10.0, 8.0], [14.5, 0.0]]
    for cycle in range(1, 5):
        assert assign(assigner, players, HOLD_TARGETS, context(HOLD_BALL, cycle)) == [0, 1, 2, 3]
        assert assigner.ball_player() == 2  # held
    roles = assign(assigner, players, HOLD_TARGETS, context(HOLD_BALL, 5))
    assert assigner.ball_player() == 3  # released: player 3 bids 12 m better
    # Player 3's own role (x = -2) is 17 m from the ball, more than 10 m farther than role 2's
    # target (5 m): it covers role 2, and player 2 takes player 3's old role.
    assert roles == [0, 1, 3, 2] and assigner.covered == 2


def test_after_the_hold_a_challenger_within_the_margin_does_not_take_a_role() -> None:
    targets = [[-30.0, 0.0], [0.0, 0.0], [30.0, 0.0]]
    ball = (31.0, 0.0)  # role 2 is covered; roles 1 and 0 are auctioned
    assigner = ready(3, min_hold=0, switch_margin=2.0)
    players = [[-30.0, 0.0], [1.0, 0.0], [29.0, 0.0]]
    assert assign(assigner, players, targets, context(ball, 0)) == [0, 1, 2]
    # Player 0 comes within 0.5 m of role 1's target, 1 m nearer than its holder: not enough.
    players = [[0.5, 0.0], [1.5, 0.0], [29.0, 0.0]]
    assert assign(assigner, players, targets, context(ball, 1)) == [0, 1, 2]
    # 3 m nearer (player 1 drifts to 3.5 m): more than the margin, role 1 changes hands.
    players = [[0.5, 0.0], [3.5, 0.0], [29.0, 0.0]]
    assert assign(assigner, players, targets, context(ball, 2)) == [1, 0, 2]


def test_a_formation_role_is_held_for_min_hold_cycles() -> None:
    targets = [[-30.0, 0.0], [0.0, 0.0], [30.0, 0.0]]
    ball = (31.0, 0.0)
    assigner = ready(3, min_hold=3, switch_margin=0.0)
    assert assign(assigner, [[-30.0, 0.0], [1.0, 0.0], [29.0, 0.0]], targets, context(ball, 0)) == [0, 1, 2]
    swapped = [[0.0, 1.0], [-29.0, 0.0], [29.0, 0.0]]  # players 0 and 1 have swapped places
    assert assign(assigner, swapped, targets, context(ball, 1)) == [0, 1, 2]
    assert assign(assigner, swapped, targets, context(ball, 2)) == [0, 1, 2]
    assert assign(assigner, swapped, targets, context(ball, 3)) == [1, 0, 2]  # released at min_hold


def test_the_ball_player_keeps_covering_its_own_role_while_it_is_near_the_play() -> None:
    targets = [[-30.0, 0.0], [10.0, 0.0], [25.0, 0.0]]
    start = [[-30.0, 0.0], [10.0, 0.0], [25.0, 0.0]]
    later = [[-30.0, 0.0], [18.0, 0.0], [25.0, 0.0]]
    for slack, expected in ((10.0, [0, 1, 2]), (0.0, [0, 2, 1])):
        assigner = ready(3, min_hold=0, switch_margin=0.0, cover_slack=slack)
        assert assign(assigner, start, targets, context((11.0, 0.0), 0)) == [0, 1, 2]
        assert assigner.ball_player() == 1 and assigner.covered == 1
        # The ball moves on to (19, 0): role 2's target is now the nearest (6 m), role 1's is 9 m.
        assert assign(assigner, later, targets, context((19.0, 0.0), 1)) == expected
        assert assigner.ball_player() == 1


def test_ball_player_is_unknown_before_the_first_assign() -> None:
    assigner = ready(3)
    assert assigner.ball_player() is None
    assign(assigner, PRIORITY_PLAYERS, PRIORITY_TARGETS, context(BALL))
    assert assigner.ball_player() == 0
    assigner.reset(3, np.random.default_rng(0))
    assert assigner.ball_player() is None


def test_a_single_player_takes_the_ball_role_and_the_only_formation_role() -> None:
    assigner = ready(1)
    assert assign(assigner, [[3.0, 4.0]], [[-10.0, 0.0]], context((0.0, 0.0))) == [0]
    assert assigner.ball_player() == 0


def test_steer_moves_supporters_down_the_field_and_the_ball_player_to_its_role_target() -> None:
    assigner = ready(4)
    targets = np.array([[-30.0, -10.0], [-30.0, 10.0], [30.0, 0.0], [20.0, 0.0]])
    players = np.array([[-30.0, -10.0], [-30.0, 10.0], [13.0, 0.0], [30.0, 0.5]])
    ctx = context((15.0, 0.0), attacking=True)
    roles = assigner.assign(players, targets, offensive_order(targets), None, ctx)
    assert assigner.ball_player() == 2
    goals = assigner.steer(players, targets, roles, ctx)
    assert goals[2].tolist() == targets[roles[2]].tolist()
    # Player 3 stands in the shooting lane between the ball and the goal: it steps out of it.
    assert abs(goals[3, 1]) > abs(players[3, 1]) + 0.5
    steps = np.hypot(*(goals - players)[[0, 1, 3]].T)
    assert steps.max() <= BiddingParams().field.max_step + 1e-9


def test_steer_pulls_a_defensive_supporter_onto_the_shot_line_when_defending() -> None:
    assigner = ready(2, anchor_weight=0.0, side_weight=0.0, defensive_weight=0.0)
    targets = np.array([[-30.0, 15.0], [10.0, 0.0]])
    players = np.array([[-30.0, 15.0], [12.0, 0.0]])  # player 1 wins the ball role
    for attacking, moves in ((False, True), (True, False)):
        ctx = context((10.0, 0.0), attacking=attacking)
        roles = assigner.assign(players, targets, offensive_order(targets), None, ctx)
        assert assigner.ball_player() == 1 and roles[0] == 0
        goal = assigner.steer(players, targets, roles, ctx)[0]
        # The ball-to-our-goal segment runs along y = 0: defending, step towards it.
        assert (goal[1] < players[0, 1] - 0.5) == moves  # 0.3 per metre x 3 m lookahead: 0.9 m


def test_steered_points_stay_inside_the_field() -> None:
    assigner = ready(3, max_step=50.0, lookahead=100.0)
    targets = np.array([[52.0, 33.9], [-52.0, -33.9], [0.0, 0.0]])
    players = np.array([[52.4, 33.9], [-52.4, -33.9], [0.0, 0.0]])
    ctx = context((0.0, 0.0))
    roles = assigner.assign(players, targets, offensive_order(targets), None, ctx)
    goals = assigner.steer(players, targets, roles, ctx)
    margin = BiddingParams().field.field_margin
    assert (np.abs(goals[:, 0]) <= HALF_LENGTH - margin + 1e-12).all()
    assert (np.abs(goals[:, 1]) <= HALF_WIDTH - margin + 1e-12).all()


def test_the_teams_ball_reach_replaces_the_straight_distance_in_the_ball_bid() -> None:
    from dataclasses import replace

    players = np.array([[8.0, 0.0], [-5.0, 0.0], [-30.0, 0.0]])  # all lined up behind the ball
    targets = np.array([[-30.0, 0.0], [0.0, 0.0], [12.0, 0.0]])
    ctx = context((10.0, 0.0))
    assigner = ready(3)
    assert assigner.bids(players, targets, ctx)[:, 3].tolist() == pytest.approx([2.0, 15.0, 20.0])
    # The team knows player 1 is running onto the ball's path: it is 1 m away in effect.
    reach = replace(ctx, ball_reach=np.array([4.0, 1.0, np.inf]))
    # (player 2 cannot intercept: it bids after everybody who can, by its straight distance, capped)
    assert assigner.bids(players, targets, reach)[:, 3].tolist() == pytest.approx([4.0, 1.0, 40.0 + 3.0 * math.pi])
    assigner.assign(players, targets, offensive_order(targets), None, reach)
    assert assigner.ball_player() == 1
    for bad, message in ((np.array([1.0, 2.0]), r"float64 \(3,\) array"), (np.array([1.0, np.nan, 2.0]), "NaN")):
        with pytest.raises(RoleError, match=message):
            assigner.assign(players, targets, offensive_order(targets), None, replace(ctx, ball_reach=bad))


def test_the_compiled_bidding_reads_each_parameter_by_its_name() -> None:
    from agents.roles.bidding import BIDDING_DTYPE

    params = BiddingParams(ball_cap=21.0, angle_weight=2.5, goal_side_weight=0.75, min_hold=7, switch_margin=1.25,
                           cover_slack=9.5)
    record = params.as_record()
    assert record.dtype == BIDDING_DTYPE and record.shape == (1,)
    assert {name: record[0][name].item() for name in BIDDING_DTYPE.names} == {
        "ball_cap": 21.0, "angle_weight": 2.5, "goal_side_weight": 0.75, "min_hold": 7, "switch_margin": 1.25,
        "cover_slack": 9.5}
    # The goal-side weight, not another number, scales the defensive term (a player d metres
    # upfield of a defensive role's target bids its distance plus d x the weight), and the cap,
    # not another number, caps the ball bid of a player lined up behind the ball.
    assigner = BiddingAssigner(params)
    assigner.reset(2, np.random.default_rng(0))
    costs = assigner.bids(np.array([[0.0, 0.0], [-50.0, 0.0]]), np.array([[-10.0, 0.0], [40.0, 0.0]]),
                          context((20.0, 0.0)))
    assert costs[0, 0] == pytest.approx(10.0 + 10.0 * 0.75) and costs[1, 0] == pytest.approx(40.0)
    assert costs[0, 2] == pytest.approx(20.0) and costs[1, 2] == pytest.approx(21.0)


def test_a_player_who_cannot_intercept_never_outbids_one_who_can() -> None:
    """The cap makes every reach beyond ``ball_cap`` alike; "cannot intercept" (inf: the ball
    leaves the field first, or the player may not play it) must not count as merely far."""
    from dataclasses import replace

    ball = (10.0, 0.0)
    players = np.array([[12.0, 0.0], [9.0, 0.0], [-30.0, 0.0]])  # 0 is beyond the ball (misaligned), 1 lined up
    targets = np.array([[-30.0, 0.0], [0.0, 0.0], [12.0, 0.0]])
    ctx = replace(context(ball), ball_reach=np.array([30.0, np.inf, 60.0]))
    assigner = ready(3)
    costs = assigner.bids(players, targets, ctx)[:, 3]
    assert costs[1] > max(costs[0], costs[2])  # 1 m away but unable (e.g. offside): the worst bid
    assert costs[0] == pytest.approx(20.0 + 3.0 * math.pi) and costs[2] == pytest.approx(20.0)
    assigner.assign(players, targets, offensive_order(targets), None, ctx)
    assert assigner.ball_player() == 2
    # Nobody can intercept: the straight distance (capped) and the alignment decide among them.
    nobody = replace(ctx, ball_reach=np.full(3, np.inf))
    costs = assigner.bids(players, targets, nobody)[:, 3]
    assert np.argmin(costs) == 1 and costs[0] - costs[1] == pytest.approx(1.0 + 3.0 * math.pi)


def test_the_hold_does_not_keep_the_ball_role_with_a_player_who_can_no_longer_intercept() -> None:
    """The hold guards against bids that differ by little; a holder who cannot get to the ball
    at all (inf reach: the ball will leave the field first, or it stands offside) while a
    team-mate can is no such case, and it loses the ball role at once, within ``min_hold``."""
    from dataclasses import replace

    ball = (10.0, 0.0)
    players = np.array([[8.0, 0.0], [-5.0, 0.0], [-30.0, 0.0]])
    targets = np.array([[-30.0, 0.0], [0.0, 0.0], [12.0, 0.0]])
    assigner = ready(3, min_hold=10, switch_margin=1.0)
    start = replace(context(ball, 0), ball_reach=np.array([2.0, 15.0, 40.0]))
    assigner.assign(players, targets, offensive_order(targets), None, start)
    assert assigner.ball_player() == 0
    # Two cycles later player 0 could not reach the ball any more; player 1 could, in 15 m.
    unable = replace(context(ball, 2), ball_reach=np.array([np.inf, 15.0, 40.0]))
    assigner.assign(players, targets, offensive_order(targets), None, unable)
    assert assigner.ball_player() == 1
    # While it can still reach the ball, however slowly, the hold keeps it (the paper's rule).
    assigner = ready(3, min_hold=10, switch_margin=1.0)
    assigner.assign(players, targets, offensive_order(targets), None, start)
    slow = replace(context(ball, 2), ball_reach=np.array([30.0, 15.0, 40.0]))
    assigner.assign(players, targets, offensive_order(targets), None, slow)
    assert assigner.ball_player() == 0
    # Nobody can: the hold stands.
    assigner = ready(3, min_hold=10, switch_margin=1.0)
    assigner.assign(players, targets, offensive_order(targets), None, start)
    nobody = replace(context(ball, 2), ball_reach=np.full(3, np.inf))
    assigner.assign(players, targets, offensive_order(targets), None, nobody)
    assert assigner.ball_player() == 0
