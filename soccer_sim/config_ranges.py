"""The allowed range of every number of the match configuration: one table, :data:`FIELD_RANGES`.

Each configuration dataclass checks its fields against this table when it is constructed
(:func:`check_ranges`), so a value that would break the physics (a field 1e308 m long makes
pymunk's spatial hash spin; a ball 1e308 m wide makes every dash NaN) is refused at once with
a :class:`~soccer_sim.config_checks.ConfigError` naming the field, before any match.

The ranges are wide: they accept every value rcssserver 19 sends in its ``server_param`` and
``player_type`` messages (its defaults and every heterogeneous type it can draw), and
everything between a toy pitch and one ten times the regulation size. What they keep out is
what no simulation can run: non-finite numbers, sizes and speeds many orders of magnitude
beyond the game, probabilities outside [0, 1]. Relations between fields (the goal narrower
than the field, the set-play clearance inside it, ...) are checked by the dataclasses
themselves. docs/limits.md lists the same table with units.

Units are the configuration's: metres, cycles, metres per cycle (m/cycle), m/cycle² and
rcssserver's power and stamina units.
"""

from __future__ import annotations

import math
import numbers
from dataclasses import dataclass

from soccer_sim.config_checks import ConfigError

MAX_HALF_CYCLES = 500_000
"""The longest half (cycles): a match of up to 1,000,000 cycles, ``soccer-sim``'s ``--cycles``."""


@dataclass(frozen=True)
class FieldRange:
    """The values one configuration field accepts: ``low`` to ``high`` inclusive (``low``
    excluded when ``low_open``), whole numbers only when ``integer``, also None when
    ``optional``. ``high`` may be infinite (a stamina capacity without limit)."""

    low: float
    high: float
    unit: str
    integer: bool = False
    low_open: bool = False
    optional: bool = False

    def contains(self, value: object) -> bool:
        """Whether ``value`` is an allowed value (bools are not numbers here)."""
        if value is None:
            return self.optional
        if isinstance(value, bool) or not isinstance(value, numbers.Integral if self.integer else numbers.Real):
            return False
        if (not isinstance(value, numbers.Integral) and math.isnan(value)) or value > self.high:
            return False  # (an integer is never NaN, and math.isnan overflows on a huge one)
        return value > self.low if self.low_open else value >= self.low

    def describe(self) -> str:
        """The range in words, e.g. ``a positive number up to 1000 (m)``."""
        unit = f" ({self.unit})" if self.unit else ""
        none = "None or " if self.optional else ""
        if self.integer:
            kind = {0: "a non-negative integer", 1: "a positive integer"}.get(self.low, f"an integer from {self.low}")
            return f"{none}{kind} up to {self.high:,}{unit}"
        if math.isinf(self.high):
            return f"{none}a number >= {self.low:g}{unit}"
        if self.low == 0 and self.low_open:
            return f"{none}a positive number up to {self.high:g}{unit}"
        opening = "(" if self.low_open else "["
        return f"{none}within {opening}{self.low:g}, {self.high:g}]{unit}"


def _length(high: float = 1000.0, *, positive: bool = True) -> FieldRange:
    return FieldRange(0.0, high, "m", low_open=positive)


def _fraction(unit: str = "") -> FieldRange:
    return FieldRange(0.0, 1.0, unit)


def _cycles(high: int = 1_000_000, low: int = 0, *, optional: bool = False) -> FieldRange:
    return FieldRange(low, high, "cycles", integer=True, optional=optional)


def _positive(high: float, unit: str) -> FieldRange:
    return FieldRange(0.0, high, unit, low_open=True)


def _non_negative(high: float, unit: str) -> FieldRange:
    return FieldRange(0.0, high, unit)


_PLAYER_TYPE_NUMBER = FieldRange(-1e6, 1e6, "")
"""A delta or trade-off factor of the player types (rcssserver's lie within ±6000)."""

