"""rcssserver game logs (``.rcg``, text version 6) of soccer-sim matches.

:class:`RcgRecorder` writes a match as the RoboCup 2D simulator's game log, so that
RoboCup's own tools (rcssmonitor, soccerwindow2, librcsc's log tools, log analysers) replay
and analyse it; :func:`read_rcg` reads such a log back. See :mod:`soccer_sim.rcg.recorder`
for what is written how.
"""

from soccer_sim.rcg.reader import GameLog, PlayerFrame, Show, read_rcg
from soccer_sim.rcg.recorder import RcgError, RcgRecorder

__all__ = ["GameLog", "PlayerFrame", "RcgError", "RcgRecorder", "Show", "read_rcg"]
