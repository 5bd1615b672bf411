"""The say/hear channel (soccer_sim.perception.audio) against rcssserver's rules."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim.config_checks import ConfigError
from soccer_sim.perception.audio import SAY_CHARACTERS, AudioChannel, AudioParams, check_message
from soccer_sim.team import TeamError


def line_up(n0: int, n1: int, spacing: float = 1.0) -> np.ndarray:
    """Both teams' players on the x axis, ``spacing`` m apart (home first)."""
    return np.stack([np.arange(n0 + n1) * spacing, np.zeros(n0 + n1)], axis=1)


def test_server_character_set_and_defaults() -> None:
    assert len(SAY_CHARACTERS) == 74 and len(set(SAY_CHARACTERS)) == 74
    for c in "-09azAZ ().+*/?<>_":
        assert c in SAY_CHARACTERS
    for c in "\"',;:!@#$%^&=[]{}~`\\|\n":
        assert c not in SAY_CHARACTERS
    p = AudioParams()
    assert (p.say_msg_size, p.audio_cut_dist, p.hear_max, p.hear_inc, p.hear_decay) == (10, 50.0, 1, 1, 1)


@pytest.mark.parametrize("kwargs, field", [({"say_msg_size": 0}, "say_msg_size"), ({"hear_max": -1}, "hear_max"),
                                           ({"hear_inc": 1.5}, "hear_inc"), ({"audio_cut_dist": np.nan}, "audio_cut_dist"),
                                           ({"characters": ""}, "characters")])
def test_bad_params_name_the_field(kwargs: dict, field: str) -> None:
    with pytest.raises(ConfigError, match=f"AudioParams.{field}"):
        AudioParams(**kwargs)


@pytest.mark.parametrize("msg, what", [("a" * 11, "11 characters"), ("ab,c", "','"), ("", "empty"),
                                       ('x"y', "'\"'"), (12, "str or None")])
def test_bad_messages_are_team_errors_naming_the_player(msg: object, what: str) -> None:
    ch = AudioChannel((2, 1), ("reds", "blues"))
    says = [[None, msg], [None]]
    with pytest.raises(TeamError, match=f"team 'reds', player 1: .*{what}") as err:
        ch.say(0, says, line_up(2, 1))
    assert err.value.player == 1 and isinstance(err.value, Exception)
    check_message("a" * 10)  # the longest allowed
    check_message(SAY_CHARACTERS[:10])


def test_heard_exactly_one_cycle_later_within_range_opponents_included() -> None:
    pos = line_up(2, 2, spacing=30.0)  # x = 0, 30 (home), 60, 90 (away)
    ch = AudioChannel((2, 2))
    rng = np.random.default_rng(0)
    ch.hear(0, rng)
    ch.say(0, [["hello", None], [None, None]], pos)
    h1 = ch.hear(1, rng)
    # speaker 0 at x=0 reaches x=30 (mate) and x=50 limit: the opponent at 60 is out of range
    assert h1.heard[:, 0].tolist() == [False, True, False, False]
    assert h1.for_listener(1) == (((0, "hello"),), (), None)
    assert h1.for_listener(0) == ((), (), "hello")  # the speaker gets its own message back
    ch.say(1, [[None, None], [None, "yo"]], pos)  # speaker 3 at x=90: reaches 60 (mate); 30 is 60 m away
    h2 = ch.hear(2, rng)
    assert not h2.heard[:, 0].any()  # said at 0, not heard again at 2
    assert h2.heard[:, 3].tolist() == [False, False, True, False]
    ch.say(2, [[None, "hi"], [None, None]], pos)  # from x=30: x=0 and x=60 within 50 m, x=90 not
    h3 = ch.hear(3, rng)
    assert h3.heard[:, 1].tolist() == [True, False, True, False]
    assert h3.for_listener(2) == ((), ("hi",), None)  # an opponent's message does not name its speaker
    assert h3.for_listener(3) == ((), (), None)
    # exactly at audio_cut_dist still arrives (distance2 <= cut**2)
    ch2 = AudioChannel((1, 1))
    ch2.say(5, [["a"], ["b"]], np.array([[0.0, 0.0], [50.0, 0.0]]))
    assert ch2.hear(6, rng).heard.tolist() == [[False, True], [True, False]]


def test_message_lost_when_a_delivery_is_skipped() -> None:
    ch = AudioChannel((2, 0))
    ch.say(4, [["a", "b"], []], line_up(2, 0))
    assert not ch.hear(6, np.random.default_rng(1)).heard.any()


