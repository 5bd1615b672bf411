"""The rules the agents predict are the simulator's own functions, not copies.

A team that keeps its players onside or predicts how hard a kick leaves must use the same
formula the referee and the physics use; a second copy drifts (one clamped the distance term,
the other did not). These tests hold the agents to the simulator's objects and check the
shared formulas against rcssserver's numbers."""

from __future__ import annotations

import ast
import math
from pathlib import Path

import numpy as np
import pytest

import agents.skills.ball_kernels as ball_kernels
import agents.skills.passing as passing
import agents.teams.pipeline_kernels as pipeline_kernels
import agents.teams.role_behaviours as role_behaviours
import agents.teams.role_kernels as role_kernels
import soccer_sim.kernels as core_kernels
from soccer_sim import kick_rate
from soccer_sim.config import PhysicsConfig
from soccer_sim.rules import offside

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize("module", [ball_kernels, passing, pipeline_kernels, role_behaviours, role_kernels])
def test_the_agents_keep_players_onside_by_the_referees_offside_line(module) -> None:
    assert module.offside_line is offside.offside_line


@pytest.mark.parametrize("name", ["kick_effectiveness", "kick_distance_rate", "kick_angle_rate"])
def test_the_agents_predict_kicks_with_the_simulators_kick_rate(name) -> None:
    assert getattr(ball_kernels, name) is getattr(kick_rate, name)
    assert getattr(core_kernels, name) is getattr(kick_rate, name)


@pytest.mark.parametrize(("package", "names"), [
    # (agents.skills.kicking.kick_effectiveness is the skill's public wrapper of the shared kernel)
    ("agents", {"offside_line", "kick_distance_rate", "kick_angle_rate", "distance_effect"}),
    ("soccer_sim", {"distance_effect"}),
])
def test_no_second_definition_of_a_shared_formula(package, names) -> None:
    defined = []
    for path in sorted((ROOT / package).rglob("*.py")):
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.FunctionDef) and node.name in names:
                defined.append(f"{path.relative_to(ROOT)}:{node.name}")
    assert defined == []


def test_the_kick_rate_is_rcssservers() -> None:
    """Ball touching the front of the body: full power; at the far edge of the kickable area
    and behind the body: 1 - 0.25 - 0.25 (rcssserver's effective_kick_power_rate)."""
    physics = PhysicsConfig()
    touch = physics.player_radius + physics.ball_radius
    margin = physics.kickable_margin
    assert kick_rate.kick_effectiveness(kick_rate.kick_distance_rate(touch, touch, margin), kick_rate.kick_angle_rate(0.0),
                                        physics.kick_distance_penalty, physics.kick_angle_penalty) == 1.0
    far_behind = kick_rate.kick_effectiveness(kick_rate.kick_distance_rate(touch + margin, touch, margin),
                                              kick_rate.kick_angle_rate(math.pi), 0.25, 0.25)
    assert far_behind == pytest.approx(0.5)
    # rcssserver measured: kick 100 at the farthest kickable ball in front leaves at 2.0260 m/cycle
    # against 2.6999 touching: 2.026 / 2.7 = 0.75 = 1 - 0.25.
    assert kick_rate.kick_effectiveness(1.0, 0.0, 0.25, 0.25) == pytest.approx(2.0260 / 2.6999, abs=1e-3)


def test_the_offside_line_is_the_deepest_of_halfway_ball_and_second_last_opponent() -> None:
    line = offside.offside_line
    assert line(np.array([50.0, 10.0, 30.0]), 5.0) == 30.0       # second-last opponent
    assert line(np.array([50.0, 10.0, 30.0]), 40.0) == 40.0      # the ball
    assert line(np.array([50.0, -20.0, -10.0]), -5.0) == 0.0     # the halfway line
    assert line(np.array([50.0, 50.0, 0.0]), 0.0) == 50.0        # two level: both last and second-last
    assert line(np.array([50.0]), 0.0) == math.inf               # no second-last opponent: nobody offside
    opp = np.array([[50.0, 3.0], [10.0, -2.0], [30.0, 0.0]])
    assert line(opp[:, 0], 5.0) == 30.0                           # a column of a team-frame (m, 2) array
