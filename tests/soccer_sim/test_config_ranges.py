"""Every number of the configuration has a range (soccer_sim.config_ranges.FIELD_RANGES), checked
when a configuration dataclass is constructed, with the field named; the ranges accept every
value rcssserver 19's server_param and player_type messages carry."""

from __future__ import annotations

import dataclasses
import json
import math
from pathlib import Path

import pytest

from soccer_sim import run_match
from soccer_sim.config import (ConfigError, FieldConfig, MatchConfig, PhysicsConfig, PlayerTypeConfig, RuleConfig,
                               StaminaConfig, TackleConfig)
from soccer_sim.config_ranges import FIELD_RANGES
from soccer_sim.perception.audio import AudioParams
from soccer_sim.perception.params import SeeParams
from soccer_sim.player_types import PlayerType, draw_player_types
from soccer_sim.rcg.defaults import DEFAULT_PLAYER_TYPE, PLAYER_PARAMS, SERVER_PARAMS
from soccer_sim.rcg.params import PLAYER_TYPE_PARAMETERS, SERVER_PARAMETERS

RCSSSERVER_DATA = Path(__file__).resolve().parents[1] / "data" / "rcssserver"

CONFIGS = (FieldConfig, PhysicsConfig, StaminaConfig, RuleConfig, TackleConfig, PlayerTypeConfig, SeeParams, AudioParams,
           MatchConfig)


@pytest.mark.parametrize("make, message", [
    (lambda: FieldConfig(length=1e308), "FieldConfig.length must be a positive number up to 1000 (m), got 1e+308"),
    (lambda: FieldConfig(margin=float("inf")), "FieldConfig.margin must be a positive number up to 1000 (m)"),
    (lambda: RuleConfig(set_play_clearance=1e308), "RuleConfig.set_play_clearance must be a positive number up to 1000"),
    (lambda: RuleConfig(half_cycles=10**9), "RuleConfig.half_cycles must be a positive integer up to 500,000 (cycles)"),
    (lambda: RuleConfig(stuck_ball_radius=float("nan")), "RuleConfig.stuck_ball_radius must be a positive number"),
    (lambda: PhysicsConfig(ball_radius=1e308), "PhysicsConfig.ball_radius must be a positive number up to 10 (m)"),
    (lambda: PhysicsConfig(player_speed_max=1e308), "PhysicsConfig.player_speed_max must be a positive number up to 100"),
    (lambda: PhysicsConfig(dash_power_max=1e308), "PhysicsConfig.dash_power_max must be a positive number up to 10000"),
    (lambda: PhysicsConfig(max_substep_distance=1e-300), "PhysicsConfig.max_substep_distance must be within [0.001, 10]"),
    (lambda: PhysicsConfig(player_mass=1e308), "PhysicsConfig.player_mass must be a positive number up to 1e+06 (kg)"),
    (lambda: StaminaConfig(maximum=float("inf")), "StaminaConfig.maximum must be a positive number up to 1e+06"),
    (lambda: StaminaConfig(recover_dec=5.0), "StaminaConfig.recover_dec must be within [0, 1] (per cycle), got 5.0"),
    (lambda: StaminaConfig(capacity=float("nan")), "StaminaConfig.capacity must be None or a number >= 0"),
    (lambda: TackleConfig(tackle_dist=1e308), "TackleConfig.tackle_dist must be a positive number up to 100 (m)"),
    (lambda: TackleConfig(tackle_cycles=10**12), "TackleConfig.tackle_cycles must be a non-negative integer up to"),
    (lambda: PlayerTypeConfig(player_decay_delta_max=1e308), "PlayerTypeConfig.player_decay_delta_max must be within"),
    (lambda: PlayerTypeConfig(types=10**9), "PlayerTypeConfig.types must be a positive integer up to 1,000"),
    (lambda: MatchConfig(max_cycles=10**12), "MatchConfig.max_cycles must be None or a positive integer up to 1,000,000"),
    (lambda: MatchConfig(players_per_team=10**6), "MatchConfig.players_per_team must be a positive integer up to 50"),
    (lambda: MatchConfig(rules=RuleConfig(set_play_clearance=40.0)),
     "RuleConfig.set_play_clearance (40 m) must be less than half the field's smaller side (34 m)"),
    (lambda: MatchConfig(rules=RuleConfig(corner_inset=500.0)),
     "RuleConfig.corner_inset (500 m) must be less than half the field's smaller side (34 m)"),
])
def test_values_that_break_physics_are_refused_at_construction_naming_the_field(make, message) -> None:
    with pytest.raises(ConfigError) as refused:
        make()
    assert str(refused.value).startswith(message)
    assert "\n" not in str(refused.value)


