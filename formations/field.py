"""Dimensions of the standard field, as formations need them.

Formations live in the *team-relative frame*: metres, origin at the centre
spot, the team attacks towards +x (its own goal line is x = -52.5), and +y
points to the left of a player facing the opponent goal. The numbers are those
of the RoboCup 2D soccer server (FIFA's pitch rounded to 105 x 68 m). They are
kept here, rather than imported from the simulator, because this package is
pure (numpy/scipy only); the simulator's configuration uses the same values.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class FieldDimensions:
    """Lengths of the field markings, in metres."""

    length: float = 105.0
    """Distance between the two goal lines."""
    width: float = 68.0
    """Distance between the two touchlines."""
    penalty_area_depth: float = 16.5
    """How far the penalty area reaches into the field from the goal line."""
    penalty_area_width: float = 40.32
    """Extent of the penalty area along the goal line."""
    goal_area_depth: float = 5.5
    """How far the goal area reaches into the field from the goal line."""
    goal_area_width: float = 18.32
    """Extent of the goal area along the goal line."""
    goal_width: float = 14.02
    """Distance between the goal posts (the server's wide goal)."""
    centre_circle_radius: float = 9.15
    """Radius of the centre circle, also the distance opponents keep at set plays."""

    @property
    def half_length(self) -> float:
        """x of the opponent goal line (our own is at minus this)."""
        return self.length / 2.0

    @property
    def half_width(self) -> float:
        """|y| of the touchlines."""
        return self.width / 2.0


STANDARD_FIELD = FieldDimensions()
"""The field every built-in formation is designed for."""

FAR_OUTSIDE_MARGIN = 10.0
"""Metres beyond the goal lines and touchlines where a ball or player position
in a formation file is still accepted; anything farther is rejected as a typo
(or as coordinates in another unit or frame)."""

MIN_SAMPLE_SEPARATION = 0.5
"""Metres: two samples whose ball positions are closer than this are treated as
duplicates, because they would make needle-thin triangles whose interpolation
amplifies every small difference between the two samples."""
