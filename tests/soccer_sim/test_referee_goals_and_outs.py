"""Goals, kick-ins, corners and goal kicks, judged on hand-built world states."""

import numpy as np
import pytest

from soccer_sim.config import MatchConfig
from soccer_sim.state import AWAY, HOME, NO_PLAYER, NO_TEAM, EventKind, PlayMode
from tests.soccer_sim.referee_world import N, config_with, kinds, make_world, move_ball, set_play_modes, step

CFG = MatchConfig()
HL = CFG.field.half_length
HW = CFG.field.half_width
R = CFG.physics.ball_radius


def test_ball_over_the_goal_line_between_the_posts_is_a_goal_for_the_attackers():
    ref, st, ev = make_world(ball=(52.0, 3.0), last_touch=9)  # home player 9, home attacks +x
    step(ref, st)
    move_ball(st, HL + R + 0.3, 3.2)
    step(ref, st)
    assert tuple(st.score) == (1, 0)
    goals = ev.of_kind(EventKind.GOAL)
    assert len(goals) == 1
    cycle, team, player, x, y, own_goal = goals[0]
    assert (cycle, team, player, own_goal) == (101, HOME, 9, 0)
    assert x == pytest.approx(HL + R)
    assert 3.0 < y < 3.2  # where the ball's centre crossed the line
    # A pause, then the team that conceded kicks off from the centre spot.
    assert st.play_mode == PlayMode.AFTER_GOAL and st.mode_team == AWAY
    assert st.ball.tolist() == [0.0, 0.0] and st.ball_vel.tolist() == [0.0, 0.0]
    for _ in range(CFG.rules.goal_pause_cycles):
        assert ref.kick_mask(st).sum() == 0  # nobody may kick during the pause
        step(ref, st)
    assert st.play_mode == PlayMode.KICK_OFF and st.mode_team == AWAY
    assert st.mode_start == 102 + CFG.rules.goal_pause_cycles
    assert st.ball.tolist() == [0.0, 0.0] and st.ball_vel.tolist() == [0.0, 0.0]
    assert st.last_touch == NO_PLAYER
    assert set_play_modes(ev) == [PlayMode.AFTER_GOAL, PlayMode.KICK_OFF]


def test_ball_on_the_line_is_not_a_goal_until_wholly_over():
    ref, st, ev = make_world(ball=(HL + R - 1e-6, 0.0), last_touch=9)
    step(ref, st)
    assert st.play_mode == PlayMode.PLAY_ON and tuple(st.score) == (0, 0)
    move_ball(st, HL + R + 1e-6, 0.0)
    step(ref, st)
    assert tuple(st.score) == (1, 0)


def test_ball_just_outside_the_post_is_no_goal_but_a_goal_kick():
    post = CFG.field.goal_width / 2
    ref, st, ev = make_world(ball=(52.0, post + 0.05), last_touch=9)
    step(ref, st)
    move_ball(st, HL + 1.0, post + 0.05)
    step(ref, st)
    assert tuple(st.score) == (0, 0)
    assert st.play_mode == PlayMode.GOAL_KICK and st.mode_team == AWAY


@pytest.mark.parametrize("last_touch, goal_x, scorer", [(N + 4, HL + 1.0, HOME), (4, -HL - 1.0, AWAY)])
def test_own_goal_counts_for_the_opponents(last_touch, goal_x, scorer):
    ref, st, ev = make_world(ball=(np.sign(goal_x) * 52.0, 0.0), last_touch=last_touch)
    step(ref, st)
    move_ball(st, goal_x, 0.5)
    step(ref, st)
    expected = [0, 0]
    expected[scorer] = 1
    assert st.score.tolist() == expected
    [(_, team, player, _, _, own_goal)] = ev.of_kind(EventKind.GOAL)
    assert (team, player, own_goal) == (scorer, 4, 1)
    assert st.mode_team == 1 - scorer  # the conceding team kicks off


def test_goals_swap_with_the_ends_in_the_second_half():
    ref, st, ev = make_world(ball=(-52.0, 0.0), home_attacks=-1, last_touch=7)
    step(ref, st)
    move_ball(st, -HL - 1.0, 0.0)
    step(ref, st)
    assert tuple(st.score) == (1, 0)
    assert st.mode_team == AWAY


