"""Compiled kernels of the see model, the self-localisation and ``sense_body``: the one
implementation of their formulas (:mod:`.see`, :mod:`.localise` and :mod:`.observer` call them;
the formulas are documented there and in ``docs/simulator.md`` §12).

Compiled because a partially observed match runs them every cycle for up to 22 observers x
(23 objects + 55 flags): as numpy expressions they cost about 0.6 ms per cycle, four times a
whole cycle of the full-observation match. Angles are degrees, distances metres.

Parameters travel as a named record (:data:`SEE_PARAMS`, made by :func:`see_record` from
:class:`~.params.SeeParams`; the kernels read its fields by name, as :mod:`soccer_sim.kernels`
does), so the kernels have one signature whatever the configuration; arrays that travel together
(the players' constants, this cycle's truth, the outputs) are named tuples read by field name.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from soccer_sim.body import facing
from soccer_sim.kernels import make_record
from soccer_sim.perception.params import SeeParams

EPS = 1.0e-10
"""rcssserver's ``EPS`` (``utility.h``), added before the logarithm."""

UNSEEN, ANONYMOUS, TEAM_ONLY, FULL = -1, 0, 1, 2
"""Identity levels (:mod:`.see`)."""

SEE_PARAMS = np.dtype(
    [(name, np.float64) for name in (
        "half_angle", "visible_distance", "quantize_step", "quantize_step_l", "distance_step", "direction_step",
        "unum_far_length", "unum_too_far_length", "team_far_length", "team_too_far_length",
        "max_observation_length")]
    + [("omnidirectional", np.bool_), ("exact_self", np.bool_)])
"""The see model's and the self-localisation's parameters (:class:`~.params.SeeParams`' fields
of the same names, degrees and metres; ``half_angle`` is half its ``visible_angle``)."""


def see_record(params: SeeParams) -> np.ndarray:
    """``params`` as the kernels' :data:`SEE_PARAMS` record."""
    return make_record(
        SEE_PARAMS, half_angle=params.visible_angle / 2.0, visible_distance=params.visible_distance,
        quantize_step=params.quantize_step, quantize_step_l=params.quantize_step_l,
        distance_step=params.distance_step, direction_step=params.direction_step,
        unum_far_length=params.unum_far_length, unum_too_far_length=params.unum_too_far_length,
        team_far_length=params.team_far_length, team_too_far_length=params.team_too_far_length,
        max_observation_length=params.max_observation_length, omnidirectional=params.omnidirectional,
        exact_self=params.exact_self)


class SightingRows(NamedTuple):
    """What observers see of the objects (object 0 the ball, then the players): one row per
    observer, or one observer's row, of :class:`~.see.Sightings`' arrays (unseen: NaN, UNSEEN)."""

    seen: np.ndarray
    distance: np.ndarray
    direction: np.ndarray
    identity: np.ndarray
    in_cone: np.ndarray


class TrueBodies(NamedTuple):
    """This cycle's truth that :func:`perceive` perceives, absolute frame: the players' (P, 2)
    positions (m) and velocities (m/cycle), the ball (2,) m, who is on the pitch (P,), each
    player's neck angle (P,) (degrees relative to its body, :mod:`.neck`) and half its view
    cone (P,) (degrees: its view width's, :mod:`.view_width`)."""

    pos: np.ndarray
    vel: np.ndarray
    ball: np.ndarray
    present: np.ndarray
    neck: np.ndarray
    half_angle: np.ndarray


class ObserverRows(NamedTuple):
    """Each player row's constants for :func:`perceive` (P,): its ``inertia_moment``, its
    ``player_decay``, its team (0 home, 1 away) and the row of its team's first player."""

    inertia: np.ndarray
    decay: np.ndarray
    team: np.ndarray
    first: np.ndarray


class Perception(NamedTuple):
    """What :func:`perceive` writes, one row per player, in each player's team frame: the
    arrays of :class:`~.views.PlayerViews` of the same names, and ``seen_rows`` (P, K) the player
    row behind each seen player (-1 padding, for tests and statistics)."""

    body_direction: np.ndarray
    neck_angle: np.ndarray
    position: np.ndarray
    velocity: np.ndarray
    localised: np.ndarray
    ball_seen: np.ndarray
    ball_distance: np.ndarray
    ball_direction: np.ndarray
    ball: np.ndarray
    seen_count: np.ndarray
    seen_distance: np.ndarray
    seen_direction: np.ndarray
    seen_position: np.ndarray
    seen_side: np.ndarray
    seen_number: np.ndarray
    seen_rows: np.ndarray


