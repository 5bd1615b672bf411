"""Kick-offs, set plays (clearance, timeout, kick mask), half time and time over."""

import numpy as np
import pytest

from soccer_sim.config import MatchConfig
from soccer_sim.state import AWAY, HOME, NO_PLAYER, NO_TEAM, EventKind, EventLog, PlayMode, WorldState
from soccer_sim.referee import Referee
from soccer_sim.setup import MatchSetup
from tests.soccer_sim.referee_world import (
    N, config_with, default_positions, kick, kinds, make_world, set_play_modes, step,
)

CFG = MatchConfig()
HL = CFG.field.half_length
HW = CFG.field.half_width
CLEAR = CFG.rules.set_play_clearance


def test_start_is_a_home_kick_off_with_teams_in_their_halves():
    rng = np.random.default_rng(3)
    pos = rng.uniform((-50.0, -30.0), (50.0, 30.0), size=(2 * N, 2))
    st = WorldState(pos=pos, vel=np.ones((2 * N, 2)), stamina=np.ones(2 * N), ball=np.array([4.0, 4.0]),
                    ball_vel=np.ones(2), cycle=0, play_mode=PlayMode.PLAY_ON, mode_team=NO_TEAM)
    ev = EventLog()
    Referee(MatchSetup.resolve(CFG), ev).start(st)
    assert (st.play_mode, st.mode_team, st.mode_start) == (PlayMode.KICK_OFF, HOME, 0)
    assert st.ball.tolist() == [0.0, 0.0] and not st.ball_vel.any() and not st.vel.any()
    assert (st.pos[:N, 0] <= 0).all() and (st.pos[N:, 0] >= 0).all()
    assert np.hypot(*st.pos[N:].T).min() >= CFG.field.centre_circle_radius - 1e-9
    assert [(e[1], e[5]) for e in ev.of_kind(EventKind.SET_PLAY)] == [(HOME, int(PlayMode.KICK_OFF))]


def test_start_rejects_a_state_of_the_wrong_size():
    st = WorldState(pos=np.zeros((10, 2)), vel=np.zeros((10, 2)), stamina=np.zeros(10),
                    ball=np.zeros(2), ball_vel=np.zeros(2))
    with pytest.raises(ValueError, match=r"WorldState.pos must have shape \(22, 2\)"):
        Referee(MatchSetup.resolve(CFG), EventLog()).start(st)


def test_kick_off_keeps_teams_in_their_halves_and_the_defenders_out_of_the_circle_every_cycle():
    ref, st, ev = make_world(mode=PlayMode.KICK_OFF, mode_team=HOME)
    st.pos[3] = (1.5, 2.0)  # home player wanders into the away half
    st.pos[N + 3] = (3.0, 4.0)  # away player walks into the centre circle
    st.pos[N + 4] = (-1.0, 8.0)  # away player crosses the halfway line
    st.vel[3] = (0.5, 0.0)
    step(ref, st)
    assert st.pos[3].tolist() == [0.0, 2.0]
    assert np.hypot(*st.pos[N + 3]) == pytest.approx(CFG.field.centre_circle_radius)
    assert st.pos[N + 3, 1] / st.pos[N + 3, 0] == pytest.approx(4.0 / 3.0)  # pushed radially
    assert st.pos[N + 4, 0] >= 0.0 and np.hypot(*st.pos[N + 4]) == pytest.approx(CFG.field.centre_circle_radius)
    assert not st.vel[3].any()
    assert st.play_mode == PlayMode.KICK_OFF


