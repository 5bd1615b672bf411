"""The body directions a game log shows: :func:`soccer_sim.body.facing` (the simulator's one
body-direction model) for every player with the ball, in one compiled call per cycle."""

from __future__ import annotations

import numpy as np
from numba import njit

from soccer_sim.body import facing


@njit(cache=True, nogil=True)
def facings(pos: np.ndarray, vel: np.ndarray, ball: np.ndarray, inertia_moment: float,
            out: np.ndarray) -> None:  # pragma: no cover - compiled
    """Write into ``out`` (P, 2) the unit vector each player (rows of ``pos``/``vel``) faces
    with the ball at ``ball``, by :func:`soccer_sim.body.facing`."""
    for r in range(pos.shape[0]):
        fx, fy = facing(vel[r, 0], vel[r, 1], ball[0] - pos[r, 0], ball[1] - pos[r, 1], inertia_moment)
        out[r, 0] = fx
        out[r, 1] = fy