def test_a_huge_field_never_reaches_the_physics() -> None:
    """run_match with a field 1e308 m long spun in pymunk's spatial hash; the configuration is
    refused before a match exists."""
    with pytest.raises(ConfigError, match="FieldConfig.length"):
        run_match("idle", "idle", config=MatchConfig(field=FieldConfig(length=1e308), max_cycles=2))


def test_every_numeric_field_has_a_range_and_every_range_a_field() -> None:
    for config in CONFIGS:
        numeric = {f.name for f in dataclasses.fields(config)
                   if str(f.type).split(" |")[0] in ("int", "float")}
        assert numeric == set(FIELD_RANGES[config.__name__]), config.__name__
    assert set(FIELD_RANGES) == {config.__name__ for config in CONFIGS}


def test_every_default_lies_in_its_range() -> None:
    for config in CONFIGS:
        default = config()
        for name, allowed in FIELD_RANGES[config.__name__].items():
            assert allowed.contains(getattr(default, name)), (config.__name__, name)


# ----------------------------------------------------------------- rcssserver's messages
def _number(text: str) -> float:
    return float(text)


SERVER_PARAM_FIELDS: dict[str, tuple[str, str]] = {
    "goal_width": ("field", "goal_width"), "ball_size": ("physics", "ball_radius"),
    "player_size": ("physics", "player_radius"), "player_speed_max": ("physics", "player_speed_max"),
    "maxpower": ("physics", "dash_power_max"), "dash_power_rate": ("physics", "dash_power_rate"),
    "side_dash_rate": ("physics", "side_dash_rate"), "back_dash_rate": ("physics", "back_dash_rate"),
    "player_decay": ("physics", "player_decay"), "ball_decay": ("physics", "ball_decay"),
    "ball_speed_max": ("physics", "ball_speed_max"), "ball_accel_max": ("physics", "kick_speed_max"),
    "kickable_margin": ("physics", "kickable_margin"), "player_rand": ("physics", "player_rand"),
    "ball_rand": ("physics", "ball_rand"), "kick_rand": ("physics", "kick_rand"),
    "inertia_moment": ("physics", "inertia_moment"),
    "stamina_max": ("stamina", "maximum"), "stamina_inc_max": ("stamina", "recovery_per_cycle"),
    "extra_stamina": ("stamina", "extra_stamina"), "stamina_capacity": ("stamina", "capacity"),
    "recover_dec_thr": ("stamina", "recover_dec_thr"), "recover_dec": ("stamina", "recover_dec"),
    "recover_min": ("stamina", "recover_min"), "effort_dec_thr": ("stamina", "effort_dec_thr"),
    "effort_dec": ("stamina", "effort_dec"), "effort_min": ("stamina", "effort_min"),
    "effort_inc_thr": ("stamina", "effort_inc_thr"), "effort_inc": ("stamina", "effort_inc"),
    "effort_init": ("stamina", "effort_max"),
    "use_offside": ("rules", "offside"), "offside_kick_margin": ("rules", "set_play_clearance"),
    "drop_ball_time": ("rules", "set_play_timeout"), "catchable_area_l": ("rules", "catch_length"),
    "catchable_area_w": ("rules", "catch_width"), "catch_ban_cycle": ("rules", "catch_ban_cycles"),
    "goalie_max_moves": ("rules", "goalie_max_moves"),
    "back_passes": ("rules", "back_pass_rule"), "ckick_margin": ("rules", "corner_inset"),
    "ball_stuck_area": ("rules", "stuck_ball_radius"), "proper_goal_kicks": ("rules", "proper_goal_kicks"),
    "max_goal_kicks": ("rules", "max_goal_kicks"), "player_speed_max_min": ("player_types", "player_speed_max_min"),
    **{name: ("tackles", name) for name in (
        "tackle_dist", "tackle_back_dist", "tackle_width", "tackle_exponent", "tackle_cycles", "tackle_power_rate",
        "max_tackle_power", "max_back_tackle_power", "tackle_rand_factor", "foul_exponent", "foul_detect_probability",
        "foul_cycles", "red_card_probability")},
}
"""rcssserver ``server_param`` name -> (section, field) of the configuration that takes it as it is."""

