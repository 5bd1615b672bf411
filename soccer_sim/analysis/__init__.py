"""What the players did, derived from the play, in one place for statistics, replays and the
environment alike: PASS and SHOT events (:mod:`soccer_sim.analysis.plays`), how shots end
(:mod:`soccer_sim.analysis.shots`), possession
(:mod:`soccer_sim.analysis.possession`) and events as text (:mod:`soccer_sim.analysis.events`)."""

from soccer_sim.analysis.events import describe_event
from soccer_sim.analysis.plays import PlayAnalysis
from soccer_sim.analysis.possession import Possession
from soccer_sim.analysis.shots import shot_endings

__all__ = ["PlayAnalysis", "Possession", "describe_event", "shot_endings"]
