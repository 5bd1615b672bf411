"""Transcripts of a client's exchange with the server: every datagram, one JSON line each.

A line is ``{"client": NAME, "step": STEP, "dir": "in" | "out", "text": TEXT}``: ``client``
names the connection (``TEAM-UNUM`` for a player, ``TEAM-coach`` for the online coach),
``step`` is the client's own step counter (-1 before the first ``(think)``) and ``text`` the
datagram without its trailing NUL. :class:`TranscriptWriter` records a live exchange
(:class:`~rcss_bridge.client.TeamClient` takes one), :func:`read_transcript` reads a file
back (the tests replay recorded transcripts of the real server).
"""

from __future__ import annotations

import gzip
import json
from dataclasses import dataclass
from pathlib import Path
from typing import IO

from rcss_bridge.errors import ProtocolError


@dataclass(frozen=True)
class Datagram:
    """One datagram of a transcript."""

    client: str
    step: int
    direction: str
    """``"in"`` (from the server) or ``"out"`` (to it)."""
    text: str


class TranscriptWriter:
    """Writes datagrams as JSON lines to an open text stream (the caller owns the stream)."""

    def __init__(self, stream: IO[str]) -> None:
        self._stream = stream

    def __call__(self, client: str, step: int, direction: str, text: str) -> None:
        self._stream.write(json.dumps({"client": client, "step": step, "dir": direction, "text": text}) + "\n")


def read_transcript(path: str | Path) -> list[Datagram]:
    """Every datagram of the transcript file at ``path`` (gzip-compressed when its name ends in
    ``.gz``), in order (a :class:`ProtocolError` naming the line for one that is not a datagram)."""
    out: list[Datagram] = []
    opener = gzip.open if str(path).endswith(".gz") else open
    with opener(path, "rt", encoding="utf-8") as stream:
        for number, line in enumerate(stream, 1):
            if not line.strip():
                continue
            try:
                row = json.loads(line)
                out.append(Datagram(str(row["client"]), int(row["step"]), str(row["dir"]), str(row["text"])))
            except (ValueError, KeyError, TypeError) as exc:
                raise ProtocolError(f"{path}:{number}: not a transcript line ({exc})") from None
    return out
