"""The environment in TorchRL: wrap it, check its specs, collect a rollout.

    pip install -e ".[rl]"
    python examples/torchrl_setup.py

``PettingZooWrapper`` groups the agents by side (``left``, ``right``), stacks each group's
observations, rewards and (numeric) infos into tensors, and with ``return_state=True`` adds the
global ``state``. ``check_env_specs`` steps the wrapped environment and compares every tensor
with its spec. For the high-level actions, pass ``action_mode="high_level"`` to the environment
and ``categorical_actions=True, use_mask=True`` to the wrapper: the mask is read from
``infos[agent]["action_mask"]``.
"""

from __future__ import annotations

from soccer_sim.env import parallel_env


def make_env(**options):
    """A TorchRL environment of ``parallel_env(**options)`` (TorchRL imported here)."""
    from torchrl.envs.libs.pettingzoo import PettingZooWrapper

    high_level = options.get("action_mode") == "high_level"
    return PettingZooWrapper(env=parallel_env(**options), return_state=True, categorical_actions=high_level,
                             use_mask=high_level)


def main() -> dict:
    from torchrl.envs.utils import check_env_specs

    env = make_env(scenario="3-vs-1-with-keeper", controlled="both", rewards="dense", max_cycles=100)
    check_env_specs(env)  # raises if a tensor does not match its spec
    rollout = env.rollout(50, break_when_any_done=False)  # random actions; ended episodes restart
    summary = {"steps": rollout.batch_size[0],
               "left_reward": float(rollout["next", "left", "reward"].sum()),
               "right_reward": float(rollout["next", "right", "reward"].sum()),
               "state_shape": tuple(rollout["state"].shape)}
    print(f"check_env_specs passed; {summary['steps']} steps of random actions, summed dense rewards: "
          f"left {summary['left_reward']:+.3f}, right {summary['right_reward']:+.3f}; state {summary['state_shape']}")
    env.close()
    return summary


if __name__ == "__main__":
    main()
