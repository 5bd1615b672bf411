"""The environment's message codec: ``k`` numbers in [-1, 1] as one say message and back.

Under partial observation with ``say_values=k`` (1 to :data:`MAX_SAY_VALUES`) an agent's action
ends with a speak flag and ``k`` values in [-1, 1]; when the flag is above 0 the values become
one message of ``2 k`` characters, two per value, which the match carries through its say/hear
channel (``docs/simulator.md`` §13) to the team-mates in range, who find it decoded in their
next observation (:mod:`soccer_sim.env.partial_spaces`).

Each value is quantised to one of ``71 * 71 = 5041`` evenly spaced levels over [-1, 1] (a step
of 2 / 5040, so a decoded value is within 1 / 5040 of the clipped value said) and written as two
base-71 digits, most significant first, over :data:`ALPHABET`: rcssserver's say characters
without space and parentheses (the characters a client can put in a message without quoting).
A message of another length or with another character (a scripted team's, a user's) is not in
this codec: :meth:`SayCodec.decode` gives None, never an exception.
"""

from __future__ import annotations

import numpy as np

from soccer_sim.perception import SAY_CHARACTERS

ALPHABET: str = "".join(c for c in SAY_CHARACTERS if c not in " ()")
"""The 71 characters of the codec, in :data:`~soccer_sim.perception.SAY_CHARACTERS` order."""
BASE = len(ALPHABET)
LEVELS = BASE * BASE
"""Quantisation levels of one value (two characters)."""
CHARS_PER_VALUE = 2
MAX_SAY_VALUES = 5
"""The most values one message holds: 10 characters, rcssserver's ``say_msg_size``."""

_DIGITS = np.frombuffer(ALPHABET.encode("ascii"), dtype=np.uint8)
"""Digit -> ASCII code."""
_PAIRS = {a + b: (BASE * i + j) * (2.0 / (LEVELS - 1)) - 1.0 for i, a in enumerate(ALPHABET)
          for j, b in enumerate(ALPHABET)}
"""Two characters -> the value of their level (5041 entries)."""


class SayCodec:
    """Encodes and decodes messages of ``values`` numbers (1 to :data:`MAX_SAY_VALUES`)."""

    def __init__(self, values: int) -> None:
        if not 1 <= values <= MAX_SAY_VALUES:
            raise ValueError(f"a message holds 1 to {MAX_SAY_VALUES} values, got {values}")
        self.values = values
        self.length = CHARS_PER_VALUE * values
        """Characters of one message."""
        self._dtype = np.dtype(f"S{self.length}")

    def encode(self, values: np.ndarray, speak: np.ndarray) -> list[str | None]:
        """One message per row of ``values`` (n, k), clipped to [-1, 1], for the rows where
        ``speak`` (n,) is True; None (silent) for the others."""
        levels = np.rint((np.clip(values, -1.0, 1.0) + 1.0) * ((LEVELS - 1) / 2.0)).astype(np.int64)
        digits = np.empty((len(levels), self.length), dtype=np.uint8)
        digits[:, 0::2] = _DIGITS[levels // BASE]
        digits[:, 1::2] = _DIGITS[levels % BASE]
        words = digits.view(self._dtype)[:, 0]
        return [word.decode("ascii") if talk else None for word, talk in zip(words.tolist(), speak.tolist())]

    def decode(self, message: object) -> np.ndarray | None:
        """The (k,) values of ``message`` (each within 1/5040 of the value said), or None when it
        is not a message of this codec (another length, another character, not a str)."""
        values = self.values_of(message)
        return None if values is None else np.array(values)

    def values_of(self, message: object) -> list[float] | None:
        """:meth:`decode` as a list of floats (the fast path for a few messages per cycle: one
        dictionary look-up per character pair)."""
        if not isinstance(message, str) or len(message) != self.length:
            return None
        try:
            return [_PAIRS[message[j:j + 2]] for j in range(0, self.length, 2)]
        except KeyError:
            return None
