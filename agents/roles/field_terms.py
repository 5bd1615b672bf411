"""The supporters' potential field as compiled kernels callable from Python: its terms, the
whole field (:func:`supporter_field`, with each supporter's side, :func:`supporter_sides`) and
one step down it (:func:`descend`); the table and conventions are in
:mod:`agents.roles.potential_field`, the caller is :class:`agents.roles.bidding.BiddingAssigner`.

Every term takes ``points`` (k, 2) in the team frame (metres) and returns ``(potential (k,),
gradient (k, 2))``, the gradient with respect to each player's own position. ``weight`` is the
term's weight, ``reach`` its reach (m), ``soft`` a huber's soft radius (m).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

EPS = 1e-9
"""Distances below this (m) have no direction."""


@njit(cache=True, nogil=True, inline="always")
def _huber(e: float, soft: float) -> tuple[float, float]:  # pragma: no cover - compiled
    """``huber(e)`` (see :mod:`agents.roles.potential_field`) and its derivative; ``soft = 0``: ``|e|``."""
    a = abs(e)
    if a < soft:
        return e * e / (2.0 * soft), e / soft
    return a - 0.5 * soft, (1.0 if e > 0.0 else (-1.0 if e < 0.0 else 0.0))


@njit(cache=True, nogil=True, inline="always")
def _radial_huber(pot: np.ndarray, grad: np.ndarray, i: int, dx: float, dy: float, d: float, excess: float,
                  weight: float, soft: float) -> None:  # pragma: no cover - compiled
    """Row ``i`` of a term ``weight * huber(excess, soft)`` where ``excess`` grows one for one
    with the distance ``d`` along the offset ``(dx, dy)`` (no direction when ``d`` is zero)."""
    value, slope = _huber(excess, soft)
    pot[i] = weight * value
    if d > EPS:
        grad[i, 0] = weight * slope * dx / d
        grad[i, 1] = weight * slope * dy / d


@njit(cache=True, nogil=True)
def walls(points: np.ndarray, half_length: float, half_width: float, weight: float,
          reach: float) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover - compiled
    """Linear push inwards from the four lines (x = +-half_length, y = +-half_width), starting
    ``reach`` metres inside: potential ``weight * max(0, 1 - d / reach)`` per line, ``d`` the
    signed distance to it (negative outside the field), gradient ``weight / reach`` outwards
    per line in range."""
    k = points.shape[0]
    pot = np.zeros(k)
    grad = np.zeros((k, 2))
    slope = weight / reach
    for i in range(k):
        for axis in range(2):
            half = half_length if axis == 0 else half_width
            for sign in (1.0, -1.0):
                d = half - sign * points[i, axis]
                if d < reach:
                    pot[i] += weight * (1.0 - d / reach)
                    grad[i, axis] += sign * slope
    return pot, grad


@njit(cache=True, nogil=True)
def own_area(points: np.ndarray, half_length: float, area_length: float, area_half_width: float, weight: float,
             reach: float) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover - compiled
    """Linear push out of our penalty area (``x <= -half_length + area_length``,
    ``|y| <= area_half_width``): potential ``weight * max(0, 1 - s / reach)``, ``s`` the signed
    distance to the area (negative inside: minus the distance to the nearer of the front line
    and the flank), gradient ``weight / reach`` towards the area's nearest point (outside) or
    inwards through the nearer exit (inside)."""
    k = points.shape[0]
    pot = np.zeros(k)
    grad = np.zeros((k, 2))
    x0, x1 = -half_length, -half_length + area_length
    slope = weight / reach
    for i in range(k):
        px, py = points[i, 0], points[i, 1]
        cx = min(max(px, x0), x1)
        cy = min(max(py, -area_half_width), area_half_width)
        dx, dy = px - cx, py - cy
        out = math.hypot(dx, dy)
        if out > 0.0:
            s, gx, gy = out, dx / out, dy / out  # gradient of s: away from the area
        else:
            to_front, to_flank = x1 - px, area_half_width - abs(py)
            if to_front <= to_flank:
                s, gx, gy = -to_front, 1.0, 0.0
            else:
                s, gx, gy = -to_flank, 0.0, (1.0 if py >= 0.0 else -1.0)
        if s < reach:
            pot[i] = weight * (1.0 - s / reach)
            grad[i, 0] = -slope * gx
            grad[i, 1] = -slope * gy
    return pot, grad


@njit(cache=True, nogil=True)
def teammates(points: np.ndarray, weight: float, reach: float) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover
    """Linear repulsion between every pair of ``points`` closer than ``reach``: potential of
    player i ``sum_j weight * max(0, 1 - |p_i - p_j| / reach)``, gradient ``weight / reach``
    towards each near team-mate (players on the same spot: along y, the lower row to +y)."""
    k = points.shape[0]
    pot = np.zeros(k)
    grad = np.zeros((k, 2))
    slope = weight / reach
    for i in range(k):
        for j in range(i + 1, k):
            dx, dy = points[i, 0] - points[j, 0], points[i, 1] - points[j, 1]
            d = math.hypot(dx, dy)
            if d < reach:
                if d > EPS:
                    ux, uy = dx / d, dy / d
                else:
                    ux, uy = 0.0, 1.0
                value = weight * (1.0 - d / reach)
                pot[i] += value
                pot[j] += value
                grad[i, 0] -= slope * ux
                grad[i, 1] -= slope * uy
                grad[j, 0] += slope * ux
                grad[j, 1] += slope * uy
    return pot, grad


@njit(cache=True, nogil=True)
def ball_distance(points: np.ndarray, ball: np.ndarray, weight: float, distance: float,
                  soft: float) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover - compiled
    """Attraction to the circle of radius ``distance`` around ``ball``: potential
    ``weight * huber(|p - b| - distance, soft)``, gradient at most ``weight`` along the radius."""
    k = points.shape[0]
    pot = np.zeros(k)
    grad = np.zeros((k, 2))
    for i in range(k):
        dx, dy = points[i, 0] - ball[0], points[i, 1] - ball[1]
        d = math.hypot(dx, dy)
        _radial_huber(pot, grad, i, dx, dy, d, d - distance, weight, soft)
    return pot, grad


@njit(cache=True, nogil=True)
def forward_bias(points: np.ndarray, ball: np.ndarray, weight: float,
                 offset: float) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover - compiled
    """Offensive supporters: potential ``weight * max(0, ball_x + offset - p_x)`` (being behind
    the line ``offset`` metres ahead of the ball), gradient ``(-weight, 0)`` behind it."""
    k = points.shape[0]
    pot = np.zeros(k)
    grad = np.zeros((k, 2))
    for i in range(k):
        behind = ball[0] + offset - points[i, 0]
        if behind > 0.0:
            pot[i] = weight * behind
            grad[i, 0] = -weight
    return pot, grad


@njit(cache=True, nogil=True)
def defensive_bias(points: np.ndarray, ball: np.ndarray, weight: float,
                   offset: float) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover - compiled
    """Defensive supporters: potential ``weight * max(0, p_x - (ball_x - offset))`` (being
    beyond the line ``offset`` metres goal-side of the ball), gradient ``(weight, 0)`` beyond it."""
    k = points.shape[0]
    pot = np.zeros(k)
    grad = np.zeros((k, 2))
    for i in range(k):
        ahead = points[i, 0] - (ball[0] - offset)
        if ahead > 0.0:
            pot[i] = weight * ahead
            grad[i, 0] = weight
    return pot, grad


@njit(cache=True, nogil=True, inline="always")
def _segment_offset(px: float, py: float, start: np.ndarray, end: np.ndarray) -> tuple[float, float, float]:
    """The point minus its nearest point on the segment ``start``-``end``, and its length."""
    ax, ay = end[0] - start[0], end[1] - start[1]
    length2 = ax * ax + ay * ay
    t = 0.0
    if length2 > EPS:
        t = min(max(((px - start[0]) * ax + (py - start[1]) * ay) / length2, 0.0), 1.0)
    dx, dy = px - (start[0] + t * ax), py - (start[1] + t * ay)
    return dx, dy, math.hypot(dx, dy)


@njit(cache=True, nogil=True)
def corridor_clear(points: np.ndarray, ball: np.ndarray, goal: np.ndarray, weight: float,
                   width: float) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover - compiled
    """Offensive supporters: linear push out of the corridor of half-width ``width`` around the
    segment from ``ball`` to ``goal`` (the opponents'): potential ``weight * max(0, 1 - c /
    width)``, gradient ``weight / width`` towards the segment inside the corridor."""
    k = points.shape[0]
    pot = np.zeros(k)
    grad = np.zeros((k, 2))
    slope = weight / width
    for i in range(k):
        dx, dy, c = _segment_offset(points[i, 0], points[i, 1], ball, goal)
        if c < width:
            pot[i] = weight * (1.0 - c / width)
            if c > EPS:
                grad[i, 0] = -slope * dx / c
                grad[i, 1] = -slope * dy / c
    return pot, grad


@njit(cache=True, nogil=True)
def corridor_block(points: np.ndarray, ball: np.ndarray, goal: np.ndarray, weight: float,
                   soft: float) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover - compiled
    """Defensive supporters: pull onto the segment from ``ball`` to ``goal`` (ours): potential
    ``weight * huber(c, soft)``, ``c`` the distance to the segment, gradient at most ``weight``
    away from it."""
    k = points.shape[0]
    pot = np.zeros(k)
    grad = np.zeros((k, 2))
    for i in range(k):
        dx, dy, c = _segment_offset(points[i, 0], points[i, 1], ball, goal)
        _radial_huber(pot, grad, i, dx, dy, c, c, weight, soft)
    return pot, grad


@njit(cache=True, nogil=True)
def side(points: np.ndarray, sides: np.ndarray, weight: float) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover
    """Potential ``weight * max(0, -s_i * p_y)`` for player i of side ``s_i = sides[i]`` (+1: the
    +y half, -1: the -y half, 0: none): gradient ``(0, -weight * s_i)`` on the wrong side."""
    k = points.shape[0]
    pot = np.zeros(k)
    grad = np.zeros((k, 2))
    for i in range(k):
        wrong = -sides[i] * points[i, 1]
        if wrong > 0.0:
            pot[i] = weight * wrong
            grad[i, 1] = -weight * sides[i]
    return pot, grad


@njit(cache=True, nogil=True)
def anchor(points: np.ndarray, anchors: np.ndarray, weight: float,
           soft: float) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover - compiled
    """Pull of each player's anchor (its formation target): potential ``weight * huber(|p - a|,
    soft)``, gradient at most ``weight`` away from the anchor."""
    k = points.shape[0]
    pot = np.zeros(k)
    grad = np.zeros((k, 2))
    for i in range(k):
        dx, dy = points[i, 0] - anchors[i, 0], points[i, 1] - anchors[i, 1]
        d = math.hypot(dx, dy)
        _radial_huber(pot, grad, i, dx, dy, d, d, weight, soft)
    return pot, grad


@njit(cache=True, nogil=True)
def supporter_sides(anchors: np.ndarray, offensive: np.ndarray, ball: np.ndarray,
                    threshold: float) -> np.ndarray:  # pragma: no cover - compiled
    """The side (+1, -1 or 0) each supporter keeps to: its anchor's side when the anchor is more
    than ``threshold`` off the long axis; otherwise, for an offensive supporter, the side
    opposite the ball when the ball is that far off the axis (the paper's offensive supporter
    takes the other side of the field from the primary attacker); else none."""
    k = anchors.shape[0]
    sides = np.zeros(k)
    away = 0.0
    if ball[1] > threshold:
        away = -1.0
    elif ball[1] < -threshold:
        away = 1.0
    for i in range(k):
        y = anchors[i, 1]
        if y > threshold:
            sides[i] = 1.0
        elif y < -threshold:
            sides[i] = -1.0
        elif offensive[i]:
            sides[i] = away
    return sides


@njit(cache=True, nogil=True)
def supporter_field(points: np.ndarray, anchors: np.ndarray, offensive: np.ndarray, attacking: bool,
                    ball: np.ndarray, own_goal: np.ndarray, opp_goal: np.ndarray, half_length: float,
                    half_width: float, area_length: float, area_half_width: float,
                    params: np.ndarray) -> tuple[np.ndarray, np.ndarray]:  # pragma: no cover - compiled
    """The whole field at ``points`` (k, 2) for supporters with formation ``anchors`` (k, 2);
    ``params`` is :meth:`FieldParams.as_record`. Returns (potential (k,), gradient (k, 2)).

    Every supporter: walls, own area, team-mates (all ``points`` repel each other), side and
    anchor. An **offensive** supporter (``offensive[i]``) adds the ball's equilibrium distance
    and the forward bias, and when ``attacking`` the push out of the shooting corridor; a
    **defensive** one adds the defensive bias, and when not ``attacking`` the pull onto the
    ball-to-our-goal line.
    """
    p = params[0]
    pot, grad = walls(points, half_length, half_width, p.wall_weight, p.wall_reach)
    terms = (
        own_area(points, half_length, area_length, area_half_width, p.area_weight, p.area_reach),
        teammates(points, p.teammate_weight, p.teammate_reach),
        side(points, supporter_sides(anchors, offensive, ball, p.side_threshold), p.side_weight),
        anchor(points, anchors, p.anchor_weight, p.anchor_soft),
    )
    for t_pot, t_grad in terms:
        pot += t_pot
        grad += t_grad
    a_pot, a_grad = ball_distance(points, ball, p.ball_weight, p.ball_distance, p.ball_soft)
    attack = (
        forward_bias(points, ball, p.forward_weight, p.forward_offset),
        corridor_clear(points, ball, opp_goal, p.corridor_clear_weight if attacking else 0.0, p.corridor_width),
    )
    for t_pot, t_grad in attack:
        a_pot += t_pot
        a_grad += t_grad
    d_pot, d_grad = defensive_bias(points, ball, p.defensive_weight, p.defensive_offset)
    b_pot, b_grad = corridor_block(points, ball, own_goal, 0.0 if attacking else p.corridor_block_weight,
                                   p.corridor_block_soft)
    d_pot += b_pot
    d_grad += b_grad
    for i in range(points.shape[0]):
        if offensive[i]:
            pot[i] += a_pot[i]
            grad[i, 0] += a_grad[i, 0]
            grad[i, 1] += a_grad[i, 1]
        else:
            pot[i] += d_pot[i]
            grad[i, 0] += d_grad[i, 0]
            grad[i, 1] += d_grad[i, 1]
    return pot, grad


@njit(cache=True, nogil=True)
def descend(points: np.ndarray, gradient: np.ndarray, half_length: float, half_width: float,
            params: np.ndarray) -> np.ndarray:  # pragma: no cover - compiled
    """One step down the field from each point: ``lookahead`` metres per unit of gradient
    along the descent direction, at most ``max_step`` metres, then kept ``field_margin`` inside
    the field. ``params`` is :meth:`FieldParams.as_record`."""
    k = points.shape[0]
    out = np.empty((k, 2))
    p = params[0]
    lookahead, max_step, margin = p.lookahead, p.max_step, p.field_margin
    x_lim, y_lim = max(half_length - margin, 0.0), max(half_width - margin, 0.0)
    for i in range(k):
        gx, gy = gradient[i, 0], gradient[i, 1]
        size = math.hypot(gx, gy)
        x, y = points[i, 0], points[i, 1]
        if size > EPS:
            step = min(size * lookahead, max_step) / size
            x -= gx * step
            y -= gy * step
        out[i, 0] = min(max(x, -x_lim), x_lim)
        out[i, 1] = min(max(y, -y_lim), y_lim)
    return out
