"""The views' heard messages (:class:`HeardLog`) say what the channel's :class:`Heard` says."""

from __future__ import annotations

import numpy as np
import pytest

from agents.messages import heard_pairs
from soccer_sim.perception.audio import AudioChannel, AudioParams
from soccer_sim.perception.views import HeardLog

SIZES = (11, 10)


def _said_and_heard(seed: int, params: AudioParams = AudioParams()):
    """A channel after one random say (some players silent) and the next cycle's hearing."""
    rng = np.random.default_rng(seed)
    channel = AudioChannel(SIZES, params=params)
    players = sum(SIZES)
    positions = rng.uniform(-40.0, 40.0, (players, 2))
    words = [f"p{p}c{seed}" if rng.random() < 0.8 else None for p in range(players)]
    channel.say(4, [words[:SIZES[0]], words[SIZES[0]:]], positions)
    return channel.hear(5, np.random.default_rng(seed + 100)), words


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("hear_max", [1, 3])
def test_each_listener_hears_what_the_channel_delivered(seed, hear_max):
    heard, words = _said_and_heard(seed, AudioParams(hear_max=hear_max, hear_inc=hear_max))
    rows = (slice(0, SIZES[0]), slice(SIZES[0], sum(SIZES)))
    for team in (0, 1):
        r, other = rows[team], rows[1 - team]
        mates = HeardLog(heard.heard[r, r], heard.messages[r], named=True)
        opponents = HeardLog(heard.heard[r, other], heard.messages[other], named=False)
        assert len(mates) == len(opponents) == SIZES[team]
        for i in range(SIZES[team]):
            own_mates, own_opponents, _ = heard.for_listener(r.start + i)
            assert mates[i] == own_mates and opponents[i] == own_opponents
        listeners, speakers, texts = mates.pairs()
        assert listeners.dtype == speakers.dtype == np.int64
        reference = heard_pairs(tuple(mates))  # the general path, over plain tuples
        assert np.array_equal(listeners, reference[0]) and np.array_equal(speakers, reference[1])
        assert texts == reference[2]
    assert heard.heard.any()


def test_a_log_behaves_as_the_tuple_it_stands_for():
    heard = np.array([[False, True, True], [False, False, False], [True, False, False]])
    log = HeardLog(heard, ("a", "b", "c"), named=True)
    expected = (((1, "b"), (2, "c")), (), ((0, "a"),))
    assert log == expected and tuple(log) == expected and list(log) == list(expected)
    assert log[0] == expected[0] and log[-1] == expected[-1] and log[1:] == expected[1:]
    assert log != ((),) * 3 and log == HeardLog(heard.copy(), ("a", "b", "c"), named=True)
    assert HeardLog(heard, ("a", "b", "c"), named=False) == (("b", "c"), (), ("a",))
    assert "HeardLog" in repr(log)


def test_deliver_draws_and_delivers_as_hear_does():
    players = sum(SIZES)
    positions = np.random.default_rng(1).uniform(-20.0, 20.0, (players, 2))
    words = [f"w{p}" for p in range(players)]
    channels = [AudioChannel(SIZES) for _ in range(2)]
    for channel in channels:
        channel.say(0, [words[:SIZES[0]], words[SIZES[0]:]], positions)
    full = channels[0].hear(1, np.random.default_rng(7))
    arrived, heard, messages = channels[1].deliver(1, np.random.default_rng(7))
    assert np.array_equal(full.heard, heard) and np.array_equal(full.arrived, arrived)
    assert full.messages == messages and heard.any()


def test_checked_messages_are_not_checked_again_but_unchecked_ones_are():
    channel = AudioChannel((1, 1))
    positions = np.zeros((2, 2))
    with pytest.raises(Exception, match="more than say_msg_size"):
        channel.say(0, [["x" * 11], [None]], positions)
    channel.say(1, [["x" * 11], [None]], positions, checked=True)  # the caller vouched for it
    assert channel.hear(2, np.random.default_rng(0)).messages[0] == "x" * 11
