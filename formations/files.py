"""Reading and writing formations as JSON.

The package's own layout (documented in ``docs/formations.md``) is one JSON
object, either a single formation::

    {"format": "soccer-sim-formation", "version": 1,
     "name": "...", "description": "...",
     "roles": [{"number": 1, "name": "goalkeeper", "kind": "goalkeeper"},
               {"number": 2, "name": "right back", "kind": "defender", "partner": 3}, ...],
     "samples": [{"ball": [x, y], "positions": {"1": [x, y], "2": [x, y], ...}}, ...]}

or a formation set, whose ``formations`` maps situation names to objects with
the same ``name``/``description``/``roles``/``samples`` members::

    {"format": "soccer-sim-formation-set", "version": 1, "name": "4-3-3",
     "description": "...", "formations": {"normal": {...}, "attack": {...}, ...}}

Coordinates are metres in the team-relative frame (:mod:`formations.field`).
:func:`load` also reads helios-base / agent2d formation files, in their JSON
layout (:mod:`formations.helios`) or agent2d's text layouts
(:mod:`formations.helios_text`). Every problem is reported as a
:class:`~formations.errors.FormationError` naming the file and the sample,
role or formation at fault; a missing or unreadable file raises ``OSError``.
The writer (and the layout's names and version) is :mod:`formations.writing`;
:func:`dumps` and :func:`save` here take either a formation or a set.
"""

from __future__ import annotations

import json
import math
import os
from pathlib import Path
from typing import Any

import numpy as np

from formations.errors import FormationError
from formations.field import FieldDimensions
from formations.formation import Formation
from formations.formation_set import FormationSet
from formations.helios import formation_from_helios, is_helios_layout
from formations.helios_text import formation_from_helios_text
from formations.input_files import MiB, read_input
from formations.roles import Role, check_roles
from formations.validation import check_role_count
from formations.writing import (
    FORMAT_FORMATION,
    FORMAT_SET,
    FORMAT_VERSION,
    document_text,
    formation_set_to_dict,
    formation_to_dict,
)

_FORMATION_KEYS = {"format", "version", "name", "description", "roles", "samples"}
_SET_KEYS = {"format", "version", "name", "description", "formations"}
_ROLE_KEYS = {"number", "name", "kind", "partner"}
_SAMPLE_KEYS = {"ball", "positions"}


# ----------------------------------------------------------------- reading
FORMATION_FILE_LIMIT = 16 * MiB
"""The largest formation file read (an agent2d file of a few hundred samples is about 100 KiB):
a device or a runaway file is refused instead of filling memory."""


def read_text(path: str | os.PathLike[str]) -> str:
    """The text of the file at *path*; FormationError (naming the file) if it is not UTF-8 text,
    OSError if it is not a regular file of at most :data:`FORMATION_FILE_LIMIT` bytes
    (:mod:`formations.input_files`)."""
    data = read_input(path, limit=FORMATION_FILE_LIMIT, what="a formation file")
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError as error:
        raise FormationError(str(path), f"not a text file (byte {error.start} is not UTF-8)") from None


def parse_json(text: str, source: str) -> Any:
    """Parse JSON *text* read from *source*; FormationError (naming it) if it is not JSON."""
    try:
        return json.loads(text)
    except json.JSONDecodeError as error:
        raise FormationError(
            source, f"invalid JSON: {error.msg} (line {error.lineno}, column {error.colno})"
        ) from None


def read_json(path: str | os.PathLike[str]) -> Any:
    """Parse the JSON file at *path*; FormationError (naming the file) if it is not JSON."""
    return parse_json(read_text(path), str(path))


def looks_like_json(text: str) -> bool:
    """True if *text* is empty or starts (after white space) like a JSON object or list."""
    stripped = text.lstrip()
    return not stripped or stripped[0] in "{["


def read_any(path: str | os.PathLike[str], *, field: FieldDimensions) -> Formation | FormationSet:
    """Read a formation or a formation set for *field* from *path*.

    *field* is the field the formation is played on (the simulator's ``FieldConfig``):
    every position must lie within :data:`~formations.field.FAR_OUTSIDE_MARGIN` of its lines,
    and helios layouts take their static samples and unnamed roles' kinds from it.

    The layout is recognised by the content, whatever the file is called: our
    JSON layouts, helios-base's JSON layout, or agent2d's text layouts
    (``Formation DelaunayTriangulation 2``, ``Formation Static``, ...; see
    :mod:`formations.helios_text`).
    """
    source = str(path)
    text = read_text(path)
    if not looks_like_json(text):
        return formation_from_helios_text(text, source, field=field, name=Path(path).stem)
    document = parse_json(text, source)
    if not isinstance(document, dict):
        raise FormationError(source, f"expected a JSON object at the top level, got {_json_type(document)}")
    if is_helios_layout(document):
        return formation_from_helios(document, source, field=field, name=Path(path).stem)
    layout = document.get("format")
    if layout == FORMAT_FORMATION:
        return formation_from_dict(document, source, field)
    if layout == FORMAT_SET:
        return formation_set_from_dict(document, source, field)
    raise FormationError(
        source,
        f"unknown layout: 'format' is {layout!r}, expected {FORMAT_FORMATION!r} or {FORMAT_SET!r} "
        "(or a helios-base file with 'method': 'DelaunayTriangulation')",
    )


