"""Small stand-ins for the RL libraries' loading and acting calls (Stable-Baselines3, torch,
TorchRL's tensordict, Tianshou, RLlib), so that the checkpoint loaders are tested without
installing any of them: each mimics only the calls :mod:`soccer_sim.env.checkpoints` makes,
and records how it was called. Install them with :func:`install` (``monkeypatch``: removed
after the test). Every stand-in policy is linear in the observation, computed row by row so
that a batch of one gives the same bits as a row of a larger batch."""

from __future__ import annotations

import contextlib
import enum
import json
import pickle
import sys
import types
from pathlib import Path

import numpy as np

SB3_SOURCE = '''"""A stand-in for Stable-Baselines3's load and predict (tests only)."""
import json
from pathlib import Path

import numpy as np


class PPO:
    loaded = []

    def __init__(self, weights, discrete):
        self.weights, self.discrete, self.seen, self.calls = weights, discrete, [], []

    @classmethod
    def load(cls, path, device="auto"):
        path = Path(path) if str(path).endswith(".zip") else Path(str(path) + ".zip")
        data = json.loads(path.read_text())
        model = cls(np.array(data["weights"], dtype=np.float32), data["discrete"])
        model.device = device
        cls.loaded.append(model)
        return model

    def predict(self, observation, state=None, episode_start=None, deterministic=False):
        self.calls.append(deterministic)
        masked = isinstance(observation, dict)
        rows = observation["observation"] if masked else observation
        self.seen.extend(np.array(row) for row in rows)
        scores = np.stack([row @ self.weights for row in rows])
        if self.discrete:
            if masked:
                scores = np.where(observation["action_mask"] > 0, scores, -np.inf)
            return scores.argmax(axis=1), None
        return np.clip(np.tanh(scores), -1.0, 1.0), None


class DQN(PPO):
    loaded = []
'''
"""A Stable-Baselines3 stand-in, as source: written into a directory on the path it reaches
the worker processes of the command line too."""


def write_sb3_checkpoint(path: Path, weights: np.ndarray, discrete: bool) -> Path:
    """A checkpoint the SB3 stand-in loads (JSON, where the real library keeps a zip)."""
    path.write_text(json.dumps({"weights": np.asarray(weights).tolist(), "discrete": discrete}))
    return path


def sb3_module(directory: Path) -> types.ModuleType:
    """The SB3 stand-in as the package ``stable_baselines3`` in ``directory`` (written there)."""
    package = directory / "stable_baselines3"
    package.mkdir(parents=True, exist_ok=True)
    (package / "__init__.py").write_text(SB3_SOURCE)
    module = types.ModuleType("stable_baselines3")
    module.__file__ = str(package / "__init__.py")
    exec(compile(SB3_SOURCE, module.__file__, "exec"), module.__dict__)
    return module


# ----------------------------------------------------------------------------- torch and TorchRL
class LinearModule:
    """A torch-module stand-in: ``x @ weights`` row by row (tanh for low-level actions)."""

    def __init__(self, inputs: int = 0, outputs: int = 0, squash: bool = True, weights=None) -> None:
        self.weights = np.zeros((inputs, outputs), dtype=np.float32) if weights is None else np.asarray(weights)
        self.squash = squash
        self.seen: list[np.ndarray] = []
        self.evaluated = False

    def __call__(self, rows):
        self.seen.extend(np.array(row) for row in rows)
        scores = np.stack([row @ self.weights for row in np.asarray(rows)])
        return np.tanh(scores) if self.squash else scores

    def eval(self):
        self.evaluated = True
        return self

    def state_dict(self) -> dict:
        return {"weights": self.weights}

    def load_state_dict(self, state: dict) -> None:
        self.weights = np.asarray(state["weights"])

    def __getstate__(self):
        return {"weights": self.weights, "squash": self.squash}

    def __setstate__(self, state):
        self.__init__(squash=state["squash"], weights=state["weights"])


def make_empty_linear() -> LinearModule:
    """A constructor for state dicts (``constructor=tests.env.rl_standins:make_empty_linear``)."""
    return LinearModule(squash=False)


class TensorDictLinear(LinearModule):
    """A TorchRL ``TensorDictModule`` stand-in: reads ``in_keys`` from a TensorDict, writes the action."""

    in_keys = [("left", "observation"), ("left", "action_mask")]
    out_keys = [("left", "logits"), ("left", "action")]

    def __call__(self, data):
        exploration = sys.modules["torchrl.envs.utils"].CURRENT[-1]
        assert exploration == "DETERMINISTIC", exploration
        scores = LinearModule.__call__(self, data.get(("left", "observation")))
        scores = np.where(data.get(("left", "action_mask")), scores, -np.inf)
        data.set(("left", "action"), scores.argmax(axis=1))
        return data


