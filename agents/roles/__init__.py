"""Role assigners of the built-in team: which outfield player takes which formation role.

Team-relative frame throughout (we attack +x, our goal at ``x = -half_length``), metres,
cycles of 100 ms.

**The interface** (:class:`RoleAssigner`, :mod:`agents.roles.base`)::

    assigner = make_assigner("bidding", min_hold=5)      # by name, with parameters
    assigner.reset(n_roles, rng)                         # once per match; rng: the team's Generator
    # every cycle:
    order = offensive_order(targets)                     # roles by target x descending, ties by index
    role_of_player = assigner.assign(players, targets, order, previous, context)
    goals = assigner.steer(players, targets, role_of_player, context)
    ball_row = assigner.ball_player()                    # or None: the team picks its ball player

* ``players`` (k, 2) and ``targets`` (k, 2) float64: the k outfield players' positions and
  the k outfield roles' targets (row r = role r), 1 <= k; the same k as ``reset``;
* ``role_order`` (k,): role indices most offensive first (:func:`offensive_order`); an
  assigner that ignores it sets ``uses_role_order = False`` and may then be given None;
* ``previous`` (k,): last cycle's ``role_of_player`` or None;
* ``context`` (:class:`RoleContext`): ball (the predicted control point, if the team has
  one), goals, opponents, field size, penalty area, cycle and whether we attack;
* ``assign`` returns ``role_of_player`` (k,) int64, a permutation of ``range(k)``: player row
  i takes role ``role_of_player[i]``; the array is the caller's;
* ``steer`` returns (k, 2) points to move to (default: each player's role target);
* ``ball_player()`` the row the assigner sends to the ball, or None (the default).

Wrong shapes, a ``role_order`` that is not a permutation, or ``assign`` before ``reset``
raise :class:`RoleError` (an :class:`~agents.errors.AgentsError` and a ValueError) naming the
assigner and the problem. Every assigner is deterministic given
the generator given to ``reset`` (only ``random`` draws from it).

**The assigners** (:data:`ASSIGNERS`, :func:`assigner_names`, :func:`make_assigner`):

==================  ============================================================================
name                rule
==================  ============================================================================
``static``          role i to player i (shirt-number roles, as agent2d/helios-base teams)
``greedy``          repeatedly the shortest remaining player-role pair (:mod:`agents.assignment`)
``greedy-offense``  roles most offensive first, each to the nearest free player
``mmdr``            SCRAM's minimal-makespan lexicographic bottleneck ("SCRAM: Scalable
                    Collision-avoiding Role Assignment with Minimal-makespan for Formational
                    Positioning"), through :func:`agents.assignment.assign`
``mmd+msd2``        SCRAM's minimal makespan, then the least sum of squared distances
``msd``, ``msd2``   least sum of distances / of squared distances
``random``          a fresh uniformly random permutation every call (from the reset generator)
``bidding``         potential-field bidding ("Dynamic multi-robot coordination", Vail and
                    Veloso): a ball role and the formation roles auctioned in priority order
                    with hysteresis; names the ball player and steers the supporters down a
                    potential field (:mod:`agents.roles.bidding`,
                    :mod:`agents.roles.potential_field`). Parameters: the fields of
                    :class:`BiddingParams` and :class:`FieldParams`, e.g. ``min_hold=5``.
==================  ============================================================================

Only ``bidding`` takes parameters and only it overrides ``ball_player``/``steer``. Times per
call for k = 10: ``python -m agents.roles.timing`` (:mod:`agents.roles.timing`).
"""

from __future__ import annotations

import inspect
from collections.abc import Callable

from agents.roles.base import RoleAssigner, RoleContext, offensive_order
from agents.roles.bidding import BiddingAssigner, BiddingParams
from agents.roles.errors import RoleError
from agents.roles.matching import GreedyOffenseAssigner, MethodAssigner, RandomAssigner, StaticAssigner
from agents.roles.field_params import FieldParams


def _method(method: str) -> Callable[[], RoleAssigner]:
    def make() -> RoleAssigner:
        return MethodAssigner(method)

    make.__doc__ = f"An assigner using agents.assignment's {method!r} method."
    return make


ASSIGNERS: dict[str, Callable[..., RoleAssigner]] = {
    "static": StaticAssigner,
    "greedy": _method("greedy"),
    "greedy-offense": GreedyOffenseAssigner,
    "mmdr": _method("mmdr"),
    "mmd+msd2": _method("mmd+msd2"),
    "msd": _method("msd"),
    "msd2": _method("msd2"),
    "random": RandomAssigner,
    "bidding": BiddingAssigner,
}
"""Assigner name -> factory (called with the keyword parameters, for those that take any)."""

def assigner_names() -> tuple[str, ...]:
    """The registered assigner names, in registration order."""
    return tuple(ASSIGNERS)


def make_assigner(name: str, **params: object) -> RoleAssigner:
    """A new assigner called ``name`` (see :data:`ASSIGNERS`) with keyword ``params``.

    Raises:
        RoleError: (a ValueError) for an unknown name (the message lists the known ones), parameters given
            to an assigner that takes none, or unknown or invalid parameter values.
    """
    factory = ASSIGNERS.get(name)
    if factory is None:
        raise RoleError(f"unknown role assigner {name!r}; known: {', '.join(ASSIGNERS)}")
    try:
        inspect.signature(factory).bind(**params)
    except TypeError as exc:
        raise RoleError(f"role assigner {name!r} does not take parameters {', '.join(sorted(params))}: {exc}") from None
    return factory(**params)


__all__ = [
    "ASSIGNERS", "BiddingAssigner", "BiddingParams", "FieldParams", "RoleAssigner", "RoleContext", "RoleError",
    "assigner_names", "make_assigner", "offensive_order",
]
