"""Reading rcssserver's text log (``.rcl``): which steps each player answered.

The text log holds every command the server received, one line each, stamped with the
server's clock and its stoppage counter: ``57,0<TAB>Recv TEAM_3: (dash 57.71 -121)(done)``
(``0,152`` before kick-off, ``34,12`` in the pause after a goal at 34: the counter tells the
steps apart while the clock stands still), and the referee's calls (``30,0<TAB>(referee
half_time)``). In synchronous mode a player answers a step with ``(done)``; a step of the match
at which a player sent none is a step the server went on without it (it waited 1.25 s).
:func:`missed_steps` counts them per player.
"""

from __future__ import annotations

import re
from pathlib import Path

_RECEIVED = re.compile(r"^(\d+),(\d+)\tRecv (\S+)_(\d+): (.*)$")
"""``T,S<TAB>Recv TEAM_UNUM: COMMANDS`` (a player's datagram; the coach's is ``TEAM_Coach``)."""


def done_steps(rcl: Path) -> tuple[set[tuple[int, int]], dict[tuple[str, int], set[tuple[int, int]]]]:
    """Every step (clock, stoppage counter) after kick-off at which any player sent
    ``(done)``, and per (team, shirt) the steps at which that player did."""
    steps: set[tuple[int, int]] = set()
    players: dict[tuple[str, int], set[tuple[int, int]]] = {}
    with open(rcl, encoding="latin-1") as f:
        for line in f:
            found = _RECEIVED.match(line.rstrip("\n"))
            if found is None or "(done)" not in found.group(5):
                continue
            stamp = (int(found.group(1)), int(found.group(2)))
            if stamp[0] == 0:
                continue  # before kick-off: teams still connecting
            steps.add(stamp)
            players.setdefault((found.group(3), int(found.group(4))), set()).add(stamp)
    return steps, players


def missed_steps(rcl: Path, team: str) -> dict[int, int]:
    """For each player of ``team`` that missed any, shirt number -> the steps of the match
    (after kick-off, up to the team's last answered step) at which it sent no ``(done)``;
    empty when every player answered every step. A player that never answered after kick-off
    misses them all."""
    steps, players = done_steps(rcl)
    ours = {shirt: stamps for (name, shirt), stamps in players.items() if name == team}
    if not ours:
        return {}
    last = max(max(stamps) for stamps in ours.values())
    played = {stamp for stamp in steps if stamp <= last}
    missed = {shirt: len(played - ours.get(shirt, set())) for shirt in range(1, 12)}
    return {shirt: count for shirt, count in missed.items() if count}