@njit(cache=True, nogil=True)
def _quantize(value: float, step: float) -> float:  # pragma: no cover - compiled
    """rcssserver's ``Quantize``: ``rint(value / step) * step``; ``value`` itself for ``step``
    0 (no quantisation: :meth:`~.params.SeeParams.without_noise`)."""
    if step == 0.0:
        return value
    return np.rint(value / step) * step


@njit(cache=True, nogil=True)
def _reported_distance(distance: float, log_step: float, final_step: float) -> float:  # pragma: no cover - compiled
    """``Quantize(exp(Quantize(log(d + EPS), log_step)), final_step)``; with ``log_step`` 0 the
    logarithmic step is skipped (both 0: ``d`` itself, no quantisation)."""
    if log_step == 0.0:
        return _quantize(distance, final_step)
    return _quantize(math.exp(_quantize(math.log(distance + EPS), log_step)), final_step)


@njit(cache=True, nogil=True)
def reported_distances(distance: np.ndarray, log_step: float, final_step: float,
                       out: np.ndarray) -> None:  # pragma: no cover - compiled
    """:func:`_reported_distance` of every element of ``distance`` (flat arrays) into ``out``."""
    for i in range(distance.shape[0]):
        out[i] = _reported_distance(distance[i], log_step, final_step)


@njit(cache=True, nogil=True)
def _wrap(angle: float) -> float:  # pragma: no cover - compiled
    """``angle`` (degrees) folded into [-180, 180)."""
    return (angle + 180.0) % 360.0 - 180.0


@njit(cache=True, nogil=True)
def _drop_chance(distance: float, far: float, too_far: float) -> float:  # pragma: no cover - compiled
    """The linear chance of losing an identity at reported ``distance``, clipped to [0, 1]."""
    if too_far == far:
        return 1.0 if distance > far else 0.0
    return min(1.0, max(0.0, (distance - far) / (too_far - far)))


@njit(cache=True, nogil=True)
def body_degrees(pos: np.ndarray, vel: np.ndarray, ball: np.ndarray, inertia: np.ndarray,
                 out: np.ndarray) -> None:  # pragma: no cover - compiled
    """Each player's body direction (degrees) by :func:`soccer_sim.body.facing` into ``out``."""
    for i in range(pos.shape[0]):
        fx, fy = facing(vel[i, 0], vel[i, 1], ball[0] - pos[i, 0], ball[1] - pos[i, 1], inertia[i])
        out[i] = math.degrees(math.atan2(fy, fx))


@njit(cache=True, nogil=True)
def _sensed(vx: float, vy: float, face: float, direction_step: float) -> tuple[float, float]:  # pragma: no cover
    """``sense_body``'s velocity: speed quantised to 0.01 m/cycle, direction relative to the
    face (``face`` degrees: body plus neck) rounded to ``direction_step`` degrees."""
    speed = _quantize(math.hypot(vx, vy), 0.01)
    heading = math.radians(face + _quantize(_wrap(math.degrees(math.atan2(vy, vx)) - face), direction_step))
    return speed * math.cos(heading), speed * math.sin(heading)


@njit(cache=True, nogil=True)
def sense_velocities(vel: np.ndarray, body: np.ndarray, direction_step: float,
                     out: np.ndarray) -> None:  # pragma: no cover - compiled
    """:func:`_sensed` of every player into ``out``."""
    for i in range(vel.shape[0]):
        out[i, 0], out[i, 1] = _sensed(vel[i, 0], vel[i, 1], body[i], direction_step)


