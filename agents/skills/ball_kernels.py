"""The compiled kernels of the ball skills: kicks (:mod:`agents.skills.kicking`), ball lanes
(:mod:`agents.skills.lanes`), the offside line and the pass search
(:mod:`agents.skills.passing`), the spread of a kicked ball under the kick and ball noise
(:meth:`agents.skills.model.MotionModel.kick_spread`) and the shot scores
(:mod:`agents.skills.shooting`).

Arguments travel as named records, as in :mod:`soccer_sim.kernels`: the constants of a match
(and of a skill's parameters) as one-element numpy structured arrays read by field name
(:data:`KICK_MODEL`, :data:`PASS_PARAMS`, :data:`SHOT_PARAMS`, made with
:func:`soccer_sim.kernels.make_record`); arrays that belong together as named tuples read by
field name (:class:`PassLanes`, :class:`ShotAims`)."""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from agents.skills.interception_kernels import UNREACHABLE
from soccer_sim.body import ball_angle_to_body
from soccer_sim.kick_rate import kick_angle_rate, kick_distance_rate, kick_effectiveness
from soccer_sim.rules.offside import offside_line

LEAD_CAP = 10
"""Cycles of lead over the opponents beyond which a pass scores no better (the score's lead
term is ``min(lead, LEAD_CAP) / LEAD_CAP``)."""


def _fields(*names: str, kind: type = np.float64) -> list[tuple[str, type]]:
    return [(name, kind) for name in names]


KICK_MODEL = np.dtype(_fields(
    "kick_max", "ball_max", "distance_penalty", "angle_penalty", "kickable_margin", "touch", "inertia_moment"))
"""The kick rule as the kicker models it (:func:`kick_kernel`; made once per match,
:attr:`agents.skills.model.MotionModel.kick_model`): the largest kick (``kick_max``, rcssserver's
``max_power`` times ``kick_power_rate``) and ball speed, the kick rate's distance and angle
penalties, the kickable margin, the touch distance (player plus ball radius) and the player
type's inertia moment."""

PASS_PARAMS = np.dtype(_fields("x_max", "y_max", "min_distance", "max_distance", "decay")
                       + _fields("horizon", "extra_cycles", "min_lead", kind=np.int64)
                       + _fields("coast", "kickable", "half_length", "weight_forward", "weight_goal", "weight_space",
                                 "weight_lead"))
"""The pass search's constants for one match and one
:class:`~agents.skills.passing.PassParams` (:func:`pass_targets`, :func:`pass_scores`): the
largest |x| and |y| of a target, the usable pass distances, the ball decay, the search horizon,
the cycles searched beyond a lane's arrival, the smallest lead over the opponents (cycles), the
player coast factor at the horizon, the kickable distance, the field's half length and the
score's four weights."""

SHOT_PARAMS = np.dtype(_fields("kick_max", "kick_rand", "ball_rand", "post", "lead_half", "lead_scale"))
"""The shot scores' constants for one match and one :class:`~agents.skills.shooting.ShotParams`
(:func:`shot_scores`): the largest kick, the kick and ball noise, the largest |y| of a ball
entering the goal (the post less the ball radius) and the unblocked factor's logistic centre and
scale (cycles of lead)."""


class PassLanes(NamedTuple):
    """The usable lanes of a pass search, one row each (:func:`pass_scores`)."""

    targets: np.ndarray
    """(L, 2) where the pass goes."""
    owners: np.ndarray
    """(L,) int: the receiver of each."""
    arrival: np.ndarray
    """(L,) int: the cycle the ball gets to the target."""
    receive: np.ndarray
    """(L,) int: the cycle the receiver controls it (UNREACHABLE: never)."""
    received_at: np.ndarray
    """(L, 2) where it does."""
    theirs: np.ndarray
    """(L,) int: the first opponent's cycle."""


class ShotAims(NamedTuple):
    """The aims of a shot, one row each, ascending across the goal line (:func:`shot_scores`)."""

    aim_y: np.ndarray
    """(A,) y of each aim on the goal line (m)."""
    lead: np.ndarray
    """(A,) cycles by which the ball beats the opponents to the line."""
    kicks: np.ndarray
    """(A, 2) the kick requests."""
    velocities: np.ndarray
    """(A, 2) the ball velocities they give."""
    cross: np.ndarray
    """(A,) int: the cycle the ball crosses the line."""


