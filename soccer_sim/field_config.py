"""The field's dimensions (:class:`FieldConfig`), defined here once for the simulator, the
teams and the formations alike, and :data:`STANDARD_FIELD`, the default field every component
uses unless a match configures another; importable from :mod:`soccer_sim.config` like every
configuration.

A module of its own (imported by :mod:`soccer_sim.config`, which re-exports both) so that the
perception code that :mod:`soccer_sim.config` itself imports can take the field from here.
"""

from __future__ import annotations

from dataclasses import dataclass

from soccer_sim.config_checks import ConfigError
from soccer_sim.config_ranges import check_ranges


@dataclass(frozen=True)
class FieldConfig:
    """Dimensions of the pitch (metres)."""

    length: float = 105.0
    """Distance between the two goal lines."""
    width: float = 68.0
    """Distance between the two touchlines."""
    goal_width: float = 14.02
    """Distance between the inner sides of the goal posts."""
    goal_post_radius: float = 0.06
    """Radius of each (static, collidable) goal post."""
    penalty_area_length: float = 16.5
    """Depth of the penalty area from the goal line."""
    penalty_area_width: float = 40.32
    """Width of the penalty area across the field."""
    goal_area_length: float = 5.5
    """Depth of the goal area from the goal line."""
    goal_area_width: float = 18.32
    """Width of the goal area across the field."""
    centre_circle_radius: float = 9.15
    """Radius of the centre circle, also the set-play clearance distance."""
    margin: float = 5.0
    """How far beyond the lines players may run (the ground around the pitch)."""

    def __post_init__(self) -> None:
        self.validate()

    def validate(self) -> None:
        """ConfigError naming the first field out of its range (:mod:`soccer_sim.config_ranges`)
        or out of proportion with the others."""
        check_ranges(self)
        if self.goal_width >= self.width:
            raise ConfigError(f"FieldConfig.goal_width ({self.goal_width}) must be smaller than the field width ({self.width})")
        if self.penalty_area_width >= self.width or self.goal_area_width >= self.penalty_area_width:
            raise ConfigError("FieldConfig: need goal_area_width < penalty_area_width < width")
        if self.goal_width >= self.goal_area_width:
            raise ConfigError("FieldConfig: the goal must be narrower than the goal area")
        if self.penalty_area_length * 2 >= self.length or self.goal_area_length >= self.penalty_area_length:
            raise ConfigError("FieldConfig: need goal_area_length < penalty_area_length < length / 2")
        if self.centre_circle_radius * 2 >= min(self.length, self.width):
            raise ConfigError("FieldConfig.centre_circle_radius does not fit in the field")

    @property
    def half_length(self) -> float:
        return self.length / 2.0

    @property
    def half_width(self) -> float:
        return self.width / 2.0


STANDARD_FIELD = FieldConfig()
"""The default field, rcssserver's pitch: the one :class:`soccer_sim.config.MatchConfig` plays
on by default, the built-in formations are designed for and rcssserver's flags stand on."""
