"""Role assigners that match players to role targets by distance alone (no memory).

* ``static``: role i to player i, whatever the positions (the shirt-number roles of
  agent2d/helios-base teams).
* ``mmdr``, ``mmd+msd2`` (from "SCRAM: Scalable Collision-avoiding Role Assignment with
  Minimal-makespan for Formational Positioning"), ``msd``, ``msd2`` and ``greedy`` (the
  shortest remaining player-role pair first, ties to the lower player then the lower role):
  :func:`agents.assignment.assign` with that method on Euclidean distances.

Every assigner here that weighs distances uses *time costs* when the team's players differ in
speed (``context.time_scale``, see :class:`~agents.roles.base.RoleContext`): a player's
distance to a target times its factor, so a faster player far away may take a target a slow
near one would have taken. With equal players (``time_scale`` None) they are plain distances.
* ``greedy-offense``: roles from the most to the least offensive, each taken by the nearest
  free player (ties to the lower player row).
* ``random``: a fresh uniformly random permutation every call, from the team's generator.
"""

from __future__ import annotations

import numpy as np

from agents.assignment.api import dense_target_of, dense_targets_of_rows
from agents.roles.base import RoleAssigner, RoleContext
from agents.roles.errors import RoleError
from agents.roles.kernels import all_finite, greedy_in_order


class StaticAssigner(RoleAssigner):
    """Player i always takes role i."""

    name = "static"
    uses_role_order = False

    def assign(self, players: np.ndarray, targets: np.ndarray, role_order: np.ndarray,
               previous: np.ndarray | None, context: RoleContext) -> np.ndarray:
        return np.arange(self.check_inputs(players, targets), dtype=np.int64)


class MethodAssigner(RoleAssigner):
    """An assignment method of :mod:`agents.assignment` (``method``) on player-target distances."""

    METHODS = ("greedy", "mmdr", "mmd+msd2", "msd", "msd2")
    uses_role_order = False

    def __init__(self, method: str) -> None:
        if method not in self.METHODS:
            raise RoleError(f"MethodAssigner: unknown method {method!r}; known: {', '.join(self.METHODS)}")
        self.name = method
        self.method = method

    def assign(self, players: np.ndarray, targets: np.ndarray, role_order: np.ndarray,
               previous: np.ndarray | None, context: RoleContext) -> np.ndarray:
        k = self.check_inputs(players, targets)
        players, targets = self._clean(players, targets)
        return dense_target_of(players, targets, self.method, self.time_scale(context, k))

    def assign_rows(self, players: np.ndarray, targets: np.ndarray, context: RoleContext) -> np.ndarray:
        k = self.check_inputs(players, targets, problems=True)
        players, targets = self._clean(players, targets)
        return dense_targets_of_rows(players, targets, self.method, self.time_scale(context, k))

    def _clean(self, players: np.ndarray, targets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """``players`` and ``targets`` as C-contiguous float64 arrays; RoleError if any entry is
        not finite."""
        players = np.ascontiguousarray(players, dtype=np.float64)
        targets = np.ascontiguousarray(targets, dtype=np.float64)
        if not all_finite(players, targets):
            raise RoleError(f"role assigner {self.name!r}: players and targets must be finite")
        return players, targets


class GreedyOffenseAssigner(RoleAssigner):
    """Roles in ``role_order`` (most offensive first), each taken by the nearest free player
    (the quickest there, with ``context.time_scale``)."""

    name = "greedy-offense"

    def assign(self, players: np.ndarray, targets: np.ndarray, role_order: np.ndarray,
               previous: np.ndarray | None, context: RoleContext) -> np.ndarray:
        k = self.check_inputs(players, targets)
        self.check_order(role_order, k)
        scale = self.time_scale(context, k)
        return greedy_in_order(players, targets, role_order, _EQUAL if scale is None else scale)


_EQUAL = np.empty(0)
"""An empty time scale: plain distances."""


class RandomAssigner(RoleAssigner):
    """A uniformly random permutation, drawn anew from the team's generator every call."""

    name = "random"
    uses_role_order = False

    def assign(self, players: np.ndarray, targets: np.ndarray, role_order: np.ndarray,
               previous: np.ndarray | None, context: RoleContext) -> np.ndarray:
        k = self.check_inputs(players, targets)
        return self.rng.permutation(k)
