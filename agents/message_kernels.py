"""The compiled arithmetic of the message encoding (:mod:`agents.messages`): a message is a
base-71 number of 10 digits (below ``71 ** 10``, which fits a signed 64-bit integer), whose
last base-2 digit is its kind. One message or a whole team's messages per cycle go through the
same functions: :mod:`agents.messages` encodes and decodes single messages with them, and
:func:`agents.messages.world_texts`, :func:`~agents.messages.vote_texts` and
:func:`~agents.messages.decode_texts` a team's ten or eleven at a time (a plain-Python big-number loop
costs about 15 us a message, ten times a compiled one).

Digits are the indices of the characters in :data:`agents.messages.ALPHABET`; grid indices and
sizes are those :mod:`agents.messages` documents. The ranges, steps and sizes travel as one named
record (:data:`GRID_PARAMS`, :data:`agents.messages.WORLD_GRID`), read by field name.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

BASE = 71
"""Symbols of the alphabet."""
LENGTH = 10
"""Digits of a message."""
KINDS, WORLD, VOTE = 2, 0, 1
"""Kinds of message and their last digits (:mod:`agents.messages`)."""
MAX_PLAYERS = 11
FACTORIAL_MAX = math.factorial(MAX_PLAYERS)
INVALID = -1
"""A decoded kind that is no message of ours."""

GRID_PARAMS = np.dtype([("x_range", np.float64), ("y_range", np.float64), ("v_range", np.float64)]
                       + [(name, np.int64) for name in ("per_m", "per_v", "max_age", "nx", "ny", "nv", "nage",
                                                        "modulus")])
"""The message grid: the largest |x|, |y| (m) and |velocity| (m/cycle) a world message holds,
grid points per m and per m/cycle, the largest ball age (cycles), the grid sizes of a position
coordinate, a velocity coordinate and an age, and the modulus of a vote's cycle."""


@njit(cache=True, nogil=True)
def grid_index(value: float, half_range: float, per_unit: int) -> int:  # pragma: no cover - compiled
    """``value`` clipped into [-half_range, half_range] as its grid index (``per_unit`` steps a unit)."""
    return round((min(max(value, -half_range), half_range) + half_range) * per_unit)  # halves to even, as Python


@njit(cache=True, nogil=True)
def world_number(bx: int, by: int, vx: int, vy: int, age: int, sx: int, sy: int, nx: int, ny: int, nv: int,
                 nage: int) -> int:  # pragma: no cover - compiled
    """The number of a world message of grid indices (most significant first)."""
    payload = (((((bx * ny + by) * nv + vx) * nv + vy) * nage + age) * nx + sx) * ny + sy
    return payload * KINDS + WORLD


@njit(cache=True, nogil=True)
def vote_number(assignment: np.ndarray, cycle: int, modulus: int) -> int:  # pragma: no cover - compiled
    """The number of a vote for the permutation ``assignment`` (n,) at ``cycle``: the cycle
    modulo ``modulus``, n and the permutation's Lehmer-code rank."""
    n = assignment.shape[0]
    left = np.arange(n)
    size = n
    rank = 0
    for value in assignment:
        i = 0
        while left[i] != value:
            i += 1
        rank = rank * size + i
        for j in range(i, size - 1):
            left[j] = left[j + 1]
        size -= 1
    payload = ((cycle % modulus) * (MAX_PLAYERS + 1) + n) * FACTORIAL_MAX + rank
    return payload * KINDS + VOTE


@njit(cache=True, nogil=True)
def number_digits(number: int, out: np.ndarray) -> None:  # pragma: no cover - compiled
    """``number`` as LENGTH base-71 digits into ``out``, most significant first."""
    for d in range(LENGTH - 1, -1, -1):
        out[d] = number % BASE
        number //= BASE


@njit(cache=True, nogil=True)
def digits_number(digits: np.ndarray) -> int:  # pragma: no cover - compiled
    """The number of LENGTH base-71 ``digits`` (most significant first), -1 if a digit is not one."""
    number = 0
    for d in digits:
        if d < 0 or d >= BASE:
            return -1
        number = number * BASE + d
    return number


