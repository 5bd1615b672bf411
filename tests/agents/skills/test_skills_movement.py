"""Dash to a point: the player arrives and stops (the simulator's own dash rule, side and back
dash rates included), respects the speed cap, and sprints only when urgent and above the
stamina floor (the policy itself: test_skills_pacing)."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import (MotionModel, PacingParams, Players, SkillContext, SkillInputError, dash_to_points,
                           paced_dashes, speed_caps)
from soccer_sim.kinematics import Kinematics
from tests.agents.skills.skill_views import CONFIG, N, make_view

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
ROWS = 2 * N


def simulate(pos, vel, targets, cycles, speed_cap=None, effort=None, stamina_share=1.0):
    """Roll the team's players with the simulator's dash rule (no noise): each cycle the skill's
    command, Kinematics.dash, pos += vel, vel *= decay. Returns the positions and speeds."""
    kin = Kinematics(CONFIG, 2 * CONFIG.players_per_team)
    n = len(pos)
    all_vel = np.zeros((ROWS, 2))
    all_vel[:n] = vel
    pos = np.array(pos, float)
    stamina = np.full(ROWS, CONFIG.stamina.maximum * stamina_share)
    eff = np.ones(ROWS) if effort is None else np.concatenate([effort, np.ones(ROWS - n)])
    recovery, capacity = np.ones(ROWS), np.full(ROWS, np.inf)
    noise = np.zeros((ROWS + 1, 2))  # noise lengths of zero: no noise
    ball_vel = np.zeros(2)
    path, speeds = [pos.copy()], []
    for _ in range(cycles):
        dash = np.zeros((ROWS, 2))
        dash[:n] = dash_to_points(MODEL, Players(MODEL, pos, all_vel[:n], eff[:n]), targets, speed_cap)
        kin.dash(all_vel, ball_vel, stamina, eff, recovery, capacity, dash, noise)
        speeds.append(np.hypot(all_vel[:n, 0], all_vel[:n, 1]))
        pos += all_vel[:n]
        all_vel *= CONFIG.physics.player_decay
        path.append(pos.copy())
    return np.array(path), np.array(speeds), all_vel[:n]


def test_players_arrive_and_stop_without_overshoot() -> None:
    start = np.array([[0.0, 0.0], [5.0, 5.0], [-10.0, 3.0]])
    targets = np.array([[10.0, 3.0], [5.5, 4.0], [-30.0, -20.0]])
    vel = np.array([[0.0, 0.0], [0.3, 0.0], [0.0, 0.4]])
    path, speeds, final_vel = simulate(start, vel, targets, 50)
    assert np.allclose(path[-1], targets, atol=0.05)
    assert np.allclose(final_vel, 0.0, atol=1e-3)
    # No overshoot past the target along the line from the start (first two players start at
    # rest or slow towards it; small sideways drift allowed for the third).
    for i in range(3):
        line = (targets[i] - start[i]) / np.linalg.norm(targets[i] - start[i])
        progress = (path[:, i] - start[i]) @ line
        assert progress.max() <= np.linalg.norm(targets[i] - start[i]) + 0.02
    # The far runner reaches top speed on the way (1 m/cycle at full effort).
    assert speeds[:, 2].max() == pytest.approx(MODEL.top_speed, abs=0.01)


def test_a_sprint_of_ten_metres_takes_the_model_time() -> None:
    path, _, _ = simulate(np.array([[0.0, 0.0]]), np.zeros((1, 2)), np.array([[10.0, 0.0]]), 14)
    # reach(k): 0.6, 1.44, 2.38, 3.35, 4.34, 5.34, 6.33, 7.33, 8.33, 9.33 at k = 10: one more
    # cycle covers the rest and the player stands on the point.
    assert path[10, 0, 0] == pytest.approx(MODEL.reach[10])
    assert path[11, 0, 0] == pytest.approx(10.0)
    assert np.allclose(path[11:, 0], (10.0, 0.0), atol=1e-9)


def test_speed_cap_is_respected() -> None:
    cap = MODEL.sustainable_speed(1.0)
    assert cap == pytest.approx(0.45)  # 45 stamina/cycle * 0.006 / (1 - 0.4)
    _, speeds, _ = simulate(np.array([[0.0, 0.0]]), np.zeros((1, 2)), np.array([[20.0, 0.0]]), 30, speed_cap=cap)
    assert speeds.max() <= cap + 1e-9
    assert speeds[5:25].min() == pytest.approx(cap)


def test_tired_players_accelerate_less() -> None:
    path, speeds, _ = simulate(np.array([[0.0, 0.0]]), np.zeros((1, 2)), np.array([[30.0, 0.0]]), 10,
                               effort=np.array([0.6]), stamina_share=0.5)  # effort neither falls nor recovers
    assert speeds[0, 0] == pytest.approx(0.36)
    assert speeds.max() <= 0.6 + 1e-9


CRUISE_SPEED = PacingParams().cruise * CONFIG.stamina.recovery_per_cycle * CONFIG.physics.dash_power_rate / (
    1.0 - CONFIG.physics.player_decay)
"""The speed a fresh player's cruising budget holds (0.72 m/cycle by default)."""