def test_at_most_hear_max_per_side_uniform_choice_and_capacity() -> None:
    ch = AudioChannel((11, 11))
    pos = line_up(11, 11, spacing=0.5)
    says = [[f"m{i}" for i in range(11)], [f"o{i}" for i in range(11)]]
    rng = np.random.default_rng(7)
    counts = np.zeros(22)
    for t in range(0, 4000, 2):
        ch.say(t, says, pos)
        h = ch.hear(t + 1, rng)
        mates = h.heard[:11, :11].sum(axis=1)
        opps = h.heard[:11, 11:].sum(axis=1)
        assert np.all(mates == 1) and np.all(opps == 1)  # hear_max 1 per side
        assert np.all(h.heard <= h.arrived)
        counts += h.heard[0]
    # listener 0 chooses among its 10 team-mates and 11 opponents uniformly
    assert counts[0] == 0
    assert np.all(np.abs(counts[1:11] / 2000 - 0.1) < 0.03)
    assert np.all(np.abs(counts[11:] / 2000 - 1 / 11) < 0.03)


def test_capacity_rule_with_other_parameters() -> None:
    # hear_max 2, hear_inc 1, hear_decay 1: two per side at first, then one per cycle regained
    ch = AudioChannel((4, 0), params=AudioParams(hear_max=2, hear_inc=1, hear_decay=1))
    pos = line_up(4, 0)
    rng = np.random.default_rng(3)
    ch.hear(0, rng)
    got = []
    for t in range(0, 4):
        ch.say(t, [["a", "b", "c", "d"], []], pos)
        got.append(ch.hear(t + 1, rng).heard[0].sum())
    assert got == [2, 1, 1, 1]
    # hear_decay 0: everything is heard
    ch0 = AudioChannel((4, 0), params=AudioParams(hear_decay=0))
    ch0.say(0, [["a", "b", "c", "d"], []], pos)
    assert ch0.hear(1, rng).heard.sum(axis=1).tolist() == [3, 3, 3, 3]


def test_attention_takes_that_message_first_and_determinism() -> None:
    pos = line_up(5, 0)
    says = [["a", "b", "c", "d", "e"], []]
    att = np.array([3, -1, -1, -1, -1])
    runs = []
    for _ in range(2):
        ch = AudioChannel((5, 0))
        rng = np.random.default_rng(11)
        out = []
        for t in range(0, 40, 2):
            ch.say(t, says, pos)
            h = ch.hear(t + 1, rng, attention=att)
            assert h.heard[0].tolist() == [False, False, False, True, False]
            out.append(h.heard.copy())
        runs.append(np.array(out))
    assert np.array_equal(runs[0], runs[1])
    assert len({tuple(np.flatnonzero(x[1])) for x in runs[0]}) > 1  # player 1's choice varies with the rng


def test_call_order_errors() -> None:
    ch = AudioChannel((1, 0))
    ch.say(3, [["a"], []], np.zeros((1, 2)))
    with pytest.raises(ValueError, match="not after"):
        ch.say(3, [["a"], []], np.zeros((1, 2)))
    with pytest.raises(ValueError, match="positions"):
        ch.say(4, [["a"], []], np.zeros((2, 2)))
    with pytest.raises(TeamError, match="2 say messages for 1 players"):
        ch.say(5, [["a", "b"], []], np.zeros((1, 2)))
    with pytest.raises(ValueError, match="team_sizes"):
        AudioChannel((12, 0))


def test_direction_to_the_speaker_truncated_degrees_from_the_body() -> None:
    ch = AudioChannel((2, 1))
    pos = np.array([[0.0, 0.0], [10.0, 10.0], [-10.0, 0.5]])
    ch.say(0, [[None, "a"], ["b"]], pos)
    body = np.array([0.0, 90.0, 50.0])
    h = ch.hear(1, np.random.default_rng(0), positions=pos, body_dirs=body)
    assert h.direction is not None
    assert h.direction[0, 1] == 45.0                        # speaker 1 at 45 degrees
    assert h.direction[0, 2] == 177.0                       # atan2(0.5, -10) = 177.14 -> 177 (truncated)
    assert h.direction[1, 2] == 115.0                       # -154.59 - 90 folded: 115.41 -> 115
    assert h.direction[2, 1] == -24.0                       # 25.41 - 50 = -24.59 -> -24 (towards zero)
    assert np.isnan(h.direction[0, 0]) and np.isnan(h.direction[1, 0])  # 0 said nothing
    plain = AudioChannel((1, 0))
    assert plain.hear(0, np.random.default_rng(0)).direction is None
    with pytest.raises(ValueError, match="body_dirs"):
        ch.hear(2, np.random.default_rng(0), positions=pos)


def test_capacity_not_regained_without_hear_inc_until_reset() -> None:
    ch = AudioChannel((2, 0), params=AudioParams(hear_inc=0))
    pos = line_up(2, 0)
    rng = np.random.default_rng(4)
    got = []
    for t in range(3):
        ch.say(2 * t, [["a", "b"], []], pos)
        got.append(int(ch.hear(2 * t + 1, rng).heard.sum()))
        if t == 1:
            ch.reset_capacity()  # half time: rcssserver's recoverAll
    assert got == [2, 0, 2]
