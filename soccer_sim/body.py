"""Where a player's body faces: the one body-direction model of the simulator.

rcssserver's players have a body direction that they turn with ``(turn MOMENT)``; several
rules depend on it (how strongly a ball lying beside or behind the body can be kicked, how
far in front a tackle reaches, side and back dashes). soccer-sim's players are
orientation-less point robots, so every such rule asks this module instead, and all ask the
same question the same way.

**The model.** A real agent that wants to kick or tackle turns towards the ball the cycle
before. rcssserver limits a turn by the player's speed: the largest turn is
``180° / (1 + inertia_moment * speed)`` (speed in m/cycle; ``inertia_moment`` 5.0 for the
default player type). So:

* a player at rest faces the ball (it could turn any amount);
* a moving player faces its direction of motion turned towards the ball by at most that
  largest turn: a slow player faces the ball, a sprinter whose ball lies behind it does not.

A player exactly on the ball's centre has no direction to the ball; it faces its motion (or
+x at rest), which does not matter to any rule since the ball's distance is then zero.
Directions are unit vectors in the frame of the positions given (absolute or a team's).
"""

from __future__ import annotations

import math

from numba import njit

DEFAULT_INERTIA_MOMENT = 5.0
"""rcssserver's ``inertia_moment`` of the default player type."""


@njit(cache=True, nogil=True)
def turn_angle(moment: float, speed: float, inertia_moment: float) -> float:  # pragma: no cover - compiled
    """rcssserver's turn (``Player::turn``, noise aside): a ``(turn MOMENT)`` of a player moving
    at ``speed`` (m/cycle) turns its body by ``moment / (1 + inertia_moment * speed)``, in the
    moment's unit (degrees or radians). With ``moment`` 180° (``maxmoment``) it is the largest
    turn at that speed."""
    return moment / (1.0 + inertia_moment * speed)


@njit(cache=True, nogil=True)
def facing(vx: float, vy: float, to_ball_x: float, to_ball_y: float,
           inertia_moment: float) -> tuple[float, float]:  # pragma: no cover - compiled
    """The unit vector a player with velocity ``(vx, vy)`` (m/cycle) faces when the ball lies
    at ``(to_ball_x, to_ball_y)`` from it (m), by the model of the module docstring."""
    speed = math.hypot(vx, vy)
    distance = math.hypot(to_ball_x, to_ball_y)
    if distance == 0.0:
        if speed == 0.0:
            return 1.0, 0.0
        return vx / speed, vy / speed
    bx, by = to_ball_x / distance, to_ball_y / distance
    if speed == 0.0:
        return bx, by
    mx, my = vx / speed, vy / speed
    angle = math.atan2(mx * by - my * bx, mx * bx + my * by)  # from the motion to the ball, (-pi, pi]
    largest = turn_angle(math.pi, speed, inertia_moment)
    if abs(angle) <= largest:
        return bx, by
    turn = largest if angle > 0.0 else -largest
    c, s = math.cos(turn), math.sin(turn)
    return mx * c - my * s, mx * s + my * c


@njit(cache=True, nogil=True)
def ball_angle_to_body(vx: float, vy: float, to_ball_x: float, to_ball_y: float,
                       inertia_moment: float) -> float:  # pragma: no cover - compiled
    """The angle (radians, [0, pi]) between where the player faces (:func:`facing`) and the
    direction to the ball: rcssserver's ``dir_diff`` of the kick and tackle rules. 0 when the
    player is on the ball's centre."""
    distance = math.hypot(to_ball_x, to_ball_y)
    if distance == 0.0:
        return 0.0
    fx, fy = facing(vx, vy, to_ball_x, to_ball_y, inertia_moment)
    cosine = (fx * to_ball_x + fy * to_ball_y) / distance
    return math.acos(min(1.0, max(-1.0, cosine)))