@njit(cache=True, nogil=True)
def body_effect(rx: float, ry: float, rnorm: float, pvx: float, pvy: float,
                kick: np.ndarray) -> float:  # pragma: no cover - compiled
    """Effectiveness of any kick by a player moving at (``pvx``, ``pvy``) on the ball lying at
    (``rx``, ``ry``) from it (``rnorm`` away): the simulator's kick rate
    (:mod:`soccer_sim.kick_rate`, rcssserver's), with the body direction of
    :mod:`soccer_sim.body` (a player at rest or slow faces the ball); ``kick``: a
    :data:`KICK_MODEL` record."""
    k = kick[0]
    angle = ball_angle_to_body(pvx, pvy, rx, ry, k.inertia_moment)
    return kick_effectiveness(kick_distance_rate(rnorm, k.touch, k.kickable_margin), kick_angle_rate(angle),
                              k.distance_penalty, k.angle_penalty)


@njit(cache=True, nogil=True)
def effect(rx: float, ry: float, rnorm: float, base: float, angle_penalty: float, kx: float, ky: float,
           holder: bool) -> float:  # pragma: no cover - compiled
    """Effectiveness of a kick (``kx``, ``ky``): ``base`` (:func:`body_effect`); 1 for a
    goalkeeper holding the ball. The simulator's kick rule (rcssserver's) penalises where the
    ball lies relative to the kicker's body, not the kick's direction, so the kick's direction
    (and ``rx``, ``ry``, ``angle_penalty``) does not change it."""
    if holder:
        return 1.0
    return base


@njit(cache=True, nogil=True)
def effect_kernel(player: np.ndarray, player_vel: np.ndarray, ball: np.ndarray, kicks: np.ndarray, out: np.ndarray,
                  kick: np.ndarray) -> None:  # pragma: no cover - compiled
    """The effectiveness of each of ``kicks`` by a player at ``player`` moving at
    ``player_vel`` on the ball at ``ball`` (``kick``: a :data:`KICK_MODEL` record)."""
    rx, ry = ball[0] - player[0], ball[1] - player[1]
    rnorm = math.sqrt(rx * rx + ry * ry)
    base = body_effect(rx, ry, rnorm, player_vel[0], player_vel[1], kick)
    angle_penalty = kick[0].angle_penalty
    for j in range(kicks.shape[0]):
        out[j] = effect(rx, ry, rnorm, base, angle_penalty, kicks[j, 0], kicks[j, 1], False)


@njit(cache=True, nogil=True)
def largest_speed(ux: float, uy: float, vx: float, vy: float, low: float, high: float, kick_max: float,
                  eff: float) -> float:  # pragma: no cover - compiled
    """The largest speed s in [low, high] along the unit vector u such that the change
    ``s u - v`` fits in one kick of effectiveness ``eff`` (:func:`effect`; ``low`` does,
    ``high`` does not).

    The boundary solves ``|s u - v| = kick_max eff``, a quadratic in s. The result is checked
    and, if it is not feasible (rounding), bisection between ``low`` and it settles the
    matter.
    """
    along = ux * vx + uy * vy
    rest = vx * vx + vy * vy - along * along
    s = high
    for _ in range(5):
        reach = kick_max * eff
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
        if math.sqrt(cx * cx + cy * cy) <= kick_max * eff:
            return t
    high = s
    for _ in range(18):  # to within 2^-18 of the range (~1e-5 m/cycle)
        mid = 0.5 * (low + high)
        cx, cy = mid * ux - vx, mid * uy - vy
        if math.sqrt(cx * cx + cy * cy) <= kick_max * eff:
            low = mid
        else:
            high = mid
    return low


