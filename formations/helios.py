"""Import of helios-base / agent2d formation files (their JSON layout).

The layout read here (librcsc's JSON formation files)::

    {"version": "...",                      (optional, ignored)
     "method": "DelaunayTriangulation",
     "role": [{"number": 1, "name": "Goalie", "type": "G", "side": "C", "pair": 0}, ...],
     "data": [{"index": 0, "ball": {"x": 0.0, "y": 0.0},
               "1": {"x": -50.0, "y": 0.0}, ..., "11": {"x": ..., "y": ...}}, ...]}

* ``method`` is ``DelaunayTriangulation`` (samples of positions per ball
  position) or ``Static`` (helios-base's ``before-kick-off.conf`` and the
  other fixed line-ups): exactly one sample, whose positions hold whatever
  the ball does; it becomes the four corner samples of
  :func:`~formations.helios_roles.static_samples`.
* ``type`` is G, DF, MF or FW (goalkeeper, defender, midfielder, forward).
  A static formation may say ``Unknown`` (as helios-base's do); the kind then
  comes from the role's name or depth (:func:`~formations.helios_roles.role_kind`).
* ``pair`` says how a role mirrors: 0 a central role, -1 a role that others
  mirror, n > 0 the mirror of role n. ``side`` is optional and not needed.
* Coordinates are those of the RoboCup soccer server for the left team: x
  towards the opponent goal like ours, but y grows to the *right* of a player
  facing that goal (the server's y axis points down the monitor). Our y grows
  to the left, so the importer negates y: a helios left back (y < 0) stays a
  left back (y > 0 here).
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from formations.errors import FormationError
from formations.field import FieldDimensions
from formations.formation import Formation
from formations.helios_roles import (
    HELIOS_KINDS,
    ROLE_COUNT,
    partners_from_pairs,
    role_kind,
    server_to_team_frame,
    static_samples,
)
from formations.roles import Role

HELIOS_METHOD = "DelaunayTriangulation"
"""The helios formation method whose samples mean what ours mean."""

STATIC_METHOD = "Static"
"""helios's fixed line-up: one sample, the same positions for every ball position."""

UNKNOWN_TYPE = "Unknown"
"""Role type helios writes in static formations, which need none."""

HELIOS_ROLE_COUNT = ROLE_COUNT

_ROLE_KEYS = {"number", "name", "type", "side", "pair"}


def is_helios_layout(document: dict[str, Any]) -> bool:
    """True if the parsed JSON object looks like a helios-base formation file."""
    return "method" in document and "format" not in document


def formation_from_helios(document: dict[str, Any], source: str, *, field: FieldDimensions,
                          name: str = "") -> Formation:
    """Convert a parsed helios-base JSON formation into a :class:`Formation` on *field* (the
    server's pitch the file was written for; its positions are checked against it)."""
    method = document.get("method")
    if method not in (HELIOS_METHOD, STATIC_METHOD):
        raise FormationError(
            source, f"helios formation method {method!r} is not supported (only {HELIOS_METHOD!r} and {STATIC_METHOD!r})"
        )
    static = method == STATIC_METHOD
    role_items = document.get("role")
    if not isinstance(role_items, list):
        raise FormationError(source, "missing 'role' list")
    data_items = document.get("data")
    if not isinstance(data_items, list):
        raise FormationError(source, "missing 'data' list")
    entries = _parse_roles(role_items, source, static)
    balls, positions = _parse_data(data_items, source)
    if static:
        if len(balls) != 1:
            raise FormationError(source, f"a static formation holds exactly one sample (its line-up), found {len(balls)}")
        balls, positions = static_samples(positions[0], field)
    server_to_team_frame(balls, positions)
    partners = partners_from_pairs(
        {number: item["pair"] for number, item in entries.items()}, source, lambda number: f"role {number}"
    )
    roles = []
    for n in range(1, HELIOS_ROLE_COUNT + 1):
        given = HELIOS_KINDS.get(entries[n]["type"])
        kind = role_kind(given, entries[n]["name"], float(positions[:, n - 1, 0].mean()), field)
        roles.append(Role(n, entries[n]["name"], kind, partners.get(n)))
    description = f"imported from helios-base formation {source}" + (" (static)" if static else "")
    try:
        return Formation(roles, balls, positions, name=name, description=description, source=source,
                         field=field)
    except FormationError as error:
        if static and error.where:  # the four samples are copies of the file's one sample
            raise FormationError(source, error.problem, re.sub(r"^sample \d+", "sample 0", error.where)) from None
        raise


