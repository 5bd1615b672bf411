"""The compiled loops of the simulator core (numba), in one place.

Each kernel runs once or twice per cycle over every player, where the same work written as a
handful of numpy calls would cost several times more (numpy's per-call overhead dominates
on arrays of 23 rows). Parameters fixed for a match travel as a named record: a one-element
numpy structured array whose fields the kernel reads by name (``params[0].ball_decay``); see
:func:`make_record`. Passing such a record costs the same as passing a plain float array.

Users: :mod:`soccer_sim.kinematics` (dash and stamina, movement noise, kick candidates,
decay), :mod:`soccer_sim.physics` (sub-steps, rcssserver's and swept ball contacts, the field
margin and teammate contacts), :mod:`soccer_sim.view` (mirrored views, command intake),
:mod:`soccer_sim.trivial_teams` (the chaser) and :mod:`soccer_sim.statistics` (distance run).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from soccer_sim.body import ball_angle_to_body
from soccer_sim.kick_rate import kick_angle_rate, kick_distance_rate, kick_effectiveness

REQUEST_CAP = 1e100
"""Longest dash or kick request the rules work with: a longer one is shortened to this length in
the same direction first. Any request above the physical limits is clipped to them anyway;
shortening it first keeps its length (and the products of the angle rules) from overflowing to
inf, which would turn a dash of 1e160 or a kick of 1.7e308 into none at all."""


def _fields(*names: str, kind: type = np.float64) -> list[tuple[str, type]]:
    return [(name, kind) for name in names]


PT_DASH_POWER_RATE, PT_EXTRA_STAMINA, PT_SPEED_MAX, PT_STAMINA_INC, PT_EFFORT_MIN, PT_EFFORT_MAX = 0, 1, 2, 3, 4, 5
PT_DECAY, PT_KICKABLE, PT_KICKABLE_MARGIN, PT_KICK_RAND, PT_INERTIA_MOMENT = 6, 7, 8, 9, 10
PT_CATCH_STRETCH = 11
PT_COLUMNS = 12
"""Columns of the per-player parameter table (one float64 row per player row): each player's
type's ``dash_power_rate``, ``extra_stamina``, ``player_speed_max``, ``stamina_inc_max``,
``effort_min``, ``effort_max``, ``player_decay``, kickable distance (centre to centre:
player and ball radii plus ``kickable_margin``), ``kickable_margin``, ``kick_rand`` and
``inertia_moment`` (:mod:`soccer_sim.player_types`)."""

DASH_PARAMS = np.dtype(_fields(
    "power_max", "side_rate", "back_rate", "heading_speed",
    "player_rand", "ball_rand", "stamina_max", "recover_dec_thr", "recover_dec", "recover_min",
    "effort_dec_thr", "effort_dec", "effort_inc_thr", "effort_inc"))
"""The dash and stamina rules and the movement noise (:func:`dash_players`); the thresholds are
absolute stamina values. The player type's parameters come from the per-player table."""

KICK_PARAMS = np.dtype(_fields(
    "kick_max", "ball_speed_max", "touch_distance", "angle_penalty", "distance_penalty",
    "speed_rate_scale") + _fields("cap_sum", kind=np.bool_))
"""The kick rule (:func:`apply_kicks`): ``speed_rate_scale`` is ``0.5 / (ball_speed_max *
ball_decay)``, ``cap_sum`` whether the cycle's kicks are capped together. The player type's
parameters come from the per-player table."""

DECAY_PARAMS = np.dtype(_fields("ball_decay"))
"""Ball decay (:func:`decay_velocities`; each player's decay comes from the per-player table)."""

MARGIN_PARAMS = np.dtype(_fields("home", "players", kind=np.int64) + _fields(
    "begin2", "end2", "x_max", "y_max"))
"""Player rows of home and of both sides, the squared centre distances below which a teammate
contact begins and above which it ends, the largest |x| and |y| of a player
(:func:`keep_in_field_and_count_contacts`)."""

SUBSTEP_PARAMS = np.dtype(_fields(
    "player_radius", "ball_radius", "max_step", "post_contact", "post_step", "post_x", "post_y")
    + _fields("ball_meets_players", kind=np.bool_))
