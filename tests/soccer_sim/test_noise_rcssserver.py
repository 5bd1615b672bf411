"""Noise with rcssserver's formulas: movement noise of length uniform in ``[0, rand * speed]``
in a uniform direction (``player_rand`` 0.1, ``ball_rand`` 0.05), and kick noise that grows
with the ball's distance, its angle to the body, its speed and the kick's power (``kick_rand``
0.1). Exact checks with chosen draws, then statistics with fixed seeds against rcssserver 19's
traces with its default noise (``tests/data/rcssserver/noise.json``: 200 kicks of each ball
place, 20 start phases of the contact probes; the tolerances allow for both sample sizes). The
sideways drift of a sprint and balls launched at a standing player with noise are compared in
``test_rcssserver_reference.py``, from the same file."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from tests.soccer_sim.probe_rig import (ROWS, Rig, dash_power, direction_degrees, first_step_of_a_kick, kick_once,
                                        probe_config, run_at_a_still_ball)

from soccer_sim.config import PhysicsConfig
from soccer_sim.kinematics import Kinematics

PHYS = PhysicsConfig()
TOUCH = PHYS.player_radius + PHYS.ball_radius
REAL = json.loads((Path(__file__).parents[1] / "data" / "rcssserver" / "noise.json").read_text())
"""rcssserver 19's traces with noise (what each figure means: its ``meta``)."""


def server_kick_statistics(place: str) -> tuple[float, float]:
    """The server's standard deviations of a full kick's first-cycle speed (m/cycle) and
    direction (°) with its default noise, the ball at rest ``place`` ("near": touching, "far":
    farthest kickable) in front."""
    steps = np.array(REAL["kick_default_noise"][place])
    return float(np.std(np.hypot(*steps.T))), float(np.std(np.degrees(np.arctan2(steps[:, 1], steps[:, 0]))))


def top_noise(angle_draw: float = 0.5) -> np.ndarray:
    """Kick noise draws at the top of the length range, direction ``(2 * draw - 1) * 180°``."""
    noise = np.zeros((ROWS, 2))
    noise[:, 0] = 1.0
    noise[:, 1] = angle_draw
    return noise


@pytest.mark.parametrize("offset, player_vel, rate", [
    ((TOUCH, 0.0), (0.0, 0.0), 0.5),                      # touching, at rest: pos_rate 0.5
    ((PHYS.kickable_distance, 0.0), (0.0, 0.0), 0.75),    # farthest: + 0.25
    ((-TOUCH, 0.0), (1.0, 0.0), 0.5 + 0.25 * 150 / 180),  # behind a sprinter: 150° off the body
])
def test_kick_noise_grows_with_the_balls_distance_and_angle(offset, player_vel, rate) -> None:
    config = probe_config(noise=True)
    _, quiet = kick_once(offset, (1.35, 0.0), player_vel=player_vel, config=config, noise=np.zeros((ROWS, 2)))
    _, noisy = kick_once(offset, (1.35, 0.0), player_vel=player_vel, config=config, noise=top_noise(0.75))
    # Largest length: kick_rand x power / 100 x (pos_rate + speed_rate 0.5), here along +y.
    assert noisy - quiet == pytest.approx((0.0, PHYS.kick_rand * 0.5 * (rate + 0.5)))


def test_kick_noise_grows_with_the_balls_speed_and_the_kicks_power() -> None:
    config = probe_config(noise=True)
    kin = Kinematics(config, ROWS)
    pos, vel = np.full((ROWS, 2), 40.0), np.zeros((ROWS, 2))
    pos[0] = (-TOUCH, 0.0)
    dist = np.hypot(*pos.T)
    for ball_speed, power, expected in ((2.82, 1.35, 0.1 * 0.5 * (0.5 + 1.0)), (0.0, 1.35, 0.1 * 0.5 * 1.0),
                                        (0.0, 0.675, 0.1 * 0.25 * 1.0)):
        kick = np.zeros((ROWS, 2))
        kick[0] = (0.0, -power)
        moved = []
        for noise in (np.zeros((ROWS, 2)), top_noise(1.0)):  # top of the range, direction -x
            ball_vel = np.array([0.0, ball_speed])
            kin.kick(np.array([0]), pos, vel, np.zeros(2), ball_vel, kick, dist, -1, noise)
            moved.append(ball_vel.copy())
        # speed_rate = 0.5 + 0.5 x speed / (ball_speed_max x ball_decay): 1 at 2.82 m/cycle.
        assert moved[1] - moved[0] == pytest.approx((-expected, 0.0), abs=1e-9)


