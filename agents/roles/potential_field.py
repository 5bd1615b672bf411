"""The potential field that places supporting players, after "Dynamic multi-robot
coordination" (Vail and Veloso): a sum of bounded, piecewise-linear terms, each encoding one
piece of soccer sense; a supporter moves down the field's gradient.

Every term takes ``points`` (k, 2) in the team frame (metres) and returns ``(potential (k,),
gradient (k, 2))``; potentials are dimensionless (a weight of 1 per metre means "as bad as a
metre away from the anchor"). All are vectorised over the players.

==================  ===========================================================================
term                potential (``w`` weight, ``r`` reach)
==================  ===========================================================================
walls               ``w * max(0, 1 - d / r)`` summed over the four lines, ``d`` the distance to
                    the line: a linear push away from the touchlines and goal lines
own area            ``w * min(1 - s / r, 2)`` for ``s < r``, ``s`` the signed distance to our
                    penalty area (negative inside): supporters keep out of the goalkeeper's area
teammates           ``w * max(0, 1 - |p - q| / r)`` summed over the other players ``q``
ball distance       ``w * | |p - b| - d_eq |``: an equilibrium distance from the ball ``b``
forward bias        ``w * max(0, b_x + o - p_x)``: offensive supporters level with or ahead of
                    the ball
defensive bias      ``w * max(0, p_x - (b_x - o))``: defensive supporters goal-side of the ball
corridor (clear)    ``w * max(0, 1 - c / r)``, ``c`` the distance to the segment from the ball to
                    the opponents' goal: offensive supporters leave the shooting lane open
corridor (block)    ``w * c'``, ``c'`` the distance to the segment from the ball to our goal:
                    defensive supporters stand in the way of a shot
side                ``w * max(0, -sign(a_y) p_y)`` for anchors ``a`` off the centre line: a
                    supporter stays on its side of the field
anchor              ``w * |p - a|``: the pull of the formation target
==================  ===========================================================================

Where a term is not differentiable (a kink) the gradient of either side is used; at a
point where a distance is zero the gradient of that distance is taken as zero.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

_EPS = 1e-9


@dataclass(frozen=True)
class FieldParams:
    """Weights (per metre, or per unit of a bounded term), reaches and distances (m)."""

    wall_weight: float = 3.0
    wall_reach: float = 3.0
    area_weight: float = 3.0
    area_reach: float = 2.0
    teammate_weight: float = 2.0
    teammate_reach: float = 5.0
    ball_weight: float = 0.4
    ball_distance: float = 12.0
    forward_weight: float = 0.5
    forward_offset: float = 3.0
    defensive_weight: float = 0.5
    defensive_offset: float = 5.0
    corridor_clear_weight: float = 3.0
    corridor_width: float = 4.0
    corridor_block_weight: float = 0.3
    side_weight: float = 0.3
    side_threshold: float = 5.0
    """Anchors within this distance of the centre line (|y|) have no side."""
    anchor_weight: float = 0.5
    lookahead: float = 3.0
    """Metres moved per unit of gradient when stepping down the field..."""
    max_step: float = 5.0
    """...but never more than this (m)."""


def _distance_gradient(delta: np.ndarray, dist: np.ndarray) -> np.ndarray:
    """Gradient of ``|delta|`` with respect to the point (``delta = point - other``)."""
    return np.divide(delta, dist[:, None], out=np.zeros_like(delta), where=dist[:, None] > _EPS)


def walls(points: np.ndarray, half_length: float, half_width: float, weight: float,
          reach: float) -> tuple[np.ndarray, np.ndarray]:
    """Linear repulsion from the four lines, within ``reach``."""
    pot = np.zeros(points.shape[0])
    grad = np.zeros_like(points)
    for axis, half in ((0, half_length), (1, half_width)):
        for sign in (1.0, -1.0):
            d = half - sign * points[:, axis]  # distance to the line on this side
            near = d < reach
            pot += np.where(near, weight * (1.0 - d / reach), 0.0)
            grad[:, axis] += np.where(near, sign * weight / reach, 0.0)
    return pot, grad


def own_area(points: np.ndarray, half_length: float, area_length: float, area_half_width: float, weight: float,
             reach: float) -> tuple[np.ndarray, np.ndarray]:
    """Linear repulsion from our penalty area (the box ``x <= -half_length + area_length``,
    ``|y| <= area_half_width``), growing inside it up to twice the weight."""
    x0, x1 = -half_length, -half_length + area_length
    cx = np.clip(points[:, 0], x0, x1)
    cy = np.clip(points[:, 1], -area_half_width, area_half_width)
    delta = points - np.column_stack((cx, cy))
    outside = np.hypot(delta[:, 0], delta[:, 1])
    grad_s = _distance_gradient(delta, outside)
    inside = outside == 0.0
    # Inside: the signed distance is minus the distance to the nearest side (front or flank).
    to_front = x1 - points[:, 0]
    to_flank = area_half_width - np.abs(points[:, 1])
    front = to_front <= to_flank
    signed = np.where(inside, -np.minimum(to_front, to_flank), outside)
    inside_grad = np.where(front[:, None], np.array([1.0, 0.0]),
                           np.column_stack((np.zeros_like(to_flank), np.sign(points[:, 1]))))
    grad_s = np.where(inside[:, None], inside_grad, grad_s)
    raw = 1.0 - signed / reach
    active = (signed < reach) & (raw < 2.0)
    pot = weight * np.clip(raw, 0.0, 2.0)
    grad = np.where(active[:, None], -weight / reach * grad_s, 0.0)
    return pot, grad


def teammates(points: np.ndarray, weight: float, reach: float) -> tuple[np.ndarray, np.ndarray]:
    """Linear repulsion between every pair of ``points`` within ``reach``."""
    delta = points[:, None, :] - points[None, :, :]
    dist = np.hypot(delta[..., 0], delta[..., 1])
    near = (dist < reach) & (dist > _EPS)
    pot = np.where(near, weight * (1.0 - dist / reach), 0.0).sum(axis=1)
    unit = np.divide(delta, dist[..., None], out=np.zeros_like(delta), where=near[..., None])
    grad = (-weight / reach * unit).sum(axis=1)
    return pot, grad


def ball_distance(points: np.ndarray, ball: np.ndarray, weight: float,
                  distance: float) -> tuple[np.ndarray, np.ndarray]:
    """Attraction to the circle of radius ``distance`` around the ball."""
    delta = points - ball
    dist = np.hypot(delta[:, 0], delta[:, 1])
    off = dist - distance
    return weight * np.abs(off), weight * np.sign(off)[:, None] * _distance_gradient(delta, dist)


def forward_bias(points: np.ndarray, ball: np.ndarray, weight: float, offset: float) -> tuple[np.ndarray, np.ndarray]:
    """Offensive supporters: cost of being behind ``ball_x + offset``."""
    behind = ball[0] + offset - points[:, 0]
    grad = np.zeros_like(points)
    grad[:, 0] = np.where(behind > 0.0, -weight, 0.0)
    return weight * np.maximum(behind, 0.0), grad


def defensive_bias(points: np.ndarray, ball: np.ndarray, weight: float, offset: float) -> tuple[np.ndarray, np.ndarray]:
    """Defensive supporters: cost of being ahead of ``ball_x - offset``."""
    ahead = points[:, 0] - (ball[0] - offset)
    grad = np.zeros_like(points)
    grad[:, 0] = np.where(ahead > 0.0, weight, 0.0)
    return weight * np.maximum(ahead, 0.0), grad


def _segment_offset(points: np.ndarray, start: np.ndarray, end: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``points`` minus their nearest points on the segment, and its length."""
    axis = end - start
    length2 = float(axis @ axis)
    t = np.zeros(points.shape[0]) if length2 < _EPS else np.clip((points - start) @ axis / length2, 0.0, 1.0)
    delta = points - (start + t[:, None] * axis)
    return delta, np.hypot(delta[:, 0], delta[:, 1])


