"""The team-relative view: the left-hand team sees the absolute frame, the right-hand team sees
it turned by 180°, commands go back the same way, and the two views of mirrored worlds agree."""

from __future__ import annotations

import numpy as np
import pytest
from tests.soccer_sim.core_helpers import Scripted
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from soccer_sim import AWAY, HOME, PlayMode, TeamCommand
from soccer_sim.state import NO_PLAYER, StateError, WorldState
from soccer_sim.view import TeamFrame

N = 4


def view_of(frame: TeamFrame, state: WorldState):
    return frame.update_view(state, state.attack_direction(frame.team))


def make_world(n: int = N) -> tuple[WorldState, np.ndarray]:
    state = WorldState((n, n), stamina=np.arange(2 * n, dtype=float))
    return state, np.zeros((2 * n, 4))


def fill(state: WorldState, values: np.ndarray) -> None:
    state.bodies[:] = values


finite = st.floats(-60.0, 60.0, allow_nan=False)
worlds = arrays(np.float64, (2 * N + 1, 4), elements=finite)


@settings(max_examples=60, deadline=None, derandomize=True)
@given(worlds)
def test_away_view_is_the_absolute_world_turned_180_degrees(values: np.ndarray) -> None:
    state, commands = make_world()
    fill(state, values)
    home = view_of(TeamFrame(HOME, "h", state, commands), state)
    away = view_of(TeamFrame(AWAY, "a", state, commands), state)
    assert np.array_equal(home.own_pos, state.pos[:N]) and np.array_equal(home.opp_vel, state.vel[N:])
    assert np.array_equal(home.ball, state.ball) and np.array_equal(home.ball_vel, state.ball_vel)
    assert np.array_equal(away.own_pos, -state.pos[N:]) and np.array_equal(away.own_vel, -state.vel[N:])
    assert np.array_equal(away.opp_pos, -state.pos[:N]) and np.array_equal(away.opp_vel, -state.vel[:N])
    assert np.array_equal(away.ball, -state.ball) and np.array_equal(away.ball_vel, -state.ball_vel)
    assert np.array_equal(away.stamina, state.stamina[N:])


@settings(max_examples=60, deadline=None, derandomize=True)
@given(worlds)
def test_mirrored_worlds_look_the_same_to_the_mirrored_teams(values: np.ndarray) -> None:
    """Home in world W sees exactly what away sees in W turned by 180° with the teams swapped."""
    state, commands = make_world()
    fill(state, values)
    state.score[:] = (2, 1)
    mirror_state, mirror_commands = make_world()
    swapped = np.concatenate([values[N:2 * N], values[:N], values[2 * N:]])
    fill(mirror_state, -swapped)
    mirror_state.stamina[:] = np.concatenate([state.stamina[N:], state.stamina[:N]])
    mirror_state.score[:] = (1, 2)
    mirror_state.mode_team = AWAY
    state.mode_team = HOME
    seen = view_of(TeamFrame(HOME, "h", state, commands), state)
    mirrored = view_of(TeamFrame(AWAY, "a", mirror_state, mirror_commands), mirror_state)
    for name in ("own_pos", "own_vel", "opp_pos", "opp_vel", "ball", "ball_vel", "stamina"):
        assert np.array_equal(getattr(seen, name), getattr(mirrored, name)), name
    assert seen.score == mirrored.score == (2, 1)
    assert seen.mode_ours and mirrored.mode_ours


def test_after_half_time_the_home_team_is_the_mirrored_one() -> None:
    state, commands = make_world()
    state.pos[0] = (10.0, 3.0)
    state.pos[N] = (-7.0, 1.0)
    state.home_attacks = -1
    state.half = 1
    home = view_of(TeamFrame(HOME, "h", state, commands), state)
    away = view_of(TeamFrame(AWAY, "a", state, commands), state)
    assert home.own_pos[0].tolist() == [-10.0, -3.0]
    assert away.own_pos[0].tolist() == [-7.0, 1.0]
    assert home.half == away.half == 1


