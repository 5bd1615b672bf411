"""Role labels of helios-base's players, read from one of its formation files.

helios-base plays every shirt number in one role for the whole match, named in its
formation files (``src/formations-dt/normal-formation.conf``, a JSON document whose
``role`` list gives each ``number`` a ``name`` such as ``CenterBack``). ``bench soccer
--rcg`` labels the players of a helios-base game log with those roles, in the vocabulary
of position labels the benchmark reports (:data:`POSITIONS`), so that the distance run by
role can be set beside soccer-sim's.
"""

from __future__ import annotations

import json
import os

from agents.teams.positions import POSITION_KINDS as KINDS

POSITIONS = {
    "Goalie": "goalkeeper",
    "CenterBack": "centre-back",
    "SideBack": "full-back",
    "DefensiveHalf": "holding-midfielder",
    "OffensiveHalf": "central-midfielder",
    "SideHalf": "wide-midfielder",
    "SideForward": "winger",
    "CenterForward": "centre-forward",
}
"""helios-base role name -> position label."""


def helios_labels(path: str | os.PathLike) -> list[str]:
    """The position label of shirt numbers 1..11 in the helios-base formation file ``path``;
    a ValueError naming the file for anything else (a role name missing from :data:`POSITIONS`
    is kept as it is)."""
    path = os.fspath(path)
    try:
        with open(path, encoding="utf-8") as f:
            roles = json.load(f)["role"]
        names = {int(role["number"]): str(role["name"]) for role in roles}
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise ValueError(f"{path}: not a helios-base formation file with a role list ({exc})") from None
    if sorted(names) != list(range(1, 12)):
        raise ValueError(f"{path}: the role list must number the roles 1..11, got {sorted(names)}")
    return [POSITIONS.get(names[number], names[number]) for number in range(1, 12)]
