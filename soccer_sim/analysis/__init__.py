"""What the players did, derived from the play (PASS and SHOT events): :mod:`soccer_sim.analysis.plays`."""

from soccer_sim.analysis.plays import PlayAnalysis

__all__ = ["PlayAnalysis"]
