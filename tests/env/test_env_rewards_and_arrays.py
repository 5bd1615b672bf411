"""The reward terms (their documented formulas) and the batched array interface."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim import EventKind
from soccer_sim.env import DENSE, parallel_env


def _distance(state, row: int) -> float:
    return float(np.hypot(*(state.pos[row] - state.ball)))


def test_a_random_policy_earns_a_dense_reward_within_300_steps_of_the_full_match() -> None:
    environment = parallel_env(controlled="left", rewards="dense")  # against the default opponent
    environment.reset(seed=0)
    rng = np.random.default_rng(1)
    total, first = np.zeros(11), None
    for step in range(300):
        _, r, *_, infos = environment.step({a: rng.uniform(-1, 1, 5) for a in environment.agents})
        if infos["left_0"]["score"].any():
            break  # only what comes before any goal counts here
        total += np.abs(list(r.values()))
        if first is None and total.any():
            first = step
    assert first is not None and first < 50 and total.sum() > 0.05
    assert total.all()  # possession and ball progress reach every agent, not only the nearest one


def test_ball_approach_rewards_the_nearest_player_for_closing_in() -> None:
    environment = parallel_env(scenario="3-vs-1-with-keeper", controlled="left", opponent="idle",
                               rewards={"ball_approach": 2.0})
    environment.reset(seed=1)
    state = environment._match.state
    nearest = int(np.argmin([_distance(state, row) for row in range(3)]))
    before = _distance(state, nearest)
    towards = (state.ball - state.pos[nearest]) / before
    actions = {a: np.zeros(5, np.float32) for a in environment.agents}
    actions[f"left_{nearest}"] = np.array([*towards, 0, 0, 0], np.float32)
    _, rewards, *_ = environment.step(actions)
    assert rewards[f"left_{nearest}"] == pytest.approx(2.0 * (before - _distance(state, nearest)), rel=1e-5)
    assert rewards[f"left_{nearest}"] > 0
    assert all(r == 0.0 for a, r in rewards.items() if a != f"left_{nearest}")


def test_ball_progress_possession_goal_and_kick_to_goal_terms() -> None:
    weights = {"ball_progress": 0.5, "possession": 0.25, "goal": 3.0, "kick_to_goal": 0.75}
    environment = parallel_env(scenario="empty-goal", action_mode="high_level", rewards=weights)
    environment.reset(seed=3)
    state = environment._match.state
    seen = {"shot": False, "goal": False}
    while environment.agents:
        kickable = environment.action_masks()[0, 10]
        x, touched = float(state.ball[0]), state.last_touch
        _, rewards, _, _, infos = environment.step({"left_0": 10 if kickable else 9})
        expected = 0.5 * (float(state.ball[0]) - x) + (0.25 if state.last_touch == 0 else 0.0)
        events = infos["left_0"]["events"]
        expected += 3.0 * events[EventKind.GOAL] + 0.75 * events[EventKind.SHOT]
        assert rewards["left_0"] == pytest.approx(expected, rel=1e-5, abs=1e-6)
        seen["shot"] |= bool(events[EventKind.SHOT])
        seen["goal"] |= bool(events[EventKind.GOAL])
        if touched < 0 <= state.last_touch:
            assert rewards["left_0"] >= 0.25 - 0.5 * 3.0  # possession counts from the first touch
    assert seen["shot"] and seen["goal"]


def test_reward_options_are_checked() -> None:
    with pytest.raises(ValueError, match="unknown reward term 'speed'; the terms are goal, ball_approach"):
        parallel_env(rewards={"speed": 1.0})
    with pytest.raises(ValueError, match="weight of reward term 'goal' must be a finite number"):
        parallel_env(rewards={"goal": float("nan")})
    with pytest.raises(ValueError, match="rewards must be None, 'sparse', 'dense' or a dict"):
        parallel_env(rewards="lots")
    assert parallel_env(rewards="dense")._rewards.weights == DENSE
    assert parallel_env(reward_shaping=0.2)._rewards.weights == {"goal": 1.0, "ball_progress": 0.2}


@pytest.mark.parametrize("mode", ["low_level", "high_level"])
def test_step_arrays_plays_the_same_episode_as_step(mode: str) -> None:
    one = parallel_env(scenario="counter-attack", controlled="both", action_mode=mode, rewards="dense")
    two = parallel_env(scenario="counter-attack", controlled="both", action_mode=mode, rewards="dense")
    observations, _ = one.reset(seed=4)
    rows = two.reset_arrays(seed=4)
    n = len(one.possible_agents)
    assert rows.shape == (n, one.observation_space("left_0").shape[0]) and rows.dtype == np.float32
    assert np.array_equal(rows, np.stack([observations[a] for a in one.possible_agents]))
    rng = np.random.default_rng(0)
    while one.agents:
        actions = rng.uniform(-1, 1, (n, 5)) if mode == "low_level" else rng.integers(0, 24, n)
        obs, rewards, terminations, truncations, _ = one.step(dict(zip(one.agents, actions)))
        arrays = two.step_arrays(actions if mode == "low_level" else actions[:, None])
        assert np.array_equal(arrays[0], np.stack([obs[a] for a in one.possible_agents]))
        assert np.array_equal(arrays[1], np.array([rewards[a] for a in one.possible_agents], np.float32))
        assert arrays[2].dtype == bool and arrays[2].tolist() == [terminations[a] for a in one.possible_agents]
        assert arrays[3].tolist() == [truncations[a] for a in one.possible_agents]
    assert not two.agents and (arrays[2] | arrays[3]).all()
    with pytest.raises(RuntimeError, match="call reset"):
        two.step_arrays(actions)


def test_step_arrays_checks_its_actions() -> None:
    environment = parallel_env(scenario="3-vs-1-with-keeper", controlled="both")
    environment.reset_arrays(seed=0)
    good = np.zeros((5, 5))
    with pytest.raises(ValueError, match=r"one row per agent \(5\), got 4"):
        environment.step_arrays(good[:4])
    bad = good.copy()
    bad[3, 1] = np.nan
    with pytest.raises(ValueError, match="action of right_0 is not finite"):
        environment.step_arrays(bad)
    with pytest.raises(ValueError, match=r"action of left_0 must have shape \(5,\), got \(4,\)"):
        environment.step_arrays(np.zeros((5, 4)))
    first = environment.step_arrays(np.full((5, 5), 7.0))[0]  # clipped into the box, like step's actions
    assert environment.step_arrays(good)[0] is not first  # new arrays every call
    high = parallel_env(scenario="3-vs-1-with-keeper", action_mode="high_level")
    high.reset_arrays(seed=0)
    assert high.action_masks().shape == (5, 24) and parallel_env().action_masks() is None
    with pytest.raises(ValueError, match="action of left_2 must be in 0..23, got 30"):
        high.step_arrays(np.array([0, 1, 30, 2, 3]))