def test_kick_off_without_a_pause_reflects_players_into_their_own_halves():
    moves = {5: (10.0, 2.0), 6: (30.0, -5.0), N + 5: (-3.0, 1.0), N + 6: (2.0, 0.5)}
    ref, st, ev = make_world(ball=(52.0, 0.0), last_touch=9, moves=moves, config=config_with(goal_pause_cycles=0))
    st.vel[:] = 0.5
    step(ref, st)
    move_ball(st, HL + 1.0, 0.0)
    step(ref, st)
    assert st.mode_team == AWAY and st.play_mode == PlayMode.KICK_OFF
    home, away = st.pos[:N], st.pos[N:]
    assert (home[:, 0] <= 0.0).all() and (away[:, 0] >= 0.0).all()
    assert st.pos[6].tolist() == [-30.0, -5.0]  # reflected across the halfway line
    # Home (not kicking off) is outside the centre circle; away may stand inside it.
    assert np.hypot(home[:, 0], home[:, 1]).min() >= CFG.field.centre_circle_radius - 1e-9
    assert st.pos[N + 5].tolist() == [3.0, 1.0]  # reflected into its own half, inside the circle
    assert st.pos[N + 6].tolist() == [2.0, 0.5]  # already in its own half: not moved
    assert not st.vel.any()


def test_kick_in_for_the_team_that_did_not_touch_last_on_the_line_where_it_left():
    ref, st, ev = make_world(ball=(10.0, 30.0), last_touch=3)
    step(ref, st)
    move_ball(st, 12.0, 35.0)
    step(ref, st)
    assert st.play_mode == PlayMode.KICK_IN and st.mode_team == AWAY
    # The ball's centre crossed y = HW + R at 81.7 % of the way from (10, 30) to (12, 35).
    t = (HW + R - 30.0) / 5.0
    assert st.ball[0] == pytest.approx(10.0 + 2.0 * t)
    assert st.ball[1] == HW
    assert not st.ball_vel.any()
    [(_, team, player, x, y, line)] = ev.of_kind(EventKind.OUT)
    assert (team, player, line) == (HOME, 3, 0)
    assert kinds(ev) == [EventKind.OUT, EventKind.SET_PLAY]


def test_kick_in_after_an_away_touch_goes_to_home_on_the_far_touchline():
    ref, st, ev = make_world(ball=(-20.0, -33.0), last_touch=N + 2)
    step(ref, st)
    move_ball(st, -20.0, -HW - 0.5)
    step(ref, st)
    assert (st.play_mode, st.mode_team) == (PlayMode.KICK_IN, HOME)
    assert st.ball.tolist() == [-20.0, -HW]


def test_players_use_the_pause_after_a_goal_to_go_back_and_stragglers_end_on_the_halfway_line():
    moves = {5: (10.0, 2.0), 6: (30.0, -5.0)}
    ref, st, ev = make_world(ball=(52.0, 0.0), last_touch=9, moves=moves)
    step(ref, st)
    move_ball(st, HL + 1.0, 0.0)
    step(ref, st)
    assert st.play_mode == PlayMode.AFTER_GOAL
    st.pos[6] = (-12.0, -5.0)  # player 6 walks home during the pause; player 5 stays
    for _ in range(CFG.rules.goal_pause_cycles):
        assert st.pos[5].tolist() == [10.0, 2.0]  # the referee moves nobody during the pause
        step(ref, st)
    assert st.play_mode == PlayMode.KICK_OFF and st.mode_team == AWAY
    # The straggler is put on the halfway line (outside the centre circle), not reflected to x = -10.
    assert st.pos[5, 0] == 0.0 and st.pos[5, 1] == pytest.approx(CFG.field.centre_circle_radius)
    assert st.pos[6].tolist() == [-12.0, -5.0]
    assert np.hypot(st.pos[:N, 0], st.pos[:N, 1]).min() >= CFG.field.centre_circle_radius - 1e-9


