"""The goalkeeper's goal-line guard: where a keeper stands as real RoboCup 2D keepers do.

Measured in the real server's helios-base logs (play on, keeper's distance from its goal line
and its y on the ball's side, medians): 2.7-3.0 m out with |y| 0-2 m while the ball is in
the other half or central; with the ball wide and close (within 18 m of the goal line, more
than 10 m off-centre) 1.3-2.5 m out at the near post (|y| 6.0-6.6 m); never beyond the goal
area while the ball is in front of it. A keeper that steps up the ball-goal segment towards
a close ball instead leaves the near post open on wide balls and is beaten by a shot across
it on central ones.

**The point.** Its distance from our goal line is ``depth`` times the cosine of the ball's
angle off the goal's axis (seen from the goal centre), at least ``min_depth``: deep on wide
balls, ``depth`` on central ones. Its y is where the line from the ball to a pivot
``pivot_behind`` metres behind our goal centre crosses that depth (nearer the post than the
straight ball-goal line, which cuts the near-post shot), kept ``post_margin`` inside the
posts. It stays ``ball_gap`` short of the ball; a ball behind our goal line (out of play) puts
it on the near post's side at ``min_depth``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from agents.skills.model import MotionModel, check_params, float_array


@dataclass(frozen=True)
class GoalLineParams:
    """Where the goal-line guard stands (metres)."""

    depth: float = 3.0
    """Distance from our goal line with the ball straight in front of the goal (helios-base's
    keeper: 2.7-3.0 m)."""
    min_depth: float = 1.3
    """Least distance from our goal line (helios-base's with the ball wide and close: 1.3 m)."""
    pivot_behind: float = 5.0
    """The keeper's y is on the line from the ball to a point this far behind our goal centre
    (0: the straight ball-goal line); 5 m matches helios-base's y within about 1 m across
    ball positions."""
    post_margin: float = 0.5
    """The guard point's |y| stays this far inside the posts."""
    ball_gap: float = 1.0
    """The guard point's depth stays this far short of the ball's."""

    def __post_init__(self) -> None:
        check_params(self, non_negative=("depth", "min_depth", "pivot_behind", "post_margin", "ball_gap"))


def goal_line_guard(model: MotionModel, ball: np.ndarray,
                    params: GoalLineParams = GoalLineParams()) -> tuple[float, float]:
    """(x, y) our goalkeeper's goal-line guard point for a ball at ``ball`` ((2,), team frame;
    see the module docstring)."""
    if not (type(ball) is np.ndarray and ball.shape == (2,) and ball.dtype.kind == "f"):
        ball = float_array("ball", ball, (2,))
    gx = -model.half_length
    dx, by = float(ball[0]) - gx, float(ball[1])
    dist = math.hypot(dx, by)
    limit = max(model.goal_half_width - params.post_margin, 0.0)
    if dx <= 0.0:  # behind (or on) our goal line: near post, shallow
        return gx + params.min_depth, math.copysign(limit, by) if by else 0.0
    depth = max(params.depth * dx / dist, params.min_depth)
    depth = max(min(depth, dx - params.ball_gap), 0.0)
    y = by * (depth + params.pivot_behind) / (dx + params.pivot_behind)
    return gx + depth, min(max(y, -limit), limit)
