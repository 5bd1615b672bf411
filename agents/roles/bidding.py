"""Potential-field bidding, after "Dynamic multi-robot coordination" (Vail and Veloso).

Every player computes every player's bid for every role from the shared state, and the roles
are auctioned one after another in a fixed priority order, each to the best bidder not yet
given a role; every player doing the same computation on the same data reaches the same
answer, so nothing needs negotiating. Here a bid is a *cost* (lower is better; the paper's
bids are "higher is better", the same thing negated):

* the **ball role** (the paper's primary attacker): ``min(reach, ball_cap) + angle_weight
  * theta``, ``reach`` the distance ``|p - b|`` to the ball ``b`` (or the team's better
  estimate, ``context.ball_reach``, e.g. from its interception race), ``theta`` (radians, 0 to
  pi) the angle between the player-to-ball and ball-to-opponents'-goal directions: near the
  ball and lined up behind it to kick towards the goal bids best. Beyond ``ball_cap`` metres
  only the alignment counts. A player whose ``ball_reach`` is inf (it cannot intercept, or may
  not play the ball) bids ``ball_cap + angle_weight * pi`` more than that with its straight
  distance: after every player who can, so the cap does not make "cannot" as good as "far";
* a **formation role** r (the paper's supporters, generalised to the formation's roles):
  ``|p - t_r|``, the distance to the role's anchor (its formation target ``t_r``), plus a
  role term: for a *defensive* role (target behind the ball, ``t_x < b_x``)
  ``goal_side_weight * max(0, p_x - t_x)``, because a player upfield of a defensive anchor has
  to run back past the play while one already goal-side is useful at once.

**Priority order.** The ball role first, then the formation roles in offensive order (most
offensive first, the ``role_order`` the team gives).

**Ten players, eleven roles.** The ball role *replaces* one formation role, the *covered*
role, which is not auctioned: the winner of the ball role takes it in ``role_of_player``.
The covered role is the ball player's own formation role (the one it held at the last
``assign``) while that role's target is at most ``cover_slack`` metres farther from the ball
than the nearest role target; otherwise the role whose target is nearest the ball (ties to
the more offensive role). The ball player covers the area around the ball anyway, so every
other formation role stays filled and ``role_of_player`` remains a permutation; keeping the
ball player's own role when it is near the play means that a new ball player does not set
off a chain of role changes.

**Hysteresis** (the paper holds a role for a short time after taking it, so that bids that
differ by noise do not swap roles every cycle). At a role's turn in the auction its holder
(the player who won it most recently) keeps it if the holder is still free (not taken by a
higher-priority role: winning the ball role always wins) and either

* fewer than ``min_hold`` cycles (of ``context.cycle``) have passed since it won the role, or
* no free player bids better than the holder by more than ``switch_margin`` metres.

Otherwise the best free bidder wins and the role's clock restarts. The hold is there for
bids that differ by little; a ball-role holder who cannot intercept the ball at all
(``ball_reach`` inf) while another player can has no hold, and the auction goes to the best
bidder at once. With ``min_hold = 0`` and ``switch_margin = 0`` the auction is memoryless.

**Players of different speeds** (``context.time_scale``): a player's formation-role costs and
its straight distance to the ball are multiplied by its time factor, so bids are times (in
metres at the reference speed); a given ``ball_reach`` is used as it is.

**Supporters** do not run straight to their targets: :meth:`BiddingAssigner.steer` moves each
one a step down the potential field of :mod:`agents.roles.potential_field` anchored at its
role's target (offensive terms for roles whose target is level with or ahead of the ball,
defensive ones for the others; the shooting corridor is kept clear when ``context.attacking``
and blocked when not). The ball player is steered to its covered role's target; the
team sends it to the ball (:meth:`BiddingAssigner.ball_player`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields, replace

import numpy as np

from agents.roles.base import RoleAssigner, RoleContext
from agents.roles.errors import RoleError
from agents.roles.field_params import FieldParams
from agents.roles.field_terms import descend, supporter_field
from agents.roles.kernels import bid_costs, bidding_round


@dataclass(frozen=True)
class BiddingParams:
    """Bid weights (metres of cost), the hysteresis and the supporters' field."""

    ball_cap: float = 20.0
    """Distances to the ball beyond this bid alike (m)."""
    angle_weight: float = 3.0
    """Metres of ball distance one radian of misalignment is worth."""
    goal_side_weight: float = 0.5
    """Cost per metre a player stands upfield of a defensive role's target."""
    min_hold: int = 10
    """Cycles a player keeps a role it won (while it is free at that role's turn): 1 s, the
    paper's "order of seconds" (longer holds keep a slow player on the ball role)."""
    switch_margin: float = 1.0
    """After ``min_hold``, a challenger must bid this much (m) better than the holder."""
    cover_slack: float = 10.0
    """The ball player keeps covering its own formation role while that role's target is at
    most this much (m) farther from the ball than the nearest role target."""
    field: FieldParams = field(default_factory=FieldParams)
    """The supporters' potential field (:class:`agents.roles.field_params.FieldParams`)."""

    def __post_init__(self) -> None:
        for name in ("ball_cap", "angle_weight", "goal_side_weight", "switch_margin", "cover_slack"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0:
                raise RoleError(f"BiddingParams.{name} must be a finite number >= 0, got {value!r}")
        if isinstance(self.min_hold, bool) or not isinstance(self.min_hold, (int, np.integer)) or self.min_hold < 0:
            raise RoleError(f"BiddingParams.min_hold must be an integer >= 0 (cycles), got {self.min_hold!r}")
        if not isinstance(self.field, FieldParams):
            raise RoleError(f"BiddingParams.field must be a FieldParams, got {type(self.field).__name__}")

    @classmethod
    def with_overrides(cls, base: BiddingParams | None = None, **overrides: object) -> BiddingParams:
        """``base`` (default: the defaults) with keyword overrides; a key may name a field of
        :class:`BiddingParams` or of its ``field`` (:class:`FieldParams`). RoleError listing
        the valid names for any other key."""
        base = base or cls()
        own = {f.name for f in fields(cls)}
        field_names = {f.name for f in fields(FieldParams)}
        unknown = sorted(set(overrides) - own - field_names)
        if unknown:
            raise RoleError(f"unknown bidding parameter(s) {', '.join(map(repr, unknown))}; valid: "
                             f"{', '.join(sorted(own))} and the field's {', '.join(sorted(field_names))}")
        mine = {key: value for key, value in overrides.items() if key in own}
        theirs = {key: value for key, value in overrides.items() if key not in own}
        if theirs:
            mine["field"] = replace(mine.get("field", base.field), **theirs)
        return replace(base, **mine)

    def as_record(self) -> np.ndarray:
        """The numbers the compiled bidding reads, by name: a one-element :data:`BIDDING_DTYPE`
        array (the field's parameters are :meth:`FieldParams.as_record`)."""
        return np.array([(self.ball_cap, self.angle_weight, self.goal_side_weight, self.min_hold, self.switch_margin,
                          self.cover_slack)], dtype=BIDDING_DTYPE)


BIDDING_DTYPE = np.dtype([("ball_cap", np.float64), ("angle_weight", np.float64), ("goal_side_weight", np.float64),
                          ("min_hold", np.int64), ("switch_margin", np.float64), ("cover_slack", np.float64)],
                         align=True)
"""The record the compiled bidding reads (:meth:`BiddingParams.as_record`)."""


class BiddingAssigner(RoleAssigner):
    """Potential-field bidding (see the module docstring). ``params`` or keyword overrides of
    :class:`BiddingParams` (and of its :class:`FieldParams`), e.g. ``BiddingAssigner(min_hold=5)``."""

    uses_ball_reach = True

    name = "bidding"

    def __init__(self, params: BiddingParams | None = None, **overrides: object) -> None:
        self.params = BiddingParams.with_overrides(params, **overrides)
        p = self.params
        self._bidding = p.as_record()
        self._field = p.field.as_record()
        self._ball_player: int | None = None
        self.covered = -1
        """The formation role the ball player took at the last ``assign`` (not auctioned)."""

    def reset(self, n_roles: int, rng: np.random.Generator) -> None:
        super().reset(n_roles, rng)
        # Auctioned roles: 0 .. n_roles - 1 the formation roles, n_roles the ball role.
        self.holder = np.full(n_roles + 1, -1, dtype=np.int64)
        """Player who won each role most recently (-1: nobody yet)."""
        self.since = np.zeros(n_roles + 1, dtype=np.int64)
        """Cycle at which each role's holder won it."""
        self.last_role = np.full(n_roles, -1, dtype=np.int64)
        """Each player's formation role at the last ``assign`` (-1: none yet)."""
        self._ball_player = None
        self.covered = -1

    def bids(self, players: np.ndarray, targets: np.ndarray, context: RoleContext) -> np.ndarray:
        """(k, k + 1) costs, lower is better: column r < k formation role r, column k the ball role."""
        k = self.check_inputs(players, targets)
        return bid_costs(players, targets, context.ball, context.opp_goal, self._reach(context, k), self._bidding,
                         self._scale(context, k))

    def assign(self, players: np.ndarray, targets: np.ndarray, role_order: np.ndarray,
               previous: np.ndarray | None, context: RoleContext) -> np.ndarray:
        k = self.check_inputs(players, targets)
        self.check_order(role_order, k)
        role_of_player, ball_player, covered = bidding_round(
            players, targets, role_order, context.ball, context.opp_goal, self._reach(context, k), self._bidding,
            self.holder, self.since, self.last_role, context.cycle, self._scale(context, k))
        self._ball_player, self.covered = int(ball_player), int(covered)
        return role_of_player

    def _reach(self, context: RoleContext, k: int) -> np.ndarray:
        """``context.ball_reach`` checked, or an empty array (the kernels then use distances)."""
        reach = context.ball_reach
        if reach is None:
            return _NO_REACH
        if not (isinstance(reach, np.ndarray) and reach.shape == (k,) and reach.dtype == np.float64):
            raise RoleError(f"role assigner 'bidding': context.ball_reach must be a float64 ({k},) array or None, "
                             f"got {type(reach).__name__} {getattr(reach, 'shape', '')}")
        if np.isnan(reach).any():
            raise RoleError("role assigner 'bidding': context.ball_reach holds NaN")
        return reach

    def _scale(self, context: RoleContext, k: int) -> np.ndarray:
        """``context.time_scale`` checked, or an empty array (plain distances)."""
        scale = self.time_scale(context, k)
        return _NO_REACH if scale is None else scale

    def ball_player(self) -> int | None:
        """The winner of the ball role at the last ``assign`` (None before the first)."""
        return self._ball_player

    def steer(self, players: np.ndarray, targets: np.ndarray, role_of_player: np.ndarray,
              context: RoleContext) -> np.ndarray:
        """Supporters one step down the potential field anchored at their role targets (at most
        ``field.max_step`` metres, inside the field); the ball player to its role's target."""
        self.check_inputs(players, targets)
        anchors = targets[role_of_player]
        offensive = anchors[:, 0] >= context.ball[0]
        _, grad = supporter_field(
            players, anchors, offensive, bool(context.attacking), context.ball, context.own_goal,
            context.opp_goal, context.field_half_length, context.field_half_width,
            context.penalty_area_length, context.penalty_area_half_width, self._field)
        goals = descend(players, grad, context.field_half_length, context.field_half_width, self._field)
        if self._ball_player is not None:
            goals[self._ball_player] = anchors[self._ball_player]
        return goals


_NO_REACH = np.empty(0)
