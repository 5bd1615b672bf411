"""The body direction between two sees, on an exchange recorded from rcssserver 19.0.0
(``tests/data/rcssserver/transcripts/turns.jsonl.gz``: shirt 9 of the left team standing at
the opponents' kick-off, seeing every second step; ``turns_truth.json``: its body direction
in the game log at each server time).

``sense_body`` tells the neck, never the body: the views builder must turn the body it kept
from the last see by the player's own turns. Kept unturned (as the bridge first did), the
translation turned the player towards the ball again on every step without a see, from a
body it had already turned: the player swung through 150-180 degrees each step and never
faced the ball (recorded here: the orders in the exchange are those of that first bridge)."""

from __future__ import annotations

import json
import re
from collections import defaultdict


from rcss_bridge.localisation import wrap
from rcss_bridge.messages import SenseBody, See, read_message
from rcss_bridge.transcripts import read_transcript
from rcss_bridge.views_builder import ViewsBuilder
from tests.rcss_bridge.recorded import DATA

ROW = 8
"""Shirt 9's row."""

TURN_NOISE = 0.1
"""rcssserver's ``player_rand``: a turn's moment is off by up to this share."""


def replay(turns_known: bool) -> list[tuple[int, bool, float, float, float]]:
    """(server time, saw, body in the views, body in the game log, the turn before it)."""
    truth = json.loads((DATA / "turns_truth.json").read_text())["body_by_time"]
    steps: dict[int, list] = defaultdict(list)
    for datagram in read_transcript(DATA / "turns.jsonl.gz"):
        steps[datagram.step].append(datagram)
    builder = ViewsBuilder("mmd_msd2", "l", 11, [0.4] * 18)
    out, turn = [], 0.0
    for step in sorted(steps):
        messages = [read_message(d.text) for d in steps[step] if d.direction == "in"]
        views = builder.update(step, {ROW: messages})
        time = next(m for m in messages if isinstance(m, SenseBody)).time
        saw = any(isinstance(m, See) for m in messages)
        out.append((time, saw, float(views.body_direction[ROW]), truth[str(time)], turn))
        sent = " ".join(d.text for d in steps[step] if d.direction == "out")
        found = re.search(r"\(turn (-?[\d.]+)\)", sent)
        turn = float(found.group(1)) if found else 0.0  # at rest (speed 0): the body turns by the moment
        if turns_known:
            angles = [0.0] * 11
            angles[ROW] = turn
            builder.turned(angles)
    return out


def test_the_body_is_turned_by_the_players_own_turns_between_sees():
    rows = replay(turns_known=True)
    between = [r for r in rows[1:] if not r[1]]
    assert len(between) >= 10 and all(abs(r[4]) > 100 for r in between)  # large turns, every one
    for time, saw, body, real, turn in rows[1:]:
        limit = 1.0 if saw else TURN_NOISE * abs(turn) + 1.0
        assert abs(wrap(body - real)) <= limit, (time, body, real, turn)


def test_kept_unturned_the_body_is_half_a_turn_off_between_sees():
    rows = replay(turns_known=False)
    between = [r for r in rows[1:] if not r[1]]
    assert all(abs(wrap(body - real)) > 100 for _, _, body, real, _ in between)
    assert all(abs(wrap(body - real)) <= 1.0 for _, saw, body, real, _ in rows if saw)
