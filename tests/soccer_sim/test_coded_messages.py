"""Messages held as character codes (soccer_sim.perception.coded): the same texts, checks and
deliveries as the strings they stand for."""

from __future__ import annotations

import numpy as np
import pytest

from agents.messages import digit_messages, digit_texts, said_bytes
from soccer_sim.perception.audio import AudioChannel, AudioParams
from soccer_sim.perception.coded import CodedMessages
from soccer_sim.team import TeamError
from tests.soccer_sim.test_audio_channel import line_up

TEXTS = ["abcdefghij", None, "0123456789", "(x) <y>+_?"]


def test_items_slices_and_equality_are_the_texts() -> None:
    coded = CodedMessages.of_texts(TEXTS, 10)
    assert len(coded) == 4 and coded.width == 10
    assert [coded[i] for i in range(4)] == TEXTS and list(coded) == TEXTS
    assert coded == TEXTS and coded == tuple(TEXTS) and coded != TEXTS[::-1]
    assert coded[1:3] == TEXTS[1:3] and type(coded[1:3]) is CodedMessages
    assert coded[-1] == TEXTS[-1]
    with pytest.raises(IndexError):
        coded[4]
    silent = coded.silent_spaces()
    assert silent[1].tobytes() == b" " * 10 and silent[0].tobytes() == b"abcdefghij"


@pytest.mark.parametrize("codes, speaks, what", [
    (np.zeros((2, 3), dtype=np.int64), np.ones(2, bool), "codes must be an \\(n, width\\) uint8"),
    (np.zeros((2, 3), dtype=np.uint8), np.ones(3, bool), "speaks must be a bool array of shape \\(2,\\)"),
    (np.zeros((2, 3), dtype=np.uint8), [True, True], "speaks must be a bool array"),
])
def test_bad_arrays_say_which(codes, speaks, what) -> None:
    with pytest.raises(TypeError, match=what):
        CodedMessages(codes, speaks)


def test_of_texts_refuses_a_text_of_another_width() -> None:
    with pytest.raises(ValueError, match="message 1 \\('abc'\\) is not 10 ASCII characters"):
        CodedMessages.of_texts(["abcdefghij", "abc"], 10)


def test_digit_messages_are_digit_texts() -> None:
    digits = np.random.default_rng(3).integers(0, 70, (11, 10))
    present = np.ones(11, bool)
    present[[2, 7]] = False
    coded = digit_messages(digits, present)
    assert coded == digit_texts(digits, present)
    assert np.array_equal(said_bytes(coded), said_bytes(digit_texts(digits, present)))


def _deliveries(says: list[list], seed: int = 5) -> list:
    """What a channel between 3 and 2 players delivers over the cycles of ``says``."""
    channel, rng, out = AudioChannel((3, 2)), np.random.default_rng(seed), []
    for cycle, said in enumerate(says):
        channel.say(cycle, said, line_up(3, 2, spacing=10.0))
        heard = channel.hear(cycle + 1, rng)
        out.append((heard.messages, heard.arrived.tolist(), heard.heard.tolist()))
    return out


def test_the_channel_delivers_coded_messages_as_their_texts() -> None:
    home = [["aaaaaaaaaa", None, "cccccccccc"], ["bbbbbbbbbb", "dddddddddd", "eeeeeeeeee"]]
    away = [["xxxxxxxxxx", "yyyyyyyyyy"], [None, None]]
    says = [[home[0], away[0]], [home[1], away[1]], [home[0], [None, None]]]
    coded = [[CodedMessages.of_texts(h, 10), CodedMessages.of_texts(a, 10) if a[0] else a] for h, a in says]
    expected = _deliveries(says)
    assert _deliveries(coded) == expected
    assert expected[1][0] == ("bbbbbbbbbb", "dddddddddd", "eeeeeeeeee", None, None)
    # one team coded and the other in texts: the general path, the same delivery
    mixed = [[CodedMessages.of_texts(h, 10), a] for h, a in says]
    assert _deliveries(mixed) == expected
    # a silent first team beside a coded second one: the coded path, the same delivery
    silent_first = [[[None, None, None], a] for _, a in says]
    assert _deliveries([[h, CodedMessages.of_texts(a, 10) if a[0] else a] for h, a in silent_first]) \
        == _deliveries(silent_first)
    # widths that differ: the general path too
    short = [[CodedMessages.of_texts(h, 10), CodedMessages.of_texts(["x1", "y2"], 2)] for h, _ in says]
    assert _deliveries(short)[0][0] == ("aaaaaaaaaa", None, "cccccccccc", "x1", "y2")


@pytest.mark.parametrize("texts, width, params, what", [
    (["abc,defghi", None, None], 10, AudioParams(), "characters the server refuses: ','"),
    ([None, "a" * 11, None], 11, AudioParams(), "11 characters, more than say_msg_size 10"),
    ([None, None, "abcd"], 4, AudioParams(characters="abc"), "characters the server refuses: 'd'"),
])
def test_a_bad_coded_message_is_a_team_error_naming_the_player(texts, width, params, what) -> None:
    channel = AudioChannel((3, 2), ("reds", "blues"), params)
    bad = CodedMessages.of_texts(texts, width)
    player = next(i for i, t in enumerate(texts) if t is not None)
    with pytest.raises(TeamError, match=f"team 'reds', player {player}: .*{what}"):
        channel.say(0, [bad, [None, None]], line_up(3, 2))
    with pytest.raises(TeamError, match="2 say messages for 3 players"):
        channel.say(0, [bad[:2], [None, None]], line_up(3, 2))


def test_a_code_outside_ascii_is_refused_not_a_crash() -> None:
    codes = np.frombuffer(b"abcdefghi\xe9", dtype=np.uint8).reshape(1, 10).copy()
    channel = AudioChannel((1, 0), ("reds", "blues"))
    with pytest.raises(TeamError, match="team 'reds', player 0: .*refuses"):
        channel.say(0, [CodedMessages(codes, np.ones(1, bool)), []], line_up(1, 0))
