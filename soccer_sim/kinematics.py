"""Motion rules applied between the teams' commands and the collision solver.

All players are handled at once on (2n, 2) arrays in the absolute frame (player rows as in
:class:`~soccer_sim.state.WorldState`). Units: metres, m/cycle, m/cycle². The rules follow
the RoboCup 2D soccer simulator's model:

* **Dash**: the requested acceleration is clipped to ``player_accel_max`` times an effort
  that falls linearly from 1 to ``min_effort`` as stamina drops below ``tired_fraction`` of
  the maximum; stamina pays ``cost_per_accel`` per m/cycle² and recovers every cycle; the
  velocity gets the acceleration, gets uniform noise proportional to its speed and is
  clipped to ``player_speed_max``. Stamina never drops below zero before the recovery.
* **Kick**: a player whose centre is within ``kickable_distance`` of the ball's centre may
  change the ball's velocity by at most ``kick_speed_max`` times an effectiveness that loses
  ``kick_distance_penalty`` at the far edge of the kickable margin and ``kick_angle_penalty``
  when kicking straight back through itself. Kicks of several players add up; kick noise is
  proportional to the total change; the ball's speed is clipped to ``ball_speed_max``.
* **Decay**: after the move, velocities are multiplied by the players' and the ball's
  decay; the ball gets noise proportional to its speed.

Noise is uniform in ``[-1, 1)`` per axis, drawn by the caller in one block per cycle so the
random stream does not depend on what happened (see :class:`CycleNoise`).

The per-player rules are compiled loops (numba): written as some twenty small numpy calls
the dash alone cost about 15 microseconds per cycle, a third of a cycle's budget; compiled,
each rule costs about one microsecond (mostly the call itself). The kick, applied by a few
players at most, is plain scalar Python.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from soccer_sim.config import MatchConfig

_EPS = 1e-12


class CycleNoise:
    """All random numbers of one cycle, drawn in a single call from the physics generator.

    ``players`` (2n, 2) movement noise, ``kick`` (2,), ``ball`` (2,): uniform in [0, 1),
    mapped to [-1, 1) where they are used. Drawing a fixed amount every cycle keeps the
    stream aligned whatever happens.
    """

    def __init__(self, rng: np.random.Generator, n_players: int) -> None:
        self._rng = rng
        self.values = np.empty((n_players + 2, 2), dtype=np.float64)
        self.players = self.values[:n_players]
        self.kick = self.values[n_players]
        self.ball = self.values[n_players + 1]

    def draw(self) -> None:
        self._rng.random(out=self.values)


class Kinematics:
    """Dash, kick and decay rules for one match configuration (preallocated buffers)."""

    def __init__(self, config: MatchConfig) -> None:
        phys, stam = config.physics, config.stamina
        n2 = 2 * config.players_per_team
        self.phys = phys
        self.kickable_distance = phys.kickable_distance
        self._touch_distance = phys.player_radius + phys.ball_radius
        # Acceleration limit = min(slope * stamina + base, accel_max): the effort ramp below
        # tired_fraction * maximum, written as one affine map.
        tired = stam.tired_fraction * stam.maximum
        if tired > 0:
            slope = phys.player_accel_max * (1.0 - stam.min_effort) / tired
            base = phys.player_accel_max * stam.min_effort
        else:
            slope, base = 0.0, phys.player_accel_max
        self._dash_params = np.array([
            slope, base, phys.player_accel_max, stam.cost_per_accel, stam.recovery_per_cycle,
            stam.maximum, phys.player_speed_max, phys.player_noise,
        ])
        self._decay_params = np.array([phys.player_decay, phys.ball_decay, phys.ball_noise, phys.ball_speed_max])
        self.ball_distance = np.empty(n2)
        """Centre distance of every player to the ball (m), from the last :meth:`kick_candidates`."""
        self.player_speed = np.empty(n2)
        """Speed of each player after the last :meth:`dash` (m/cycle)."""

    # --- kicks ------------------------------------------------------------------------------
    def kick_candidates(self, pos: np.ndarray, ball: np.ndarray, kick: np.ndarray, mask: np.ndarray,
                        holder: int, rows_out: np.ndarray) -> tuple[int, float]:
        """Find the players that kick this cycle: allowed by ``mask``, ball centre within
        ``kickable_distance`` (or holding it: row ``holder``), and a non-zero kick request.

        Writes their rows into ``rows_out[:count]`` and the centre distances of every player to
        the ball into :attr:`ball_distance`; returns (count, distance of the nearest player).
        """
        return _kick_candidates(pos, ball, kick, mask, holder, self.kickable_distance, self.ball_distance, rows_out)

    def kick(self, kickers: np.ndarray, pos: np.ndarray, ball: np.ndarray, ball_vel: np.ndarray,
             kick: np.ndarray, dist: np.ndarray, holder: int, noise: np.ndarray) -> None:
        """Apply the kicks of the player rows ``kickers`` to ``ball_vel`` (in place).

        ``dist`` holds the centre distances (:attr:`ball_distance`); a holding goalkeeper
        (row ``holder``) kicks without distance or angle penalty.
        """
        phys = self.phys
        kick_max = phys.kick_speed_max
        margin = phys.kickable_margin
        dvx = dvy = 0.0
        bx, by = float(ball[0]), float(ball[1])
        for row in kickers.tolist():
            kx, ky = float(kick[row, 0]), float(kick[row, 1])
            power = math.hypot(kx, ky)
            if power > kick_max:
                kx *= kick_max / power
                ky *= kick_max / power
                power = kick_max
            effect = 1.0
            if row != holder:
                gap = max(0.0, float(dist[row]) - self._touch_distance)
                effect -= phys.kick_distance_penalty * min(1.0, gap / margin)
                rx, ry = bx - float(pos[row, 0]), by - float(pos[row, 1])
                rnorm = math.hypot(rx, ry)
                if rnorm > _EPS and power > _EPS:
                    cos = (rx * kx + ry * ky) / (rnorm * power)
                    angle = math.acos(max(-1.0, min(1.0, cos)))
                    effect -= phys.kick_angle_penalty * angle / math.pi
            dvx += kx * effect
            dvy += ky * effect
        change = math.hypot(dvx, dvy) * phys.kick_noise
        vx = float(ball_vel[0]) + dvx + (2.0 * float(noise[0]) - 1.0) * change
        vy = float(ball_vel[1]) + dvy + (2.0 * float(noise[1]) - 1.0) * change
        speed = math.hypot(vx, vy)
        if speed > phys.ball_speed_max:
            vx *= phys.ball_speed_max / speed
            vy *= phys.ball_speed_max / speed
        ball_vel[0] = vx
        ball_vel[1] = vy

    # --- dashes -----------------------------------------------------------------------------
    def dash(self, vel: np.ndarray, stamina: np.ndarray, dash: np.ndarray, noise: np.ndarray) -> float:
        """Apply dash requests ``dash`` (2n, 2; clipped in place to what was applied) to ``vel``
        and ``stamina`` (in place); return the largest resulting player speed (m/cycle)."""
        return _dash_kernel(vel, stamina, dash, noise, self._dash_params, self.player_speed)

    # --- decay ------------------------------------------------------------------------------
    def decay(self, vel: np.ndarray, ball_vel: np.ndarray, noise: np.ndarray) -> None:
        """Velocity decay after the move (in place); ball noise proportional to the ball's speed."""
        _decay_kernel(vel, ball_vel, noise, self._decay_params)