@njit(cache=True, nogil=True)
def kick_kernel(player: np.ndarray, player_vel: np.ndarray, ball: np.ndarray, ball_vel: np.ndarray,
                desired: np.ndarray, kick_out: np.ndarray, result_out: np.ndarray, kick: np.ndarray,
                holder: bool) -> None:  # pragma: no cover - compiled
    """The kick request (``kick_out``) that gives the ball each ``desired`` velocity, or the
    nearest one kick reaches, and the velocity it gets (``result_out``); see
    :mod:`agents.skills.kicking`. ``player_vel``: the kicker's velocity (its body direction,
    :func:`body_effect`); ``kick``: a :data:`KICK_MODEL` record; ``holder``: a goalkeeper
    holding the ball (full effectiveness)."""
    kick_max, ball_max, angle_penalty = kick[0].kick_max, kick[0].ball_max, kick[0].angle_penalty
    rx, ry = ball[0] - player[0], ball[1] - player[1]
    rnorm = math.sqrt(rx * rx + ry * ry)
    base = body_effect(rx, ry, rnorm, player_vel[0], player_vel[1], kick)
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
        eff = effect(rx, ry, rnorm, base, angle_penalty, cx, cy, holder)
        if size <= kick_max * eff + 1e-12:
            lam = 1.0
        else:
            ux, uy = (dx / speed, dy / speed) if speed > 1e-12 else (0.0, 0.0)
            closest = max(0.0, vx * ux + vy * uy)  # speed along the ray nearest the current velocity
            cx, cy = closest * ux - vx, closest * uy - vy
            size = math.sqrt(cx * cx + cy * cy)
            eff = effect(rx, ry, rnorm, base, angle_penalty, cx, cy, holder)
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
            lam = largest_speed(ux, uy, vx, vy, closest, speed, kick_max,
                                effect(rx, ry, rnorm, base, angle_penalty, cx, cy, holder)) / speed
        tx, ty = lam * dx, lam * dy
        cx, cy = tx - vx, ty - vy
        eff = max(effect(rx, ry, rnorm, base, angle_penalty, cx, cy, holder), 1e-9)
        kick_out[j, 0] = cx / eff
        kick_out[j, 1] = cy / eff
        result_out[j, 0] = tx
        result_out[j, 1] = ty


@njit(cache=True, nogil=True)
def lane_arrivals(targets: np.ndarray, wanted: np.ndarray, velocities: np.ndarray, ball: np.ndarray, decay: float,
                  horizon: int, extra: int, arrival: np.ndarray, limit: np.ndarray) -> np.ndarray:  # pragma: no cover
    """Which lanes work, and when the ball gets to the end of each (compiled).

    Row i: a ball at ``ball`` meant to reach ``targets[i]`` with the velocity ``wanted[i]``
    gets ``velocities[i]`` from the kick. Returns the rows whose kick keeps the intended line
    (within 1 %) and brings the ball to the target within ``horizon`` cycles, and writes their
    ``arrival`` cycle (rounded up) and search ``limit`` (arrival + ``extra``, at most the
    horizon)."""
    keep = np.empty(targets.shape[0], dtype=np.int64)
    count = 0
    for i in range(targets.shape[0]):
        wx, wy = wanted[i, 0], wanted[i, 1]
        norm = math.sqrt(wx * wx + wy * wy)
        vx, vy = velocities[i, 0], velocities[i, 1]
        speed = (vx * wx + vy * wy) / norm  # along the intended line
        if speed <= 0.99 * math.sqrt(vx * vx + vy * vy):
            continue
        dist = math.sqrt((targets[i, 0] - ball[0]) ** 2 + (targets[i, 1] - ball[1]) ** 2)
        left = 1.0 - dist * (1.0 - decay) / speed
        if left <= 0.0:
            continue
        cycles = math.ceil(math.log(left) / math.log(decay) - 1e-9)
        if cycles > horizon:
            continue
        arrival[i] = cycles
        limit[i] = min(cycles + extra, horizon)
        keep[count] = i
        count += 1
    return keep[:count]


@njit(cache=True, nogil=True)
def beyond_line(own_pos: np.ndarray, opp_pos: np.ndarray, ball_x: float) -> np.ndarray:  # pragma: no cover
    """Whether each of ``own_pos`` is beyond the offside line
    (:func:`soccer_sim.rules.offside.offside_line`)."""
    line = offside_line(opp_pos[:, 0], ball_x)
    out = np.empty(own_pos.shape[0], dtype=np.bool_)
    for i in range(own_pos.shape[0]):
        out[i] = own_pos[i, 0] > line
    return out


@njit(cache=True, nogil=True)
def deciding_cycles(receive: np.ndarray, arrival: np.ndarray, limit: np.ndarray,
                    min_lead: int) -> np.ndarray:  # pragma: no cover - compiled
    """Per lane, the last cycle at which an opponent's interception can still change the
    pass's safety or score: ``receive + max(LEAD_CAP, min_lead)`` or ``arrival + min_lead``,
    whichever is later, within ``limit``; 0 for a lane the receiver never reaches (it is not
    scored). Opponents later than that count as UNREACHABLE, which decides the same, so the
    search stops there (the opponents' search is most of a pass decision's cost)."""
    out = np.empty(receive.shape[0], dtype=np.int64)
    for i in range(receive.shape[0]):
        if receive[i] >= UNREACHABLE:
            out[i] = 0
        else:
            out[i] = min(limit[i], max(receive[i] + max(LEAD_CAP, min_lead), arrival[i] + min_lead))
    return out


