"""A refused say message is named in one short line, however long or strange it is."""

from __future__ import annotations

import pytest

from soccer_sim import TeamError
from soccer_sim.perception.audio import AudioParams, check_message, check_team_messages


@pytest.mark.parametrize("message", ["\x1b" * 1000, "é" * 5000, "".join(map(chr, range(1, 1000)))],
                         ids=["escapes", "accents", "every-character"])
def test_a_long_refused_message_is_echoed_cut_short_on_one_line(message: str) -> None:
    with pytest.raises(TeamError) as info:
        check_message(message, AudioParams(), "talkers", 3)
    text = str(info.value)
    assert "\n" not in text and "\x1b" not in text and len(text) < 250
    assert f"has {len(message)} characters" in text and "more)" in text


def test_refused_characters_are_echoed_cut_short() -> None:
    message = "".join(map(chr, range(0x400, 0x40A)))  # ten characters, none allowed
    with pytest.raises(TeamError) as info:
        check_team_messages([None, message], 2, AudioParams(), "talkers")
    text = str(info.value)
    assert "characters the server refuses" in text and len(text) < 250 and "\n" not in text


def test_a_short_refused_message_is_echoed_whole() -> None:
    with pytest.raises(TeamError, match=r"say message 'ab\\n' has characters the server refuses: '\\n'"):
        check_message("ab\n")
