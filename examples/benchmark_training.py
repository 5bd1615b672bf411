"""One benchmark run of PPO with a shared policy (Stable-Baselines3 + SuperSuit), trained in
checkpointed chunks so that an interrupted run continues where it stopped and gives what an
uninterrupted one gives (needs the extra ``rl``: torch, Stable-Baselines3, SuperSuit).

Every chunk, up to the next checkpoint, starts the same way whether the run was interrupted or
not: the model loaded from the last checkpoint (a new one for the first chunk), every random
generator seeded and the matches reset with the chunk's seed
(:func:`examples.benchmark_baselines.chunk_seed`); it then trains until the chunk's target of
environment steps is reached (whole rollouts), saves the checkpoint (weights and optimiser state)
and the rows of ``curve.csv``. Episodes running at a checkpoint are cut there.
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np

from examples.benchmark_baselines import (CHECKPOINTS, Settings, checkpoint_path, checkpoint_targets, checkpoints, check_settings,
                                          chunk_seed, read_curve, write_curve)
from examples.ppo_shared_policy import make_env, record_episodes


def _vector(settings: Settings):
    """(SuperSuit's vector of ``settings.matches`` matches, the same under VecMonitor for PPO)."""
    import supersuit as ss
    from stable_baselines3.common.vec_env import VecMonitor

    matches = ss.pettingzoo_env_to_vec_env_v1(make_env(settings.scenario, settings.action_mode, settings.opponent))
    matches = ss.concat_vec_envs_v1(matches, settings.matches, num_cpus=0, base_class="stable_baselines3")
    return matches, VecMonitor(matches)


def _new_model(settings: Settings, env):
    from stable_baselines3 import PPO

    return PPO("MlpPolicy", env, n_steps=settings.n_steps, batch_size=settings.batch_size,
               learning_rate=settings.learning_rate, gamma=settings.gamma, gae_lambda=settings.gae_lambda,
               n_epochs=settings.n_epochs, ent_coef=0.0, device="cpu", verbose=0)


def _curve_callback(players: int, wall_before: float):
    """A Stable-Baselines3 callback collecting one curve row per rollout (its ``rows``)."""
    from stable_baselines3.common.callbacks import BaseCallback

    class Curve(BaseCallback):
        def _on_training_start(self) -> None:
            self.rows: list[dict] = []
            self.returns: list[float] = []
            self.goals: list[int] = []
            self.start = time.perf_counter()

        def _on_step(self) -> bool:
            record_episodes(self.locals["infos"], self.returns, self.goals)
            return True

        def _on_rollout_end(self) -> None:
            ended = len(self.returns)
            self.rows.append({"env_steps": self.num_timesteps // players, "agent_steps": self.num_timesteps,
                              "episodes": ended,
                              "mean_return": round(float(np.mean(self.returns)), 6) if ended else float("nan"),
                              "goal_rate": round(float(np.mean(np.asarray(self.goals) > 0)), 6) if ended
                              else float("nan"),
                              "wall_s": round(wall_before + time.perf_counter() - self.start, 1)})
            self.returns, self.goals = [], []

    return Curve()


def train(settings: Settings, run_dir: Path, budget: int) -> int:
    """Train the run in ``run_dir`` up to ``budget`` environment steps from its last checkpoint;
    returns the environment steps reached."""
    import torch
    from stable_baselines3 import PPO
    from stable_baselines3.common.utils import set_random_seed

    from experiments.results.files import write_file

    check_settings(run_dir, settings)
    (run_dir / CHECKPOINTS).mkdir(parents=True, exist_ok=True)
    torch.set_num_threads(1)  # small networks: threads only add overhead
    matches, env = _vector(settings)
    saved = checkpoints(run_dir)
    done = saved[-1][0] if saved else 0
    curve = read_curve(run_dir / "curve.csv", done)
    try:
        for chunk, target in enumerate(checkpoint_targets(budget, settings.checkpoint_every)):
            if done >= target:
                continue
            seed = chunk_seed(settings.seed, chunk)
            set_random_seed(seed)
            matches.venv.reset(seed=seed)  # PPO's own reset then continues each match's seed sequence
            model = PPO.load(checkpoint_path(run_dir, done), env=env, device="cpu") if done else \
                _new_model(settings, env)
            callback = _curve_callback(settings.players, curve[-1]["wall_s"] if curve else 0.0)
            print(f"{run_dir}: chunk {chunk} from {done} to {target} environment steps (seed {seed})", flush=True)
            model.learn(total_timesteps=settings.players * target - model.num_timesteps, callback=callback,
                        reset_num_timesteps=False)
            done = model.num_timesteps // settings.players
            write_file(checkpoint_path(run_dir, done), model.save)
            curve += callback.rows
            write_curve(run_dir / "curve.csv", curve)
            last = curve[-1]
            print(f"{run_dir}: checkpoint at {done} environment steps, {last['wall_s']:.0f} s, last rollout: "
                  f"return {last['mean_return']:+.3f}, goals in {100 * last['goal_rate']:.1f} % of "
                  f"{last['episodes']} episodes", flush=True)
    finally:
        env.close()
    return done