def test_apply_moves_clamps_into_the_own_half_and_keeps_the_defenders_out_of_the_circle():
    ref, st, ev = make_world(mode=PlayMode.KICK_OFF, mode_team=AWAY)
    targets = default_positions()[:N].copy()
    targets[1] = (20.0, 12.0)  # home in the away half
    targets[2] = (-2.0, 0.0)  # inside the centre circle
    targets[3] = (-80.0, 50.0)  # off the field
    ref.apply_moves(st, HOME, targets)
    assert st.pos[1].tolist() == [0.0, 12.0]
    assert st.pos[2].tolist() == pytest.approx([-CFG.field.centre_circle_radius, 0.0])
    assert st.pos[3].tolist() == [-HL, HW]
    assert np.array_equal(st.pos[4:N], targets[4:N])
    # The kicking team may stand inside the circle next to the ball, but not beyond halfway.
    away_targets = -default_positions()[:N]
    away_targets[9] = (0.5, 0.0)
    away_targets[10] = (-0.5, 1.0)
    ref.apply_moves(st, AWAY, away_targets)
    assert st.pos[N + 9].tolist() == [0.5, 0.0]
    assert st.pos[N + 10].tolist() == [0.0, 1.0]


def test_apply_moves_is_ignored_after_the_kick_off_and_checks_its_input():
    ref, st, ev = make_world(mode=PlayMode.PLAY_ON)
    before = st.pos.copy()
    ref.apply_moves(st, HOME, np.zeros((N, 2)))
    assert np.array_equal(st.pos, before)
    ref, st, ev = make_world(mode=PlayMode.KICK_OFF, mode_team=HOME)
    with pytest.raises(ValueError, match="team 0"):
        ref.apply_moves(st, HOME, np.zeros((N - 1, 2)))


@pytest.mark.parametrize("mode, spot", [
    (PlayMode.CORNER_KICK, (HL, HW)),
    (PlayMode.KICK_IN, (10.0, -HW)),
    (PlayMode.FREE_KICK, (30.0, 5.0)),
    (PlayMode.GOAL_KICK, (-HL + 5.5, 9.16)),
])
def test_opponents_are_kept_clear_of_the_ball_at_set_plays(mode, spot):
    ref, st, ev = make_world(ball=spot, mode=mode, mode_team=HOME)
    rng = np.random.default_rng(1)
    st.pos[:] = np.asarray(spot) + rng.uniform(-6.0, 6.0, size=(2 * N, 2))
    home_before = st.pos[:N].copy()
    limit = np.array([HL + CFG.field.margin, HW + CFG.field.margin])
    step(ref, st)
    for _ in range(3):
        st.pos[N:] += rng.uniform(-1.0, 1.0, size=(N, 2))  # the opponents keep trying to close in
        np.clip(st.pos[N:], -limit, limit, out=st.pos[N:])  # as the physics keeps them on the ground
        st.ball[:] += 0.3  # a body bumped the ball
        step(ref, st)
        dist = np.hypot(*(st.pos[N:] - np.asarray(spot)).T)
        assert dist.min() >= CLEAR - 1e-9
        assert (np.abs(st.pos[N:]) <= limit + 1e-9).all()
        assert st.ball.tolist() == list(spot) and not st.ball_vel.any()
    assert np.array_equal(st.pos[:N], home_before)  # the team taking the set play is never moved
    assert st.play_mode == mode


def test_a_set_play_not_taken_in_time_is_restarted_by_dropping_the_ball():
    ref, st, ev = make_world(ball=(10.0, HW), mode=PlayMode.KICK_IN, mode_team=AWAY, cycle=200,
                             config=config_with(set_play_timeout=10))
    st.mode_start = 201  # the kick-in was called at cycle 200; teams first act on it at 201
    for _ in range(10):  # cycles 200..209 are judged
        step(ref, st)
    assert st.play_mode == PlayMode.KICK_IN
    step(ref, st)  # cycle 210 is the tenth cycle of the set play: the ball is dropped
    assert st.play_mode == PlayMode.PLAY_ON and st.mode_team == NO_TEAM
    [(cycle, team, player, x, y, detail)] = ev.of_kind(EventKind.DROP_BALL)
    assert (cycle, x, y, detail) == (210, 10.0, HW, int(PlayMode.KICK_IN))
    assert st.ball.tolist() == [10.0, HW] and not st.ball_vel.any()
    assert set_play_modes(ev) == [PlayMode.PLAY_ON]


