"""The team message (agents.messages): every permutation of ten roles with its stamp round-trips
in 10 characters, the world information within half a step, every message valid for the say
channel, bad input a clear error."""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest
from numba import njit

from agents.message_kernels import (DECODED, assignment_code, code_assignment, decode_digits, message_number,
                                    number_digits, perm_offset, stamp_cycle)
from agents.messages import (ALPHABET, BALL_STEP, MAX_AGE, MAX_ROLES, MESSAGE_GRID, MESSAGE_LENGTH, SENDER_STEP,
                             STAMP_MODULUS, VELOCITY_STEP, V_RANGE, X_RANGE, Y_RANGE, MessageError, TeamMessage,
                             decode, decode_texts, encode, heard_batch)
from soccer_sim.perception.audio import SAY_CHARACTERS, AudioChannel, check_message


def test_alphabet_is_the_server_set_without_space_and_parentheses() -> None:
    assert len(ALPHABET) == 71 and set(ALPHABET) == set(SAY_CHARACTERS) - set(" ()")


@njit(cache=True)
def _round_trip_all(n: int, stamps: int, grid: np.ndarray, decoded: np.ndarray) -> int:
    """Encode every permutation of ``n`` roles (by rank) with each stamp and a fixed ball, decode
    it, and count the messages that come back other than they went in."""
    wrong = 0
    assignment = np.empty(n, dtype=np.int64)
    back = np.empty((1, 10), dtype=np.int64)
    digits = np.empty((1, 10), dtype=np.int64)
    ball = np.array([12.3, -4.5])
    extra = np.array([0.5, -0.25])
    factorial = 1
    for m in range(2, n + 1):
        factorial *= m
    for rank in range(factorial):
        code_assignment(perm_offset(n) + rank, n, assignment)
        for stamp in range(stamps):
            number_digits(message_number(assignment, stamp, rank % 2 == 0, ball, 3, extra, 0, grid), digits[0])
            decode_digits(digits, grid, decoded, back)
            row = decoded[0]
            if not row.valid or row.size != n or row.stamp != stamp or row.settled != (rank % 2 == 0):
                wrong += 1
                continue
            for r in range(n):
                if back[0, r] != assignment[r]:
                    wrong += 1
                    break
            if assignment_code(assignment) != perm_offset(n) + rank:
                wrong += 1
    return wrong


def test_every_permutation_of_ten_roles_round_trips_with_its_stamp() -> None:
    decoded = np.zeros(1, dtype=DECODED)
    assert _round_trip_all(MAX_ROLES, STAMP_MODULUS, MESSAGE_GRID, decoded) == 0
    assert math.factorial(MAX_ROLES) == 3_628_800


def test_small_assignments_round_trip_through_text() -> None:
    for n in range(0, 5):
        texts = set()
        for perm in itertools.permutations(range(n)):
            msg = TeamMessage(perm, 1, False, (0.0, 0.0), 0, ball_velocity=(0.0, 0.0))
            text = encode(msg)
            check_message(text)
            assert decode(text) == msg
            texts.add(text)
        assert len(texts) == math.factorial(n)


def random_message(rng: np.random.Generator, velocity: bool) -> TeamMessage:
    def point(half_x: float, half_y: float) -> tuple[float, float]:
        return (float(rng.uniform(-half_x, half_x)), float(rng.uniform(-half_y, half_y)))
    return TeamMessage(tuple(int(r) for r in rng.permutation(int(rng.integers(0, MAX_ROLES + 1)))),
                       int(rng.integers(0, 10_000)), bool(rng.integers(0, 2)), point(X_RANGE, Y_RANGE),
                       int(rng.integers(0, 30)),
                       ball_velocity=point(V_RANGE, V_RANGE) if velocity else None,
                       sender=None if velocity else point(X_RANGE, Y_RANGE))


@pytest.mark.parametrize("velocity", [True, False])
def test_world_information_round_trips_within_half_a_step(velocity: bool) -> None:
    rng = np.random.default_rng(5)
    seen = set()
    for _ in range(2000):
        m = random_message(rng, velocity)
        text = encode(m)
        assert len(text) == MESSAGE_LENGTH
        check_message(text)  # the channel accepts it (raises TeamError otherwise)
        back = decode(text)
        assert back.assignment == m.assignment and back.cycle == m.cycle % STAMP_MODULUS
        assert back.settled == m.settled and back.ball_age == min(m.ball_age, MAX_AGE)
        assert np.all(np.abs(np.subtract(back.ball, m.ball)) <= BALL_STEP / 2 + 1e-9)
        if velocity:
            assert back.sender is None
            assert np.all(np.abs(np.subtract(back.ball_velocity, m.ball_velocity)) <= VELOCITY_STEP / 2 + 1e-9)
        else:
            assert back.ball_velocity is None
            assert np.all(np.abs(np.subtract(back.sender, m.sender)) <= SENDER_STEP / 2 + 1e-9)
        assert encode(back) == text  # decoded values sit on the grid
        seen.add(text)
    assert len(seen) == 2000


