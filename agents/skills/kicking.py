"""Kicks: who may kick, how effective a kick is, and the kick that gives the ball a velocity.

The rule mirrored is :meth:`soccer_sim.kinematics.Kinematics.kick` (rcssserver's): a kick
request ``r`` is clipped to ``kick_speed_max`` and multiplied by an effectiveness

    ``1 - kick_distance_penalty * min(1, gap / kickable_margin)
         - kick_angle_penalty * angle / pi``

where ``gap`` is the distance between the ball's and the player's surfaces and ``angle`` is
the angle between the kick and the direction from the player to the ball (kicking the ball
straight back through oneself costs the most). A goalkeeper holding the ball kicks at full
effectiveness. The ball's speed is then clipped to ``ball_speed_max``.

:func:`kick_for_velocity` inverts the rule: the change needed is ``desired - ball_vel``; the
request is that change divided by the effectiveness of its direction. When the change is
larger than one kick allows, it keeps the desired *direction* and gives the largest speed
along it that one kick can reach (the effectiveness depends on the kick's direction, so a
few rounds of solving a quadratic, checked, with bisection as the fallback); when no speed
along the desired direction is reachable (a fast ball would have to be turned round), it
kicks at full power towards the point of the desired ray closest to the ball's current
velocity.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from agents.skills.model import MotionModel, float_array


def kickable(model: MotionModel, pos: np.ndarray, ball: np.ndarray) -> np.ndarray:
    """Bool per player (``pos`` (n, 2) or (2,)): the ball's centre is within the kickable distance."""
    diff = np.asarray(pos, float) - np.asarray(ball, float)
    return np.einsum("...i,...i->...", diff, diff) <= model.kickable_distance ** 2


def kick_effectiveness(model: MotionModel, player: np.ndarray, ball: np.ndarray, kick: np.ndarray) -> np.ndarray:
    """Effectiveness (fraction of the requested change that reaches the ball) of kicks in the
    directions ``kick`` ((k, 2) or (2,)) by a player at ``player`` on the ball at ``ball``."""
    kick = np.asarray(kick, dtype=np.float64)
    single = kick.ndim == 1
    rows = float_array("kick", kick.reshape(1, -1) if single else kick, (-1, 2))
    out = np.empty(rows.shape[0])
    _effect_kernel(float_array("player", player, (2,)), float_array("ball", ball, (2,)), rows,
                   _kick_params(model, False), out)
    return out[0] if single else out


def kick_for_velocity(model: MotionModel, player: np.ndarray, ball: np.ndarray, ball_vel: np.ndarray,
                      desired: np.ndarray, holder: bool = False) -> tuple[np.ndarray, np.ndarray]:
    """The kick request that makes the ball leave with velocity ``desired`` ((k, 2) or (2,),
    team frame, m/cycle), and the velocity it really gets (same shape; equal to ``desired``
    when one kick can do it, else the best direction-preserving result). ``player``, ``ball``,
    ``ball_vel``: (2,). ``holder``: the kicker is a goalkeeper holding the ball (full
    effectiveness). Noise is not modelled.
    """
    desired = np.asarray(desired, dtype=np.float64)
    single = desired.ndim == 1
    rows = float_array("desired", desired.reshape(1, -1) if single else desired, (-1, 2))
    kick = np.empty_like(rows)
    result = np.empty_like(rows)
    _kick_kernel(float_array("player", player, (2,)), float_array("ball", ball, (2,)),
                 float_array("ball_vel", ball_vel, (2,)), rows, _kick_params(model, holder), kick, result)
    if single:
        return kick[0], result[0]
    return kick, result


def _kick_params(model: MotionModel, holder: bool) -> np.ndarray:
    return np.array([model.kick_speed_max, model.ball_speed_max, model.kick_distance_penalty,
                     model.kick_angle_penalty, model.kickable_margin, model.touch_distance, 1.0 if holder else 0.0])


@njit(cache=True, nogil=True)
def _distance_effect(rnorm: float, params: np.ndarray) -> float:  # pragma: no cover - compiled
    """Effectiveness left after the distance penalty, for a ball ``rnorm`` from the kicker's centre."""
    return 1.0 - params[2] * min(1.0, max(0.0, rnorm - params[5]) / params[4])


@njit(cache=True, nogil=True)
def _effect(rx: float, ry: float, rnorm: float, base: float, angle_penalty: float, kx: float, ky: float,
            holder: bool) -> float:  # pragma: no cover - compiled
    if holder:
        return 1.0
    knorm = math.sqrt(kx * kx + ky * ky)
    if knorm <= 1e-12 or rnorm <= 1e-12:
        return base
    cos = max(-1.0, min(1.0, (rx * kx + ry * ky) / (rnorm * knorm)))
    return base - angle_penalty * math.acos(cos) / math.pi


@njit(cache=True, nogil=True)
def _effect_kernel(player: np.ndarray, ball: np.ndarray, kicks: np.ndarray, params: np.ndarray,
                   out: np.ndarray) -> None:  # pragma: no cover - compiled
    rx, ry = ball[0] - player[0], ball[1] - player[1]
    rnorm = math.sqrt(rx * rx + ry * ry)
    base = _distance_effect(rnorm, params)
    angle_penalty = params[3]
    for j in range(kicks.shape[0]):
        out[j] = _effect(rx, ry, rnorm, base, angle_penalty, kicks[j, 0], kicks[j, 1], False)


