"""The team's message: what the player whose turn it is tells its team-mates in one ``say`` (10 characters).

The channel (:mod:`soccer_sim.perception.audio`) carries any string of at most
``say_msg_size`` (10) characters from rcssserver's set; what the characters mean is the team's
own protocol, so it lives with the teams (:mod:`agents.teams.speaking` says who speaks when).
Every message is exactly :data:`MESSAGE_LENGTH` characters of :data:`ALPHABET` (the server's
set without space and parentheses, which a client's S-expression parser could trip on): 71
symbols, so a message is a base-71 number below ``71 ** 10`` (about 61.5 bits). One message
carries the vote and the world information together (:class:`TeamMessage`):

* **the vote**: a role assignment, ``assignment[i]`` the role of the team's outfield player
  ``i``, a permutation of ``0 .. n - 1`` for ``n <= MAX_ROLES`` (10) roles, sent exactly (its
  Lehmer-code rank; 21.9 bits for ten roles), with its **stamp**: the cycle it was computed
  for, modulo :data:`STAMP_MODULUS` (a message is heard the cycle after it is said, so the
  listener recovers the cycle, :func:`~agents.message_kernels.stamp_cycle`), and whether it is
  **settled** (the team's assignment, which every listener follows at once) or a proposal
  (:mod:`agents.teams.speaking`);
* **the ball** as the speaker believes it: its position, resolution :data:`BALL_STEP` 0.1 m
  over x in [-X_RANGE, X_RANGE], y in [-Y_RANGE, Y_RANGE] (the standard pitch with a 2.5 m
  margin; a fixed range of the format), and its age in whole cycles, saturating at
  :data:`MAX_AGE`;
* **one of two payloads** (the layout): the ball's velocity, resolution :data:`VELOCITY_STEP`
  0.05 m/cycle over [-V_RANGE, V_RANGE] (``ball_speed_max``), or the speaker's own position,
  resolution :data:`SENDER_STEP` 1 m over the same field as the ball. Both do not fit beside
  an exact vote at these resolutions; the speaking turns alternate them
  (:func:`agents.teams.speaking.carries_velocity`).

Values are clipped into their ranges by the team's fast encoder and rounded to the nearest step,
so decoding is within half a step. Bad input to :func:`encode` (a value out of range, not
finite, not a permutation) and a string that is not a message in :func:`decode` are a
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
from agents.message_kernels import (DECODED, GRID_PARAMS, LAYOUTS, MAX_ROLES, SENDER, VELOCITY, decode_digits,
                                    message_number, number_digits, perm_offset)
from soccer_sim.kernels import make_record
from soccer_sim.perception.audio import SAY_CHARACTERS
from soccer_sim.perception.coded import CodedMessages
from soccer_sim.perception.views import HeardLog

ALPHABET: str = "".join(c for c in SAY_CHARACTERS if c not in " ()")
"""The 71 characters a message uses: rcssserver's ``say`` set without space and parentheses."""
MESSAGE_LENGTH = 10
"""Characters of every message (rcssserver's ``say_msg_size``)."""
X_RANGE = 55.0
"""Positions' x lie in [-X_RANGE, X_RANGE] m (the standard pitch's half-length plus 2.5 m)."""
Y_RANGE = 37.0
"""Positions' y lie in [-Y_RANGE, Y_RANGE] m (the standard pitch's half-width plus 3 m)."""
BALL_STEP = 0.1
"""Resolution of the ball's position (m)."""
SENDER_STEP = 1.0
"""Resolution of the speaker's position (m)."""
VELOCITY_STEP = 0.05
"""Resolution of the ball's velocity (m/cycle)."""
V_RANGE = 3.0
"""Velocity components lie in [-V_RANGE, V_RANGE] m/cycle (``ball_speed_max``)."""
MAX_AGE = 7
"""Ball ages (cycles since the speaker's ball was seen) above this are sent as this."""
STAMP_MODULUS = 2
"""An assignment's cycle is sent modulo this."""

_PER_BALL = round(1 / BALL_STEP)
_PER_V = round(1 / VELOCITY_STEP)
_PER_SENDER = round(1 / SENDER_STEP)
_CODE = {c: i for i, c in enumerate(ALPHABET)}
ALPHABET_BYTES = np.frombuffer(ALPHABET.encode("ascii"), dtype=np.uint8)
"""The alphabet's characters as bytes, indexed by digit."""
DIGIT_OF_BYTE = np.full(256, -1, dtype=np.int64)
"""(256,) each character byte's alphabet digit, -1 for a character outside the alphabet."""
DIGIT_OF_BYTE[ALPHABET_BYTES] = np.arange(len(ALPHABET))
_SILENT = " " * MESSAGE_LENGTH
"""Characters standing for a message not said (a space is outside the alphabet)."""

