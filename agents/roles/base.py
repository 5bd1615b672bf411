"""The role-assigner interface: which outfield player takes which formation role.

Team-relative frame (we attack +x, our goal at ``x = -half_length``), metres, cycles. The
field's default sizes are the simulator's default field's
(:data:`soccer_sim.config.STANDARD_FIELD`), the field the built-in formations are designed for.
"""

from __future__ import annotations

from abc import ABC, abstractmethod
from dataclasses import dataclass

import numpy as np

from agents.roles.errors import RoleError
from agents.roles.kernels import descending_x, is_permutation
from soccer_sim.config import STANDARD_FIELD


@dataclass
class RoleContext:
    """What an assigner may look at besides the positions. The team keeps one per match and
    refreshes it every cycle, so an assigner must copy what it keeps."""

    ball: np.ndarray
    """(2,) where the ball will be controlled (possibly predicted: the built-in team gives its
    ball race's interception point in play on, not the formation's query point, which follows
    the ball at a running pace), metres."""
    own_goal: np.ndarray
    """(2,) centre of our goal, (-half_length, 0)."""
    opp_goal: np.ndarray
    """(2,) centre of the opponents' goal, (half_length, 0)."""
    opponents: np.ndarray
    """(n_opp, 2) opponent positions."""
    field_half_length: float
    """Half the field's length (m): the goal lines are at x = +-field_half_length."""
    field_half_width: float
    """Half the field's width (m): the touchlines are at y = +-field_half_width."""
    cycle: int
    """The match cycle (100 ms each); hysteresis counts in these."""
    attacking: bool
    """The situation: True when we expect to control the ball first (we attack)."""
    penalty_area_length: float = STANDARD_FIELD.penalty_area_length
    """Depth of the penalty area from the goal line (m; default: the default field's, as
    rcssserver's)."""
    penalty_area_half_width: float = STANDARD_FIELD.penalty_area_width / 2.0
    """Half the penalty area's width (m; default: the default field's, as rcssserver's)."""
    ball_reach: np.ndarray | None = None
    """Optional (k,) how far (m) each outfield player (row of ``players``) effectively is from
    controlling the ball, when the team knows better than the straight distance to ``ball``
    (e.g. the cycles its interception takes times the top speed, or inf when it cannot
    intercept). None: the straight distance. Bidding's ball role uses it."""
    time_scale: np.ndarray | None = None
    """Optional (k,) positive factor per outfield player (row of ``players``) turning its
    distances into *time costs*: ``distance * time_scale[i]`` is the time player i needs, in
    metres run at a reference speed (``reference_speed / top_speed[i]``, so a faster player's
    metres cost less). Every assigner that weighs distances (all but ``static`` and ``random``)
    uses it; None (the default, and what a team of equal players gives) means plain
    distances, exactly as before."""


def offensive_order(targets: np.ndarray) -> np.ndarray:
    """Role indices from the most to the least offensive: by target x descending, ties by role
    index. ``targets`` (k, 2) role target positions (team frame)."""
    if type(targets) is np.ndarray and targets.dtype == np.float64 and targets.ndim == 2 and targets.shape[1] == 2:
        order = descending_x(targets)
        if order is not None:
            return order
    return np.argsort(-targets[:, 0], kind="stable")


