"""Offside: marking at the kick, penalising the marked player, and the exceptions."""

import pytest

from soccer_sim.config import MatchConfig
from soccer_sim.state import AWAY, HOME, EventKind, PlayMode
from tests.soccer_sim.referee_world import N, config_with, kick, kinds, make_world, step

CFG = MatchConfig()

# Home attacks +x. The away goalkeeper (row N) stands on its goal line at x = 50 and the
# second-last away defender (row N + 1) at x = 25; all other away players are deeper
# (the default layout puts them at x = 21..30 -> moved back to 22 and below).
DEFENCE = {N + 1: (25.0, 0.0), **{N + k: (20.0 - k, 2.0 * k) for k in range(2, N)}}
KICKER = 9


def world(striker_x: float, *, ball_x: float = 10.0, config=None, mode=PlayMode.PLAY_ON, mode_team=-1):
    moves = {**DEFENCE, KICKER: (ball_x - 0.5, 0.0), 10: (striker_x, 10.0)}
    return make_world(ball=(ball_x, 0.0), moves=moves, config=config, mode=mode, mode_team=mode_team)


def run_towards_ball(ref, st, row: int, cycles: int = 30, play: bool = True) -> None:
    """Move ``row`` straight at the ball, 1 m per cycle, judging each cycle, until it stands on
    the ball (and, if ``play``, touches it) or play stops."""
    for _ in range(cycles):
        if st.play_mode != PlayMode.PLAY_ON:
            return
        d = st.ball - st.pos[row]
        dist = float((d ** 2).sum() ** 0.5)
        if dist < 1e-9:
            if play:
                step(ref, st, touchers=[row])
            return
        st.pos[row] += d / dist * min(1.0, dist)
        step(ref, st)
    raise AssertionError("the player never reached the ball")


def test_player_beyond_the_second_last_defender_is_penalised_only_when_it_plays_the_ball():
    ref, st, ev = world(striker_x=30.0)
    kick(ref, st, [KICKER], (0.0, 0.0))
    run_towards_ball(ref, st, 10, play=False)  # standing on the ball without playing it
    assert EventKind.OFFSIDE not in kinds(ev) and st.play_mode == PlayMode.PLAY_ON
    step(ref, st, touchers=[10])
    [(cycle, team, player, x, y, _)] = ev.of_kind(EventKind.OFFSIDE)
    assert (team, player) == (HOME, 10)
    assert (x, y) == (10.0, 0.0)  # where the offender played the ball
    assert (st.play_mode, st.mode_team) == (PlayMode.FREE_KICK, AWAY)
    # The free kick is taken on the offside line (the second-last defender at x = 25 when the
    # ball was played), level with the offender.
    assert st.ball.tolist() == [25.0, 0.0]


def test_the_old_approach_rule_is_still_available():
    ref, st, ev = world(striker_x=30.0, config=config_with(offside_active_distance=2.5))
    kick(ref, st, [KICKER], (0.0, 0.0))
    run_towards_ball(ref, st, 10, play=False)
    [(cycle, team, player, x, y, _)] = ev.of_kind(EventKind.OFFSIDE)
    assert (team, player) == (HOME, 10)
    assert ((x - 10.0) ** 2 + y ** 2) ** 0.5 <= 2.5


@pytest.mark.parametrize("striker_x", [25.0, 24.0])
def test_level_with_or_behind_the_second_last_defender_is_not_offside(striker_x):
    ref, st, ev = world(striker_x=striker_x)
    kick(ref, st, [KICKER], (0.0, 0.0))
    run_towards_ball(ref, st, 10)
    assert EventKind.OFFSIDE not in kinds(ev)


def test_player_in_its_own_half_is_never_offside():
    moves = {**{N + k: (-15.0 - k, 2.0 * k) for k in range(1, N)}, KICKER: (-20.0, 0.0), 10: (-1.0, 10.0)}
    ref, st, ev = make_world(ball=(-19.5, 0.0), moves=moves)
    kick(ref, st, [KICKER], (0.0, 0.0))
    run_towards_ball(ref, st, 10)
    assert EventKind.OFFSIDE not in kinds(ev)


