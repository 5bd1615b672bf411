"""Motion rules applied between the teams' commands and the collision solver.

All players are handled at once on (2n, 2) arrays in the absolute frame (player rows as in
:class:`~soccer_sim.state.WorldState`). Units: metres, m/cycle, m/cycle². The rules follow
the RoboCup 2D soccer simulator (rcssserver):

* **Dash**: a team requests an acceleration (any finite length: a request longer than
  ``1e100`` is first shortened to that length, direction kept, so that it cannot overflow);
  the match finds the dash power that gives it,
  ``power = |a| / (dash_power_rate * effort * dir_rate)``, clipped to ``dash_power_max`` and to
  the player's stamina plus ``extra_stamina``, pays that power in stamina, and applies
  ``power * dash_power_rate * effort * dir_rate`` in the requested direction. ``dir_rate`` is
  rcssserver's rule for a dash at angle θ to the body: ``1`` straight ahead falling linearly
  to ``side_dash_rate`` at 90° and changing linearly to ``back_dash_rate`` at 180°. A point
  robot has no body direction, so θ is measured from its direction of motion, weighted by
  ``min(1, speed / dash_heading_speed)`` (a robot at rest dashes equally well every way;
  reversing at speed costs like rcssserver's back dash). The velocity then gets uniform noise
  proportional to its speed and is clipped to ``player_speed_max``.
* **Stamina** (after the dashes, every player): recovery rate and effort fall below their
  thresholds and effort recovers above its own; stamina recovers by ``recovery *
  recovery_per_cycle`` paid from the half's capacity (see config.StaminaConfig). A player
  who sprints until its stamina is spent keeps dashing with ``recover_min *
  recovery_per_cycle + extra_stamina`` power per cycle at ``effort_min``: about 0.44 m/cycle.
* **Kick** (a request longer than ``1e100`` is first shortened like a dash's): a player whose
  centre is within ``kickable_distance`` of the ball's centre may
  change the ball's velocity by at most ``kick_speed_max`` times an effectiveness that loses
  ``kick_distance_penalty`` at the far edge of the kickable margin and ``kick_angle_penalty``
  when kicking straight back through itself. The kicks of one cycle add up and the sum is
  capped at ``kick_speed_max`` (``cap_summed_kicks``); kick noise is proportional to the sum of
  the kicks' own strengths (at most ``kick_speed_max``), so kicks that cancel each other still
  move the ball a little; the ball's speed is clipped to ``ball_speed_max``.
* **Decay**: after the move, velocities are multiplied by the players' and the ball's
  decay; the ball gets noise proportional to its speed.

Noise is uniform in ``[-1, 1)`` per axis, drawn by the caller in one block per cycle so the
random stream does not depend on what happened (see :class:`CycleNoise`).

The per-player rules are compiled loops (numba): written as small numpy calls the dash
alone cost about 15 microseconds per cycle, a third of a cycle's budget; compiled, each
rule costs about one microsecond (mostly the call itself). The kick, applied by a few
players at most, is plain scalar Python.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from soccer_sim.config import MatchConfig

_EPS = 1e-12
_REQUEST_CAP = 1e100
"""Longest dash or kick request the rules work with: a longer one is shortened to this length in
the same direction first. Any request above the physical limits is clipped to them anyway;
shortening it first keeps its length (and the products of the angle rules) from overflowing to
inf, which would turn a dash of 1e160 or a kick of 1.7e308 into none at all."""


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

    def __init__(self, config: MatchConfig, n_players: int | None = None) -> None:
        """``n_players``: player rows of the match (None: two sides of ``config.players_per_team``)."""
        phys, stam = config.physics, config.stamina
        n2 = 2 * config.players_per_team if n_players is None else int(n_players)
        self.phys = phys
        self.kickable_distance = phys.kickable_distance
        self._touch_distance = phys.player_radius + phys.ball_radius
        self._dash_params = np.array([
            phys.dash_power_rate, phys.dash_power_max, phys.side_dash_rate, phys.back_dash_rate,
            phys.dash_heading_speed, stam.extra_stamina, phys.player_speed_max, phys.player_noise,
            stam.maximum, stam.recovery_per_cycle,
            stam.recover_dec_thr * stam.maximum, stam.recover_dec, stam.recover_min,
            stam.effort_dec_thr * stam.maximum, stam.effort_dec, stam.effort_min,
            stam.effort_inc_thr * stam.maximum, stam.effort_inc, stam.effort_max,
        ])
        self._stamina_config = stam
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
        dvx = dvy = strength = 0.0
        bx, by = float(ball[0]), float(ball[1])
        for row in kickers.tolist():
            kx, ky = float(kick[row, 0]), float(kick[row, 1])
            power = math.hypot(kx, ky)
            if power > _REQUEST_CAP:  # huge (or overflowing) request: same direction, finite length
                big = max(abs(kx), abs(ky))
                kx = kx / big * _REQUEST_CAP
                ky = ky / big * _REQUEST_CAP
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
            strength += power * effect
        change = math.hypot(dvx, dvy)
        if change > kick_max and phys.cap_summed_kicks:
            dvx *= kick_max / change
            dvy *= kick_max / change
        # Noise grows with every kick's own strength (as rcssserver draws it per kick), so two
        # opposite kicks that cancel out still leave the ball wandering; never more than the
        # capped change could carry.
        change = min(strength, kick_max) * phys.kick_noise
        vx = float(ball_vel[0]) + dvx + (2.0 * float(noise[0]) - 1.0) * change
        vy = float(ball_vel[1]) + dvy + (2.0 * float(noise[1]) - 1.0) * change
        speed = math.hypot(vx, vy)
        if speed > phys.ball_speed_max:
            vx *= phys.ball_speed_max / speed
            vy *= phys.ball_speed_max / speed
        ball_vel[0] = vx
        ball_vel[1] = vy

    # --- dashes and stamina ----------------------------------------------------------------
    def dash(self, vel: np.ndarray, stamina: np.ndarray, effort: np.ndarray, recovery: np.ndarray,
             capacity: np.ndarray, dash: np.ndarray, noise: np.ndarray) -> float:
        """Apply dash requests ``dash`` (2n, 2; overwritten with the accelerations applied) to
        ``vel``, pay them from ``stamina``, then update every player's stamina model
        (``stamina``, ``effort``, ``recovery``, ``capacity``, all (2n,), in place); return the
        largest resulting player speed (m/cycle)."""
        return _dash_kernel(vel, stamina, effort, recovery, capacity, dash, noise, self._dash_params,
                            self.player_speed)

    def restore(self, stamina: np.ndarray, effort: np.ndarray, recovery: np.ndarray,
                capacity: np.ndarray) -> None:
        """Fresh players (the start of a match and of the second half): stamina at its maximum,
        effort at ``effort_max``, recovery 1, the half's full capacity."""
        stam = self._stamina_config
        stamina[:] = stam.maximum
        effort[:] = stam.effort_max
        recovery[:] = 1.0
        capacity[:] = stam.capacity_or_inf

    # --- decay ------------------------------------------------------------------------------
    def decay(self, vel: np.ndarray, ball_vel: np.ndarray, noise: np.ndarray) -> None:
        """Velocity decay after the move (in place); ball noise proportional to the ball's speed."""
        _decay_kernel(vel, ball_vel, noise, self._decay_params)


