"""Loaders of saved RL checkpoints: a Stable-Baselines3, torch/TorchRL, Tianshou or RLlib
checkpoint turned into the batched policy :class:`~soccer_sim.env.PolicyTeam` plays.

:func:`load_policy` ``(kind, path, ...)`` returns a :class:`CheckpointPolicy`, whose
``act_batch(observations)`` takes the team's observations as the environment gives them (an
``(n, D)`` array, or ``{"observation": (n, D), "action_mask": (n, A)}`` with the mask in the
observation) and returns ``(n, 5)`` low-level or ``(n,)`` discrete actions, one call a cycle.
Each library is imported only when its kind is loaded; these libraries are the optional extra
``rl`` (``pip install 'soccer-sim[rl]'``), and a missing one is a :class:`CheckpointError`
naming it and that command. Loading a checkpoint runs the code pickled in it (every library's
loader unpickles): load only checkpoints you trust.

The kinds (:data:`KINDS`), each with the library's own loading and acting calls:

``sb3``
    a ``.zip`` saved by ``model.save``: ``ALGORITHM.load(path, device="cpu")``, ``ALGORITHM``
    the ``algorithm`` option (default ``PPO``; a name of ``stable_baselines3`` or a dotted
    ``package.Class``), then ``model.predict(observations, deterministic=True)``.
``torch`` (also ``torchrl``)
    a module saved whole with ``torch.save(module, path)``, or a state dict
    (``torch.save(module.state_dict(), path)``) with ``constructor`` (``package.module:callable``
    making the module before ``load_state_dict``). A plain module is called on the float32
    observation tensor; a TorchRL ``TensorDictModule`` (it has ``in_keys``) on a ``TensorDict``
    whose keys ending in ``observation`` hold the observations and those ending in ``mask`` or
    ``action_mask`` the mask, under TorchRL's deterministic exploration type, its action read from
    the out key ending in ``action``.
``tianshou``
    a Tianshou policy (a torch module), saved whole or as a state dict with ``constructor``;
    called as Tianshou's collector calls it on a ``PettingZooEnv``:
    ``policy(Batch(obs=Batch(obs=..., mask=...), info=Batch()))``, its ``act`` passed through
    ``policy.map_action`` where it has one.
``rllib``
    an RLlib checkpoint directory (``algorithm.save_to_path()``): the RLModule of the policy
    ``policy`` (the only one when the option is left out) under
    ``learner_group/learner/rl_module/``, or an RLModule's own checkpoint directory, loaded with
    ``RLModule.from_checkpoint`` and asked ``forward_inference({"obs": ...})``.

Outputs become actions in one place (:func:`actions_from_output`): a discrete policy's logits
(or Q-values, or RLlib's action distribution inputs) the best allowed action (the mask applied),
integer actions as they are; low-level outputs clipped to the action space ``[-1, 1]`` (as
``predict`` does for Stable-Baselines3), of an RLlib Gaussian the mean (the first half of its
inputs).
"""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import Any, Callable

import numpy as np

from soccer_sim.errors import SoccerSimError

INSTALL = "pip install 'soccer-sim[rl]'"
"""The command that installs every library a loader may need."""

SB3_ALGORITHMS = ("A2C", "DDPG", "DQN", "PPO", "SAC", "TD3")
"""Stable-Baselines3's algorithms, named in the error for an unknown ``algorithm``."""

RLLIB_MODULES = Path("learner_group", "learner", "rl_module")
"""Where an RLlib algorithm checkpoint keeps one RLModule checkpoint per policy."""


class CheckpointError(SoccerSimError, ValueError):
    """A checkpoint that cannot be loaded: its library missing, its file missing or not of its
    kind, an option wrong; the message says which, on one line."""


def require(module: str, library: str, kind: str) -> Any:
    """The imported ``module`` of ``library``, which ``kind`` checkpoints need; a
    :class:`CheckpointError` naming the library and :data:`INSTALL` when it is not installed."""
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        raise CheckpointError(f"loading a {kind!r} checkpoint needs {library} (module {module!r}), which cannot be "
                              f"imported ({_one_line(exc)}): {INSTALL}") from None


def _one_line(exc: BaseException) -> str:
    return " ".join(str(exc).split()) or type(exc).__name__


def _failed(path: Path, what: str, exc: BaseException) -> CheckpointError:
    return CheckpointError(f"checkpoint {str(path)!r}: cannot load it as {what}: {type(exc).__name__}: "
                           f"{_one_line(exc)}")