"""Radii, the largest relative move per sub-step, the ball-post contact distance and the largest
ball step near a post, the post centre's |x| and |y|, and whether the collision solver meets
ball and players (:func:`substeps_needed`)."""

BALL_CONTACT_PARAMS = np.dtype(_fields("contact", "factor"))
"""Player-ball contact distance and the velocity factor of a contact (:func:`resolve_ball_contacts`)."""

OVERLAP_PARAMS = np.dtype(_fields("contact", "factor") + _fields("rounds", kind=np.int64))
"""Player-ball contact distance, the velocity factor of a contact and the most rounds of
separation per cycle (:func:`separate_ball_overlaps`)."""

SEPARATION_EPS = 1e-10
"""What rcssserver adds to each half of a separation (its ``EPS``), so that separated bodies
no longer count as overlapping."""


def make_record(dtype: np.dtype, **values: float | bool) -> np.ndarray:
    """A one-element record array of ``dtype`` with every field set by name (all are required)."""
    names = set(dtype.names or ())
    if set(values) != names:
        missing, unknown = sorted(names - set(values)), sorted(set(values) - names)
        raise TypeError(f"record fields missing {missing}, unknown {unknown}")
    record = np.zeros(1, dtype=dtype)
    for name, value in values.items():
        record[name] = value
    return record


# --- kinematics ------------------------------------------------------------------------------
@njit(cache=True, nogil=True)
def _perturb(vx: float, vy: float, rand: float, length_draw: float,
             angle_draw: float) -> tuple[float, float]:  # pragma: no cover - compiled
    """rcssserver's movement noise (``MPObject::noise``): a vector of length uniform in
    ``[0, rand * speed]`` and direction uniform in ``[-pi, pi)``, from two draws in [0, 1)."""
    length = math.sqrt(vx * vx + vy * vy) * rand * length_draw
    if length == 0.0:
        return vx, vy
    angle = (2.0 * angle_draw - 1.0) * math.pi
    return vx + length * math.cos(angle), vy + length * math.sin(angle)


@njit(cache=True, nogil=True)
def dash_direction_rate(ax: float, ay: float, size: float, vx: float, vy: float, speed: float, side_rate: float,
                        back_rate: float, heading_speed: float) -> float:  # pragma: no cover - compiled
    """The share of a dash's power that counts, for a dash (ax, ay) of length ``size`` by a
    player moving at (vx, vy), ``speed`` > 0 (rcssserver's ``dash_angle`` rates:
    ``side_rate`` at 90 degrees from the motion, ``back_rate`` against it, interpolated
    linearly in the angle, and weighted by the speed up to ``heading_speed``)."""
    cos = min(1.0, max(-1.0, (ax * vx + ay * vy) / (size * speed)))
    angle = math.degrees(math.acos(cos))
    if angle > 90.0:
        dir_rate = back_rate - (back_rate - side_rate) * (1.0 - (angle - 90.0) / 90.0)
    else:
        dir_rate = side_rate + (1.0 - side_rate) * (1.0 - angle / 90.0)
    weight = min(1.0, speed / heading_speed)
    return 1.0 - weight * (1.0 - dir_rate)


@njit(cache=True, nogil=True)
def _capped_request(x: float, y: float) -> tuple[float, float, float]:  # pragma: no cover - compiled
    """A dash or kick request (x, y) and its length, shortened to :data:`REQUEST_CAP` in the same
    direction when longer (or overflowing)."""
    size = math.sqrt(x * x + y * y)
    if size > REQUEST_CAP:
        big = max(abs(x), abs(y))
        x = x / big * REQUEST_CAP
        y = y / big * REQUEST_CAP
        size = math.sqrt(x * x + y * y)
    return x, y, size