@njit(cache=True, nogil=True)
def _in_cone(dx: float, dy: float, dist: float, bx: float, by: float, cos_half: float,
             prm: np.ndarray) -> bool:  # pragma: no cover - compiled
    """Whether an object at offset ``(dx, dy)`` (distance ``dist``) lies in the view cone of a
    player facing the unit vector ``(bx, by)``: ``|dir| < visible_angle / 2`` (as ``cos dir >
    cos(visible_angle / 2)``, which spares the arctangent of the objects out of view) and
    ``dist < max_observation_length``; any direction when omnidirectional."""
    if dist >= prm[0].max_observation_length:
        return False
    if prm[0].omnidirectional:
        return True
    return dx * bx + dy * by > dist * cos_half


_SLACK = 1.0e-9
"""Relative slack of :func:`_surely_unseen`'s tests on squares, far above their rounding errors."""


@njit(cache=True, nogil=True)
def _unseen_bounds(cos_half: float, close: float, prm: np.ndarray) -> tuple[float, float]:  # pragma: no cover
    """:func:`_surely_unseen`'s bounds for one observer: the squared ``close`` distance and the
    squared cosine of the half view angle, each with :data:`_SLACK` to spare; (inf, 0) -- the
    shortcut off -- when omnidirectional or for a cone as wide as a half-plane or wider."""
    if prm[0].omnidirectional or cos_half <= 0.0:
        return math.inf, 0.0
    return close * close * (1.0 + _SLACK), cos_half * cos_half * (1.0 - _SLACK)


@njit(cache=True, nogil=True)
def _surely_unseen(dx: float, dy: float, bx: float, by: float, close2: float,
                   cos2: float) -> bool:  # pragma: no cover - compiled
    """Whether an object at offset ``(dx, dy)`` is certainly outside the view cone of a player
    facing ``(bx, by)`` and farther than its close distance, judged on squared lengths with the
    bounds of :func:`_unseen_bounds`, so most objects out of view need no distance (a square
    root): when this says True, :func:`_in_cone` and ``dist <= close`` would both say False
    (False here decides nothing)."""
    d2 = dx * dx + dy * dy
    if not d2 > close2:
        return False
    dot = dx * bx + dy * by
    return dot <= 0.0 or dot * dot < d2 * cos2


@njit(cache=True, nogil=True)
def _flag_fix(fx: float, fy: float, distance: float, direction: float) -> tuple[float, float]:  # pragma: no cover
    """Where an observer stands that sees the flag at ``(fx, fy)`` at ``distance`` (m) in the
    absolute ``direction`` (degrees: its look direction plus the reported relative one):
    ``f - d (cos a, sin a)``, one flag's term of the self-localisation mean."""
    a = math.radians(direction)
    return fx - distance * math.cos(a), fy - distance * math.sin(a)


@njit(cache=True, nogil=True)
def position_from_sightings(flags: np.ndarray, distances: np.ndarray, directions: np.ndarray,
                            look: float) -> tuple[float, float]:  # pragma: no cover - compiled
    """The self-localisation estimate from reported sightings: the mean of :func:`_flag_fix`
    over the flags at ``flags`` (k, 2) m seen at ``distances`` (k,) m and ``directions`` (k,)
    degrees relative to the look direction ``look`` (degrees, absolute); NaN for k = 0. The
    same formula :func:`_localise_one` applies to the distances and directions it computes."""
    k = flags.shape[0]
    if k == 0:
        return np.nan, np.nan
    sx = 0.0
    sy = 0.0
    for f in range(k):
        x, y = _flag_fix(flags[f, 0], flags[f, 1], distances[f], look + directions[f])
        sx += x
        sy += y
    return sx / k, sy / k


@njit(cache=True, nogil=True)
def _localise_one(px: float, py: float, body: float, half: float, flags: np.ndarray,
                  prm: np.ndarray) -> tuple[float, float, int]:  # pragma: no cover - compiled
    """One player's position from the flags it sees looking along ``body`` with a cone of half
    angle ``half`` (degrees), and how many it sees (NaN, NaN, 0 for none)."""
    close, q_l, d_step, a_step = prm[0].visible_distance, prm[0].quantize_step_l, prm[0].distance_step, \
        prm[0].direction_step
    b = math.radians(body)
    bx, by, cos_half = math.cos(b), math.sin(b), math.cos(math.radians(half))
    close2, cos2 = _unseen_bounds(cos_half, close, prm)
    sx = 0.0
    sy = 0.0
    k = 0
    for f in range(flags.shape[0]):
        dx, dy = flags[f, 0] - px, flags[f, 1] - py
        if _surely_unseen(dx, dy, bx, by, close2, cos2):
            continue
        dist = math.hypot(dx, dy)
        if not (_in_cone(dx, dy, dist, bx, by, cos_half, prm) or dist <= close):
            continue
        rel = _wrap(math.degrees(math.atan2(dy, dx)) - body)
        x, y = _flag_fix(flags[f, 0], flags[f, 1], _reported_distance(dist, q_l, d_step),
                         body + _quantize(rel, a_step))
        sx += x
        sy += y
        k += 1
    if k == 0:
        return np.nan, np.nan, 0
    return sx / k, sy / k, k


