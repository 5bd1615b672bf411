"""A team's messages of one cycle, encoded and decoded in compiled batches.

The built-in decentralised team says eleven messages a cycle and hears up to eleven from its
team-mates (``hear_max`` 1 each); :mod:`agents.messages` handles one message at a time with
the same compiled arithmetic (:mod:`agents.message_kernels`). Here the whole team's go
through one call each way.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from agents import message_kernels as mk
from agents.messages import (_NAGE, _NV, _NX, _NY, _PER_M, _PER_V, ALPHABET_BYTES, CYCLE_MODULUS, MAX_AGE,
                             MESSAGE_LENGTH, V_RANGE, X_RANGE, Y_RANGE, Decoded, decode_texts)
from numba import njit


class HeardBatch(NamedTuple):
    """The team-mates' messages a team's players heard this cycle, one row per message."""

    listener: np.ndarray
    """(p,) the player who heard it."""
    speaker: np.ndarray
    """(p,) the team-mate who said it."""
    decoded: Decoded
    """What each one says (kind -1: none of ours)."""


def heard_batch(heard_mates: tuple[tuple[tuple[int, str], ...], ...]) -> HeardBatch:
    """Every (listener, speaker, message) of ``heard_mates`` (per listener its (team-mate
    index, text) pairs), decoded in one call."""
    listeners, speakers, texts = [], [], []
    for listener, pairs in enumerate(heard_mates):
        for speaker, text in pairs:
            listeners.append(listener)
            speakers.append(speaker)
            texts.append(text)
    return HeardBatch(np.array(listeners, dtype=np.int64), np.array(speakers, dtype=np.int64),
                      decode_texts(texts))


def world_texts(ball: np.ndarray, ball_vel: np.ndarray, ball_age: np.ndarray, sender: np.ndarray,
                present: np.ndarray) -> list[str | None]:
    """Each present player's world message (:func:`agents.messages.encode_world_clipped` for
    rows of (n, 2) ball, velocity and sender positions and (n,) ball ages); None for the absent."""
    digits = np.empty((ball.shape[0], MESSAGE_LENGTH), dtype=np.int64)
    _world_digits(ball, ball_vel, ball_age, sender, digits, X_RANGE, Y_RANGE, V_RANGE, _PER_M, _PER_V, MAX_AGE,
                  _NX, _NY, _NV, _NAGE)
    return _texts(digits, present)


def vote_texts(assignments: np.ndarray, cycle: int, present: np.ndarray) -> list[str | None]:
    """Each present player's vote for its row of ``assignments`` (n, k) computed at ``cycle``."""
    digits = np.empty((assignments.shape[0], MESSAGE_LENGTH), dtype=np.int64)
    _vote_digits(assignments, cycle, CYCLE_MODULUS, digits)
    return _texts(digits, present)


def _texts(digits: np.ndarray, present: np.ndarray) -> list[str | None]:
    """Rows of digits as message texts (None where not ``present``)."""
    raw = ALPHABET_BYTES[digits].tobytes().decode("ascii")
    return [raw[i * MESSAGE_LENGTH:(i + 1) * MESSAGE_LENGTH] if there else None
            for i, there in enumerate(present.tolist())]


@njit(cache=True, nogil=True)
def _world_digits(ball, ball_vel, ball_age, sender, out, x_range, y_range, v_range, per_m, per_v, max_age, nx, ny,
                  nv, nage) -> None:  # pragma: no cover - compiled
    """Rows of world messages' digits (values clipped into their ranges)."""
    for i in range(ball.shape[0]):
        number = mk.world_number(mk.grid_index(ball[i, 0], x_range, per_m), mk.grid_index(ball[i, 1], y_range, per_m),
                                 mk.grid_index(ball_vel[i, 0], v_range, per_v),
                                 mk.grid_index(ball_vel[i, 1], v_range, per_v),
                                 min(max(ball_age[i], 0), max_age), mk.grid_index(sender[i, 0], x_range, per_m),
                                 mk.grid_index(sender[i, 1], y_range, per_m), nx, ny, nv, nage)
        mk.number_digits(number, out[i])


@njit(cache=True, nogil=True)
def _vote_digits(assignments, cycle, modulus, out) -> None:  # pragma: no cover - compiled
    """Rows of votes' digits."""
    for i in range(assignments.shape[0]):
        mk.number_digits(mk.vote_number(assignments[i], cycle, modulus), out[i])