@njit(cache=True, nogil=True)
def dash_players(vel: np.ndarray, ball_vel: np.ndarray, stamina: np.ndarray, effort: np.ndarray,
                 recovery: np.ndarray, capacity: np.ndarray, dash: np.ndarray, noise: np.ndarray,
                 params: np.ndarray, types: np.ndarray, speed_out: np.ndarray) -> float:  # pragma: no cover
    """The dash and stamina rules for every player row (see :mod:`soccer_sim.kinematics`), then
    the movement noise of every body; returns the top player speed. ``noise``: (P + 1, 2) draws
    in [0, 1), the players' rows then the ball's; ``params``: a :data:`DASH_PARAMS` record;
    ``types``: the per-player parameter table (``PT_*`` columns).

    As in rcssserver's ``MPObject::_inc``, a body's velocity is first clipped to its largest
    speed, then perturbed (so noise may carry it slightly beyond), then moved."""
    p = params[0]
    power_max, side_rate, back_rate, heading_speed = p.power_max, p.side_rate, p.back_rate, p.heading_speed
    player_rand, stamina_max = p.player_rand, p.stamina_max
    rec_thr, rec_dec, rec_min = p.recover_dec_thr, p.recover_dec, p.recover_min
    eff_dec_thr, eff_dec = p.effort_dec_thr, p.effort_dec
    eff_inc_thr, eff_inc = p.effort_inc_thr, p.effort_inc
    fastest = 0.0
    for i in range(vel.shape[0]):
        power_rate, extra, speed_max = types[i, PT_DASH_POWER_RATE], types[i, PT_EXTRA_STAMINA], types[i, PT_SPEED_MAX]
        inc_max, eff_min, eff_max = types[i, PT_STAMINA_INC], types[i, PT_EFFORT_MIN], types[i, PT_EFFORT_MAX]
        ax, ay, size = _capped_request(dash[i, 0], dash[i, 1])
        vx, vy = vel[i, 0], vel[i, 1]
        if size > 0.0:
            rate = 1.0
            speed = math.sqrt(vx * vx + vy * vy)
            if speed > 0.0:
                rate = dash_direction_rate(ax, ay, size, vx, vy, speed, side_rate, back_rate, heading_speed)
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
        speed = math.sqrt(vx * vx + vy * vy)
        if speed > speed_max:
            vx *= speed_max / speed
            vy *= speed_max / speed
        vx, vy = _perturb(vx, vy, player_rand, noise[i, 0], noise[i, 1])
        speed = math.sqrt(vx * vx + vy * vy)
        vel[i, 0] = vx
        vel[i, 1] = vy
        speed_out[i] = speed
        if speed > fastest:
            fastest = speed
    ball = vel.shape[0]
    ball_vel[0], ball_vel[1] = _perturb(ball_vel[0], ball_vel[1], p.ball_rand, noise[ball, 0], noise[ball, 1])
    return fastest


@njit(cache=True, nogil=True)
def find_kickers(pos: np.ndarray, ball: np.ndarray, kick: np.ndarray, mask: np.ndarray, holder: int,
                 types: np.ndarray, dist_out: np.ndarray, rows_out: np.ndarray) -> tuple[int, float]:  # pragma: no cover
    """Rows allowed by ``mask`` with the ball within their kickable distance (the per-player
    table ``types``, column ``PT_KICKABLE``; or holding it: ``holder``) and
    a non-zero kick into ``rows_out``; every player's centre distance to the ball into
    ``dist_out``; returns (count, nearest distance)."""
    bx, by = ball[0], ball[1]
    count = 0
    nearest = np.inf
    for i in range(pos.shape[0]):
        dx, dy = bx - pos[i, 0], by - pos[i, 1]
        d = math.sqrt(dx * dx + dy * dy)
        dist_out[i] = d
        if d < nearest:
            nearest = d
        if mask[i] and (d <= types[i, PT_KICKABLE] or i == holder) and (kick[i, 0] != 0.0 or kick[i, 1] != 0.0):
            rows_out[count] = i
            count += 1
    return count, nearest


