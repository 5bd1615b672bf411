"""What the players did, derived from the play, in one place for statistics, replays and the
environment alike: PASS and SHOT events (:mod:`soccer_sim.analysis.plays`) and events as text
(:mod:`soccer_sim.analysis.events`)."""

from soccer_sim.analysis.events import describe_event
from soccer_sim.analysis.plays import PlayAnalysis

__all__ = ["PlayAnalysis", "describe_event"]
