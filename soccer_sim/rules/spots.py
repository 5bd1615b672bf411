"""Field geometry the referee needs to restart play: where the ball is placed and how
players are moved out of the way.

Everything here works in the absolute frame (origin at the centre spot, metres) and
mutates the arrays it is given in place. ``direction`` is a team's attack direction
(+1 towards +x, -1 towards -x), so ``direction * x <= 0`` is that team's own half.

Placement decisions (the rules text leaves them open):

* a kick-in is taken on the touchline where the ball's centre crossed it (linear
  interpolation between the ball's positions at the start and end of the cycle);
* a corner kick is taken on the corner point on the side where the ball left;
* a goal kick is taken on the corner of the goal area on the side where the ball left;
* a free kick for a goalkeeper holding the ball too long is taken on the point of the
  penalty-area edge (front line or side line, never the goal line) nearest the ball.
"""

from __future__ import annotations

import math

import numpy as np

from soccer_sim.config import FieldConfig


def line_crossing(x0: float, y0: float, x1: float, y1: float,
                  line_x: float, line_y: float) -> tuple[str, float, float]:
    """Which boundary the ball crossed first when moving from (x0, y0) to (x1, y1), and where.

    ``line_x`` / ``line_y`` are the (positive) distances from the centre at which the ball
    counts as out over a goal line / touchline. Returns ``("goal_line" | "touchline", x, y)``
    with the point where the ball's centre crossed that line. When the start point is
    unknown (NaN) or already out, the end point clamped onto the line is used.
    """
    t_goal = math.inf
    t_touch = math.inf
    if abs(x1) > line_x:
        t_goal = _crossing_fraction(x0, x1, line_x)
    if abs(y1) > line_y:
        t_touch = _crossing_fraction(y0, y1, line_y)
    if t_goal <= t_touch:
        t = t_goal
        y = y0 + t * (y1 - y0) if t < 1.0 else y1
        return "goal_line", math.copysign(line_x, x1), y
    t = t_touch
    x = x0 + t * (x1 - x0) if t < 1.0 else x1
    return "touchline", x, math.copysign(line_y, y1)


def _crossing_fraction(a0: float, a1: float, limit: float) -> float:
    """Fraction of the segment a0 -> a1 at which |a| first exceeds ``limit`` (1.0 if unknown)."""
    if not math.isfinite(a0) or abs(a0) > limit or a1 == a0:
        return 1.0
    bound = math.copysign(limit, a1)
    t = (bound - a0) / (a1 - a0)
    return min(max(t, 0.0), 1.0)


def corner_spot(field: FieldConfig, goal_side: float, y: float, inset: float = 0.0) -> tuple[float, float]:
    """Corner kick spot at the goal line ``goal_side`` (+1: x > 0), in the corner nearer to
    ``y``, ``inset`` metres inside the field along both lines."""
    return goal_side * (field.half_length - inset), math.copysign(field.half_width - inset, y)


def out_of_goal_area(field: FieldConfig, direction: int, x: float, y: float) -> tuple[float, float]:
    """(x, y), or, if it lies inside the goal area defended by the team attacking
    ``direction``, the point on the goal area's front line level with it (where an indirect
    free kick inside the goal area is taken)."""
    front = field.half_length - field.goal_area_length
    if -direction * x > front and abs(y) < field.goal_area_width / 2.0:
        return -direction * front, y
    return x, y


def push_out_of_penalty_area(block: np.ndarray, direction: int, field: FieldConfig) -> np.ndarray | None:
    """Move the players of ``block`` ((k, 2) rows) standing inside the penalty area defended
    by the team attacking ``direction`` onto its nearest front or side line (just outside).
    Returns the bool mask of moved rows, or None if nobody was moved."""
    depth = -direction * block[:, 0]  # distance towards that goal line from the halfway line
    front = field.half_length - field.penalty_area_length
    half_w = field.penalty_area_width / 2.0
    inside = (depth > front) & (np.abs(block[:, 1]) < half_w)
    if not np.count_nonzero(inside):
        return None
    to_front = depth - front
    to_side = half_w - np.abs(block[:, 1])
    via_front = inside & (to_front <= to_side)
    via_side = inside & ~via_front
    block[via_front, 0] = -direction * front
    block[via_side, 1] = np.copysign(half_w, block[via_side, 1])
    return inside


def goal_kick_spot(field: FieldConfig, goal_side: float, y: float) -> tuple[float, float]:
    """Corner of the goal area in front of goal ``goal_side`` (+1: x > 0), on the side of ``y``."""
    return (goal_side * (field.half_length - field.goal_area_length),
            math.copysign(field.goal_area_width / 2.0, y))


def in_penalty_area(field: FieldConfig, direction: int, x: float, y: float) -> bool:
    """Whether (x, y) lies inside the penalty area the team attacking ``direction`` defends."""
    depth = direction * x + field.half_length  # distance in front of the own goal line
    return 0.0 <= depth <= field.penalty_area_length and abs(y) <= field.penalty_area_width / 2.0


