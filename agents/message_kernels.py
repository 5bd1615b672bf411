"""The compiled arithmetic of the team message (:mod:`agents.messages`): a message is a base-71
number of 10 digits (below ``71 ** 10``, which fits a signed 64-bit integer). One message or a
whole team's messages per cycle go through the same functions: :mod:`agents.messages` encodes
and decodes single messages with them, the team's pipeline encodes its speaker's message and its
world models decode a whole delivery (a plain-Python big-number loop costs about 15 us a message,
ten times a compiled one).

The number, most significant part first (mixed radix, each part's size in
:data:`GRID_PARAMS`):

``assignment code`` (the permutation: ``perm_offset(n) + rank``, ``rank`` its Lehmer-code rank,
``perm_offset(n)`` the number of permutations of fewer than ``n`` roles), ``stamp`` (the cycle
the assignment was computed for, modulo ``stamps``), ``settled`` (0 or 1), ``ball age``, ``ball x``, ``ball y``,
``payload`` (the ball's velocity ``vx * nv + vy``, or the speaker's position ``sx * nsy + sy``),
``layout`` (:data:`VELOCITY` or :data:`SENDER`: which of the two the payload holds).

Digits are the indices of the characters in :data:`agents.messages.ALPHABET`; grid indices
and values are those :mod:`agents.messages` documents. Decoded messages come out as rows of a
:data:`DECODED` record array, read by field name.
"""

from __future__ import annotations

import numpy as np
from numba import njit

BASE = 71
"""Symbols of the alphabet."""
LENGTH = 10
"""Digits of a message."""
LAYOUTS, VELOCITY, SENDER = 2, 0, 1
"""What a message carries besides its vote and ball position: the ball's velocity or the
speaker's own position (its last digit in base ``LAYOUTS``)."""
MAX_ROLES = 10
"""The most roles an assignment in a message covers (a full side's outfield)."""

GRID_PARAMS = np.dtype([("x_range", np.float64), ("y_range", np.float64), ("v_range", np.float64)]
                       + [(name, np.int64) for name in ("ball_per_m", "velocity_per", "sender_per_m", "max_age",
                                                        "nbx", "nby", "nv", "nsx", "nsy", "nage", "stamps",
                                                        "max_roles")])
"""The message grid: the largest |x| and |y| (m) a position holds and the largest |velocity|
(m/cycle); grid points per m of the ball's position, per m/cycle of its velocity and per m of
the speaker's position; the largest ball age (cycles); the grid sizes of the ball's x and y,
a velocity component, the speaker's x and y and the age; the stamp's modulus; the most roles."""

DECODED = np.dtype([("valid", np.bool_), ("size", np.int64), ("stamp", np.int64), ("settled", np.bool_),
                    ("ball_age", np.int64),
                    ("layout", np.int64), ("ball_x", np.float64), ("ball_y", np.float64),
                    ("velocity_x", np.float64), ("velocity_y", np.float64),
                    ("sender_x", np.float64), ("sender_y", np.float64)])
"""One decoded message: whether it is one of ours, the number of roles of its assignment, its
stamp, whether the assignment is settled (:mod:`agents.teams.speaking`), the ball's age (cycles), its layout, the ball's position (m), and the ball's velocity
(m/cycle, layout VELOCITY) or the speaker's position (m, layout SENDER); the other pair is 0."""


@njit(cache=True, nogil=True)
def grid_index(value: float, half_range: float, per_unit: int) -> int:  # pragma: no cover - compiled
    """``value`` clipped into [-half_range, half_range] as its grid index (``per_unit`` steps a unit)."""
    return round((min(max(value, -half_range), half_range) + half_range) * per_unit)  # halves to even, as Python


@njit(cache=True, nogil=True)
def grid_value(index: int, half_range: float, per_unit: int) -> float:  # pragma: no cover - compiled
    """The value of grid index ``index`` (a division, so 0.1 m steps come out as 52.5, not
    52.500000000000014)."""
    return (index - half_range * per_unit) / per_unit


@njit(cache=True, nogil=True)
def perm_offset(n: int) -> int:  # pragma: no cover - compiled
    """How many permutations there are of fewer than ``n`` roles (0! + 1! + ... + (n-1)!)."""
    total, factorial = 0, 1
    for m in range(n):
        total += factorial
        factorial *= m + 1
    return total


@njit(cache=True, nogil=True)
def assignment_code(assignment: np.ndarray) -> int:  # pragma: no cover - compiled
    """The code of the permutation ``assignment`` (n,): ``perm_offset(n)`` plus its Lehmer-code rank."""
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
    return perm_offset(n) + rank


