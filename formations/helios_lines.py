"""What agent2d's text layouts and helios-base's comma-separated layout share: the
meaningful lines of a file read one at a time (:class:`LineReader`, whose errors name the
line), what a layout says before conversion (:class:`ParsedLayout`), and the conversion to a
:class:`~formations.formation.Formation` in our frame (:func:`build_formation`).

The parsers of the layouts themselves are :mod:`formations.helios_text` and
:mod:`formations.helios_csv`.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from dataclasses import field as default_of

import numpy as np

from formations.errors import FormationError
from formations.field import FieldDimensions
from formations.formation import Formation
from formations.helios_roles import ROLE_COUNT, partners_from_pairs, role_kind, server_to_team_frame, static_samples
from formations.roles import Role

DT_METHOD = "DelaunayTriangulation"
"""The method name of agent2d's sampled (Delaunay-triangulated) formations."""
STATIC_METHOD = "Static"
"""The method name of agent2d's static formations (one position per player)."""

_NUMBER = re.compile(r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?")
_INTEGER = re.compile(r"[+-]?\d+")
ALL_ROLES = range(1, ROLE_COUNT + 1)
"""agent2d's player numbers, 1..11."""


def is_integer(token: str) -> bool:
    """True if *token* is written as an integer (a player line starts with one)."""
    return _INTEGER.fullmatch(token) is not None


# ----------------------------------------------------------------- lines
@dataclass(frozen=True)
class Line:
    """A meaningful line of a formation file (comments and blank lines are never one)."""

    number: int
    """1-based line number in the file."""
    text: str
    tokens: list[str]


def content_lines(text: str) -> list[Line]:
    lines = []
    for number, raw in enumerate(text.splitlines(), start=1):
        stripped = raw.strip()
        if not stripped or stripped.startswith("#") or stripped.startswith("//"):
            continue
        lines.append(Line(number, stripped, stripped.split()))
    return lines


class LineReader:
    """The meaningful lines of a file, read one at a time; errors name the line."""

    def __init__(self, text: str, source: str) -> None:
        self.source = source
        self.lines = content_lines(text)
        self.last_number = max(len(text.splitlines()), 1)
        self.index = 0

    def peek(self) -> Line | None:
        return self.lines[self.index] if self.index < len(self.lines) else None

    def next(self, expected: str) -> Line:
        line = self.peek()
        if line is None:
            raise FormationError(self.source, f"the file ends where {expected} was expected", f"line {self.last_number}")
        self.index += 1
        return line

    def error(self, line: Line | None, problem: str) -> FormationError:
        number = line.number if line is not None else self.last_number
        return FormationError(self.source, problem, f"line {number}")

    def number(self, line: Line, token: str, what: str) -> float:
        if not _NUMBER.fullmatch(token):
            raise self.error(line, f"{token!r} is not a number ({what})")
        return float(token)

    def integer(self, line: Line, token: str, what: str) -> int:
        if not _INTEGER.fullmatch(token):
            raise self.error(line, f"{token!r} is not an integer ({what})")
        return int(token)

    def role_number(self, line: Line, token: str, what: str) -> int:
        number = self.integer(line, token, what)
        if number not in ALL_ROLES:
            raise self.error(line, f"{what} {number} is out of range (agent2d numbers players 1..{ROLE_COUNT})")
        return number


def is_tag(line: Line | None, *words: str) -> bool:
    return line is not None and line.tokens[: len(words)] == list(words)


@dataclass
class ParsedLayout:
    """What a text layout says, before conversion to our frame and roles.

    *types* holds the kinds a type column gives; roles without one get theirs
    from their names or depth. Coordinates are still the server's.
    """

    names: dict[int, str] = default_of(default_factory=dict)
    pairs: dict[int, int] = default_of(default_factory=dict)
    types: dict[int, str] = default_of(default_factory=dict)
    role_lines: dict[int, int] = default_of(default_factory=dict)
    balls: list[tuple[float, float]] = default_of(default_factory=list)
    positions: list[np.ndarray] = default_of(default_factory=list)
    sample_lines: list[int] = default_of(default_factory=list)
    static: bool = False
    static_positions: np.ndarray | None = None
    """A static formation's one position per role (11, 2), server frame."""
    static_line: int = 0
    """The line a static formation's positions are written on."""

    def hold_static(self, positions: np.ndarray, line: int) -> None:
        """Make this a static formation of *positions* (11, 2); *line* is where they are written.
        Its samples (:func:`~formations.helios_roles.static_samples`) are made when the
        formation is built, on the field it is built for."""
        self.static = True
        self.static_positions = np.asarray(positions, dtype=np.float64)
        self.static_line = line

    def expand_static(self, field: FieldDimensions) -> None:
        """A static formation's samples on *field*: its positions at each of the field's corners."""
        if self.static_positions is None:
            return
        for ball, sample in zip(*static_samples(self.static_positions, field)):
            self.balls.append((float(ball[0]), float(ball[1])))
            self.positions.append(sample)
            self.sample_lines.append(self.static_line)
        self.static_positions = None


def symmetry_number(reader: LineReader, line: Line, token: str, number: int) -> int:
    """Role *number*'s symmetry number *token*: -1, 0 or a role number."""
    pair = reader.integer(line, token, f"symmetry number of role {number}")
    if not -1 <= pair <= ROLE_COUNT:
        raise reader.error(line, f"symmetry number {pair} of role {number} must be -1, 0 or a role number 1..{ROLE_COUNT}")
    return pair


def sample_field(i: int, k: int) -> str:
    """Name of value *i* of sample *k* in a row 'ball x y, then x y of players 1..11'."""
    axis = "xy"[i % 2]
    return f"ball {axis} of sample {k}" if i < 2 else f"{axis} of player {i // 2} in sample {k}"


# ----------------------------------------------------------------- building
def build_formation(parsed: ParsedLayout, source: str, name: str, description: str,
                    field: FieldDimensions) -> Formation:
    """The :class:`Formation` *parsed* describes, in our frame, on *field* (the pitch of the
    server the layout was written for); errors name the line at fault."""
    parsed.expand_static(field)
    balls = np.array(parsed.balls, dtype=np.float64).reshape(-1, 2)
    positions = np.array(parsed.positions, dtype=np.float64).reshape(-1, ROLE_COUNT, 2)
    server_to_team_frame(balls, positions)
    partners = partners_from_pairs(
        parsed.pairs, source, lambda n: f"line {parsed.role_lines[n]}, role {n}", field="symmetry number"
    )
    roles = []
    for number in ALL_ROLES:
        role_name = parsed.names[number]
        mean_x = float(positions[:, number - 1, 0].mean()) if len(positions) else 0.0
        kind = role_kind(parsed.types.get(number), role_name, mean_x, field)
        roles.append(Role(number, role_name, kind, partners.get(number)))
    try:
        return Formation(roles, balls, positions, name=name, description=description, source=source,
                         field=field)
    except FormationError as error:
        raise _locate(error, parsed) from None


def _locate(error: FormationError, parsed: ParsedLayout) -> FormationError:
    """Prefix the line of the sample (or, for a static formation, the role) an error names."""
    match = re.match(r"sample (\d+)(?:, role (\d+))?", error.where or "")
    if match is None:
        return error
    if parsed.static and match.group(2):
        line = parsed.role_lines[int(match.group(2))]
        return FormationError(error.source, error.problem, f"line {line}, role {match.group(2)}")
    line = parsed.sample_lines[int(match.group(1))]
    return FormationError(error.source, error.problem, f"line {line}, {error.where}")
