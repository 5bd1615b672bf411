"""Mirror symmetry across the long axis of the field (y -> -y).

A formation is mirror-symmetric when, for every sample with ball (x, y),
there is a sample with ball (x, -y) whose role positions are the mirror
images of the first sample's partner roles: the left back stands where the
right back stood, mirrored. Designing one half of the field and completing the
other with :func:`mirror_complete` halves the work and guarantees symmetry.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from formations.errors import FormationError
from formations.formation import Formation

ON_AXIS_TOLERANCE = 1e-9
"""|y| (metres) below which a sample's ball counts as lying on the axis."""


def mirror_permutation(formation: Formation) -> np.ndarray:
    """Index array p such that role i of a mirrored position array is role p[i]."""
    return np.array([formation.index_of(role.mirror_number) for role in formation.roles], dtype=np.intp)


def mirror_positions(positions: np.ndarray, permutation: np.ndarray) -> np.ndarray:
    """Mirror (..., roles, 2) positions in y and swap partner roles."""
    mirrored = positions[..., permutation, :].copy()
    mirrored[..., 1] *= -1.0
    return mirrored


def mirror_complete(formation: Formation, *, name: str | None = None) -> Formation:
    """Complete a formation designed on one half of the field into a symmetric one.

    *formation*'s samples must all have ball y >= 0 or all y <= 0 (up to
    :data:`ON_AXIS_TOLERANCE`). Each off-axis sample gets a mirrored twin; each
    on-axis sample is made self-symmetric by averaging it with its own mirror
    image (so a central role ends on the axis and partners mirror each other).
    Raises :class:`FormationError` if the samples lie on both sides.
    """
    balls = formation.balls
    upper = balls[:, 1] > ON_AXIS_TOLERANCE
    lower = balls[:, 1] < -ON_AXIS_TOLERANCE
    if upper.any() and lower.any():
        offender = int(np.flatnonzero(lower)[0]) if upper.sum() >= lower.sum() else int(np.flatnonzero(upper)[0])
        raise FormationError(
            formation.source,
            "to be completed by mirroring, all samples must have their ball on one side of y = 0",
            f"sample {offender}",
        )
    perm = mirror_permutation(formation)
    positions = formation.sample_positions
    on_axis = ~(upper | lower)
    axis_balls = balls[on_axis].copy()
    axis_balls[:, 1] = 0.0
    # Averaging with the mirror image is exactly symmetric in floating point
    # (central roles get y = 0, partners become exact mirrors).
    axis_positions = 0.5 * (positions[on_axis] + mirror_positions(positions[on_axis], perm))
    side = ~on_axis
    side_balls = balls[side]
    mirrored_balls = side_balls * np.array([1.0, -1.0])
    all_balls = np.concatenate((axis_balls, side_balls, mirrored_balls))
    all_positions = np.concatenate((axis_positions, positions[side], mirror_positions(positions[side], perm)))
    return Formation(
        formation.roles,
        all_balls,
        all_positions,
        name=formation.name if name is None else name,
        description=formation.description,
        source=formation.source,
    )


@dataclass(frozen=True)
class Asymmetry:
    """One violation of mirror symmetry."""

    sample: int
    """Index of the sample concerned."""
    role: int | None
    """Role number whose position is not mirrored, or None if the sample has no mirror sample."""
    error: float
    """Metres between the position and the mirror of its partner's position."""

    def describe(self) -> str:
        if self.role is None:
            return f"sample {self.sample}: no sample has the mirrored ball position"
        return f"sample {self.sample}, role {self.role}: {self.error:.3g} m from the mirror of its partner"


def asymmetries(formation: Formation, tolerance: float = 1e-9) -> list[Asymmetry]:
    """List every way in which *formation*'s samples break mirror symmetry.

    Empty if and only if every sample has a mirror sample (ball (x, -y)
    within *tolerance* metres) whose positions mirror its own, partner for
    partner, within *tolerance*.
    """
    balls = formation.balls
    perm = mirror_permutation(formation)
    tree = cKDTree(balls)
    distance, twin = tree.query(balls * np.array([1.0, -1.0]))
    found: list[Asymmetry] = []
    positions = formation.sample_positions
    for i in range(len(balls)):
        if distance[i] > tolerance:
            found.append(Asymmetry(i, None, float(distance[i])))
            continue
        expected = mirror_positions(positions[twin[i]], perm)
        errors = np.hypot(*(positions[i] - expected).T)
        for j in np.flatnonzero(errors > tolerance):
            found.append(Asymmetry(i, formation.roles[j].number, float(errors[j])))
    return found


def query_asymmetry(formation: Formation, balls: np.ndarray) -> float:
    """Largest distance (metres) between positions(b) and the mirror of
    positions(mirror(b)) over *balls* ((k, 2)).

    Zero only if the triangulation itself is symmetric, which symmetric
    samples do not guarantee: cocircular samples let Delaunay pick either
    diagonal of a quadrilateral.
    """
    perm = mirror_permutation(formation)
    direct = formation.positions_many(balls)
    mirrored = formation.positions_many(balls * np.array([1.0, -1.0]))
    return float(np.max(np.abs(direct - mirror_positions(mirrored, perm)), initial=0.0))
