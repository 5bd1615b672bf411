"""A compact encoding of what a player tells its team-mates in one ``say`` (10 characters).

The channel (:mod:`soccer_sim.perception.audio`) carries any string of at most
``say_msg_size`` (10) characters from rcssserver's set; what the characters mean is the team's
own protocol, so it lives with the teams. Every message is exactly :data:`MESSAGE_LENGTH`
characters of :data:`ALPHABET` (the server's set without space and parentheses, which a
client's S-expression parser could trip on): 71 symbols, so a message is a base-71 number
below ``71 ** 10`` (about 61.5 bits). Its last base-:data:`KINDS` digit is the kind:

* :class:`WorldMessage` -- the sender's ball estimate (position, velocity, age) and its own
  position. Positions in the team's frame (m; the sender and its team-mates share it) with
  resolution :data:`POSITION_STEP` 0.1 m over x in [-64, 64], y in [-44, 44] (the default
  field, :data:`soccer_sim.config.STANDARD_FIELD`, with a wide margin; a fixed range of the
  message format); velocity with resolution :data:`VELOCITY_STEP` 0.02 m/cycle over
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
from collections.abc import Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from agents import message_kernels
from agents.errors import AgentsError
from agents.message_kernels import (GRID_PARAMS, decode_digits, grid_index, number_digits, vote_digits_rows,
                                    vote_number, world_digits_rows, world_number)
from soccer_sim.kernels import make_record
from soccer_sim.perception.audio import SAY_CHARACTERS
from soccer_sim.perception.coded import CodedMessages
from soccer_sim.perception.views import HeardLog

ALPHABET: str = "".join(c for c in SAY_CHARACTERS if c not in " ()")
"""The 71 characters a message uses: rcssserver's ``say`` set without space and parentheses."""
MESSAGE_LENGTH = 10
"""Characters of every message (rcssserver's ``say_msg_size``)."""
KINDS = message_kernels.KINDS
"""Kinds of message: :data:`WORLD` and :data:`VOTE`."""
WORLD, VOTE = message_kernels.WORLD, message_kernels.VOTE
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
MAX_PLAYERS = message_kernels.MAX_PLAYERS
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
ALPHABET_BYTES = np.frombuffer(ALPHABET.encode("ascii"), dtype=np.uint8)
"""The alphabet's characters as bytes, indexed by digit."""
DIGIT_OF_BYTE = np.full(256, -1, dtype=np.int64)
"""(256,) each character byte's alphabet digit, -1 for a character outside the alphabet."""
DIGIT_OF_BYTE[ALPHABET_BYTES] = np.arange(len(ALPHABET))
_SILENT = " " * MESSAGE_LENGTH
"""Characters standing for a message not said (a space is outside the alphabet)."""


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
    digits = np.empty(MESSAGE_LENGTH, dtype=np.int64)
    number_digits(number, digits)
    return ALPHABET_BYTES[digits].tobytes().decode("ascii")


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
    return _world_text(grid_index(ball[0], X_RANGE, _PER_M), grid_index(ball[1], Y_RANGE, _PER_M),
                       grid_index(ball_velocity[0], V_RANGE, _PER_V), grid_index(ball_velocity[1], V_RANGE, _PER_V),
                       min(max(int(ball_age), 0), MAX_AGE), grid_index(sender[0], X_RANGE, _PER_M),
                       grid_index(sender[1], Y_RANGE, _PER_M))


def _world_text(bx: int, by: int, vx: int, vy: int, age: int, sx: int, sy: int) -> str:
    """The world message of grid indices (the encoder's digits, most significant first)."""
    return _to_text(world_number(bx, by, vx, vy, age, sx, sy, _NX, _NY, _NV, _NAGE))


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
    return _to_text(vote_number(np.array(assignment, dtype=np.int64), msg.cycle, CYCLE_MODULUS))


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
    for c in text:
        if c not in _CODE:
            raise MessageError(f"message {text!r} has a character outside the alphabet: {c!r}")
    decoded = decode_texts([text])
    if decoded.kind[0] == WORLD:
        return decoded.world_message(0)
    if decoded.kind[0] == VOTE:
        return decoded.vote_message(0)
    number = 0
    for c in text:
        number = number * len(ALPHABET) + _CODE[c]
    kind = "world" if number % KINDS == WORLD else "vote"
    raise MessageError(f"message {text!r} is not a valid {kind} message")


