"""The compiled kernels of the player skills: dashing to points (:mod:`agents.skills.movement`),
the dribbling fan (:mod:`agents.skills.dribbling`) and the goalkeeper's guard point
(:mod:`agents.skills.goalkeeping`).

Arguments travel as named records, as in :mod:`soccer_sim.kernels`: the pacing kernels'
constants as a :data:`~agents.skills.pacing.PACING_PARAMS` record and the dribbling fan's as a
:data:`FAN_PARAMS` record (one-element numpy structured arrays read by field name); arrays that
belong together as named tuples read by field name (:class:`Bodies`, :class:`DashOut`,
:class:`FanOut`); the guard point's and the plain dash's few constants as named scalars."""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from agents.skills.interception_kernels import MotionTables
from soccer_sim.kernels import dash_direction_rate

FAN_PARAMS = np.dtype([(name, np.float64) for name in ("kickable", "cap", "goal_weight", "x_max", "y_max")])
"""The dribbling fan's constants (:func:`fan_kernel`): the kickable distance, the clearance
that counts no more, the weight of heading for the goal, and the largest |x| and |y| of a probe
(m)."""


class Bodies(NamedTuple):
    """The players' own state as the pacing kernels read it, one row per player."""

    pos: np.ndarray
    """(n, 2) positions (team frame, m)."""
    vel: np.ndarray
    """(n, 2) velocities (m/cycle)."""
    effort: np.ndarray
    """(n,) effort."""
    stamina: np.ndarray
    """(n,) stamina."""
    capacity: np.ndarray
    """(n,) stamina still to recover this match (rcssserver's ``stamina_capacity``)."""


class DashOut(NamedTuple):
    """What the pacing kernels write, one row per player."""

    dash: np.ndarray
    """(n, 2) the dash (m/cycle², team frame)."""
    budgets: np.ndarray
    """(n,) the power budget (stamina per cycle; 0 when not dashing)."""


class FanOut(NamedTuple):
    """What :func:`fan_kernel` writes, one row per direction."""

    dirs: np.ndarray
    """(D, 2) unit vectors."""
    clearance: np.ndarray
    """(D,) the smallest margin to an opponent's reach (m; inf without opponents)."""
    score: np.ndarray
    """(D,) the direction's score (-inf: it leaves the field)."""



@njit(cache=True, nogil=True)
def arrive_and_stop(dx: float, dy: float, vx: float, vy: float, dist: float, cap: float,
                    limit: float) -> tuple[float, float, float]:  # pragma: no cover - compiled
    """The acceleration (ax, ay) and its size that take a player moving at (vx, vy) towards a
    point (dx, dy) away (``dist`` m) at no more than ``cap`` m/cycle and stop it there, capped
    at ``limit`` m/cycle^2 (a full dash at the player's effort)."""
    if dist > cap:
        dx *= cap / dist
        dy *= cap / dist
    ax, ay = dx - vx, dy - vy
    size = math.sqrt(ax * ax + ay * ay)
    if size > limit:
        ax *= limit / size
        ay *= limit / size
        size = limit
    return ax, ay, size


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
        ax, ay, _ = arrive_and_stop(dx, dy, vx, vy, dist, min(caps[i], speed_max), accel_max * effort[i])
        out[i, 0] = ax
        out[i, 1] = ay


@njit(cache=True, nogil=True)
def paced_dash_kernel(bodies: Bodies, targets: np.ndarray, urgent: np.ndarray, ball: np.ndarray, goalie: int,
                      attacking: int, cycle: int, half: int, pacing: np.ndarray,
                      out: DashOut) -> None:  # pragma: no cover - compiled
    """Per player, the dash to its ``targets`` row under the stamina policy of
    :mod:`agents.skills.pacing` (``pacing``: its :data:`~agents.skills.pacing.PACING_PARAMS`
    record): the power budget (into ``out.budgets``, stamina per cycle), the pace it holds, the
    arrive-and-stop dash at that pace (into ``out.dash``), shortened when its power (the
    simulator's count, side and back dashes included) exceeds the budget. ``attacking``: 1 we
    attack, 0 we defend (play on), -1 neither (set plays); ``cycle``, ``half``: the view's."""
    cycles_left = cycles_left_in_half(cycle, half, pacing)
    for i in range(bodies.pos.shape[0]):
        paced_dash_player(i, bodies, targets, urgent[i], ball[0], ball[1], goalie, attacking, cycles_left, pacing,
                          out)