class _TensorDict:
    def __init__(self, source: dict, batch_size) -> None:
        self.values, self.batch_size = dict(source), list(batch_size)

    def set(self, key, value) -> None:
        assert len(value) == self.batch_size[0]
        self.values[key] = value

    def get(self, key):
        return self.values[key]


def torch_modules(record: list) -> dict[str, types.ModuleType]:
    """``torch`` (load by unpickling, tensors as numpy arrays), ``tensordict`` and
    ``torchrl.envs.utils``; each ``torch.load`` call is appended to ``record``, what it loaded
    to ``torch.loaded``."""
    torch = types.ModuleType("torch")
    torch.float32 = np.float32
    torch.loaded = []  # every object loaded, last one last

    def load(path, map_location=None, weights_only=True):
        record.append({"path": path, "map_location": map_location, "weights_only": weights_only})
        with open(path, "rb") as file:
            torch.loaded.append(pickle.load(file))
        return torch.loaded[-1]

    torch.load = load
    torch.as_tensor = lambda value, dtype=None: np.asarray(value, dtype=dtype)
    torch.no_grad = contextlib.nullcontext
    tensordict = types.ModuleType("tensordict")
    tensordict.TensorDict = _TensorDict
    utils = types.ModuleType("torchrl.envs.utils")
    utils.ExplorationType = enum.Enum("ExplorationType", "RANDOM DETERMINISTIC")
    utils.CURRENT = ["RANDOM"]

    @contextlib.contextmanager
    def set_exploration_type(kind):
        utils.CURRENT.append(kind.name)
        yield
        utils.CURRENT.pop()

    utils.set_exploration_type = set_exploration_type
    return {"torch": torch, "tensordict": tensordict, "torchrl.envs.utils": utils}


# ----------------------------------------------------------------------------- Tianshou
class _Batch:
    def __init__(self, **values) -> None:
        self.__dict__.update(values)


class TianshouPolicy(LinearModule):
    """A Tianshou policy stand-in: ``policy(Batch(obs=Batch(obs, mask), info))`` -> ``Batch(act=...)``."""

    def __init__(self, inputs: int = 0, outputs: int = 0, weights=None) -> None:
        super().__init__(inputs, outputs, squash=False, weights=weights)
        self.action_space = types.SimpleNamespace(n=self.weights.shape[1])
        self.batches: list = []

    def __call__(self, batch):
        self.batches.append(batch)
        assert isinstance(batch.info, _Batch)
        scores = LinearModule.__call__(self, batch.obs.obs)
        if hasattr(batch.obs, "mask"):
            scores = np.where(batch.obs.mask, scores, -np.inf)
            return _Batch(act=scores.argmax(axis=1))
        return _Batch(act=scores)

    def map_action(self, act):
        return np.clip(act, -1.0, 1.0) * 0.5  # stands for Tianshou's scaling to the action space

    def __setstate__(self, state):
        self.__init__(weights=state["weights"])


def tianshou_modules() -> dict[str, types.ModuleType]:
    data = types.ModuleType("tianshou.data")
    data.Batch = _Batch
    return {"tianshou.data": data}


# ----------------------------------------------------------------------------- RLlib
class _RLModule:
    loaded: list = []

    def __init__(self, weights: np.ndarray, directory: str) -> None:
        self.weights, self.directory, self.inputs = weights, directory, []

    @classmethod
    def from_checkpoint(cls, path):
        module = cls(np.load(Path(path) / "weights.npy"), str(path))
        cls.loaded.append(module)
        return module

    def forward_inference(self, batch: dict) -> dict:
        self.inputs.append(batch)
        observation = batch["obs"]["observation"] if isinstance(batch["obs"], dict) else batch["obs"]
        return {"action_dist_inputs": np.stack([row @ self.weights for row in observation])}


def rllib_modules() -> dict[str, types.ModuleType]:
    module = types.ModuleType("ray.rllib.core.rl_module.rl_module")
    _RLModule.loaded = []
    module.RLModule = _RLModule
    return {"ray.rllib.core.rl_module.rl_module": module}


def write_rllib_checkpoint(directory: Path, policies: dict[str, np.ndarray]) -> Path:
    """An algorithm checkpoint directory holding one RLModule (its weights) per policy."""
    for policy, weights in policies.items():
        where = directory / "learner_group" / "learner" / "rl_module" / policy
        where.mkdir(parents=True)
        np.save(where / "weights.npy", weights)
    return directory


def install(monkeypatch, modules: dict[str, types.ModuleType]) -> None:
    """Put ``modules`` in ``sys.modules`` for the test (monkeypatch removes them after it)."""
    for name, module in modules.items():
        monkeypatch.setitem(sys.modules, name, module)