FIELD_RANGES: dict[str, dict[str, FieldRange]] = {
    "FieldConfig": {name: _length() for name in (
        "length", "width", "goal_width", "goal_post_radius", "penalty_area_length", "penalty_area_width",
        "goal_area_length", "goal_area_width", "centre_circle_radius", "margin")},
    "PhysicsConfig": {
        "cycle_seconds": _positive(10.0, "s"),
        "player_radius": _length(10.0),
        "ball_radius": _length(10.0),
        "player_speed_max": _positive(100.0, "m/cycle"),
        "dash_power_max": _positive(10_000.0, "power"),
        "dash_power_rate": _positive(1.0, "m/cycle² per power"),
        "side_dash_rate": _fraction(),
        "back_dash_rate": _fraction(),
        "dash_heading_speed": _positive(100.0, "m/cycle"),
        "player_decay": _fraction("per cycle"),
        "ball_decay": FieldRange(0.0, 1.0, "per cycle", low_open=True),  # (the kick noise divides by it)
        "ball_speed_max": _positive(100.0, "m/cycle"),
        "kick_speed_max": _positive(100.0, "m/cycle"),
        "kickable_margin": _length(10.0),
        "kick_distance_penalty": _fraction(),
        "kick_angle_penalty": _fraction(),
        "inertia_moment": _positive(1000.0, ""),
        "player_rand": _fraction(),
        "ball_rand": _fraction(),
        "kick_rand": _fraction(),
        "player_mass": _positive(1e6, "kg"),
        "ball_mass": _positive(1e6, "kg"),
        "player_restitution": _fraction(),
        "ball_restitution": _fraction(),
        "collision_velocity_factor": FieldRange(-1.0, 0.0, ""),
        "max_substep_distance": FieldRange(0.001, 10.0, "m"),
    },
    "StaminaConfig": {
        "maximum": _positive(1e6, "stamina"),
        "recovery_per_cycle": _non_negative(1e6, "stamina per cycle"),
        "extra_stamina": _non_negative(1e6, "power"),
        "capacity": FieldRange(0.0, math.inf, "stamina per half", optional=True),
        "recover_dec_thr": _fraction("of maximum"),
        "recover_dec": _fraction("per cycle"),
        "recover_min": _fraction(),
        "effort_dec_thr": _fraction("of maximum"),
        "effort_dec": _fraction("per cycle"),
        "effort_min": _fraction(),
        "effort_inc_thr": _fraction("of maximum"),
        "effort_inc": _fraction("per cycle"),
        "effort_max": _fraction(),
    },
    "RuleConfig": {
        "half_cycles": _cycles(MAX_HALF_CYCLES, 1),
        "offside_active_distance": FieldRange(0.0, 1000.0, "m", low_open=True, optional=True),
        "set_play_clearance": _length(),
        "set_play_timeout": _cycles(low=1),
        "catch_length": _length(100.0),
        "catch_width": _length(100.0),
        "catch_ban_cycles": _cycles(),
        "goalie_max_moves": FieldRange(-1, 1_000_000, "moves", integer=True),
        "goalie_index": FieldRange(0, 1000, "player", integer=True),
        "goal_pause_cycles": _cycles(),
        "corner_inset": _length(positive=False),
        "stuck_ball_radius": _length(),
        "stuck_ball_cycles": _cycles(low=1, optional=True),
        "max_goal_kicks": FieldRange(0, 1000, "retakes", integer=True),
    },
    "TackleConfig": {
        "tackle_dist": _length(100.0),
        "tackle_back_dist": _length(100.0, positive=False),
        "tackle_width": _length(100.0),
        "tackle_exponent": _positive(1000.0, ""),
        "tackle_cycles": _cycles(),
        "tackle_power_rate": _non_negative(1.0, "m/cycle² per power"),
        "max_tackle_power": _non_negative(10_000.0, "power"),
        "max_back_tackle_power": _non_negative(10_000.0, "power"),
        "tackle_rand_factor": _non_negative(1000.0, ""),
        "foul_exponent": _positive(1000.0, ""),
        "foul_detect_probability": _fraction(),
        "foul_cycles": _cycles(),
        "red_card_probability": _fraction(),
    },
    "PlayerTypeConfig": {
        "types": FieldRange(1, 1000, "types", integer=True),
        "pt_max": FieldRange(1, 1000, "players", integer=True),
        "max_trials": FieldRange(1, 1_000_000, "draws", integer=True),
        "player_speed_max_min": _non_negative(100.0, "m/cycle"),
        **{name: _PLAYER_TYPE_NUMBER for name in (
            "player_speed_max_delta_min", "player_speed_max_delta_max", "stamina_inc_max_delta_factor",
            "player_decay_delta_min", "player_decay_delta_max", "inertia_moment_delta_factor",
            "dash_power_rate_delta_min", "dash_power_rate_delta_max", "player_size_delta_factor",
            "new_dash_power_rate_delta_min", "new_dash_power_rate_delta_max", "new_stamina_inc_max_delta_factor",
            "kickable_margin_delta_min", "kickable_margin_delta_max", "kick_rand_delta_factor",
            "extra_stamina_delta_min", "extra_stamina_delta_max", "effort_max_delta_factor",
            "effort_min_delta_factor", "kick_power_rate_delta_min", "kick_power_rate_delta_max",
            "foul_detect_probability_delta_factor", "catchable_area_l_stretch_min",
            "catchable_area_l_stretch_max")},
    },
    "SeeParams": {
        "visible_angle": FieldRange(0.0, 360.0, "degrees", low_open=True),
        "visible_distance": _length(positive=False),
        # 0: no quantisation (exact), SeeParams.without_noise
        "quantize_step": FieldRange(0.0, 10.0, ""),
        "quantize_step_l": FieldRange(0.0, 10.0, ""),
        "distance_step": _length(100.0, positive=False),
        "direction_step": FieldRange(0.0, 180.0, "degrees"),
        **{name: _length(10_000.0) for name in ("unum_far_length", "unum_too_far_length", "team_far_length",
                                                "team_too_far_length", "max_observation_length")},
        "min_neck_angle": FieldRange(-180.0, 0.0, "degrees"),
        "max_neck_angle": FieldRange(0.0, 180.0, "degrees"),
        "min_neck_moment": FieldRange(-360.0, 0.0, "degrees"),
        "max_neck_moment": FieldRange(0.0, 360.0, "degrees"),
        "send_step": FieldRange(1, 60_000, "ms", integer=True),
        "simulator_step": FieldRange(1, 60_000, "ms", integer=True),
    },
    "AudioParams": {
        "say_msg_size": FieldRange(1, 8_192, "characters", integer=True),
        "audio_cut_dist": _length(10_000.0, positive=False),
        "hear_max": FieldRange(0, 1_000, "messages", integer=True),
        "hear_inc": FieldRange(0, 1_000, "messages", integer=True),
        "hear_decay": FieldRange(0, 1_000, "messages", integer=True),
    },
    "MatchConfig": {
        "players_per_team": FieldRange(1, 50, "players", integer=True),
        "max_cycles": _cycles(2 * MAX_HALF_CYCLES, 1, optional=True),
    },
}
"""The range of every numeric field, by dataclass name and field name."""


def check_ranges(config: object) -> None:
    """ConfigError naming the first numeric field of ``config`` (a configuration dataclass)
    outside its range in :data:`FIELD_RANGES`."""
    owner = type(config).__name__
    for name, allowed in FIELD_RANGES[owner].items():
        value = getattr(config, name)
        if not allowed.contains(value):
            raise ConfigError(f"{owner}.{name} must be {allowed.describe()}, got {_shown(value)}")


def _shown(value: object, longest: int = 40) -> str:
    """``value``'s repr for an error line, cut short (a huge integer has hundreds of digits)."""
    text = repr(value)
    return text if len(text) <= longest else f"{text[:longest - 12]}... ({len(text)} characters)"