@njit(cache=True, nogil=True)
def paced_dash_rows(rows: np.ndarray, bodies: Bodies, targets: np.ndarray, urgent: np.ndarray, balls: np.ndarray,
                    goalie: int, attacking: np.ndarray, cycle: int, half: int, pacing: np.ndarray,
                    out: DashOut) -> None:  # pragma: no cover - compiled
    """:func:`paced_dash_kernel` for the players ``rows`` only, each with its own ball
    (``balls`` (n, 2)) and phase (``attacking`` (n,)): players who each decide from what they
    alone believe."""
    cycles_left = cycles_left_in_half(cycle, half, pacing)
    for i in rows:
        paced_dash_player(i, bodies, targets, urgent[i], balls[i, 0], balls[i, 1], goalie, attacking[i], cycles_left,
                          pacing, out)


@njit(cache=True, nogil=True)
def paced_dash_player(i: int, bodies: Bodies, targets: np.ndarray, hurry: bool, bx: float, by: float, goalie: int,
                      attacking: int, cycles_left: float, pacing: np.ndarray,
                      out: DashOut) -> None:  # pragma: no cover - compiled
    """Player ``i``'s row of :func:`paced_dash_kernel` (the ball at ``bx``, ``by``; ``hurry``
    its urgent flag)."""
    pos, vel, effort, stamina, capacity = bodies.pos, bodies.vel, bodies.effort, bodies.stamina, bodies.capacity
    dash, budgets = out.dash, out.budgets
    k = pacing[0]
    accel_max, rate = k.accel_max, k.power_rate
    side_rate, back_rate, heading_speed = k.side_rate, k.back_rate, k.heading_speed
    run = k.run_distance
    px, py = pos[i, 0], pos[i, 1]
    tx, ty = targets[i, 0], targets[i, 1]
    dx, dy = tx - px, ty - py
    vx, vy = vel[i, 0], vel[i, 1]
    dist = math.sqrt(dx * dx + dy * dy)
    dash[i, 0] = 0.0
    dash[i, 1] = 0.0
    budgets[i] = 0.0
    if dist <= k.tolerance and vx * vx + vy * vy <= 1e-6:
        return
    st = stamina[i]
    ball_gap = math.sqrt((px - bx) ** 2 + (py - by) ** 2)
    if not hurry and attacking >= 0 and i != goalie:
        if attacking == 1:  # an attacking run into the final third, the ball in their half
            hurry = bx >= 0.0 and tx >= k.final_third_x and tx - px >= run
        else:  # a run back goal-side of the ball by a player caught in front of it
            hurry = bx <= k.danger_x and tx < bx < px and px - tx >= run
    if not hurry and i != goalie and dist <= max(k.settle, k.settle_share * ball_gap) \
            and not (tx > 0.0 and px > tx):
        return  # near enough: coast to a stop
    # Away from the play: behind it when we attack (rest defence), ahead of it when they do.
    rest = not hurry and i != goalie and ((attacking == 1 and tx < bx - k.rest_gap)
                                          or (attacking == 0 and tx > bx + k.rest_gap))
    eff = effort[i]
    budget = power_budget(st, capacity[i], hurry, i == goalie, rest, dist, ball_gap, cycles_left, pacing)
    budgets[i] = budget
    if budget <= 0.0 or eff <= 0.0:
        return
    ax, ay, size = arrive_and_stop(dx, dy, vx, vy, dist, pace_speed(budget, hurry, eff, pacing), accel_max * eff)
    if size <= 0.0:
        return
    # The power the simulator will charge (soccer_sim.kinematics: the dash direction
    # against the direction of motion, weighted by the speed).
    dir_rate = 1.0
    speed = math.sqrt(vx * vx + vy * vy)
    if speed > 0.0 and size > budget * rate * eff * min(side_rate, back_rate, 1.0):
        # (within budget even at the costliest direction: no need for the angle)
        dir_rate = dash_direction_rate(ax, ay, size, vx, vy, speed, side_rate, back_rate, heading_speed)
    power = size / (rate * eff * dir_rate)
    if power > budget:
        ax *= budget / power
        ay *= budget / power
    dash[i, 0] = ax
    dash[i, 1] = ay


