"""The 10-character message encoding (agents.messages): round trips within the stated
resolution, every message valid for the say channel, bad input a clear error."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from agents.messages import (ALPHABET, CYCLE_MODULUS, MAX_AGE, MESSAGE_LENGTH, POSITION_STEP, VELOCITY_STEP,
                             V_RANGE, X_RANGE, Y_RANGE, MessageError, VoteMessage, WorldMessage, decode, encode)
from soccer_sim.perception.audio import SAY_CHARACTERS, AudioChannel, check_message


def test_alphabet_is_the_server_set_without_space_and_parentheses() -> None:
    assert len(ALPHABET) == 71 and set(ALPHABET) == set(SAY_CHARACTERS) - set(" ()")


def random_world(rng: np.random.Generator) -> WorldMessage:
    return WorldMessage(ball=(rng.uniform(-X_RANGE, X_RANGE), rng.uniform(-Y_RANGE, Y_RANGE)),
                        ball_velocity=(rng.uniform(-V_RANGE, V_RANGE), rng.uniform(-V_RANGE, V_RANGE)),
                        ball_age=int(rng.integers(0, 30)),
                        sender=(rng.uniform(-X_RANGE, X_RANGE), rng.uniform(-Y_RANGE, Y_RANGE)))


def test_world_round_trip_within_half_a_step_and_valid_for_the_channel() -> None:
    rng = np.random.default_rng(5)
    tol_p, tol_v = POSITION_STEP / 2 + 1e-9, VELOCITY_STEP / 2 + 1e-9
    seen = set()
    for _ in range(2000):
        m = random_world(rng)
        text = encode(m)
        assert len(text) == MESSAGE_LENGTH
        check_message(text)  # the channel accepts it (raises TeamError otherwise)
        back = decode(text)
        assert isinstance(back, WorldMessage)
        assert np.all(np.abs(np.subtract(back.ball, m.ball)) <= tol_p)
        assert np.all(np.abs(np.subtract(back.sender, m.sender)) <= tol_p)
        assert np.all(np.abs(np.subtract(back.ball_velocity, m.ball_velocity)) <= tol_v)
        assert back.ball_age == min(m.ball_age, MAX_AGE)
        assert encode(back) == text  # decoded values sit on the grid
        seen.add(text)
    assert len(seen) == 2000


def test_world_extremes_and_neighbours_differ() -> None:
    corner = WorldMessage((X_RANGE, -Y_RANGE), (-V_RANGE, V_RANGE), MAX_AGE, (-X_RANGE, Y_RANGE))
    assert decode(encode(corner)) == corner
    a = WorldMessage((10.0, 5.0), (0.0, 0.0), 0, (0.0, 0.0))
    b = WorldMessage((10.1, 5.0), (0.0, 0.0), 0, (0.0, 0.0))
    assert encode(a) != encode(b) and decode(encode(b)).ball == (10.1, 5.0)


def test_vote_round_trip_is_exact() -> None:
    rng = np.random.default_rng(2)
    for n in range(0, 12):
        for _ in range(50):
            perm = tuple(int(x) for x in rng.permutation(n))
            cycle = int(rng.integers(0, 3 * CYCLE_MODULUS))
            text = encode(VoteMessage(perm, cycle))
            check_message(text)
            assert decode(text) == VoteMessage(perm, cycle % CYCLE_MODULUS)
    # every permutation of 5 gets its own message
    texts = {encode(VoteMessage(p, 7)) for p in itertools.permutations(range(5))}
    assert len(texts) == math.factorial(5)
    assert isinstance(decode(encode(VoteMessage((1, 0), 3))), VoteMessage)


@pytest.mark.parametrize("msg, what", [
    (WorldMessage((X_RANGE + 0.2, 0.0), (0.0, 0.0), 0, (0.0, 0.0)), "ball x"),
    (WorldMessage((0.0, math.nan), (0.0, 0.0), 0, (0.0, 0.0)), "ball y"),
    (WorldMessage((0.0, 0.0), (3.5, 0.0), 0, (0.0, 0.0)), "ball_velocity x"),
    (WorldMessage((0.0, 0.0), (0.0, 0.0), -1, (0.0, 0.0)), "ball_age"),
    (WorldMessage((0.0, 0.0), (0.0, 0.0), 0, (0.0, "a")), "sender y"),
    (WorldMessage((0.0, 0.0), (0.0, 0.0), 0, 5.0), "sender must be a pair"),
    (VoteMessage((0, 0, 1), 0), "permutation"),
    (VoteMessage(tuple(range(12)), 0), "permutation"),
    (VoteMessage((0, 1), -3), "cycle"),
    ("hello", "cannot encode"),
])
def test_bad_values_are_clear_errors(msg: object, what: str) -> None:
    with pytest.raises(MessageError, match=what) as err:
        encode(msg)  # type: ignore[arg-type]
    assert isinstance(err.value, ValueError)


@pytest.mark.parametrize("text, what", [("abc", "10 characters"), (None, "10 characters"),
                                        ("abcdefghi(", "outside the alphabet"), (ALPHABET[-1] * 10, "not a valid world"),
                                        (ALPHABET[-1] * 9 + ALPHABET[-2], "not a valid vote")])
def test_bad_strings_are_clear_errors(text: object, what: str) -> None:
    with pytest.raises(MessageError, match=what):
        decode(text)  # type: ignore[arg-type]


def test_messages_travel_through_the_channel() -> None:
    ch = AudioChannel((2, 0))
    world = WorldMessage((3.0, -2.0), (0.5, 0.26), 1, (1.0, 1.0))  # on the grid
    vote = VoteMessage((1, 0), 40)
    ch.say(40, [[encode(world), encode(vote)], []], np.zeros((2, 2)))
    heard = ch.hear(41, np.random.default_rng(0))
    (sender, text), = heard.for_listener(1)[0]
    assert sender == 0 and decode(text) == world
    assert decode(heard.for_listener(0)[0][0][1]) == vote


def test_the_message_grid_is_one_packed_record_of_the_encoders_constants() -> None:
    from agents import messages
    from agents.message_kernels import GRID_PARAMS

    grid = messages.WORLD_GRID
    assert grid.dtype == GRID_PARAMS and grid.shape == (1,) and not GRID_PARAMS.isalignedstruct
    assert (grid[0]["x_range"], grid[0]["y_range"], grid[0]["v_range"], grid[0]["max_age"], grid[0]["modulus"]) == (
        messages.X_RANGE, messages.Y_RANGE, messages.V_RANGE, messages.MAX_AGE, messages.CYCLE_MODULUS)
