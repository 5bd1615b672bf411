"""Dribbling: the direction avoids opponents and heads for goal; in the real simulator, kicking
and dashing on alternate cycles (one body command a cycle), the ball stays within reach and off
the body while the dribbler advances."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import MotionModel, SkillContext, dribble, dribble_directions
from tests.agents.skills.skill_views import N, ScriptedTeam, far_positions, make_view, play_on_match, quiet_config

CONFIG = quiet_config(max_cycles=400)
MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
DRIBBLER = 9


def test_free_dribbler_heads_for_goal() -> None:
    view = make_view(own={DRIBBLER: (0.0, 0.0)}, ball=(0.7, 0.0))
    plan = dribble(CTX, view, DRIBBLER)
    assert plan.direction[0] > 0.99
    assert plan.clearance > 5.0


def test_opponent_ahead_turns_the_dribble_aside() -> None:
    view = make_view(own={DRIBBLER: (0.0, 0.0)}, opp={4: (6.0, 0.0)}, ball=(0.7, 0.0))
    plan = dribble(CTX, view, DRIBBLER)
    assert abs(plan.direction[1]) > 0.5  # away from the straight line through the opponent
    dirs, clearance, _ = dribble_directions(CTX, view, DRIBBLER)
    straight = int(np.argmax(dirs[:, 0]))
    assert clearance[straight] < 0.0 < plan.clearance


def test_directions_leaving_the_field_are_excluded() -> None:
    view = make_view(own={DRIBBLER: (20.0, CONFIG.field.half_width - 1.5)}, ball=(20.5, CONFIG.field.half_width - 1.5))
    plan = dribble(CTX, view, DRIBBLER)
    assert plan.direction[1] <= 0.3


def test_dribble_keeps_the_ball_in_reach_in_the_simulator() -> None:
    def script(view):
        dash, kick = np.zeros((N, 2)), np.zeros((N, 2))
        plan = dribble(CTX, view, DRIBBLER)
        dash[DRIBBLER], kick[DRIBBLER] = plan.dash, plan.kick
        return dash, kick, False

    home = ScriptedTeam(script)
    own = far_positions(-1.0)
    own[DRIBBLER] = (-20.0, 0.0)
    away = far_positions(1.0)
    away[4] = (-5.0, 0.5)  # one opponent (idle) in the way
    match = play_on_match(home, ScriptedTeam(), CONFIG, own, away, ball=(-19.3, 0.0), ball_vel=(0.0, 0.0))
    for _ in range(30):
        match.step()
    gaps = [np.linalg.norm(v["ball"] - v["own_pos"][DRIBBLER]) for v in home.views[1:]]
    assert max(gaps) <= CONFIG.physics.kickable_distance
    assert min(gaps) > CONFIG.physics.player_radius + CONFIG.physics.ball_radius  # never touching the body
    start, end = home.views[0]["own_pos"][DRIBBLER], home.views[-1]["own_pos"][DRIBBLER]
    # About 0.45 m a cycle: one body command a cycle, so on the kick cycles (about one in three)
    # the dribbler only coasts, and its speed decays to 0.4 of itself.
    assert end[0] - start[0] > 12.0
    # It went round the opponent rather than through it.
    path = np.array([v["own_pos"][DRIBBLER] for v in home.views])
    assert np.min(np.hypot(*(path - (-5.0, 0.5)).T)) > 1.0
