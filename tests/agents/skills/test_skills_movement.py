"""Dash to a point: the player arrives and stops (the simulator's own dash rule, side and back
dash rates included), respects the speed cap, and runs at its sustainable speed when it need
not sprint."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import MotionModel, Players, SkillContext, SkillInputError, dash_to_points, paced_dashes, speed_caps
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


def test_speed_caps_sprint_only_when_urgent_and_fresh() -> None:
    stamina = np.full(N, CONFIG.stamina.maximum)
    stamina[3] = 0.25 * CONFIG.stamina.maximum  # below the recovery threshold
    view = make_view(stamina=stamina)
    urgent = np.zeros(N, dtype=bool)
    urgent[[2, 3]] = True
    caps = speed_caps(CTX, view, urgent)
    assert caps[2] == pytest.approx(MODEL.top_speed)
    assert caps[3] == pytest.approx(MODEL.sustainable_speed(1.0))
    assert caps[0] == pytest.approx(MODEL.sustainable_speed(1.0))


def test_standing_on_the_target_costs_nothing() -> None:
    out = dash_to_points(MODEL, Players(MODEL, np.array([[1.0, 1.0]]), np.zeros((1, 2))), np.array([[1.01, 1.0]]))
    assert np.all(out == 0.0)


def test_players_near_the_ball_may_sprint() -> None:
    own = {4: (3.0, 4.0), 5: (30.0, 0.0)}
    view = make_view(own=own, ball=(0.0, 0.0))
    caps = speed_caps(CTX, view, near=10.0)
    assert caps[4] == pytest.approx(MODEL.top_speed)
    assert caps[5] == pytest.approx(MODEL.sustainable_speed(1.0))


def test_paced_dashes_are_the_caps_and_the_dashes_in_one_pass() -> None:
    rng = np.random.default_rng(5)
    stamina = np.full(N, CONFIG.stamina.maximum)
    stamina[[1, 6]] = 0.2 * CONFIG.stamina.maximum
    view = make_view(own=rng.uniform(-40, 40, (N, 2)), own_vel=rng.uniform(-0.5, 0.5, (N, 2)),
                     effort=rng.uniform(0.6, 1.0, N), stamina=stamina, ball=(5.0, 5.0))
    targets = rng.uniform(-40, 40, (N, 2))
    urgent = rng.uniform(size=N) < 0.5
    for near in (None, 20.0):
        caps = speed_caps(CTX, view, urgent, near=near)
        two_steps = dash_to_points(MODEL, CTX.arrays(view).ours, targets, caps)
        out = np.empty((N, 2))
        assert paced_dashes(CTX, view, targets, urgent, out, near=near) is out
        np.testing.assert_array_equal(out, two_steps)
    with pytest.raises(SkillInputError, match="urgent"):
        paced_dashes(CTX, view, targets, np.ones(3, dtype=bool))
