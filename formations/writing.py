"""Writing formations in the package's JSON layout (read back by :mod:`formations.files`).

The layout's names and version live here, with the writer, so that :class:`Formation` and
:class:`FormationSet` can save themselves without importing the reader (which builds them).
This module takes the objects it writes by their attributes and imports neither class.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import TYPE_CHECKING, Any

from formations.roles import Role

if TYPE_CHECKING:
    from formations.formation import Formation
    from formations.formation_set import FormationSet

FORMAT_FORMATION = "soccer-sim-formation"
"""Value of ``format`` in a single-formation file."""
FORMAT_SET = "soccer-sim-formation-set"
"""Value of ``format`` in a formation-set file."""
FORMAT_VERSION = 1
"""Layout version written here and the only one :func:`formations.files.load` reads."""


def formation_to_dict(formation: Formation, *, header: bool = True) -> dict[str, Any]:
    """The JSON object of *formation* in our layout (``header`` adds format/version)."""
    document: dict[str, Any] = {}
    if header:
        document.update(format=FORMAT_FORMATION, version=FORMAT_VERSION)
    document["name"] = formation.name
    document["description"] = formation.description
    document["roles"] = [_role_to_dict(role) for role in formation.roles]
    numbers = [str(role.number) for role in formation.roles]
    document["samples"] = [
        {
            "ball": [float(ball[0]), float(ball[1])],
            "positions": {n: [float(p[0]), float(p[1])] for n, p in zip(numbers, positions)},
        }
        for ball, positions in zip(formation.balls, formation.sample_positions)
    ]
    return document


def formation_set_to_dict(formation_set: FormationSet) -> dict[str, Any]:
    """The JSON object of *formation_set* in our set layout."""
    return {
        "format": FORMAT_SET,
        "version": FORMAT_VERSION,
        "name": formation_set.name,
        "description": formation_set.description,
        "formations": {
            situation.value: formation_to_dict(formation, header=False)
            for situation, formation in formation_set.own_formations().items()
        },
    }


def document_text(document: dict[str, Any]) -> str:
    """JSON text of a layout object: readable, one sample or role per line, floats round-trip exactly."""
    return _format(document, 0) + "\n"


def write_document(document: dict[str, Any], path: str | os.PathLike[str]) -> None:
    """Write a layout object to *path* as :func:`document_text`, UTF-8."""
    Path(path).write_text(document_text(document), encoding="utf-8")


def _role_to_dict(role: Role) -> dict[str, Any]:
    entry: dict[str, Any] = {"number": role.number, "name": role.name, "kind": role.kind}
    if role.partner is not None:
        entry["partner"] = role.partner
    return entry


def _format(value: Any, depth: int) -> str:
    """Indent containers down to samples and roles, which stay on one line each."""
    pad = "  " * (depth + 1)
    if isinstance(value, dict) and not ({"ball", "positions"} <= value.keys() or "number" in value):
        if not value:
            return "{}"
        items = [f"{pad}{json.dumps(k)}: {_format(v, depth + 1)}" for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + "  " * depth + "}"
    if isinstance(value, list) and value and isinstance(value[0], dict):
        items = [pad + _format(v, depth + 1) for v in value]
        return "[\n" + ",\n".join(items) + "\n" + "  " * depth + "]"
    return json.dumps(value, allow_nan=False)