def import_path(text: str, option: str) -> Any:
    """The object a ``package.module:attribute`` path names (the ``constructor`` option, a
    dotted ``algorithm``); a :class:`CheckpointError` naming ``option`` otherwise."""
    module_name, _, attribute = text.partition(":")
    if not module_name or not attribute:
        raise CheckpointError(f"{option} {text!r} must look like 'package.module:attribute'")
    try:
        target = importlib.import_module(module_name)
        for part in attribute.split("."):
            target = getattr(target, part)
    except Exception as exc:  # noqa: BLE001 - any failure is a bad option, said on one line
        raise CheckpointError(f"{option} {text!r}: {type(exc).__name__}: {_one_line(exc)}") from None
    return target


# ----------------------------------------------------------------------------- outputs to actions
def actions_from_output(output: Any, masks: np.ndarray | None, discrete: bool) -> np.ndarray:
    """The team's actions from a network's ``output`` for ``n`` players (see the module
    docstring): discrete: ``(n,)`` integers as they are, ``(n, A)`` scores the best action
    ``masks`` allows (every action when None); low level: ``(n, k)`` clipped to ``[-1, 1]``."""
    values = np.asarray(output)
    if discrete:
        if values.ndim == 2:
            scores = values.astype(np.float64)
            if masks is not None:
                if masks.shape != scores.shape:
                    raise ValueError(f"the policy gave scores of shape {scores.shape} for masks of shape {masks.shape}")
                scores = np.where(np.asarray(masks) > 0, scores, -np.inf)
            return np.argmax(scores, axis=1)
        return values.reshape(-1).astype(np.int64)
    return np.clip(values.astype(np.float64), -1.0, 1.0)


def _split(observations: Any) -> tuple[np.ndarray, np.ndarray | None]:
    """(``(n, D)`` observations, ``(n, A)`` masks or None) of a batch as PolicyTeam gives it."""
    if isinstance(observations, dict):
        return np.asarray(observations["observation"]), np.asarray(observations["action_mask"])
    return np.asarray(observations), None


def _numpy(value: Any) -> np.ndarray:
    """A torch tensor (or anything array-like) as a numpy array."""
    if hasattr(value, "detach"):
        value = value.detach().cpu().numpy()
    return np.asarray(value)


class CheckpointPolicy:
    """A loaded checkpoint as a batched policy: ``act_batch(observations) -> actions``
    (module docstring). ``describe`` says what was loaded (kind and path)."""

    def __init__(self, act: Callable[[Any], Any], describe: str) -> None:
        self._act = act
        self.describe = describe

    def act_batch(self, observations: Any) -> np.ndarray:
        return self._act(observations)

    def __repr__(self) -> str:
        return f"CheckpointPolicy({self.describe})"


# ----------------------------------------------------------------------------- the loaders
def _load_sb3(path: Path, discrete: bool, algorithm: str = "PPO", deterministic: bool = True) -> CheckpointPolicy:
    sb3 = require("stable_baselines3", "Stable-Baselines3", "sb3")
    if "." in algorithm:
        module, _, name = algorithm.rpartition(".")
        cls = import_path(f"{module}:{name}", "algorithm")
    else:
        cls = getattr(sb3, algorithm, None)
        if cls is None or not hasattr(cls, "load"):
            raise CheckpointError(f"algorithm {algorithm!r} is not one of Stable-Baselines3's "
                                  f"({', '.join(SB3_ALGORITHMS)}); give another as 'package.Class'")
    if not path.is_file() and not path.with_name(path.name + ".zip").is_file():
        raise CheckpointError(f"checkpoint {str(path)!r}: no such file (a Stable-Baselines3 model saved with "
                              "model.save, a .zip)")
    try:
        model = cls.load(str(path), device="cpu")
    except Exception as exc:  # noqa: BLE001 - the library's own complaint, on one line
        raise _failed(path, f"a Stable-Baselines3 {algorithm} model", exc) from None

    def act(observations: Any) -> np.ndarray:
        actions, _ = model.predict(observations, deterministic=deterministic)
        return actions_from_output(actions, _split(observations)[1], discrete)

    return CheckpointPolicy(act, f"sb3 {algorithm} {path}")


