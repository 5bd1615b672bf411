"""Who goes for the ball, and the matching: the built-in team's ``ball_role`` option.

In play on one outfield player (the first to reach the ball, or the assigner's ball player)
runs to the point where it will control the ball. What happens to its formation role:

* ``"keep"``: it stays in the matching like everybody else. The assigner maps all k outfield
  players to the k outfield roles; the ball player's role is then empty while it chases the
  ball (its target far from where it runs).
* ``"leave"``: it leaves the matching. The role it *covers* is the one whose target lies
  nearest its interception point (it plays there anyway); the other k - 1 players are
  assigned by the same assigner to the other k - 1 roles, the ones that matter once the
  ball is taken care of (as UT Austin Villa's positioning does). In ``role_of_player`` the
  ball player holds the covered role, so it stays a permutation of all k roles.

``static`` with ``"leave"`` keeps its shirt numbers but for one swap: the ball player takes
the covered role and the covered role's owner takes the ball player's own role (a plain
static over the k - 1 others would shift several players by one role). ``bidding`` already
takes its ball player out of its formation auction (its *covered* role, see
:mod:`agents.roles.bidding`), so ``"leave"`` does not apply to it (a ValueError). Outside
play on, and when no outfield player goes for the ball (nobody reaches it, or the goalkeeper
does), both options assign all k players.

Team names: ``<assigner>-leave`` is the team with that assigner and ``ball_role="leave"``
(:mod:`agents.teams.builtin`); the plain name keeps the default (:data:`DEFAULT_BALL_ROLE`).
"""

from __future__ import annotations

import numpy as np

from agents.roles import RoleAssigner, RoleContext, make_assigner, offensive_order
from agents.roles.matching import StaticAssigner

BALL_ROLES: tuple[str, ...] = ("keep", "leave")
"""The values of ``TeamStyle.ball_role``."""

DEFAULT_BALL_ROLE = "keep"
"""The built-in team's default (see ``TeamStyle.ball_role`` for why)."""


def check_ball_role(value: object, assigner: str) -> str:
    """``value`` if it is one of :data:`BALL_ROLES` usable with ``assigner``; a ValueError
    naming the problem otherwise."""
    if value not in BALL_ROLES:
        raise ValueError(f"ball_role must be one of {', '.join(map(repr, BALL_ROLES))}, got {value!r}")
    if value == "leave" and assigner == "bidding":
        raise ValueError("ball_role 'leave' does not apply to the 'bidding' assigner: it already takes its "
                         "ball player out of its formation auction")
    return str(value)


def covered_role(targets: np.ndarray, point: np.ndarray) -> int:
    """The role (row of ``targets`` (k, 2)) whose target lies nearest ``point`` (2,), the ball
    player's interception point; ties to the lower role."""
    gaps = (targets[:, 0] - point[0]) ** 2 + (targets[:, 1] - point[1]) ** 2
    return int(np.argmin(gaps))


class LeaveMatching:
    """The ``"leave"`` matching for one match: k - 1 players to k - 1 roles with a second
    instance of the team's assigner (reset for k - 1 roles with the team's generator)."""

    def __init__(self, assigner_name: str, assigner_params: dict) -> None:
        self.static = assigner_name == "static"
        self.assigner: RoleAssigner = make_assigner(assigner_name, **assigner_params)
        self.k = 0

    def reset(self, outfield: np.ndarray, n: int, rng: np.random.Generator) -> None:
        """A new match: ``outfield`` the team rows of the k outfield players (as many roles),
        ``n`` the team's size."""
        k = self.k = len(outfield)
        self._row_of = np.full(n, -1, dtype=np.int64)
        """Team row -> outfield row (-1: the goalkeeper)."""
        self._row_of[outfield] = np.arange(k)
        self._rows = np.arange(k, dtype=np.int64)
        if k > 1 and not isinstance(self.assigner, StaticAssigner):
            self.assigner.reset(k - 1, rng)

    def assign(self, players: np.ndarray, targets: np.ndarray, ball_player: int, points: np.ndarray,
               previous: np.ndarray | None, context: RoleContext) -> np.ndarray | None:
        """``role_of_player`` (k,) with the team's player ``ball_player`` out of the matching,
        holding the role it covers (:func:`covered_role` of its interception point
        ``points[ball_player]``); None when no outfield player goes for the ball (-1, or the
        goalkeeper): then the team assigns everybody."""
        if ball_player < 0 or self._row_of[ball_player] < 0:
            return None
        k, ball_row = self.k, int(self._row_of[ball_player])
        covered = covered_role(targets, points[ball_player])
        if self.static or k == 1:
            roles = self._rows.copy()
            owner = covered  # static: player i holds role i
            roles[owner], roles[ball_row] = roles[ball_row], covered
            return roles
        rows = self._rows[self._rows != ball_row]
        kept = self._rows[self._rows != covered]
        sub_targets = targets[kept]
        assigner = self.assigner
        order = offensive_order(sub_targets) if assigner.uses_role_order else None
        sub_previous = None
        if previous is not None:
            to_sub = np.full(k, -1, dtype=np.int64)
            to_sub[kept] = np.arange(k - 1)
            mapped = to_sub[previous[rows]]
            sub_previous = mapped if (mapped >= 0).all() else None
        scale = context.time_scale
        if scale is not None:
            context.time_scale = scale[rows]
        try:
            sub = assigner.assign(players[rows], sub_targets, order, sub_previous, context)
        finally:
            context.time_scale = scale
        roles = np.empty(k, dtype=np.int64)
        roles[rows] = kept[sub]
        roles[ball_row] = covered
        return roles
