"""The root of the simulator's errors.

Every error :mod:`soccer_sim` raises on purpose derives from :class:`SoccerSimError`, so a
caller can catch the whole package's complaints with one ``except``; each also keeps the
built-in base it had (``ValueError`` for bad input, ``LookupError`` for an unknown name), so
existing ``except ValueError`` code keeps working.
"""

from __future__ import annotations


class SoccerSimError(Exception):
    """Something the simulator refuses or could not do (bad configuration, scenario, team,
    replay)."""