def _torch_module(path: Path, kind: str, what: str, constructor: str | None) -> Any:
    """The torch module saved at ``path``: whole, or a state dict loaded into ``constructor()``."""
    torch = require("torch", "PyTorch", kind)
    if not path.is_file():
        raise CheckpointError(f"checkpoint {str(path)!r}: no such file ({what} saved with torch.save)")
    make = import_path(constructor, "constructor") if constructor else None
    try:
        loaded = torch.load(str(path), map_location="cpu", weights_only=make is not None)
    except Exception as exc:  # noqa: BLE001
        raise _failed(path, what, exc) from None
    if make is not None:
        if not isinstance(loaded, dict):
            raise CheckpointError(f"checkpoint {str(path)!r} holds a {type(loaded).__name__}, not a state dict; "
                                  "leave out constructor for a module saved whole")
        try:
            module = make()
            module.load_state_dict(loaded)
        except Exception as exc:  # noqa: BLE001
            raise _failed(path, f"a state dict of {constructor}()", exc) from None
    elif isinstance(loaded, dict):
        raise CheckpointError(f"checkpoint {str(path)!r} holds a state dict: give constructor="
                              "package.module:callable, which makes the module it belongs to")
    else:
        module = loaded
    if not callable(module):
        raise CheckpointError(f"checkpoint {str(path)!r} holds a {type(module).__name__}, which cannot be called "
                              f"as {what}")
    if hasattr(module, "eval"):
        module.eval()
    return module, torch


def _load_torch(path: Path, discrete: bool, constructor: str | None = None) -> CheckpointPolicy:
    module, torch = _torch_module(path, "torch", "a torch module", constructor)
    if hasattr(module, "in_keys"):
        return _torchrl_policy(module, torch, path, discrete)

    def act(observations: Any) -> np.ndarray:
        rows, masks = _split(observations)
        with torch.no_grad():
            output = module(torch.as_tensor(rows, dtype=torch.float32))
        return actions_from_output(_numpy(output), masks, discrete)

    return CheckpointPolicy(act, f"torch {path}")


def _key_end(key: Any) -> str:
    return key[-1] if isinstance(key, tuple) else key


def _torchrl_policy(module: Any, torch: Any, path: Path, discrete: bool) -> CheckpointPolicy:
    """A TorchRL ``TensorDictModule`` (see the module docstring for the keys it is given)."""
    tensordict = require("tensordict", "TorchRL's tensordict", "torch")
    utils = require("torchrl.envs.utils", "TorchRL", "torch")
    for key in module.in_keys:
        if _key_end(key) not in ("observation", "mask", "action_mask"):
            raise CheckpointError(f"checkpoint {str(path)!r}: the TorchRL module reads {key!r}; a team gives only "
                                  "keys ending in 'observation' and 'mask' or 'action_mask'")
    actions = [key for key in module.out_keys if _key_end(key) == "action"]
    if not actions:
        raise CheckpointError(f"checkpoint {str(path)!r}: the TorchRL module writes no key ending in 'action' "
                              f"(its out keys: {list(module.out_keys)})")

    def act(observations: Any) -> np.ndarray:
        rows, masks = _split(observations)
        data = tensordict.TensorDict({}, batch_size=[len(rows)])
        for key in module.in_keys:
            if _key_end(key) == "observation":
                data.set(key, torch.as_tensor(rows, dtype=torch.float32))
            elif masks is None:
                raise ValueError(f"the TorchRL module reads the mask {key!r}: enter it with "
                                 "action_mask_in_observation")
            else:
                data.set(key, torch.as_tensor(masks > 0))
        with torch.no_grad(), utils.set_exploration_type(utils.ExplorationType.DETERMINISTIC):
            output = module(data)
        return actions_from_output(_numpy(output.get(actions[0])), masks, discrete)

    return CheckpointPolicy(act, f"torchrl {path}")


def _load_tianshou(path: Path, discrete: bool, constructor: str | None = None) -> CheckpointPolicy:
    data = require("tianshou.data", "Tianshou", "tianshou")
    policy, torch = _torch_module(path, "tianshou", "a Tianshou policy", constructor)
    map_action = getattr(policy, "map_action", None)

    def act(observations: Any) -> np.ndarray:
        rows, masks = _split(observations)
        if discrete:  # as Tianshou's PettingZooEnv gives it: a boolean mask, all allowed without one
            allowed = masks > 0 if masks is not None else np.ones((len(rows), _width(policy)), dtype=bool)
            seen = data.Batch(obs=rows, mask=allowed)
        else:
            seen = data.Batch(obs=rows)
        with torch.no_grad():
            result = policy(data.Batch(obs=seen, info=data.Batch()))
        actions = _numpy(result.act)
        if map_action is not None and not discrete:
            actions = _numpy(map_action(actions))
        return actions_from_output(actions, masks, discrete)

    return CheckpointPolicy(act, f"tianshou {path}")


