"""How far a team's players are from following one role assignment: the roles they believe they hold.

Under partial observation every player follows an assignment of its own (the one it last heard,
:mod:`agents.teams.speaking`, or its own proposal), so two players may believe they hold the same
role while another role is left to nobody. :func:`role_conflicts` counts both for the roles the
players believe they hold; :func:`believed_conflicts` reads those roles from what each player follows.
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, nogil=True)
def role_conflicts(roles: np.ndarray, n_roles: int) -> tuple[int, int]:  # pragma: no cover - compiled
    """(roles claimed by two or more players, roles claimed by nobody) for ``roles`` (k,) int64,
    the role each player believes it holds (under one shared assignment both are 0); roles
    outside ``0 .. n_roles - 1`` are not counted."""
    counts = np.zeros(n_roles, dtype=np.int64)
    for r in roles:
        if 0 <= r < n_roles:
            counts[r] += 1
    shared, empty = 0, 0
    for c in counts:
        if c > 1:
            shared += 1
        elif c == 0:
            empty += 1
    return shared, empty


@njit(cache=True, nogil=True)
def believed_conflicts(followed: np.ndarray, outfield: np.ndarray) -> tuple[int, int]:  # pragma: no cover
    """:func:`role_conflicts` of the roles the ``outfield`` players (k,) believe they hold:
    player ``outfield[j]``'s own entry ``followed[outfield[j], j]`` of the assignment it
    follows (``followed`` (n, k))."""
    k = outfield.shape[0]
    roles = np.empty(k, dtype=np.int64)
    for j in range(k):
        roles[j] = followed[outfield[j], j]
    return role_conflicts(roles, k)