@njit(cache=True, nogil=True)
def code_assignment(code: int, max_roles: int, out: np.ndarray) -> int:  # pragma: no cover - compiled
    """The permutation of ``code`` into ``out`` (its first n entries); returns n, or -1 when no
    permutation of at most ``max_roles`` roles has that code."""
    n = 0
    while n <= max_roles and perm_offset(n + 1) <= code:
        n += 1
    if n > max_roles:
        return -1
    rank = code - perm_offset(n)
    lehmer = np.empty(max(n, 1), dtype=np.int64)
    for size in range(1, n + 1):
        lehmer[size - 1] = rank % size
        rank //= size
    left = np.arange(max(n, 1))
    size = n
    for j in range(n):
        d = lehmer[n - 1 - j]
        out[j] = left[d]
        for t in range(d, size - 1):
            left[t] = left[t + 1]
        size -= 1
    return n


@njit(cache=True, nogil=True)
def message_number(assignment: np.ndarray, cycle: int, settled: bool, ball: np.ndarray, ball_age: int,
                   extra: np.ndarray, layout: int, grid: np.ndarray) -> int:  # pragma: no cover - compiled
    """The number of one message: the permutation ``assignment`` (n,) computed at ``cycle``,
    whether it is ``settled``, the ball (2,) m and its age (cycles), and ``extra`` (2,): the ball's velocity (m/cycle) for
    layout VELOCITY or the speaker's position (m) for SENDER; every value clipped into its
    range (``grid``: a :data:`GRID_PARAMS` record, :data:`agents.messages.MESSAGE_GRID`)."""
    g = grid[0]
    number = (assignment_code(assignment) * g.stamps + cycle % g.stamps) * 2 + (1 if settled else 0)
    number = number * g.nage + min(max(ball_age, 0), g.max_age)
    number = number * g.nbx + grid_index(ball[0], g.x_range, g.ball_per_m)
    number = number * g.nby + grid_index(ball[1], g.y_range, g.ball_per_m)
    if layout == VELOCITY:
        payload = grid_index(extra[0], g.v_range, g.velocity_per) * g.nv + grid_index(extra[1], g.v_range,
                                                                                        g.velocity_per)
    else:
        payload = grid_index(extra[0], g.x_range, g.sender_per_m) * g.nsy + grid_index(extra[1], g.y_range,
                                                                                         g.sender_per_m)
    return (number * g.nv * g.nv + payload) * LAYOUTS + layout


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
def decode_digits(digits: np.ndarray, grid: np.ndarray, out: np.ndarray,
                  assignment: np.ndarray) -> None:  # pragma: no cover - compiled
    """Decode messages given as digits (p, LENGTH) (a digit -1: a character outside the
    alphabet, not a message) on the :data:`GRID_PARAMS` record ``grid`` into ``out`` (p,) of
    :data:`DECODED` and each assignment into ``assignment`` (p, max_roles) (its first ``size``
    entries); a row no encoder makes has ``valid`` False."""
    g = grid[0]
    for p in range(digits.shape[0]):
        row = out[p]
        row.valid = False
        number = digits_number(digits[p])
        if number < 0:
            continue
        layout = number % LAYOUTS
        number //= LAYOUTS
        payload = number % (g.nv * g.nv)
        number //= g.nv * g.nv
        by = number % g.nby
        number //= g.nby
        bx = number % g.nbx
        number //= g.nbx
        age = number % g.nage
        number //= g.nage
        settled = number % 2 == 1
        number //= 2
        stamp = number % g.stamps
        code = number // g.stamps
        if bx >= g.nbx or (layout == SENDER and payload >= g.nsx * g.nsy):
            continue
        size = code_assignment(code, g.max_roles, assignment[p])
        if size < 0:
            continue
        row.size, row.stamp, row.settled, row.ball_age, row.layout = size, stamp, settled, age, layout
        row.ball_x = grid_value(bx, g.x_range, g.ball_per_m)
        row.ball_y = grid_value(by, g.y_range, g.ball_per_m)
        row.velocity_x = row.velocity_y = row.sender_x = row.sender_y = 0.0
        if layout == VELOCITY:
            row.velocity_x = grid_value(payload // g.nv, g.v_range, g.velocity_per)
            row.velocity_y = grid_value(payload % g.nv, g.v_range, g.velocity_per)
        else:
            row.sender_x = grid_value(payload // g.nsy, g.x_range, g.sender_per_m)
            row.sender_y = grid_value(payload % g.nsy, g.y_range, g.sender_per_m)
        row.valid = True


@njit(cache=True, nogil=True)
def stamp_cycle(stamp: int, heard_cycle: int, stamps: int) -> int:  # pragma: no cover - compiled
    """The cycle an assignment stamped ``stamp`` was computed for, heard at ``heard_cycle``: the
    latest cycle before it (a message said at ``t`` is heard at ``t + 1``) with that residue."""
    said = heard_cycle - 1
    return said - (said - stamp) % stamps
