"""Self-play: the learning policy plays the left side against a frozen copy of itself on the
right, and the copy is refreshed from the learner every ``--refresh-every`` steps.

    pip install -e ".[rl]"
    nice -n 10 python examples/self_play.py --timesteps 300000 --out self-play    # PPO (SB3 + SuperSuit)
    python examples/self_play.py --smoke                                          # no extra needed

The environment's own primitives make the opponent: ``opponent=`` takes any Team, and
:meth:`~soccer_sim.env.PolicyTeam.for_env` enters a policy exactly as the environment presents
it to the learner (same observations in the team's own frame, attacking +x from either side;
same action mode and horizon). The opponent's policy is a :class:`FrozenPolicy`, a holder whose
snapshot is replaced at each refresh, so the environments and their opponent are built once. The
matches run in this process, each built around the same holder (SuperSuit's ``ConcatVecEnv`` of
``MarkovVectorEnv`` s; its ``concat_vec_envs_v1`` would copy the environment by pickling, and the
refreshes would not reach the copies).

The scenario is :data:`SMALL_SIDED`, 3 against 3 from a kick-off until a goal (400 cycles at most),
with the dense rewards, so that both sides face the same task.

``--smoke`` needs neither torch nor Stable-Baselines3: the learner is a linear policy improved
by a (1+1) evolution strategy (a random change of its weights kept when its episode return
against the frozen copy, on the same seed, is higher), a few short episodes; it shows the
self-play loop end to end, not a strong policy. The PPO run writes ``model.zip`` to ``--out``,
and the scenario as ``self-play-3v3.toml``; the policy enters a tournament on it as a checkpoint
team (docs/env.md, "Saved checkpoints of RL libraries")::

    soccer-sim tournament --scenario self-play/self-play-3v3.toml --games 10 --teams \\
        "idle,chaser,checkpoint:sb3:self-play/model.zip?scenario=self-play/self-play-3v3.toml&name=self-play"
"""

from __future__ import annotations

import argparse
import copy
import json
from pathlib import Path
from typing import Any, Callable

import numpy as np

from soccer_sim.env import PolicyTeam, parallel_env
from soccer_sim.scenarios import BallStart, Scenario, Side, save_scenario

SMALL_SIDED = Scenario(
    name="self-play-3v3", description="3 against 3 without goalkeepers from a kick-off, until a goal",
    home=Side(positions=((-10.0, 0.0), (-6.0, 10.0), (-6.0, -10.0)), goalie=None),
    away=Side(positions=((10.0, 0.0), (6.0, -10.0), (6.0, 10.0)), goalie=None),
    ball=BallStart((0.0, 0.0)), start_mode="kick_off", end_on=("goal",), cycle_limit=400, half_time=False)
"""The symmetric scenario both copies play (the away side mirrors the home side)."""


class FrozenPolicy:
    """The opponent's policy: a snapshot of the learner, replaced by :meth:`refresh`.

    ``snapshot``: a batched policy, ``(n, D)`` observations to ``(n, 5)`` actions."""

    def __init__(self, snapshot: Callable[[np.ndarray], np.ndarray]) -> None:
        self.snapshot = snapshot
        self.version = 0

    def refresh(self, snapshot: Callable[[np.ndarray], np.ndarray]) -> None:
        self.snapshot = snapshot
        self.version += 1

    def act_batch(self, observations: np.ndarray) -> np.ndarray:
        return self.snapshot(observations)


def make_env(frozen: FrozenPolicy, max_cycles: int | None = None, rewards: str = "dense"):
    """The learner's environment (the left side) with ``frozen`` entered on the right as the
    environment itself would present it (:meth:`PolicyTeam.for_env` of a twin environment)."""
    options = dict(scenario=SMALL_SIDED, controlled="left", rewards=rewards, max_cycles=max_cycles)
    twin = parallel_env(**options)
    opponent = PolicyTeam.for_env(frozen, twin, name="frozen-copy")
    return parallel_env(**options, opponent=opponent)


# ----------------------------------------------------------------------------- without the rl extra
class LinearPolicy:
    """``tanh(observations @ weights)``: the smoke mode's learner."""

    def __init__(self, weights: np.ndarray) -> None:
        self.weights = weights

    def __call__(self, observations: np.ndarray) -> np.ndarray:
        return np.tanh(np.asarray(observations, dtype=np.float64) @ self.weights)


def episode_return(env, policy: Callable[[np.ndarray], np.ndarray], seed: int) -> float:
    """The left side's summed rewards over one episode on ``seed``."""
    observations, _ = env.reset(seed=seed)
    total = 0.0
    while env.agents:
        agents = list(env.agents)
        actions = policy(np.stack([observations[a] for a in agents]))
        observations, rewards, *_ = env.step(dict(zip(agents, actions)))
        total += sum(rewards.values())
    return total