@njit(cache=True, nogil=True)
def _dash_kernel(vel: np.ndarray, stamina: np.ndarray, effort: np.ndarray, recovery: np.ndarray,
                 capacity: np.ndarray, dash: np.ndarray, noise: np.ndarray, params: np.ndarray,
                 speed_out: np.ndarray) -> float:  # pragma: no cover - compiled
    """The dash and stamina rules for every player row (see the module docstring); returns the
    top speed. ``params``: see ``Kinematics.__init__`` (power rate, power max, side and back
    dash rates, heading speed, extra stamina, speed max, noise fraction, stamina max and
    increment, recovery threshold/decrement/minimum, effort decrement threshold/decrement/
    minimum, effort increment threshold/increment/maximum)."""
    power_rate, power_max, side_rate, back_rate, heading_speed = params[0], params[1], params[2], params[3], params[4]
    extra, speed_max, noise_frac, stamina_max, inc_max = params[5], params[6], params[7], params[8], params[9]
    rec_thr, rec_dec, rec_min = params[10], params[11], params[12]
    eff_dec_thr, eff_dec, eff_min = params[13], params[14], params[15]
    eff_inc_thr, eff_inc, eff_max = params[16], params[17], params[18]
    request_cap = _REQUEST_CAP
    fastest = 0.0
    for i in range(vel.shape[0]):
        ax, ay = dash[i, 0], dash[i, 1]
        size = math.sqrt(ax * ax + ay * ay)
        if size > request_cap:  # huge (or overflowing) request: same direction, finite length
            big = max(abs(ax), abs(ay))
            ax = ax / big * request_cap
            ay = ay / big * request_cap
            size = math.sqrt(ax * ax + ay * ay)
        vx, vy = vel[i, 0], vel[i, 1]
        if size > 0.0:
            rate = 1.0
            speed = math.sqrt(vx * vx + vy * vy)
            if speed > 0.0:
                cos = min(1.0, max(-1.0, (ax * vx + ay * vy) / (size * speed)))
                angle = math.degrees(math.acos(cos))
                if angle > 90.0:
                    dir_rate = back_rate - (back_rate - side_rate) * (1.0 - (angle - 90.0) / 90.0)
                else:
                    dir_rate = side_rate + (1.0 - side_rate) * (1.0 - angle / 90.0)
                weight = min(1.0, speed / heading_speed)
                rate = 1.0 - weight * (1.0 - dir_rate)
            per_power = power_rate * effort[i] * rate
            power = size / per_power if per_power > 0.0 else 0.0
            power = max(0.0, min(power, power_max, stamina[i] + extra))
            stamina[i] = max(0.0, stamina[i] - power)
            shrink = power * per_power / size
            ax *= shrink
            ay *= shrink
        dash[i, 0] = ax
        dash[i, 1] = ay
        # The stamina model, in rcssserver's order: recovery and effort fall below their
        # thresholds, effort rises above its own, then stamina recovers from the capacity.
        st = stamina[i]
        if st <= rec_thr and recovery[i] > rec_min:
            recovery[i] = max(rec_min, recovery[i] - rec_dec)
        if st <= eff_dec_thr and effort[i] > eff_min:
            effort[i] = max(eff_min, effort[i] - eff_dec)
        if st >= eff_inc_thr and effort[i] < eff_max:
            effort[i] = min(eff_max, effort[i] + eff_inc)
        gain = min(recovery[i] * inc_max, stamina_max - st, capacity[i])
        if gain > 0.0:
            capacity[i] -= gain
            stamina[i] = st + gain
        vx += ax
        vy += ay
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
