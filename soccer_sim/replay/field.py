"""The field's markings as polylines (absolute frame, metres) and its colours, for replays and pictures."""

from __future__ import annotations

import numpy as np

from soccer_sim.config import FieldConfig

GRASS_COLOUR = (35, 90, 40)
LINE_COLOUR = (255, 255, 255)
"""The pitch (RGB): white lines on a dark green, in the viewer (whose theme then does not
matter: the grass is drawn under the field and is the view's background) and in pictures."""


def _circle(cx: float, cy: float, radius: float, start: float = 0.0, stop: float = 2 * np.pi,
            points: int = 64) -> np.ndarray:
    angles = np.linspace(start, stop, points)
    return np.column_stack([cx + radius * np.cos(angles), cy + radius * np.sin(angles)])


def field_lines(field: FieldConfig) -> list[np.ndarray]:
    """Every marking as an (k, 2) polyline: touch and goal lines, halfway line, centre circle
    and spot, both penalty and goal areas; the goals are :func:`goal_frames`."""
    hl, hw = field.length / 2.0, field.width / 2.0
    lines = [
        np.array([[-hl, -hw], [hl, -hw], [hl, hw], [-hl, hw], [-hl, -hw]]),
        np.array([[0.0, -hw], [0.0, hw]]),
        _circle(0.0, 0.0, field.centre_circle_radius),
        _circle(0.0, 0.0, 0.25, points=12),
    ]
    for side in (-1.0, 1.0):
        for depth, half_width in ((field.penalty_area_length, field.penalty_area_width / 2.0),
                                  (field.goal_area_length, field.goal_area_width / 2.0)):
            x_in = side * (hl - depth)
            lines.append(np.array([[side * hl, -half_width], [x_in, -half_width], [x_in, half_width],
                                   [side * hl, half_width]]))
    return lines


def goal_frames(field: FieldConfig, depth: float = 1.5) -> list[np.ndarray]:
    """Both goals as (4, 2) polylines behind the goal lines (home's goal at -x first)."""
    hl, half_goal = field.length / 2.0, field.goal_width / 2.0
    return [np.array([[side * hl, -half_goal], [side * (hl + depth), -half_goal],
                      [side * (hl + depth), half_goal], [side * hl, half_goal]]) for side in (-1.0, 1.0)]
