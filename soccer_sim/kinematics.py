"""Motion rules applied between the teams' commands and the collision solver.

All players are handled at once on (2n, 2) arrays in the absolute frame (player rows as in
:class:`~soccer_sim.state.WorldState`). Units: metres, m/cycle, m/cycle². The rules follow
the RoboCup 2D soccer simulator (rcssserver):

* **Dash**: a team requests an acceleration (any finite length: a request longer than
  ``1e100`` is first shortened to that length, direction kept, so that it cannot overflow);
  the match finds the dash power that gives it,
  ``power = |a| / (dash_power_rate * effort * dir_rate)``, clipped to ``dash_power_max`` and to
  the player's stamina plus ``extra_stamina``, pays that power in stamina, and applies
  ``power * dash_power_rate * effort * dir_rate`` in the requested direction (any direction:
  rcssserver 19 rounds dash directions to ``dash_angle_step``, 1°). ``dir_rate`` is
  rcssserver's rule for a dash at angle θ to the body: ``1`` straight ahead falling linearly
  to ``side_dash_rate`` at 90° and changing linearly to ``back_dash_rate`` at 180°. A point
  robot has no body direction, so θ is measured from its direction of motion, weighted by
  ``min(1, speed / dash_heading_speed)`` (a robot at rest dashes equally well every way;
  reversing at speed costs like rcssserver's back dash). The velocity is clipped to
  ``player_speed_max``, then gets rcssserver's movement noise (``player_rand``).
* **Stamina** (after the dashes, every player): recovery rate and effort fall below their
  thresholds and effort recovers above its own; stamina recovers by ``recovery *
  recovery_per_cycle`` paid from the half's capacity (see config.StaminaConfig). A player
  who sprints until its stamina is spent keeps dashing with ``recover_min *
  recovery_per_cycle + extra_stamina`` power per cycle at ``effort_min``: 0.435 m/cycle
  (rcssserver 17/18's figure; see docs/simulator.md for rcssserver 19's 0.468).
* **Kick** (rcssserver's ``Player::kick``; a request longer than ``1e100`` is first
  shortened like a dash's): a player whose centre is within ``kickable_distance`` of the
  ball's centre may change the ball's velocity by its request clipped to ``kick_speed_max``
  (a kick of power ``|request| / kick_speed_max * 100``) times
  ``1 - kick_angle_penalty * dir_diff / 180° - kick_distance_penalty * dist_ball /
  kickable_margin``: ``dir_diff`` is the angle between where the player's body faces
  (:mod:`soccer_sim.body`, from its velocity before the dash) and the direction to the ball,
  ``dist_ball`` the gap between the two surfaces. The penalty is for where the ball lies,
  not for where it is sent. Each kick adds rcssserver's kick noise (``kick_rand``, growing
  with ``dir_diff``, ``dist_ball``, the ball's speed and the kick's power); the kicks of one
  cycle add up, the sum is capped at ``kick_speed_max`` (``cap_summed_kicks``; rcssserver's
  ``ball_accel_max``) and the ball's speed at ``ball_speed_max``.
* **Movement noise** (every cycle, before the move): every player's and the ball's velocity
  gets a random vector of length uniform in ``[0, rand * speed]`` and uniform direction
  (``player_rand``, ``ball_rand``; rcssserver's ``MPObject::noise``).
* **Decay**: after the move, velocities are multiplied by the players' and the ball's decay.

**Player types**: each player's own ``dash_power_rate``, ``player_speed_max``, stamina
recovery, ``extra_stamina``, effort bounds, ``player_decay``, ``kickable_margin``,
``kick_rand`` and ``inertia_moment`` come from a per-player table (:attr:`Kinematics.types`,
rows of :mod:`soccer_sim.player_types`' types); every player is of the default type (the
config's values) until :meth:`Kinematics.set_types`.

Random numbers are uniform in ``[0, 1)``, drawn by the caller in one block per cycle so the
random stream does not depend on what happened (see :class:`CycleNoise`).

The per-player rules are compiled loops (numba, in :mod:`soccer_sim.kernels`): written as
small numpy calls the dash alone cost about 15 microseconds per cycle, a third of a cycle's
budget; compiled, each rule costs about one microsecond (mostly the call itself).
"""

