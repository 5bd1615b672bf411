"""The compiled per-cycle part of :class:`~soccer_sim.env.partial_spaces.PartialObservationBuilder`:
each agent's memories updated from its own row of the views, and the agent part of its
observation (own state, ball, player slots) written, row by row.

Compiled because a side's 11 rows x 21 seen players cost about 0.15 ms per cycle as numpy
expressions (many small fancy-indexing operations), more than the rest of an environment step.
Each row reads only its own row of every input and writes only its own rows of the memories
and of the output: what keeps one agent's observation free of what another perceives.

The scales and slot counts travel as a named record (:data:`OBSERVATION_PARAMS`), the views'
arrays and the memories as named tuples (:class:`ViewRows`, :class:`Memories`), each read by
field name.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

OPPONENT_SIDE = -1
"""``PlayerViews.seen_side`` of an opponent (:data:`soccer_sim.perception.views.OPPONENT`)."""

OBSERVATION_PARAMS = np.dtype(
    [(name, np.float64) for name in ("length", "speed", "stamina_max", "see_cap", "ball_cap")]
    + [("slots", np.int64), ("unidentified", np.int64)])
"""The observation's divisors and slots: half the field's length (m), the top player speed
(m/cycle), the stamina maximum, the see age and ball age caps (cycles), and the numbered slots
per team and the unidentified slots (:mod:`soccer_sim.env.partial_spaces`)."""


class ViewRows(NamedTuple):
    """The arrays of a team's :class:`~soccer_sim.perception.views.PlayerViews` that
    :func:`observe_rows` reads (team frame: m, m/cycle, degrees)."""

    position: np.ndarray
    velocity: np.ndarray
    stamina: np.ndarray
    body_direction: np.ndarray
    saw: np.ndarray
    ball_seen: np.ndarray
    ball: np.ndarray
    seen_count: np.ndarray
    seen_position: np.ndarray
    seen_side: np.ndarray
    seen_number: np.ndarray


class Memories(NamedTuple):
    """Each agent's memories (one row each, only its own row written by it)."""

    last_ball: np.ndarray
    """(n, 2) m where it last saw the ball."""
    ball_cycle: np.ndarray
    """(n,) the cycle of its last ball sighting."""
    see_cycle: np.ndarray
    """(n,) the cycle of its last see."""
    block: np.ndarray
    """(n, 6 slots + 4 unidentified) the player slots of its last see (already scaled)."""


@njit(cache=True, nogil=True)
def observe_rows(cycle: int, params: np.ndarray, views: ViewRows, goalie: np.ndarray, memory: Memories, write: bool,
                 out: np.ndarray) -> None:  # pragma: no cover - compiled
    """Update the ``memory`` with the ``views`` of ``cycle`` and (``write``) fill
    ``out[:, :16 + 6 slots + 4 unidentified]``; ``params``: an :data:`OBSERVATION_PARAMS`
    record; ``goalie`` (n,) 1 for the goalkeeper's row. Layout: :mod:`soccer_sim.env.partial_spaces`."""
    p = params[0]
    length, speed, stamina_max, see_cap, ball_cap = p.length, p.speed, p.stamina_max, p.see_cap, p.ball_cap
    slots, unidentified = p.slots, p.unidentified
    position, velocity, stamina, body_direction = views.position, views.velocity, views.stamina, views.body_direction
    saw, ball_seen, ball, seen_count = views.saw, views.ball_seen, views.ball, views.seen_count
    seen_position, seen_side, seen_number = views.seen_position, views.seen_side, views.seen_number
    last_ball, ball_cycle, see_cycle, block = memory.last_ball, memory.ball_cycle, memory.see_cycle, memory.block
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