@njit(cache=True, nogil=True)
def apply_kicks(kickers: np.ndarray, pos: np.ndarray, vel: np.ndarray, ball: np.ndarray, ball_vel: np.ndarray,
                kick: np.ndarray, dist: np.ndarray, holder: int, noise: np.ndarray,
                params: np.ndarray, types: np.ndarray) -> None:  # pragma: no cover - compiled
    """rcssserver's kick rule for the player rows ``kickers`` (see
    :meth:`soccer_sim.kinematics.Kinematics.kick`); changes ``ball_vel`` in place. ``noise``:
    (P, 2) draws in [0, 1) (length, direction) of each player's kick noise; ``params``: a
    :data:`KICK_PARAMS` record; ``types``: the per-player parameter table (``PT_*`` columns)."""
    p = params[0]
    kick_max, touch = p.kick_max, p.touch_distance
    ax = ay = 0.0
    bx, by = ball[0], ball[1]
    speed_rate = 0.5 + p.speed_rate_scale * math.sqrt(ball_vel[0] * ball_vel[0] + ball_vel[1] * ball_vel[1])
    for k in range(kickers.shape[0]):
        row = kickers[k]
        margin = types[row, PT_KICKABLE_MARGIN]
        kx, ky, power = _capped_request(kick[row, 0], kick[row, 1])
        if power > kick_max:
            kx *= kick_max / power
            ky *= kick_max / power
            power = kick_max
        angle_rate = 0.0  # dir_diff / 180°
        distance_rate = 0.0  # dist_ball / kickable_margin
        if row != holder:
            distance_rate = kick_distance_rate(dist[row], touch, margin)
            angle_rate = kick_angle_rate(ball_angle_to_body(vel[row, 0], vel[row, 1], bx - pos[row, 0],
                                                            by - pos[row, 1], types[row, PT_INERTIA_MOMENT]))
        effect = kick_effectiveness(distance_rate, angle_rate, p.distance_penalty, p.angle_penalty)
        kx *= effect
        ky *= effect
        # rcssserver's kick noise: largest length kick_rand * power / max_power * (pos_rate +
        # speed_rate), each rate within [0.5, 1].
        pos_rate = 0.5 + 0.25 * (angle_rate + distance_rate)
        reach = types[row, PT_KICK_RAND] * (power / kick_max) * (pos_rate + speed_rate) * noise[row, 0]
        turn = (2.0 * noise[row, 1] - 1.0) * math.pi
        kx += reach * math.cos(turn)
        ky += reach * math.sin(turn)
        if not p.cap_sum:
            change = math.sqrt(kx * kx + ky * ky)
            if change > kick_max:
                kx *= kick_max / change
                ky *= kick_max / change
        ax += kx
        ay += ky
    change = math.sqrt(ax * ax + ay * ay)
    if change > kick_max and p.cap_sum:
        ax *= kick_max / change
        ay *= kick_max / change
    vx = ball_vel[0] + ax
    vy = ball_vel[1] + ay
    speed = math.sqrt(vx * vx + vy * vy)
    if speed > p.ball_speed_max:
        vx *= p.ball_speed_max / speed
        vy *= p.ball_speed_max / speed
    ball_vel[0] = vx
    ball_vel[1] = vy


@njit(cache=True, nogil=True)
def decay_velocities(vel: np.ndarray, ball_vel: np.ndarray, params: np.ndarray,
                     types: np.ndarray) -> None:  # pragma: no cover - compiled
    """Velocity decay of players and ball after the move. ``params``: a :data:`DECAY_PARAMS`
    record; ``types``: the per-player parameter table (column ``PT_DECAY``)."""
    ball_decay = params[0].ball_decay
    for i in range(vel.shape[0]):
        player_decay = types[i, PT_DECAY]
        vel[i, 0] *= player_decay
        vel[i, 1] *= player_decay
    ball_vel[0] *= ball_decay
    ball_vel[1] *= ball_decay