MESSAGE_GRID = make_record(
    GRID_PARAMS, x_range=X_RANGE, y_range=Y_RANGE, v_range=V_RANGE, ball_per_m=_PER_BALL, velocity_per=_PER_V,
    sender_per_m=_PER_SENDER, max_age=MAX_AGE, nbx=round(2 * X_RANGE * _PER_BALL) + 1,
    nby=round(2 * Y_RANGE * _PER_BALL) + 1, nv=round(2 * V_RANGE * _PER_V) + 1,
    nsx=round(2 * X_RANGE * _PER_SENDER) + 1, nsy=round(2 * Y_RANGE * _PER_SENDER) + 1, nage=MAX_AGE + 1,
    stamps=STAMP_MODULUS, max_roles=MAX_ROLES)
"""The message grid's ranges, steps and sizes as the compiled encoder and decoder take them (a
:data:`~agents.message_kernels.GRID_PARAMS` record)."""


class MessageError(AgentsError, ValueError):
    """A value that cannot be encoded, or a string that is not a message."""


@dataclass(frozen=True)
class TeamMessage:
    """What the speaker says (module docstring; team frame: m, m/cycle, cycles): its vote, its
    ball, and either the ball's velocity or its own position (exactly one of the two)."""

    assignment: tuple[int, ...]
    """A permutation of ``0 .. n - 1`` (n <= MAX_ROLES): ``assignment[i]`` the role of outfield player i."""
    cycle: int
    """The cycle the assignment was computed for (sent modulo STAMP_MODULUS)."""
    settled: bool
    """Whether the assignment is the team's (else a proposal)."""
    ball: tuple[float, float]
    """Ball position (m)."""
    ball_age: int
    """Cycles since the speaker's ball was seen (0: this cycle); saturates at MAX_AGE."""
    ball_velocity: tuple[float, float] | None = None
    """Ball velocity (m/cycle), or None when the message carries the sender instead."""
    sender: tuple[float, float] | None = None
    """The speaker's own position (m), or None when the message carries the ball's velocity."""


def _checked(name: str, value: object, half_range: float) -> float:
    """``value`` as a float within [-half_range, half_range], or an error naming ``name``."""
    v = math.nan
    if not isinstance(value, (bool, str)):
        try:
            v = float(value)  # type: ignore[arg-type]
        except (TypeError, ValueError):
            v = math.nan
    if not math.isfinite(v) or abs(v) > half_range + 1e-9:
        raise MessageError(f"{name} must be finite and within [-{half_range}, {half_range}], got {value!r}")
    return v


def _whole(name: str, value: object) -> int:
    """``value`` as a whole number >= 0, or an error naming ``name``."""
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < 0:
        raise MessageError(f"{name} must be a whole number >= 0, got {value!r}")
    return int(value)


def _to_text(number: int) -> str:
    """``number`` (0 <= number < 71 ** 10) as exactly MESSAGE_LENGTH base-71 characters."""
    digits = np.empty(MESSAGE_LENGTH, dtype=np.int64)
    number_digits(number, digits)
    return ALPHABET_BYTES[digits].tobytes().decode("ascii")


def encode(msg: TeamMessage) -> str:
    """``msg`` as a 10-character message (resolution in the module docstring)."""
    if not isinstance(msg, TeamMessage):
        raise MessageError(f"cannot encode {type(msg).__name__}: a TeamMessage is needed")
    try:
        assignment = np.array([int(r) for r in msg.assignment], dtype=np.int64)
    except (TypeError, ValueError):
        raise MessageError(f"assignment must be a sequence of role indices, got {msg.assignment!r}") from None
    n = assignment.size
    if n > MAX_ROLES or sorted(assignment.tolist()) != list(range(n)):
        raise MessageError(f"assignment must be a permutation of 0..n-1 with n <= {MAX_ROLES}, "
                           f"got {tuple(assignment.tolist())}")
    cycle = _whole("cycle", msg.cycle)
    age = _whole("ball_age", msg.ball_age)
    ball = np.array([_checked("ball x", _pair_item(msg.ball, "ball", 0), X_RANGE),
                     _checked("ball y", _pair_item(msg.ball, "ball", 1), Y_RANGE)])
    if (msg.ball_velocity is None) == (msg.sender is None):
        raise MessageError("a message carries exactly one of ball_velocity and sender")
    if msg.ball_velocity is not None:
        extra = np.array([_checked("ball_velocity x", _pair_item(msg.ball_velocity, "ball_velocity", 0), V_RANGE),
                          _checked("ball_velocity y", _pair_item(msg.ball_velocity, "ball_velocity", 1), V_RANGE)])
        layout = VELOCITY
    else:
        extra = np.array([_checked("sender x", _pair_item(msg.sender, "sender", 0), X_RANGE),
                          _checked("sender y", _pair_item(msg.sender, "sender", 1), Y_RANGE)])
        layout = SENDER
    if not isinstance(msg.settled, (bool, np.bool_)):
        raise MessageError(f"settled must be True or False, got {msg.settled!r}")
    return _to_text(message_number(assignment, cycle, bool(msg.settled), ball, min(age, MAX_AGE), extra, layout,
                                   MESSAGE_GRID))