def test_taking_a_set_play_in_time_means_no_drop_ball():
    ref, st, ev = make_world(ball=(10.0, HW), mode=PlayMode.KICK_IN, mode_team=AWAY,
                             config=config_with(set_play_timeout=10), moves={N + 5: (10.0, HW - 0.5)})
    for _ in range(5):
        step(ref, st)
    kick(ref, st, [N + 5], (0.0, -2.0))
    assert st.play_mode == PlayMode.PLAY_ON
    for _ in range(20):
        st.ball += st.ball_vel
        st.ball_vel *= 0.94
        step(ref, st)
    assert EventKind.DROP_BALL not in kinds(ev)
    [(_, team, player, _, _, detail)] = ev.of_kind(EventKind.SET_PLAY)
    assert (team, player, detail) == (NO_TEAM, 5, int(PlayMode.PLAY_ON))


def test_kick_mask_by_play_mode_is_cached_and_read_only():
    ref, st, ev = make_world()
    everyone = ref.kick_mask(st)
    assert everyone.all() and ref.kick_mask(st) is everyone
    with pytest.raises(ValueError):
        everyone[0] = False
    for mode in (PlayMode.KICK_OFF, PlayMode.KICK_IN, PlayMode.CORNER_KICK, PlayMode.GOAL_KICK, PlayMode.FREE_KICK):
        st.play_mode, st.mode_team = mode, AWAY
        mask = ref.kick_mask(st)
        assert not mask[:N].any() and mask[N:].all()
    st.play_mode, st.mode_team, st.ball_holder = PlayMode.GOALIE_HOLDS, AWAY, N
    assert np.flatnonzero(ref.kick_mask(st)).tolist() == [N]
    st.play_mode, st.mode_team = PlayMode.TIME_OVER, NO_TEAM
    assert not ref.kick_mask(st).any()


def test_kicks_by_the_mode_team_take_the_set_play():
    ref, st, ev = make_world(ball=(HL, HW), mode=PlayMode.CORNER_KICK, mode_team=HOME, moves={9: (HL - 0.5, HW - 0.5)})
    kick(ref, st, [9], (-2.0, -1.0))
    assert st.play_mode == PlayMode.PLAY_ON and st.mode_start == st.cycle + 1
    assert kinds(ev) == [EventKind.KICK, EventKind.SET_PLAY]


def test_half_time_keeps_the_ends_and_the_away_team_kicks_off():
    """rcssserver 19 changes no sides at half time: the right-hand team kicks off the second half."""
    ref, st, ev = make_world(cycle=49, ball=(20.0, 5.0), ball_vel=(1.0, 0.0), config=config_with(half_cycles=50),
                             last_touch=4)
    st.pos[4] = (-10.0, 5.0)
    st.pos[N + 4] = (-12.0, 3.0)  # an away player in home's half
    step(ref, st)
    assert (st.half, st.home_attacks, st.cycle) == (1, 1, 50)
    assert st.pos[4].tolist() == [-10.0, 5.0]  # home keeps its end: nobody is moved who stands in their half
    assert st.pos[N + 4].tolist() == [12.0, 3.0]  # reflected across the halfway line into its own half
    assert (st.pos[:N, 0] <= 0).all() and (st.pos[N:, 0] >= 0).all()
    assert (st.play_mode, st.mode_team, st.mode_start) == (PlayMode.KICK_OFF, AWAY, 50)
    assert st.ball.tolist() == [0.0, 0.0] and not st.ball_vel.any()
    assert np.hypot(*st.pos[:N].T).min() >= CFG.field.centre_circle_radius - 1e-9
    assert kinds(ev) == [EventKind.HALF_TIME, EventKind.SET_PLAY]
    assert st.attack_direction(HOME) == 1 and st.attack_direction(AWAY) == -1 and st.last_touch == NO_PLAYER


def test_time_over_after_the_last_cycle():
    ref, st, ev = make_world(cycle=98, config=config_with(half_cycles=50))
    step(ref, st)
    assert st.play_mode == PlayMode.PLAY_ON
    step(ref, st)
    assert st.play_mode == PlayMode.TIME_OVER
    assert kinds(ev) == [EventKind.TIME_OVER, EventKind.SET_PLAY]
    assert not ref.kick_mask(st).any()
    st.ball[:] = (HL + 5.0, 0.0)  # nothing is judged any more
    step(ref, st)
    assert tuple(st.score) == (0, 0) and len(ev) == 2