@njit(cache=True, nogil=True)
def cycles_left_in_half(cycle: int, half: int, pacing: np.ndarray) -> float:  # pragma: no cover - compiled
    """Cycles until the end of the current half (at least 1): the horizon over which the
    stamina still to recover (``capacity``) must last."""
    k = pacing[0]
    return max((half + 1) * k.half_cycles - cycle, 1.0)


@njit(cache=True, nogil=True)
def power_budget(st: float, capacity: float, hurry: bool, goalie: bool, rest: bool, dist: float, ball_gap: float,
                 cycles_left: float, pacing: np.ndarray) -> float:  # pragma: no cover - compiled
    """One player's dash-power budget (stamina per cycle) under the policy of
    :mod:`agents.skills.pacing`: full power when in a hurry, else the income times the share
    its target's distance, its stamina and (``rest``) its distance from the play allow; never
    below the floor unless it is in a hurry within ``play_distance`` of the ball."""
    k = pacing[0]
    floor = k.floor
    if hurry:
        budget = k.power_max
    else:
        cruise, walk = k.cruise, k.walk
        income = min(k.income, max(0.0, (capacity + st - floor) / cycles_left))
        share = cruise if goalie else walk + (cruise - walk) * min(dist / k.far, 1.0)
        vigour = min(max((st - k.tired) / (k.fresh - k.tired), 0.0), 1.0)
        share = min(share, k.recover_share + (cruise - k.recover_share) * vigour)
        if rest:
            share = min(share, k.rest_share)
        budget = share * income
    spendable = st + k.extra if hurry and ball_gap <= k.play_distance else st - floor
    return max(0.0, min(budget, k.power_max, spendable))


@njit(cache=True, nogil=True)
def pace_speed(budget: float, hurry: bool, eff: float, pacing: np.ndarray) -> float:  # pragma: no cover - compiled
    """The running-speed cap of a player with dash-power ``budget`` and effort ``eff``: its
    top speed when in a hurry, else the speed the budget holds against the decay (m/cycle)."""
    k = pacing[0]
    top = k.top_speed * eff
    cap = top if hurry else min(top, budget * k.power_rate * eff / max(1.0 - k.decay, 1e-12))
    return min(cap, k.speed_max)


@njit(cache=True, nogil=True)
def caps_kernel(urgent: np.ndarray, stamina: np.ndarray, capacity: np.ndarray, effort: np.ndarray, goalie: int,
                cycle: int, half: int, pacing: np.ndarray, caps: np.ndarray) -> None:  # pragma: no cover - compiled
    """The running-speed caps of :func:`speed_caps`: each player's :func:`pace_speed` for a
    long run (a target at least ``far`` away, the ball not near), 0 when it may not dash."""
    cycles_left = cycles_left_in_half(cycle, half, pacing)
    for i in range(caps.shape[0]):
        budget = power_budget(stamina[i], capacity[i], urgent[i], i == goalie, False, pacing[0].far, np.inf,
                              cycles_left, pacing)
        caps[i] = pace_speed(budget, urgent[i], effort[i], pacing) if budget > 0.0 else 0.0


@njit(cache=True, nogil=True)
def fan_kernel(start: np.ndarray, base: float, offsets: np.ndarray, probes: np.ndarray, cycles: np.ndarray,
               opp_pos: np.ndarray, opp_vel: np.ndarray, tables: MotionTables, params: np.ndarray,
               out: FanOut) -> None:  # pragma: no cover - compiled
    """Per direction (``base`` + offset): the unit vector, the clearance (the smallest margin
    in metres between a probe point and the disc an opponent can cover by the time the
    dribbler gets there; inf without opponents) and the score (-inf when the farthest probe
    is outside the field less the margin), into ``out``; ``params``: a :data:`FAN_PARAMS`
    record."""
    reach, coast = tables.reach, tables.coast
    dirs, clearance, score = out.dirs, out.clearance, out.score
    p = params[0]
    kickable, cap, goal_weight, x_max, y_max = p.kickable, p.cap, p.goal_weight, p.x_max, p.y_max
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