def _pair_item(value: object, name: str, index: int) -> object:
    """Item ``index`` of the pair ``value``, or an error naming ``name``."""
    try:
        x, y = value  # type: ignore[misc]
    except (TypeError, ValueError):
        raise MessageError(f"{name} must be a pair (x, y), got {value!r}") from None
    return (x, y)[index]


def decode(text: str) -> TeamMessage:
    """The message ``text`` encodes; :class:`MessageError` if it is not one (wrong length,
    a character outside :data:`ALPHABET`, or digits no encoder produces)."""
    if not isinstance(text, str) or len(text) != MESSAGE_LENGTH:
        raise MessageError(f"a message is a str of {MESSAGE_LENGTH} characters, got {text!r}")
    for c in text:
        if c not in _CODE:
            raise MessageError(f"message {text!r} has a character outside the alphabet: {c!r}")
    decoded = decode_texts([text])
    if not decoded.rows[0]["valid"]:
        raise MessageError(f"message {text!r} is not a valid team message")
    return decoded.message(0)


class Decoded:
    """Messages decoded in one compiled call (:func:`decode_texts`): per message a
    :data:`~agents.message_kernels.DECODED` row and its assignment."""

    def __init__(self, count: int) -> None:
        self.rows = np.zeros(count, dtype=DECODED)
        """(p,) each message's fields (``valid`` False: none of ours)."""
        self.assignment = np.zeros((count, MAX_ROLES), dtype=np.int64)
        """(p, MAX_ROLES) each message's assignment (its first ``size`` entries)."""

    def message(self, p: int) -> TeamMessage:
        """Message ``p`` as a :class:`TeamMessage` (it must be valid); the cycle is the stamp."""
        row = self.rows[p]
        velocity = sender = None
        if row["layout"] == VELOCITY:
            velocity = (float(row["velocity_x"]), float(row["velocity_y"]))
        else:
            sender = (float(row["sender_x"]), float(row["sender_y"]))
        return TeamMessage(assignment=tuple(self.assignment[p, : row["size"]].tolist()), cycle=int(row["stamp"]),
                           settled=bool(row["settled"]), ball=(float(row["ball_x"]), float(row["ball_y"])), ball_age=int(row["ball_age"]),
                           ball_velocity=velocity, sender=sender)


def decode_texts(texts: Sequence[str]) -> Decoded:
    """Decode many message texts in one compiled call; a text that is not a message (wrong
    length, not ASCII, a character outside the alphabet, digits no encoder makes) is not valid."""
    decoded = Decoded(len(texts))
    if texts:
        decode_digits(text_digits(texts), MESSAGE_GRID, decoded.rows, decoded.assignment)
    return decoded


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
    """What each one says."""


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


def digit_messages(digits: np.ndarray, speaks: np.ndarray) -> CodedMessages:
    """Rows of digits (n, MESSAGE_LENGTH) as a team's messages held as codes, what a command
    may say (:class:`~soccer_sim.perception.coded.CodedMessages`: no text is made unless read;
    silent where not ``speaks``)."""
    return CodedMessages.of_arrays(ALPHABET_BYTES[digits], np.array(speaks, dtype=bool))


def digit_texts(digits: np.ndarray, speaks: np.ndarray) -> list[str | None]:
    """Rows of digits (n, MESSAGE_LENGTH) as message texts (None where not ``speaks``)."""
    return list(digit_messages(digits, speaks))


_g = MESSAGE_GRID[0]
assert len(ALPHABET) == message_kernels.BASE and MESSAGE_LENGTH == message_kernels.LENGTH
assert _g["nsx"] * _g["nsy"] <= _g["nv"] * _g["nv"]
assert (perm_offset(MAX_ROLES + 1) * STAMP_MODULUS * 2 * _g["nage"] * _g["nbx"] * _g["nby"] * _g["nv"] ** 2 * LAYOUTS
        <= len(ALPHABET) ** MESSAGE_LENGTH), "the message's parts do not fit in 10 characters"
del _g
