"""Every physical and rule parameter of a match, in one place.

Defaults follow the RoboCup 2D soccer simulator's server parameters where one
exists. Units: metres, cycles (one cycle = ``cycle_seconds`` of game time),
metres per cycle for speeds and metres per cycle² for accelerations. The
absolute frame has its origin at the centre spot, x along the length of the
field (towards the right-hand goal) and y across it.

All configs are frozen dataclasses; :func:`MatchConfig.validate` (called on
construction) rejects impossible values with a message naming the field.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass, fields
from dataclasses import field as default_of


class ConfigError(ValueError):
    """A configuration value is impossible (negative size, goal wider than the field, ...)."""


def _is_integer(value: object) -> bool:
    """True for Python and numpy integers (not bools)."""
    return isinstance(value, numbers.Integral) and not isinstance(value, bool)


def _is_real(value: object) -> bool:
    """True for Python and numpy real numbers (not bools)."""
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def _require_positive(owner: object, *names: str) -> None:
    for name in names:
        value = getattr(owner, name)
        if not (_is_real(value) and math.isfinite(value) and value > 0):
            raise ConfigError(f"{type(owner).__name__}.{name} must be a positive finite number, got {value!r}")


def _require_fraction(owner: object, *names: str) -> None:
    for name in names:
        value = getattr(owner, name)
        if not (_is_real(value) and 0.0 <= value <= 1.0):
            raise ConfigError(f"{type(owner).__name__}.{name} must be within [0, 1], got {value!r}")


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

    def validate(self) -> None:
        _require_positive(self, *(f.name for f in fields(self)))
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


@dataclass(frozen=True)
class PhysicsConfig:
    """Bodies, motion limits, kicking and noise."""

    cycle_seconds: float = 0.1
    """Game time of one simulation cycle (s)."""
    player_radius: float = 0.3
    ball_radius: float = 0.085
    player_speed_max: float = 1.05
    """Largest player speed (m/cycle)."""
    player_accel_max: float = 1.0
    """Largest dash acceleration with full stamina (m/cycle²)."""
    player_decay: float = 0.4
    """Fraction of a player's velocity kept from one cycle to the next."""
    ball_decay: float = 0.94
    """Fraction of the ball's velocity kept from one cycle to the next."""
    ball_speed_max: float = 3.0
    """Largest ball speed (m/cycle)."""
    kick_speed_max: float = 2.7
    """Largest velocity change one kick can give the ball (m/cycle), before effectiveness."""
    kickable_margin: float = 0.7
    """The ball is kickable when its surface is within this distance of the player's surface (m)."""
    kick_distance_penalty: float = 0.25
    """Kick effectiveness lost when the ball is at the far edge of the kickable margin."""
    kick_angle_penalty: float = 0.25
    """Kick effectiveness lost when kicking the ball straight back through the player (180°)."""
    player_noise: float = 0.05
    """Uniform movement noise per axis, as a fraction of the player's speed."""
    ball_noise: float = 0.05
    """Uniform ball-movement noise per axis, as a fraction of the ball's speed."""
    kick_noise: float = 0.05
    """Uniform kick noise per axis, as a fraction of the kick's velocity change."""
    player_mass: float = 70.0
    """Mass of a player's body (kg); only the ratio to ``ball_mass`` matters in collisions."""
    ball_mass: float = 0.43
    """Mass of the ball (kg)."""
    player_restitution: float = 0.2
    """Bounciness of a player's body in collisions (0: dead stop, 1: perfectly elastic). The
    restitution of a contact is the product of the two bodies' values."""
    ball_restitution: float = 0.8
    """Bounciness of the ball; goal posts are perfectly elastic, so the ball keeps this fraction
    of its normal speed off a post and ``ball_restitution * player_restitution`` off a player."""
    max_substep_distance: float = 0.3
    """Physics sub-steps are added until no body moves further than this in one sub-step (m),
    so that a full-speed ball cannot pass through a player. Motion is measured relative to the
    bodies it could meet in the cycle (see soccer_sim.physics.SubstepPlanner): a body far from
    everything cannot pass through anything, whatever its speed."""

    def validate(self) -> None:
        _require_positive(
            self, "cycle_seconds", "player_radius", "ball_radius", "player_speed_max", "player_accel_max",
            "ball_speed_max", "kick_speed_max", "kickable_margin", "max_substep_distance",
            "player_mass", "ball_mass",
        )
        _require_fraction(
            self, "player_decay", "ball_decay", "kick_distance_penalty", "kick_angle_penalty",
            "player_noise", "ball_noise", "kick_noise", "player_restitution", "ball_restitution",
        )
        if self.max_substep_distance > 2 * self.ball_radius + 2 * self.player_radius:
            raise ConfigError("PhysicsConfig.max_substep_distance must not exceed the ball-player contact diameter")

    @property
    def kickable_distance(self) -> float:
        """Centre-to-centre distance within which a player can kick the ball (m)."""
        return self.player_radius + self.ball_radius + self.kickable_margin


