"""Roles: the named places of a formation, one per player.

A role's ``number`` is the shirt number of the player who takes it (1..11 in
the built-in formations, 1 being the goalkeeper). ``partner`` names the role
that mirrors it across the long axis of the field (left back <-> right back);
central roles have none and mirror onto themselves.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from formations.errors import FormationError

ROLE_KINDS: tuple[str, ...] = ("goalkeeper", "defender", "midfielder", "forward")
"""The kinds a role may have; teams use them to pick behaviours."""


@dataclass(frozen=True)
class Role:
    """One place in a formation."""

    number: int
    """Shirt number of the player who takes this role (unique in a formation)."""
    name: str
    """Human-readable name, e.g. ``"left back"``."""
    kind: str
    """One of :data:`ROLE_KINDS`."""
    partner: int | None = None
    """Number of the mirror role across y = 0, or None for a central role."""

    @property
    def mirror_number(self) -> int:
        """The role this one becomes when the field is mirrored in y."""
        return self.number if self.partner is None else self.partner


def check_roles(roles: Sequence[Role], source: str) -> None:
    """Raise :class:`FormationError` unless *roles* form a consistent role list.

    Checks: at least one role, unique positive integer numbers, non-empty
    names, known kinds, at most one goalkeeper, and partners that exist, differ
    from the role itself and point back to it.
    """
    if len(roles) == 0:
        raise FormationError(source, "a formation needs at least one role")
    by_number: dict[int, Role] = {}
    for role in roles:
        where = f"role {role.number!r}"
        if isinstance(role.number, bool) or not isinstance(role.number, int) or role.number < 1:
            raise FormationError(source, "role number must be a positive integer", where)
        if role.number in by_number:
            raise FormationError(source, "role number is used twice", where)
        if not isinstance(role.name, str) or not role.name.strip():
            raise FormationError(source, "role name must be a non-empty string", where)
        if role.kind not in ROLE_KINDS:
            raise FormationError(source, f"unknown kind {role.kind!r} (expected one of {', '.join(ROLE_KINDS)})", where)
        by_number[role.number] = role
    goalkeepers = [r.number for r in roles if r.kind == "goalkeeper"]
    if len(goalkeepers) > 1:
        raise FormationError(source, f"more than one goalkeeper role: {goalkeepers}")
    for role in roles:
        if role.partner is None:
            continue
        where = f"role {role.number}"
        if role.partner == role.number:
            raise FormationError(source, "a role cannot be its own partner (use no partner for a central role)", where)
        other = by_number.get(role.partner)
        if other is None:
            raise FormationError(source, f"partner {role.partner!r} is not a role of this formation", where)
        if other.partner != role.number:
            raise FormationError(
                source, f"partner {role.partner} does not name role {role.number} as its partner", where
            )