# --- physics ---------------------------------------------------------------------------------
@njit(cache=True, nogil=True)
def keep_in_field_and_count_contacts(data: np.ndarray, in_contact: np.ndarray, params: np.ndarray,
                                     counts: np.ndarray) -> None:  # pragma: no cover - compiled
    """Clamp the players (body rows 0..P-1) into the field plus margin, update the teammate
    contact matrix and add the contacts that began to ``counts`` (per team). ``params``: a
    :data:`MARGIN_PARAMS` record."""
    p = params[0]
    home, n2 = p.home, p.players
    begin2, end2, x_max, y_max = p.begin2, p.end2, p.x_max, p.y_max
    for i in range(n2):
        data[i, 0] = min(max(data[i, 0], -x_max), x_max)
        data[i, 1] = min(max(data[i, 1], -y_max), y_max)
    for team in range(2):
        first = 0 if team == 0 else home
        last = home if team == 0 else n2
        for i in range(first, last):
            xi, yi = data[i, 0], data[i, 1]
            for j in range(i + 1, last):
                dx, dy = data[j, 0] - xi, data[j, 1] - yi
                d2 = dx * dx + dy * dy
                if in_contact[i, j]:
                    if d2 > end2:
                        in_contact[i, j] = False
                elif d2 < begin2:
                    in_contact[i, j] = True
                    counts[team] += 1


@njit(cache=True, nogil=True)
def substeps_needed(bodies: np.ndarray, ball_free: bool, params: np.ndarray) -> int:  # pragma: no cover
    """Sub-steps a cycle needs (see :class:`soccer_sim.physics.SubstepPlanner`). ``bodies``: rows
    ``[x, y, vx, vy]`` of the players then the ball; ``params``: a :data:`SUBSTEP_PARAMS` record."""
    p = params[0]
    r_player, r_ball, step, post_contact, post_step, post_x, post_y = (
        p.player_radius, p.ball_radius, p.max_step, p.post_contact, p.post_step, p.post_x, p.post_y)
    ball_meets_players = p.ball_meets_players
    n2 = bodies.shape[0] - 1
    need = 1.0
    pair_step = 2.0 * step
    for i in range(n2):
        xi, yi, ui, wi = bodies[i, 0], bodies[i, 1], bodies[i, 2], bodies[i, 3]
        for j in range(i + 1, n2):
            du, dw = ui - bodies[j, 2], wi - bodies[j, 3]
            closing = math.sqrt(du * du + dw * dw)
            if closing > pair_step * need:
                dx, dy = xi - bodies[j, 0], yi - bodies[j, 1]
                if math.sqrt(dx * dx + dy * dy) - 2.0 * r_player <= closing:
                    need = closing / pair_step
    if ball_free:
        bx, by, bu, bw = bodies[n2, 0], bodies[n2, 1], bodies[n2, 2], bodies[n2, 3]
        for j in range(n2 if ball_meets_players else 0):
            du, dw = bu - bodies[j, 2], bw - bodies[j, 3]
            closing = math.sqrt(du * du + dw * dw)
            if closing > step * need:
                dx, dy = bx - bodies[j, 0], by - bodies[j, 1]
                if math.sqrt(dx * dx + dy * dy) - r_player - r_ball <= closing:
                    need = closing / step
        speed = math.sqrt(bu * bu + bw * bw)
        if speed > post_step * need:
            dx, dy = post_x - abs(bx), post_y - abs(by)
            if math.sqrt(dx * dx + dy * dy) - post_contact <= speed:
                need = speed / post_step
    return int(math.ceil(need - 1e-9))


