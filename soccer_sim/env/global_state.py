"""The environment's global state (``env.state()`` and ``env.state_space``) for centralised critics.

Absolute frame (home, the ``left`` side, kicks off towards +x; the sides change ends at half
time, see ``home attacks``), scaled like the observations (:mod:`soccer_sim.env.spaces`):
positions over the field's half length, velocities over the top speeds, stamina over its
maximum. ``k`` slots per side (the observations' slots, 11 by default); a slot without a
player holds zeros. float32, ``state_size(k)`` values:

=====================  ======  ===============================================================
slice                  size    what
=====================  ======  ===============================================================
``0:6k``               6k      home slots by shirt number: x, y, vx, vy, stamina, on the pitch
``6k:12k``             6k      away slots, the same
next                   4       ball: x, y, vx, vy
next                   2       goals: home, away
next                   1       match time: cycle / total cycles (a fraction)
next                   1       half: 0 first, 1 second
next                   1       home attacks: 1 towards +x, 0 towards -x
next                   9       play mode, one-hot (:class:`~soccer_sim.state.PlayMode` order)
next                   2       whose play mode: home, away (one-hot; both 0 for nobody's)
=====================  ======  ===============================================================

The bounds are those of the observations (goals within the match's cycles); the state is
clipped to them, so it always lies in ``state_space``.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from gymnasium import spaces

from soccer_sim.config import MatchConfig
from soccer_sim.env.spaces import MODES, VELOCITY_BOUND, Scales

PER_PLAYER = 6
_TAIL = 4 + 2 + 1 + 1 + 1 + MODES + 2


def state_size(slots: int) -> int:
    """Values in the global state for ``slots`` slots per side."""
    return 2 * PER_PLAYER * slots + _TAIL


class GlobalState:
    """Builds the normalised global state of a match with sides ``sizes`` and ``slots`` slots."""

    def __init__(self, sizes: tuple[int, int], slots: int, config: MatchConfig) -> None:
        self.sizes, self.slots = sizes, slots
        self.scales = s = Scales.of(config)
        field, physics = config.field, config.physics
        player = (s.length + field.margin) / s.length
        ball = (s.length + field.margin + physics.ball_speed_max) / s.length
        high = np.ones(state_size(slots), dtype=np.float64)
        rows = high[:2 * PER_PLAYER * slots].reshape(2 * slots, PER_PLAYER)
        rows[:, 0:2], rows[:, 2:4] = player, VELOCITY_BOUND
        tail = 2 * PER_PLAYER * slots
        high[tail:tail + 2], high[tail + 2:tail + 4] = ball, VELOCITY_BOUND
        high[tail + 4:tail + 6] = max(config.total_cycles, 1)
        low = np.zeros_like(high)
        low[:2 * PER_PLAYER * slots] = -rows.reshape(-1)
        rows_low = low[:2 * PER_PLAYER * slots].reshape(2 * slots, PER_PLAYER)
        rows_low[:, 4:6] = 0.0
        low[tail:tail + 4] = -high[tail:tail + 4]
        self.space = spaces.Box(low.astype(np.float32), high.astype(np.float32), dtype=np.float32)
        self._tail = tail
        self._buf = np.zeros(state_size(slots), dtype=np.float32)
        self._players = self._buf[:tail].reshape(2, slots, PER_PLAYER)

    def build(self, state: Any) -> np.ndarray:
        """The global state of the world ``state`` (a new float32 array)."""
        s, buf, players = self.scales, self._buf, self._players
        first = (0, self.sizes[0])
        for team in (0, 1):
            n = self.sizes[team]
            rows = slice(first[team], first[team] + n)
            block = players[team, :n]
            block[:, 0:2] = state.pos[rows] / s.length
            block[:, 2:4] = state.vel[rows] / s.player_speed
            block[:, 4] = state.stamina[rows] / s.stamina
            block[:, 5] = state.present[rows]
        t = self._tail
        buf[t:t + 2] = state.ball / s.length
        buf[t + 2:t + 4] = state.ball_vel / s.ball_speed
        buf[t + 4:t + 6] = state.score
        buf[t + 6] = state.cycle / s.total_cycles
        buf[t + 7] = state.half
        buf[t + 8] = state.home_attacks > 0
        modes = buf[t + 9:t + 9 + MODES]
        modes[:] = 0.0
        modes[int(state.play_mode)] = 1.0
        owner = buf[t + 9 + MODES:]
        owner[:] = 0.0
        if state.mode_team in (0, 1):
            owner[state.mode_team] = 1.0
        return np.clip(buf, self.space.low, self.space.high)