from __future__ import annotations

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.kernels import (DASH_PARAMS, DECAY_PARAMS, KICK_PARAMS, PT_COLUMNS, PT_DASH_POWER_RATE, PT_DECAY,
                                PT_EFFORT_MAX, PT_EFFORT_MIN, PT_EXTRA_STAMINA, PT_INERTIA_MOMENT, PT_KICK_RAND,
                                PT_CATCH_STRETCH,
                                PT_KICKABLE, PT_KICKABLE_MARGIN, PT_SPEED_MAX, PT_STAMINA_INC, apply_kicks,
                                dash_players, decay_velocities, find_kickers, make_record)
from soccer_sim.player_types import PlayerType, default_type


class CycleNoise:
    """All random numbers of one cycle, drawn in a single call from the physics generator.

    Uniform in [0, 1); each body's pair is (length draw, direction draw) of rcssserver's polar
    noise. ``motion`` (P + 1, 2): the players' movement noise then the ball's (``players``
    and ``ball`` are its parts); ``kick`` (P, 2): each player's kick noise, used when it
    kicks. Drawing a fixed amount every cycle keeps the stream aligned whatever happens.
    """

    def __init__(self, rng: np.random.Generator, n_players: int) -> None:
        self._rng = rng
        self.values = np.empty((2 * n_players + 1, 2), dtype=np.float64)
        self.motion = self.values[:n_players + 1]
        self.players = self.values[:n_players]
        self.ball = self.values[n_players]
        self.kick = self.values[n_players + 1:]

    def draw(self) -> None:
        self._rng.random(out=self.values)


