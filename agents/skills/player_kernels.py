"""The compiled kernels of the player skills: dashing to points (:mod:`agents.skills.movement`),
the dribbling fan (:mod:`agents.skills.dribbling`) and the goalkeeper's guard point
(:mod:`agents.skills.goalkeeping`). Constants come as named scalar arguments."""

from __future__ import annotations

import math

import numpy as np
from numba import njit


@njit(cache=True, nogil=True)
def dash_kernel(pos: np.ndarray, vel: np.ndarray, targets: np.ndarray, effort: np.ndarray, caps: np.ndarray,
                accel_max: float, speed_max: float, tolerance: float, out: np.ndarray) -> None:  # pragma: no cover
    """Per player, the dash that brings it from ``pos``/``vel`` to its ``targets`` row and stops
    it there, running at most at its cap (see :mod:`agents.skills.movement`)."""
    for i in range(pos.shape[0]):
        dx = targets[i, 0] - pos[i, 0]
        dy = targets[i, 1] - pos[i, 1]
        vx, vy = vel[i, 0], vel[i, 1]
        dist = math.sqrt(dx * dx + dy * dy)
        if dist <= tolerance and vx * vx + vy * vy <= 1e-6:
            out[i, 0] = 0.0
            out[i, 1] = 0.0
            continue
        cap = min(caps[i], speed_max)
        if dist > cap:
            dx *= cap / dist
            dy *= cap / dist
        ax, ay = dx - vx, dy - vy
        size = math.sqrt(ax * ax + ay * ay)
        limit = accel_max * effort[i]
        if size > limit:
            ax *= limit / size
            ay *= limit / size
        out[i, 0] = ax
        out[i, 1] = ay


@njit(cache=True, nogil=True)
def paced_dash_kernel(pos: np.ndarray, vel: np.ndarray, targets: np.ndarray, effort: np.ndarray, stamina: np.ndarray,
                      urgent: np.ndarray, top_speed: float, jog_speed: float, fresh: float, accel_max: float,
                      speed_max: float, tolerance: float, out: np.ndarray) -> None:  # pragma: no cover - compiled
    """:func:`caps_kernel`'s caps fed to :func:`dash_kernel`, in one pass."""
    caps = np.empty(pos.shape[0])
    caps_kernel(urgent, stamina, effort, top_speed, jog_speed, fresh, caps)
    dash_kernel(pos, vel, targets, effort, caps, accel_max, speed_max, tolerance, out)


@njit(cache=True, nogil=True)
def caps_kernel(urgent: np.ndarray, stamina: np.ndarray, effort: np.ndarray, top_speed: float, jog_speed: float,
                fresh: float, caps: np.ndarray) -> None:  # pragma: no cover - compiled
    """The running-speed rule of :func:`speed_caps`: the top speed for a player who is urgent
    and has stamina above ``fresh``, else the jogging speed; both times its effort (both
    speeds are proportional to it, see MotionModel.sustainable_speed)."""
    for i in range(caps.shape[0]):
        pace = top_speed if urgent[i] and stamina[i] > fresh else jog_speed
        caps[i] = pace * effort[i]


@njit(cache=True, nogil=True)
def fan_kernel(start: np.ndarray, base: float, offsets: np.ndarray, probes: np.ndarray, cycles: np.ndarray,
               opp_pos: np.ndarray, opp_vel: np.ndarray, reach: np.ndarray, coast: np.ndarray, dirs: np.ndarray,
               clearance: np.ndarray, score: np.ndarray, kickable: float, cap: float, goal_weight: float, x_max: float,
               y_max: float) -> None:  # pragma: no cover - compiled
    """Per direction (``base`` + offset): the unit vector, the clearance (the smallest margin
    in metres between a probe point and the disc an opponent can cover by the time the
    dribbler gets there; inf without opponents) and the score (-inf when the farthest probe
    is outside the field less the margin). ``kickable``: the kickable distance; ``cap``: the
    clearance that counts no more; ``goal_weight``: the weight of heading for the goal;
    ``x_max``, ``y_max``: the largest |x| and |y| of a probe."""
    far = probes[probes.shape[0] - 1]
    for d in range(offsets.shape[0]):
        ux, uy = math.cos(base + offsets[d]), math.sin(base + offsets[d])
        dirs[d, 0], dirs[d, 1] = ux, uy
        best = np.inf
        for j in range(probes.shape[0]):
            qx = start[0] + ux * probes[j]
            qy = start[1] + uy * probes[j]
            k = cycles[j]
            for o in range(opp_pos.shape[0]):
                cx = opp_pos[o, 0] + coast[k] * opp_vel[o, 0]
                cy = opp_pos[o, 1] + coast[k] * opp_vel[o, 1]
                margin = math.sqrt((qx - cx) ** 2 + (qy - cy) ** 2) - reach[k] - kickable
                if margin < best:
                    best = margin
        clearance[d] = best
        if abs(start[0] + ux * far) > x_max or abs(start[1] + uy * far) > y_max:
            score[d] = -np.inf
        else:
            score[d] = min(best, cap) / cap + goal_weight * math.cos(offsets[d])


@njit(cache=True, nogil=True)
def guard_kernel(dist: float, dx: float, dy: float, gx: float, near: float, far: float, depth_far: float,
                 ball_gap: float, area_length: float,
                 area_half_width: float) -> tuple[float, float]:  # pragma: no cover - compiled
    """The guard point on the segment from the goal centre (``gx``, 0) towards the ball (``dx``,
    ``dy`` from it, ``dist`` away): deeper the nearer the ball, inside the goal area, short of
    the ball."""
    if dist < 1e-9:
        return gx, 0.0
    ux, uy = dx / dist, dy / dist
    if ux < 0.0:  # a ball behind our goal line (out of play): stay on the line, on its side
        ux, uy = 0.0, (1.0 if uy >= 0.0 else -1.0)
    share = min(max((far - dist) / max(far - near, 1e-9), 0.0), 1.0)
    depth = depth_far + share * (area_length - depth_far)
    if ux > 1e-9:
        depth = min(depth, area_length / ux)
    if abs(uy) > 1e-9:
        depth = min(depth, area_half_width / abs(uy))
    depth = max(0.0, min(depth, dist - ball_gap))
    return gx + ux * depth, uy * depth
