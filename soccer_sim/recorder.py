"""Observers of the match loop.

A recorder is any object with ``on_start(match)``, ``on_cycle(match)`` and ``on_end(match)``.
The loop calls them and does not know what they do (collect statistics, write a replay,
...). They receive the running :class:`~soccer_sim.match.Match` and may read (never write)
``match.state``, ``match.events``, ``match.config``, ``match.team_names``, ``match.teams``,
``match.teammate_contacts`` and ``match.touchers``/``match.kickers`` (player rows of the
cycle just simulated). ``on_cycle`` is called after each cycle, once ``state.cycle`` has
advanced.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import TYPE_CHECKING, Protocol, runtime_checkable

from soccer_sim.errors import SoccerSimError

if TYPE_CHECKING:
    from soccer_sim.match import Match


@runtime_checkable
class Recorder(Protocol):
    def on_start(self, match: Match) -> None: ...

    def on_cycle(self, match: Match) -> None: ...

    def on_end(self, match: Match) -> None: ...


RECORDER_METHODS = ("on_start", "on_cycle", "on_end")
"""What makes an object a recorder."""


class RecorderError(SoccerSimError, TypeError):
    """``recorders`` is not an iterable of recorders (objects with the three methods)."""


def check_recorders(recorders: object) -> tuple[Recorder, ...]:
    """``recorders`` as a tuple, each one checked before the match starts; RecorderError naming
    the first that is not a recorder (a string, a number or a single recorder not in a list
    for ``recorders`` itself)."""
    if isinstance(recorders, (str, bytes)) or not isinstance(recorders, Iterable):
        hint = "; put a single recorder in a list: recorders=[recorder]" if _lacks(recorders) == [] else ""
        raise RecorderError(f"recorders must be a list or other iterable of recorders, got "
                            f"{type(recorders).__name__}{hint}")
    found = tuple(recorders)
    for index, recorder in enumerate(found):
        missing = _lacks(recorder)
        if missing:
            raise RecorderError(f"recorders[{index}] ({type(recorder).__name__}) is not a recorder: it lacks "
                                f"{', '.join(missing)} (a recorder has {', '.join(RECORDER_METHODS)})")
    return found


def _lacks(candidate: object) -> list[str]:
    """The recorder methods ``candidate`` does not have (or that are not callable)."""
    return [name for name in RECORDER_METHODS if not callable(getattr(candidate, name, None))]
