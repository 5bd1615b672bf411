"""The world state owns its arrays: one body table with views into it, arrays that cannot be
replaced, hand-built states copied into the owned arrays, copies that keep the views."""

from __future__ import annotations

import copy
import pickle

import numpy as np
import pytest

from soccer_sim.errors import SoccerSimError
from soccer_sim.state import NO_PLAYER, PlayMode, StateError, WorldState

ARRAYS = ("pos", "vel", "ball", "ball_vel", "bodies", "body_table", "stamina", "effort", "recovery", "capacity",
          "score")


def test_bodies_are_views_into_one_table_in_the_solver_layout() -> None:
    state = WorldState((2, 3))
    assert state.body_table.shape == (7, 4) and state.bodies.shape == (6, 4)
    state.pos[4] = (1.0, 2.0)
    state.vel[4] = (3.0, 4.0)
    state.ball[:] = (5.0, 6.0)
    state.ball_vel[:] = (7.0, 8.0)
    assert state.body_table[4].tolist() == [1.0, 2.0, 3.0, 4.0]
    assert state.body_table[5].tolist() == [5.0, 6.0, 7.0, 8.0]
    assert state.body_table[6].tolist() == [0.0, 0.0, 0.0, 0.0]  # the field's fixed frame
    assert state.bodies.base is state.body_table or np.shares_memory(state.bodies, state.body_table)


def test_a_fresh_state_holds_fresh_players_and_the_opening_fields() -> None:
    state = WorldState((3, 3))
    assert state.sizes == (3, 3) and state.players_per_team == 3
    assert not state.stamina.any() and (state.effort == 1.0).all() and (state.recovery == 1.0).all()
    assert np.isinf(state.capacity).all() and state.score.tolist() == [0, 0]
    assert (state.play_mode, state.ball_holder, state.last_touch, state.cycle) == (PlayMode.KICK_OFF, NO_PLAYER,
                                                                                  NO_PLAYER, 0)


def test_arrays_cannot_be_replaced_but_in_place_arithmetic_works() -> None:
    state = WorldState((2, 2))
    for name in ARRAYS:
        array = getattr(state, name)
        with pytest.raises(AttributeError, match=f"WorldState.{name} cannot be replaced"):
            setattr(state, name, array.copy())
        assert getattr(state, name) is array
    ball = state.ball
    state.ball_vel[:] = (0.5, -1.0)
    state.ball += state.ball_vel  # adds in place, then assigns the same array back: allowed
    assert state.ball is ball and state.ball.tolist() == [0.5, -1.0]


def test_hand_built_values_are_copied_into_the_owned_arrays() -> None:
    pos = np.arange(8, dtype=float).reshape(4, 2)
    state = WorldState(pos=pos, stamina=np.full(4, 100.0), ball=(1.0, 2.0), score=(1, 0), cycle=7)
    assert state.sizes == (2, 2)  # without sizes: two even sides
    assert state.pos.tolist() == pos.tolist() and state.pos is not pos
    pos[0] = (99.0, 99.0)
    assert state.pos[0].tolist() == [0.0, 1.0]
    assert state.ball.tolist() == [1.0, 2.0] and state.score.tolist() == [1, 0] and state.cycle == 7
    assert np.shares_memory(state.pos, state.body_table)


def test_bad_hand_built_values_are_refused_with_the_field_named() -> None:
    with pytest.raises(StateError, match=r"WorldState.vel must have shape \(4, 2\), got \(3, 2\)"):
        WorldState((2, 2), vel=np.zeros((3, 2)))
    with pytest.raises(StateError, match="sizes .* or the players' pos"):
        WorldState()
    with pytest.raises(StateError, match="non-negative"):
        WorldState((2, -1))
    assert issubclass(StateError, SoccerSimError) and issubclass(StateError, ValueError)


@pytest.mark.parametrize("duplicate", [lambda s: pickle.loads(pickle.dumps(s)), copy.deepcopy])
def test_copies_keep_their_views_on_their_own_table(duplicate) -> None:
    state = WorldState((2, 3))
    state.pos[1] = (4.0, 5.0)
    state.ball[:] = (1.0, 1.0)
    state.score[1] = 2
    state.play_mode = PlayMode.PLAY_ON
    twin = duplicate(state)
    assert twin.sizes == (2, 3) and twin.play_mode == PlayMode.PLAY_ON and twin.score.tolist() == [0, 2]
    assert twin.pos[1].tolist() == [4.0, 5.0] and twin.ball.tolist() == [1.0, 1.0]
    twin.ball[:] = (9.0, 9.0)
    assert twin.bodies[-1, :2].tolist() == [9.0, 9.0] and twin.body_table[5, :2].tolist() == [9.0, 9.0]
    assert state.ball.tolist() == [1.0, 1.0]