def test_teams_may_place_their_players_with_move_during_the_pause_after_a_goal():
    ref, st, ev = make_world(ball=(52.0, 0.0), last_touch=9, moves={6: (30.0, -5.0)})
    step(ref, st)
    move_ball(st, HL + 1.0, 0.0)
    step(ref, st)
    targets = st.pos[:N].copy()
    targets[6] = (-12.0, -5.0)
    targets[7] = (20.0, 1.0)  # asks for the opponents' half: clamped onto the halfway line
    ref.apply_moves(st, HOME, targets)
    assert st.pos[6].tolist() == [-12.0, -5.0]
    assert st.pos[7, 0] == 0.0
    ref2, st2, _ = make_world(ball=(10.0, 0.0))  # in play on a move is ignored
    before = st2.pos.copy()
    ref2.apply_moves(st2, HOME, targets)
    assert np.array_equal(st2.pos, before)


@pytest.mark.parametrize("x, taker", [(-20.0, HOME), (20.0, AWAY)])
def test_kick_in_with_no_last_touch_goes_to_the_team_defending_that_half(x, taker):
    ref, st, ev = make_world(ball=(x, 33.0), last_touch=NO_PLAYER)
    step(ref, st)
    move_ball(st, x, HW + 1.0)
    step(ref, st)
    assert (st.play_mode, st.mode_team) == (PlayMode.KICK_IN, taker)
    [(_, team, player, _, _, _)] = ev.of_kind(EventKind.OUT)
    assert (team, player) == (NO_TEAM, NO_PLAYER)


@pytest.mark.parametrize("y", [20.0, -20.0])
def test_ball_out_over_the_goal_line_off_a_defender_is_a_corner_at_the_nearer_corner(y):
    ref, st, ev = make_world(ball=(52.0, y), last_touch=N + 3)  # away defends +x
    step(ref, st)
    move_ball(st, HL + 1.0, y)
    step(ref, st)
    assert (st.play_mode, st.mode_team) == (PlayMode.CORNER_KICK, HOME)
    inset = CFG.rules.corner_inset  # 1 m inside the corner along both lines
    assert st.ball.tolist() == [HL - inset, np.sign(y) * (HW - inset)]
    assert ev.of_kind(EventKind.OUT)[0][5] == 1  # goal line


@pytest.mark.parametrize("y", [20.0, -20.0])
def test_ball_out_over_the_goal_line_off_an_attacker_is_a_goal_kick_at_the_goal_area(y):
    ref, st, ev = make_world(ball=(52.0, y), last_touch=8)
    step(ref, st)
    move_ball(st, HL + 1.0, y)
    step(ref, st)
    assert (st.play_mode, st.mode_team) == (PlayMode.GOAL_KICK, AWAY)
    f = CFG.field
    assert st.ball.tolist() == [HL - f.goal_area_length, np.sign(y) * f.goal_area_width / 2]


def test_ball_out_over_a_goal_line_with_no_last_touch_is_a_goal_kick():
    ref, st, ev = make_world(ball=(-52.0, 20.0), last_touch=NO_PLAYER)
    step(ref, st)
    move_ball(st, -HL - 1.0, 20.0)
    step(ref, st)
    assert (st.play_mode, st.mode_team) == (PlayMode.GOAL_KICK, HOME)


def test_corner_after_half_time_goes_to_the_team_now_attacking_that_goal():
    ref, st, ev = make_world(ball=(52.0, 10.0), home_attacks=-1, last_touch=2)  # home defends +x
    step(ref, st)
    move_ball(st, HL + 1.0, 10.0)
    step(ref, st)
    assert (st.play_mode, st.mode_team) == (PlayMode.CORNER_KICK, AWAY)


def test_ball_crossing_near_the_corner_is_judged_on_the_line_crossed_first():
    ref, st, ev = make_world(ball=(51.0, 33.5), last_touch=N + 1)
    step(ref, st)
    move_ball(st, 54.0, 35.5)  # crosses the touchline after 29 % of the way, the goal line after 53 %
    step(ref, st)
    assert (st.play_mode, st.mode_team) == (PlayMode.KICK_IN, HOME)
    assert st.ball[1] == HW and st.ball[0] <= HL