def _parse_roles(items: list[Any], source: str, static: bool) -> dict[int, dict[str, Any]]:
    """Role number -> its checked entry; ``Unknown`` types are allowed only if *static*."""
    entries: dict[int, dict[str, Any]] = {}
    for i, item in enumerate(items):
        where = f"role entry {i}"
        if not isinstance(item, dict):
            raise FormationError(source, "expected an object", where)
        number = item.get("number")
        if isinstance(number, bool) or not isinstance(number, int) or not 1 <= number <= HELIOS_ROLE_COUNT:
            raise FormationError(source, f"'number' must be an integer 1..{HELIOS_ROLE_COUNT}, got {number!r}", where)
        where = f"role {number}"
        if number in entries:
            raise FormationError(source, "role number is used twice", where)
        unknown = sorted(set(item) - _ROLE_KEYS)
        if unknown:
            raise FormationError(source, f"unknown field(s) {', '.join(map(repr, unknown))}", where)
        if not isinstance(item.get("name"), str) or not item["name"]:
            raise FormationError(source, "'name' must be a non-empty string", where)
        if item.get("type") not in HELIOS_KINDS and not (static and item.get("type") == UNKNOWN_TYPE):
            allowed = ", ".join(HELIOS_KINDS) + (f" or {UNKNOWN_TYPE}" if static else "")
            raise FormationError(source, f"'type' must be one of {allowed}, got {item.get('type')!r}", where)
        pair = item.get("pair")
        if isinstance(pair, bool) or not isinstance(pair, int) or not -1 <= pair <= HELIOS_ROLE_COUNT:
            raise FormationError(source, f"'pair' must be -1, 0 or a role number, got {pair!r}", where)
        entries[number] = item
    missing = sorted(set(range(1, HELIOS_ROLE_COUNT + 1)) - set(entries))
    if missing:
        raise FormationError(source, f"roles {missing} are missing (a helios formation has roles 1..11)")
    return entries


def _parse_data(items: list[Any], source: str) -> tuple[np.ndarray, np.ndarray]:
    keys = [str(n) for n in range(1, HELIOS_ROLE_COUNT + 1)]
    allowed = {"index", "ball", *keys}
    balls = np.empty((len(items), 2))
    positions = np.empty((len(items), HELIOS_ROLE_COUNT, 2))
    for i, item in enumerate(items):
        where = f"sample {i}"
        if not isinstance(item, dict):
            raise FormationError(source, "expected an object", where)
        extra = sorted(set(item) - allowed)
        if extra:
            raise FormationError(source, f"unknown role(s) or field(s) {', '.join(map(repr, extra))}", where)
        if "ball" not in item:
            raise FormationError(source, "missing the ball position", where)
        balls[i] = _point(item["ball"], source, f"{where}, ball")
        for j, key in enumerate(keys):
            if key not in item:
                raise FormationError(source, f"missing the position of role {key}", where)
            positions[i, j] = _point(item[key], source, f"{where}, role {key}")
    return balls, positions


def _point(value: Any, source: str, where: str) -> tuple[float, float]:
    if not isinstance(value, dict) or "x" not in value or "y" not in value:
        raise FormationError(source, f'a position must be an object {{"x": ..., "y": ...}}, got {value!r}', where)
    coords = []
    for axis in ("x", "y"):
        v = value[axis]
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not np.isfinite(v):
            raise FormationError(source, f"{axis} = {v!r} is not a finite number", where)
        coords.append(float(v))
    return coords[0], coords[1]