@njit(cache=True, nogil=True)
def _dash_kernel(vel: np.ndarray, stamina: np.ndarray, dash: np.ndarray, noise: np.ndarray,
                 params: np.ndarray, speed_out: np.ndarray) -> float:  # pragma: no cover - compiled
    """The dash rule for every player row (see the module docstring); returns the top speed.

    ``params``: limit slope and base (acceleration limit per unit stamina and at zero
    stamina), accel_max, stamina cost per m/cycle², recovery per cycle, stamina maximum,
    speed_max, movement noise fraction.
    """
    slope, base, accel_max, cost, recovery, stamina_max, speed_max, noise_frac = (
        params[0], params[1], params[2], params[3], params[4], params[5], params[6], params[7])
    fastest = 0.0
    for i in range(vel.shape[0]):
        ax, ay = dash[i, 0], dash[i, 1]
        size = math.sqrt(ax * ax + ay * ay)
        limit = min(stamina[i] * slope + base, accel_max)
        if size > limit:
            shrink = limit / size
            ax *= shrink
            ay *= shrink
            size = limit
        dash[i, 0] = ax
        dash[i, 1] = ay
        stamina[i] = min(max(stamina[i] - size * cost, 0.0) + recovery, stamina_max)
        vx = vel[i, 0] + ax
        vy = vel[i, 1] + ay
        amount = math.sqrt(vx * vx + vy * vy) * noise_frac
        vx += (2.0 * noise[i, 0] - 1.0) * amount
        vy += (2.0 * noise[i, 1] - 1.0) * amount
        speed = math.sqrt(vx * vx + vy * vy)
        if speed > speed_max:
            vx *= speed_max / speed
            vy *= speed_max / speed
            speed = speed_max
        vel[i, 0] = vx
        vel[i, 1] = vy
        speed_out[i] = speed
        if speed > fastest:
            fastest = speed
    return fastest


@njit(cache=True, nogil=True)
def _kick_candidates(pos: np.ndarray, ball: np.ndarray, kick: np.ndarray, mask: np.ndarray, holder: int,
                     kickable: float, dist_out: np.ndarray, rows_out: np.ndarray) -> tuple[int, float]:  # pragma: no cover
    bx, by = ball[0], ball[1]
    count = 0
    nearest = np.inf
    for i in range(pos.shape[0]):
        dx, dy = bx - pos[i, 0], by - pos[i, 1]
        d = math.sqrt(dx * dx + dy * dy)
        dist_out[i] = d
        if d < nearest:
            nearest = d
        if mask[i] and (d <= kickable or i == holder) and (kick[i, 0] != 0.0 or kick[i, 1] != 0.0):
            rows_out[count] = i
            count += 1
    return count, nearest


@njit(cache=True, nogil=True)
def _decay_kernel(vel: np.ndarray, ball_vel: np.ndarray, noise: np.ndarray,
                  params: np.ndarray) -> None:  # pragma: no cover - compiled
    """``params``: player decay, ball decay, ball noise fraction, ball speed limit."""
    player_decay, ball_decay, ball_noise, ball_max = params[0], params[1], params[2], params[3]
    for i in range(vel.shape[0]):
        vel[i, 0] *= player_decay
        vel[i, 1] *= player_decay
    vx = ball_vel[0] * ball_decay
    vy = ball_vel[1] * ball_decay
    amount = math.sqrt(vx * vx + vy * vy) * ball_noise
    vx += (2.0 * noise[0] - 1.0) * amount
    vy += (2.0 * noise[1] - 1.0) * amount
    speed = math.sqrt(vx * vx + vy * vy)
    if speed > ball_max:
        vx *= ball_max / speed
        vy *= ball_max / speed
    ball_vel[0] = vx
    ball_vel[1] = vy
