"""Checks of a formation's samples, each naming the sample and role at fault."""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
from scipy.spatial import cKDTree

from formations.errors import FormationError
from formations.field import FAR_OUTSIDE_MARGIN, MIN_SAMPLE_SEPARATION, STANDARD_FIELD
from formations.roles import Role

X_LIMIT = STANDARD_FIELD.half_length + FAR_OUTSIDE_MARGIN
"""Largest |x| accepted for any ball or role position, metres."""
Y_LIMIT = STANDARD_FIELD.half_width + FAR_OUTSIDE_MARGIN
"""Largest |y| accepted for any ball or role position, metres."""
MAX_ROLES = 11
"""Most roles a formation may have: it places the players of one team."""


def check_samples(roles: Sequence[Role], balls: np.ndarray, positions: np.ndarray, source: str) -> None:
    """Raise :class:`FormationError` unless the samples are usable.

    *balls* is (n, 2) and *positions* (n, len(roles), 2). Checks that there are at
    most :data:`MAX_ROLES` roles, shapes, that
    every coordinate is finite and within :data:`X_LIMIT` / :data:`Y_LIMIT`,
    and that no two ball positions are closer than
    :data:`~formations.field.MIN_SAMPLE_SEPARATION`. (Enough samples and a
    non-degenerate layout are checked when triangulating.)
    """
    check_role_count(roles, source)
    n = len(balls)
    if balls.ndim != 2 or balls.shape[1] != 2:
        raise FormationError(source, f"ball positions must have shape (n, 2), got {balls.shape}")
    expected = (n, len(roles), 2)
    if positions.shape != expected:
        raise FormationError(source, f"role positions must have shape {expected}, got {positions.shape}")
    for i in range(n):
        _check_point(balls[i], source, f"sample {i}, ball")
        for j, role in enumerate(roles):
            _check_point(positions[i, j], source, f"sample {i}, role {role.number}")
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


def check_ball_position(ball: Sequence[float], source: str) -> None:
    """Raise :class:`FormationError` (naming *source*, e.g. a command option) unless *ball* is
    a finite position within :data:`X_LIMIT` / :data:`Y_LIMIT`, the limits of a formation file."""
    _check_point(np.asarray(ball, dtype=float), source, None)


def _check_point(point: np.ndarray, source: str, where: str | None) -> None:
    x, y = float(point[0]), float(point[1])
    if not (np.isfinite(x) and np.isfinite(y)):
        raise FormationError(source, f"coordinates must be finite numbers, got ({x}, {y})", where)
    if abs(x) > X_LIMIT or abs(y) > Y_LIMIT:
        raise FormationError(
            source,
            f"position ({x:g}, {y:g}) is far outside the {STANDARD_FIELD.length:g} x {STANDARD_FIELD.width:g} m "
            f"field (limits |x| <= {X_LIMIT:g}, |y| <= {Y_LIMIT:g}; coordinates are metres from the centre)",
            where,
        )
