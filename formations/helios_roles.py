"""What agent2d / helios-base formation layouts share: roles, frame and static line-ups.

Both helios layouts (librcsc's JSON files and agent2d's text files) give every
role a *pair* (the text layout calls it the symmetry number): 0 for a central
role, -1 for a side role that another role mirrors, and n > 0 for the mirror of
role n. Both become :attr:`~formations.roles.Role.partner` links that name each
other.

The text layouts (except version 3) give no role type, only a name such as
``CenterBack``; :func:`kind_from_name` maps the names agent2d-based teams use
onto our kinds, and :func:`kind_from_depth` places any other name (agent2d's
``Sample``, for instance) by where the role stands.

Every layout also has a *static* form (agent2d's ``before-kick-off.conf``):
one position per player whatever the ball does; :func:`static_samples` turns
it into samples our formations interpolate.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping

import numpy as np

from formations.errors import FormationError
from formations.field import FieldDimensions

ROLE_COUNT = 11
"""agent2d formations always have roles 1..11."""

HELIOS_KINDS = {"G": "goalkeeper", "DF": "defender", "MF": "midfielder", "FW": "forward"}
"""helios role type (JSON ``type``, text version 3 type column) -> our role kind."""

NAME_KINDS: tuple[tuple[str, str], ...] = (
    # Checked in order on the lower-case name with spaces, '-' and '_' removed;
    # the first suffix that matches wins (so "HalfBack" is a defender).
    ("goalie", "goalkeeper"),
    ("goalkeeper", "goalkeeper"),
    ("keeper", "goalkeeper"),
    ("back", "defender"),
    ("defender", "defender"),
    ("defense", "defender"),
    ("defence", "defender"),
    ("sweeper", "defender"),
    ("stopper", "defender"),
    ("libero", "defender"),
    ("half", "midfielder"),
    ("midfielder", "midfielder"),
    ("midfield", "midfielder"),
    ("mid", "midfielder"),
    ("volante", "midfielder"),
    ("forward", "forward"),
    ("striker", "forward"),
    ("attacker", "forward"),
    ("winger", "forward"),
    ("wing", "forward"),
)
"""Name suffix -> kind: Goalie, *Back, *Half, *Forward and the other names of the table."""

FIELD_THIRDS = 3
"""A role of unknown name is placed by the third of the field's length its mean x falls in:
the defending third (defender), the middle one (midfielder) or the attacking one (forward)."""


def kind_from_name(name: str) -> str | None:
    """Our kind for an agent2d role name (``CenterBack`` -> defender), or None if unknown."""
    key = re.sub(r"[\s_\-]+", "", name).lower()
    for suffix, kind in NAME_KINDS:
        if key.endswith(suffix):
            return kind
    return None


def role_kind(given: str | None, name: str, mean_x: float, field: FieldDimensions) -> str:
    """Our kind of a role: *given* (from a type column) if any, else from its *name*, else from its
    depth on *field*."""
    return given or kind_from_name(name) or kind_from_depth(mean_x, field)


def kind_from_depth(mean_x: float, field: FieldDimensions) -> str:
    """Kind of a role of unknown name from its mean x over the samples (metres, our frame) and
    the third of *field* it falls in (:data:`FIELD_THIRDS`)."""
    middle_half_length = field.length / (2 * FIELD_THIRDS)
    if mean_x < -middle_half_length:
        return "defender"
    if mean_x > middle_half_length:
        return "forward"
    return "midfielder"


def partners_from_pairs(
    pairs: Mapping[int, int], source: str, where: Callable[[int], str], field: str = "pair"
) -> dict[int, int]:
    """Role number -> partner number from helios pairs (0 central, -1 mirrored, n mirror of n).

    *pairs* maps every role number to its pair value, already checked to be -1, 0
    or a role number; *where* names a role in error messages and *field* is the
    name of the pair column. Raises :class:`FormationError` for a role paired
    with itself, a pair that the other role contradicts, or two roles mirroring
    the same role.
    """
    partners: dict[int, int] = {}
    for number, pair in pairs.items():
        if pair <= 0:
            continue
        if pair == number:
            raise FormationError(source, "a role cannot be paired with itself", where(number))
        other = pairs.get(pair)
        if other is None:
            raise FormationError(source, f"{field} {pair} names no role of this formation", where(number))
        if other not in (-1, number):
            raise FormationError(source, f"pairs with role {pair}, but role {pair} has {field} {other}", where(number))
        if pair in partners and partners[pair] != number:
            raise FormationError(source, f"role {pair} is paired with both {partners[pair]} and {number}", where(number))
        partners[number] = pair
        partners[pair] = number
    return partners


def server_to_team_frame(balls: np.ndarray, positions: np.ndarray) -> None:
    """Convert helios coordinates to ours in place.

    helios formations are written in the soccer server's frame for the team
    attacking towards +x, whose y axis points to the *right* of a player
    facing the opponent goal; ours points to the left, so y is negated and x
    kept (a helios left back at y < 0 stays a left back at y > 0 here).
    """
    balls[:, 1] *= -1.0
    positions[..., 1] *= -1.0


def static_balls(field: FieldDimensions) -> np.ndarray:
    """(4, 2) ball positions of the samples a static formation becomes: the corners of *field*
    (symmetric about both axes, so the same in the server's frame and ours)."""
    hl, hw = field.half_length, field.half_width
    return np.array([(-hl, -hw), (-hl, hw), (hl, -hw), (hl, hw)], dtype=np.float64)


def static_samples(positions: np.ndarray, field: FieldDimensions) -> tuple[np.ndarray, np.ndarray]:
    """Samples (balls (4, 2), positions (4, n, 2)) that hold *positions* (n, 2) for every ball.

    A static formation has one position per player whatever the ball does;
    the same positions at the four corners of *field* make every ball
    position on the field give exactly them.
    """
    balls = static_balls(field)
    return balls, np.repeat(np.asarray(positions, dtype=np.float64)[None], len(balls), axis=0)
