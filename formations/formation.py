"""The Formation: roles, samples, and the target positions for any ball position.

A formation in the style of the RoboCup 2D reference teams (agent2d /
helios-base): a list of *samples*, each a ball position paired with one
position per role. The ball positions are Delaunay-triangulated once; for any
ball position the role positions are interpolated barycentrically from the
three samples of the triangle containing it, and beyond the samples' convex
hull from the nearest point of the hull boundary (see
:mod:`formations.interpolation`).

All coordinates are in the team-relative frame of :mod:`formations.field`.
"""

from __future__ import annotations

import os
from collections.abc import Sequence

import numpy as np
from numpy.typing import ArrayLike

from formations.errors import FormationError, FormationInputError, UnknownRoleError
from formations.field import FieldDimensions
from formations.interpolation import TriangleInterpolator
from formations.interpolation_kernels import QueryTables
from formations.roles import Role, check_roles
from formations.triangulation import triangulate
from formations.validation import check_samples
from formations.writing import formation_to_dict, write_document


class Formation:
    """Target positions of the roles as a function of the ball position.

    Parameters
    ----------
    roles:
        The roles, in the order used by every position array.
    balls:
        (n, 2) ball positions of the samples, metres.
    positions:
        (n, len(roles), 2) role positions of the samples, metres.
    name, description:
        Free text, saved with the formation.
    source:
        What to name in error messages (the file a formation was read from).
    field:
        The field the samples are for (the simulator's ``FieldConfig``); given, every
        position must lie within :data:`~formations.field.FAR_OUTSIDE_MARGIN` of its lines
        (the readers of formation files pass it to catch typos). Not kept.

    Raises :class:`FormationError` if the roles or samples are unusable.
    """

    def __init__(
        self,
        roles: Sequence[Role],
        balls: ArrayLike,
        positions: ArrayLike,
        *,
        name: str = "",
        description: str = "",
        source: str | None = None,
        field: FieldDimensions | None = None,
    ) -> None:
        self.source = source or (f"formation {name!r}" if name else "<formation>")
        roles = tuple(roles)
        check_roles(roles, self.source)
        balls_array = _as_float_array(balls, self.source, "ball positions")
        positions_array = _as_float_array(positions, self.source, "role positions")
        check_samples(roles, balls_array, positions_array, self.source, field)
        self.roles: tuple[Role, ...] = roles
        self.name = name
        self.description = description
        self._balls = balls_array
        self._positions = positions_array
        self._balls.flags.writeable = False
        self._positions.flags.writeable = False
        self._n_roles = len(roles)
        tri = triangulate(balls_array, self.source)
        self._interpolator = TriangleInterpolator(tri, positions_array.reshape(len(balls_array), -1))
        self._index_of = {role.number: i for i, role in enumerate(roles)}

    # ------------------------------------------------------------ description
    @property
    def balls(self) -> np.ndarray:
        """(n, 2) ball positions of the samples (read-only)."""
        return self._balls

    @property
    def sample_positions(self) -> np.ndarray:
        """(n, roles, 2) role positions of the samples (read-only)."""
        return self._positions

    @property
    def n_samples(self) -> int:
        return len(self._balls)

    @property
    def role_numbers(self) -> tuple[int, ...]:
        return tuple(role.number for role in self.roles)

    @property
    def triangles(self) -> np.ndarray:
        """(T, 3) sample indices of the Delaunay triangles."""
        return self._interpolator.tri.simplices

    @property
    def hull_edges(self) -> np.ndarray:
        """(E, 2) sample indices of the convex hull's boundary segments."""
        return self._interpolator.tri.convex_hull

    def role(self, number: int) -> Role:
        """The role with shirt number *number*."""
        return self.roles[self.index_of(number)]

    def index_of(self, number: int) -> int:
        """Row of role *number* in every position array."""
        try:
            return self._index_of[number]
        except KeyError:
            raise UnknownRoleError(f"{self.source} has no role {number!r} (roles: {list(self._index_of)})") from None

    # ---------------------------------------------------------------- queries
    def positions(self, ball_xy: ArrayLike) -> np.ndarray:
        """(roles, 2) target positions for one ball position (x, y) in metres.

        Cheap enough to call every cycle: a few microseconds. Raises
        FormationInputError (a ValueError) for anything but two finite numbers.
        """
        if len(ball_xy) != 2:
            raise FormationInputError(f"a ball position is two numbers (x, y), got {len(ball_xy)}: {ball_xy!r}")
        return self._interpolator.value(float(ball_xy[0]), float(ball_xy[1])).reshape(self._n_roles, 2)

    def positions_many(self, balls: ArrayLike) -> np.ndarray:
        """(k, roles, 2) target positions for k ball positions given as (k, 2)."""
        points = np.asarray(balls, dtype=np.float64)
        if points.ndim == 1 and points.shape == (2,):
            points = points[None, :]
        values = self._interpolator.values_many(points)
        return values.reshape(len(points), self._n_roles, 2)

    @property
    def query_tables(self) -> QueryTables:
        """The compiled query's tables (:func:`formations.interpolation_kernels.value_kernel`'s
        ``tables``), for callers that query inside their own compiled loops."""
        return self._interpolator.tables

    def nearest_covered_ball(self, ball_xy: ArrayLike) -> tuple[float, float]:
        """The ball position actually interpolated: *ball_xy* itself inside the
        samples' convex hull, else its projection onto the hull boundary."""
        return self._interpolator.hull_projection(float(ball_xy[0]), float(ball_xy[1]))

    # ------------------------------------------------------------------ files
    def save(self, path: str | os.PathLike[str]) -> None:
        """Write this formation to *path* in the package's JSON layout."""
        write_document(formation_to_dict(self), path)

    def __reduce__(self):
        # Pickle the definition only (a few kB): the triangulation and lookup
        # tables are rebuilt on unpickling in a few milliseconds.
        return (
            _rebuild,
            (self.roles, self._balls.copy(), self._positions.copy(), self.name, self.description, self.source),
        )

    def __repr__(self) -> str:
        return (
            f"Formation(name={self.name!r}, roles={len(self.roles)}, samples={self.n_samples}, "
            f"triangles={len(self.triangles)})"
        )


def _as_float_array(data: ArrayLike, source: str, what: str) -> np.ndarray:
    try:
        return np.array(data, dtype=np.float64, copy=True)
    except (TypeError, ValueError) as error:
        raise FormationError(source, f"{what} are not an array of numbers ({error})") from None


def _rebuild(
    roles: tuple[Role, ...], balls: np.ndarray, positions: np.ndarray, name: str, description: str, source: str
) -> Formation:
    return Formation(roles, balls, positions, name=name, description=description, source=source)
