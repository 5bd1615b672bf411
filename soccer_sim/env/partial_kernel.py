"""The compiled per-cycle part of :class:`~soccer_sim.env.partial_spaces.PartialObservationBuilder`:
each agent's memories updated from its own row of the views, and the agent part of its
observation (own state, ball, player slots) written, row by row.

Compiled because a side's 11 rows x 21 seen players cost about 0.15 ms per cycle as numpy
expressions (many small fancy-indexing operations), more than the rest of an environment step.
Each row reads only its own row of every input and writes only its own rows of the memories
and of the output: what keeps one agent's observation free of what another perceives.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

OPPONENT_SIDE = -1
"""``PlayerViews.seen_side`` of an opponent (:data:`soccer_sim.perception.views.OPPONENT`)."""


@njit(cache=True, nogil=True)
def observe_rows(cycle: int, scale: np.ndarray, position: np.ndarray, velocity: np.ndarray, stamina: np.ndarray,
                 body_direction: np.ndarray, saw: np.ndarray, ball_seen: np.ndarray, ball: np.ndarray,
                 seen_count: np.ndarray, seen_position: np.ndarray, seen_side: np.ndarray, seen_number: np.ndarray,
                 goalie: np.ndarray, last_ball: np.ndarray, ball_cycle: np.ndarray, see_cycle: np.ndarray,
                 block: np.ndarray, slots: int, unidentified: int, write: bool,
                 out: np.ndarray) -> None:  # pragma: no cover - compiled
    """Update the memories and (``write``) fill ``out[:, :16 + 6 slots + 4 unidentified]``.

    ``scale`` = (half length m, top player speed m/cycle, stamina maximum, see age cap cycles,
    ball age cap cycles). Positions in the team frame (m), velocities m/cycle, directions degrees.
    Memories: ``last_ball`` (n, 2) m, ``ball_cycle`` and ``see_cycle`` (n,) the cycle of the
    last ball sighting and of the last see, ``block`` (n, 6 slots + 4 unidentified) the player
    slots of the last see (already scaled). Layout: :mod:`soccer_sim.env.partial_spaces`."""
    length, speed, stamina_max, see_cap, ball_cap = scale[0], scale[1], scale[2], scale[3], scale[4]
    width = block.shape[1]
    for p in range(position.shape[0]):
        if ball_seen[p]:
            last_ball[p, 0], last_ball[p, 1] = ball[p, 0], ball[p, 1]
            ball_cycle[p] = cycle
        if saw[p]:
            see_cycle[p] = cycle
            block[p, :] = 0.0
            filled = 0
            for c in range(seen_count[p]):
                number, side = seen_number[p, c], seen_side[p, c]
                x, y = seen_position[p, c, 0] / length, seen_position[p, c, 1] / length
                if number >= 0:
                    if side == 0:
                        continue
                    col = 3 * number + (3 * slots if side == OPPONENT_SIDE else 0)
                    block[p, col], block[p, col + 1], block[p, col + 2] = x, y, 1.0
                elif filled < unidentified:
                    col = 6 * slots + 4 * filled
                    block[p, col], block[p, col + 1], block[p, col + 2], block[p, col + 3] = x, y, side, 1.0
                    filled += 1
        if not write:
            continue
        px, py = position[p, 0] / length, position[p, 1] / length
        out[p, 0], out[p, 1] = px, py
        out[p, 2], out[p, 3] = velocity[p, 0] / speed, velocity[p, 1] / speed
        out[p, 4] = stamina[p] / stamina_max
        out[p, 5] = goalie[p]
        angle = math.radians(body_direction[p])
        out[p, 6], out[p, 7] = math.cos(angle), math.sin(angle)
        out[p, 8] = 1.0 if saw[p] else 0.0
        out[p, 9] = min(cycle - see_cycle[p], see_cap) / see_cap
        bx, by = last_ball[p, 0] / length, last_ball[p, 1] / length
        out[p, 10], out[p, 11], out[p, 12], out[p, 13] = bx, by, bx - px, by - py
        out[p, 14] = min(cycle - ball_cycle[p], ball_cap) / ball_cap
        out[p, 15] = 1.0 if ball_seen[p] else 0.0
        for j in range(width):
            out[p, 16 + j] = block[p, j]
        own = 16 + 3 * p  # its own team-mate slot: its number is its row
        out[p, own], out[p, own + 1], out[p, own + 2] = px, py, 1.0