def load_helios(path: str | os.PathLike[str], *, field: FieldDimensions) -> Formation:
    """Read a helios-base / agent2d formation for *field* (as :func:`read_any`) from *path*: their
    JSON layout or agent2d's text layouts; FormationError for anything else (our own layouts
    included)."""
    source = str(path)
    text = read_text(path)
    if not looks_like_json(text):
        return formation_from_helios_text(text, source, field=field, name=Path(path).stem)
    document = parse_json(text, source)
    if not isinstance(document, dict) or not is_helios_layout(document):
        raise FormationError(
            source,
            "not a helios-base formation: neither a JSON file with a 'method' field nor an agent2d text "
            "file starting 'Formation DelaunayTriangulation' or 'Formation Static'",
        )
    return formation_from_helios(document, source, field=field, name=Path(path).stem)


def load(path: str | os.PathLike[str], *, field: FieldDimensions) -> Formation:
    """Read one formation for *field* (as :func:`read_any`) from *path*, in our JSON layout or
    helios-base's."""
    result = read_any(path, field=field)
    if isinstance(result, FormationSet):
        raise FormationError(str(path), "this file holds a formation set; read it with formations.load_set")
    return result


def load_set(path: str | os.PathLike[str], *, field: FieldDimensions) -> FormationSet:
    """Read a formation set for *field* (as :func:`read_any`) from *path* (our set layout)."""
    result = read_any(path, field=field)
    if not isinstance(result, FormationSet):
        raise FormationError(str(path), "this file holds a single formation, not a formation set")
    return result


def load_packaged_set(path: str | os.PathLike[str]) -> FormationSet:
    """Read a formation set shipped with this package (our set layout) from *path*. Its
    positions are not checked against a field here: the package's tests check the built-in
    sets against the simulator's field, the one they are designed for."""
    source = str(path)
    document = parse_json(read_text(path), source)
    if not isinstance(document, dict) or document.get("format") != FORMAT_SET:
        raise FormationError(source, f"not a formation set ('format' must be {FORMAT_SET!r})")
    return formation_set_from_dict(document, source, None)


def formation_from_dict(document: dict[str, Any], source: str, field: FieldDimensions | None) -> Formation:
    """Build a :class:`Formation` for *field* (None: positions not checked against a field) from
    the parsed JSON object of our layout."""
    _check_version(document, source)
    _reject_unknown_keys(document, _FORMATION_KEYS, source, None)
    name = _optional_string(document, "name", source)
    description = _optional_string(document, "description", source)
    roles = _parse_roles(_require(document, "roles", list, source, None), source)
    check_roles(roles, source)  # before the samples, which refer to the roles
    check_role_count(roles, source)
    balls, positions = _parse_samples(_require(document, "samples", list, source, None), roles, source)
    return Formation(roles, balls, positions, name=name, description=description, source=source, field=field)


def formation_set_from_dict(document: dict[str, Any], source: str, field: FieldDimensions | None) -> FormationSet:
    """Build a :class:`FormationSet` for *field* (as :func:`formation_from_dict`) from the parsed
    JSON object of our set layout."""
    _check_version(document, source)
    _reject_unknown_keys(document, _SET_KEYS, source, None)
    name = _optional_string(document, "name", source)
    description = _optional_string(document, "description", source)
    members = _require(document, "formations", dict, source, None)
    formations: dict[str, Formation] = {}
    for situation, member in members.items():
        where = f"formation {situation!r}"
        if not isinstance(member, dict):
            raise FormationError(source, f"expected an object, got {_json_type(member)}", where)
        try:
            formations[situation] = formation_from_dict(member, source, field)
        except FormationError as error:
            raise error.within(where) from None
    return FormationSet(name, formations, description=description, source=source)


