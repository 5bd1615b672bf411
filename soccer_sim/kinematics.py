"""Motion rules applied between the teams' commands and the collision solver.

All players are handled at once on (2n, 2) arrays in the absolute frame; the ball with
scalar math (one body: plain floats are cheaper than numpy calls). Units: metres, m/cycle,
m/cycle². The rules follow the RoboCup 2D soccer simulator's model:

* **Dash**: the requested acceleration is clipped to ``player_accel_max`` times an effort
  that falls linearly from 1 to ``min_effort`` as stamina drops below ``tired_fraction`` of
  the maximum; stamina pays ``cost_per_accel`` per m/cycle² and recovers every cycle; the
  velocity gets the acceleration, is clipped to ``player_speed_max`` and gets uniform noise
  proportional to its speed.
* **Kick**: a player whose centre is within ``kickable_distance`` of the ball's centre may
  change the ball's velocity by at most ``kick_speed_max`` times an effectiveness that loses
  ``kick_distance_penalty`` at the far edge of the kickable margin and ``kick_angle_penalty``
  when kicking straight back through itself. Kicks of several players add up; kick noise is
  proportional to the total change; the ball's speed is clipped to ``ball_speed_max``.
* **Decay**: after the move, velocities are multiplied by the players' and the ball's
  decay; the ball gets noise proportional to its speed.

Noise is uniform in ``[-1, 1)`` per axis, drawn by the caller in one block per cycle so the
random stream does not depend on what happened (see :class:`CycleNoise`).
"""

from __future__ import annotations

import math

import numpy as np

from soccer_sim.config import MatchConfig

_EPS = 1e-12


class CycleNoise:
    """All random numbers of one cycle, drawn in a single call from the physics generator.

    ``players`` (2n, 2) movement noise, ``kick`` (2,), ``ball`` (2,): uniform in [-1, 1).
    Drawing a fixed amount every cycle keeps the stream aligned whatever happens.
    """

    def __init__(self, rng: np.random.Generator, n_players: int) -> None:
        self._rng = rng
        self._raw = np.empty((n_players + 2, 2), dtype=np.float64)
        self.values = np.empty_like(self._raw)
        self.players = self.values[:n_players]
        self.kick = self.values[n_players]
        self.ball = self.values[n_players + 1]

    def draw(self) -> None:
        self._rng.random(out=self._raw)
        np.multiply(self._raw, 2.0, out=self.values)
        self.values -= 1.0


class Kinematics:
    """Dash, kick and decay rules for one match configuration (preallocated buffers)."""

    def __init__(self, config: MatchConfig) -> None:
        phys, stam = config.physics, config.stamina
        n2 = 2 * config.players_per_team
        self.phys = phys
        self.kickable_distance = phys.kickable_distance
        self._touch_distance = phys.player_radius + phys.ball_radius
        # Effort = clip(effort_slope * stamina + min_effort, ..., 1): the linear ramp below
        # tired_fraction * maximum, written as one affine map (acceleration limit units).
        tired = stam.tired_fraction * stam.maximum
        if tired > 0:
            self._limit_slope = phys.player_accel_max * (1.0 - stam.min_effort) / tired
        else:
            self._limit_slope = math.inf
        self._limit_base = phys.player_accel_max * stam.min_effort
        self._accel_max = phys.player_accel_max
        self._stamina_cost = stam.cost_per_accel
        self._stamina_recovery = stam.recovery_per_cycle
        self._stamina_max = stam.maximum
        self._rel = np.empty((n2, 2))
        self._dist = np.empty(n2)
        self._norm = np.empty(n2)
        self._limit = np.empty(n2)
        self.player_speed = np.empty(n2)
        """Speed of each player after the last :meth:`dash` (m/cycle)."""

    # --- kicks ------------------------------------------------------------------------------
    def ball_distances(self, pos: np.ndarray, ball: np.ndarray) -> np.ndarray:
        """Centre distance of every player to the ball (m); the returned buffer is reused."""
        rel = np.subtract(ball, pos, out=self._rel)
        return np.hypot(rel[:, 0], rel[:, 1], out=self._dist)

    def kick(self, kickers: np.ndarray, pos: np.ndarray, ball: np.ndarray, ball_vel: np.ndarray,
             kick: np.ndarray, dist: np.ndarray, holder: int, noise: np.ndarray) -> None:
        """Apply the kicks of the player rows ``kickers`` to ``ball_vel`` (in place).

        ``dist`` holds the centre distances from :meth:`ball_distances`; a holding goalkeeper
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
        vx = float(ball_vel[0]) + dvx + float(noise[0]) * change
        vy = float(ball_vel[1]) + dvy + float(noise[1]) * change
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
        norm = np.hypot(dash[:, 0], dash[:, 1], out=self._norm)
        limit = np.multiply(stamina, self._limit_slope, out=self._limit)
        limit += self._limit_base
        np.minimum(limit, self._accel_max, out=limit)
        # scale = min(1, limit / |a|): shrink only requests above the limit.
        np.maximum(norm, _EPS, out=norm)
        np.divide(limit, norm, out=limit)
        np.minimum(limit, 1.0, out=limit)
        dash *= limit[:, None]
        # Stamina pays for the applied acceleration |a| * scale.
        np.multiply(norm, limit, out=norm)
        norm *= self._stamina_cost
        stamina -= norm
        stamina += self._stamina_recovery
        np.clip(stamina, 0.0, self._stamina_max, out=stamina)
        vel += dash
        return self._limit_speed(vel, noise)

    def _limit_speed(self, vel: np.ndarray, noise: np.ndarray) -> float:
        phys = self.phys
        speed = np.hypot(vel[:, 0], vel[:, 1], out=self.player_speed)
        # Noise proportional to the speed, then the hard limit.
        noisy = np.multiply(noise, speed[:, None] * phys.player_noise, out=self._rel)
        vel += noisy
        np.hypot(vel[:, 0], vel[:, 1], out=speed)
        scale = np.divide(phys.player_speed_max, np.maximum(speed, phys.player_speed_max, out=self._limit), out=self._limit)
        vel *= scale[:, None]
        np.multiply(speed, scale, out=speed)
        return float(speed.max())

    # --- decay ------------------------------------------------------------------------------
    def decay(self, vel: np.ndarray, ball_vel: np.ndarray, noise: np.ndarray) -> None:
        """Velocity decay after the move; ball noise proportional to the ball's speed."""
        phys = self.phys
        vel *= phys.player_decay
        vx = float(ball_vel[0]) * phys.ball_decay
        vy = float(ball_vel[1]) * phys.ball_decay
        speed = math.hypot(vx, vy)
        amount = speed * phys.ball_noise
        vx += float(noise[0]) * amount
        vy += float(noise[1]) * amount
        speed = math.hypot(vx, vy)
        if speed > phys.ball_speed_max:
            vx *= phys.ball_speed_max / speed
            vy *= phys.ball_speed_max / speed
        ball_vel[0] = vx
        ball_vel[1] = vy
