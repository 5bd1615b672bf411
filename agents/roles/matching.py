"""Role assigners that match players to role targets by distance alone.

* ``static``: role i to player i, whatever the positions (the shirt-number roles of
  agent2d/helios-base teams).
* ``mmdr``, ``mmd+msd2`` (SCRAM: "SCRAM: Scalable Collision-avoiding Role Assignment with
  Minimal-makespan for Formational Positioning"), ``msd``, ``msd2``, ``greedy`` (the shortest
  remaining player-role pair first): :func:`agents.assignment.assign` with that method.
* ``greedy-offense``: roles from the most to the least offensive, each to the nearest free
  player (the role order of the SCRAM paper's greedy baseline).
* ``random``: a fresh uniformly random permutation every cycle, from the team's generator.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from agents.assignment import assign
from agents.roles.base import RoleAssigner


class StaticAssigner(RoleAssigner):
    """Player i always takes role i."""

    name = "static"

    def reset(self, n_roles: int, rng: np.random.Generator) -> None:
        super().reset(n_roles, rng)
        self._identity = np.arange(n_roles)

    def assign(self, players, targets, role_order, previous, context):
        return self._identity


class MethodAssigner(RoleAssigner):
    """An assignment method of :mod:`agents.assignment` on player-target distances."""

    def __init__(self, method: str) -> None:
        self.name = method
        self.method = method

    def assign(self, players, targets, role_order, previous, context):
        return assign(players, targets, method=self.method).target_of


class GreedyOffenseAssigner(RoleAssigner):
    """Roles in ``role_order`` (most offensive first), each taken by the nearest free player."""

    name = "greedy-offense"

    def assign(self, players, targets, role_order, previous, context):
        return _greedy_in_order(players, targets, role_order)


class RandomAssigner(RoleAssigner):
    """A uniformly random permutation, drawn anew every cycle."""

    name = "random"

    def assign(self, players, targets, role_order, previous, context):
        return self.rng.permutation(players.shape[0])


@njit(cache=True, nogil=True)
def _greedy_in_order(players: np.ndarray, targets: np.ndarray,
                     order: np.ndarray) -> np.ndarray:  # pragma: no cover - compiled
    """For each role in ``order``, the nearest player not yet taken (ties: lower row)."""
    k = players.shape[0]
    role_of_player = np.full(k, -1, dtype=np.int64)
    for r in order:
        best, best_d = -1, math.inf
        tx, ty = targets[r, 0], targets[r, 1]
        for i in range(k):
            if role_of_player[i] < 0:
                d = (players[i, 0] - tx) ** 2 + (players[i, 1] - ty) ** 2
                if d < best_d:
                    best, best_d = i, d
        role_of_player[best] = r
    return role_of_player
