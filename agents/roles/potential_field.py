"""The potential field that places supporting players, after "Dynamic multi-robot
coordination" (Vail and Veloso): a sum of simple terms, each encoding one piece of soccer
sense, each zero or linear away from where it acts, so that its gradient is bounded by its
weight (per metre) and terms interact only where they overlap. A supporter moves down the
field's gradient (the paper samples nearby points for the slope; here it is analytic).

Every term takes ``points`` (k, 2) in the team frame (metres) and returns ``(potential (k,),
gradient (k, 2))``, the gradient with respect to each player's own position; potentials are
in "metres of anchor distance" (a weight of 1 per metre is as bad as standing a metre
farther from the formation target). All terms are numba-compiled, vectorised over the
players, and callable from Python. ``w`` is the term's weight, ``r`` its reach (m).

====================  ========================================================================
term                  potential
====================  ========================================================================
:func:`walls`         ``w * max(0, 1 - d / r)`` summed over the two touchlines and two goal
                      lines, ``d`` the (signed) distance to the line: a linear push inwards
:func:`own_area`      ``w * max(0, 1 - s / r)``, ``s`` the signed distance to our penalty area
                      (negative inside): supporters keep out of the goalkeeper's area, and
                      deep inside the push out stays on
:func:`teammates`     ``w * max(0, 1 - |p - q| / r)`` summed over the other players ``q``
:func:`ball_distance` ``w * huber(|p - b| - d_eq)``: an equilibrium distance from the ball ``b``
:func:`forward_bias`  ``w * max(0, b_x + o - p_x)``: offensive supporters at least ``o`` metres
                      ahead of the ball
:func:`defensive_bias` ``w * max(0, p_x - (b_x - o))``: defensive supporters at least ``o``
                      metres goal-side of the ball
:func:`corridor_clear` ``w * max(0, 1 - c / r)``, ``c`` the distance to the segment from the ball
                      to the opponents' goal: offensive supporters leave the shooting lane open
:func:`corridor_block` ``w * huber(c')``, ``c'`` the distance to the segment from the ball to our
                      goal: defensive supporters stand in the way of a shot
:func:`side`          ``w * max(0, -s p_y)`` for a side ``s`` in {-1, 0, +1}: a supporter stays
                      on its side of the field (see :func:`supporter_field` for the sides)
:func:`anchor`        ``w * huber(|p - a|)``: the pull of the formation target ``a``
====================  ========================================================================

``huber(e) = e² / (2 h)`` for ``|e| < h`` and ``|e| - h / 2`` beyond (``h`` the term's
"soft" radius): linear far away, but with a gradient that fades to zero at the attractor, so
a player settles there instead of stepping back and forth across it. Where a term has a
kink (a corner of the penalty area, the end of a ramp) the gradient of one side is used;
where a distance is zero its direction is taken as zero (players on the same spot are pushed
apart along y, the lower row towards +y).
"""

from __future__ import annotations

import math
from dataclasses import astuple, dataclass, fields

import numpy as np
from numba import njit

from agents.roles.errors import RoleError

_EPS = 1e-9


@dataclass(frozen=True)
class FieldParams:
    """Weights (per metre, or the height of a ramp term), reaches and distances (m) of the
    supporters' field, and how far one step goes. The defaults balance the terms so that a
    supporter settles within a few metres of its formation target."""

    wall_weight: float = 3.0
    """Height of the wall ramp at a line."""
    wall_reach: float = 3.0
    """Distance from a line (m) where the wall ramp starts."""
    area_weight: float = 3.0
    """Height of the penalty-area ramp at the area's edge."""
    area_reach: float = 2.0
    """Distance outside our penalty area (m) where its ramp starts."""
    teammate_weight: float = 2.0
    """Height of the ramp between two team-mates on the same spot."""
    teammate_reach: float = 5.0
    """Team-mates farther apart than this (m) do not repel."""
    ball_weight: float = 0.4
    """Per metre off the equilibrium circle around the ball (offensive supporters)."""
    ball_distance: float = 12.0
    """Radius of the equilibrium circle around the ball (m)."""
    ball_soft: float = 2.0
    """Soft radius of the ball term's huber (m)."""
    forward_weight: float = 0.5
    """Per metre an offensive supporter is short of ``ball_x + forward_offset``."""
    forward_offset: float = 3.0
    """How far ahead of the ball (m) offensive supporters should be."""
    defensive_weight: float = 0.5
    """Per metre a defensive supporter is beyond ``ball_x - defensive_offset``."""
    defensive_offset: float = 5.0
    """How far goal-side of the ball (m) defensive supporters should be."""
    corridor_clear_weight: float = 3.0
    """Height of the ramp on the ball-to-their-goal segment (offensive supporters, attacking)."""
    corridor_width: float = 4.0
    """Half-width (m) of the shooting corridor kept clear."""
    corridor_block_weight: float = 0.3
    """Per metre a defensive supporter is off the ball-to-our-goal segment (defending)."""
    corridor_block_soft: float = 1.0
    """Soft radius of the blocking term's huber (m)."""
    side_weight: float = 0.3
    """Per metre a supporter is on the wrong side of the field's long axis."""
    side_threshold: float = 5.0
    """Anchors (and balls) within this distance (m) of the long axis have no side."""
    anchor_weight: float = 0.5
    """Per metre from the formation target."""
    anchor_soft: float = 2.0
    """Soft radius of the anchor term's huber (m)."""
    lookahead: float = 3.0
    """Metres moved per unit of gradient when stepping down the field..."""
    max_step: float = 5.0
    """...but never more than this (m)."""
    field_margin: float = 1.0
    """A steered point stays this far (m) inside the touchlines and goal lines."""

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0:
                raise RoleError(f"FieldParams.{f.name} must be a finite number >= 0, got {value!r}")
        for name in ("wall_reach", "area_reach", "teammate_reach", "corridor_width"):
            if getattr(self, name) <= 0:
                raise RoleError(f"FieldParams.{name} must be > 0 (it divides the ramp), got {getattr(self, name)!r}")

    def as_array(self) -> np.ndarray:
        """The parameters as a float64 array in field order (what the compiled kernels read)."""
        return np.array(astuple(self), dtype=np.float64)