def corridor_clear(points: np.ndarray, ball: np.ndarray, goal: np.ndarray, weight: float,
                   width: float) -> tuple[np.ndarray, np.ndarray]:
    """Offensive supporters: linear push out of the ball-to-goal corridor (half-width ``width``)."""
    delta, dist = _segment_offset(points, ball, goal)
    inside = dist < width
    pot = np.where(inside, weight * (1.0 - dist / width), 0.0)
    grad = np.where(inside[:, None], -weight / width * _distance_gradient(delta, dist), 0.0)
    return pot, grad


def corridor_block(points: np.ndarray, ball: np.ndarray, goal: np.ndarray,
                   weight: float) -> tuple[np.ndarray, np.ndarray]:
    """Defensive supporters: linear pull onto the ball-to-our-goal segment."""
    delta, dist = _segment_offset(points, ball, goal)
    return weight * dist, weight * _distance_gradient(delta, dist)


def side(points: np.ndarray, anchors: np.ndarray, weight: float, threshold: float) -> tuple[np.ndarray, np.ndarray]:
    """Cost of crossing to the other side of the field from one's anchor."""
    sided = np.where(np.abs(anchors[:, 1]) > threshold, np.sign(anchors[:, 1]), 0.0)
    wrong = -sided * points[:, 1]
    grad = np.zeros_like(points)
    grad[:, 1] = np.where(wrong > 0.0, -weight * sided, 0.0)
    return weight * np.maximum(wrong, 0.0), grad


