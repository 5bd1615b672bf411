"""The environment in Tianshou: the AEC form in ``PettingZooEnv``, a vector of matches and a
``Collector`` filling a replay buffer.

    pip install -e ".[rl]"
    python examples/tianshou_setup.py

Every agent has the same spaces, so one policy can act for all of them (parameter sharing):
the collector's batches hold ``obs.agent_id`` beside ``obs.obs`` when a policy needs to know
whose turn it is. Put a trained Tianshou policy where the random one is. (Tianshou's
``MultiAgentPolicy``, one policy per agent, needs masked observations: use it with
``action_mode="high_level", action_mask_in_observation=True``.)
"""

from __future__ import annotations

import soccer_sim.env as soccer_env

OPTIONS = {"scenario": "3-vs-1-with-keeper", "controlled": "left", "rewards": "dense", "max_cycles": 100}


def make_env():
    from tianshou.env import PettingZooEnv

    return PettingZooEnv(soccer_env.env(**OPTIONS))


def main(steps: int = 900, matches: int = 2) -> dict:
    from tianshou.algorithm.algorithm_base import RandomActionPolicy
    from tianshou.data import Collector, VectorReplayBuffer
    from tianshou.env import DummyVectorEnv

    envs = DummyVectorEnv([make_env for _ in range(matches)])
    envs.seed(list(range(matches)))
    policy = RandomActionPolicy(make_env().action_space)  # one policy for every agent
    collector = Collector(policy, envs, VectorReplayBuffer(10 * steps, matches))
    collector.reset()
    stats = collector.collect(n_step=steps)
    summary = {"steps": int(stats.n_collected_steps), "episodes": int(stats.n_collected_episodes),
               "buffer": len(collector.buffer), "info_keys": sorted(collector.buffer.info.keys())}
    print(f"collected {summary['steps']} agent steps ({summary['episodes']} episodes ended) into a buffer of "
          f"{summary['buffer']}; info keys: {', '.join(summary['info_keys'])}")
    envs.close()
    return summary


if __name__ == "__main__":
    main()