def out_of_penalty_area(field: FieldConfig, direction: int, x: float, y: float) -> tuple[float, float]:
    """(x, y), or, if it lies inside the penalty area defended by the team attacking
    ``direction``, that area's front corner on the side of ``y`` (rcssserver's
    ``moveOutOfPenalty``: where a ball dropped or a free kick given out of the area is put)."""
    if in_penalty_area(field, direction, x, y):
        front = field.half_length - field.penalty_area_length
        return -direction * front, math.copysign(field.penalty_area_width / 2.0, y if y > 0.0 else -1.0)
    return x, y


def clamp_into_penalty_area(field: FieldConfig, direction: int, x: float, y: float) -> tuple[float, float]:
    """The nearest point to (x, y) inside the penalty area defended by the team attacking ``direction``."""
    depth = min(max(direction * x + field.half_length, 0.0), field.penalty_area_length)
    half_w = field.penalty_area_width / 2.0
    return direction * (depth - field.half_length), min(max(y, -half_w), half_w)


def penalty_area_edge_spot(field: FieldConfig, direction: int, x: float, y: float) -> tuple[float, float]:
    """Point of the penalty area's front or side line nearest to (x, y), a point inside that
    area (defended by the team attacking ``direction``)."""
    x, y = clamp_into_penalty_area(field, direction, x, y)
    front_x = direction * (field.penalty_area_length - field.half_length)
    half_w = field.penalty_area_width / 2.0
    if abs(x - front_x) <= half_w - abs(y):
        return front_x, y
    return x, math.copysign(half_w, y)


def mirror_into_own_half(pos: np.ndarray, direction: int | np.ndarray) -> np.ndarray:
    """Reflect the players of ``pos`` ((k, 2) rows) standing in the opponents' half across the
    halfway line. ``direction``: the attack direction, one for all rows or one per row.
    Returns the bool mask of moved rows."""
    depth = pos[:, 0] * direction
    wrong = depth > 0.0
    if wrong.any():
        pos[:, 0] = -np.abs(depth) * direction
    return wrong


def keep_in_own_half(pos: np.ndarray, direction: int | np.ndarray) -> np.ndarray | None:
    """Move the players of ``pos`` ((k, 2) rows) standing in the opponents' half onto the
    halfway line. ``direction``: the attack direction, one for all rows or one per row.
    Returns the bool mask of moved rows, or None if nobody was moved (the common case)."""
    depth = pos[:, 0] * direction
    if not depth.size or depth.max() <= 0.0:
        return None
    pos[:, 0] = np.minimum(depth, 0.0) * direction
    return depth > 0.0


def clamp_into_own_half(block: np.ndarray, direction: int, field: FieldConfig) -> np.ndarray:
    """Clamp the players of ``block`` ((k, 2) rows of one team) into their own half of the
    field (lines included). Returns the bool mask of moved rows."""
    depth = direction * block[:, 0]
    new_depth = np.clip(depth, -field.half_length, 0.0)
    y = block[:, 1]
    new_y = np.clip(y, -field.half_width, field.half_width)
    moved = (new_depth != depth) | (new_y != y)
    block[:, 0] = direction * new_depth
    block[:, 1] = new_y
    return moved


def push_out_of_circle(block: np.ndarray, cx: float, cy: float, radius: float,
                       fallback: tuple[float, float]) -> np.ndarray | None:
    """Move the players of ``block`` ((k, 2) rows) closer than ``radius`` to (cx, cy) radially
    out onto the circle; players elsewhere are left bit-for-bit unchanged. A player exactly on
    the centre goes along the unit vector ``fallback``. Returns the bool mask of moved rows,
    or None if nobody was moved (the common case)."""
    centre = np.array((cx, cy))
    diff = block - centre
    d2 = (diff * diff).sum(axis=1)
    inside = d2 < radius * radius
    if not np.count_nonzero(inside):  # (cheaper than inside.any() on small arrays)
        return None
    d = np.sqrt(d2, out=d2)
    if not d.all():  # somebody stands exactly on the centre
        centred = d == 0.0
        diff[centred] = fallback
        d[centred] = 1.0
    np.divide(radius, d, out=d)
    diff *= d[:, None]
    diff += centre
    np.copyto(block, diff, where=inside[:, None])
    return inside


def push_clear_of_spot(block: np.ndarray, cx: float, cy: float, clearance: float,
                       field: FieldConfig) -> np.ndarray | None:
    """Keep the players of ``block`` at least ``clearance`` from the set-play spot (cx, cy).

    Players too close are pushed radially out. Where that would take them beyond the ground
    around the pitch (field plus ``field.margin``) they are instead put on the clearance circle
    in the direction of the centre spot, which always lies inside the field. Returns the bool
    mask of moved rows, or None if nobody was moved.
    """
    to_centre = math.hypot(cx, cy)
    fallback = (-cx / to_centre, -cy / to_centre) if to_centre > 0.0 else (1.0, 0.0)
    moved = push_out_of_circle(block, cx, cy, clearance, fallback)
    if moved is None:
        return None
    x_lim = field.half_length + field.margin
    y_lim = field.half_width + field.margin
    off = moved & ((np.abs(block[:, 0]) > x_lim) | (np.abs(block[:, 1]) > y_lim))
    if off.any():
        block[off, 0] = cx + clearance * fallback[0]
        block[off, 1] = cy + clearance * fallback[1]
    return moved