def anchor(points: np.ndarray, anchors: np.ndarray, weight: float) -> tuple[np.ndarray, np.ndarray]:
    """Linear pull towards each point's anchor (its formation target)."""
    delta = points - anchors
    dist = np.hypot(delta[:, 0], delta[:, 1])
    return weight * dist, weight * _distance_gradient(delta, dist)


def supporter_field(points: np.ndarray, anchors: np.ndarray, offensive: np.ndarray, ball: np.ndarray,
                    own_goal: np.ndarray, opp_goal: np.ndarray, half_length: float, half_width: float,
                    area_length: float, area_half_width: float,
                    params: FieldParams = FieldParams()) -> tuple[np.ndarray, np.ndarray]:
    """The whole field for supporters at ``points`` with formation ``anchors``; ``offensive``
    (k,) bool selects the offensive supporters' terms, the others get the defensive ones.
    Returns (potential (k,), gradient (k, 2))."""
    p = params
    terms = [
        walls(points, half_length, half_width, p.wall_weight, p.wall_reach),
        own_area(points, half_length, area_length, area_half_width, p.area_weight, p.area_reach),
        teammates(points, p.teammate_weight, p.teammate_reach),
        side(points, anchors, p.side_weight, p.side_threshold),
        anchor(points, anchors, p.anchor_weight),
    ]
    pot = sum(t[0] for t in terms)
    grad = sum(t[1] for t in terms)
    attack = [
        ball_distance(points, ball, p.ball_weight, p.ball_distance),
        forward_bias(points, ball, p.forward_weight, p.forward_offset),
        corridor_clear(points, ball, opp_goal, p.corridor_clear_weight, p.corridor_width),
    ]
    defend = [
        defensive_bias(points, ball, p.defensive_weight, p.defensive_offset),
        corridor_block(points, ball, own_goal, p.corridor_block_weight),
    ]
    for part, mask in ((attack, offensive), (defend, ~offensive)):
        for t_pot, t_grad in part:
            pot = pot + np.where(mask, t_pot, 0.0)
            grad = grad + np.where(mask[:, None], t_grad, 0.0)
    return pot, grad


def descend(points: np.ndarray, gradient: np.ndarray, params: FieldParams = FieldParams()) -> np.ndarray:
    """One step down the field from each point: ``lookahead`` metres per unit of gradient,
    at most ``max_step`` metres."""
    size = np.hypot(gradient[:, 0], gradient[:, 1])
    step = np.minimum(size * params.lookahead, params.max_step)
    unit = np.divide(gradient, size[:, None], out=np.zeros_like(gradient), where=size[:, None] > _EPS)
    return points - unit * step[:, None]
