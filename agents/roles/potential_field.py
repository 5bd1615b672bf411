"""The potential field that places supporting players, after "Dynamic multi-robot
coordination" (Vail and Veloso): a sum of simple terms, each encoding one piece of soccer
sense, each zero or linear away from where it acts, so that its gradient is bounded by its
weight (per metre) and terms interact only where they overlap. A supporter moves down the
field's gradient (the paper samples nearby points for the slope; here it is analytic).

Every term takes ``points`` (k, 2) in the team frame (metres) and returns ``(potential (k,),
gradient (k, 2))``, the gradient with respect to each player's own position; potentials are
in "metres of anchor distance" (a weight of 1 per metre is as bad as standing a metre
farther from the formation target). All terms are numba-compiled, vectorised over the
players, and callable from Python (:mod:`agents.roles.field_terms`; their weights, reaches and
distances are :class:`~agents.roles.field_params.FieldParams`). ``w`` is the term's weight,
``r`` its reach (m).

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

import numpy as np
from numba import njit

from agents.roles.field_params import FIELD_DTYPE, FieldParams
from agents.roles.field_terms import (
    EPS,
    anchor,
    ball_distance,
    corridor_block,
    corridor_clear,
    defensive_bias,
    forward_bias,
    own_area,
    side,
    teammates,
    walls,
)

__all__ = [
    "FIELD_DTYPE", "FieldParams", "anchor", "ball_distance", "corridor_block", "corridor_clear", "defensive_bias",
    "descend", "forward_bias", "own_area", "side", "supporter_field", "supporter_sides", "teammates", "walls",
]


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
