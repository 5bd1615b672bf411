"""Kick power as rcssserver computes it: ``1 - 0.25 * dir_diff / 180° - 0.25 * dist_ball /
kickable_margin`` of the request, where ``dir_diff`` is where the ball lies relative to the
body (the body-direction model of :mod:`soccer_sim.body`) and ``dist_ball`` the gap between
the surfaces; not where the ball is sent. Figures: rcssserver 19, kick 100 of a ball at rest
(``tests/data/rcssserver/kick.json``)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from tests.soccer_sim.probe_rig import first_step_of_a_kick, kick_once

from soccer_sim.config import PhysicsConfig

PHYS = PhysicsConfig()
KICKS = json.loads((Path(__file__).resolve().parents[1] / "data" / "rcssserver" / "kick.json").read_text())["kicks"]
TOUCH = PHYS.player_radius + PHYS.ball_radius


def server_kick_speed(name: str) -> float:
    """The real server's first-cycle ball speed of the kick probe ``name`` (kick.json)."""
    return float(np.hypot(*KICKS[name]["first_cycle"]))


@pytest.mark.parametrize("offset, probe", [
    ((0.3851, 0.0), "kick_near_at0"),   # touching: 2.6999
    ((0.735, 0.0), "kick_mid_at0"),     # mid margin: 2.3625
    ((1.084, 0.0), "kick_far_at0"),     # farthest kickable: 2.0260
])
def test_kick_power_falls_with_the_balls_distance_as_measured(offset, probe) -> None:
    assert np.hypot(*first_step_of_a_kick(offset)) == pytest.approx(server_kick_speed(probe), abs=1e-3)


@pytest.mark.parametrize("direction, sent", [((0.0, 1.0), 90), ((-1.0, 0.0), 180),
                                             ((math.sqrt(0.5), math.sqrt(0.5)), 45)])
def test_the_direction_the_ball_is_sent_costs_nothing(direction, sent) -> None:
    """rcssserver: a ball in front kicked at 45°, 90° or 180° to the body leaves at 2.6999."""
    step = first_step_of_a_kick((0.3851, 0.0), direction)
    assert np.hypot(*step) == pytest.approx(server_kick_speed(f"kick_near_at0_dir{sent}"), abs=1e-3)
    assert step / np.hypot(*step) == pytest.approx(direction)


def test_a_player_at_rest_faces_the_ball_so_only_distance_costs() -> None:
    """A still player turns to the ball before it kicks (the body model), so a ball beside or
    behind it is kicked like one in front (rcssserver with the body left at 0°: 2.3624 beside,
    2.0249 behind; a real agent turns first)."""
    for offset in ((0.0, TOUCH), (-TOUCH, 0.0), (0.0, -1.084)):
        front = np.hypot(*first_step_of_a_kick((math.hypot(*offset), 0.0)))
        assert np.hypot(*first_step_of_a_kick(offset)) == pytest.approx(front)


def test_a_sprinter_cannot_face_a_ball_behind_it() -> None:
    """At 1 m/cycle a player turns at most 180° / (1 + 5 x 1) = 30°, so with the ball straight
    behind it still faces 150° away from the ball: 1 - 0.25 x 150 / 180 of the power."""
    _, velocity = kick_once((-TOUCH, 0.0), (2.0, 0.0), player_vel=(1.0, 0.0))
    assert velocity == pytest.approx((2.0 * (1 - 0.25 * 150 / 180), 0.0))
    # A slow player turns all the way to a ball beside it (at 0.05 m/cycle up to 144°)...
    _, slow = kick_once((0.0, TOUCH), (2.0, 0.0), player_vel=(0.05, 0.0))
    assert slow == pytest.approx((2.0, 0.0))
    # ...but not to one straight behind: 36° short of it.
    _, behind = kick_once((-TOUCH, 0.0), (2.0, 0.0), player_vel=(0.05, 0.0))
    assert behind == pytest.approx((2.0 * (1 - 0.25 * 36 / 180), 0.0))


def test_kick_effectiveness_falls_with_distance_and_the_balls_angle_to_the_body() -> None:
    _, close = kick_once((TOUCH, 0.0), (2.0, 0.0))
    assert close == pytest.approx((2.0, 0.0))  # ball touching, at rest: full power, any direction
    _, back = kick_once((TOUCH, 0.0), (-2.0, 0.0))
    assert back == pytest.approx((-2.0, 0.0))
    _, far = kick_once((PHYS.kickable_distance, 0.0), (2.0, 0.0))
    assert far == pytest.approx((2.0 * (1 - PHYS.kick_distance_penalty), 0.0))
    # Running along +y at top speed with the ball touching its side: it turns 180° / (1 + 5 x
    # 1.05) = 28.8° towards the ball and still faces 61.2° off it.
    speed = PHYS.player_speed_max
    turn = 180.0 / (1.0 + PHYS.inertia_moment * speed)
    _, side = kick_once((TOUCH, 0.0), (0.0, 2.0), player_vel=(0.0, speed))
    assert side == pytest.approx((0.0, 2.0 * (1 - PHYS.kick_angle_penalty * (90.0 - turn) / 180.0)))


def test_a_ball_overlapping_the_body_is_kicked_harder_but_capped() -> None:
    """rcssserver does not clip ``dist_ball`` at 0: a ball inside the body gains power, and the
    summed acceleration is capped at ``ball_accel_max``."""
    _, inside = kick_once((0.2, 0.0), (1.0, 0.0))
    assert inside == pytest.approx((1.0 + 0.25 * (TOUCH - 0.2) / PHYS.kickable_margin, 0.0))
    _, full = kick_once((0.2, 0.0), (2.7, 0.0))
    assert full == pytest.approx((PHYS.kick_speed_max, 0.0))
