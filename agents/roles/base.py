"""The role-assigner interface: which outfield player takes which formation role.

Team-relative frame (we attack +x, our goal at ``x = -half_length``), metres, cycles.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass

import numpy as np


@dataclass
class RoleContext:
    """What an assigner may look at besides the positions. The team keeps one per match and
    refreshes it every cycle, so an assigner must copy what it keeps."""

    ball: np.ndarray
    """(2,) the ball position the formation was queried at (where the ball will be controlled)."""
    own_goal: np.ndarray
    """(2,) centre of our goal, (-half_length, 0)."""
    opp_goal: np.ndarray
    """(2,) centre of the opponents' goal."""
    opponents: np.ndarray
    """(n_opp, 2) opponent positions."""
    field_half_length: float
    field_half_width: float
    cycle: int
    attacking: bool
    """True when we expect to control the ball first."""
    penalty_area_length: float = 16.5
    penalty_area_half_width: float = 20.16


def offensive_order(targets: np.ndarray) -> np.ndarray:
    """Role indices from the most to the least offensive: by target x descending, ties by role
    index. ``targets`` (k, 2) role target positions."""
    return np.lexsort((np.arange(targets.shape[0]), -targets[:, 0]))


class RoleAssigner(ABC):
    """Maps the outfield players to the outfield roles every cycle.

    ``assign`` returns ``role_of_player`` (k,), a permutation of ``range(k)``: player row i
    (of ``players``) takes role ``role_of_player[i]`` (row of ``targets``). An assigner may
    also name a player to go for the ball (:meth:`ball_player`) and move the others to points
    other than their targets (:meth:`steer`); the defaults leave both to the team.
    """

    name: str = ""

    def reset(self, n_roles: int, rng: np.random.Generator) -> None:
        """A new match with ``n_roles`` roles; ``rng`` is the team's seeded generator."""
        self.n_roles = n_roles
        self.rng = rng

    @abstractmethod
    def assign(self, players: np.ndarray, targets: np.ndarray, role_order: np.ndarray,
               previous: np.ndarray | None, context: RoleContext) -> np.ndarray:
        """``players`` (k, 2), ``targets`` (k, 2) (row r: role r's target), ``role_order`` (k,)
        roles most offensive first, ``previous`` (k,) last cycle's ``role_of_player`` or None."""

    def ball_player(self) -> int | None:
        """The player (row of the last ``assign``'s ``players``) this assigner sends to the ball,
        or None to let the team choose."""
        return None

    def steer(self, players: np.ndarray, targets: np.ndarray, role_of_player: np.ndarray,
              context: RoleContext) -> np.ndarray:
        """(k, 2) where each player should move; by default its role's target."""
        return targets[role_of_player]
