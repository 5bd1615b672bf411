"""The checkpoint loaders (soccer_sim.env.checkpoints) and checkpoint team names
(soccer_sim.env.checkpoint_teams), tested with stand-ins of the RL libraries' loading and
acting calls (tests/env/rl_standins.py): no RL library is installed or imported here. A loaded
checkpoint sees exactly the observations the environment gave in training; a missing library,
file or bad option is one line naming it."""

from __future__ import annotations

import pickle
import sys

import numpy as np
import pytest

from soccer_sim import run_match
from soccer_sim.env import parallel_env
from soccer_sim.env.checkpoint_teams import checkpoint_team, parse_checkpoint_name
from soccer_sim.env.checkpoints import INSTALL, CheckpointError, actions_from_output, load_policy
from tests.env import rl_standins as standins
from tests.env.test_policy_team_as_trained import _environment_observations

D, A = 136, 24
"""Observation size with 11 slots, and the high-level action count, of the scenarios used here."""


def _weights(outputs: int, seed: int = 0, scale: float = 0.3) -> np.ndarray:
    return (np.random.default_rng(seed).normal(size=(D, outputs)) * scale).astype(np.float32)


@pytest.fixture
def sb3(monkeypatch, tmp_path):
    module = standins.sb3_module(tmp_path / "site")
    standins.install(monkeypatch, {"stable_baselines3": module})
    return module


@pytest.fixture
def torch_calls(monkeypatch) -> list:
    calls: list = []
    standins.install(monkeypatch, standins.torch_modules(calls))
    return calls


# ----------------------------------------------------------------------------- each kind
def test_sb3_loads_with_the_algorithm_named_and_predicts_deterministically(sb3, tmp_path) -> None:
    path = standins.write_sb3_checkpoint(tmp_path / "dqn.zip", _weights(A), discrete=True)
    policy = load_policy("sb3", tmp_path / "dqn", discrete=True, algorithm="DQN")  # .zip added as SB3 does
    masks = np.zeros((3, A), dtype=np.int8)
    masks[:, [2, 9]] = 1
    rows = np.random.default_rng(1).normal(size=(3, D)).astype(np.float32)
    actions = policy.act_batch({"observation": rows, "action_mask": masks})
    assert set(actions) <= {2, 9} and actions.shape == (3,)
    model = sb3.DQN.loaded[-1]
    assert model.device == "cpu" and model.calls == [True] and not sb3.PPO.loaded
    with pytest.raises(CheckpointError, match=r"algorithm 'NoSuch' is not one of Stable-Baselines3's \(A2C, "):
        load_policy("sb3", path, algorithm="NoSuch")


def test_a_torch_module_saved_whole_or_as_a_state_dict_with_its_constructor(torch_calls, tmp_path) -> None:
    whole = tmp_path / "actor.pt"
    whole.write_bytes(pickle.dumps(standins.LinearModule(weights=_weights(5))))
    rows = np.random.default_rng(2).normal(size=(4, D)).astype(np.float32)
    actions = load_policy("torch", whole).act_batch(rows)
    assert actions.shape == (4, 5) and np.all(np.abs(actions) <= 1.0)
    assert torch_calls[-1] == {"path": str(whole), "map_location": "cpu", "weights_only": False}

    state = tmp_path / "q.pt"
    state.write_bytes(pickle.dumps({"weights": _weights(A)}))
    with pytest.raises(CheckpointError, match="holds a state dict: give constructor=package.module:callable"):
        load_policy("torch", state, discrete=True)
    policy = load_policy("torch", state, discrete=True, constructor="tests.env.rl_standins:make_empty_linear")
    assert torch_calls[-1]["weights_only"] is True  # a state dict is loaded without unpickling code
    masks = np.ones((4, A), dtype=np.int8)
    masks[:, 0] = 0
    chosen = policy.act_batch({"observation": rows, "action_mask": masks})
    expected = np.stack([row @ _weights(A) for row in rows])
    expected[:, 0] = -np.inf
    assert np.array_equal(chosen, expected.argmax(axis=1))


def test_a_torchrl_tensordict_module_gets_its_keys_under_deterministic_exploration(torch_calls, tmp_path) -> None:
    path = tmp_path / "policy.pt"
    path.write_bytes(pickle.dumps(standins.TensorDictLinear(squash=False, weights=_weights(A))))
    masks = np.zeros((2, A), dtype=np.int8)
    masks[:, 5] = 1
    actions = load_policy("torchrl", path, discrete=True).act_batch(
        {"observation": np.ones((2, D), dtype=np.float32), "action_mask": masks})
    assert list(actions) == [5, 5]  # the stand-in asserts the exploration type it ran under