@dataclass(frozen=True)
class StaminaConfig:
    """Stamina: dashing drains it, it recovers every cycle, and low stamina weakens acceleration.

    Dashing at acceleration ``a`` (m/cycle²) costs ``a * cost_per_accel`` stamina, so a
    full-strength dash costs 100 units, like a full-power dash in the RoboCup simulator.
    """

    maximum: float = 8000.0
    recovery_per_cycle: float = 45.0
    cost_per_accel: float = 100.0
    tired_fraction: float = 0.25
    """Below this fraction of ``maximum`` the acceleration limit shrinks in proportion."""
    min_effort: float = 0.3
    """Acceleration limit, as a fraction of the full one, when stamina is empty."""

    def validate(self) -> None:
        _require_positive(self, "maximum", "cost_per_accel")
        if not (self.recovery_per_cycle >= 0):
            raise ConfigError(f"StaminaConfig.recovery_per_cycle must be >= 0, got {self.recovery_per_cycle!r}")
        _require_fraction(self, "tired_fraction", "min_effort")


@dataclass(frozen=True)
class RuleConfig:
    """The referee's rules and time limits (cycles)."""

    half_cycles: int = 3000
    """Length of one half; a match is two halves and the teams swap ends at half time."""
    offside: bool = True
    """Whether the offside rule is enforced."""
    offside_active_distance: float = 2.5
    """A player in an offside position is penalised when it comes this close to the ball (m)."""
    set_play_clearance: float = 9.15
    """Opponents are kept at least this far from the ball at set plays (m)."""
    set_play_timeout: int = 100
    """A set play not taken within this many cycles is restarted by dropping the ball."""
    catch_length: float = 1.2
    """Length of the goalkeeper's catchable area, measured from the goalkeeper towards the ball (m)."""
    catch_width: float = 1.0
    """Width of the goalkeeper's catchable area (m)."""
    catch_ban_cycles: int = 5
    """Cycles after a catch attempt during which the goalkeeper cannot try again."""
    goalie_hold_cycles: int = 60
    """The goalkeeper must release a caught ball within this many cycles, or the opponents
    get an indirect free kick."""
    goalie_index: int = 0
    """Index (within its team, 0-based) of each team's goalkeeper; shirt number 1."""

    def validate(self) -> None:
        for name in ("half_cycles", "set_play_timeout", "goalie_hold_cycles"):
            value = getattr(self, name)
            if not (_is_integer(value) and value > 0):
                raise ConfigError(f"RuleConfig.{name} must be a positive integer, got {value!r}")
        if not (_is_integer(self.catch_ban_cycles) and self.catch_ban_cycles >= 0):
            raise ConfigError(f"RuleConfig.catch_ban_cycles must be a non-negative integer, got {self.catch_ban_cycles!r}")
        _require_positive(self, "offside_active_distance", "set_play_clearance", "catch_length", "catch_width")
        if not (_is_integer(self.goalie_index) and 0 <= self.goalie_index):
            raise ConfigError(f"RuleConfig.goalie_index must be a non-negative integer, got {self.goalie_index!r}")


@dataclass(frozen=True)
class MatchConfig:
    """Everything that, with the two teams and the seed, determines a match."""

    field: FieldConfig = default_of(default_factory=FieldConfig)
    physics: PhysicsConfig = default_of(default_factory=PhysicsConfig)
    stamina: StaminaConfig = default_of(default_factory=StaminaConfig)
    rules: RuleConfig = default_of(default_factory=RuleConfig)
    players_per_team: int = 11
    max_cycles: int | None = None
    """Stop after this many cycles (None: two full halves)."""

    def __post_init__(self) -> None:
        self.validate()

    def validate(self) -> None:
        for name, kind in (("field", FieldConfig), ("physics", PhysicsConfig), ("stamina", StaminaConfig),
                           ("rules", RuleConfig)):
            part = getattr(self, name)
            if not isinstance(part, kind):
                raise ConfigError(f"MatchConfig.{name} must be a {kind.__name__}, got {type(part).__name__}")
            part.validate()
        if not (_is_integer(self.players_per_team) and 1 <= self.players_per_team):
            raise ConfigError(f"MatchConfig.players_per_team must be a positive integer, got {self.players_per_team!r}")
        if self.rules.goalie_index >= self.players_per_team:
            raise ConfigError("RuleConfig.goalie_index must index a player of the team")
        if self.max_cycles is not None and not (_is_integer(self.max_cycles) and self.max_cycles > 0):
            raise ConfigError(f"MatchConfig.max_cycles must be None or a positive integer, got {self.max_cycles!r}")

    @property
    def total_cycles(self) -> int:
        """Number of cycles the match lasts."""
        full = 2 * self.rules.half_cycles
        return full if self.max_cycles is None else min(full, self.max_cycles)