@njit(cache=True, nogil=True)
def resolve_ball_contacts(before: np.ndarray, after: np.ndarray, ghost: np.ndarray, params: np.ndarray,
                          rows_out: np.ndarray) -> int:  # pragma: no cover - compiled
    """Swept body-ball contacts (``body_ball_contact = "swept"``, not rcssserver's rule: see
    :func:`separate_ball_overlaps` for that); returns how many contacts it resolved (their
    player rows in ``rows_out``).

    ``before``/``after``: rows ``[x, y, vx, vy]`` of the players then the ball, at the start
    and the end of the cycle's move (``after`` is corrected in place). Each body is taken to
    move in a straight line between the two, so the sweep is exact for any speed: the earliest
    moment the ball's disc meets a player's disc (``contact``: the sum of the radii) is found,
    and both are put back where they were at that moment, with their velocities multiplied by
    ``factor`` (-0.1); ``params`` is a :data:`BALL_CONTACT_PARAMS` record. A player already
    overlapping the ball at the start pushes it out radially. Further rounds put back any
    player that ran into the ball's corrected position later in the cycle (along the player's
    own path, the ball staying). Rows with ``ghost`` set (this cycle's kickers) are passed through.
    """
    p = params[0]
    contact, factor = p.contact, p.factor
    contact2 = contact * contact
    n2 = after.shape[0] - 1
    count = 0
    b0x, b0y = before[n2, 0], before[n2, 1]
    dbx, dby = after[n2, 0] - b0x, after[n2, 1] - b0y
    for round_ in range(rows_out.shape[0]):
        best_t, best = 2.0, -1
        for i in range(n2):
            if ghost[i]:
                continue
            p0x, p0y = before[i, 0], before[i, 1]
            rx, ry = b0x - p0x, b0y - p0y
            drx, dry = dbx - (after[i, 0] - p0x), dby - (after[i, 1] - p0y)
            c = rx * rx + ry * ry - contact2
            if c <= 0.0:
                t = 0.0
            else:
                a = drx * drx + dry * dry
                b = rx * drx + ry * dry
                if a == 0.0 or b >= 0.0:
                    continue
                disc = b * b - a * c
                if disc < 0.0:
                    continue
                t = (-b - math.sqrt(disc)) / a
                if t > 1.0:
                    continue
            if t < best_t:
                best_t, best = t, i
        if best < 0:
            break
        t = best_t
        px = before[best, 0] + t * (after[best, 0] - before[best, 0])
        py = before[best, 1] + t * (after[best, 1] - before[best, 1])
        bx, by = b0x + t * dbx, b0y + t * dby
        ox, oy = bx - px, by - py
        gap = math.sqrt(ox * ox + oy * oy)
        if gap < contact:  # overlapping from the start: push the ball out radially
            if gap > 1e-12:
                bx, by = px + ox * contact / gap, py + oy * contact / gap
            else:
                bx, by = px + contact, py
        after[best, 0], after[best, 1] = px, py
        after[best, 2] *= factor
        after[best, 3] *= factor
        after[n2, 0], after[n2, 1] = bx, by
        if round_ == 0:
            after[n2, 2] *= factor
            after[n2, 3] *= factor
        rows_out[count] = best
        count += 1
        ghost[best] = True  # resolved: not met again this cycle
        # Later rounds: the ball stays at its corrected position for the whole sweep.
        b0x, b0y, dbx, dby = bx, by, 0.0, 0.0
        for k in range(n2):
            before[k, 0] = before[k, 0] + t * (after[k, 0] - before[k, 0])
            before[k, 1] = before[k, 1] + t * (after[k, 1] - before[k, 1])
    for k in range(count):
        ghost[rows_out[k]] = False
    return count


