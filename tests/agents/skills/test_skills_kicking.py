"""Kicks: the kick vector gives the ball the desired velocity through the simulator's own kick
rule, or the best velocity along the desired direction when one kick cannot."""

from __future__ import annotations

import math

import numpy as np
import pytest

from agents.skills import MotionModel, SkillContext, kick_effectiveness, kick_for_velocity, kickable
from soccer_sim.kinematics import Kinematics
from tests.agents.skills.skill_views import N, quiet_config

CONFIG = quiet_config()
MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
PHYS = CONFIG.physics


def apply_kick(player, ball, ball_vel, kick, holder=False, player_vel=(0.0, 0.0)) -> np.ndarray:
    """The ball's velocity after the simulator applies ``kick`` by row 0 moving at
    ``player_vel`` (no noise)."""
    kin = Kinematics(CONFIG, 2 * CONFIG.players_per_team)
    pos = np.full((2 * N, 2), 40.0)
    pos[0] = player
    requests = np.zeros((2 * N, 2))
    requests[0] = kick
    dist = np.hypot(*(pos - np.asarray(ball)).T)
    vel = np.array(ball_vel, float)
    velocities = np.zeros((2 * N, 2))
    velocities[0] = player_vel
    kin.kick(np.array([0]), pos, velocities, np.asarray(ball, float), vel, requests, dist,
             0 if holder else -1, np.zeros((2 * N, 2)))
    return vel


@pytest.mark.parametrize("offset, ball_vel, desired", [
    ((0.5, 0.0), (0.0, 0.0), (2.0, 0.5)),       # ball in front, kicked forward
    ((0.0, 0.9), (0.4, -0.2), (1.5, 1.0)),      # ball to the side, far edge, moving
    ((-0.6, 0.2), (0.0, 0.0), (1.2, 0.0)),      # ball behind: kicked back through the player
    ((0.7, 0.3), (1.0, 0.0), (0.0, 0.0)),       # stop a rolling ball
])
def test_kick_vector_yields_the_desired_velocity(offset, ball_vel, desired) -> None:
    player = np.array([3.0, -2.0])
    ball = player + offset
    kick, result = kick_for_velocity(MODEL, player, ball, np.array(ball_vel), np.array(desired))
    assert result == pytest.approx(desired)
    assert np.hypot(*kick) <= PHYS.kick_speed_max + 1e-9
    assert apply_kick(player, ball, ball_vel, kick) == pytest.approx(desired, abs=1e-9)


@pytest.mark.parametrize("player_vel, offset, desired", [
    ((0.42, 0.0), (-0.5, 0.3), (1.0, 1.0)),     # sprinting past the ball: it lies behind the body
    ((0.0, -0.3), (0.6, 0.0), (1.8, -0.4)),     # running sideways, ball at 90° to the motion
    ((0.05, 0.0), (0.0, 0.6), (-1.5, 0.0)),     # walking, ball at 90°: slow enough to face it
])
def test_a_moving_kicker_is_planned_with_the_simulators_body_direction(player_vel, offset, desired) -> None:
    """The planner's kick gives the ball the desired velocity for a moving kicker too: the body
    direction (and so the angle penalty) is the simulator's, from the kicker's velocity."""
    player = np.array([3.0, -2.0])
    ball = player + offset
    kick, result = kick_for_velocity(MODEL, player, ball, np.zeros(2), np.array(desired), player_vel=player_vel)
    assert result == pytest.approx(desired)
    assert apply_kick(player, ball, (0.0, 0.0), kick, player_vel=player_vel) == pytest.approx(desired, abs=1e-9)
    effect = kick_effectiveness(MODEL, player, ball, desired, player_vel=player_vel)
    at_rest = kick_effectiveness(MODEL, player, ball, desired)
    assert effect < at_rest - 0.01 if np.hypot(*player_vel) > 0.1 else effect == pytest.approx(at_rest)


