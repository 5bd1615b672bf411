"""Train one policy shared by every controlled player with PPO (Stable-Baselines3 through
SuperSuit) on a curriculum scenario, save the reward curve, and compare the trained policy's
goals with a random policy's.

    pip install -e ".[rl]"
    nice -n 10 python examples/ppo_shared_policy.py --timesteps 600000 --out ppo-empty-goal

Parameter sharing: SuperSuit's ``pettingzoo_env_to_vec_env_v1`` turns each agent of each
match into one slot of a Stable-Baselines3 vector environment, so one network acts for all of
them (one player on ``empty-goal``, three on ``3-vs-1-with-keeper``). The rewards are the
environment's dense terms (``rewards="dense"``: goals plus ball approach, possession, ball
progress and shots), which a random policy already meets, so learning starts at once.

Writes to ``--out``: ``reward_curve.csv`` (per PPO rollout: timesteps, episodes ended, mean
episode return, share of episodes with a goal), ``reward_curve.png``, ``model.zip`` and
``evaluation.json`` (goals of the trained and of a random policy over ``--eval-episodes``
episodes with the same seeds).
"""

from __future__ import annotations

import argparse
import csv
import json
import time
from pathlib import Path

import numpy as np
from pettingzoo.utils import BaseParallelWrapper

from soccer_sim.env import parallel_env


class EpisodeGoals(BaseParallelWrapper):
    """Copies the episode's goals into ``infos[agent]["goals_for"]`` on its last step.

    SuperSuit merges the next episode's reset infos over the last step's, and the
    environment's ``episode_goals`` key is in both, so the ended episode's value would be
    lost; a key only the last step has survives."""

    def step(self, actions):
        observations, rewards, terminations, truncations, infos = self.env.step(actions)
        if not self.env.agents:
            for agent, info in infos.items():
                side = 0 if agent.startswith("left") else 1
                infos[agent] = {**info, "goals_for": int(info["episode_goals"][side])}
        return observations, rewards, terminations, truncations, infos


def record_episodes(infos, returns: list[float], goals: list[int]) -> None:
    """Append the return and the goals of each episode that ended in this step's ``infos``
    (Stable-Baselines3's monitor puts an ended episode's return under ``"episode"``)."""
    for info in infos:
        if "episode" in info:
            returns.append(float(info["episode"]["r"]))
            goals.append(int(info.get("goals_for", 0)))


def make_env(scenario: str, action_mode: str, opponent: str | None = None) -> EpisodeGoals:
    """The scenario's attacking side (``left``) played by agents, with the dense rewards."""
    options = {"scenario": scenario, "controlled": "left", "rewards": "dense", "action_mode": action_mode}
    if opponent:
        options["opponent"] = opponent
    return EpisodeGoals(parallel_env(**options))


def train(args: argparse.Namespace) -> tuple[object, list[dict]]:
    """PPO on ``args.envs`` matches; returns the model and the reward curve (one row per rollout)."""
    import supersuit as ss
    import torch
    from stable_baselines3 import PPO
    from stable_baselines3.common.callbacks import BaseCallback
    from stable_baselines3.common.utils import set_random_seed
    from stable_baselines3.common.vec_env import VecMonitor

    torch.set_num_threads(1)  # small networks: threads only add overhead
    set_random_seed(args.seed)
    vec = ss.pettingzoo_env_to_vec_env_v1(make_env(args.scenario, args.action_mode, args.opponent))
    vec = ss.concat_vec_envs_v1(vec, args.envs, num_cpus=args.processes, base_class="stable_baselines3")
    # Match i starts from seed + i; every later episode continues that match's seed sequence.
    # (SuperSuit's Stable-Baselines3 wrapper has no seed(), so PPO gets seed=None.)
    vec.venv.reset(seed=args.seed)
    vec = VecMonitor(vec)

    curve: list[dict] = []

    class Curve(BaseCallback):
        """Collects every ended episode's return and goals; one curve row per rollout."""

        def _on_training_start(self) -> None:
            self.returns, self.goals, self.start = [], [], time.perf_counter()

        def _on_step(self) -> bool:
            record_episodes(self.locals["infos"], self.returns, self.goals)
            return True

        def _on_rollout_end(self) -> None:
            if self.returns:
                curve.append({"timesteps": self.num_timesteps, "episodes": len(self.returns),
                              "mean_return": float(np.mean(self.returns)),
                              "goal_rate": float(np.mean(np.asarray(self.goals) > 0)),
                              "wall_s": round(time.perf_counter() - self.start, 1)})
                row = curve[-1]
                print(f"{row['timesteps']:>9} steps  return {row['mean_return']:+.3f}  "
                      f"goals in {100 * row['goal_rate']:5.1f}% of {row['episodes']} episodes  "
                      f"({row['wall_s']:.0f} s)", flush=True)
            self.returns, self.goals = [], []

    model = PPO("MlpPolicy", vec, n_steps=args.n_steps, batch_size=args.batch_size, learning_rate=args.learning_rate,
                gamma=0.99, gae_lambda=0.95, n_epochs=10, ent_coef=0.0, device="cpu", verbose=0)
    model.learn(total_timesteps=args.timesteps, callback=Curve())
    vec.close()
    return model, curve


