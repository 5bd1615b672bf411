"""How shots end (soccer_sim.analysis.shots): the first ball event after each shot decides."""

from __future__ import annotations

from soccer_sim.analysis.shots import shot_endings
from soccer_sim.state import AWAY, HOME, EventKind, EventLog


def log(*events: tuple[EventKind, int, int]) -> EventLog:
    out = EventLog()
    for cycle, (kind, team, detail) in enumerate(events):
        out.add(cycle, kind, team, 0, 0.0, 0.0, detail)
    return out


def test_the_first_ball_event_after_a_shot_says_how_it_ended():
    events = log((EventKind.KICK, HOME, 0), (EventKind.SHOT, HOME, 0), (EventKind.SET_PLAY, AWAY, 0),
                 (EventKind.TOUCH, AWAY, 0), (EventKind.KICK, AWAY, 0),
                 (EventKind.KICK, AWAY, 0), (EventKind.SHOT, AWAY, 0), (EventKind.CATCH, HOME, 0),
                 (EventKind.KICK, HOME, 0), (EventKind.SHOT, HOME, 0), (EventKind.GOAL, HOME, 0),
                 (EventKind.KICK, AWAY, 0), (EventKind.SHOT, AWAY, 0), (EventKind.OUT, AWAY, 0),
                 (EventKind.KICK, HOME, 0), (EventKind.SHOT, HOME, 0), (EventKind.TACKLE, AWAY, 1),
                 (EventKind.KICK, AWAY, 0), (EventKind.SHOT, AWAY, 0))
    assert shot_endings(events) == [(HOME, "body"), (AWAY, "caught"), (HOME, "goal"), (AWAY, "out"),
                                    (HOME, "played on"), (AWAY, "unfinished")]


def test_shots_recorded_for_a_goal_are_left_out():
    events = log((EventKind.TOUCH, HOME, 0), (EventKind.SHOT, HOME, 1), (EventKind.GOAL, HOME, 0))
    assert shot_endings(events) == []