@njit(cache=True, nogil=True)
def separate_ball_overlaps(bodies: np.ndarray, play_on: bool, collided: np.ndarray, params: np.ndarray,
                           rows_out: np.ndarray) -> int:  # pragma: no cover - compiled
    """rcssserver's end-of-cycle body-ball overlap resolution (``Stadium::collisions`` with
    ``calcCollisionPos``); returns how many players touched the ball (their rows, in order of
    first contact, in ``rows_out``).

    ``bodies``: rows ``[x, y, vx, vy]`` of the players then the ball, after the cycle's move
    (corrected in place); ``collided``: a (P,) bool scratch array, all False on entry and on
    return; ``params``: an :data:`OVERLAP_PARAMS` record. Each round, every player whose
    centre is closer to the ball's than ``contact`` is separated from it: in play on both are
    moved apart from their midpoint along the line of centres to ``contact / 2`` each (plus
    :data:`SEPARATION_EPS`); otherwise the ball stays and the player is moved off it. A ball
    that met several players goes to the mean of its separated positions. Rounds repeat while
    an overlap remains (at most ``rounds``); then the velocities of the ball and of every
    player that touched it are multiplied by ``factor`` once. Two bodies on the same centre
    are separated along +x (rcssserver draws a random direction; a measure-zero case).
    """
    p = params[0]
    contact, factor = p.contact, p.factor
    contact2 = contact * contact
    half = contact / 2.0 + SEPARATION_EPS
    n2 = bodies.shape[0] - 1
    count = 0
    for _ in range(p.rounds):
        bx, by = bodies[n2, 0], bodies[n2, 1]
        sum_x = sum_y = 0.0
        met = 0
        for i in range(n2):
            px, py = bodies[i, 0], bodies[i, 1]
            dx, dy = px - bx, py - by
            if dx * dx + dy * dy >= contact2:
                continue
            if not collided[i]:
                collided[i] = True
                rows_out[count] = i
                count += 1
            if play_on:
                mx, my = (px + bx) / 2.0, (py + by) / 2.0
                ux, uy = px - mx, py - my
                r = math.sqrt(ux * ux + uy * uy)
                if r < SEPARATION_EPS:
                    ux, uy, r = 1.0, 0.0, 1.0
                scale = half / r
                ux *= scale
                uy *= scale
                # rcssserver widens the separation by 0.01 % steps while rounding keeps the
                # two just inside the contact distance.
                steps = 0
                while 4.0 * (ux * ux + uy * uy) < contact2 and steps < 10:
                    ux *= 1.0001
                    uy *= 1.0001
                    steps += 1
                bodies[i, 0], bodies[i, 1] = mx + ux, my + uy
                sum_x += mx - ux
                sum_y += my - uy
            else:
                r = math.sqrt(dx * dx + dy * dy)
                if r < SEPARATION_EPS:
                    dx, dy, r = 1.0, 0.0, 1.0
                scale = (contact + SEPARATION_EPS) / r
                bodies[i, 0], bodies[i, 1] = bx + dx * scale, by + dy * scale
                sum_x += bx
                sum_y += by
            met += 1
        if met == 0:
            break
        bodies[n2, 0], bodies[n2, 1] = sum_x / met, sum_y / met
    if count:
        bodies[n2, 2] *= factor
        bodies[n2, 3] *= factor
        for k in range(count):
            i = rows_out[k]
            bodies[i, 2] *= factor
            bodies[i, 3] *= factor
            collided[i] = False
    return count


# --- team views and commands -----------------------------------------------------------------
@njit(cache=True, nogil=True)
def one_body_command(commands: np.ndarray, tackle: np.ndarray, catch: np.ndarray, goalie_rows: np.ndarray,
                     moving: np.ndarray, home: int, ignored: np.ndarray) -> None:  # pragma: no cover - compiled
    """rcssserver executes one body command per player and cycle, the first it receives
    (``M_command_done`` in ``player.cpp``); a team sends its commands at once, so the match keeps
    the one of highest priority, tackle > catch > kick > move > dash, and drops the others.

    ``commands``: (P, 4) rows ``[dash, kick]``, a dropped kick or dash zeroed in place (a
    non-zero vector is a command); ``tackle``: (P,) tackle directions, NaN for none; ``catch``:
    (2,) each team's goalkeeper's catch request, cleared when that goalkeeper tackles;
    ``goalie_rows``: (2,) the goalkeepers' rows (-1: none); ``moving``: (P,) the rows a
    kick-off placement moves this cycle, cleared where a higher command was sent; ``home``:
    home's player count (rows below it are home's); ``ignored``: (2,) each team's count of
    dropped commands, added to."""
    for i in range(commands.shape[0]):
        team = 0 if i < home else 1
        dash = commands[i, 0] != 0.0 or commands[i, 1] != 0.0
        kick = commands[i, 2] != 0.0 or commands[i, 3] != 0.0
        catches = catch[team] and goalie_rows[team] == i
        move = moving[i]
        if not math.isnan(tackle[i]):
            dropped = int(catches) + int(kick) + int(move) + int(dash)
            if catches:
                catch[team] = False
        elif catches:
            dropped = int(kick) + int(move) + int(dash)
        elif kick:
            dropped = int(move) + int(dash)
        elif move:
            dropped = int(dash)
        else:
            continue
        if dropped == 0:
            continue
        ignored[team] += dropped
        if not math.isnan(tackle[i]) or catches:
            commands[i, 2] = commands[i, 3] = 0.0
        commands[i, 0] = commands[i, 1] = 0.0
        if move and (kick or catches or not math.isnan(tackle[i])):
            moving[i] = False


