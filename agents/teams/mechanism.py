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
* ``makespan_gap``: the mean of (fixed roles' makespan - minimal makespan), m.

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
def fixed_and_minimal_makespan(players: np.ndarray, targets: np.ndarray) -> tuple[float, float]:  # pragma: no cover - compiled
    """``(fixed, minimal)``: the makespan (m) of player i on target i for ``players`` and
    ``targets`` (k, 2), and the smallest makespan of any assignment (computed on the same
    distances, so ``fixed == minimal`` exactly when the fixed roles are optimal)."""
    minimal, lengths = bottleneck_of_points(players, targets)
    fixed = 0.0
    for i in range(players.shape[0]):
        if lengths[i, i] > fixed:
            fixed = lengths[i, i]
    return fixed, minimal


def sampled(cycle: int) -> bool:
    """Whether a play-on ``cycle`` is a sample."""
    return cycle % SAMPLE_EVERY == 0