def test_a_tianshou_policy_gets_the_batch_its_pettingzoo_wrapper_gives(monkeypatch, torch_calls, tmp_path) -> None:
    standins.install(monkeypatch, standins.tianshou_modules())
    path = tmp_path / "dqn.pth"
    path.write_bytes(pickle.dumps(standins.TianshouPolicy(weights=_weights(A))))
    policy = load_policy("tianshou", path, discrete=True)
    rows = np.random.default_rng(3).normal(size=(3, D)).astype(np.float32)
    actions = policy.act_batch(rows)  # no mask in the observation: every action allowed, as PettingZooEnv does
    assert np.array_equal(actions, np.stack([row @ _weights(A) for row in rows]).argmax(axis=1))
    path.write_bytes(pickle.dumps(standins.TianshouPolicy(weights=_weights(5))))
    low = load_policy("tianshou", path).act_batch(rows)
    assert np.all(np.abs(low) <= 0.5)  # passed through the policy's map_action


def test_an_rllib_checkpoint_directory_gives_the_module_of_the_policy_chosen(monkeypatch, tmp_path) -> None:
    standins.install(monkeypatch, {**standins.torch_modules([]), **standins.rllib_modules()})
    directory = standins.write_rllib_checkpoint(tmp_path / "ckpt", {"shared": _weights(10), "other": _weights(A)})
    with pytest.raises(CheckpointError, match="holds the policies other, shared: choose one with policy=NAME"):
        load_policy("rllib", directory)
    rows = np.random.default_rng(4).normal(size=(2, D)).astype(np.float32)
    actions = load_policy("rllib", directory, policy="shared").act_batch(rows)
    means = np.stack([row @ _weights(10) for row in rows])[:, :5]
    assert np.array_equal(actions, np.clip(means, -1, 1))  # the Gaussian's means, clipped to the space
    module = sys.modules["ray.rllib.core.rl_module.rl_module"].RLModule.loaded[-1]
    assert module.directory.endswith("learner_group/learner/rl_module/shared") and "obs" in module.inputs[-1]
    with pytest.raises(CheckpointError, match="has no policy 'nobody'; it has other, shared"):
        load_policy("rllib", directory, policy="nobody")


def test_outputs_become_actions_in_one_place() -> None:
    scores = np.array([[0.0, 5.0, 1.0], [3.0, 2.0, 9.0]])
    assert list(actions_from_output(scores, None, discrete=True)) == [1, 2]
    assert list(actions_from_output(scores, np.array([[1, 0, 1], [1, 1, 0]]), discrete=True)) == [2, 0]
    assert list(actions_from_output(np.array([4, 7]), None, discrete=True)) == [4, 7]
    assert np.array_equal(actions_from_output(np.array([[2.0, -3.0, 0.5]]), None, discrete=False), [[1.0, -1.0, 0.5]])


# ----------------------------------------------------------------------------- missing libraries, bad input
@pytest.mark.parametrize("kind, module, library", [
    ("sb3", "stable_baselines3", "Stable-Baselines3"),
    ("torch", "torch", "PyTorch"),
    ("tianshou", "tianshou.data", "Tianshou"),
    ("rllib", "ray.rllib.core.rl_module.rl_module", "Ray RLlib"),
])
def test_a_missing_library_is_one_line_naming_it_and_the_extra(monkeypatch, tmp_path, kind, module, library) -> None:
    monkeypatch.setitem(sys.modules, module, None)  # what an uninstalled library looks like to import
    with pytest.raises(CheckpointError) as raised:
        load_policy(kind, tmp_path / "anything")
    message = str(raised.value)
    assert f"needs {library} (module {module!r})" in message and message.endswith(INSTALL) and "\n" not in message


