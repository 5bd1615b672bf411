"""Events as text: one line of an event log per event, for replays and the environment alike."""

from __future__ import annotations

import math

from soccer_sim.state import EventKind, PlayMode

_EVENT_NAMES = {EventKind.KICK: "kick", EventKind.PASS: "pass", EventKind.SHOT: "shot", EventKind.GOAL: "GOAL",
                EventKind.CATCH: "catch", EventKind.OUT: "ball out", EventKind.SET_PLAY: "set play",
                EventKind.OFFSIDE: "offside", EventKind.DROP_BALL: "dropped ball", EventKind.HALF_TIME: "half time",
                EventKind.TIME_OVER: "time over", EventKind.TOUCH: "touch", EventKind.BACK_PASS: "back-pass",
                EventKind.TACKLE: "tackle", EventKind.FOUL: "foul", EventKind.YELLOW_CARD: "yellow card",
                EventKind.RED_CARD: "red card", EventKind.CATCH_FAULT: "catch fault"}


def describe_event(names: tuple[str, str], kind: int, team: int, player: int, x: float, y: float,
                   detail: int) -> str:
    """One event as a line of the event log, e.g. ``"GOAL mmdr #9 at (50.1, 3.2)"``."""
    text = _EVENT_NAMES.get(EventKind(kind), f"event {kind}")
    if kind == EventKind.SET_PLAY:
        text = f"{PlayMode(detail).name.lower().replace('_', ' ')}"
    if team in (0, 1):
        text += f" {names[team]}"
        if player >= 0:
            text += f" #{player + 1}"
        if kind == EventKind.PASS and detail >= 0:
            text += f" to #{detail + 1}"
    if math.isfinite(x) and math.isfinite(y):
        text += f" at ({x:.1f}, {y:.1f})"
    return text
