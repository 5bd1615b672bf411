"""Potential-field bidding, after "Dynamic multi-robot coordination" (Vail and Veloso).

Every player computes every player's bid for every role from the shared state (here one
cost matrix, lower is better), and the roles are auctioned one after another in a fixed
priority order, each to the best bidder not yet given a role:

1. the **ball role** (the paper's primary attacker): cost ``min(|p - b|, ball_cap) +
   angle_weight * theta``, ``theta`` the angle (radians) between the player-to-ball and the
   ball-to-goal directions, so a player lined up to kick towards the goal bids better;
2. the ten **formation roles** (the paper's supporters, generalised), in role-index order
   (the formation's numbering: defenders first): cost ``|p - t_r|`` plus, for a role behind
   the ball (a defensive supporter), ``goal_side_weight * max(0, p_x - t_x)`` (a player
   already goal-side of the anchor defends better).

Ten players and eleven roles: the ball player takes the place of the formation role whose
target is nearest the ball (it is the one covering that area), so every other formation role
is filled and ``role_of_player`` stays a permutation.

**Hysteresis.** A role's holder keeps it for at least ``min_hold`` cycles after winning it
(if it is still free at that role's turn); after that a challenger must beat the holder's
cost by ``switch_margin`` metres. Without it, bids that differ by noise would swap roles
every cycle.

**Supporters** do not run straight to their targets: :meth:`BiddingAssigner.steer` moves each
one down the potential field of :mod:`agents.roles.potential_field` anchored at its target
(offensive terms for roles level with or ahead of the ball, defensive ones behind it).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from agents.roles import potential_field as pf
from agents.roles.base import RoleAssigner, RoleContext


@dataclass(frozen=True)
class BiddingParams:
    """Bid weights (metres) and the hysteresis."""

    ball_cap: float = 20.0
    """Distances to the ball beyond this bid alike (m)."""
    angle_weight: float = 3.0
    """Metres of ball distance one radian of misalignment is worth."""
    goal_side_weight: float = 0.5
    """Cost per metre a defensive supporter stands ahead of its anchor."""
    min_hold: int = 10
    """Cycles a player keeps a role it won."""
    switch_margin: float = 1.0
    """After ``min_hold``, a challenger must bid this much better (m) to take a role."""
    field: pf.FieldParams = pf.FieldParams()


class BiddingAssigner(RoleAssigner):
    """Potential-field bidding (see the module docstring)."""

    name = "bidding"

    def __init__(self, params: BiddingParams | None = None) -> None:
        self.params = params or BiddingParams()

    def reset(self, n_roles: int, rng: np.random.Generator) -> None:
        super().reset(n_roles, rng)
        # Auctioned roles: 0 .. n_roles - 1 the formation roles, n_roles the ball role.
        self.holder = np.full(n_roles + 1, -1, dtype=np.int64)
        self.since = np.zeros(n_roles + 1, dtype=np.int64)
        self._ball_player: int | None = None
        self._covered = -1

    def bids(self, players: np.ndarray, targets: np.ndarray, context: RoleContext) -> np.ndarray:
        """(k, k + 1) costs: column r < k formation role r, column k the ball role."""
        p = self.params
        k = players.shape[0]
        costs = np.empty((k, k + 1))
        delta = players[:, None, :] - targets[None, :, :]
        costs[:, :k] = np.hypot(delta[..., 0], delta[..., 1])
        behind = targets[:, 0] < context.ball[0]
        ahead = np.maximum(players[:, 0:1] - targets[None, :, 0], 0.0)
        costs[:, :k] += np.where(behind[None, :], p.goal_side_weight * ahead, 0.0)
        to_ball = context.ball - players
        dist = np.hypot(to_ball[:, 0], to_ball[:, 1])
        to_goal = context.opp_goal - context.ball
        goal_dist = float(np.hypot(*to_goal))
        cos = np.divide(to_ball @ to_goal, dist * goal_dist, out=np.ones(k), where=(dist > 1e-9) & (goal_dist > 1e-9))
        costs[:, k] = np.minimum(dist, p.ball_cap) + p.angle_weight * np.arccos(np.clip(cos, -1.0, 1.0))
        return costs

    def assign(self, players, targets, role_order, previous, context):
        k = players.shape[0]
        costs = self.bids(players, targets, context)
        gaps = np.hypot(targets[:, 0] - context.ball[0], targets[:, 1] - context.ball[1])
        covered = int(np.argmin(gaps))
        priority = np.concatenate(([k], np.delete(np.arange(k), covered))).astype(np.int64)
        winners = _auction(costs, priority, self.holder, self.since, context.cycle, self.params.min_hold,
                           self.params.switch_margin)
        role_of_player = np.empty(k, dtype=np.int64)
        role_of_player[winners[priority[1:]]] = priority[1:]
        ball_player = int(winners[k])
        role_of_player[ball_player] = covered
        self._ball_player, self._covered = ball_player, covered
        return role_of_player

    def ball_player(self) -> int | None:
        return self._ball_player

    def steer(self, players, targets, role_of_player, context):
        anchors = targets[role_of_player]
        offensive = anchors[:, 0] >= context.ball[0]
        _, grad = pf.supporter_field(
            players, anchors, offensive, context.ball, context.own_goal, context.opp_goal,
            context.field_half_length, context.field_half_width, context.penalty_area_length,
            context.penalty_area_half_width, self.params.field)
        goals = pf.descend(players, grad, self.params.field)
        if self._ball_player is not None:
            goals[self._ball_player] = anchors[self._ball_player]
        return goals


@njit(cache=True, nogil=True)
def _auction(costs: np.ndarray, priority: np.ndarray, holder: np.ndarray, since: np.ndarray, cycle: int,
             min_hold: int, margin: float) -> np.ndarray:  # pragma: no cover - compiled
    """Auction the roles (columns of ``costs``) in ``priority`` order, each to the best free
    bidder, with hysteresis (see the module docstring); updates ``holder``/``since`` and returns
    the winner of every role (-1 for roles not auctioned)."""
    k = costs.shape[0]
    taken = np.zeros(k, dtype=np.bool_)
    winners = np.full(costs.shape[1], -1, dtype=np.int64)
    for role in priority:
        best, best_cost = -1, math.inf
        for i in range(k):
            if not taken[i] and costs[i, role] < best_cost:
                best, best_cost = i, costs[i, role]
        incumbent = holder[role]
        if incumbent >= 0 and not taken[incumbent] and incumbent != best:
            if cycle - since[role] < min_hold or costs[incumbent, role] - margin <= best_cost:
                best = incumbent
        if best != incumbent:
            holder[role] = best
            since[role] = cycle
        winners[role] = best
        taken[best] = True
    return winners
