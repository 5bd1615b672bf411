"""Properties of the referee's geometry on random situations (hypothesis)."""

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from soccer_sim.config import MatchConfig
from soccer_sim.rules.offside import mark_offside_positions
from soccer_sim.state import AWAY, HOME, EventKind, PlayMode
from tests.soccer_sim.referee_world import N, make_world, step

CFG = MatchConfig()
F = CFG.field
GROUND = (F.half_length + F.margin, F.half_width + F.margin)
SETTINGS = settings(max_examples=60, deadline=None, derandomize=True)

coordinate_x = st.floats(-GROUND[0], GROUND[0], allow_nan=False)
coordinate_y = st.floats(-GROUND[1], GROUND[1], allow_nan=False)
positions = st.lists(st.tuples(coordinate_x, coordinate_y), min_size=2 * N, max_size=2 * N).map(np.array)


def offside_by_the_book(pos, team, direction, ball_x, kicker):
    """One player at a time, straight from the rule's wording."""
    own = range(team * N, (team + 1) * N)
    opponents = sorted((direction * pos[r, 0] for r in range((1 - team) * N, (2 - team) * N)), reverse=True)
    second_last = opponents[1]
    marked = set()
    for r in own:
        depth = direction * pos[r, 0]
        if r != kicker and depth > 0 and depth > direction * ball_x and depth > second_last:
            marked.add(r)
    return marked


@SETTINGS
@given(pos=positions, team=st.sampled_from([HOME, AWAY]), direction=st.sampled_from([1, -1]),
       ball_x=coordinate_x, kicker=st.integers(0, N - 1))
def test_offside_marks_match_the_rule_player_by_player(pos, team, direction, ball_x, kicker):
    out = np.zeros(2 * N, dtype=bool)
    kicker_row = team * N + kicker
    line = mark_offside_positions(pos, N, team, direction, ball_x, np.array([kicker_row]), out)
    expected = offside_by_the_book(pos, team, direction, ball_x, kicker_row)
    assert set(np.flatnonzero(out).tolist()) == expected
    assert (line is not None) == bool(expected)
    if line is not None:  # every marked player is beyond the line, which is in the opponents' half
        assert direction * line >= 0.0
        assert all(direction * pos[row, 0] > direction * line for row in expected)


@SETTINGS
@given(pos=positions, mode=st.sampled_from([PlayMode.KICK_IN, PlayMode.CORNER_KICK, PlayMode.GOAL_KICK, PlayMode.FREE_KICK]),
       spot_x=st.floats(-F.half_length, F.half_length), spot_y=st.floats(-F.half_width, F.half_width),
       team=st.sampled_from([HOME, AWAY]))
def test_set_play_clearance_holds_for_any_spot_and_positions(pos, mode, spot_x, spot_y, team):
    ref, s, ev = make_world(ball=(spot_x, spot_y), mode=mode, mode_team=team)
    s.pos[:] = pos
    step(ref, s)
    other = s.pos[(1 - team) * N:(2 - team) * N]
    dist = np.hypot(other[:, 0] - spot_x, other[:, 1] - spot_y)
    assert dist.min() >= CFG.rules.set_play_clearance - 1e-9
    assert (np.abs(other) <= np.array(GROUND) + 1e-9).all()
    assert np.array_equal(s.pos[team * N:(team + 1) * N], pos[team * N:(team + 1) * N])
    assert s.ball.tolist() == [spot_x, spot_y]


@SETTINGS
@given(pos=positions, team=st.sampled_from([HOME, AWAY]), home_attacks=st.sampled_from([1, -1]))
def test_kick_off_positions_hold_for_any_positions(pos, team, home_attacks):
    ref, s, ev = make_world(mode=PlayMode.KICK_OFF, mode_team=team, home_attacks=home_attacks)
    s.pos[:] = pos
    step(ref, s)
    for t in (HOME, AWAY):
        assert (s.attack_direction(t) * s.pos[t * N:(t + 1) * N, 0] <= 0.0).all()
    other = s.pos[(1 - team) * N:(2 - team) * N]
    assert np.hypot(other[:, 0], other[:, 1]).min() >= F.centre_circle_radius - 1e-9


@SETTINGS
@given(x0=st.floats(-50.0, 50.0), y0=st.floats(-32.0, 32.0), speed=st.floats(0.5, 3.0),
       angle=st.floats(-math.pi, math.pi))
def test_shot_events_agree_with_a_simulated_free_ball(x0, y0, speed, angle):
    """A kick is a SHOT exactly when the decaying ball, left alone, crosses the opponents'
    goal line between the posts (checked by stepping the ball cycle by cycle)."""
    ref, s, ev = make_world(ball=(x0, y0))
    vx, vy = speed * math.cos(angle), speed * math.sin(angle)
    s.ball_vel[:] = (vx, vy)
    ref.on_commands(s, np.array([5]), np.zeros(2, dtype=bool))
    goal_x = F.half_length + CFG.physics.ball_radius
    x, y, crossed = x0, y0, False
    for _ in range(2000):
        nx, ny = x + vx, y + vy
        if nx > goal_x:
            cross_y = y + (goal_x - x) / (nx - x) * (ny - y)
            crossed = abs(cross_y) < F.goal_width / 2
            break
        x, y, vx, vy = nx, ny, vx * CFG.physics.ball_decay, vy * CFG.physics.ball_decay
    assert (len(ev.of_kind(EventKind.SHOT)) == 1) == crossed
