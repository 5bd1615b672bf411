"""Import of agent2d's text formation layouts (the ``formations-dt/*.conf`` files).

agent2d-based teams (helios-base and the teams built on it) ship their
formations as text, recognised by the first line (blank lines and lines
starting with ``#`` or ``//`` are skipped everywhere)::

    Formation DelaunayTriangulation 2
    Begin Roles
    1 Goalie 0                   number, name, symmetry
    2 CenterBack -1
    3 CenterBack 2
    ...
    End Roles
    Begin Samples 2 115          layout version of the samples, sample count
    ----- 0 -----
    Ball 54.5 -36
    1 -50 0                      number, x, y: one line per player 1..11
    ...
    End Samples
    End

Other layouts read here:

* ``Formation DelaunayTriangulation`` (no version, or ``1``): one line of
  eleven ``name symmetry`` pairs, then one line per sample of 24 numbers
  (ball x y, then x y of players 1..11), then ``End``.
* ``Formation DelaunayTriangulation 3``: role lines ``number type name
  symmetry marker setplay_marker`` where the type (G, DF, MF, FW) gives the
  kind; the samples as in version 2.
* ``Formation Static`` (also ``Formation Static 0``, as librcsc's editor
  writes it): one line ``number name x y`` per player; the same positions for
  every ball position (agent2d's ``before-kick-off.conf``). The editor ends
  the file with an empty samples block, ``Begin Samples 2 0`` / ``End
  Samples``, read and dropped here. It becomes a formation whose four samples,
  at the field's corners, all hold those positions
  (:func:`~formations.helios_roles.static_samples`).
* helios-base's comma-separated layout (first line ``Method,...``), read by
  :mod:`formations.helios_csv`.

What the layouts share (reading lines, the parsed layout, the conversion to a
formation) is :mod:`formations.helios_lines`.

A ``Begin Constraints`` block after the samples (edges helios's editor forces
into its triangulation) is skipped: our triangulation is plain Delaunay.

The symmetry number is agent2d's pair: 0 a central role, -1 a side role that
another mirrors, n > 0 the mirror of role n (see :mod:`formations.helios_roles`).
Coordinates are the soccer server's and are converted to ours by negating y,
exactly as for helios's JSON files. Every problem is a
:class:`~formations.errors.FormationError` naming the file and the line.
"""

from __future__ import annotations

import re

import numpy as np

from formations.field import FieldDimensions
from formations.formation import Formation
from formations.helios_csv import parse_csv
from formations.helios_lines import (
    ALL_ROLES,
    DT_METHOD,
    STATIC_METHOD,
    Line,
    LineReader,
    ParsedLayout,
    build_formation,
    content_lines,
    is_integer,
    is_tag,
    sample_field,
    symmetry_number,
)
from formations.helios_roles import HELIOS_KINDS, ROLE_COUNT

DT_VERSIONS = (1, 2, 3)
"""Versions of the ``Formation DelaunayTriangulation`` layout this module reads."""
HEADER_EXAMPLES = "'Formation DelaunayTriangulation 2', 'Formation Static' or 'Method,DelaunayTriangulation'"

_SAMPLE_HEADER = re.compile(r"-+\s*(\S+)\s*-+")

__all__ = [  # the shared pieces stay importable from here
    "DT_METHOD", "DT_VERSIONS", "HEADER_EXAMPLES", "STATIC_METHOD", "Line", "LineReader", "ParsedLayout",
    "build_formation", "formation_from_helios_text", "is_csv_header", "is_helios_text", "sample_field",
    "symmetry_number",
]


def is_helios_text(text: str) -> bool:
    """True if the first meaningful line of *text* is an agent2d ``Formation ...`` or ``Method,...`` header."""
    for line in content_lines(text):
        return line.tokens[0] == "Formation" or is_csv_header(line)
    return False


def is_csv_header(line: Line) -> bool:
    """True for the first line of helios-base's comma-separated layout (``Method,...``)."""
    return line.text.split(",", 1)[0].strip() == "Method" and "," in line.text


