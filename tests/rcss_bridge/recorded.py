"""The transcripts recorded from rcssserver 19 (tests/data/rcssserver/transcripts/, made by
tests/data/rcssserver/probes/record_transcripts.py and make_transcripts.py), grouped for the
tests: BRIDGE (left) players 1 (goalkeeper) and 2 with their online coach, OTHERS (right)
player 1, and the trainer's exact positions (see_global) at the same steps."""

from __future__ import annotations

import re
from collections import defaultdict
from functools import lru_cache
from pathlib import Path

from rcss_bridge.transcripts import Datagram, read_transcript

DATA = Path(__file__).resolve().parents[1] / "data" / "rcssserver" / "transcripts"
EXCHANGE = DATA / "exchange.jsonl.gz"
TRUTH = DATA / "truth.jsonl.gz"

_GLOBAL_PLAYER = re.compile(r'\(\(p "(\w+)" (\d+)(?: goalie)?\) ([-\d.e]+) ([-\d.e]+) ([-\d.e]+) ([-\d.e]+) '
                            r'([-\d.e]+) ([-\d.e]+)\)')
_GLOBAL_BALL = re.compile(r"\(\(b\) ([-\d.e]+) ([-\d.e]+) ([-\d.e]+) ([-\d.e]+)\)")


@lru_cache(maxsize=None)
def exchange() -> tuple[Datagram, ...]:
    return tuple(read_transcript(EXCHANGE))


def received(client: str) -> dict[int, list[str]]:
    """The texts ``client`` received, by the recorder's step (-1: at connection)."""
    out: dict[int, list[str]] = defaultdict(list)
    for d in exchange():
        if d.client == client and d.direction == "in":
            out[d.step].append(d.text)
    return dict(out)


def sent(client: str) -> dict[int, list[str]]:
    """The texts ``client`` sent, by step."""
    out: dict[int, list[str]] = defaultdict(list)
    for d in exchange():
        if d.client == client and d.direction == "out":
            out[d.step].append(d.text)
    return dict(out)


@lru_cache(maxsize=None)
def truth() -> dict[int, dict]:
    """Recorder step -> {"ball": (x, y), ("TEAM", unum): (x, y, body)} from the trainer (by
    step: the server's clock stands still before kick-off and after a goal)."""
    out: dict[int, dict] = {}
    for d in read_transcript(TRUTH):
        state: dict = {}
        ball = _GLOBAL_BALL.search(d.text)
        if ball:
            state["ball"] = (float(ball.group(1)), float(ball.group(2)))
        for m in _GLOBAL_PLAYER.finditer(d.text):
            state[(m.group(1), int(m.group(2)))] = (float(m.group(3)), float(m.group(4)), float(m.group(7)))
        out[d.step] = state
    return out
