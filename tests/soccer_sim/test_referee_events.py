"""KICK, SHOT, PASS, TOUCH and SET_PLAY events."""

import pytest

from soccer_sim.config import MatchConfig
from soccer_sim.state import AWAY, HOME, EventKind, PlayMode
from tests.soccer_sim.referee_world import N, config_with, kick, kinds, make_world, step

CFG = MatchConfig()
HL = CFG.field.half_length
GOAL_LINE = HL + CFG.physics.ball_radius
REACH = 1.0 / (1.0 - CFG.physics.ball_decay)  # total distance / initial speed of a free ball


def shots(ev):
    return ev.of_kind(EventKind.SHOT)


def test_kick_towards_goal_that_reaches_it_is_a_shot():
    ref, st, ev = make_world(ball=(20.0, 0.0), moves={9: (19.5, 0.0)}, config=config_with(offside=False))
    kick(ref, st, [9], (2.5, 0.3))  # reaches x = 20 + 2.5 * 16.7 = 61.7: crosses at y = 3.9
    assert kinds(ev) == [EventKind.KICK, EventKind.SHOT]
    [(cycle, team, player, x, y, _)] = shots(ev)
    assert (cycle, team, player, x, y) == (100, HOME, 9, 20.0, 0.0)


def test_kick_too_weak_to_reach_the_goal_line_is_not_a_shot():
    speed = (GOAL_LINE - 20.0) / REACH * 0.98
    ref, st, ev = make_world(ball=(20.0, 0.0))
    kick(ref, st, [9], (speed, 0.0))
    assert shots(ev) == []
    ref, st, ev = make_world(ball=(20.0, 0.0))
    kick(ref, st, [9], (speed / 0.98 * 1.02, 0.0))
    assert len(shots(ev)) == 1


@pytest.mark.parametrize("vy, is_shot", [(1.0, True), (1.2, False), (-1.2, False)])
def test_kick_wide_of_the_posts_is_not_a_shot(vy, is_shot):
    ref, st, ev = make_world(ball=(40.0, 0.0))
    kick(ref, st, [9], (2.0, vy))
    crossing_y = vy * (GOAL_LINE - 40.0) / 2.0  # 6.3 m (inside the posts) or 7.55 m (wide)
    assert (abs(crossing_y) < CFG.field.goal_width / 2) == is_shot
    assert len(shots(ev)) == int(is_shot)


def test_kick_towards_the_own_goal_is_not_a_shot():
    ref, st, ev = make_world(ball=(-40.0, 0.0))
    kick(ref, st, [3], (-2.5, 0.0))
    assert shots(ev) == []


def test_away_shots_go_towards_minus_x_and_swap_at_half_time():
    ref, st, ev = make_world(ball=(-30.0, 0.0))
    kick(ref, st, [N + 9], (-2.5, 0.0))
    assert [(e[1], e[2]) for e in shots(ev)] == [(AWAY, 9)]
    ref, st, ev = make_world(ball=(-30.0, 0.0), home_attacks=-1)
    kick(ref, st, [9], (-2.5, 0.0))
    assert [(e[1], e[2]) for e in shots(ev)] == [(HOME, 9)]


def test_pass_received_by_a_kick_or_a_touch_names_passer_and_receiver():
    ref, st, ev = make_world(ball=(-10.0, 0.0), config=config_with(offside=False))
    kick(ref, st, [4], (1.0, 0.0))
    step(ref, st)
    kick(ref, st, [7], (0.0, 1.0))  # received by a kick
    step(ref, st, touchers=[8])  # received by a touch
    passes = [(team, player, detail) for _, team, player, _, _, detail in ev.of_kind(EventKind.PASS)]
    assert passes == [(HOME, 4, 7), (HOME, 7, 8)]
    assert st.last_touch == 8


def test_an_opponent_touch_in_between_breaks_the_pass():
    ref, st, ev = make_world(ball=(-10.0, 0.0))
    kick(ref, st, [4], (1.0, 0.0))
    step(ref, st, touchers=[N + 2])
    step(ref, st, touchers=[8])
    assert ev.of_kind(EventKind.PASS) == []


def test_team_mates_kicking_together_is_not_a_pass():
    ref, st, ev = make_world(ball=(-10.0, 0.0))
    kick(ref, st, [4, 5], (1.0, 0.0))
    assert ev.of_kind(EventKind.PASS) == []
    assert len(ev.of_kind(EventKind.KICK)) == 2


def test_no_pass_across_a_restart():
    ref, st, ev = make_world(ball=(10.0, 33.9))
    kick(ref, st, [4], (0.0, 1.0))
    st.ball[:] = (10.0, 35.0)
    step(ref, st)  # out: kick-in for away
    kick(ref, st, [N + 4], (0.0, -1.0))
    step(ref, st, touchers=[N + 5])
    assert [(e[1], e[2], e[5]) for e in ev.of_kind(EventKind.PASS)] == [(AWAY, 4, 5)]