class Kinematics:
    """Dash, kick and decay rules for one match configuration (preallocated buffers)."""

    def __init__(self, config: MatchConfig, n_players: int) -> None:
        """``n_players``: player rows of the match, both sides together."""
        phys, stam = config.physics, config.stamina
        n2 = int(n_players)
        self.phys = phys
        self._touch_distance = phys.player_radius + phys.ball_radius
        self._dash_params = make_record(
            DASH_PARAMS, power_max=phys.dash_power_max,
            side_rate=phys.side_dash_rate, back_rate=phys.back_dash_rate, heading_speed=phys.dash_heading_speed,
            player_rand=phys.player_rand, ball_rand=phys.ball_rand, stamina_max=stam.maximum,
            recover_dec_thr=stam.recover_dec_thr * stam.maximum, recover_dec=stam.recover_dec,
            recover_min=stam.recover_min, effort_dec_thr=stam.effort_dec_thr * stam.maximum,
            effort_dec=stam.effort_dec, effort_inc_thr=stam.effort_inc_thr * stam.maximum, effort_inc=stam.effort_inc)
        self._stamina_config = stam
        self._decay_params = make_record(DECAY_PARAMS, ball_decay=phys.ball_decay)
        self._kick_params = make_record(
            KICK_PARAMS, kick_max=phys.kick_speed_max, ball_speed_max=phys.ball_speed_max,
            touch_distance=self._touch_distance,
            angle_penalty=phys.kick_angle_penalty, distance_penalty=phys.kick_distance_penalty,
            speed_rate_scale=0.5 / (phys.ball_speed_max * phys.ball_decay), cap_sum=phys.cap_summed_kicks)
        self.types = np.empty((n2, PT_COLUMNS), dtype=np.float64)
        """Each player row's type parameters (``PT_*`` columns of :mod:`soccer_sim.kernels`);
        every player of the default type until :meth:`set_types`."""
        base = default_type(config)
        self.set_types([base] * n2)
        self.ball_distance = np.empty(n2)
        """Centre distance of every player to the ball (m), from the last :meth:`kick_candidates`."""
        self.player_speed = np.empty(n2)
        """Speed of each player after the last :meth:`dash` (m/cycle)."""

    def set_types(self, types: list[PlayerType] | tuple[PlayerType, ...]) -> None:
        """Give player row ``i`` the parameters of ``types[i]`` (one type per player row)."""
        touch = self._touch_distance
        for row, t in enumerate(types):
            self.types[row] = self._row(t, touch + t.kickable_margin)  # as PhysicsConfig.kickable_distance

    @staticmethod
    def _row(t: PlayerType, kickable: float) -> np.ndarray:
        row = np.empty(PT_COLUMNS)
        row[PT_DASH_POWER_RATE], row[PT_EXTRA_STAMINA], row[PT_SPEED_MAX] = (
            t.dash_power_rate, t.extra_stamina, t.player_speed_max)
        row[PT_STAMINA_INC], row[PT_EFFORT_MIN], row[PT_EFFORT_MAX] = t.stamina_inc_max, t.effort_min, t.effort_max
        row[PT_DECAY], row[PT_KICKABLE], row[PT_KICKABLE_MARGIN] = t.player_decay, kickable, t.kickable_margin
        row[PT_KICK_RAND], row[PT_INERTIA_MOMENT] = t.kick_rand, t.inertia_moment
        row[PT_CATCH_STRETCH] = t.catchable_area_l_stretch
        return row

    # --- kicks ------------------------------------------------------------------------------
    def kick_candidates(self, pos: np.ndarray, ball: np.ndarray, kick: np.ndarray, mask: np.ndarray,
                        holder: int, rows_out: np.ndarray) -> tuple[int, float]:
        """Find the players that kick this cycle: allowed by ``mask``, ball centre within
        its kickable distance (its type's, :attr:`types`; or holding it: row ``holder``), and a
        non-zero kick request.

        Writes their rows into ``rows_out[:count]`` and the centre distances of every player to
        the ball into :attr:`ball_distance`; returns (count, distance of the nearest player).
        """
        return find_kickers(pos, ball, kick, mask, holder, self.types, self.ball_distance, rows_out)

    def kick(self, kickers: np.ndarray, pos: np.ndarray, vel: np.ndarray, ball: np.ndarray, ball_vel: np.ndarray,
             kick: np.ndarray, dist: np.ndarray, holder: int, noise: np.ndarray) -> None:
        """Apply the kicks of the player rows ``kickers`` to ``ball_vel`` (in place).

        ``vel``: the players' velocities (where each body faces, :mod:`soccer_sim.body`);
        ``dist``: the centre distances (:attr:`ball_distance`); ``noise``: (P, 2) kick noise
        draws (:attr:`CycleNoise.kick`). A holding goalkeeper (row ``holder``) holds the ball
        touching the front of its body, so it kicks without distance or angle penalty.
        """
        apply_kicks(kickers, pos, vel, ball, ball_vel, kick, dist, holder, noise, self._kick_params, self.types)

    # --- dashes and stamina ----------------------------------------------------------------
    def dash(self, vel: np.ndarray, ball_vel: np.ndarray, stamina: np.ndarray, effort: np.ndarray,
             recovery: np.ndarray, capacity: np.ndarray, dash: np.ndarray, noise: np.ndarray) -> float:
        """Apply dash requests ``dash`` (2n, 2; overwritten with the accelerations applied) to
        ``vel``, pay them from ``stamina``, update every player's stamina model (``stamina``,
        ``effort``, ``recovery``, ``capacity``, all (2n,), in place), then add the movement
        noise of the players and of the ball (``ball_vel``; ``noise``: :attr:`CycleNoise.motion`);
        return the largest resulting player speed (m/cycle)."""
        return dash_players(vel, ball_vel, stamina, effort, recovery, capacity, dash, noise, self._dash_params, self.types,
                            self.player_speed)

    def restore(self, stamina: np.ndarray, effort: np.ndarray, recovery: np.ndarray,
                capacity: np.ndarray) -> None:
        """Fresh players (the start of a match and of the second half): stamina at its maximum,
        effort at each player type's ``effort_max``, recovery 1, the half's full capacity."""
        stam = self._stamina_config
        stamina[:] = stam.maximum
        effort[:] = self.types[:, PT_EFFORT_MAX]
        recovery[:] = 1.0
        capacity[:] = stam.capacity_or_inf

    # --- decay ------------------------------------------------------------------------------
    def decay(self, vel: np.ndarray, ball_vel: np.ndarray) -> None:
        """Velocity decay after the move (in place)."""
        decay_velocities(vel, ball_vel, self._decay_params, self.types)
