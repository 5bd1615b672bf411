"""A team's messages of one cycle held as character codes rather than strings.

A ``TeamCommand.say`` is one ``str`` or None per player. A team whose players always say
messages of one fixed width (the built-in teams' 10-character encodings) may give a
:class:`CodedMessages` instead: the same sequence of texts, kept as an (n, width) array of
ASCII codes. The match then checks the characters with one table look-up per code
(:func:`first_bad_row`), the say/hear channel stores and delivers the array as it stands, and
a listener that decodes whole deliveries (the built-in world models) reads the codes without a
string ever being made. A text is made only when somebody reads an item.
"""

from __future__ import annotations

import functools
from collections.abc import Iterator, Sequence

import numpy as np
from numba import njit

SILENT_CODE = ord(" ")
"""The code filling a silent player's row (its row is never read as a message)."""


class CodedMessages(Sequence):
    """Messages of one width, one per player, as ASCII codes (module docstring).

    ``codes`` (n, width) uint8: each player's characters; ``speaks`` (n,) bool: who says its
    row (the others say nothing: their items are None). Indexing gives the text (``str``) or
    None; a slice gives a :class:`CodedMessages` sharing the arrays. Equal to any sequence of
    the same texts."""

    __slots__ = ("codes", "speaks")

    def __init__(self, codes: np.ndarray, speaks: np.ndarray) -> None:
        if not (isinstance(codes, np.ndarray) and codes.dtype == np.uint8 and codes.ndim == 2):
            raise TypeError(f"CodedMessages: codes must be an (n, width) uint8 array, got "
                            f"{getattr(codes, 'dtype', type(codes).__name__)} {getattr(codes, 'shape', '')}")
        if not (isinstance(speaks, np.ndarray) and speaks.dtype == np.bool_ and speaks.shape == codes.shape[:1]):
            raise TypeError(f"CodedMessages: speaks must be a bool array of shape {codes.shape[:1]}, got "
                            f"{getattr(speaks, 'dtype', type(speaks).__name__)} {getattr(speaks, 'shape', '')}")
        self.codes, self.speaks = codes, speaks

    @classmethod
    def of_arrays(cls, codes: np.ndarray, speaks: np.ndarray) -> CodedMessages:
        """The messages of ``codes`` and ``speaks`` known to be right (arrays of this module's
        callers, made every cycle): the constructor without its checks."""
        messages = object.__new__(cls)
        messages.codes, messages.speaks = codes, speaks
        return messages

    @classmethod
    def of_texts(cls, texts: Sequence[str | None], width: int) -> CodedMessages:
        """The messages ``texts`` (each None or an ASCII str of exactly ``width`` characters)."""
        codes = np.full((len(texts), width), SILENT_CODE, dtype=np.uint8)
        speaks = np.array([text is not None for text in texts], dtype=bool)
        for i, text in enumerate(texts):
            if text is not None:
                if not isinstance(text, str) or len(text) != width or not text.isascii():
                    raise ValueError(f"CodedMessages.of_texts: message {i} ({text!r}) is not {width} ASCII characters")
                codes[i] = np.frombuffer(text.encode("ascii"), dtype=np.uint8)
        return cls(codes, speaks)

    @property
    def width(self) -> int:
        """The characters of every message."""
        return self.codes.shape[1]

    def silent_spaces(self) -> np.ndarray:
        """``codes`` with every silent player's row made spaces (the array itself when all speak)."""
        speaks = self.speaks
        if np.count_nonzero(speaks) == speaks.shape[0]:
            return self.codes
        return np.where(self.speaks[:, None], self.codes, np.uint8(SILENT_CODE))

    def __len__(self) -> int:
        return self.speaks.shape[0]

    def __getitem__(self, index):  # type: ignore[override]
        if isinstance(index, slice):
            return CodedMessages.of_arrays(self.codes[index], self.speaks[index])
        if not self.speaks[index]:
            return None
        return self.codes[index].tobytes().decode("latin-1")

    def __iter__(self) -> Iterator[str | None]:
        width = self.width
        raw = self.codes.tobytes().decode("latin-1")
        return iter([raw[i * width:(i + 1) * width] if speaks else None
                     for i, speaks in enumerate(self.speaks.tolist())])

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Sequence) and not isinstance(other, (str, bytes)):
            return tuple(self) == tuple(other)
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]

    def __repr__(self) -> str:
        return f"CodedMessages({tuple(self)!r})"


@functools.lru_cache(maxsize=8)
def allowed_codes(characters: str) -> np.ndarray:
    """(256,) bool, read only: the codes of ``characters`` (the channel's allowed set), made once
    per set."""
    table = np.zeros(256, dtype=bool)
    table[[ord(c) for c in characters if ord(c) < 256]] = True
    table.setflags(write=False)
    return table


@njit(cache=True, nogil=True)
def first_bad_row(codes: np.ndarray, speaks: np.ndarray, allowed: np.ndarray) -> int:  # pragma: no cover - compiled
    """The first speaking row of ``codes`` (n, width) with a code ``allowed`` (256,) refuses;
    -1 when there is none."""
    for i in range(codes.shape[0]):
        if speaks[i]:
            for j in range(codes.shape[1]):
                if not allowed[codes[i, j]]:
                    return i
    return -1
