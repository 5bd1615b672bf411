"""The compiled interception search (see :mod:`agents.skills.interception` for the model).

Arguments travel as named records, as in :mod:`soccer_sim.kernels`: the match's constants as
an :data:`INTERCEPT_PARAMS` record (a one-element numpy structured array read by field name,
made from :class:`~agents.skills.context.InterceptConstants`); arrays that belong together as
named tuples read by field name (:class:`Runners`: one team's players; :class:`MotionTables`:
the motion model's per-cycle tables); the call's own choices as named scalars (``catch_side``:
the side whose penalty area the catch radius counts in, -1 ours, +1 theirs; ``delay``: the
cycles before the players start to dash; ``first_only``: stop a trajectory at its first
interception). The ball race's result is a named tuple (:class:`RaceFirsts`).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

UNREACHABLE = 1_000_000
"""Interception cycle of a player who cannot get to the ball before it leaves the field or the
cycle limit (larger than any real cycle, so ``argmin`` over cycles works unchanged)."""

NO_LIMITS = np.full(0, -1, dtype=np.int64)
"""Empty cycle limits: the search goes to the horizon."""
EVERYONE = np.zeros(0, dtype=np.int64)
"""Empty ``only``: every player is searched on every trajectory."""
_MARGIN = 1e-6
"""Slack (m) of the run bound that skips hopeless hit tests, far above any rounding error."""

INTERCEPT_PARAMS = np.dtype([(name, np.float64) for name in (
    "x_max", "y_max", "top_speed", "area_x", "area_y", "accel_max", "speed_max", "decay", "body")])
"""The interception search's constants of one match (the fields of
:class:`~agents.skills.context.InterceptConstants`, which documents them; metres, m/cycle,
m/cycle²)."""


class Runners(NamedTuple):
    """One team's players as the compiled search reads them, all C-contiguous float64."""

    pos: np.ndarray
    """(n, 2) positions (team frame, m)."""
    vel: np.ndarray
    """(n, 2) velocities (m/cycle)."""
    effort: np.ndarray
    """(n,) effort (1: fresh)."""
    radius: np.ndarray
    """(n,) control distance (m): the kickable distance."""
    catch_radius: np.ndarray
    """(n,) control distance inside the penalty area where the player catches (m)."""


class MotionTables(NamedTuple):
    """The motion model's per-cycle tables (:class:`~agents.skills.model.MotionModel`), index k
    = cycles from now, ``horizon + 1`` entries each."""

    reach: np.ndarray
    """How far a player starting at rest runs in k cycles at full effort (m)."""
    ball_travel: np.ndarray
    """Distance factor of a rolling ball after k cycles (times its velocity: m)."""
    coast: np.ndarray
    """Distance factor of a coasting player after k cycles (times its velocity: m)."""


class RaceFirsts(NamedTuple):
    """Who gets to the ball first on each side (:func:`race_kernel`)."""

    first: int
    """Our first player (-1: nobody gets there)."""
    first_cycle: int
    """Its cycle (UNREACHABLE when nobody gets there)."""
    their_first: int
    """Their first player (-1: nobody)."""
    their_first_cycle: int
    """Its cycle (UNREACHABLE when nobody)."""