def _width(policy: Any) -> int:
    """How many discrete actions a Tianshou policy chooses among (its action space's ``n``)."""
    space = getattr(policy, "action_space", None)
    if space is None or not hasattr(space, "n"):
        raise ValueError("the Tianshou policy has no discrete action_space to size its all-allowed mask; enter it "
                         "with action_mask_in_observation")
    return int(space.n)


def _load_rllib(path: Path, discrete: bool, policy: str | None = None) -> CheckpointPolicy:
    rl_module = require("ray.rllib.core.rl_module.rl_module", "Ray RLlib", "rllib")
    torch = require("torch", "PyTorch", "rllib")
    if not path.is_dir():
        raise CheckpointError(f"checkpoint {str(path)!r}: no such directory (an RLlib checkpoint is the directory "
                              "algorithm.save_to_path() wrote)")
    directory = _rllib_module_dir(path, policy)
    try:
        module = rl_module.RLModule.from_checkpoint(str(directory))
    except Exception as exc:  # noqa: BLE001
        raise _failed(directory, "an RLlib RLModule", exc) from None

    def act(observations: Any) -> np.ndarray:
        rows, masks = _split(observations)
        seen = torch.as_tensor(rows, dtype=torch.float32)
        if masks is not None:
            seen = {"observation": seen, "action_mask": torch.as_tensor(masks, dtype=torch.float32)}
        with torch.no_grad():
            inputs = _numpy(module.forward_inference({"obs": seen})["action_dist_inputs"])
        if not discrete:
            inputs = inputs[:, :inputs.shape[1] // 2]  # a diagonal Gaussian's inputs: the means, then log stds
        return actions_from_output(inputs, masks, discrete)

    return CheckpointPolicy(act, f"rllib {directory}")


def _rllib_module_dir(path: Path, policy: str | None) -> Path:
    """The RLModule checkpoint of ``policy`` in the algorithm checkpoint ``path`` (the only one
    when None), or ``path`` itself when it is not an algorithm checkpoint."""
    modules = path / RLLIB_MODULES
    if not modules.is_dir():
        if policy is not None:
            raise CheckpointError(f"checkpoint {str(path)!r} has no {RLLIB_MODULES.as_posix()}/ to find policy "
                                  f"{policy!r} in; give the algorithm checkpoint's directory")
        return path
    found = sorted(p.name for p in modules.iterdir() if p.is_dir())
    if policy is None:
        if len(found) != 1:
            raise CheckpointError(f"checkpoint {str(path)!r} holds the policies {', '.join(found) or '(none)'}: "
                                  "choose one with policy=NAME")
        policy = found[0]
    if policy not in found:
        raise CheckpointError(f"checkpoint {str(path)!r} has no policy {policy!r}; it has {', '.join(found) or '(none)'}")
    return modules / policy


KINDS: dict[str, tuple[Callable[..., CheckpointPolicy], tuple[str, ...]]] = {
    "sb3": (_load_sb3, ("algorithm", "deterministic")),
    "torch": (_load_torch, ("constructor",)),
    "torchrl": (_load_torch, ("constructor",)),
    "tianshou": (_load_tianshou, ("constructor",)),
    "rllib": (_load_rllib, ("policy",)),
}
"""Each checkpoint kind's loader and the options it takes (besides ``discrete``)."""


def load_policy(kind: str, path: str | Path, discrete: bool = False, **options: Any) -> CheckpointPolicy:
    """The checkpoint of ``kind`` (:data:`KINDS`) at ``path`` as a batched policy for
    :class:`~soccer_sim.env.PolicyTeam` (enter it with the action mode it was trained in;
    ``discrete``: a discrete action mode such as ``"high_level"``). ``options``: the kind's
    (``algorithm``, ``deterministic``, ``constructor``, ``policy``; module docstring).
    A :class:`CheckpointError` for a missing library, file or option."""
    if kind not in KINDS:
        raise CheckpointError(f"unknown checkpoint kind {kind!r}; the kinds are {', '.join(KINDS)}")
    loader, known = KINDS[kind]
    unknown = sorted(set(options) - set(known))
    if unknown:
        raise CheckpointError(f"a {kind!r} checkpoint takes no option {', '.join(map(repr, unknown))}; its options: "
                              f"{', '.join(known)}")
    return loader(Path(path), discrete, **options)