def test_bad_files_and_options_say_what_is_wrong(monkeypatch, sb3, torch_calls, tmp_path) -> None:
    standins.install(monkeypatch, standins.rllib_modules())
    with pytest.raises(CheckpointError, match=r"checkpoint '.*missing\.zip': no such file \(a Stable-Baselines3"):
        load_policy("sb3", tmp_path / "missing.zip")
    broken = tmp_path / "broken.zip"
    broken.write_text("not a model")
    with pytest.raises(CheckpointError, match="cannot load it as a Stable-Baselines3 PPO model: JSONDecodeError"):
        load_policy("sb3", broken)
    with pytest.raises(CheckpointError, match="unknown checkpoint kind 'keras'; the kinds are sb3, torch"):
        load_policy("keras", broken)
    with pytest.raises(CheckpointError, match="a 'torch' checkpoint takes no option 'policy'"):
        load_policy("torch", broken, policy="x")
    with pytest.raises(CheckpointError, match="constructor 'nowhere:make': ModuleNotFoundError"):
        load_policy("torch", broken, constructor="nowhere:make")
    with pytest.raises(CheckpointError, match="no such directory"):
        load_policy("rllib", tmp_path / "nothing")


@pytest.mark.parametrize("name, message", [
    ("checkpoint:keras:x.h5", "KIND one of sb3, torch, torchrl, tianshou, rllib"),
    ("checkpoint:sb3:", "no checkpoint path"),
    ("checkpoint:sb3:a.zip?colour=red", "unknown option 'colour'; the options: scenario,"),
    ("checkpoint:sb3:a.zip?max_cycles=many", "option max_cycles='many' must be an integer"),
    ("checkpoint:sb3:a.zip?action_mask_in_observation=maybe", "must be true or false"),
    ("checkpoint:sb3:a.zip?name=a&name=b", "option 'name' is given twice"),
    ("checkpoint:sb3:a.zip?scenario", "option 'scenario' must look like OPTION=VALUE"),
])
def test_bad_checkpoint_names_are_refused_naming_the_part(name, message) -> None:
    with pytest.raises(CheckpointError, match=message.replace("(", r"\(")):
        parse_checkpoint_name(name)


def test_a_name_reads_into_team_and_loader_options() -> None:
    spec = parse_checkpoint_name("checkpoint:sb3:runs/dqn.zip?scenario=empty-goal&action_mode=high_level"
                                 "&action_mask_in_observation=true&max_cycles=200&algorithm=DQN")
    assert (spec.kind, spec.path, spec.name) == ("sb3", "runs/dqn.zip", "dqn")
    assert spec.team == {"scenario": "empty-goal", "action_mode": "high_level", "action_mask_in_observation": True,
                         "max_cycles": 200}
    assert spec.loader == {"algorithm": "DQN"}


# ----------------------------------------------------------------------------- as trained
class _Acting:
    """A loaded checkpoint acting for one agent of the environment (a batch of one row)."""

    def __init__(self, policy) -> None:
        self.policy = policy

    def act(self, observation):
        if isinstance(observation, dict):
            batch = {"observation": observation["observation"][None], "action_mask": observation["action_mask"][None]}
        else:
            batch = observation[None]
        return self.policy.act_batch(batch)[0]


@pytest.mark.parametrize("kind, options, env_options", [
    ("torch", "scenario=empty-goal", dict(scenario="empty-goal")),
    ("sb3", "scenario=3-vs-1-with-keeper&action_mode=high_level&action_mask_in_observation=true&algorithm=DQN",
     dict(scenario="3-vs-1-with-keeper", opponent="chaser", action_mode="high_level",
          action_mask_in_observation=True)),
])
def test_a_checkpoint_team_sees_exactly_what_the_environment_gave(sb3, torch_calls, tmp_path, kind, options,
                                                                  env_options) -> None:
    if kind == "torch":
        path = tmp_path / "actor.pt"
        path.write_bytes(pickle.dumps(standins.LinearModule(weights=_weights(5, scale=0.1))))
    else:
        path = standins.write_sb3_checkpoint(tmp_path / "dqn.zip", _weights(A), discrete=True)
    env = parallel_env(controlled="left", **env_options)
    spec = parse_checkpoint_name(f"checkpoint:{kind}:{path}?{options}")
    trained = _environment_observations(
        env, _Acting(load_policy(kind, path, discrete="action_mode" in spec.team, **spec.loader)), seed=3)
    assert len(trained) >= 5 * len(env.possible_agents)
    team = checkpoint_team(f"checkpoint:{kind}:{path}?{options}&name=learned")
    run_match(team, env_options.get("opponent", "static"), seed=env.match_seed, scenario=env_options["scenario"],
              config=env.config)
    # the stand-ins keep what they were given; the last one loaded played the match
    seen = sb3.DQN.loaded[-1].seen if kind == "sb3" else sys.modules["torch"].loaded[-1].seen
    assert len(seen) >= len(trained)
    assert all(np.array_equal(a, b) for a, b in zip(trained, seen[:len(trained)]))
    assert team.name == "learned"

