"""A compact encoding of what a player tells its team-mates in one ``say`` (10 characters).

The channel (:mod:`soccer_sim.perception.audio`) carries any string of at most
``say_msg_size`` (10) characters from rcssserver's set; what the characters mean is the team's
own protocol, so it lives with the teams. Every message is exactly :data:`MESSAGE_LENGTH`
characters of :data:`ALPHABET` (the server's set without space and parentheses, which a
client's S-expression parser could trip on): 71 symbols, so a message is a base-71 number
below ``71 ** 10`` (about 61.5 bits). Its last base-:data:`KINDS` digit is the kind:

* :class:`WorldMessage` -- the sender's ball estimate (position, velocity, age) and its own
  position. Positions in the team's frame (m; the sender and its team-mates share it) with
  resolution :data:`POSITION_STEP` 0.1 m over x in [-64, 64], y in [-44, 44] (the 105 x 68 m
  pitch with a wide margin); velocity with resolution :data:`VELOCITY_STEP` 0.02 m/cycle over
  [-3, 3] m/cycle (``ball_speed_max``); age in whole cycles, saturating at :data:`MAX_AGE`.
  Values are rounded to the nearest step, so decoding is within half a step.
* :class:`VoteMessage` -- a role-assignment vote: ``assignment[i]`` the role of the team's
  player ``i``, a permutation of ``0 .. n - 1`` for ``n <= 11`` players, sent exactly (its
  Lehmer-code rank), with the cycle it was computed for, modulo :data:`CYCLE_MODULUS`.

Bad input (a value out of range, not finite, a string that is not a message) is a
:class:`MessageError` naming what is wrong.
"""

from __future__ import annotations

import math
from collections.abc import Iterator
from dataclasses import dataclass

from agents.errors import AgentsError
from soccer_sim.perception.audio import SAY_CHARACTERS

ALPHABET: str = "".join(c for c in SAY_CHARACTERS if c not in " ()")
"""The 71 characters a message uses: rcssserver's ``say`` set without space and parentheses."""
MESSAGE_LENGTH = 10
"""Characters of every message (rcssserver's ``say_msg_size``)."""
KINDS = 2
"""Kinds of message: :data:`WORLD` and :data:`VOTE`."""
WORLD, VOTE = 0, 1
POSITION_STEP = 0.1
"""Resolution of positions (m)."""
X_RANGE = 64.0
"""Positions' x must lie in [-X_RANGE, X_RANGE] m (half the pitch length plus 11.5 m)."""
Y_RANGE = 44.0
"""Positions' y must lie in [-Y_RANGE, Y_RANGE] m (half the pitch width plus 10 m)."""
VELOCITY_STEP = 0.02
"""Resolution of the ball's velocity (m/cycle)."""
V_RANGE = 3.0
"""Velocity components must lie in [-V_RANGE, V_RANGE] m/cycle (``ball_speed_max``)."""
MAX_AGE = 13
"""Ball ages (cycles since the sender saw the ball) above this are sent as this."""
MAX_PLAYERS = 11
"""The most players a vote covers."""
CYCLE_MODULUS = 1 << 20
"""A vote's cycle is sent modulo this (1 048 576 cycles, far beyond a match)."""

_NX = round(2 * X_RANGE / POSITION_STEP) + 1
_NY = round(2 * Y_RANGE / POSITION_STEP) + 1
_NV = round(2 * V_RANGE / VELOCITY_STEP) + 1
_NAGE = MAX_AGE + 1
_PER_M = round(1 / POSITION_STEP)        # grid points per m
_PER_V = round(1 / VELOCITY_STEP)        # grid points per m/cycle
_CAPACITY = len(ALPHABET) ** MESSAGE_LENGTH
_CODE = {c: i for i, c in enumerate(ALPHABET)}


class MessageError(AgentsError, ValueError):
    """A value that cannot be encoded, or a string that is not a message."""


@dataclass(frozen=True)
class WorldMessage:
    """A player's ball estimate and own position (team frame: m, m/cycle, cycles)."""

    ball: tuple[float, float]
    """Ball position (m)."""
    ball_velocity: tuple[float, float]
    """Ball velocity (m/cycle)."""
    ball_age: int
    """Cycles since the sender last saw the ball (0: seen this cycle); saturates at MAX_AGE."""
    sender: tuple[float, float]
    """The sender's own position (m)."""


@dataclass(frozen=True)
class VoteMessage:
    """A role-assignment vote: ``assignment[i]`` is the role of the team's player ``i``."""

    assignment: tuple[int, ...]
    """A permutation of ``0 .. n - 1`` (n <= MAX_PLAYERS)."""
    cycle: int
    """The cycle the assignment was computed for, modulo CYCLE_MODULUS."""