def test_time_over_with_a_match_shorter_than_a_half():
    from dataclasses import replace
    ref, st, ev = make_world(cycle=9, config=replace(MatchConfig(), max_cycles=10))
    step(ref, st)
    assert st.play_mode == PlayMode.TIME_OVER and st.half == 0


def test_a_defender_standing_on_the_centre_spot_is_pushed_back_into_its_own_half():
    ref, st, ev = make_world(mode=PlayMode.KICK_OFF, mode_team=HOME)
    st.pos[N + 2] = (0.0, 0.0)  # away defends +x
    st.pos[N + 3] = (0.0, 9.15)  # on the circle already: stays exactly where it is
    step(ref, st)
    assert st.pos[N + 2].tolist() == [CFG.field.centre_circle_radius, 0.0]
    assert st.pos[N + 3].tolist() == [0.0, 9.15]


def test_a_ball_stuck_in_play_on_is_dropped_and_the_crowd_pushed_back():
    rules = CFG.rules
    scrum = {3: (10.5, 0.0), 4: (9.0, 1.0), N + 3: (11.0, -0.5)}
    ref, st, ev = make_world(ball=(10.0, 0.0), moves=scrum)
    step(ref, st)  # the referee notes where the ball is: the first of the stuck cycles
    for k in range(rules.stuck_ball_cycles - 2):
        st.ball[:] = (10.0 + 2.0 * np.sin(k), 1.0 * np.cos(k))  # jostled about, never 3 m away
        step(ref, st)
    assert EventKind.DROP_BALL not in kinds(ev)
    step(ref, st)
    [(cycle, team, player, x, y, detail)] = ev.of_kind(EventKind.DROP_BALL)
    assert detail == PlayMode.PLAY_ON and st.play_mode == PlayMode.PLAY_ON
    d = np.hypot(st.pos[:, 0] - st.ball[0], st.pos[:, 1] - st.ball[1])
    assert d.min() >= rules.stuck_ball_radius - 1e-9  # everybody pushed out to the radius


def test_a_moving_ball_is_never_dropped():
    ref, st, ev = make_world(ball=(-40.0, 0.0))
    for k in range(400):
        st.ball[:] = (-40.0 + 0.2 * k, 5.0 * np.sin(k / 20))  # slow, but it gets somewhere
        step(ref, st)
    assert EventKind.DROP_BALL not in kinds(ev)


GOAL_KICK_SPOT = (HL - CFG.field.goal_area_length, 9.16)  # away defends +x: its goal kick
TAKER, MATE, OPPONENT = N + 4, N + 5, 6


def goal_kick_taken(config: MatchConfig = CFG):
    """An away goal kick just taken by TAKER, the ball still inside the penalty area, a
    team-mate and an opponent of the taker close to it."""
    spot = GOAL_KICK_SPOT
    ref, st, ev = make_world(ball=spot, mode=PlayMode.GOAL_KICK, mode_team=AWAY, config=config,
                             moves={TAKER: (spot[0] + 0.5, spot[1]), MATE: (44.0, 8.0), OPPONENT: (-10.0, 0.0)})
    kick(ref, st, [TAKER], (-1.0, 0.0))
    assert st.play_mode == PlayMode.PLAY_ON
    st.ball[:] = (45.0, 8.0)  # still inside the penalty area
    step(ref, st)
    return ref, st, ev


def test_an_opponent_playing_a_goal_kick_inside_the_penalty_area_has_it_retaken():
    ref, st, ev = goal_kick_taken()
    step(ref, st, touchers=[OPPONENT])
    assert (st.play_mode, st.mode_team) == (PlayMode.GOAL_KICK, AWAY)
    assert st.ball.tolist() == list(GOAL_KICK_SPOT)
    # Taken properly: the ball leaves the area, then anybody may play it.
    kick(ref, st, [TAKER], (-2.5, 0.0))
    st.ball[:] = (30.0, 8.0)
    step(ref, st)
    step(ref, st, touchers=[OPPONENT])
    assert st.play_mode == PlayMode.PLAY_ON


