"""What formations read from a field, and the tolerances of formation files.

Formations live in the *team-relative frame*: metres, origin at the centre
spot, the team attacks towards +x (its own goal line is x = -half_length), and
+y points to the left of a player facing the opponent goal.

This package is pure (numpy/scipy only), so it does not define the field: the
field's dimensions are defined once, in the simulator's configuration
(``soccer_sim.config.FieldConfig``, its default ``soccer_sim.config.STANDARD_FIELD``),
and every function here that needs them takes the field from its caller as a
:class:`FieldDimensions`, which ``FieldConfig`` satisfies.
"""

from __future__ import annotations

from typing import Protocol


class FieldDimensions(Protocol):
    """The lengths of the field markings formations use (metres): the interface of the
    simulator's ``FieldConfig``, with its names."""

    @property
    def length(self) -> float:
        """Distance between the two goal lines."""

    @property
    def width(self) -> float:
        """Distance between the two touchlines."""

    @property
    def half_length(self) -> float:
        """x of the opponent goal line (our own is at minus this)."""

    @property
    def half_width(self) -> float:
        """|y| of the touchlines."""

    @property
    def penalty_area_length(self) -> float:
        """How far the penalty area reaches into the field from the goal line."""

    @property
    def penalty_area_width(self) -> float:
        """Extent of the penalty area along the goal line."""

    @property
    def goal_area_length(self) -> float:
        """How far the goal area reaches into the field from the goal line."""

    @property
    def goal_area_width(self) -> float:
        """Extent of the goal area along the goal line."""

    @property
    def goal_width(self) -> float:
        """Distance between the goal posts."""

    @property
    def centre_circle_radius(self) -> float:
        """Radius of the centre circle, also the distance opponents keep at set plays."""


FAR_OUTSIDE_MARGIN = 10.0
"""Metres beyond the goal lines and touchlines where a ball or player position
in a formation file is still accepted; anything farther is rejected as a typo
(or as coordinates in another unit or frame)."""

MIN_SAMPLE_SEPARATION = 0.5
"""Metres: two samples whose ball positions are closer than this are treated as
duplicates, because they would make needle-thin triangles whose interpolation
amplifies every small difference between the two samples."""