def smoke(episodes: int = 6, cycles: int = 60, refresh_every: int = 2, seed: int = 0, scale: float = 0.05) -> dict:
    """Self-play with the (1+1) evolution strategy of the module docstring: ``episodes`` pairs
    of episodes of at most ``cycles`` cycles, the frozen copy refreshed after every
    ``refresh_every`` kept changes. Returns what happened."""
    rng = np.random.default_rng(seed)
    probe = parallel_env(scenario=SMALL_SIDED, controlled="left")
    size = probe.observation_space(probe.possible_agents[0]).shape[0]
    learner = LinearPolicy(rng.normal(0.0, scale, (size, 5)))
    frozen = FrozenPolicy(LinearPolicy(learner.weights.copy()))
    env = make_env(frozen, max_cycles=cycles)
    kept, returns = 0, []
    for k in range(episodes):
        candidate = LinearPolicy(learner.weights + rng.normal(0.0, scale, learner.weights.shape))
        episode_seed = seed + k  # the same episode for both: common random numbers
        now, then = episode_return(env, learner, episode_seed), episode_return(env, candidate, episode_seed)
        if then > now:
            learner, kept = candidate, kept + 1
            if kept % refresh_every == 0:
                frozen.refresh(LinearPolicy(learner.weights.copy()))
        returns.append(max(now, then))
    summary = {"episodes": episodes, "kept": kept, "refreshes": frozen.version, "returns": returns}
    print(f"self-play smoke: {episodes} candidates, {kept} kept, frozen copy refreshed {frozen.version} times; "
          f"returns {', '.join(f'{r:+.3f}' for r in returns)}")
    return summary


# ----------------------------------------------------------------------------- PPO (the rl extra)
def train(args: argparse.Namespace) -> dict:
    """PPO with parameter sharing (SuperSuit + Stable-Baselines3) against the frozen copy."""
    import torch
    from stable_baselines3 import PPO
    from stable_baselines3.common.callbacks import BaseCallback
    from stable_baselines3.common.utils import set_random_seed
    from stable_baselines3.common.vec_env import VecMonitor
    from supersuit.vector import ConcatVecEnv, MarkovVectorEnv
    from supersuit.vector.sb3_vector_wrapper import SB3VecEnvWrapper

    torch.set_num_threads(1)
    set_random_seed(args.seed)
    frozen = FrozenPolicy(lambda observations: np.zeros((len(observations), 5)))  # stands still until the first refresh

    def one_match() -> MarkovVectorEnv:
        """One match sharing ``frozen`` (``ss.concat_vec_envs_v1`` would copy the environment by
        pickling, and with it the opponent: the refreshes would not reach the copies)."""
        return MarkovVectorEnv(make_env(frozen))

    first = one_match()
    vec = SB3VecEnvWrapper(ConcatVecEnv([one_match] * args.envs, first.observation_space, first.action_space))
    vec.venv.reset(seed=args.seed)
    model = PPO("MlpPolicy", VecMonitor(vec), n_steps=512, batch_size=256, seed=args.seed, verbose=0)

    def snapshot() -> Callable[[np.ndarray], np.ndarray]:
        policy = copy.deepcopy(model.policy)
        policy.set_training_mode(False)
        return lambda observations: policy.predict(observations, deterministic=True)[0]

    class Refresh(BaseCallback):
        """Replaces the opponent's snapshot every ``--refresh-every`` steps."""

        def _on_step(self) -> bool:
            if self.num_timesteps // args.refresh_every > frozen.version:
                frozen.refresh(snapshot())
            return True

    model.learn(total_timesteps=args.timesteps, callback=Refresh())
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    model.save(out / "model.zip")
    save_scenario(SMALL_SIDED, out / "self-play-3v3.toml")
    summary = {"timesteps": args.timesteps, "refreshes": frozen.version}
    (out / "self_play.json").write_text(json.dumps(summary, indent=2))
    print(f"trained {args.timesteps} steps, the frozen copy refreshed {frozen.version} times; wrote {out}/model.zip")
    return summary


def parse_args(argv: list[str] | None = None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(description="self-play against a frozen copy of the learning policy")
    parser.add_argument("--smoke", action="store_true", help="a few episodes without the rl extra (no torch)")
    parser.add_argument("--timesteps", type=int, default=300_000)
    parser.add_argument("--refresh-every", type=int, default=20_000, help="steps between refreshes of the copy")
    parser.add_argument("--envs", type=int, default=4, help="matches stepped together (in this process)")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--out", default="self-play")
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> dict:
    args = parse_args(argv)
    if args.smoke:
        return smoke(seed=args.seed)
    return train(args)


if __name__ == "__main__":
    main()
