"""Impossible configurations are rejected with a ConfigError naming the field."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from soccer_sim import ConfigError, FieldConfig, MatchConfig, PhysicsConfig, RuleConfig, StaminaConfig, run_match


@pytest.mark.parametrize("make, fragment", [
    (lambda: FieldConfig(length=-105.0), "FieldConfig.length must be a positive"),
    (lambda: FieldConfig(width=0.0), "FieldConfig.width must be a positive"),
    (lambda: FieldConfig(goal_width=80.0), "goal_width"),
    (lambda: FieldConfig(penalty_area_length=60.0), "penalty_area_length"),
    (lambda: PhysicsConfig(player_radius=-0.3), "PhysicsConfig.player_radius"),
    (lambda: PhysicsConfig(ball_decay=1.5), "PhysicsConfig.ball_decay must be a positive number up to 1"),
    (lambda: PhysicsConfig(ball_decay=0.0), "PhysicsConfig.ball_decay must be a positive number up to 1"),
    (lambda: PhysicsConfig(player_mass=0.0), "PhysicsConfig.player_mass"),
    (lambda: PhysicsConfig(ball_restitution=2.0), "PhysicsConfig.ball_restitution"),
    (lambda: PhysicsConfig(max_substep_distance=5.0), "max_substep_distance"),
    (lambda: PhysicsConfig(player_speed_max=float("nan")), "player_speed_max"),
    (lambda: StaminaConfig(maximum=-1.0), "StaminaConfig.maximum"),
    (lambda: RuleConfig(half_cycles=0), "RuleConfig.half_cycles"),
    (lambda: RuleConfig(max_goal_kicks=-1), "RuleConfig.max_goal_kicks must be a non-negative integer"),
    (lambda: RuleConfig(proper_goal_kicks=1), "RuleConfig.proper_goal_kicks must be a bool"),
])
def test_impossible_parts_are_rejected(make, fragment: str) -> None:
    with pytest.raises(ConfigError, match=fragment):
        make().validate()


def test_match_config_validates_on_construction() -> None:
    with pytest.raises(ConfigError, match="players_per_team"):
        MatchConfig(players_per_team=0)
    with pytest.raises(ConfigError, match="goalie_index"):
        MatchConfig(players_per_team=3, rules=RuleConfig(goalie_index=5))
    with pytest.raises(ConfigError, match="max_cycles"):
        MatchConfig(max_cycles=-4)
    with pytest.raises(ConfigError, match="goal_width"):
        replace(MatchConfig(), field=replace(FieldConfig(), goal_width=70.0))


def test_small_valid_configs_play() -> None:
    config = MatchConfig(players_per_team=3, max_cycles=200,
                         field=FieldConfig(length=40.0, width=25.0, goal_width=5.0, penalty_area_length=8.0,
                                           penalty_area_width=15.0, goal_area_length=3.0, goal_area_width=8.0,
                                           centre_circle_radius=4.0))
    result = run_match("chaser", "chaser", seed=2, config=config)
    assert result.state.pos.shape == (6, 2)
    assert result.cycles == 200


def test_parts_of_the_wrong_type_are_named() -> None:
    with pytest.raises(ConfigError, match="MatchConfig.field must be a FieldConfig, got dict"):
        MatchConfig(field={"length": 100.0})
    with pytest.raises(ConfigError, match="MatchConfig.rules must be a RuleConfig, got PhysicsConfig"):
        MatchConfig(rules=PhysicsConfig())


def test_numpy_numbers_are_accepted_and_bools_are_not() -> None:
    config = MatchConfig(max_cycles=np.int64(50), rules=RuleConfig(half_cycles=np.int32(25)))
    assert config.total_cycles == 50
    assert PhysicsConfig(ball_decay=np.float32(0.9)).ball_decay == pytest.approx(0.9)
    with pytest.raises(ConfigError, match="max_cycles"):
        MatchConfig(max_cycles=True)
    with pytest.raises(ConfigError, match="player_radius"):
        MatchConfig(physics=PhysicsConfig(player_radius=True))


def test_cycles_per_minute_follow_the_cycle_length() -> None:
    assert PhysicsConfig().cycles_per_minute == 600.0
    assert PhysicsConfig(cycle_seconds=0.05).cycles_per_minute == 1200.0
    assert PhysicsConfig(cycle_seconds=0.2).cycles_per_minute == 300.0