@njit(cache=True, nogil=True)
def _largest_speed(ux: float, uy: float, vx: float, vy: float, low: float, high: float, kick_max: float, rx: float,
                   ry: float, rnorm: float, base: float, angle_penalty: float,
                   holder: bool) -> float:  # pragma: no cover - compiled
    """The largest speed s in [low, high] along the unit vector u such that the change
    ``s u - v`` fits in one kick (``low`` does, ``high`` does not).

    For a fixed effectiveness e the boundary solves ``|s u - v| = kick_max e``, a quadratic
    in s; e depends on the change's direction only, which moves little with s, so a few
    rounds of "solve, re-evaluate e" land on the boundary. The result is checked and, if it
    is not feasible, bisection between ``low`` and it settles the matter.
    """
    along = ux * vx + uy * vy
    rest = vx * vx + vy * vy - along * along
    s = high
    for _ in range(5):
        cx, cy = s * ux - vx, s * uy - vy
        reach = kick_max * _effect(rx, ry, rnorm, base, angle_penalty, cx, cy, holder)
        disc = reach * reach - rest
        if disc < 0.0:
            break
        step = min(max(along + math.sqrt(disc), low), high)
        done = abs(step - s) < 1e-9
        s = step
        if done:
            break
    for nudge in (0.0, 1e-8):  # the boundary is met to rounding: step just inside it
        t = max(s - nudge, low)
        cx, cy = t * ux - vx, t * uy - vy
        if math.sqrt(cx * cx + cy * cy) <= kick_max * _effect(rx, ry, rnorm, base, angle_penalty, cx, cy, holder):
            return t
    high = s
    for _ in range(18):  # to within 2^-18 of the range (~1e-5 m/cycle)
        mid = 0.5 * (low + high)
        cx, cy = mid * ux - vx, mid * uy - vy
        if math.sqrt(cx * cx + cy * cy) <= kick_max * _effect(rx, ry, rnorm, base, angle_penalty, cx, cy, holder):
            low = mid
        else:
            high = mid
    return low


@njit(cache=True, nogil=True)
def _kick_kernel(player: np.ndarray, ball: np.ndarray, ball_vel: np.ndarray, desired: np.ndarray, params: np.ndarray,
                 kick_out: np.ndarray, result_out: np.ndarray) -> None:  # pragma: no cover - compiled
    kick_max, ball_max, angle_penalty, holder = params[0], params[1], params[3], params[6] > 0.5
    rx, ry = ball[0] - player[0], ball[1] - player[1]
    rnorm = math.sqrt(rx * rx + ry * ry)
    base = _distance_effect(rnorm, params)
    vx, vy = ball_vel[0], ball_vel[1]
    for j in range(desired.shape[0]):
        dx, dy = desired[j, 0], desired[j, 1]
        speed = math.sqrt(dx * dx + dy * dy)
        if speed > ball_max:
            dx *= ball_max / speed
            dy *= ball_max / speed
            speed = ball_max
        # Feasible when the change fits within kick_max times the effectiveness of its direction.
        cx, cy = dx - vx, dy - vy
        size = math.sqrt(cx * cx + cy * cy)
        eff = _effect(rx, ry, rnorm, base, angle_penalty, cx, cy, holder)
        if size <= kick_max * eff + 1e-12:
            lam = 1.0
        else:
            ux, uy = (dx / speed, dy / speed) if speed > 1e-12 else (0.0, 0.0)
            closest = max(0.0, vx * ux + vy * uy)  # speed along the ray nearest the current velocity
            cx, cy = closest * ux - vx, closest * uy - vy
            size = math.sqrt(cx * cx + cy * cy)
            eff = _effect(rx, ry, rnorm, base, angle_penalty, cx, cy, holder)
            if size > kick_max * eff or speed <= 1e-12:
                # Nothing along the desired direction is reachable: full power towards it.
                if size <= 1e-12:
                    kick_out[j, 0] = 0.0
                    kick_out[j, 1] = 0.0
                    result_out[j, 0] = vx
                    result_out[j, 1] = vy
                    continue
                eff = max(eff, 1e-9)
                kick_out[j, 0] = cx / size * kick_max
                kick_out[j, 1] = cy / size * kick_max
                nx, ny = vx + cx / size * kick_max * eff, vy + cy / size * kick_max * eff
                nspeed = math.sqrt(nx * nx + ny * ny)
                if nspeed > ball_max:
                    nx *= ball_max / nspeed
                    ny *= ball_max / nspeed
                result_out[j, 0] = nx
                result_out[j, 1] = ny
                continue
            lam = _largest_speed(ux, uy, vx, vy, closest, speed, kick_max, rx, ry, rnorm, base, angle_penalty,
                                 holder) / speed
        tx, ty = lam * dx, lam * dy
        cx, cy = tx - vx, ty - vy
        eff = max(_effect(rx, ry, rnorm, base, angle_penalty, cx, cy, holder), 1e-9)
        kick_out[j, 0] = cx / eff
        kick_out[j, 1] = cy / eff
        result_out[j, 0] = tx
        result_out[j, 1] = ty
