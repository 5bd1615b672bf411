"""The environment in Ray RLlib: PPO with one policy shared by every controlled player.

    pip install -e ".[rl]"
    python examples/rllib_setup.py --iterations 5

RLlib's ``ParallelPettingZooEnv`` turns the parallel environment into a ``MultiAgentEnv``;
``policy_mapping_fn`` maps every agent to the one policy ``shared``. The first iteration
includes Ray's start-up (tens of seconds on a small machine). For the high-level actions with
an action-masking RLModule, ``action_mode="high_level", action_mask_in_observation=True`` makes
the observations ``{"observation", "action_mask"}`` dicts.
"""

from __future__ import annotations

import argparse

ENV_CONFIG = {"scenario": "3-vs-1-with-keeper", "controlled": "left", "rewards": "dense"}


def make_env(config: dict):
    """RLlib's environment creator: ``config`` is the ``env_config`` (options of ``parallel_env``)."""
    from ray.rllib.env.wrappers.pettingzoo_env import ParallelPettingZooEnv

    from soccer_sim.env import parallel_env

    return ParallelPettingZooEnv(parallel_env(**config))


def shared_policy(agent_id, episode, **kwargs) -> str:
    return "shared"


def main(iterations: int = 2, batch: int = 512) -> list[float]:
    import ray
    from ray.rllib.algorithms.ppo import PPOConfig
    from ray.tune.registry import register_env

    ray.init(num_cpus=1, include_dashboard=False, log_to_driver=False, ignore_reinit_error=True)
    register_env("soccer_sim", make_env)
    config = (PPOConfig()
              .environment("soccer_sim", env_config=ENV_CONFIG)
              .env_runners(num_env_runners=0)  # sample in the driver; raise for more processes
              .multi_agent(policies={"shared"}, policy_mapping_fn=shared_policy)
              .training(train_batch_size_per_learner=batch, minibatch_size=128, num_epochs=4))
    algorithm = config.build_algo()
    returns = []
    try:
        for iteration in range(iterations):
            result = algorithm.train()
            runners = result["env_runners"]
            returns.append(float(runners.get("episode_return_mean", float("nan"))))
            print(f"iteration {iteration + 1}: {int(runners['num_env_steps_sampled_lifetime'])} steps, "
                  f"mean episode return {returns[-1]:+.3f}")
    finally:
        algorithm.stop()
        ray.shutdown()
    return returns


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description="PPO on the environment with RLlib, one shared policy")
    parser.add_argument("--iterations", type=int, default=2)
    main(parser.parse_args().iterations)
