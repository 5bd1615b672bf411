"""Replays in rerun: record a match (:class:`RerunRecorder`), read a recording back
(:func:`read_replay`), draw a picture of it (:func:`draw_replay`)."""

from soccer_sim.replay.reader import Replay, read_blueprint, read_replay
from soccer_sim.replay.recorder import ReplayError, RerunRecorder, describe_event

__all__ = ["Replay", "ReplayError", "RerunRecorder", "describe_event", "read_blueprint", "read_replay"]