def evaluate(policy, args: argparse.Namespace, episodes: int) -> dict:
    """Goals and returns of ``policy`` (observations (N, D) -> actions (N, ...), or None for
    random actions) over ``episodes`` episodes, seeds 10_000 + k (the same for every policy)."""
    environment = make_env(args.scenario, args.action_mode, args.opponent)
    goals, returns = [], []
    for k in range(episodes):
        observations, _ = environment.reset(seed=10_000 + k)
        space = environment.action_space(environment.possible_agents[0])
        space.seed(k)
        total = 0.0
        while environment.agents:
            agents = environment.agents
            if policy is None:
                actions = {agent: space.sample() for agent in agents}
            else:
                chosen = policy(np.stack([observations[agent] for agent in agents]))
                actions = dict(zip(agents, chosen))
            observations, rewards, _, _, infos = environment.step(actions)
            total += float(np.mean(list(rewards.values())))
        goals.append(infos[environment.possible_agents[0]]["goals_for"])
        returns.append(total)
    environment.close()
    return {"episodes": episodes, "goals": int(np.sum(goals)), "episodes_with_goal": int(np.sum(np.asarray(goals) > 0)),
            "mean_return": float(np.mean(returns))}


def save_curve(curve: list[dict], out: Path, title: str) -> None:
    """``reward_curve.csv`` and ``reward_curve.png`` in ``out``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    with open(out / "reward_curve.csv", "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=["timesteps", "episodes", "mean_return", "goal_rate", "wall_s"])
        writer.writeheader()
        writer.writerows(curve)
    steps = [row["timesteps"] for row in curve]
    figure, (top, bottom) = plt.subplots(2, 1, figsize=(7, 6), sharex=True)
    top.plot(steps, [row["mean_return"] for row in curve])
    top.set_ylabel("mean episode return")
    top.set_title(title)
    bottom.plot(steps, [100 * row["goal_rate"] for row in curve], color="tab:green")
    bottom.set_ylabel("episodes with a goal (%)")
    bottom.set_xlabel("agent steps")
    for axis in (top, bottom):
        axis.grid(alpha=0.3)
    figure.tight_layout()
    figure.savefig(out / "reward_curve.png", dpi=100)
    plt.close(figure)


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--scenario", default="empty-goal", help="a scenario of soccer_sim/scenarios (default: %(default)s)")
    parser.add_argument("--opponent", default=None, help="team playing the scenario's other side (default: the env's)")
    parser.add_argument("--action-mode", default="low_level", choices=("low_level", "high_level"))
    parser.add_argument("--timesteps", type=int, default=600_000, help="agent steps of training (default: %(default)s)")
    parser.add_argument("--envs", type=int, default=8, help="matches played at once (default: %(default)s)")
    parser.add_argument("--processes", type=int, default=0,
                        help="SuperSuit worker processes (default 0: all matches in this process)")
    parser.add_argument("--n-steps", type=int, default=256, help="PPO rollout length per slot (default: %(default)s)")
    parser.add_argument("--batch-size", type=int, default=256, help="PPO minibatch (default: %(default)s)")
    parser.add_argument("--learning-rate", type=float, default=3e-4, help="(default: %(default)s)")
    parser.add_argument("--eval-episodes", type=int, default=100, help="(default: %(default)s)")
    parser.add_argument("--seed", type=int, default=0, help="(default: %(default)s)")
    parser.add_argument("--out", type=Path, default=Path("ppo-run"), help="output folder (default: %(default)s)")
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> dict:
    args = parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    start = time.perf_counter()
    model, curve = train(args)
    train_s = time.perf_counter() - start
    model.save(args.out / "model.zip")
    save_curve(curve, args.out, f"PPO, shared policy, {args.scenario} ({args.action_mode})")

    def trained(observations: np.ndarray) -> np.ndarray:
        return model.predict(observations, deterministic=True)[0]

    result = {"scenario": args.scenario, "action_mode": args.action_mode, "timesteps": int(model.num_timesteps),
              "train_wall_s": round(train_s, 1), "seed": args.seed,
              "trained": evaluate(trained, args, args.eval_episodes),
              "random": evaluate(None, args, args.eval_episodes)}
    (args.out / "evaluation.json").write_text(json.dumps(result, indent=2) + "\n")
    print(f"trained for {result['timesteps']} agent steps in {train_s:.0f} s")
    for name in ("trained", "random"):
        row = result[name]
        print(f"{name:>8}: {row['goals']} goals in {row['episodes']} episodes, mean return {row['mean_return']:+.3f}")
    return result


if __name__ == "__main__":
    main()