def formation_from_helios_text(text: str, source: str, *, field: FieldDimensions, name: str = "") -> Formation:
    """Parse agent2d's text formation *text* (read from *source*) into a :class:`Formation` on
    *field* (the server's pitch the file was written for; its positions are checked against it)."""
    reader = LineReader(text, source)
    header = reader.next("the header line (" + HEADER_EXAMPLES + ")")
    if is_csv_header(header):
        parsed, layout = parse_csv(reader, header)
    else:
        method, version = _parse_header(reader, header)
        if method == STATIC_METHOD:
            parsed = _parse_static(reader)
            layout = "Formation Static"
        else:
            parsed = _parse_dt_v1(reader) if version == 1 else _parse_dt(reader, version)
            layout = f"Formation {DT_METHOD} {version}"
    return build_formation(parsed, source, name, f"imported from agent2d formation {source} ({layout})", field)


# ----------------------------------------------------------------- parsing
def _parse_header(reader: LineReader, line: Line) -> tuple[str, int]:
    tokens = line.tokens
    if tokens[0] != "Formation":
        raise reader.error(
            line, f"unknown layout header {line.text[:60]!r}: expected a JSON formation or an agent2d header "
            f"such as {HEADER_EXAMPLES}"
        )
    if len(tokens) < 2:
        raise reader.error(line, f"the header names no formation method (expected {HEADER_EXAMPLES})")
    if len(tokens) > 3:
        raise reader.error(line, f"unexpected text after the header: {' '.join(tokens[3:])!r}")
    method = tokens[1]
    version = reader.integer(line, tokens[2], "layout version") if len(tokens) == 3 else None
    if method == STATIC_METHOD:
        return method, version or 1
    if method != DT_METHOD:
        raise reader.error(
            line, f"formation method {method!r} is not supported: only {DT_METHOD} and {STATIC_METHOD} "
            "formations are samples of positions per ball position"
        )
    version = 1 if version in (None, 0) else version
    if version not in DT_VERSIONS:
        raise reader.error(line, f"{DT_METHOD} layout version {version} is not supported (versions 1, 2 and 3 are)")
    return method, version


def _parse_dt(reader: LineReader, version: int) -> ParsedLayout:
    parsed = ParsedLayout()
    _parse_roles_block(reader, parsed, version)
    _parse_samples_block(reader, parsed)
    _parse_trailer(reader)
    return parsed


def _parse_roles_block(reader: LineReader, parsed: ParsedLayout, version: int) -> None:
    begin = reader.next("'Begin Roles'")
    if not is_tag(begin, "Begin", "Roles") or len(begin.tokens) != 2:
        raise reader.error(begin, f"expected 'Begin Roles', found {begin.text!r}")
    columns = "number name symmetry" if version == 2 else "number type name symmetry marker setplay_marker"
    while True:
        line = reader.next("a role line or 'End Roles'")
        if is_tag(line, "End", "Roles"):
            break
        if is_tag(line, "Begin", "Samples"):
            raise reader.error(line, f"'End Roles' is missing before 'Begin Samples' (roles begin on line {begin.number})")
        if len(line.tokens) != len(columns.split()):
            raise reader.error(line, f"a role line is '{columns}', found {line.text!r}")
        if version == 2:
            number_token, role_name, pair_token = line.tokens
        else:
            number_token, role_type, role_name, pair_token = line.tokens[:4]
        number = reader.role_number(line, number_token, "role number")
        if number in parsed.names:
            raise reader.error(line, f"role {number} is declared twice (first on line {parsed.role_lines[number]})")
        if version == 3:
            if role_type not in HELIOS_KINDS:
                raise reader.error(line, f"role type {role_type!r} of role {number} is not one of {', '.join(HELIOS_KINDS)}")
            parsed.types[number] = HELIOS_KINDS[role_type]
        parsed.pairs[number] = symmetry_number(reader, line, pair_token, number)
        parsed.names[number] = role_name
        parsed.role_lines[number] = line.number
    missing = sorted(set(ALL_ROLES) - set(parsed.names))
    if missing:
        raise reader.error(line, f"roles {missing} are missing (an agent2d formation declares roles 1..{ROLE_COUNT})")