def test_movement_noise_is_a_vector_of_uniform_length_up_to_rand_times_speed() -> None:
    rig = Rig(probe_config(noise=True), seed=4)
    lengths = []
    for _ in range(400):
        rig.state.vel[0] = (1.0, 0.0)
        rig.state.ball_vel[:] = (0.0, 2.0)
        rig.state.pos[0] = (-20.0, 0.0)
        rig.state.ball[:] = (0.0, 20.0)
        rig.kin.dash(rig.state.vel, rig.state.ball_vel, rig.state.stamina, rig.state.effort, rig.state.recovery,
                     rig.state.capacity, np.zeros((ROWS, 2)), rig.noise.motion)
        player, ball = np.hypot(*(rig.state.vel[0] - (1.0, 0.0))), np.hypot(*(rig.state.ball_vel - (0.0, 2.0)))
        assert player <= PHYS.player_rand * 1.0 + 1e-12 and ball <= PHYS.ball_rand * 2.0 + 1e-12
        lengths.append(player / PHYS.player_rand)
        rig.noise.draw()
    # Uniform length: mean 1/2, and no direction preferred.
    assert np.mean(lengths) == pytest.approx(0.5, abs=0.05)


def kick_statistics(offset, trials: int = 400) -> tuple[float, float]:
    """Standard deviations of the kicked ball's first-cycle speed (m/cycle) and direction (°)."""
    steps = [first_step_of_a_kick(offset, noise=True, seed=seed) for seed in range(trials)]
    return float(np.std([np.hypot(*s) for s in steps])), float(np.std([direction_degrees(s) for s in steps]))


def test_kick_noise_matches_rcssserver_with_the_ball_touching() -> None:
    real_speed_sd, real_direction_sd = server_kick_statistics("near")
    speed_sd, direction_sd = kick_statistics((0.3851, 0.0))
    assert speed_sd == pytest.approx(real_speed_sd, rel=0.2)               # rcssserver: 0.061 m/cycle
    assert direction_sd == pytest.approx(real_direction_sd, rel=0.15)      # rcssserver: 1.58°


def test_kick_noise_matches_rcssserver_with_the_ball_farthest() -> None:
    _, direction_sd = kick_statistics((1.084, 0.0))
    assert direction_sd == pytest.approx(server_kick_statistics("far")[1], rel=0.15)  # rcssserver: 2.00°


def two_sample_tolerance(real: int, trials: int) -> float:
    """Two standard deviations of the difference of two counts out of ``trials`` with the real
    server's share (at least one trial)."""
    share = real / trials
    return max(1.0, 2.0 * math.sqrt(2.0 * trials * share * (1.0 - share)))


def test_with_noise_a_walker_slips_past_the_ball_as_in_rcssserver() -> None:
    """With noise the ball slides off a walker's body sideways within a few pushes (rcssserver:
    20 of 20 walkers end beyond the ball, which moved 0.11 to 0.71 m, 0.30 m on average)."""
    real = REAL["contact"]["walk"]
    results = run_at_a_still_ball(30, 40, start=-3.0, step=0.015, noise=True)
    assert sum(passed for _, passed in results) >= sum(player > ball for ball, player in real) - 2
    assert float(np.mean([x for x, _ in results])) == pytest.approx(np.mean([ball for ball, _ in real]), abs=0.1)
    assert max(x for x, _ in results) < 1.0


def test_with_noise_a_path_near_the_ball_sometimes_touches_it() -> None:
    real = REAL["contact"]["past_0.3_moved"]
    moved = 0
    for k in range(len(real)):
        rig = Rig(probe_config(noise=True), seed=k)
        rig.state.pos[0] = (-5.0 - 0.05 * k, 0.0)
        rig.state.ball[:] = (0.0, 0.3)
        for _ in range(25):
            rig.cycle(dash=dash_power(100))
        moved += bool(abs(rig.state.ball[0]) > 1e-6 or abs(rig.state.ball[1] - 0.3) > 1e-6)
    assert abs(moved - sum(real)) <= two_sample_tolerance(sum(real), len(real))  # rcssserver: 7 of 20


@pytest.mark.parametrize("field, value", [("player_rand", -0.1), ("ball_rand", 1.5), ("kick_rand", float("nan")),
                                          ("inertia_moment", 0.0)])
def test_bad_noise_and_body_parameters_are_rejected_by_name(field: str, value: float) -> None:
    with pytest.raises(ValueError, match=f"PhysicsConfig.{field} must be"):
        PhysicsConfig(**{field: value}).validate()


def test_the_old_fixed_fraction_names_are_gone_and_the_planners_figure_is_derived() -> None:
    with pytest.raises(TypeError, match="player_noise"):
        PhysicsConfig(player_noise=0.05)
    # The one-figure spread planners read: the half-width of a uniform spread with the standard
    # deviation of a full-power kick's direction (1.41° measured; 0.044 rad x 1/sqrt(3) = 1.46°).
    assert PHYS.kick_noise == pytest.approx(0.0441, abs=5e-4)
    assert math.degrees(PHYS.kick_noise / math.sqrt(3)) == pytest.approx(1.41, rel=0.05)
    assert PhysicsConfig(kick_rand=0.0, ball_rand=0.0).kick_noise == 0.0