def test_an_impossible_kick_keeps_the_direction_and_gives_the_most_speed() -> None:
    player = np.array([0.0, 0.0])
    ball = np.array([0.0, 1.0])  # at the far edge: 25 % effectiveness lost to distance
    ball_vel = np.array([1.0, 0.0])
    desired = np.array([-3.0, 1.0])  # fast, nearly against the ball's motion
    kick, result = kick_for_velocity(MODEL, player, ball, ball_vel, desired)
    unit = desired / np.linalg.norm(desired)
    assert result[0] * unit[1] - result[1] * unit[0] == pytest.approx(0.0, abs=1e-9) and result @ unit > 0.0
    assert np.linalg.norm(result) < np.linalg.norm(desired)
    assert apply_kick(player, ball, ball_vel, kick) == pytest.approx(result, abs=1e-6)
    # The largest: 1 % more speed along the same direction is out of reach of one kick.
    more = result * 1.01
    change = more - ball_vel
    effect = kick_effectiveness(MODEL, player, ball, change)
    assert np.linalg.norm(change) > PHYS.kick_speed_max * effect


def test_a_holding_goalkeeper_kicks_at_full_strength() -> None:
    player = ball = np.array([-48.0, 0.0])
    kick, result = kick_for_velocity(MODEL, player, ball, np.zeros(2), np.array([2.7, 0.0]), holder=True)
    assert result == pytest.approx([2.7, 0.0]) and kick == pytest.approx([2.7, 0.0])
    assert apply_kick(player, ball, np.zeros(2), kick, holder=True) == pytest.approx([2.7, 0.0])


def test_desired_speed_beyond_the_ball_limit_is_capped() -> None:
    player, ball = np.zeros(2), np.array([0.4, 0.0])
    _, result = kick_for_velocity(MODEL, player, ball, np.array([2.0, 0.0]), np.array([5.0, 0.0]))
    assert np.linalg.norm(result) <= PHYS.ball_speed_max + 1e-9


def test_effectiveness_numbers() -> None:
    player = np.zeros(2)
    touch = PHYS.player_radius + PHYS.ball_radius
    # Touching: full effect, whichever way the ball is sent (rcssserver: 2.6999 at 90° and 180°).
    assert kick_effectiveness(MODEL, player, (touch, 0.0), (1.0, 0.0)) == pytest.approx(1.0)
    assert kick_effectiveness(MODEL, player, (touch, 0.0), (-1.0, 0.0)) == pytest.approx(1.0)
    # At the edge of the kickable distance: 1 - 0.25, at 90° too.
    edge = PHYS.kickable_distance
    assert kick_effectiveness(MODEL, player, (edge, 0.0), (0.0, 1.0)) == pytest.approx(1 - 0.25)


def test_kickable_is_the_kickable_distance() -> None:
    pos = np.array([[0.0, 0.0], [0.0, 5.0]])
    edge = PHYS.kickable_distance
    assert kickable(MODEL, pos, (edge - 1e-6, 0.0)).tolist() == [True, False]
    assert kickable(MODEL, pos, (edge + 1e-6, 0.0)).tolist() == [False, False]
    assert math.isclose(edge, 0.3 + 0.085 + 0.7)


def test_best_direction_preserving_kick_matches_a_fine_scan() -> None:
    rng = np.random.default_rng(11)
    for _ in range(200):
        player = np.zeros(2)
        angle = rng.uniform(-np.pi, np.pi)
        ball = rng.uniform(0.4, PHYS.kickable_distance) * np.array([np.cos(angle), np.sin(angle)])
        ball_vel = rng.uniform(-1.5, 1.5, 2)
        desired = rng.uniform(-3.0, 3.0, 2)
        _, result = kick_for_velocity(MODEL, player, ball, ball_vel, desired)
        unit = desired / np.linalg.norm(desired)
        speeds = np.linspace(0.0, min(np.linalg.norm(desired), PHYS.ball_speed_max), 3001)
        changes = speeds[:, None] * unit - ball_vel
        limits = PHYS.kick_speed_max * kick_effectiveness(MODEL, player, ball, changes)
        feasible = np.linalg.norm(changes, axis=1) <= limits + 1e-12
        if not feasible.any():
            continue  # nothing along the direction: the full-power fallback
        assert result @ unit >= speeds[feasible].max() - 2e-3
        change = result - ball_vel
        assert np.linalg.norm(change) <= PHYS.kick_speed_max * kick_effectiveness(MODEL, player, ball, change) + 1e-9