def _parse_roles(items: list[Any], source: str) -> list[Role]:
    roles = []
    for i, item in enumerate(items):
        where = f"role entry {i}"
        if not isinstance(item, dict):
            raise FormationError(source, f"expected an object, got {_json_type(item)}", where)
        number = item.get("number")
        if isinstance(number, int) and not isinstance(number, bool):
            where = f"role {number}"
        _reject_unknown_keys(item, _ROLE_KEYS, source, where)
        number = _require(item, "number", int, source, where)
        name = _require(item, "name", str, source, where)
        kind = _require(item, "kind", str, source, where)
        partner = item.get("partner")
        if partner is not None and (not isinstance(partner, int) or isinstance(partner, bool)):
            raise FormationError(source, f"'partner' must be a role number or null, got {partner!r}", where)
        roles.append(Role(number, name, kind, partner))
    return roles


def _parse_samples(items: list[Any], roles: list[Role], source: str) -> tuple[np.ndarray, np.ndarray]:
    numbers = [role.number for role in roles]
    keys = {str(n): j for j, n in enumerate(numbers)}
    balls = np.empty((len(items), 2))
    positions = np.empty((len(items), len(roles), 2))
    for i, item in enumerate(items):
        where = f"sample {i}"
        if not isinstance(item, dict):
            raise FormationError(source, f"expected an object, got {_json_type(item)}", where)
        _reject_unknown_keys(item, _SAMPLE_KEYS, source, where)
        balls[i] = _parse_point(_require(item, "ball", object, source, where), source, f"{where}, ball")
        given = _require(item, "positions", dict, source, where)
        for key in given:
            if key not in keys:
                raise FormationError(source, f"role {key} is not one of the declared roles {numbers}", where)
        for key, j in keys.items():
            if key not in given:
                raise FormationError(source, f"missing the position of role {key}", where)
            positions[i, j] = _parse_point(given[key], source, f"{where}, role {key}")
    return balls, positions


def _parse_point(value: Any, source: str, where: str) -> tuple[float, float]:
    if not isinstance(value, list) or len(value) != 2:
        raise FormationError(source, f"a position must be a list [x, y] of two numbers, got {value!r}", where)
    return _number(value[0], source, where), _number(value[1], source, where)


def _number(value: Any, source: str, where: str) -> float:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise FormationError(source, f"coordinate {value!r} is not a number", where)
    number = float(value)
    if not math.isfinite(number):
        raise FormationError(source, f"coordinate {value!r} is not a finite number", where)
    return number


# ----------------------------------------------------------------- writing
def dumps(item: Formation | FormationSet) -> str:
    """JSON text of a formation or set: readable, one sample per line, floats round-trip exactly."""
    if isinstance(item, FormationSet):
        document = formation_set_to_dict(item)
    elif isinstance(item, Formation):
        document = formation_to_dict(item)
    else:
        raise TypeError(f"expected a Formation or FormationSet, got {type(item).__name__}")
    return document_text(document)


def save(item: Formation | FormationSet, path: str | os.PathLike[str]) -> None:
    """Write a formation or a formation set to *path* in our JSON layout."""
    Path(path).write_text(dumps(item), encoding="utf-8")


# ----------------------------------------------------------------- helpers
def _check_version(document: dict[str, Any], source: str) -> None:
    version = document.get("version", FORMAT_VERSION)
    if version != FORMAT_VERSION:
        raise FormationError(source, f"unsupported layout version {version!r} (this library reads {FORMAT_VERSION})")


def _reject_unknown_keys(item: dict[str, Any], allowed: set[str], source: str, where: str | None) -> None:
    unknown = sorted(set(item) - allowed)
    if unknown:
        raise FormationError(
            source, f"unknown field(s) {', '.join(map(repr, unknown))} (allowed: {', '.join(sorted(allowed))})", where
        )


def _require(item: dict[str, Any], key: str, kind: type, source: str, where: str | None) -> Any:
    if key not in item:
        raise FormationError(source, f"missing field {key!r}", where)
    value = item[key]
    if kind is object:
        return value
    if not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
        raise FormationError(source, f"field {key!r} must be {_TYPE_NAMES[kind]}, got {_json_type(value)}", where)
    return value


def _optional_string(item: dict[str, Any], key: str, source: str) -> str:
    value = item.get(key, "")
    if not isinstance(value, str):
        raise FormationError(source, f"field {key!r} must be a string, got {_json_type(value)}")
    return value


_TYPE_NAMES = {int: "an integer", str: "a string", list: "a list", dict: "an object", float: "a number"}


def _json_type(value: Any) -> str:
    if value is None:
        return "null"
    if isinstance(value, bool):
        return "a boolean"
    if isinstance(value, (int, float)):
        return f"the number {value!r}"
    if isinstance(value, str):
        return f"the string {value!r}"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "an object"
    return type(value).__name__
