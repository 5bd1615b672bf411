"""Role assigners of the built-in team: which outfield player takes which formation role.

One interface (:class:`RoleAssigner`, see :mod:`agents.roles.base`): every cycle the team
gives the outfield players' positions, the formation's role targets (for the ball position
the formation was queried at), the roles' order from most to least offensive
(:func:`offensive_order`), the previous assignment and a :class:`RoleContext`; the assigner
returns ``role_of_player``. It may also name the player who goes for the ball and steer the
others (potential-field bidding does both).

Registered by name (:func:`make_assigner`, :data:`ASSIGNERS`): ``static``, ``greedy``,
``greedy-offense``, ``mmdr``, ``mmd+msd2``, ``msd``, ``msd2``, ``random``, ``bidding``.
"""

from __future__ import annotations

from collections.abc import Callable

from agents.roles.base import RoleAssigner, RoleContext, offensive_order
from agents.roles.bidding import BiddingAssigner, BiddingParams
from agents.roles.matching import GreedyOffenseAssigner, MethodAssigner, RandomAssigner, StaticAssigner

ASSIGNERS: dict[str, Callable[..., RoleAssigner]] = {
    "static": StaticAssigner,
    "greedy": lambda: MethodAssigner("greedy"),
    "greedy-offense": GreedyOffenseAssigner,
    "mmdr": lambda: MethodAssigner("mmdr"),
    "mmd+msd2": lambda: MethodAssigner("mmd+msd2"),
    "msd": lambda: MethodAssigner("msd"),
    "msd2": lambda: MethodAssigner("msd2"),
    "random": RandomAssigner,
    "bidding": BiddingAssigner,
}
"""Assigner name -> factory (keyword parameters, where the assigner has any)."""


def assigner_names() -> tuple[str, ...]:
    """The registered assigner names."""
    return tuple(ASSIGNERS)


def make_assigner(name: str, **params: object) -> RoleAssigner:
    """A new assigner called ``name``; ValueError naming the known ones for an unknown name."""
    factory = ASSIGNERS.get(name)
    if factory is None:
        raise ValueError(f"unknown role assigner {name!r}; known: {', '.join(ASSIGNERS)}")
    try:
        return factory(**params)
    except TypeError as exc:
        raise ValueError(f"role assigner {name!r} does not take {sorted(params)}: {exc}") from exc


__all__ = [
    "ASSIGNERS", "BiddingAssigner", "BiddingParams", "RoleAssigner", "RoleContext", "assigner_names",
    "make_assigner", "offensive_order",
]