@njit(cache=True, nogil=True)
def decode_digits(digits: np.ndarray, grid: np.ndarray, kind: np.ndarray, world: np.ndarray, values: np.ndarray,
                  vote: np.ndarray, vote_size: np.ndarray, vote_cycle: np.ndarray) -> None:  # pragma: no cover
    """Decode messages given as digits (p, LENGTH) (a digit -1: a character outside the
    alphabet, not a message) on the :data:`GRID_PARAMS` record ``grid``: ``kind`` (p,) WORLD,
    VOTE or INVALID; a world message's grid indices into ``world`` (p, 7) (ball x, y, velocity
    x, y, age, sender x, y) and their values into ``values`` (p, 7: m, m/cycle, cycles); a
    vote's permutation into ``vote`` (p, MAX_PLAYERS), its size and cycle."""
    g = grid[0]
    nx, ny, nv, nage, per_m, per_v, modulus = g.nx, g.ny, g.nv, g.nage, g.per_m, g.per_v, g.modulus
    lehmer = np.empty(MAX_PLAYERS, dtype=np.int64)
    left = np.empty(MAX_PLAYERS, dtype=np.int64)
    for p in range(digits.shape[0]):
        number = digits_number(digits[p])
        kind[p] = INVALID
        if number < 0:
            continue
        payload, k = number // KINDS, number % KINDS
        if k == WORLD:
            sizes = (ny, nx, nage, nv, nv, ny)  # the encoder's digits, last first
            for j in range(6):
                world[p, 6 - j] = payload % sizes[j]
                payload //= sizes[j]
            world[p, 0] = payload
            if payload < nx:
                kind[p] = WORLD
                for j in (0, 5):  # a division, so 0.1 m steps come out as 52.5, not 52.500000000000014
                    values[p, j] = (world[p, j] - nx // 2) / per_m
                for j in (1, 6):
                    values[p, j] = (world[p, j] - ny // 2) / per_m
                for j in (2, 3):
                    values[p, j] = (world[p, j] - nv // 2) / per_v
                values[p, 4] = world[p, 4]
            continue
        rank = payload % FACTORIAL_MAX
        payload //= FACTORIAL_MAX
        n = payload % (MAX_PLAYERS + 1)
        cycle = payload // (MAX_PLAYERS + 1)
        factorial = 1
        for j in range(2, n + 1):
            factorial *= j
        if cycle >= modulus or rank >= factorial:
            continue
        for size in range(1, n + 1):
            lehmer[size - 1] = rank % size
            rank //= size
        for j in range(n):
            left[j] = j
        size = n
        for j in range(n):
            d = lehmer[n - 1 - j]
            vote[p, j] = left[d]
            for t in range(d, size - 1):
                left[t] = left[t + 1]
            size -= 1
        vote_size[p] = n
        vote_cycle[p] = cycle
        kind[p] = VOTE


@njit(cache=True, nogil=True)
def world_digits_rows(ball: np.ndarray, ball_vel: np.ndarray, ball_age: np.ndarray, sender: np.ndarray,
                      grid: np.ndarray, out: np.ndarray) -> None:  # pragma: no cover - compiled
    """Rows of world messages' digits into ``out`` (n, LENGTH): ball (n, 2), its velocity
    (n, 2), ages (n,) and senders (n, 2), each clipped into its range (``grid``: a
    :data:`GRID_PARAMS` record)."""
    for i in range(ball.shape[0]):
        number_digits(world_message_number(ball[i], ball_vel[i], ball_age[i], sender[i], grid), out[i])


@njit(cache=True, nogil=True)
def vote_digits_rows(assignments: np.ndarray, cycle: int, modulus: int,
                     out: np.ndarray) -> None:  # pragma: no cover - compiled
    """Rows of votes' digits into ``out`` (n, LENGTH), one per row of ``assignments`` (n, k)."""
    for i in range(assignments.shape[0]):
        number_digits(vote_number(assignments[i], cycle, modulus), out[i])


@njit(cache=True, nogil=True)
def world_message_number(ball: np.ndarray, ball_vel: np.ndarray, ball_age: int, sender: np.ndarray,
                         grid: np.ndarray) -> int:  # pragma: no cover - compiled
    """The number of one world message of ball (2,), velocity (2,), age and sender (2,), each
    clipped into its range (``grid``: a :data:`GRID_PARAMS` record, :data:`agents.messages.WORLD_GRID`),
    as :func:`world_digits_rows` makes it."""
    g = grid[0]
    x_range, y_range, v_range, per_m, per_v, max_age = g.x_range, g.y_range, g.v_range, g.per_m, g.per_v, g.max_age
    nx, ny, nv, nage = g.nx, g.ny, g.nv, g.nage
    return world_number(grid_index(ball[0], x_range, per_m), grid_index(ball[1], y_range, per_m),
                        grid_index(ball_vel[0], v_range, per_v), grid_index(ball_vel[1], v_range, per_v),
                        min(max(ball_age, 0), max_age), grid_index(sender[0], x_range, per_m),
                        grid_index(sender[1], y_range, per_m), nx, ny, nv, nage)
