"""The reinforcement-learning examples (optional extra ``rl``): each runs where its library is
installed and is skipped where it is not; those that import torch are marked slow."""

from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest


def test_episode_goals_are_kept_under_a_key_only_the_last_step_has() -> None:
    from examples.ppo_shared_policy import make_env  # needs only the core dependencies

    environment = make_env("empty-goal", "low_level")
    scored = 0
    for seed in range(6):
        environment.reset(seed=seed)
        rng = np.random.default_rng(seed)
        while environment.agents:
            _, _, _, _, infos = environment.step({"left_0": rng.uniform(-1, 1, 5).astype(np.float32)})
            if environment.agents:
                assert "goals_for" not in infos["left_0"]
        info = infos["left_0"]
        assert info["goals_for"] == int(info["episode_goals"][0]) and info["episode_goals"][1] == 0
        scored += info["goals_for"]
    environment.close()
    assert scored <= 6  # empty-goal ends at the first goal


@pytest.mark.slow
def test_ppo_example_trains_saves_its_curve_and_evaluates(tmp_path, capsys) -> None:
    pytest.importorskip("torch")
    pytest.importorskip("stable_baselines3")
    pytest.importorskip("supersuit")
    from examples.ppo_shared_policy import main

    result = main(["--timesteps", "2048", "--envs", "2", "--n-steps", "512", "--batch-size", "128",
                   "--eval-episodes", "3", "--out", str(tmp_path)])
    assert result["timesteps"] >= 2048
    with open(tmp_path / "reward_curve.csv") as handle:
        rows = list(csv.DictReader(handle))
    assert [int(row["timesteps"]) for row in rows] == sorted(int(row["timesteps"]) for row in rows)
    assert rows and all(math.isfinite(float(row["mean_return"])) for row in rows)
    assert (tmp_path / "reward_curve.png").stat().st_size > 1000 and (tmp_path / "model.zip").exists()
    saved = json.loads((tmp_path / "evaluation.json").read_text())
    assert saved == result
    for name in ("trained", "random"):
        assert saved[name]["episodes"] == 3 and 0 <= saved[name]["goals"] <= 3
    assert "trained:" in capsys.readouterr().out


@pytest.mark.slow  # importing torch and TorchRL alone takes seconds
def test_torchrl_setup_passes_check_env_specs() -> None:
    pytest.importorskip("torchrl")
    from examples.torchrl_setup import main

    summary = main()  # check_env_specs raises on a spec mismatch
    assert summary["steps"] == 50 and summary["state_shape"][0] == 50


@pytest.mark.slow
def test_tianshou_setup_collects_numeric_infos() -> None:
    pytest.importorskip("tianshou")
    from examples.tianshou_setup import main

    summary = main(steps=300)
    assert summary["steps"] == 300 and summary["buffer"] == 300
    assert {"episode_goals", "score", "play_mode", "events"} <= set(summary["info_keys"])


@pytest.mark.slow
def test_rllib_setup_trains_a_shared_policy() -> None:
    pytest.importorskip("ray.rllib")
    pytest.importorskip("torch")
    from examples.rllib_setup import main

    returns = main(iterations=1, batch=256)
    assert len(returns) == 1 and math.isfinite(returns[0])


LIBRARY_CASES = {
    "full match, both, low level": {"controlled": "both", "max_cycles": 40},
    "full match, left, high level": {"controlled": "left", "max_cycles": 40, "action_mode": "high_level"},
    "empty-goal": {"scenario": "empty-goal", "controlled": "left", "rewards": "dense"},
    "3-vs-1-with-keeper, both": {"scenario": "3-vs-1-with-keeper", "controlled": "both", "rewards": "dense",
                                 "max_cycles": 40},
    "counter-attack, high level": {"scenario": "counter-attack", "controlled": "left", "max_cycles": 40,
                                   "action_mode": "high_level"},
}


@pytest.mark.slow
@pytest.mark.parametrize("case", list(LIBRARY_CASES))
def test_torchrl_specs_and_a_tianshou_collector_over_sides_modes_and_scenarios(case) -> None:
    pytest.importorskip("torchrl")
    pytest.importorskip("tianshou")
    from tianshou.algorithm.algorithm_base import RandomActionPolicy
    from tianshou.algorithm.multiagent.marl import MultiAgentPolicy
    from tianshou.algorithm.random import MARLRandomDiscreteMaskedOffPolicyAlgorithm
    from tianshou.data import Collector, VectorReplayBuffer
    from tianshou.env import DummyVectorEnv, PettingZooEnv
    from torchrl.envs.utils import check_env_specs

    import soccer_sim.env as soccer_env
    from examples.torchrl_setup import make_env

    options = LIBRARY_CASES[case]
    wrapped = make_env(**options)
    check_env_specs(wrapped)
    assert wrapped.rollout(60, break_when_any_done=False).batch_size[0] == 60
    make = lambda: PettingZooEnv(soccer_env.env(**options))  # noqa: E731
    envs = DummyVectorEnv([make, make])
    probe = make()
    if options.get("action_mode") == "high_level":  # integer actions within the mask
        shared = MARLRandomDiscreteMaskedOffPolicyAlgorithm(probe.action_space).policy
        policy = MultiAgentPolicy({agent: shared for agent in probe.agents})
    else:
        policy = RandomActionPolicy(probe.action_space)
    collector = Collector(policy, envs, VectorReplayBuffer(4000, 2))
    collector.reset()
    assert collector.collect(n_step=400).n_collected_steps == 400
    envs.close()
