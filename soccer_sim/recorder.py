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

from typing import TYPE_CHECKING, Protocol, runtime_checkable

if TYPE_CHECKING:
    from soccer_sim.match import Match


@runtime_checkable
class Recorder(Protocol):
    def on_start(self, match: Match) -> None: ...

    def on_cycle(self, match: Match) -> None: ...

    def on_end(self, match: Match) -> None: ...