@njit(cache=True, nogil=True)
def localise_into(pos: np.ndarray, body: np.ndarray, flags: np.ndarray, prm: np.ndarray,
                  estimate: np.ndarray, count: np.ndarray) -> None:  # pragma: no cover - compiled
    """Each player's position from the flags it sees (mean of ``f - d_f (cos, sin)(b + a_f)``)
    into ``estimate`` (NaN when none is seen) and the number of flags into ``count``."""
    for i in range(pos.shape[0]):
        estimate[i, 0], estimate[i, 1], count[i] = _localise_one(pos[i, 0], pos[i, 1], body[i], prm[0].half_angle,
                                                                 flags, prm)


@njit(cache=True, nogil=True)
def _see_one(ox: float, oy: float, body: float, half: float, objects: np.ndarray, me: int, visible: np.ndarray,
             u_team: np.ndarray, u_unum: np.ndarray, prm: np.ndarray,
             out: SightingRows) -> None:  # pragma: no cover - compiled
    """What one observer at ``(ox, oy)`` looking along ``body`` with a cone of half angle
    ``half`` (degrees) sees of ``objects`` (object 0 the ball; ``me`` its own object row or -1;
    ``visible[j]`` False for objects that cannot be seen), into its row ``out``; ``u_team``,
    ``u_unum``: its identity-drop draws; ``prm``: a :data:`SEE_PARAMS` record."""
    seen, distance, direction, identity, in_cone = out.seen, out.distance, out.direction, out.identity, out.in_cone
    close, q, d_step, a_step = prm[0].visible_distance, prm[0].quantize_step, prm[0].distance_step, \
        prm[0].direction_step
    b = math.radians(body)
    bx, by, cos_half = math.cos(b), math.sin(b), math.cos(math.radians(half))
    close2, cos2 = _unseen_bounds(cos_half, close, prm)
    for j in range(objects.shape[0]):
        dx, dy = objects[j, 0] - ox, objects[j, 1] - oy
        unseen = _surely_unseen(dx, dy, bx, by, close2, cos2)
        dist = 0.0 if unseen else math.hypot(dx, dy)
        cone = (not unseen) and _in_cone(dx, dy, dist, bx, by, cos_half, prm)
        near = (not unseen) and (not cone) and dist <= close
        if (not (cone or near)) or j == me or not visible[j]:
            seen[j] = False
            in_cone[j] = False
            distance[j] = np.nan
            direction[j] = np.nan
            identity[j] = UNSEEN
            continue
        d_rep = _reported_distance(dist, q, d_step)
        seen[j] = True
        in_cone[j] = cone
        distance[j] = d_rep
        direction[j] = _wrap(_quantize(_wrap(math.degrees(math.atan2(dy, dx)) - body), a_step))
        if j == 0:
            identity[j] = FULL
        elif near:
            identity[j] = ANONYMOUS
        elif u_team[j] < _drop_chance(d_rep, prm[0].team_far_length, prm[0].team_too_far_length):
            identity[j] = ANONYMOUS
        elif u_unum[j] < _drop_chance(d_rep, prm[0].unum_far_length, prm[0].unum_too_far_length):
            identity[j] = TEAM_ONLY
        else:
            identity[j] = FULL


