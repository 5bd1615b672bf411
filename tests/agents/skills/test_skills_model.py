"""The motion model's tables and helpers follow the configuration's numbers."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from agents.skills import MotionModel, SkillContext
from soccer_sim import MatchConfig
from soccer_sim.config import FieldConfig, PhysicsConfig
from tests.agents.skills.skill_views import CONFIG, HL, ball_at

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)


def test_ball_path_and_travel_follow_the_decay() -> None:
    path = MODEL.ball_path(np.array([1.0, 2.0]), np.array([2.0, -1.0]), 30)
    for k in (0, 1, 7, 30):
        assert path[k] == pytest.approx(ball_at(CONFIG, (1.0, 2.0), (2.0, -1.0), k))
    assert len(MODEL.ball_path(np.zeros(2), np.ones(2), 90)) == 91  # beyond the horizon too


def test_ball_speed_and_cycles_are_inverse() -> None:
    speed = MODEL.ball_speed_for(20.0, 0.8)
    assert speed == pytest.approx(20.0 * 0.06 + 0.8)
    cycles = float(MODEL.ball_cycles_to(20.0, speed))
    assert np.linalg.norm(ball_at(CONFIG, (0, 0), (speed, 0), int(np.ceil(cycles)))) >= 20.0
    assert np.linalg.norm(ball_at(CONFIG, (0, 0), (speed, 0), int(np.ceil(cycles)) - 1)) < 20.0
    assert np.isinf(MODEL.ball_cycles_to(50.0, 2.0))  # 2 m/cycle rolls 33.3 m at most


def test_every_number_comes_from_the_config() -> None:
    physics = replace(PhysicsConfig(), dash_power_rate=0.004, player_decay=0.5, ball_decay=0.9)
    field = replace(FieldConfig(), length=90.0, goal_width=10.0)
    model = MotionModel.even_sides(replace(MatchConfig(), physics=physics, field=field))
    assert model.accel_max == pytest.approx(0.4)
    assert model.top_speed == pytest.approx(0.8)
    assert model.reach[1:3] == pytest.approx([0.4, 0.4 + 0.6])
    assert model.ball_travel[2] == pytest.approx(1.9)
    assert model.goal_centre(ours=True)[0] == -45.0 and model.goal_half_width == 5.0
    assert model.sustainable_speed(1.0) == pytest.approx(45.0 * 0.004 / 0.5)


def test_field_geometry_helpers() -> None:
    assert MODEL.in_penalty_area(np.array([-HL + 10.0, 15.0]))
    assert not MODEL.in_penalty_area(np.array([-HL + 10.0, 15.0]), ours=False)
    assert MODEL.in_penalty_area(np.array([HL - 16.5, -20.16]), ours=False)  # lines included
    assert not MODEL.in_field(np.array([HL + 0.1, 0.0]))
    assert MODEL.clamp_to_field(np.array([[60.0, -40.0]]), 1.0).tolist() == [[HL - 1.0, -33.0]]


@pytest.mark.parametrize("gap, cycles", [(0.0, 8), (0.6, 4)])
def test_kick_spread_matches_the_simulators_noise(gap, cycles) -> None:
    """The spread the shots are planned with is the simulator's: kicks of a ball at rest ``gap``
    from the kicker's surface, rolled ``cycles`` cycles with rcssserver's kick and ball noise on,
    scatter across their line with the standard deviation kick_spread predicts (400 draws: the
    estimate's relative standard error is about 3.5 %)."""
    from tests.soccer_sim.probe_rig import Rig, kick_full, probe_config
    config = probe_config(noise=True)
    model = MotionModel.even_sides(config)
    touch = config.physics.player_radius + config.physics.ball_radius
    across, speeds = [], []
    for seed in range(400):
        rig = Rig(config, seed=seed)
        rig.state.pos[0] = (-30.0, 0.0)
        rig.state.ball[:] = (-30.0 + touch + gap, 0.0)
        rig.cycle(kick=kick_full())
        speeds.append(float(np.hypot(*rig.state.ball_vel)) / config.physics.ball_decay)
        for _ in range(cycles - 1):
            rig.cycle()
        across.append(float(rig.state.ball[1]))
    launch = float(np.mean(speeds))
    predicted = float(model.kick_spread(gap, 0.0, config.physics.kick_speed_max, launch, cycles))
    assert np.std(across) == pytest.approx(predicted, rel=0.12)
    # Without noise there is no spread; a faster ball before the kick, or one lying off the
    # direction the body faces, spreads more.
    quiet = MotionModel.even_sides(probe_config(noise=False))
    assert float(quiet.kick_spread(gap, 0.0, 2.7, launch, cycles)) == 0.0
    assert model.kick_spread(gap, 2.0, 2.7, launch, cycles) > predicted
    assert model.kick_spread(gap, 0.0, 2.7, launch, cycles, np.pi / 2) > predicted