def test_speed_caps_sprint_only_when_urgent_and_above_the_floor() -> None:
    stamina = np.full(N, CONFIG.stamina.maximum)
    stamina[3] = 0.25 * CONFIG.stamina.maximum  # below the recovery threshold, so below the floor
    view = make_view(stamina=stamina)
    urgent = np.zeros(N, dtype=bool)
    urgent[[2, 3]] = True
    caps = speed_caps(CTX, view, urgent)
    assert caps[2] == pytest.approx(MODEL.top_speed)
    assert caps[3] == 0.0  # far from the ball: it waits until it has recovered above the floor
    assert caps[0] == pytest.approx(CRUISE_SPEED)
    assert MODEL.sustainable_speed(1.0) < caps[0] < MODEL.top_speed


def test_standing_on_the_target_costs_nothing() -> None:
    out = dash_to_points(MODEL, Players(MODEL, np.array([[1.0, 1.0]]), np.zeros((1, 2))), np.array([[1.01, 1.0]]))
    assert np.all(out == 0.0)


def test_players_near_the_ball_may_sprint() -> None:
    own = {4: (3.0, 4.0), 5: (30.0, 0.0)}
    view = make_view(own=own, ball=(0.0, 0.0))
    caps = speed_caps(CTX, view, near=10.0)
    assert caps[4] == pytest.approx(MODEL.top_speed)
    assert caps[5] == pytest.approx(CRUISE_SPEED)


def test_a_long_run_from_rest_is_the_dash_at_the_speed_cap_within_the_budget() -> None:
    """Players at rest with far targets: the urgent ones dash as dash_to_points at the
    policy's speed caps (top speed); the others dash the same way, shortened to the power
    their budget buys (they reach their cruising speed over a few cycles). The checks name
    bad arguments."""
    rng = np.random.default_rng(5)
    stamina = np.full(N, CONFIG.stamina.maximum)
    stamina[[1, 6]] = 0.6 * CONFIG.stamina.maximum
    own = rng.uniform(-30, 30, (N, 2))
    effort = rng.uniform(0.6, 1.0, N)
    view = make_view(own=own, effort=effort, stamina=stamina, ball=(5.0, 5.0))
    angles = rng.uniform(0, 2 * np.pi, N)
    targets = own + 20.0 * np.column_stack([np.cos(angles), np.sin(angles)])
    urgent = np.arange(N) % 2 == 0
    income, rate = CONFIG.stamina.recovery_per_cycle, CONFIG.physics.dash_power_rate
    for near in (None, 20.0):
        caps = speed_caps(CTX, view, urgent, near=near)
        two_steps = dash_to_points(MODEL, CTX.arrays(view).ours, targets, caps)
        out, budgets = np.empty((N, 2)), np.empty(N)
        assert paced_dashes(CTX, view, targets, urgent, out, near=near, budgets=budgets) is out
        hurry = urgent if near is None else urgent | (np.hypot(*(own - (5.0, 5.0)).T) <= near)
        np.testing.assert_allclose(out[hurry], two_steps[hurry], rtol=1e-12)
        assert np.all(budgets[hurry] == 100.0)
        calm = ~hurry
        np.testing.assert_allclose(np.hypot(*out[calm].T), budgets[calm] * rate * effort[calm], rtol=1e-9)
        np.testing.assert_allclose(out[calm] / np.hypot(*out[calm].T)[:, None],
                                   two_steps[calm] / np.hypot(*two_steps[calm].T)[:, None], atol=1e-12)
        fresh = calm & (stamina == CONFIG.stamina.maximum)
        np.testing.assert_allclose(budgets[fresh], PacingParams().cruise * income)
        assert np.all(budgets[calm & ~fresh] < PacingParams().cruise * income)
    with pytest.raises(SkillInputError, match="urgent"):
        paced_dashes(CTX, view, targets, np.ones(3, dtype=bool))
    with pytest.raises(SkillInputError, match="attacking"):
        paced_dashes(CTX, view, targets, attacking="yes")
    with pytest.raises(SkillInputError, match="budgets"):
        paced_dashes(CTX, view, targets, budgets=np.zeros(3))