def _step_index(name: str, value: float, half_range: float, step: float) -> int:
    """``value`` as its grid index over [-half_range, half_range] with ``step``, or an error."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        v = math.nan
    if isinstance(value, (bool, str)):
        v = math.nan
    if not math.isfinite(v) or abs(v) > half_range + 1e-9:
        raise MessageError(f"{name} must be finite and within [-{half_range}, {half_range}], got {value!r}")
    return int(round((v + half_range) / step))


def _pair(name: str, value: object) -> tuple[float, float]:
    """``value`` as two numbers, or an error naming ``name``."""
    try:
        x, y = value  # type: ignore[misc]
    except (TypeError, ValueError):
        raise MessageError(f"{name} must be a pair (x, y), got {value!r}") from None
    return x, y


def _to_text(number: int) -> str:
    """``number`` (0 <= number < 71 ** 10) as exactly MESSAGE_LENGTH base-71 characters."""
    base = len(ALPHABET)
    chars = []
    for _ in range(MESSAGE_LENGTH):
        number, digit = divmod(number, base)
        chars.append(ALPHABET[digit])
    return "".join(reversed(chars))


def encode_world(msg: WorldMessage) -> str:
    """``msg`` as a 10-character message (resolution in the module docstring)."""
    bx, by = _pair("ball", msg.ball)
    vx, vy = _pair("ball_velocity", msg.ball_velocity)
    sx, sy = _pair("sender", msg.sender)
    if isinstance(msg.ball_age, bool) or not isinstance(msg.ball_age, int) or msg.ball_age < 0:
        raise MessageError(f"ball_age must be a whole number of cycles >= 0, got {msg.ball_age!r}")
    return _world_text(_step_index("ball x", bx, X_RANGE, POSITION_STEP),
                       _step_index("ball y", by, Y_RANGE, POSITION_STEP),
                       _step_index("ball_velocity x", vx, V_RANGE, VELOCITY_STEP),
                       _step_index("ball_velocity y", vy, V_RANGE, VELOCITY_STEP), min(msg.ball_age, MAX_AGE),
                       _step_index("sender x", sx, X_RANGE, POSITION_STEP),
                       _step_index("sender y", sy, Y_RANGE, POSITION_STEP))


def encode_world_clipped(ball: tuple[float, float], ball_velocity: tuple[float, float], ball_age: int,
                         sender: tuple[float, float]) -> str:
    """A world message of finite values, each clipped into its range first (positions to the
    pitch with its margin, the velocity to ``V_RANGE``, the age to ``MAX_AGE``): the fast way a
    team says what it believes, which may lie a little outside the ranges (a ball behind the
    goal line, a sender beyond the margin)."""
    def grid(value: float, half_range: float, per_unit: int) -> int:
        return round((min(max(value, -half_range), half_range) + half_range) * per_unit)

    return _world_text(grid(ball[0], X_RANGE, _PER_M), grid(ball[1], Y_RANGE, _PER_M),
                       grid(ball_velocity[0], V_RANGE, _PER_V), grid(ball_velocity[1], V_RANGE, _PER_V),
                       min(max(int(ball_age), 0), MAX_AGE), grid(sender[0], X_RANGE, _PER_M),
                       grid(sender[1], Y_RANGE, _PER_M))


def _world_text(bx: int, by: int, vx: int, vy: int, age: int, sx: int, sy: int) -> str:
    """The world message of grid indices (the encoder's digits, most significant first)."""
    payload = (((((bx * _NY + by) * _NV + vx) * _NV + vy) * _NAGE + age) * _NX + sx) * _NY + sy
    return _to_text(payload * KINDS + WORLD)


def _permutation_rank(assignment: tuple[int, ...]) -> int:
    """The Lehmer-code rank of a permutation of ``0 .. n - 1`` (0 .. n! - 1)."""
    rank = 0
    left = list(range(len(assignment)))
    for value in assignment:
        i = left.index(value)
        rank = rank * len(left) + i
        left.pop(i)
    return rank


def _permutation(rank: int, n: int) -> tuple[int, ...]:
    """The permutation of ``0 .. n - 1`` with Lehmer-code ``rank`` (inverse of the above)."""
    digits = []
    for size in range(1, n + 1):
        rank, d = divmod(rank, size)
        digits.append(d)
    left = list(range(n))
    return tuple(left.pop(d) for d in reversed(digits))


def encode_vote(msg: VoteMessage) -> str:
    """``msg`` as a 10-character message (the assignment exactly, the cycle modulo
    CYCLE_MODULUS)."""
    try:
        assignment = tuple(int(r) for r in msg.assignment)
    except (TypeError, ValueError):
        raise MessageError(f"assignment must be a sequence of role indices, got {msg.assignment!r}") from None
    n = len(assignment)
    if n > MAX_PLAYERS or sorted(assignment) != list(range(n)):
        raise MessageError(f"assignment must be a permutation of 0..n-1 with n <= {MAX_PLAYERS}, got {assignment}")
    if isinstance(msg.cycle, bool) or not isinstance(msg.cycle, int) or msg.cycle < 0:
        raise MessageError(f"cycle must be a whole number >= 0, got {msg.cycle!r}")
    payload = ((msg.cycle % CYCLE_MODULUS) * (MAX_PLAYERS + 1) + n) * math.factorial(MAX_PLAYERS) \
        + _permutation_rank(assignment)
    return _to_text(payload * KINDS + VOTE)


def encode(msg: WorldMessage | VoteMessage) -> str:
    """Either kind of message as 10 characters."""
    if isinstance(msg, WorldMessage):
        return encode_world(msg)
    if isinstance(msg, VoteMessage):
        return encode_vote(msg)
    raise MessageError(f"cannot encode {type(msg).__name__}: a WorldMessage or VoteMessage is needed")


def decode(text: str) -> WorldMessage | VoteMessage:
    """The message ``text`` encodes; :class:`MessageError` if it is not one (wrong length,
    a character outside :data:`ALPHABET`, or digits no encoder produces)."""
    if not isinstance(text, str) or len(text) != MESSAGE_LENGTH:
        raise MessageError(f"a message is a str of {MESSAGE_LENGTH} characters, got {text!r}")
    number = 0
    for c in text:
        if c not in _CODE:
            raise MessageError(f"message {text!r} has a character outside the alphabet: {c!r}")
        number = number * len(ALPHABET) + _CODE[c]
    payload, kind = divmod(number, KINDS)
    if kind == WORLD:
        digits = []
        for size in (_NY, _NX, _NAGE, _NV, _NV, _NY):  # the encoder's digits, last first
            payload, digit = divmod(payload, size)
            digits.append(digit)
        sy, sx, age, vy, vx, by = digits
        bx = payload
        if bx >= _NX:
            raise MessageError(f"message {text!r} is not a valid world message")
        def pos(ix: int, iy: int) -> tuple[float, float]:
            """Grid indices to metres (a division, so 0.1 m steps come out as 52.5, not 52.500000000000014)."""
            return (ix - _NX // 2) / _PER_M, (iy - _NY // 2) / _PER_M

        return WorldMessage(ball=pos(bx, by), ball_velocity=((vx - _NV // 2) / _PER_V, (vy - _NV // 2) / _PER_V),
                            ball_age=age, sender=pos(sx, sy))
    payload, rank = divmod(payload, math.factorial(MAX_PLAYERS))
    cycle, n = divmod(payload, MAX_PLAYERS + 1)
    if cycle >= CYCLE_MODULUS or rank >= math.factorial(n):
        raise MessageError(f"message {text!r} is not a valid vote message")
    return VoteMessage(assignment=_permutation(rank, n), cycle=cycle)



class HeardMessages:
    """Decodes the team-mates' messages a team's players heard, each distinct text once (a
    bounded cache: the same message reaches several listeners), and lists those of one kind."""

    def __init__(self, limit: int = 4096) -> None:
        self._cache: dict[str, WorldMessage | VoteMessage | None] = {}
        self._limit = limit

    def decode(self, text: str) -> WorldMessage | VoteMessage | None:
        """The message ``text`` encodes, or None if it is none of ours."""
        found = self._cache.get(text, False)
        if found is False:
            if len(self._cache) >= self._limit:
                self._cache.clear()
            try:
                found = decode(text)
            except MessageError:
                found = None
            self._cache[text] = found
        return found  # type: ignore[return-value]

    def of_kind(self, heard_mates: tuple[tuple[tuple[int, str], ...], ...],
                kind: type) -> Iterator[tuple[int, int, object]]:
        """(listener, speaker, message) for every heard message of ``kind`` (WorldMessage or
        VoteMessage); ``heard_mates[listener]`` holds (speaker, text) pairs."""
        for listener, messages in enumerate(heard_mates):
            for speaker, text in messages:
                message = self.decode(text)
                if isinstance(message, kind):
                    yield listener, speaker, message


assert _NX * _NY * _NV * _NV * _NAGE * _NX * _NY * KINDS <= _CAPACITY
assert CYCLE_MODULUS * (MAX_PLAYERS + 1) * math.factorial(MAX_PLAYERS) * KINDS <= _CAPACITY
