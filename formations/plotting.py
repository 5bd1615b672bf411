"""Pictures of a formation: field, triangulation, samples, interpolated positions.

matplotlib is imported inside the functions (with the non-interactive Agg
backend when saving), so importing :mod:`formations` never pulls it in.
"""

from __future__ import annotations

import os
from typing import Any

import numpy as np

from formations.field import FieldDimensions
from formations.formation import Formation

KIND_COLOURS = {
    "goalkeeper": "#f2c200",
    "defender": "#1f5fbf",
    "midfielder": "#2a9d3a",
    "forward": "#c0392b",
}
"""Marker colour of each role kind."""


def draw_field(ax: Any, field: FieldDimensions) -> None:
    """Draw the markings of *field* (team-relative frame, our goal on the left)."""
    from matplotlib.patches import Arc, Circle, Rectangle

    hl, hw = field.half_length, field.half_width
    line = {"edgecolor": "white", "facecolor": "none", "linewidth": 1.2, "zorder": 1}
    ax.set_facecolor("#3b8c3b")
    ax.add_patch(Rectangle((-hl, -hw), field.length, field.width, **line))
    ax.plot([0, 0], [-hw, hw], color="white", linewidth=1.2, zorder=1)
    ax.add_patch(Circle((0, 0), field.centre_circle_radius, **line))
    for sign in (-1.0, 1.0):
        goal_line = sign * hl
        for depth, width in (
            (field.penalty_area_length, field.penalty_area_width),
            (field.goal_area_length, field.goal_area_width),
        ):
            x = goal_line if sign < 0 else goal_line - depth
            ax.add_patch(Rectangle((x, -width / 2), depth, width, **line))
        ax.add_patch(
            Rectangle(
                (goal_line if sign > 0 else goal_line - 1.5, -field.goal_width / 2), 1.5, field.goal_width, **line
            )
        )
        spot = goal_line - sign * 11.0
        ax.plot([spot], [0], marker=".", color="white", zorder=1)
        ax.add_patch(
            Arc(
                (spot, 0),
                18.3,
                18.3,
                theta1=(-53 if sign < 0 else 127),
                theta2=(53 if sign < 0 else 233),
                edgecolor="white",
                linewidth=1.2,
                zorder=1,
            )
        )
    ax.set_xlim(-hl - 6, hl + 6)
    ax.set_ylim(-hw - 5, hw + 5)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])


def draw_formation(ax: Any, formation: Formation, ball_xy: tuple[float, float]) -> np.ndarray:
    """Draw triangulation, samples, the ball and the interpolated role positions.

    Returns the (roles, 2) positions drawn.
    """
    balls = formation.balls
    ax.triplot(balls[:, 0], balls[:, 1], formation.triangles, color="white", alpha=0.35, linewidth=0.7, zorder=2)
    ax.plot(balls[:, 0], balls[:, 1], "o", color="black", markersize=2.5, alpha=0.6, zorder=3, label="samples")
    bx, by = float(ball_xy[0]), float(ball_xy[1])
    covered = formation.nearest_covered_ball((bx, by))
    if np.hypot(covered[0] - bx, covered[1] - by) > 1e-9:
        ax.plot([bx, covered[0]], [by, covered[1]], ":", color="white", zorder=4)
        ax.plot([covered[0]], [covered[1]], "x", color="white", zorder=4, label="projection on hull")
    ax.plot([bx], [by], "o", color="white", markeredgecolor="black", markersize=8, zorder=6, label="ball")
    x0, x1 = ax.get_xlim()
    y0, y1 = ax.get_ylim()
    ax.set_xlim(min(x0, bx - 3.0), max(x1, bx + 3.0))  # keep a ball far out of play in the picture
    ax.set_ylim(min(y0, by - 3.0), max(y1, by + 3.0))
    positions = formation.positions((bx, by))
    for role, (x, y) in zip(formation.roles, positions):
        ax.plot(
            [x], [y], "o", color=KIND_COLOURS.get(role.kind, "grey"), markeredgecolor="white", markersize=11, zorder=5
        )
        ax.annotate(
            str(role.number), (x, y), ha="center", va="center", fontsize=7, color="white", weight="bold", zorder=7
        )
        ax.annotate(
            role.name,
            (x, y),
            xytext=(0, -11),
            textcoords="offset points",
            ha="center",
            va="top",
            fontsize=6,
            color="white",
            zorder=7,
        )
    return positions


def save_picture(
    formation: Formation,
    ball_xy: tuple[float, float],
    path: str | os.PathLike[str],
    *,
    field: FieldDimensions,
    title: str | None = None,
) -> np.ndarray:
    """Write a PNG (or any format matplotlib infers from *path*) of *formation* at *ball_xy*, on
    the markings of *field*."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(11, 7.5))
    try:
        draw_field(ax, field)
        positions = draw_formation(ax, formation, ball_xy)
        ax.set_title(title or f"{formation.name or 'formation'}: ball at ({ball_xy[0]:g}, {ball_xy[1]:g})")
        ax.legend(loc="upper right", fontsize=7, framealpha=0.6)
        fig.tight_layout()
        fig.savefig(path, dpi=120)
    finally:
        plt.close(fig)
    return positions