class RoleAssigner(ABC):
    """Maps the outfield players to the outfield roles every cycle.

    Call :meth:`reset` once per match, then :meth:`assign` every cycle (and, if the team wants
    the assigner's positioning, :meth:`steer` with its answer). ``assign`` returns
    ``role_of_player`` (k,) int64, a permutation of ``range(k)``: player row i (of ``players``)
    takes role ``role_of_player[i]`` (row of ``targets``). The returned array belongs to the
    caller. An assigner may also name a player to go for the ball (:meth:`ball_player`) and
    move the others to points other than their targets (:meth:`steer`); the defaults leave
    both to the team.
    """

    name: str = ""
    n_roles: int | None = None
    """Roles (= players) per call, set by :meth:`reset`."""
    rng: np.random.Generator | None = None
    """The team's seeded generator, set by :meth:`reset`: the only source of randomness."""
    uses_role_order: bool = True
    """Whether :meth:`assign` looks at ``role_order``; an assigner that does not says so, and a
    team may then pass None instead of working the order out every cycle."""
    uses_ball_reach: bool = False
    """Whether :meth:`assign` looks at ``RoleContext.ball_reach``; a team that knows it may fill
    it in for such an assigner only (working it out every cycle costs time)."""

    def reset(self, n_roles: int, rng: np.random.Generator) -> None:
        """A new match with ``n_roles`` roles (and as many players); ``rng`` is the team's
        seeded generator. Forgets everything remembered from a previous match."""
        if isinstance(n_roles, bool) or not isinstance(n_roles, (int, np.integer)) or n_roles < 1:
            raise RoleError(f"role assigner {self.name!r}: n_roles must be a positive integer, got {n_roles!r}")
        if not isinstance(rng, np.random.Generator):
            raise RoleError(f"role assigner {self.name!r}: rng must be a numpy Generator, got {type(rng).__name__}")
        self.n_roles = int(n_roles)
        self.rng = rng

    @abstractmethod
    def assign(self, players: np.ndarray, targets: np.ndarray, role_order: np.ndarray,
               previous: np.ndarray | None, context: RoleContext) -> np.ndarray:
        """Which role each player takes.

        Args:
            players: (k, 2) float64 outfield player positions.
            targets: (k, 2) float64 role target positions (row r: role r's target).
            role_order: (k,) role indices, most offensive first (:func:`offensive_order`); may
                be None for an assigner whose ``uses_role_order`` is False.
            previous: (k,) last cycle's ``role_of_player``, or None on the first cycle.
            context: the rest of the situation.

        Returns:
            ``role_of_player`` (k,) int64, a permutation of ``range(k)``.
        """

    def assign_rows(self, players: np.ndarray, targets: np.ndarray, context: RoleContext) -> np.ndarray | None:
        """Many independent assignments in one call, for an assigner whose answer depends on the
        positions and ``context.time_scale`` alone (no memory, no role order, no other context):
        ``players`` and ``targets`` (problems, k, 2), each problem one player's own view of the
        team (partial observation); returns (problems, k), row ``r`` what :meth:`assign` returns
        for problem ``r``. None (the default): this assigner has no such form; call
        :meth:`assign` per problem."""
        return None

    def ball_player(self) -> int | None:
        """The player (row of the last ``assign``'s ``players``) this assigner sends to the ball,
        or None to let the team choose."""
        return None

    def steer(self, players: np.ndarray, targets: np.ndarray, role_of_player: np.ndarray,
              context: RoleContext) -> np.ndarray:
        """(k, 2) where each player should move this cycle; by default its role's target."""
        return targets[role_of_player]

    def check_inputs(self, players: np.ndarray, targets: np.ndarray, problems: bool = False) -> int:
        """The number of players k, after checking that :meth:`reset` was called and that
        ``players`` and ``targets`` are (n_roles, 2) arrays (with ``problems``: (problems,
        n_roles, 2), as :meth:`assign_rows` takes them); RoleError naming the problem."""
        k = self.n_roles
        if k is None:
            raise RoleError(f"role assigner {self.name!r}: call reset(n_roles, rng) before assign")
        shape = ((players.shape[0] if players.ndim == 3 else -1), k, 2) if problems else (k, 2)
        if players.shape != shape or targets.shape != shape:
            wanted = f"(problems, {k}, 2)" if problems else f"({k}, 2)"
            raise RoleError(f"role assigner {self.name!r} was reset for {k} roles: players and targets must "
                             f"be {wanted} arrays, got players {players.shape} and targets {targets.shape}")
        return k

    _checked_scale: np.ndarray | None = None
    """The last ``time_scale`` array found valid (a team gives the same one every cycle)."""

    def time_scale(self, context: RoleContext | None, k: int) -> np.ndarray | None:
        """``context.time_scale`` checked ((k,) finite positive float64, or None); RoleError
        otherwise."""
        scale = getattr(context, "time_scale", None)
        if scale is None or scale is self._checked_scale:
            return scale
        if not (isinstance(scale, np.ndarray) and scale.shape == (k,) and scale.dtype == np.float64
                and np.isfinite(scale).all() and (scale > 0).all()):
            raise RoleError(f"context.time_scale must be a finite positive float64 ({k},) array or None, "
                            f"got {scale!r}")
        self._checked_scale = scale
        return scale

    def check_order(self, role_order: np.ndarray, k: int) -> None:
        """RoleError unless ``role_order`` is a permutation of ``range(k)`` (for assigners that
        use it)."""
        if role_order.ndim != 1 or not is_permutation(role_order, k):
            raise RoleError(f"role assigner {self.name!r}: role_order must be a permutation of range({k}), "
                             f"got {np.asarray(role_order).tolist()}")
