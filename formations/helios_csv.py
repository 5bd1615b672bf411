"""Import of helios-base's comma-separated formation layout.

Between agent2d's text layouts and today's JSON, helios-base (librcsc's
editor) wrote its ``formations-dt/*.conf`` files as comma-separated rows, each
starting with its label::

    # 20211204-145906                      (optional comments, '#')
    Method,DelaunayTriangulation
    RoleNumber,1,2,...,11
    RoleName,Goalie,CenterBack,...
    RoleType,G,DF,...                      G, DF, MF or FW (Unknown: kind from the name)
    SymmetryNumber,0,-1,2,...              agent2d's pairs (see formations.helios_roles)
    Marker,0,0,...                         (ignored)
    SetplayMarker,0,0,...                  (ignored)
    SampleData
    Size,115
    idx,ballX,ballY,1X,1Y,...,11X,11Y     (column titles)
    0,54.5,-36,-50,0,...                   one row per sample: index, ball x y, x y of players 1..11

and a static formation (``before-kick-off.conf``) as::

    Method,Static
    RoleNumber,1,2,...,11
    RoleName,Goalie,...
    Position,-49,0,-25,-5,...              x y of players 1..11

Rows are parsed into the same :class:`~formations.helios_lines.ParsedLayout` as
the text layouts, so conversion and error locations are shared; every
problem names the file and the line.
"""

from __future__ import annotations

import numpy as np

from formations.helios_lines import (
    ALL_ROLES,
    DT_METHOD,
    STATIC_METHOD,
    Line,
    LineReader,
    ParsedLayout,
    sample_field,
    symmetry_number,
)
from formations.helios_roles import HELIOS_KINDS, ROLE_COUNT

UNKNOWN_TYPE = "Unknown"
"""Role type librcsc writes when it has none; the kind then comes from the role's name."""


def parse_csv(reader: LineReader, header: Line) -> tuple[ParsedLayout, str]:
    """Parse the rows after *header* (``Method,...``); returns what they say and the layout's name."""
    method = _values(reader, header, "Method", 1)[0]
    if method not in (DT_METHOD, STATIC_METHOD):
        raise reader.error(
            header, f"formation method {method!r} is not supported: only {DT_METHOD} and {STATIC_METHOD} "
            "formations are samples of positions per ball position"
        )
    parsed = ParsedLayout()
    numbers, cells = _next_row(reader, "RoleNumber", ROLE_COUNT)
    found = [reader.integer(numbers, token, "role number") for token in cells]
    if found != list(ALL_ROLES):
        raise reader.error(numbers, f"RoleNumber must list 1..{ROLE_COUNT} in order, found {found}")
    names, cells = _next_row(reader, "RoleName", ROLE_COUNT)
    for number, name in zip(ALL_ROLES, cells):
        if not name:
            raise reader.error(names, f"role {number} has an empty name")
        parsed.names[number] = name
        parsed.role_lines[number] = names.number
        parsed.pairs[number] = 0
    if method == STATIC_METHOD:
        _parse_static_row(reader, parsed)
    else:
        _parse_dt_rows(reader, parsed)
    line = reader.peek()
    if line is not None:
        raise reader.error(line, f"unexpected line after the {'positions' if parsed.static else 'samples'}: {line.text!r}")
    return parsed, f"helios-base CSV, {method}"


def _cells(line: Line) -> list[str]:
    return [cell.strip() for cell in line.text.split(",")]


def _next_row(reader: LineReader, label: str, count: int) -> tuple[Line, list[str]]:
    """The next line, which must be the row *label*, and its *count* values."""
    line = reader.next(f"the {label} row")
    return line, _values(reader, line, label, count)


def _values(reader: LineReader, line: Line, label: str, count: int) -> list[str]:
    """The *count* values of row *label* on *line*."""
    cells = _cells(line)
    if cells[0] != label:
        raise reader.error(line, f"expected the {label} row ('{label},...'), found {line.text[:60]!r}")
    if len(cells) - 1 != count:
        raise reader.error(line, f"the {label} row holds {count} value(s), found {len(cells) - 1}")
    return cells[1:]


def _parse_static_row(reader: LineReader, parsed: ParsedLayout) -> None:
    line, cells = _next_row(reader, "Position", 2 * ROLE_COUNT)
    values = [reader.number(line, token, f"{'xy'[i % 2]} of player {i // 2 + 1}") for i, token in enumerate(cells)]
    for number in ALL_ROLES:
        parsed.role_lines[number] = line.number  # position errors point at this row
    parsed.hold_static(np.array(values).reshape(ROLE_COUNT, 2), line.number)


def _parse_dt_rows(reader: LineReader, parsed: ParsedLayout) -> None:
    types, cells = _next_row(reader, "RoleType", ROLE_COUNT)
    for number, role_type in zip(ALL_ROLES, cells):
        if role_type in HELIOS_KINDS:
            parsed.types[number] = HELIOS_KINDS[role_type]
        elif role_type != UNKNOWN_TYPE:
            raise reader.error(
                types, f"role type {role_type!r} of role {number} is not one of {', '.join(HELIOS_KINDS)} or {UNKNOWN_TYPE}"
            )
    pairs, cells = _next_row(reader, "SymmetryNumber", ROLE_COUNT)
    for number, token in zip(ALL_ROLES, cells):
        parsed.pairs[number] = symmetry_number(reader, pairs, token, number)
        parsed.role_lines[number] = pairs.number  # pair errors point at this row
    _next_row(reader, "Marker", ROLE_COUNT)
    _next_row(reader, "SetplayMarker", ROLE_COUNT)
    tag = reader.next("the SampleData row")
    if _cells(tag) != ["SampleData"]:
        raise reader.error(tag, f"expected 'SampleData', found {tag.text[:60]!r}")
    size_line, cells = _next_row(reader, "Size", 1)
    count = reader.integer(size_line, cells[0], "number of samples")
    if count <= 0:
        raise reader.error(size_line, f"the number of samples must be positive, got {count}")
    titles = reader.next("the column titles (idx,ballX,ballY,...)")
    if _cells(titles)[0] != "idx":
        raise reader.error(titles, f"expected the column titles 'idx,ballX,ballY,...', found {titles.text[:60]!r}")
    fields = 3 + 2 * ROLE_COUNT
    for k in range(count):
        line = reader.next(f"sample {k} (of the {count} announced on line {size_line.number})")
        cells = _cells(line)
        if len(cells) != fields:
            raise reader.error(
                line, f"sample {k} has {len(cells)} values, expected {fields} (index, ball x y, then x y of players 1..11)"
            )
        index = reader.integer(line, cells[0], "sample index")
        if index != k:
            raise reader.error(line, f"sample index {index}, expected {k} (samples are numbered from 0 in order)")
        values = [reader.number(line, token, sample_field(i, k)) for i, token in enumerate(cells[1:])]
        parsed.balls.append((values[0], values[1]))
        parsed.positions.append(np.array(values[2:]).reshape(ROLE_COUNT, 2))
        parsed.sample_lines.append(line.number)