def test_touch_is_recorded_once_per_continuous_contact():
    ref, st, ev = make_world(ball=(0.0, 0.0))
    for touchers in ([3], [3], [3], [], [3]):
        step(ref, st, touchers=touchers)
    assert [e[0] for e in ev.of_kind(EventKind.TOUCH)] == [100, 104]


def test_the_nearest_of_several_touchers_touched_last():
    ref, st, ev = make_world(ball=(0.0, 0.0), moves={3: (0.0, 0.4), N + 3: (0.0, -0.3)})
    step(ref, st, touchers=[3, N + 3])
    assert st.last_touch == N + 3


@pytest.mark.parametrize("mode", [PlayMode.KICK_IN, PlayMode.GOAL_KICK, PlayMode.FREE_KICK])
def test_every_play_mode_change_is_a_set_play_event(mode):
    ref, st, ev = make_world(ball=(0.0, 20.0), mode=mode, mode_team=AWAY)
    kick(ref, st, [N + 1], (1.0, 0.0))
    assert [(e[1], e[2], e[5]) for e in ev.of_kind(EventKind.SET_PLAY)] == [(-1, 1, int(PlayMode.PLAY_ON))]


def goal_after(ref, st, ball_y=2.0):
    """Let the ball cross the home team's target goal line at ``ball_y`` (home attacks +x)."""
    step(ref, st)
    st.ball[:] = (GOAL_LINE + 0.2, ball_y)
    step(ref, st)


def test_a_goal_from_a_kick_that_looked_short_counts_as_a_shot():
    """The ball's noise can carry a kick whose noiseless path stops short over the line: every
    goal is a shot, recorded just before the GOAL for the scorer where it kicked."""
    ref, st, ev = make_world(ball=(20.0, 0.0), moves={9: (19.5, 0.0)}, config=config_with(offside=False))
    kick(ref, st, [9], ((GOAL_LINE - 20.0) / REACH * 0.9, 0.0))
    assert shots(ev) == []
    goal_after(ref, st)
    assert kinds(ev)[-3:] == [EventKind.SHOT, EventKind.GOAL, EventKind.SET_PLAY]
    [(cycle, team, player, x, y, detail)] = shots(ev)
    assert (cycle, team, player, x, y, detail) == (101, HOME, 9, 20.0, 0.0, 1)


def test_a_goal_from_a_recorded_shot_is_not_counted_twice():
    ref, st, ev = make_world(ball=(20.0, 0.0), moves={9: (19.5, 0.0)}, config=config_with(offside=False))
    kick(ref, st, [9], (2.5, 0.0))
    step(ref, st, touchers=[10])  # deflected in by a team-mate's body: still the same attempt
    goal_after(ref, st)
    assert [(e[2], e[5]) for e in shots(ev)] == [(9, 0)]
    assert tuple(st.score) == (1, 0)


def test_a_shot_touched_by_an_opponent_then_scored_by_a_touch_counts_again():
    ref, st, ev = make_world(ball=(20.0, 0.0), moves={9: (19.5, 0.0)}, config=config_with(offside=False))
    kick(ref, st, [9], (2.5, 0.0))
    step(ref, st, touchers=[N + 3])  # the opponents play the ball...
    st.ball[:] = (45.0, 1.0)
    step(ref, st, touchers=[10])  # ...and a team-mate bundles the rebound in
    goal_after(ref, st)
    assert [(e[2], e[3], e[5]) for e in shots(ev)] == [(9, 20.0, 0), (10, 45.0, 1)]


def test_an_own_goal_is_nobody_s_shot():
    ref, st, ev = make_world(ball=(50.0, 0.0), config=config_with(offside=False))
    step(ref, st, touchers=[N + 3])  # an away defender deflects the ball into its own goal
    goal_after(ref, st)
    assert tuple(st.score) == (1, 0) and shots(ev) == []


def test_a_ball_bouncing_off_a_body_to_a_team_mate_is_not_a_pass():
    ref, st, ev = make_world(ball=(-10.0, 0.0), config=config_with(offside=False))
    step(ref, st, touchers=[4])
    step(ref, st, touchers=[5])
    assert ev.of_kind(EventKind.PASS) == []


def test_the_passer_dribbling_on_keeps_its_pass_going():
    ref, st, ev = make_world(ball=(-10.0, 0.0), config=config_with(offside=False))
    kick(ref, st, [4], (0.5, 0.0))
    step(ref, st, touchers=[4])  # the kicker runs into its own ball
    step(ref, st)
    step(ref, st, touchers=[7])
    assert [(e[2], e[5]) for e in ev.of_kind(EventKind.PASS)] == [(4, 7)]