_INDEX = {f.name: i for i, f in enumerate(fields(FieldParams))}
# Positions in FieldParams.as_array() (compile-time constants for the kernels).
_WALL_W, _WALL_R = _INDEX["wall_weight"], _INDEX["wall_reach"]
_AREA_W, _AREA_R = _INDEX["area_weight"], _INDEX["area_reach"]
_MATE_W, _MATE_R = _INDEX["teammate_weight"], _INDEX["teammate_reach"]
_BALL_W, _BALL_D, _BALL_H = _INDEX["ball_weight"], _INDEX["ball_distance"], _INDEX["ball_soft"]
_FWD_W, _FWD_O = _INDEX["forward_weight"], _INDEX["forward_offset"]
_DEF_W, _DEF_O = _INDEX["defensive_weight"], _INDEX["defensive_offset"]
_CLEAR_W, _CLEAR_R = _INDEX["corridor_clear_weight"], _INDEX["corridor_width"]
_BLOCK_W, _BLOCK_H = _INDEX["corridor_block_weight"], _INDEX["corridor_block_soft"]
_SIDE_W, _SIDE_T = _INDEX["side_weight"], _INDEX["side_threshold"]
_ANCHOR_W, _ANCHOR_H = _INDEX["anchor_weight"], _INDEX["anchor_soft"]
_LOOKAHEAD, _MAX_STEP, _MARGIN = _INDEX["lookahead"], _INDEX["max_step"], _INDEX["field_margin"]


@njit(cache=True, nogil=True, inline="always")
def _huber(e: float, soft: float) -> tuple[float, float]:  # pragma: no cover - compiled
    """``huber(e)`` (see the module docstring) and its derivative; ``soft = 0``: ``|e|``."""
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
    if d > _EPS:
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
                if d > _EPS:
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
    if length2 > _EPS:
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
            if c > _EPS:
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
    ``params`` is :meth:`FieldParams.as_array`. Returns (potential (k,), gradient (k, 2)).

    Every supporter: walls, own area, team-mates (all ``points`` repel each other), side and
    anchor. An **offensive** supporter (``offensive[i]``) adds the ball's equilibrium distance
    and the forward bias, and when ``attacking`` the push out of the shooting corridor; a
    **defensive** one adds the defensive bias, and when not ``attacking`` the pull onto the
    ball-to-our-goal line.
    """
    pot, grad = walls(points, half_length, half_width, params[_WALL_W], params[_WALL_R])
    terms = (
        own_area(points, half_length, area_length, area_half_width, params[_AREA_W], params[_AREA_R]),
        teammates(points, params[_MATE_W], params[_MATE_R]),
        side(points, supporter_sides(anchors, offensive, ball, params[_SIDE_T]), params[_SIDE_W]),
        anchor(points, anchors, params[_ANCHOR_W], params[_ANCHOR_H]),
    )
    for t_pot, t_grad in terms:
        pot += t_pot
        grad += t_grad
    a_pot, a_grad = ball_distance(points, ball, params[_BALL_W], params[_BALL_D], params[_BALL_H])
    attack = (
        forward_bias(points, ball, params[_FWD_W], params[_FWD_O]),
        corridor_clear(points, ball, opp_goal, params[_CLEAR_W] if attacking else 0.0, params[_CLEAR_R]),
    )
    for t_pot, t_grad in attack:
        a_pot += t_pot
        a_grad += t_grad
    d_pot, d_grad = defensive_bias(points, ball, params[_DEF_W], params[_DEF_O])
    b_pot, b_grad = corridor_block(points, ball, own_goal, 0.0 if attacking else params[_BLOCK_W], params[_BLOCK_H])
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
    the field. ``params`` is :meth:`FieldParams.as_array`."""
    k = points.shape[0]
    out = np.empty((k, 2))
    lookahead, max_step, margin = params[_LOOKAHEAD], params[_MAX_STEP], params[_MARGIN]
    x_lim, y_lim = max(half_length - margin, 0.0), max(half_width - margin, 0.0)
    for i in range(k):
        gx, gy = gradient[i, 0], gradient[i, 1]
        size = math.hypot(gx, gy)
        x, y = points[i, 0], points[i, 1]
        if size > _EPS:
            step = min(size * lookahead, max_step) / size
            x -= gx * step
            y -= gy * step
        out[i, 0] = min(max(x, -x_lim), x_lim)
        out[i, 1] = min(max(y, -y_lim), y_lim)
    return out