def test_extremes_round_trip_and_neighbours_differ() -> None:
    corner = TeamMessage(tuple(range(MAX_ROLES))[::-1], 1, True, (X_RANGE, -Y_RANGE), MAX_AGE,
                         ball_velocity=(-V_RANGE, V_RANGE))
    assert decode(encode(corner)) == corner
    far = TeamMessage((0,), 0, False, (-X_RANGE, Y_RANGE), 0, sender=(X_RANGE, -Y_RANGE))
    assert decode(encode(far)) == far
    a = TeamMessage((1, 0), 0, False, (10.0, 5.0), 0, ball_velocity=(0.0, 0.0))
    b = TeamMessage((1, 0), 0, False, (10.1, 5.0), 0, ball_velocity=(0.0, 0.0))
    assert encode(a) != encode(b) and decode(encode(b)).ball == (10.1, 5.0)


def test_a_stamp_gives_back_the_cycle_of_a_message_heard_the_cycle_after() -> None:
    for said in range(0, 50):
        assert stamp_cycle(said % STAMP_MODULUS, said + 1, STAMP_MODULUS) == said


def _message(**changes: object) -> TeamMessage:
    fields = dict(assignment=(0, 1), cycle=0, settled=False, ball=(0.0, 0.0), ball_age=0, ball_velocity=(0.0, 0.0))
    fields.update(changes)
    return TeamMessage(**fields)  # type: ignore[arg-type]


@pytest.mark.parametrize("msg, what", [
    (_message(ball=(X_RANGE + 0.2, 0.0)), "ball x"),
    (_message(ball=(0.0, math.nan)), "ball y"),
    (_message(ball_velocity=(3.5, 0.0)), "ball_velocity x"),
    (_message(ball_age=-1), "ball_age"),
    (_message(ball_velocity=None, sender=(0.0, "a")), "sender y"),
    (_message(ball_velocity=None, sender=5.0), "sender must be a pair"),
    (_message(ball_velocity=None), "exactly one of"),
    (_message(sender=(1.0, 1.0)), "exactly one of"),
    (_message(assignment=(0, 0, 1)), "permutation"),
    (_message(assignment=tuple(range(11))), "permutation"),
    (_message(cycle=-3), "cycle"),
    (_message(settled="yes"), "settled"),
    ("hello", "cannot encode"),
])
def test_bad_values_are_clear_errors(msg: object, what: str) -> None:
    with pytest.raises(MessageError, match=what) as err:
        encode(msg)  # type: ignore[arg-type]
    assert isinstance(err.value, ValueError)


@pytest.mark.parametrize("text, what", [("abc", "10 characters"), (None, "10 characters"),
                                        ("abcdefghi(", "outside the alphabet"),
                                        (ALPHABET[-1] * 10, "not a valid team message")])
def test_bad_strings_are_clear_errors(text: object, what: str) -> None:
    with pytest.raises(MessageError, match=what):
        decode(text)  # type: ignore[arg-type]


def test_decoding_many_at_once_marks_what_is_not_a_message() -> None:
    good = encode(_message(assignment=(2, 0, 1, 4, 3), cycle=77, ball=(12.3, -4.5), ball_age=3,
                           ball_velocity=(0.5, -0.25)))
    bad = ["short", "é" * 10, "(" * 10, ALPHABET[-1] * 10]   # wrong length, not ASCII, outside, no encoder's
    decoded = decode_texts([good, *bad, good])
    assert decoded.rows["valid"].tolist() == [True, False, False, False, False, True]
    assert decoded.message(0) == decode(good)
    for text in bad:
        with pytest.raises(MessageError):
            decode(text)


def test_heard_messages_keep_their_listener_and_speaker() -> None:
    texts = [encode(_message(cycle=c)) for c in range(3)]
    heard = heard_batch(((), ((0, texts[0]),), ((3, texts[1]), (1, texts[2]))))
    assert heard.listener.tolist() == [1, 2, 2]
    assert heard.speaker.tolist() == [0, 3, 1]
    assert heard.decoded.rows["stamp"].tolist() == [0, 1, 0]


def test_messages_travel_through_the_channel() -> None:
    ch = AudioChannel((2, 0))
    msg = _message(assignment=(1, 0), cycle=41, ball=(3.0, -2.0), ball_age=1, ball_velocity=(0.5, 0.25))
    ch.say(40, [[encode(msg), None], []], np.zeros((2, 2)))
    heard = ch.hear(41, np.random.default_rng(0))
    (sender, text), = heard.for_listener(1)[0]
    assert sender == 0 and decode(text) == TeamMessage(**{**msg.__dict__, 'cycle': msg.cycle % STAMP_MODULUS})


def test_the_message_grid_is_one_packed_record_of_the_encoders_constants() -> None:
    from agents.message_kernels import GRID_PARAMS

    g = MESSAGE_GRID
    assert g.dtype == GRID_PARAMS and g.shape == (1,) and not GRID_PARAMS.isalignedstruct
    assert (g[0]["x_range"], g[0]["y_range"], g[0]["v_range"], g[0]["max_age"], g[0]["stamps"],
            g[0]["max_roles"]) == (X_RANGE, Y_RANGE, V_RANGE, MAX_AGE, STAMP_MODULUS, MAX_ROLES)
