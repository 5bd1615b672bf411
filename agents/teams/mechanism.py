"""Why the role assigner can (or cannot) matter: how far fixed roles are from the best
assignment, sampled during play.

Every :data:`SAMPLE_EVERY`-th cycle of play on (``cycle % SAMPLE_EVERY == 0``, so the sample
is a pure function of the match) the team compares, for its outfield players and their role
targets of that cycle, the *fixed shirt-number roles* (outfield player j on role j, what the
``static`` assigner does) with the *minimal makespan* over all assignments (the bottleneck
value, :func:`agents.assignment.scram.bottleneck_of_points`). Both are distances (m), not
times, whatever the players' types. Reported per match (:class:`~agents.teams.reporting.RoleFigures`):

* ``fixed_roles_optimal_share``: the share of samples in which the fixed roles already have
  the minimal makespan (then no assigner can shorten the longest run);
* ``makespan_gap``: the mean of (fixed roles' makespan - minimal makespan), m;
* ``held_roles_optimal_share`` and ``held_makespan_gap``: the same for the roles the players
  held at the previous cycle (kept as they are; for ``static`` the shirt numbers). Under an
  assigner that moves roles about, shirt numbers say what ``static`` would do from here, the
  held roles whether keeping the current assignment would have been as good.

A pure shift of every target (the formation moving with the ball as one block, players on
their old targets) keeps fixed roles optimal; the figures say how often play is like that.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from agents.assignment.scram import bottleneck_of_points

SAMPLE_EVERY = 10
"""Play-on cycles between two samples: a bottleneck solve every cycle would cost about
0.02 s per match and team for figures that change slowly; one in ten (400-odd samples a
match) estimates the shares to about +-2 %."""


@njit(cache=True, nogil=True)
def makespans(players: np.ndarray, targets: np.ndarray,
              held: np.ndarray) -> tuple[float, float, float]:  # pragma: no cover - compiled
    """``(fixed, kept, minimal)`` makespans (m) for ``players`` and ``targets`` (k, 2): player i
    on target i, player i on target ``held[i]``, and the smallest of any assignment (all on
    the same distances, so a makespan equals ``minimal`` exactly when it is optimal)."""
    minimal, lengths = bottleneck_of_points(players, targets)
    fixed = kept = 0.0
    for i in range(players.shape[0]):
        fixed = max(fixed, lengths[i, i])
        kept = max(kept, lengths[i, held[i]])
    return fixed, kept, minimal


def sampled(cycle: int) -> bool:
    """Whether a play-on ``cycle`` is a sample."""
    return cycle % SAMPLE_EVERY == 0
