"""Checks of a formation's samples, each naming the sample and role at fault."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from scipy.spatial import cKDTree

from formations.errors import FormationError
from formations.field import FAR_OUTSIDE_MARGIN, MIN_SAMPLE_SEPARATION, FieldDimensions
from formations.roles import Role

MAX_ROLES = 11
"""Most roles a formation may have: it places the players of one team."""


def check_samples(roles: Sequence[Role], balls: np.ndarray, positions: np.ndarray, source: str,
                  field: FieldDimensions | None = None) -> None:
    """Raise :class:`FormationError` unless the samples are usable.

    *balls* is (n, 2) and *positions* (n, len(roles), 2). Checks that there are at
    most :data:`MAX_ROLES` roles, shapes, that
    every coordinate is finite (and, given the *field* the samples are for, within
    :data:`~formations.field.FAR_OUTSIDE_MARGIN` of its lines: :func:`field_limits`),
    and that no two ball positions are closer than
    :data:`~formations.field.MIN_SAMPLE_SEPARATION`. (Enough samples and a
    non-degenerate layout are checked when triangulating.)
    """
    check_role_count(roles, source)
    limits = None if field is None else field_limits(field)
    n = len(balls)
    if balls.ndim != 2 or balls.shape[1] != 2:
        raise FormationError(source, f"ball positions must have shape (n, 2), got {balls.shape}")
    expected = (n, len(roles), 2)
    if positions.shape != expected:
        raise FormationError(source, f"role positions must have shape {expected}, got {positions.shape}")
    for i in range(n):
        _check_point(balls[i], source, f"sample {i}, ball", limits)
        for j, role in enumerate(roles):
            _check_point(positions[i, j], source, f"sample {i}, role {role.number}", limits)
    if n >= 2:
        pairs = cKDTree(balls).query_pairs(MIN_SAMPLE_SEPARATION, output_type="ndarray")
        if len(pairs):
            first = pairs[np.lexsort((pairs[:, 1], pairs[:, 0]))][0]
            i, j = sorted(int(v) for v in first)
            gap = float(np.hypot(*(balls[i] - balls[j])))
            raise FormationError(
                source,
                f"ball position {balls[j].tolist()} is only {gap:.3g} m from that of sample {i} "
                f"(samples must be at least {MIN_SAMPLE_SEPARATION} m apart)",
                f"sample {j}",
            )


def check_role_count(roles: Sequence[Role], source: str) -> None:
    """Raise :class:`FormationError` if there are more roles than players in a team."""
    if len(roles) > MAX_ROLES:
        raise FormationError(source, f"{len(roles)} roles; a formation places one team, at most {MAX_ROLES} players")


def check_ball_position(ball: Sequence[float], source: str, field: FieldDimensions) -> None:
    """Raise :class:`FormationError` (naming *source*, e.g. a command option) unless *ball* is
    a finite position within :func:`field_limits` of *field*, the limits of a formation file."""
    _check_point(np.asarray(ball, dtype=float), source, None, field_limits(field))


def field_limits(field: FieldDimensions) -> tuple[float, float, float, float]:
    """(largest |x|, largest |y|, length, width) m: a ball or role position of a formation on
    *field* may lie at most :data:`~formations.field.FAR_OUTSIDE_MARGIN` beyond its lines."""
    return (field.half_length + FAR_OUTSIDE_MARGIN, field.half_width + FAR_OUTSIDE_MARGIN,
            field.length, field.width)


def _check_point(point: np.ndarray, source: str, where: str | None,
                 limits: tuple[float, float, float, float] | None) -> None:
    x, y = float(point[0]), float(point[1])
    if not (np.isfinite(x) and np.isfinite(y)):
        raise FormationError(source, f"coordinates must be finite numbers, got ({x}, {y})", where)
    if limits is None:
        return
    x_limit, y_limit, length, width = limits
    if abs(x) > x_limit or abs(y) > y_limit:
        raise FormationError(
            source,
            f"position ({x:g}, {y:g}) is far outside the {length:g} x {width:g} m "
            f"field (limits |x| <= {x_limit:g}, |y| <= {y_limit:g}; coordinates are metres from the centre)",
            where,
        )