BOOLEAN = {"use_offside", "back_passes", "proper_goal_kicks"}
INTEGER = {"drop_ball_time", "catch_ban_cycle", "goalie_max_moves", "max_goal_kicks", "tackle_cycles", "foul_cycles"}


def config_from_server_param(values: dict[str, str], player_params: dict[str, str]) -> MatchConfig:
    """The configuration that rcssserver's server_param and player_param values describe (as a
    bridge to the real server builds it): each value as it is, ``half_time`` (seconds) and
    ``simulator_step`` (ms) in cycles, a negative ``stamina_capacity`` as no limit."""
    sections: dict[str, dict[str, object]] = {name: {} for name in ("field", "physics", "stamina", "rules",
                                                                    "tackles", "player_types")}
    for name, (section, field) in SERVER_PARAM_FIELDS.items():
        text = values[name]
        value: object = (text == "1") if name in BOOLEAN else int(text) if name in INTEGER else _number(text)
        sections[section][field] = value
    if sections["stamina"]["capacity"] < 0:
        sections["stamina"]["capacity"] = None
    step = _number(values["simulator_step"]) / 1000.0
    sections["physics"]["cycle_seconds"] = step
    sections["rules"]["half_cycles"] = round(_number(values["half_time"]) / step)
    for name in (f.name for f in dataclasses.fields(PlayerTypeConfig)):
        if name in player_params:
            sections["player_types"][name] = _number(player_params[name])
    sections["player_types"]["types"] = int(player_params["player_types"])
    sections["player_types"]["pt_max"] = int(player_params["pt_max"])
    return MatchConfig(field=FieldConfig(**sections["field"]), physics=PhysicsConfig(**sections["physics"]),
                       stamina=StaminaConfig(**sections["stamina"]), rules=RuleConfig(**sections["rules"]),
                       tackles=TackleConfig(**sections["tackles"]),
                       player_types=PlayerTypeConfig(**sections["player_types"]))


def test_rcssservers_default_server_param_and_player_param_make_a_configuration() -> None:
    config = config_from_server_param(dict(SERVER_PARAMS), dict(PLAYER_PARAMS))
    server = dict(SERVER_PARAMS)
    for name in SERVER_PARAMETERS.keys() & SERVER_PARAM_FIELDS.keys():      # the mapping is the log's, inverted
        assert float(SERVER_PARAMETERS[name](config)) == pytest.approx(_number(server[name])), name
    assert config.rules.half_cycles == 3000 and config.physics.cycle_seconds == 0.1


def test_the_recorded_server_parameters_make_configurations() -> None:
    """The server settings the recorded rcssserver probes ran with (noise off, referee on, ...)."""
    settings = []
    for probe in ("contact", "dash", "kick", "noise", "tackle"):
        settings += json.loads((RCSSSERVER_DATA / f"{probe}.json").read_text())["meta"]["server_parameters"].values()
    assert len(settings) >= 6
    for changed in settings:
        values = dict(SERVER_PARAMS) | {name: str(int(value) if isinstance(value, bool) else value)
                                        for name, value in changed.items() if name in SERVER_PARAM_FIELDS}
        config_from_server_param(values, dict(PLAYER_PARAMS))


def with_player_type(config: MatchConfig, kind: PlayerType) -> MatchConfig:
    """``config`` whose default player is of type ``kind`` (every player_type field it carries)."""
    physics = dataclasses.replace(
        config.physics, player_speed_max=kind.player_speed_max, player_decay=kind.player_decay,
        inertia_moment=kind.inertia_moment, dash_power_rate=kind.dash_power_rate, player_radius=kind.player_size,
        kickable_margin=kind.kickable_margin, kick_rand=kind.kick_rand,
        kick_speed_max=kind.kick_power_rate * config.physics.dash_power_max)
    stamina = dataclasses.replace(config.stamina, recovery_per_cycle=kind.stamina_inc_max,
                                  extra_stamina=kind.extra_stamina, effort_max=kind.effort_max,
                                  effort_min=kind.effort_min)
    rules = dataclasses.replace(config.rules, catch_length=config.rules.catch_length * kind.catchable_area_l_stretch)
    tackles = dataclasses.replace(config.tackles, foul_detect_probability=kind.foul_detect_probability)
    return dataclasses.replace(config, physics=physics, stamina=stamina, rules=rules, tackles=tackles)