def _samples_header(reader: LineReader) -> tuple[Line, int]:
    """Read 'Begin Samples 2 N': the line and N."""
    begin = reader.next("'Begin Samples 2 N'")
    if not is_tag(begin, "Begin", "Samples") or len(begin.tokens) != 4:
        raise reader.error(begin, f"expected 'Begin Samples 2 N' (N the number of samples), found {begin.text!r}")
    sample_version = reader.integer(begin, begin.tokens[2], "sample layout version")
    if sample_version != 2:
        raise reader.error(begin, f"sample layout version {sample_version} is not supported (version 2 is)")
    count = reader.integer(begin, begin.tokens[3], "number of samples")
    if count < 0:
        raise reader.error(begin, f"the number of samples must not be negative, got {count}")
    return begin, count


def _parse_samples_block(reader: LineReader, parsed: ParsedLayout) -> None:
    begin, count = _samples_header(reader)
    for k in range(count):
        line = reader.next(f"'----- {k} -----' (sample {k} of the {count} announced on line {begin.number})")
        if is_tag(line, "End", "Samples"):
            raise reader.error(line, f"only {k} samples precede 'End Samples', but line {begin.number} announces {count}")
        _parse_sample(reader, parsed, line, k)
    after = reader.peek()
    if after is not None and _SAMPLE_HEADER.fullmatch(after.text):
        raise reader.error(after, f"more samples than the {count} announced on line {begin.number}")
    if is_tag(after, "End", "Samples"):
        reader.next("'End Samples'")


def _parse_sample(reader: LineReader, parsed: ParsedLayout, header: Line, k: int) -> None:
    match = _SAMPLE_HEADER.fullmatch(header.text)
    if match is None:
        raise reader.error(header, f"expected the sample header '----- {k} -----', found {header.text!r}")
    index = reader.integer(header, match.group(1), "sample index")
    if index != k:
        raise reader.error(header, f"sample header says {index}, expected {k} (samples are numbered from 0 in order)")
    ball = reader.next(f"the 'Ball x y' line of sample {k}")
    if ball.tokens[0] != "Ball" or len(ball.tokens) != 3:
        raise reader.error(ball, f"expected 'Ball x y' for sample {k}, found {ball.text!r}")
    bx = reader.number(ball, ball.tokens[1], f"ball x of sample {k}")
    by = reader.number(ball, ball.tokens[2], f"ball y of sample {k}")
    positions = np.full((ROLE_COUNT, 2), np.nan)
    seen: dict[int, int] = {}
    while (line := reader.peek()) is not None and is_integer(line.tokens[0]):
        reader.next("a player line")
        if len(line.tokens) != 3:
            raise reader.error(line, f"a player line is 'number x y', found {line.text!r} (sample {k})")
        number = reader.role_number(line, line.tokens[0], "player number")
        if number in seen:
            raise reader.error(line, f"player {number} is given twice in sample {k} (also on line {seen[number]})")
        seen[number] = line.number
        positions[number - 1] = (
            reader.number(line, line.tokens[1], f"x of player {number} in sample {k}"),
            reader.number(line, line.tokens[2], f"y of player {number} in sample {k}"),
        )
    missing = sorted(set(ALL_ROLES) - set(seen))
    if missing:
        found = f"found {line.text!r}" if line is not None else "the file ends"
        raise reader.error(
            line, f"sample {k} (line {header.number}) has no position for player(s) {missing}: {found} instead"
        )
    parsed.balls.append((bx, by))
    parsed.positions.append(positions)
    parsed.sample_lines.append(header.number)