@njit(cache=True, nogil=True)
def intercept_kernel(ball: np.ndarray, ball_vel: np.ndarray, runners: Runners, tables: MotionTables,
                     limits: np.ndarray, only: np.ndarray, cycles_out: np.ndarray, points_out: np.ndarray,
                     params: np.ndarray, catch_side: float, delay: int,
                     first_only: bool) -> None:  # pragma: no cover - compiled
    """Each of the ``runners``' earliest interception cycle and point on each trajectory p
    (ball row ``ball[0 or p]``, velocity ``ball_vel[p]``) into ``cycles_out`` (P, n) and
    ``points_out`` (P, n, 2); ``params``: an :data:`INTERCEPT_PARAMS` record. ``limits[p] < 0``
    (or ``limits`` empty): search to the horizon. ``only[p] >= 0``: search that player alone on
    trajectory p (the others get UNREACHABLE). With ``first_only`` a trajectory stops at its
    first interception and the later players get UNREACHABLE."""
    pos, vel, effort, radius, catch_radius = runners.pos, runners.vel, runners.effort, runners.radius, \
        runners.catch_radius
    reach, ball_travel, coast = tables.reach, tables.ball_travel, tables.coast
    c = params[0]
    x_max, y_max, top_speed, area_x, area_y = c.x_max, c.y_max, c.top_speed, c.area_x, c.area_y
    accel_max, speed_max, decay, body = c.accel_max, c.speed_max, c.decay, c.body
    horizon = reach.shape[0] - 1
    n = pos.shape[0]
    run = np.empty(n)  # furthest straight-line run so far, per player
    speed = np.empty(n)
    short = np.empty(n)  # the run below which a player cannot reach the ball's path
    for p in range(ball_vel.shape[0]):
        b = 0 if ball.shape[0] == 1 else p
        bx0, by0, vx, vy = ball[b, 0], ball[b, 1], ball_vel[p, 0], ball_vel[p, 1]
        bound = limits[p] if limits.shape[0] > 0 else -1
        last = horizon if bound < 0 else min(bound, horizon)
        alone = only[p] if only.shape[0] > 0 else -1
        # Players who cannot get near the ball's whole path within `last` cycles are skipped
        # (-2) when the search ends at `last` anyway (first-only, or a limit within the horizon).
        prune = first_only or (0 <= bound <= horizon)
        wx, wy = ball_travel[last] * vx, ball_travel[last] * vy
        whole = wx * wx + wy * wy
        remaining = 0
        for i in range(n):
            run[i] = 0.0
            speed[i] = math.sqrt(vel[i, 0] ** 2 + vel[i, 1] ** 2)
            if alone < 0 or i == alone:
                cycles_out[p, i] = -1
                remaining += 1
                qx, qy = pos[i, 0] - bx0, pos[i, 1] - by0
                t = min(max((qx * wx + qy * wy) / whole, 0.0), 1.0) if whole > 0.0 else 0.0
                gap = math.sqrt((qx - t * wx) ** 2 + (qy - t * wy) ** 2)
                widest = max(radius[i], catch_radius[i], body)
                # Every ball point searched lies on the path, at least `gap` from the player: no
                # hit while its run falls short of that (less a margin for rounding).
                short[i] = gap - widest - _MARGIN
                if prune:
                    grow = reach[last - delay] * effort[i] if last > delay else 0.0
                    if gap > coast[last] * speed[i] + grow + max(radius[i], catch_radius[i]):
                        cycles_out[p, i] = -2
                        remaining -= 1
            else:
                cycles_out[p, i] = UNREACHABLE
                points_out[p, i, 0] = bx0
                points_out[p, i, 1] = by0
        lo, hi = (0, n) if alone < 0 else (alone, alone + 1)
        found = False
        left_field = False
        bx, by = bx0, by0
        k_end = 0
        for k in range(last + 1):
            tx = bx0 + ball_travel[k] * vx
            ty = by0 + ball_travel[k] * vy
            if abs(tx) > x_max or abs(ty) > y_max:
                left_field = True
                break
            px, py = bx, by  # where the ball was a cycle ago
            bx, by = tx, ty
            k_end = k
            in_area = catch_side * tx >= area_x and abs(ty) <= area_y
            sx, sy = tx - px, ty - py
            seg = sx * sx + sy * sy
            seg_len = math.sqrt(seg)
            for i in range(lo, hi):
                if cycles_out[p, i] != -1:
                    continue
                if k > 0:
                    boost = accel_max * effort[i] if k > delay else 0.0
                    speed[i] = min(speed[i] + boost, speed_max)
                    run[i] += speed[i]
                    speed[i] *= decay
                if run[i] < short[i]:
                    continue
                cx = pos[i, 0] + coast[k] * vel[i, 0]
                cy = pos[i, 1] + coast[k] * vel[i, 1]
                r = radius[i]
                if in_area and catch_radius[i] > r:
                    r = catch_radius[i]
                dx, dy = tx - cx, ty - cy
                ex, ey = tx - pos[i, 0], ty - pos[i, 1]
                grow = reach[k - delay] * effort[i] if k > delay else 0.0
                hit = dx * dx + dy * dy <= (grow + r) ** 2 and ex * ex + ey * ey <= (run[i] + r) ** 2
                qx, qy = tx, ty
                if not hit and seg > 0.0 and dx * dx + dy * dy <= (grow + body + seg_len) ** 2:
                    # The ball may run into the body somewhere along this cycle's path.
                    t = min(max(((cx - px) * sx + (cy - py) * sy) / seg, 0.0), 1.0)
                    qx, qy = px + t * sx, py + t * sy
                    hit = (qx - cx) ** 2 + (qy - cy) ** 2 <= (grow + body) ** 2 and \
                        (qx - pos[i, 0]) ** 2 + (qy - pos[i, 1]) ** 2 <= (run[i] + body) ** 2
                if hit:
                    cycles_out[p, i] = k
                    points_out[p, i, 0] = qx
                    points_out[p, i, 1] = qy
                    remaining -= 1
                    found = True
            if remaining == 0 or (found and first_only):
                break
        if found and first_only:
            for i in range(n):
                if cycles_out[p, i] < 0:
                    cycles_out[p, i] = UNREACHABLE
                    points_out[p, i, 0] = bx
                    points_out[p, i, 1] = by
            continue
        beyond = not left_field and k_end == horizon and (bound < 0 or bound > horizon)
        for i in range(n):
            if cycles_out[p, i] >= 0:
                continue
            points_out[p, i, 0] = bx
            points_out[p, i, 1] = by
            if beyond:
                cx = pos[i, 0] + coast[horizon] * vel[i, 0]
                cy = pos[i, 1] + coast[horizon] * vel[i, 1]
                gap = math.sqrt((bx - cx) ** 2 + (by - cy) ** 2) - radius[i] - reach[horizon - delay] * effort[i]
                pace = max(top_speed * effort[i], 1e-9)
                cycles_out[p, i] = horizon + max(1, int(math.ceil(gap / pace)))
            else:
                cycles_out[p, i] = UNREACHABLE