def test_every_player_type_rcssserver_draws_makes_a_configuration() -> None:
    """The 17 drawn types of many seeds, and rcssserver's default type as its log lists it."""
    config = config_from_server_param(dict(SERVER_PARAMS), dict(PLAYER_PARAMS))
    default = {name: _number(value) for name, value in DEFAULT_PLAYER_TYPE if name in PlayerType.__dataclass_fields__}
    kinds = [PlayerType(**default)]
    for seed in range(60):
        kinds += draw_player_types(config, seed)[1:]
    assert len({k.player_decay for k in kinds}) > 500
    for kind in kinds:
        with_player_type(config, kind)


def test_the_extremes_of_rcssservers_player_type_ranges_make_configurations() -> None:
    """Each player_type parameter at both ends of the range rcssserver draws it from (its
    default plus the player_param delta range times the trade-off factor)."""
    config = config_from_server_param(dict(SERVER_PARAMS), dict(PLAYER_PARAMS))
    pt = config.player_types
    base = draw_player_types(config, 0)[0]
    for end in ("min", "max"):
        def delta(name: str, end: str = end) -> float:
            return getattr(pt, f"{name}_delta_{end}")

        kind = dataclasses.replace(
            base, player_decay=base.player_decay + delta("player_decay"),
            inertia_moment=base.inertia_moment + delta("player_decay") * pt.inertia_moment_delta_factor,
            dash_power_rate=base.dash_power_rate + delta("new_dash_power_rate"),
            stamina_inc_max=base.stamina_inc_max + delta("new_dash_power_rate") * pt.new_stamina_inc_max_delta_factor,
            kickable_margin=base.kickable_margin + delta("kickable_margin"),
            kick_rand=base.kick_rand + delta("kickable_margin") * pt.kick_rand_delta_factor,
            extra_stamina=base.extra_stamina + delta("extra_stamina"),
            effort_max=base.effort_max + delta("extra_stamina") * pt.effort_max_delta_factor,
            effort_min=base.effort_min + delta("extra_stamina") * pt.effort_min_delta_factor,
            catchable_area_l_stretch=getattr(pt, f"catchable_area_l_stretch_{end}"))
        with_player_type(config, kind)


def test_an_unlimited_stamina_capacity_stays_allowed() -> None:
    assert StaminaConfig(capacity=None).capacity_or_inf == math.inf
    assert StaminaConfig(capacity=math.inf).capacity_or_inf == math.inf


def test_docs_list_every_field_range() -> None:
    """docs/limits.md has a row for every field of the table, under its dataclass."""
    text = (Path(__file__).resolve().parents[2] / "docs" / "limits.md").read_text()
    for owner, rows in FIELD_RANGES.items():
        section = text.split(f"### {owner}\n", 1)[1].split("###", 1)[0]
        for name, allowed in rows.items():
            line = next((line for line in section.splitlines() if line.startswith(f"| `{name}` |")), None)
            assert line is not None, (owner, name)
            high = f"{allowed.high:,}" if allowed.integer else ("inf" if math.isinf(allowed.high) else f"{allowed.high:,g}")
            assert high in line and (allowed.unit or "-") in line, line


@pytest.mark.parametrize("make, message", [
    (lambda: AudioParams(say_msg_size=10**18), "AudioParams.say_msg_size must be a positive integer up to 8,192"),
    (lambda: SeeParams(visible_distance=1e308), r"SeeParams.visible_distance must be within \[0, 1000\] \(m\)"),
    (lambda: SeeParams(send_step=10**12), "SeeParams.send_step must be a positive integer up to 60,000"),
    (lambda: AudioParams(hear_max=10**9), "AudioParams.hear_max"),
])
def test_the_partial_observation_parameters_have_ranges_too(make, message) -> None:
    with pytest.raises(ConfigError, match=message):
        make()