@njit(cache=True, nogil=True)
def see_into(obs: np.ndarray, body: np.ndarray, objects: np.ndarray, self_index: np.ndarray,
             visible: np.ndarray, uniforms: np.ndarray, prm: np.ndarray,
             out: SightingRows) -> None:  # pragma: no cover - compiled
    """What each observer sees of ``objects`` (object 0 the ball, then players) into ``out``
    ((n, m) arrays, one row per observer). ``self_index[i]``: observer i's object row minus one
    (-1: none); ``visible[j]``: object j may be seen at all (players sent off are not);
    ``uniforms`` (2, n, m): the team-drop and number-drop draws; ``prm``: a :data:`SEE_PARAMS`
    record."""
    for i in range(obs.shape[0]):
        me = self_index[i] + 1 if self_index[i] >= 0 else -1
        _see_one(obs[i, 0], obs[i, 1], body[i], prm[0].half_angle, objects, me, visible, uniforms[0, i],
                 uniforms[1, i], prm,
                 SightingRows(out.seen[i], out.distance[i], out.direction[i], out.identity[i], out.in_cone[i]))


@njit(cache=True, nogil=True)
def perceive(truth: TrueBodies, seeing: np.ndarray, uniforms: np.ndarray, advance: bool, home_attacks: float,
             rows: ObserverRows, flags: np.ndarray, prm: np.ndarray, belief: np.ndarray,
             out: Perception) -> None:  # pragma: no cover - compiled
    """One cycle of every player's perception (:mod:`.observer`'s steps 1-3) in one call.

    ``belief`` (P, 2): each player's belief about its own position, absolute frame, updated in
    place (advanced by the sensed velocity over its decay when ``advance``, replaced by the flag
    estimate from ``flags`` (F, 2) m on cycles with a see; the true position with the record
    ``prm``'s ``exact_self``). ``seeing`` (P,): who gets a see; ``uniforms`` (2, k, P + 1): the
    identity draws of the k seeing players in row order. Each player looks along its face, the
    body direction plus ``truth.neck`` (the cone, the flags and the reported directions are the
    face's, as rcssserver's; the directions written are relative to the body: the face's plus
    the neck). Outputs (``out``) are in each player's
    team frame (``home_attacks`` for the first team's players, its negative for the other's: each
    team's attack direction): the body direction in degrees, the neck angle, the believed position
    and sensed velocity, the ball's polar coordinates and position, and the seen players nearest
    first (ties in row order) with position, side (+1 team-mate, -1 opponent, 0 unknown), number
    (-1 unknown) and row. Rows of players without a see are cleared (NaN, 0, -1)."""
    pos, vel, ball, present, necks = truth.pos, truth.vel, truth.ball, truth.present, truth.neck
    inertia, decay, team, first = rows.inertia, rows.decay, rows.team, rows.first
    exact_self = prm[0].exact_self
    body_out, neck_out, pos_out, vel_out, localised = out.body_direction, out.neck_angle, out.position, out.velocity, \
        out.localised
    ball_seen, ball_dist, ball_dir, ball_at = out.ball_seen, out.ball_distance, out.ball_direction, out.ball
    count, s_dist, s_dir, s_at = out.seen_count, out.seen_distance, out.seen_direction, out.seen_position
    s_side, s_num, s_obj = out.seen_side, out.seen_number, out.seen_rows
    n = pos.shape[0]
    m = n + 1
    objects = np.empty((m, 2))
    objects[0, 0], objects[0, 1] = ball[0], ball[1]
    visible = np.empty(m, dtype=np.bool_)
    visible[0] = True
    for p in range(n):
        objects[p + 1, 0], objects[p + 1, 1] = pos[p, 0], pos[p, 1]
        visible[p + 1] = present[p]
    seen = np.empty(m, dtype=np.bool_)
    distance = np.empty(m)
    direction = np.empty(m)
    identity = np.empty(m, dtype=np.int8)
    cone = np.empty(m, dtype=np.bool_)
    sighted = SightingRows(seen, distance, direction, identity, cone)
    order = np.empty(m, dtype=np.int64)
    d_step = prm[0].direction_step
    k = 0
    for p in range(n):
        fx, fy = facing(vel[p, 0], vel[p, 1], ball[0] - pos[p, 0], ball[1] - pos[p, 1], inertia[p])
        body = math.degrees(math.atan2(fy, fx))
        neck = necks[p]
        face = body + neck  # (exactly the body when the neck is 0)
        if exact_self:
            vx, vy = vel[p, 0], vel[p, 1]
            belief[p, 0], belief[p, 1] = pos[p, 0], pos[p, 1]
        else:
            vx, vy = _sensed(vel[p, 0], vel[p, 1], face, d_step)
            if advance:
                belief[p, 0] += vx / decay[p]
                belief[p, 1] += vy / decay[p]
        s = home_attacks if team[p] == 0 else -home_attacks
        body_out[p] = _wrap(body + (0.0 if s > 0 else 180.0))
        neck_out[p] = neck
        vel_out[p, 0], vel_out[p, 1] = vx * s, vy * s
        localised[p] = False
        ball_seen[p] = False
        ball_dist[p] = np.nan
        ball_dir[p] = np.nan
        ball_at[p, 0] = np.nan
        ball_at[p, 1] = np.nan
        count[p] = 0
        for c in range(s_dist.shape[1]):
            s_dist[p, c] = np.nan
            s_dir[p, c] = np.nan
            s_at[p, c, 0] = np.nan
            s_at[p, c, 1] = np.nan
            s_side[p, c] = 0
            s_num[p, c] = -1
            s_obj[p, c] = -1
        if seeing[p]:
            if exact_self:
                localised[p] = True
            else:
                x, y, flags_seen = _localise_one(pos[p, 0], pos[p, 1], face, truth.half_angle[p], flags, prm)
                if flags_seen > 0:
                    localised[p] = True
                    belief[p, 0], belief[p, 1] = x, y
            _see_one(pos[p, 0], pos[p, 1], face, truth.half_angle[p], objects, p + 1, visible, uniforms[0, k],
                     uniforms[1, k], prm, sighted)
            k += 1
            b = math.radians(face)
            if seen[0]:
                a = b + math.radians(direction[0])
                ball_seen[p] = True
                ball_dist[p] = distance[0]
                ball_dir[p] = direction[0] if neck == 0.0 else _wrap(direction[0] + neck)
                ball_at[p, 0] = (belief[p, 0] + distance[0] * math.cos(a)) * s
                ball_at[p, 1] = (belief[p, 1] + distance[0] * math.sin(a)) * s
            found = 0
            for j in range(1, m):  # insertion sort by reported distance, stable
                if not seen[j]:
                    continue
                at = found
                while at > 0 and distance[order[at - 1]] > distance[j]:
                    order[at] = order[at - 1]
                    at -= 1
                order[at] = j
                found += 1
            count[p] = found
            for c in range(found):
                j = order[c]
                q = j - 1  # player row
                a = b + math.radians(direction[j])
                s_dist[p, c] = distance[j]
                s_dir[p, c] = direction[j] if neck == 0.0 else _wrap(direction[j] + neck)
                s_at[p, c, 0] = (belief[p, 0] + distance[j] * math.cos(a)) * s
                s_at[p, c, 1] = (belief[p, 1] + distance[j] * math.sin(a)) * s
                if identity[j] >= TEAM_ONLY:
                    s_side[p, c] = 1 if team[q] == team[p] else -1
                if identity[j] == FULL:
                    s_num[p, c] = q - first[q]
                s_obj[p, c] = q
        pos_out[p, 0], pos_out[p, 1] = belief[p, 0] * s, belief[p, 1] * s


@njit(cache=True, nogil=True)
def senses_into(stamina: np.ndarray, effort: np.ndarray, capacity: np.ndarray, frozen: np.ndarray,
                present: np.ndarray, holder: int, stamina_out: np.ndarray, effort_out: np.ndarray,
                capacity_out: np.ndarray, frozen_out: np.ndarray, present_out: np.ndarray,
                holds_out: np.ndarray) -> None:  # pragma: no cover - compiled
    """The views' every-cycle senses (sense_body's stamina, effort, capacity and frozen cycles,
    who is on the pitch, who holds the ball: ``holder`` a player row or -1) copied in one call."""
    for p in range(stamina.shape[0]):
        stamina_out[p] = stamina[p]
        effort_out[p] = effort[p]
        capacity_out[p] = capacity[p]
        frozen_out[p] = frozen[p]
        present_out[p] = present[p]
        holds_out[p] = p == holder