def _parse_trailer(reader: LineReader) -> None:
    """Skip an optional constraints block and the closing 'End'; nothing may follow."""
    line = reader.peek()
    if is_tag(line, "Begin", "Constraints"):
        reader.next("'Begin Constraints'")
        while not is_tag(reader.next(f"'End Constraints' (constraints begin on line {line.number})"), "End", "Constraints"):
            pass
        line = reader.peek()
    if line is not None and line.tokens == ["End"]:
        reader.next("'End'")
        line = reader.peek()
    if line is not None:
        raise reader.error(line, f"unexpected line after the samples: {line.text!r}")


def _parse_dt_v1(reader: LineReader) -> ParsedLayout:
    parsed = ParsedLayout()
    roles = reader.next("the role line (11 'name symmetry' pairs)")
    if len(roles.tokens) != 2 * ROLE_COUNT:
        raise reader.error(roles, f"the role line holds 11 'name symmetry' pairs (22 fields), found {len(roles.tokens)}")
    for number in ALL_ROLES:
        parsed.names[number] = roles.tokens[2 * number - 2]
        parsed.pairs[number] = symmetry_number(reader, roles, roles.tokens[2 * number - 1], number)
        parsed.role_lines[number] = roles.number
    fields = 2 + 2 * ROLE_COUNT
    while (line := reader.peek()) is not None and line.tokens != ["End"]:
        reader.next("a sample line")
        k = len(parsed.balls)
        if len(line.tokens) != fields:
            raise reader.error(
                line, f"sample {k} has {len(line.tokens)} numbers, expected {fields} (ball x y, then x y of players 1..11)"
            )
        values = [reader.number(line, token, sample_field(i, k)) for i, token in enumerate(line.tokens)]
        parsed.balls.append((values[0], values[1]))
        parsed.positions.append(np.array(values[2:]).reshape(ROLE_COUNT, 2))
        parsed.sample_lines.append(line.number)
    if line is not None:
        reader.next("'End'")
        _parse_trailer(reader)
    return parsed

def _parse_static(reader: LineReader) -> ParsedLayout:
    parsed = ParsedLayout()
    positions = np.full((ROLE_COUNT, 2), np.nan)
    while (line := reader.peek()) is not None and line.tokens != ["End"] and not is_tag(line, "Begin", "Samples"):
        reader.next("a player line")
        if len(line.tokens) != 4:
            raise reader.error(line, f"a static formation line is 'number name x y', found {line.text!r}")
        number = reader.role_number(line, line.tokens[0], "player number")
        if number in parsed.names:
            raise reader.error(line, f"player {number} is given twice (also on line {parsed.role_lines[number]})")
        parsed.names[number] = line.tokens[1]
        parsed.pairs[number] = 0
        parsed.role_lines[number] = line.number
        positions[number - 1] = (
            reader.number(line, line.tokens[2], f"x of player {number}"),
            reader.number(line, line.tokens[3], f"y of player {number}"),
        )
    missing = sorted(set(ALL_ROLES) - set(parsed.names))
    if missing:
        raise reader.error(line, f"players {missing} have no position (a static formation lists players 1..{ROLE_COUNT})")
    if is_tag(line, "Begin", "Samples"):
        _skip_empty_samples_block(reader)
    _parse_trailer(reader)
    parsed.hold_static(positions, min(parsed.role_lines.values()))
    return parsed


def _skip_empty_samples_block(reader: LineReader) -> None:
    """Read the empty 'Begin Samples 2 0' / 'End Samples' block librcsc's editor ends a static file with."""
    begin, count = _samples_header(reader)
    if count != 0:
        raise reader.error(
            begin, f"a static formation holds no samples, but this block announces {count} (expected 'Begin Samples 2 0')"
        )
    end = reader.next(f"'End Samples' (the empty samples block begins on line {begin.number})")
    if not is_tag(end, "End", "Samples"):
        raise reader.error(end, f"expected 'End Samples' after the empty samples block of line {begin.number}, found {end.text!r}")