def test_commands_are_turned_back_into_the_absolute_frame() -> None:
    state, commands = make_world()
    dash = np.arange(2 * N, dtype=float).reshape(N, 2)
    kick = -np.arange(2 * N, dtype=float).reshape(N, 2) / 10
    move = np.ones((N, 2))
    for team, sign in ((HOME, 1.0), (AWAY, -1.0)):
        frame = TeamFrame(team, "t", state, commands)
        command = TeamCommand(dash=dash, kick=kick, catch=True, move=move)
        catch, moved = frame.read_command(command, state.attack_direction(team))
        rows = slice(team * N, (team + 1) * N)
        assert np.array_equal(commands[rows, 0:2], sign * dash)
        assert np.array_equal(commands[rows, 2:4], sign * kick)
        assert catch is True
        assert np.array_equal(moved, sign * move)
    state.home_attacks = -1  # second half: home is now the mirrored team
    TeamFrame(HOME, "t", state, commands).read_command(TeamCommand(dash=dash, kick=kick),
                                                       state.attack_direction(HOME))
    assert np.array_equal(commands[:N, 0:2], -dash)


def test_view_reports_play_mode_score_cycle_and_holder_in_team_terms() -> None:
    state, commands = make_world()
    state.play_mode = PlayMode.GOALIE_HOLDS
    state.mode_team = AWAY
    state.score[:] = (3, 1)
    state.cycle = 77
    state.ball_holder = N + 2
    home = view_of(TeamFrame(HOME, "h", state, commands), state)
    assert (home.play_mode, home.mode_ours, home.score, home.cycle, home.ball_holder) == \
        (PlayMode.GOALIE_HOLDS, False, (3, 1), 77, NO_PLAYER)
    away = view_of(TeamFrame(AWAY, "a", state, commands), state)
    assert (away.mode_ours, away.score, away.ball_holder) == (True, (1, 3), 2)


def test_uneven_sides_see_their_own_sizes_and_the_stamina_model_of_their_own_rows() -> None:
    """The frame takes both sides' sizes from the state, and the effort and capacity it shows
    are the state's own (fresh players in a hand-built state: effort 1, unlimited capacity)."""
    state = WorldState((3, 5), stamina=np.arange(8, dtype=float))
    state.pos[:] = np.arange(16, dtype=float).reshape(8, 2)
    state.effort[:] = np.linspace(0.5, 1.0, 8)
    commands = np.zeros((8, 4))
    home, away = TeamFrame(HOME, "h", state, commands), TeamFrame(AWAY, "a", state, commands)
    assert (home.n, away.n, home.rows, away.rows) == (3, 5, slice(0, 3), slice(3, 8))
    seen_home, seen_away = view_of(home, state), view_of(away, state)
    assert seen_home.own_pos.shape == (3, 2) and seen_home.opp_pos.shape == (5, 2)
    assert np.array_equal(seen_away.own_pos, -state.pos[3:]) and np.array_equal(seen_away.opp_pos, -state.pos[:3])
    assert np.array_equal(seen_away.stamina, state.stamina[3:])
    assert np.array_equal(seen_away.effort, state.effort[3:]) and np.array_equal(seen_home.effort, state.effort[:3])
    assert np.isinf(seen_home.capacity).all()
    state.capacity[:] = 7.0  # written in place: the next view shows it
    assert np.array_equal(view_of(home, state).capacity, np.full(3, 7.0))


def test_a_frame_refuses_a_state_it_was_not_made_for() -> None:
    state, commands = make_world()
    frame = TeamFrame(HOME, "h", state, commands)
    other, _ = make_world()
    with pytest.raises(StateError, match="another WorldState"):
        frame.update_view(other, 1)


def test_in_a_match_the_away_team_starts_in_its_own_half_in_its_own_frame() -> None:
    """Both teams see their own players at x <= 0 at the opening kick-off, the ball at the
    centre, and the away team's view is the home team's world turned around."""
    from soccer_sim import run_match
    from soccer_sim.config import MatchConfig

    keep = ("own_pos", "opp_pos", "ball")
    home, away = Scripted(keep=keep), Scripted(keep=keep)
    run_match(home, away, config=MatchConfig(max_cycles=3))
    first_home, first_away = home.seen[0], away.seen[0]
    assert (first_home["own_pos"][:, 0] <= 0).all() and (first_away["own_pos"][:, 0] <= 0).all()
    assert np.array_equal(first_home["own_pos"], -first_away["opp_pos"])
    assert np.array_equal(first_home["opp_pos"], -first_away["own_pos"])
    assert np.allclose(first_home["ball"], 0.0) and np.allclose(first_away["ball"], 0.0)
