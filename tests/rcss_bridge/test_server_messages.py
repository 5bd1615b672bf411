"""The parsers of rcss_bridge on messages recorded from rcssserver 19."""

from __future__ import annotations

import math
import re

import pytest

from rcss_bridge.errors import BridgeError, ProtocolError
from rcss_bridge.messages import (Hear, InitReply, Parameters, Reply, See, SenseBody, Think, TypeChange,
                                  read_hear, read_message)
from rcss_bridge.sexpr import head, parse
from tests.rcss_bridge.recorded import exchange, received, sent


def test_every_recorded_message_to_a_player_parses():
    kinds = set()
    for d in exchange():
        if d.direction == "in" and d.client != "BRIDGE-coach":
            kinds.add(type(read_message(d.text)))
    assert {InitReply, SenseBody, See, Hear, TypeChange, Reply, Parameters, Think} <= kinds


def test_init_replies():
    assert read_message(received("BRIDGE-1")[-1][0]) == InitReply("l", 1, "before_kick_off")
    assert read_message(received("OTHERS-1")[-1][0]) == InitReply("r", 1, "before_kick_off")
    assert read_message(received("BRIDGE-coach")[-1][0]) == InitReply("l", None, None)


def test_sense_body_before_kick_off():
    sense = read_message(next(t for t in received("BRIDGE-1")[-1] if t.startswith("(sense_body")))
    assert isinstance(sense, SenseBody)
    assert (sense.time, sense.stamina, sense.effort, sense.capacity) == (0, 8000.0, 1.0, 130600.0)
    assert (sense.view_quality, sense.view_width, sense.head_angle, sense.card) == ("high", "normal", 0.0, "none")
    assert sense.counts["dash"] == 0 and sense.tackle_expires == 0 and sense.foul_charged == 0


def test_see_holds_flags_lines_ball_and_players():
    see = read_message(next(t for t in received("BRIDGE-1")[42] if t.startswith("(see")))
    assert isinstance(see, See) and see.time == 34
    assert len(see.landmarks) > 20 and all(obj.kind in ("f", "g") for obj in see.landmarks)
    assert {line.name for line in see.lines} <= {("l", "l"), ("l", "r"), ("l", "t"), ("l", "b")}
    assert see.ball is not None and see.ball.distance > 40
    named = [p for p in see.players if p.team is not None]
    assert named and all(p.team == "OTHERS" and p.unum in (1, 2) for p in named)
    assert all(p.body is not None for p in named)  # close enough for their body direction


def test_hears_of_each_sender():
    texts = received("BRIDGE-1")[42]
    hears = [read_message(t) for t in texts if t.startswith("(hear")]
    by_sender = {h.sender: h for h in hears}
    assert by_sender["referee"].message == "goal_l_1"
    assert by_sender["self"].message.startswith("m1s")
    mate = by_sender["our"]
    assert mate.unum is not None and mate.message == f"m{mate.unum}s41" and mate.direction is not None
    assert by_sender["opp"].message.startswith("m") and by_sender["opp"].unum is None


def test_an_unquoted_say_is_heard_as_the_server_took_it():
    """OTHERS' player 1 sent ``(turn 10)(say ABC)(done)``: the server took everything after
    ``say`` to the datagram's last parenthesis as the message, the ``(done)`` with it."""
    assert "(turn 10)(say ABC)(done)" in sent("OTHERS-1")[20]
    heard = [read_hear(t) for t in received("OTHERS-1")[21] if t.startswith("(hear") and " self " in t]
    assert heard == [Hear(13, "self", "ABC)(done")]


def test_type_changes_name_team_mates_types_and_only_opponents_numbers():
    changes = [read_message(t) for t in received("BRIDGE-2")[9] if t.startswith("(change_player_type")]
    assert TypeChange(3, 1) in changes and TypeChange(11, 10) in changes
    assert TypeChange(2, None) in changes  # the opponents' player 2: no type told
    coach_said = [read_message(t) for t in received("BRIDGE-2")[0] if t.startswith("(change_player_type")]
    assert coach_said == [TypeChange(2, 5)]


@pytest.mark.parametrize("text, wrong", [
    ("(see 3 ((f c) 1 2)", "unbalanced '('"),
    ("(see 3))", "unbalanced ')'"),
    ("(sense_body 3) x", "outside parentheses"),
    ("(teleport 3)", "unknown server message"),
    ("(sense_body x (stamina 1 1 1) (speed 0 0) (head_angle 0))", "sense_body time: expected a number"),
    ("(hear 3 nobody hello)", "unreadable hear"),
])
def test_malformed_messages_are_one_clear_error(text, wrong):
    with pytest.raises(ProtocolError, match=re.escape(wrong)) as info:
        read_message(text)
    assert isinstance(info.value, BridgeError) and isinstance(info.value, ValueError)


def test_parse_keeps_quoted_strings_whole():
    assert parse('(hear 0 (p "A B" 1) "x (y)")\0') == ["hear", "0", ["p", '"A B"', "1"], '"x (y)"']
    assert head("(sense_body 0 (x))") == "sense_body" and head("junk") == ""
    assert math.isnan(read_message("(see 1 ((b) 2))").ball.distance)