def test_a_team_mate_playing_a_goal_kick_early_puts_it_in_play_by_default():
    """rcssserver's default (proper_goal_kicks off): no retake for the taker's team-mates."""
    assert not CFG.rules.proper_goal_kicks
    ref, st, ev = goal_kick_taken()
    step(ref, st, touchers=[MATE])
    assert st.play_mode == PlayMode.PLAY_ON
    kick(ref, st, [MATE], (-0.5, 0.0))
    assert st.play_mode == PlayMode.PLAY_ON
    # The ball is in play: an opponent may play it inside the area now.
    step(ref, st, touchers=[OPPONENT])
    assert st.play_mode == PlayMode.PLAY_ON
    assert set_play_modes(ev).count(PlayMode.GOAL_KICK) == 0


def test_the_goal_kick_taker_may_play_the_ball_again_before_it_leaves_the_area():
    ref, st, ev = goal_kick_taken(config_with(proper_goal_kicks=True))
    step(ref, st, touchers=[TAKER])
    kick(ref, st, [TAKER], (-1.0, 0.0))
    assert st.play_mode == PlayMode.PLAY_ON
    step(ref, st, touchers=[OPPONENT])  # the goal kick is still not in play for the opponents
    assert (st.play_mode, st.mode_team) == (PlayMode.GOAL_KICK, AWAY)


def test_proper_goal_kicks_retake_for_team_mates_then_give_the_opponents_a_free_kick():
    rules = config_with(proper_goal_kicks=True, max_goal_kicks=2)
    ref, st, ev = goal_kick_taken(rules)
    for retake in range(3):
        step(ref, st, touchers=[MATE])  # a team-mate plays it too early
        if retake < 2:
            assert (st.play_mode, st.mode_team) == (PlayMode.GOAL_KICK, AWAY), retake
            assert st.ball.tolist() == list(GOAL_KICK_SPOT)
            kick(ref, st, [TAKER], (-1.0, 0.0))
            st.ball[:] = (45.0, 8.0)
            step(ref, st)
    # The third fault in a row, with two retakes allowed: an indirect free kick for home on the
    # penalty area's edge nearest the ball.
    assert (st.play_mode, st.mode_team) == (PlayMode.FREE_KICK, HOME)
    assert st.ball.tolist() == [HL - CFG.field.penalty_area_length, 8.0]
    assert set_play_modes(ev).count(PlayMode.GOAL_KICK) == 2


def test_retakes_forced_by_the_opponents_do_not_use_up_the_goal_kicks():
    ref, st, ev = goal_kick_taken(config_with(proper_goal_kicks=True, max_goal_kicks=1))
    for _ in range(4):
        step(ref, st, touchers=[OPPONENT])
        assert (st.play_mode, st.mode_team) == (PlayMode.GOAL_KICK, AWAY)
        kick(ref, st, [TAKER], (-1.0, 0.0))
        st.ball[:] = (45.0, 8.0)
        step(ref, st)
    step(ref, st, touchers=[MATE])  # the team's first fault: retaken
    assert (st.play_mode, st.mode_team) == (PlayMode.GOAL_KICK, AWAY)


def test_opponents_leave_the_penalty_area_at_a_goal_kick():
    spot = (HL - CFG.field.goal_area_length, -9.16)
    ref, st, ev = make_world(ball=spot, mode=PlayMode.GOAL_KICK, mode_team=AWAY,
                             moves={3: (40.0, 15.0), 4: (50.0, -19.0), 5: (37.0, 0.0)})
    step(ref, st)
    pa_front = HL - CFG.field.penalty_area_length
    inside = (st.pos[:N, 0] > pa_front) & (np.abs(st.pos[:N, 1]) < CFG.field.penalty_area_width / 2)
    assert not inside.any()
    assert np.hypot(st.pos[:N, 0] - spot[0], st.pos[:N, 1] - spot[1]).min() >= CFG.rules.set_play_clearance - 1e-9