@njit(cache=True, nogil=True)
def store_command(dash: np.ndarray, kick: np.ndarray, sign: float,
                  out: np.ndarray) -> int:  # pragma: no cover - compiled
    """Write ``sign * dash`` and ``sign * kick`` into ``out`` ((n, 4) rows ``[dash, kick]``);
    return -1 if every value is finite, else the first bad row (plus n if it is in ``kick``)."""
    n = dash.shape[0]
    bad = -1
    for i in range(n):
        for k in range(2):
            d = dash[i, k]
            c = kick[i, k]
            out[i, k] = sign * d
            out[i, 2 + k] = sign * c
            if bad < 0:
                if not np.isfinite(d):
                    bad = i
                elif not np.isfinite(c):
                    bad = n + i
    return bad


@njit(cache=True, nogil=True)
def mirror_bodies(bodies: np.ndarray, sign: float, pos_out: np.ndarray, vel_out: np.ndarray, first: int,
                  stamina: np.ndarray, effort: np.ndarray, capacity: np.ndarray, stamina_out: np.ndarray,
                  effort_out: np.ndarray, capacity_out: np.ndarray) -> None:  # pragma: no cover - compiled
    """Positions and velocities of ``bodies`` (rows ``[x, y, vx, vy]``) times ``sign`` into
    ``pos_out``/``vel_out``, and one team's stamina, effort and capacity (rows ``first``
    onwards) into the ``*_out`` arrays."""
    for i in range(bodies.shape[0]):
        pos_out[i, 0] = sign * bodies[i, 0]
        pos_out[i, 1] = sign * bodies[i, 1]
        vel_out[i, 0] = sign * bodies[i, 2]
        vel_out[i, 1] = sign * bodies[i, 3]
    for i in range(stamina_out.shape[0]):
        stamina_out[i] = stamina[first + i]
        effort_out[i] = effort[first + i]
        capacity_out[i] = capacity[first + i]


@njit(cache=True, nogil=True)
def chase_ball(own_pos: np.ndarray, ball: np.ndarray, ball_vel: np.ndarray, goal_x: float, kick_speed: float,
               gain: float, kickable: float, dash: np.ndarray, kick: np.ndarray) -> None:  # pragma: no cover
    """A player with the ball within ``kickable`` (m) kicks it so that it leaves at
    ``kick_speed`` towards (goal_x, 0); every other player dashes at the ball (one body command
    each, as the match executes only one)."""
    bx, by = ball[0], ball[1]
    dx, dy = goal_x - bx, -by
    scale = kick_speed / max(math.sqrt(dx * dx + dy * dy), 1e-9)
    kx, ky = dx * scale - ball_vel[0], dy * scale - ball_vel[1]
    for i in range(own_pos.shape[0]):
        rx, ry = bx - own_pos[i, 0], by - own_pos[i, 1]
        if rx * rx + ry * ry <= kickable * kickable:
            dash[i, 0] = dash[i, 1] = 0.0
            kick[i, 0] = kx
            kick[i, 1] = ky
        else:
            dash[i, 0] = rx * gain
            dash[i, 1] = ry * gain
            kick[i, 0] = kick[i, 1] = 0.0


@njit(cache=True, nogil=True)
def add_distances(pos: np.ndarray, previous: np.ndarray, distance: np.ndarray,
                  relocation: float) -> None:  # pragma: no cover - compiled
    """Add each player's displacement since ``previous`` to ``distance`` (relocations left out)
    and remember the positions. Compiled because it runs every cycle: one call costs about a
    tenth of the equivalent numpy expressions (0.5 against 7 microseconds for 22 players)."""
    for i in range(pos.shape[0]):
        dx, dy = pos[i, 0] - previous[i, 0], pos[i, 1] - previous[i, 1]
        step = math.sqrt(dx * dx + dy * dy)
        if step <= relocation:
            distance[i] += step
        previous[i, 0] = pos[i, 0]
        previous[i, 1] = pos[i, 1]