@njit(cache=True, nogil=True)
def pass_targets(own_pos: np.ndarray, receivers: np.ndarray, leads: np.ndarray, speeds: np.ndarray, ball: np.ndarray,
                 params: np.ndarray, targets: np.ndarray, owners: np.ndarray,
                 wanted: np.ndarray) -> int:  # pragma: no cover - compiled
    """Candidate targets (receiver + lead, kept within |x| <= x_max, |y| <= y_max), each with
    each arrival speed, at a usable distance; the ball velocity each needs (``params``: a
    :data:`PASS_PARAMS` record). Returns the count."""
    p = params[0]
    x_max, y_max, min_distance, max_distance, decay = p.x_max, p.y_max, p.min_distance, p.max_distance, p.decay
    count = 0
    for r in range(receivers.shape[0]):
        who = receivers[r]
        for j in range(leads.shape[0]):
            tx = min(max(own_pos[who, 0] + leads[j, 0], -x_max), x_max)
            ty = min(max(own_pos[who, 1] + leads[j, 1], -y_max), y_max)
            dx, dy = tx - ball[0], ty - ball[1]
            dist = math.sqrt(dx * dx + dy * dy)
            if dist < min_distance or dist > max_distance:
                continue
            for k in range(speeds.shape[0]):
                speed = dist * (1.0 - decay) + speeds[k]
                targets[count, 0] = tx
                targets[count, 1] = ty
                owners[count] = who
                wanted[count, 0] = dx / dist * speed
                wanted[count, 1] = dy / dist * speed
                count += 1
    return count


@njit(cache=True, nogil=True)
def pass_scores(lanes: PassLanes, own_pos: np.ndarray, own_vel: np.ndarray, effort: np.ndarray,
                opp_pos: np.ndarray, ball: np.ndarray, reach: np.ndarray, params: np.ndarray, score: np.ndarray,
                points: np.ndarray) -> int:  # pragma: no cover - compiled
    """Score the safe ``lanes`` (see :mod:`agents.skills.passing`; ``params``: a
    :data:`PASS_PARAMS` record) into ``score``, and where each is received into ``points``;
    unsafe ones score -inf. Returns the best row, or -1 when none is safe."""
    targets, owners, arrival = lanes.targets, lanes.owners, lanes.arrival
    receive, received_at, theirs = lanes.receive, lanes.received_at, lanes.theirs
    p = params[0]
    coast, kickable, half_length, min_lead = p.coast, p.kickable, p.half_length, p.min_lead
    weight_forward, weight_goal, weight_space, weight_lead = p.weight_forward, p.weight_goal, p.weight_space, \
        p.weight_lead
    best, best_score = -1, -np.inf
    for i in range(targets.shape[0]):
        score[i] = -np.inf
        if receive[i] >= UNREACHABLE or theirs[i] - receive[i] < min_lead:
            continue
        who = owners[i]
        # Run onto it: the receiver takes the ball at the target when it can be there by the
        # ball's arrival and no opponent gets to the ball before; else where it meets it first.
        sx = own_pos[who, 0] + coast * own_vel[who, 0]
        sy = own_pos[who, 1] + coast * own_vel[who, 1]
        need = max(math.sqrt((targets[i, 0] - sx) ** 2 + (targets[i, 1] - sy) ** 2) - kickable, 0.0) / effort[who]
        run = np.searchsorted(reach, need)
        if run <= arrival[i] and theirs[i] >= arrival[i] + min_lead:
            px, py = targets[i, 0], targets[i, 1]
        else:
            px, py = received_at[i, 0], received_at[i, 1]
        points[i, 0] = px
        points[i, 1] = py
        space = 10.0
        for o in range(opp_pos.shape[0]):
            space = min(space, math.sqrt((px - opp_pos[o, 0]) ** 2 + (py - opp_pos[o, 1]) ** 2))
        lead = min(theirs[i] - receive[i], LEAD_CAP) / LEAD_CAP
        closeness = 1.0 - math.sqrt((px - half_length) ** 2 + py * py) / (2.0 * half_length)
        forward = min(max((px - ball[0]) / 20.0, -1.0), 1.5)
        value = weight_forward * forward + weight_goal * closeness + weight_space * space / 10.0 + weight_lead * lead
        score[i] = value
        if value > best_score:
            best, best_score = i, value
    return best


