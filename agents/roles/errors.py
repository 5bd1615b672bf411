"""The role assigners' error: a bad argument, a wrong shape or a call out of order."""

from __future__ import annotations

from agents.errors import AgentsError


class RoleError(AgentsError, ValueError):
    """A role assigner (or its parameters) refuses its input: an unknown assigner name or
    parameter, a parameter out of range, arrays of the wrong shape, a ``role_order`` that is
    not a permutation, ``assign`` before ``reset``. A ``ValueError`` too, so callers catching
    that keep working."""