def test_player_behind_the_ball_is_not_offside():
    ref, st, ev = world(striker_x=30.0, ball_x=32.0)
    kick(ref, st, [KICKER], (0.0, 0.0))
    run_towards_ball(ref, st, 10)
    assert EventKind.OFFSIDE not in kinds(ev)


def test_no_offside_from_a_kick_in():
    ref, st, ev = world(striker_x=30.0, mode=PlayMode.KICK_IN, mode_team=HOME)
    kick(ref, st, [KICKER], (0.0, 0.0))
    assert st.play_mode == PlayMode.PLAY_ON
    run_towards_ball(ref, st, 10)
    assert EventKind.OFFSIDE not in kinds(ev)


def test_offside_from_a_free_kick():
    ref, st, ev = world(striker_x=30.0, mode=PlayMode.FREE_KICK, mode_team=HOME)
    kick(ref, st, [KICKER], (0.0, 0.0))
    run_towards_ball(ref, st, 10)
    assert len(ev.of_kind(EventKind.OFFSIDE)) == 1


def test_no_offside_when_the_rule_is_off():
    ref, st, ev = world(striker_x=30.0, config=config_with(offside=False))
    kick(ref, st, [KICKER], (0.0, 0.0))
    run_towards_ball(ref, st, 10)
    assert EventKind.OFFSIDE not in kinds(ev)


def test_marked_player_touching_the_ball_is_penalised_even_from_afar():
    ref, st, ev = world(striker_x=30.0)
    kick(ref, st, [KICKER], (2.0, 0.0))
    step(ref, st, touchers=[10])
    assert [e[2] for e in ev.of_kind(EventKind.OFFSIDE)] == [10]


def test_marked_player_kicking_the_ball_is_penalised():
    ref, st, ev = world(striker_x=30.0)
    kick(ref, st, [KICKER], (2.0, 0.0))
    step(ref, st)
    kick(ref, st, [10], (1.0, 0.0))
    assert [e[2] for e in ev.of_kind(EventKind.OFFSIDE)] == [10]
    assert st.play_mode == PlayMode.FREE_KICK and not st.ball_vel.any()


def test_a_defender_playing_the_ball_first_clears_the_marks():
    ref, st, ev = world(striker_x=30.0)
    kick(ref, st, [KICKER], (0.0, 0.0))
    step(ref, st, touchers=[N + 3])
    run_towards_ball(ref, st, 10)
    assert EventKind.OFFSIDE not in kinds(ev)


def test_a_team_mate_kicking_again_re_judges_the_positions():
    ref, st, ev = world(striker_x=30.0)
    kick(ref, st, [KICKER], (0.0, 0.0))
    st.pos[10] = (24.0, 10.0)  # back onside before the next kick
    kick(ref, st, [KICKER], (0.0, 0.0))
    run_towards_ball(ref, st, 10)
    assert EventKind.OFFSIDE not in kinds(ev)


def test_offside_for_the_away_team_attacking_minus_x():
    moves = {1: (-25.0, 0.0), **{k: (-20.0 + k, 2.0 * k) for k in range(2, N)}, N + 9: (-9.5, 0.0), N + 10: (-30.0, -10.0)}
    ref, st, ev = make_world(ball=(-10.0, 0.0), moves=moves)
    kick(ref, st, [N + 9], (0.0, 0.0))
    run_towards_ball(ref, st, N + 10)
    [(_, team, player, _, _, _)] = ev.of_kind(EventKind.OFFSIDE)
    assert (team, player, st.mode_team) == (AWAY, 10, HOME)


def test_the_kickers_own_touch_after_its_kick_keeps_the_team_mate_offside():
    ref, st, ev = world(striker_x=30.0)
    kick(ref, st, [KICKER], (1.0, 0.0))
    step(ref, st, touchers=[KICKER])  # the ball brushes the kicker's body as it leaves
    run_towards_ball(ref, st, 10)
    assert [e[2] for e in ev.of_kind(EventKind.OFFSIDE)] == [10]


def test_a_deflection_off_a_team_mate_counts_as_playing_the_ball():
    ref, st, ev = world(striker_x=30.0)
    step(ref, st, touchers=[KICKER])  # no kick: the ball bounced off the team-mate
    run_towards_ball(ref, st, 10)
    assert [e[2] for e in ev.of_kind(EventKind.OFFSIDE)] == [10]