class Decoded:
    """Messages decoded in one compiled call (:func:`decode_texts`): per message its kind
    (:data:`WORLD`, :data:`VOTE`, or -1 for none of ours), a world message's values and a
    vote's assignment and cycle, as arrays."""

    def __init__(self, count: int) -> None:
        self.kind = np.full(count, -1, dtype=np.int64)
        """(p,) WORLD, VOTE or -1."""
        self.grid = np.zeros((count, 7), dtype=np.int64)
        """(p, 7) a world message's grid indices (the encoder's digits)."""
        self.world = np.zeros((count, 7))
        """(p, 7) world messages' values: ball x, y (m), velocity x, y (m/cycle), age
        (cycles), sender x, y (m)."""
        self.vote = np.zeros((count, MAX_PLAYERS), dtype=np.int64)
        """(p, 11) a vote's assignment (its first ``vote_size`` entries)."""
        self.vote_size = np.zeros(count, dtype=np.int64)
        self.vote_cycle = np.zeros(count, dtype=np.int64)
        """(p,) a vote's cycle modulo CYCLE_MODULUS."""

    def world_message(self, p: int) -> WorldMessage:
        """Message ``p`` as a :class:`WorldMessage` (it must be one)."""
        bx, by, vx, vy, age, sx, sy = self.world[p].tolist()
        return WorldMessage(ball=(bx, by), ball_velocity=(vx, vy), ball_age=int(age), sender=(sx, sy))

    def vote_message(self, p: int) -> VoteMessage:
        """Message ``p`` as a :class:`VoteMessage` (it must be one)."""
        return VoteMessage(assignment=tuple(self.vote[p, : self.vote_size[p]].tolist()),
                           cycle=int(self.vote_cycle[p]))


def decode_texts(texts: Sequence[str]) -> Decoded:
    """Decode many message texts in one compiled call; a text that is not a message (wrong
    length, not ASCII, a character outside the alphabet, digits no encoder makes) gets kind -1."""
    decoded = Decoded(len(texts))
    if not texts:
        return decoded
    decode_digits(text_digits(texts), WORLD_GRID, decoded.kind, decoded.grid, decoded.world, decoded.vote,
                  decoded.vote_size, decoded.vote_cycle)
    return decoded


CODES = (WORLD, VOTE, MAX_PLAYERS)
"""The kinds' codes and the most players a vote covers, for compiled callers of the decoder."""


def text_digits(texts: Sequence[str]) -> np.ndarray:
    """(p, MESSAGE_LENGTH) int64 the alphabet digits of each text, a row of -1 for a text that
    cannot be a message (wrong length, not ASCII) and -1 for a character outside the alphabet."""
    raw = said_bytes(texts)
    if raw is not None:  # (the usual case: all of ours)
        return DIGIT_OF_BYTE[raw]
    digits = np.full((len(texts), MESSAGE_LENGTH), -1, dtype=np.int64)
    fine = [p for p, t in enumerate(texts) if len(t) == MESSAGE_LENGTH and t.isascii()]
    if fine:
        digits[fine] = DIGIT_OF_BYTE[said_bytes([texts[p] for p in fine])]
    return digits


def said_bytes(messages: Sequence[str | None]) -> np.ndarray | None:
    """(n, MESSAGE_LENGTH) uint8 the characters of each of ``messages`` (spaces for None, which
    no digit reads as a message), for a compiled decoder of whole deliveries; None when one is
    not MESSAGE_LENGTH ASCII characters (decode such texts with :func:`text_digits`)."""
    if type(messages) is CodedMessages:  # (a match's delivery of coded messages: as it stands)
        return messages.silent_spaces() if messages.width == MESSAGE_LENGTH else None
    parts = [_SILENT if m is None else m for m in messages]
    if not parts:
        return np.empty((0, MESSAGE_LENGTH), dtype=np.uint8)
    joined = "".join(parts)
    if len(joined) != MESSAGE_LENGTH * len(parts) or not joined.isascii() or max(map(len, parts)) > MESSAGE_LENGTH:
        return None
    return np.frombuffer(joined.encode("ascii"), dtype=np.uint8).reshape(len(parts), MESSAGE_LENGTH)