@njit(cache=True, nogil=True)
def kick_spread_at(distance_rate: float, angle_rate: float, speed_rate: float, power_rate: float,
                   launch_speed: float, travel: float, gain: float, kick_rand: float,
                   ball_rand: float) -> float:  # pragma: no cover - compiled
    """Standard deviation (m) across its line of a kicked ball ``travel`` (the ball-travel
    factor of the cycles since the kick) after the kick; see
    :meth:`agents.skills.model.MotionModel.kick_spread` for the rates and ``gain``. A random
    vector of length uniform in ``[0, a]`` and uniform direction has the standard deviation
    ``a / sqrt(6)`` across any line."""
    kick_reach = kick_rand * power_rate * (0.5 + 0.25 * (angle_rate + distance_rate) + speed_rate)
    ball_reach = ball_rand * launch_speed
    return math.sqrt(((kick_reach * travel) ** 2 + (ball_reach * gain) ** 2) / 6.0)


@njit(cache=True, nogil=True)
def kick_spreads(distance_rate: np.ndarray, angle_rate: np.ndarray, speed_rate: np.ndarray, power_rate: np.ndarray,
                 launch_speed: np.ndarray, cycles: np.ndarray, travel: np.ndarray, gain: np.ndarray, kick_rand: float,
                 ball_rand: float, out: np.ndarray) -> None:  # pragma: no cover - compiled
    """:func:`kick_spread_at` for each row of the (equal-length) arrays; ``cycles`` index the
    ``travel`` and ``gain`` tables."""
    for i in range(out.shape[0]):
        k = cycles[i]
        out[i] = kick_spread_at(distance_rate[i], angle_rate[i], speed_rate[i], power_rate[i], launch_speed[i],
                                travel[k], gain[k], kick_rand, ball_rand)


@njit(cache=True, nogil=True)
def shot_scores(aims: ShotAims, distance_rate: float, angle_rate: float, speed_rate: float, travel: np.ndarray,
                gain: np.ndarray, params: np.ndarray, window: np.ndarray,
                score: np.ndarray) -> int:  # pragma: no cover - compiled
    """The shooting score of each of the ``aims`` (see :mod:`agents.skills.shooting`) into
    ``score``; returns the best aim's row. ``distance_rate``, ``angle_rate``, ``speed_rate``: the
    kick noise's rates of this kick; ``travel``, ``gain``: the ball-travel and ball-noise tables;
    ``params``: a :data:`SHOT_PARAMS` record; ``window``: where across an error window (in units
    of its half-width) the unblocked factor is sampled. The error window is ``± sqrt(3)``
    standard deviations of :func:`kick_spread_at`; the unblocked factor between two aims is
    interpolated linearly, and held beyond the outermost ones."""
    aim_y, lead, kicks, velocities, cross = aims.aim_y, aims.lead, aims.kicks, aims.velocities, aims.cross
    p = params[0]
    kick_max, kick_rand, ball_rand, post = p.kick_max, p.kick_rand, p.ball_rand, p.post
    lead_half, lead_scale = p.lead_half, p.lead_scale
    count = aim_y.shape[0]
    unblocked = np.empty(count)
    for i in range(count):
        unblocked[i] = 1.0 / (1.0 + math.exp(-(lead[i] - lead_half) / lead_scale))
    best, best_score = 0, -1.0
    for i in range(count):
        power = min(math.sqrt(kicks[i, 0] ** 2 + kicks[i, 1] ** 2), kick_max) / kick_max
        launch = math.sqrt(velocities[i, 0] ** 2 + velocities[i, 1] ** 2)
        k = cross[i]
        half = max(math.sqrt(3.0) * kick_spread_at(distance_rate, angle_rate, speed_rate, power, launch, travel[k],
                                                   gain[k], kick_rand, ball_rand), 1e-6)
        total = 0.0
        for w in range(window.shape[0]):
            y = min(max(aim_y[i] + half * window[w], -post), post)
            j = 0
            while j < count - 1 and aim_y[j + 1] < y:
                j += 1
            if count == 1 or y <= aim_y[0]:
                total += unblocked[0]
            elif y >= aim_y[count - 1]:
                total += unblocked[count - 1]
            else:
                t = (y - aim_y[j]) / (aim_y[j + 1] - aim_y[j])
                total += unblocked[j] + t * (unblocked[j + 1] - unblocked[j])
        covered = max(min(aim_y[i] + half, post) - max(aim_y[i] - half, -post), 0.0)
        value = total / window.shape[0] * min(covered / (2.0 * half), 1.0)
        score[i] = value
        if value > best_score:
            best, best_score = i, value
    return best
