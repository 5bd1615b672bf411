"""Interception: the cycle and point at which players reach a rolling ball, checked against the
motion rules rolled forward by hand."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import UNREACHABLE, MotionModel, Players, SkillContext, ball_race, intercept, intercept_many
from tests.agents.skills.skill_views import CONFIG, HW, ball_at, make_view, roll_player, run_straight

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
KICKABLE = CONFIG.physics.kickable_distance
TOUCH = CONFIG.physics.player_radius + CONFIG.physics.ball_radius


def first_reach_by_hand(pos, vel, ball, ball_vel, effort=1.0, limit=60) -> int:
    """The first cycle k at which a player running flat out ends within the kickable distance
    of the ball's position at k, or within the touch distance of the ball's path during
    cycle k (the ball stops against a body): the model rolled forward by hand."""
    for k in range(limit + 1):
        target = ball_at(CONFIG, ball, ball_vel, k)
        end = run_straight(CONFIG, pos, vel, target, k, effort)
        if np.hypot(*(end - target)) <= KICKABLE + 1e-9:
            return k
        if k > 0:
            before = ball_at(CONFIG, ball, ball_vel, k - 1)
            coast = roll_player(CONFIG, pos, vel, (0.0, 0.0), k)
            path = target - before
            t = np.clip((coast - before) @ path / (path @ path), 0.0, 1.0) if path @ path > 0 else 0.0
            nearest = before + t * path
            end = run_straight(CONFIG, pos, vel, nearest, k, effort)
            if np.hypot(*(end - nearest)) <= TOUCH + 1e-9:
                return k
    return UNREACHABLE


def test_reach_table_follows_the_dash_rule() -> None:
    # Full dashes from rest: 0.6, then 0.6 + 0.4 * 0.6 = 0.84, ... towards the top speed 1.0.
    assert MODEL.reach[:4] == pytest.approx([0.0, 0.6, 1.44, 2.376])
    assert MODEL.top_speed == pytest.approx(CONFIG.physics.player_accel_max / (1 - CONFIG.physics.player_decay))
    assert np.all(np.diff(MODEL.reach[20:]) == pytest.approx(MODEL.top_speed))


def test_player_at_rest_meets_a_rolling_ball_where_the_model_says() -> None:
    ball, ball_vel = np.array([0.0, 0.0]), np.array([2.0, 0.0])
    pos = np.array([[20.0, 5.0]])
    result = intercept(CTX, ball, ball_vel, Players(MODEL, pos, np.zeros((1, 2))))
    expected = first_reach_by_hand(pos[0], (0.0, 0.0), ball, ball_vel)
    assert 0 < expected < 60
    assert result.cycles[0] == expected and result.first == 0 and result.first_cycle == expected
    assert result.points[0] == pytest.approx(ball_at(CONFIG, ball, ball_vel, expected))
    # The numbers: after 9 cycles the ball is at x = 2 (1 - 0.94^9) / 0.06 = 14.23, 7.63 m from
    # the player, who covers 8.33 m in 9 cycles (plus the kickable 1.085); after 8 cycles the
    # ball is at 13.01, 8.59 m away, but 7.33 + 1.085 = 8.42 m is not enough.
    assert result.cycles[0] == 9
    assert result.points[0] == pytest.approx([2.0 * (1 - 0.94 ** 9) / 0.06, 0.0])


def test_the_chosen_player_is_truly_first() -> None:
    rng = np.random.default_rng(3)
    for _ in range(6):
        pos = rng.uniform([-30, -20], [30, 20], (11, 2))
        vel = rng.uniform(-0.4, 0.4, (11, 2))
        ball, ball_vel = rng.uniform(-10, 10, 2), rng.uniform(-1.5, 1.5, 2)
        result = intercept(CTX, ball, ball_vel, Players(MODEL, pos, vel))
        by_hand = [first_reach_by_hand(pos[i], vel[i], ball, ball_vel) for i in range(11)]
        horizon_hits = [c for c in result.cycles if c <= MODEL.horizon]
        assert [min(c, UNREACHABLE) for c in result.cycles if c <= MODEL.horizon] == \
            [by_hand[i] for i in range(11) if result.cycles[i] <= MODEL.horizon]
        assert horizon_hits, "some player reaches a ball rolling in the middle of the field"
        assert result.first_cycle == min(by_hand) and by_hand[result.first] == min(by_hand)


def test_a_moving_player_coasts_towards_the_ball() -> None:
    ball, ball_vel = np.array([0.0, 0.0]), np.array([0.0, 0.0])
    pos = np.array([[6.0, 0.0], [6.0, 0.0]])
    vel = np.array([[-1.0, 0.0], [1.0, 0.0]])  # one runs towards the ball, one away
    result = intercept(CTX, ball, ball_vel, Players(MODEL, pos, vel))
    assert result.cycles[0] < result.cycles[1]
    assert result.cycles[0] == first_reach_by_hand(pos[0], vel[0], ball, ball_vel)
    assert result.cycles[1] == first_reach_by_hand(pos[1], vel[1], ball, ball_vel)


def test_a_tired_player_arrives_later() -> None:
    ball, ball_vel = np.array([0.0, 0.0]), np.array([0.5, 0.0])
    pos = np.array([[15.0, 8.0], [15.0, 8.0]])
    result = intercept(CTX, ball, ball_vel, Players(MODEL, pos, np.zeros((2, 2)), effort=np.array([1.0, 0.6])))
    assert result.cycles[1] > result.cycles[0]
    assert result.cycles[1] == first_reach_by_hand(pos[1], (0, 0), ball, ball_vel, effort=0.6)


def test_ball_leaving_the_field_is_unreachable_for_the_slow() -> None:
    ball, ball_vel = np.array([0.0, HW - 3.0]), np.array([0.0, 2.0])  # crosses the touchline in 2 cycles
    pos = np.array([[0.0, HW - 2.5], [-20.0, 0.0]])
    result = intercept(CTX, ball, ball_vel, Players(MODEL, pos, np.zeros((2, 2))))
    assert result.cycles[0] <= 1
    assert result.cycles[1] == UNREACHABLE
    last_inside = ball_at(CONFIG, ball, ball_vel, 1)
    assert result.points[1] == pytest.approx(last_inside)


def test_beyond_the_horizon_the_cycle_is_estimated_not_lost() -> None:
    short = MotionModel.even_sides(CONFIG, horizon=10)
    ball, ball_vel = np.array([0.0, 0.0]), np.array([0.1, 0.0])
    pos = np.array([[30.0, 0.0], [45.0, 0.0]])
    result = intercept(SkillContext(short), ball, ball_vel, Players(short, pos, np.zeros((2, 2))))
    assert 10 < result.cycles[0] < result.cycles[1] < UNREACHABLE
    # The estimate: about (distance - kickable - reach(10)) / top speed cycles after the horizon.
    assert result.cycles[0] == pytest.approx(10 + (30.0 - 1.0 - KICKABLE - short.reach[10]), abs=2)


def test_ball_race_names_the_winning_team() -> None:
    view = make_view(own={5: (-5.0, 0.0)}, opp={5: (12.0, 0.0)}, ball=(0.0, 0.0), ball_vel=(1.0, 0.0))
    race = ball_race(CTX, view)
    assert race.ours.first == 5 and race.theirs.first == 5
    assert not race.we_win and race.lead < 0
    view = make_view(own={5: (3.0, 1.0)}, opp={5: (12.0, 0.0)}, ball=(0.0, 0.0), ball_vel=(1.0, 0.0))
    race = ball_race(CTX, view)
    assert race.we_win and race.lead > 0


def test_ball_race_follows_a_view_overwritten_in_place() -> None:
    """A match overwrites its view's arrays every cycle; the race must see the new values
    (its checked inputs are kept between calls), and a view with new arrays too."""
    ctx = SkillContext(MotionModel.even_sides(CONFIG))
    view = make_view(own={5: (-5.0, 0.0)}, opp={5: (12.0, 0.0)}, ball=(0.0, 0.0), ball_vel=(1.0, 0.0))
    assert not ball_race(ctx, view).we_win
    view.own_pos[5] = (3.0, 1.0)  # in place, as the match does
    view.ball_vel[:] = (0.5, 0.0)
    race = ball_race(ctx, view)
    fresh = ball_race(SkillContext(MotionModel.even_sides(CONFIG)),
                      make_view(own={5: (3.0, 1.0)}, opp={5: (12.0, 0.0)}, ball=(0.0, 0.0), ball_vel=(0.5, 0.0)))
    assert race.we_win and race.ours.first == 5
    np.testing.assert_array_equal(race.ours.cycles, fresh.ours.cycles)
    np.testing.assert_array_equal(race.theirs.cycles, fresh.theirs.cycles)
    other = make_view(own={5: (-5.0, 0.0)}, opp={5: (12.0, 0.0)}, ball=(0.0, 0.0), ball_vel=(1.0, 0.0))
    assert not ball_race(ctx, other).we_win  # new array objects: checked and used afresh


def test_many_trajectories_match_single_calls_and_respect_limits() -> None:
    rng = np.random.default_rng(1)
    pos, vel = rng.uniform(-20, 20, (11, 2)), np.zeros((11, 2))
    balls, vels = rng.uniform(-5, 5, (6, 2)), rng.uniform(-2, 2, (6, 2))
    players = Players(MODEL, pos, vel)
    cycles, points = intercept_many(CTX, balls, vels, players)
    for p in range(6):
        one = intercept(CTX, balls[p], vels[p], players)
        assert np.array_equal(one.cycles, cycles[p]) and np.allclose(one.points, points[p])
    limited, _ = intercept_many(CTX, balls, vels, players, limit=np.full(6, 3))
    assert np.all((limited == cycles) | ((limited == UNREACHABLE) & (cycles > 3)))


def test_first_only_and_pruned_searches_agree_with_the_full_one() -> None:
    rng = np.random.default_rng(7)
    pos, vel = rng.uniform(-40, 40, (11, 2)), rng.uniform(-0.4, 0.4, (11, 2))
    vels = rng.uniform(-2.5, 2.5, (40, 2))
    start = np.array([1.0, -2.0])
    players = Players(MODEL, pos, vel)
    full, _ = intercept_many(CTX, start, vels, players)
    first, _ = intercept_many(CTX, start, vels, players, first_only=True)
    assert np.array_equal(first.min(axis=1), full.min(axis=1))
    assert np.all((first == full) | (first == UNREACHABLE))
    limits = rng.integers(0, 30, 40)
    limited, _ = intercept_many(CTX, start, vels, players, limit=limits)  # far players pruned
    inside = full <= limits[:, None]
    assert np.array_equal(limited[inside], full[inside]) and np.all(limited[~inside] == UNREACHABLE)
    one = rng.integers(0, 11, 40)
    alone, _ = intercept_many(CTX, start, vels, players, only=one)
    rows = np.arange(40)
    assert np.array_equal(alone[rows, one], full[rows, one])
    mask = np.ones_like(alone, dtype=bool)
    mask[rows, one] = False
    assert np.all(alone[mask] == UNREACHABLE)


def test_a_fast_ball_is_stopped_by_a_body_in_its_path() -> None:
    # An opponent who has not reacted yet (reaction 1) stands 0.3 m beside the path of a ball
    # that jumps 3 m in the first cycle: the ball never ends a cycle within its kickable
    # distance (3.0 is 1.53 m away, and the ball is long gone when it could run), but it runs
    # into the body on the way.
    cycles, points = intercept_many(CTX, np.zeros(2), np.array([[3.0, 0.0]]),
                                    Players(MODEL, np.array([[1.5, 0.3]]), np.zeros((1, 2))), reaction=1)
    assert cycles[0, 0] == 1
    assert points[0, 0] == pytest.approx([1.5, 0.0])  # the nearest point of the first cycle's path
    cycles, _ = intercept_many(CTX, np.zeros(2), np.array([[3.0, 0.0]]),
                               Players(MODEL, np.array([[1.5, 0.6]]), np.zeros((1, 2))), reaction=1)
    assert cycles[0, 0] > 1  # 0.6 m away: beyond the touch distance (0.385 m)


def test_players_left_out_of_the_race_never_win_it() -> None:
    view = make_view(own={5: (3.0, 1.0), 6: (8.0, 0.0)}, ball=(0.0, 0.0), ball_vel=(1.0, 0.0))
    assert ball_race(CTX, view).ours.first == 5
    eligible = np.ones(11, dtype=bool)
    eligible[5] = False  # e.g. offside when the pass was made
    race = ball_race(CTX, view, eligible)
    assert race.ours.first == 6 and race.ours.cycles[5] == UNREACHABLE
    with pytest.raises(ValueError, match="eligible"):
        ball_race(CTX, view, np.ones(3, dtype=bool))


def test_their_first_only_race_names_the_same_first_opponent() -> None:
    """The cheaper race (opponents searched only to their first interception) agrees with the
    full one on who gets there first, when and where, on random states (ties included: two
    opponents level with each other), and leaves our side untouched."""
    rng = np.random.default_rng(7)
    for trial in range(300):
        opp = rng.uniform((-50.0, -32.0), (50.0, 32.0), (11, 2))
        if trial % 10 == 0:
            opp[3] = opp[4] * np.array([1.0, -1.0])  # mirror twins
        view = make_view(own=rng.uniform((-50.0, -32.0), (50.0, 32.0), (11, 2)), opp=opp,
                         ball=rng.uniform((-50.0, -32.0), (50.0, 32.0)), ball_vel=rng.uniform(-2.5, 2.5, 2),
                         own_vel=rng.uniform(-0.5, 0.5, (11, 2)), opp_vel=rng.uniform(-0.5, 0.5, (11, 2)))
        full, cheap = ball_race(CTX, view), ball_race(CTX, view, their_first_only=True)
        assert cheap.theirs.first == full.theirs.first
        assert cheap.theirs.first_cycle == full.theirs.first_cycle
        if full.theirs.first >= 0:
            assert np.array_equal(cheap.theirs.points[full.theirs.first], full.theirs.points[full.theirs.first])
        assert np.array_equal(cheap.ours.cycles, full.ours.cycles)
        assert np.array_equal(cheap.ours.points, full.ours.points)


def test_ball_race_keeps_the_checked_inputs_of_views_sliced_from_a_buffer() -> None:
    """A match's view arrays are rows of its own (P + 1, 2) buffers (the ball is the last row);
    the race still recognises them from one cycle to the next and reuses its checked inputs,
    which follow the view in place."""
    view = make_view(own={5: (-5.0, 0.0)}, opp={5: (12.0, 0.0)}, ball=(0.0, 0.0), ball_vel=(1.0, 0.0))
    n = len(view.own_pos)
    pos, vel = np.empty((2 * n + 1, 2)), np.empty((2 * n + 1, 2))
    pos[:n], pos[n:2 * n], pos[2 * n] = view.own_pos, view.opp_pos, view.ball
    vel[:n], vel[n:2 * n], vel[2 * n] = view.own_vel, view.opp_vel, view.ball_vel
    view.own_pos, view.opp_pos, view.ball = pos[:n], pos[n:2 * n], pos[2 * n]
    view.own_vel, view.opp_vel, view.ball_vel = vel[:n], vel[n:2 * n], vel[2 * n]
    ctx = SkillContext(MotionModel.even_sides(CONFIG))
    assert not ball_race(ctx, view).we_win
    held = ctx.arrays(view)
    assert held.ours.pos is view.own_pos and held.theirs.vel is view.opp_vel  # the view's own arrays
    pos[5] = (3.0, 1.0)
    pos[2 * n] = (0.0, 0.0)
    race = ball_race(ctx, view)
    assert ctx.arrays(view) is held and race.we_win and race.ours.first == 5