class HeardBatch(NamedTuple):
    """The team-mates' messages a team's players heard in one cycle, one row per message."""

    listener: np.ndarray
    """(p,) the player who heard it."""
    speaker: np.ndarray
    """(p,) the team-mate who said it."""
    decoded: Decoded
    """What each one says (kind -1: none of ours)."""


def heard_batch(heard_mates: Sequence[tuple[tuple[int, str], ...]]) -> HeardBatch:
    """Every (listener, speaker, message) of ``heard_mates`` (per listener its (team-mate
    index, text) pairs), decoded in one call."""
    listeners, speakers, texts = heard_pairs(heard_mates)
    return HeardBatch(listeners, speakers, decode_texts(texts))


def heard_pairs(heard_mates: Sequence[tuple[tuple[int, str], ...]]) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """``heard_mates`` (per listener its (team-mate index, text) pairs) as one row per message:
    (p,) int64 listeners, (p,) int64 speakers and the p texts."""
    if isinstance(heard_mates, HeardLog):  # (a match's: its arrays at once)
        return heard_mates.pairs()
    listeners, speakers, texts = [], [], []
    for listener, pairs in enumerate(heard_mates):
        for speaker, text in pairs:
            listeners.append(listener)
            speakers.append(speaker)
            texts.append(text)
    return np.array(listeners, dtype=np.int64), np.array(speakers, dtype=np.int64), texts


def world_texts(ball: np.ndarray, ball_vel: np.ndarray, ball_age: np.ndarray, sender: np.ndarray,
                present: np.ndarray) -> list[str | None]:
    """A team's world messages in one call: :func:`encode_world_clipped` for each row of (n, 2)
    balls, velocities and senders and (n,) ball ages; None for players not ``present``."""
    digits = np.empty((ball.shape[0], MESSAGE_LENGTH), dtype=np.int64)
    world_digits_rows(ball, ball_vel, ball_age, sender, WORLD_GRID, digits)
    return digit_texts(digits, present)


def vote_texts(assignments: np.ndarray, cycle: int, present: np.ndarray) -> list[str | None]:
    """A team's votes in one call: each present player's for its row of ``assignments`` (n, k)
    int64, computed at ``cycle``."""
    digits = np.empty((assignments.shape[0], MESSAGE_LENGTH), dtype=np.int64)
    vote_digits_rows(assignments, cycle, CYCLE_MODULUS, digits)
    return digit_texts(digits, present)


def digit_messages(digits: np.ndarray, present: np.ndarray) -> CodedMessages:
    """Rows of digits (n, MESSAGE_LENGTH) as a team's messages held as codes, what a command
    may say (:class:`~soccer_sim.perception.coded.CodedMessages`: no text is made unless read;
    silent where not ``present``)."""
    return CodedMessages.of_arrays(ALPHABET_BYTES[digits], np.array(present, dtype=bool))


def digit_texts(digits: np.ndarray, present: np.ndarray) -> list[str | None]:
    """Rows of digits (n, MESSAGE_LENGTH) as message texts (None where not ``present``)."""
    return list(digit_messages(digits, present))


WORLD_GRID = make_record(GRID_PARAMS, x_range=X_RANGE, y_range=Y_RANGE, v_range=V_RANGE, per_m=_PER_M, per_v=_PER_V,
                         max_age=MAX_AGE, nx=_NX, ny=_NY, nv=_NV, nage=_NAGE, modulus=CYCLE_MODULUS)
"""The message grid's ranges, steps, sizes and the votes' cycle modulus, as the compiled encoders
and decoders take them (a :data:`~agents.message_kernels.GRID_PARAMS` record)."""


assert len(ALPHABET) == message_kernels.BASE and MESSAGE_LENGTH == message_kernels.LENGTH
assert _NX * _NY * _NV * _NV * _NAGE * _NX * _NY * KINDS <= _CAPACITY
assert CYCLE_MODULUS * (MAX_PLAYERS + 1) * math.factorial(MAX_PLAYERS) * KINDS <= _CAPACITY
