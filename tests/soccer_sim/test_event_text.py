"""Events as lines of text (``soccer_sim.analysis.events.describe_event``), shared by replays
and the environment."""

from __future__ import annotations

import math

import numpy as np

from soccer_sim.analysis.events import describe_event
from soccer_sim.state import EventKind, PlayMode

NAMES = ("red", "blue")


def test_every_event_kind_has_a_line_in_the_log() -> None:
    for kind in EventKind:
        text = describe_event(NAMES, int(kind), 0, 3, 1.0, 2.0, 0)
        assert not text.startswith("event ") and "red #4" in text
    assert describe_event(NAMES, int(EventKind.OFFSIDE), 1, 8, 10.0, 0.0, -1).startswith("offside blue #9")
    assert describe_event(NAMES, int(EventKind.GOAL), 0, 8, 52.6, 0.0, -1).startswith("GOAL red #9")


def test_passes_name_the_receiver_and_set_plays_their_mode() -> None:
    assert describe_event(NAMES, int(EventKind.PASS), 1, 2, 3.0, -4.0, 6) == "pass blue #3 to #7 at (3.0, -4.0)"
    assert describe_event(NAMES, int(EventKind.SET_PLAY), 0, -1, 0.0, 0.0, int(PlayMode.CORNER_KICK)) \
        == f"{PlayMode.CORNER_KICK.name.lower().replace('_', ' ')} red at (0.0, 0.0)"


def test_events_without_a_team_or_a_spot_leave_them_out() -> None:
    assert describe_event(NAMES, int(EventKind.TIME_OVER), -1, -1, math.nan, math.nan, 0) == "time over"
    # the event log's own array elements (numpy scalars), as the environment passes them
    assert describe_event(NAMES, np.int8(EventKind.KICK), np.int8(0), np.int16(4), np.float64(1.25),
                          np.float64(np.inf), np.int16(0)) == "kick red #5"