@njit(cache=True, nogil=True)
def race_kernel(ball: np.ndarray, ball_vel: np.ndarray, ours: Runners, theirs: Runners, tables: MotionTables,
                eligible: np.ndarray, our_cycles: np.ndarray, our_points: np.ndarray, their_cycles: np.ndarray,
                their_points: np.ndarray, params: np.ndarray,
                their_first_only: bool) -> RaceFirsts:  # pragma: no cover - compiled
    """Both teams' :func:`intercept_kernel` of one ball in one call (ours catching in our
    penalty area, theirs in theirs, nobody delayed); our players not ``eligible`` (when it is
    not empty) made UNREACHABLE. Returns each side's first player and its cycle, -1 and
    UNREACHABLE when nobody gets there."""
    intercept_kernel(ball, ball_vel, ours, tables, NO_LIMITS, EVERYONE, our_cycles, our_points, params, -1.0, 0,
                     False)
    if eligible.shape[0] > 0:
        for i in range(our_cycles.shape[1]):
            if not eligible[i]:
                our_cycles[0, i] = UNREACHABLE
    intercept_kernel(ball, ball_vel, theirs, tables, NO_LIMITS, EVERYONE, their_cycles, their_points, params, 1.0, 0,
                     their_first_only)
    first, first_cycle = first_of(our_cycles[0])
    their_first, their_first_cycle = first_of(their_cycles[0])
    return RaceFirsts(first, first_cycle, their_first, their_first_cycle)


@njit(cache=True, nogil=True)
def first_of(cycles: np.ndarray) -> tuple[int, int]:  # pragma: no cover - compiled
    """The player with the smallest cycle (the lowest index among equals) and that cycle;
    (-1, its cycle or UNREACHABLE) when nobody gets there."""
    first, first_cycle = -1, UNREACHABLE
    for i in range(cycles.shape[0]):
        if first < 0 or cycles[i] < first_cycle:
            first, first_cycle = i, cycles[i]
    if first_cycle >= UNREACHABLE:
        first = -1
    return first, first_cycle
