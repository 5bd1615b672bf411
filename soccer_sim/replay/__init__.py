"""Replays in rerun: record a match (:class:`RerunRecorder`), read a recording back
(:func:`read_replay`), draw a picture of it (:func:`draw_replay`). :func:`describe_event` (an event
as a line of text) lives in :mod:`soccer_sim.analysis.events` and is re-exported here."""

from soccer_sim.analysis.events import describe_event
from soccer_sim.replay.reader import Replay, read_blueprint, read_replay
from soccer_sim.replay.recorder import ReplayError, RerunRecorder

__all__ = ["Replay", "ReplayError", "RerunRecorder", "describe_event", "read_blueprint", "read_replay"]
