"""One benchmark run of MAPPO: PPO with a policy shared by the controlled players and a
centralised critic that values the environment's global ``state()``, built from TorchRL's
modules and loss (``MultiAgentMLP``, ``ProbabilisticActor`` with a ``TanhNormal``,
``ClipPPOLoss``, its GAE), trained in checkpointed chunks like the PPO runs
(``examples/benchmark_training.py``): an interrupted run continues where it stopped and gives
what an uninterrupted one gives. Needs torch and TorchRL (the extra ``rl``), imported with it.

The matches are stepped through the environment's array API (``reset_arrays``/``step_arrays``,
one after another in this process) rather than TorchRL's ``PettingZooWrapper``, whose
conversion of every step's observations, rewards and infos into tensor dicts costs several
times the environment's own step (docs/benchmark.md); the tensors of a whole rollout are built
at once. A rollout is ``n_steps`` steps of every match; the advantages (GAE) are computed once
per rollout, then ``n_epochs`` passes over minibatches of ``batch_size`` environment steps
(all the players of each), with the advantages normalised per minibatch, as Stable-Baselines3's
PPO does. An episode ended by the time limit is bootstrapped from the critic's value of its
last state; one ended by a goal, the ball going out or lost is not.

Each checkpoint is two files: ``checkpoints/steps-N.pt`` (actor, critic and optimiser state,
to continue training) and ``policies/steps-N.pt`` (the actor saved whole, which
``soccer-sim evaluate checkpoint:torchrl:...`` loads).
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np
import torch
from tensordict import TensorDict
from tensordict.nn import NormalParamExtractor, TensorDictModule
from torchrl.envs.utils import ExplorationType, set_exploration_type
from torchrl.modules import MultiAgentMLP, ProbabilisticActor, TanhNormal
from torchrl.objectives import ClipPPOLoss, ValueEstimators

from examples.benchmark_baselines import (Settings, checkpoint_path, checkpoint_targets, checkpoints, check_settings,
                                          chunk_seed, read_curve, write_curve)
from soccer_sim.env import ACTION_SIZE, parallel_env

HIDDEN = 64
"""Units of each of the two hidden layers (tanh) of the actor and of the critic."""
DEPTH = 2
CLIP = 0.2
CRITIC_COEFFICIENT = 0.5
MAX_GRAD_NORM = 0.5
ADAM_EPS = 1e-5
ALGORITHM = "mappo"


class Matches:
    """``settings.matches`` matches of the run's environment, stepped in turn through the array
    API; an ended episode restarts at once (continuing the match's seed sequence). Keeps the
    ended episodes' mean return per player and whether the home side scored."""

    def __init__(self, settings: Settings) -> None:
        self.envs = [parallel_env(scenario=settings.scenario, controlled="left", rewards=settings.rewards,
                                  action_mode=settings.action_mode, opponent=settings.opponent)
                     for _ in range(settings.matches)]
        self.players = len(self.envs[0].possible_agents)
        self.returns = np.zeros(len(self.envs))
        self.ended: list[tuple[float, bool]] = []

    def reset(self, seed: int) -> tuple[np.ndarray, np.ndarray]:
        """(observations (E, N, D), states (E, S)); match m starts from ``seed + m``."""
        observations = np.stack([env.reset_arrays(seed + m) for m, env in enumerate(self.envs)])
        self.returns[:] = 0.0
        return observations, self.states()

    def states(self) -> np.ndarray:
        return np.stack([env.state() for env in self.envs])

    def step(self, actions: np.ndarray) -> dict[str, np.ndarray]:
        """One step of every match: the step's ``next_observation``/``next_state`` (the ended
        episode's last ones where it ended), ``reward`` (E, N), ``terminated`` and ``truncated``
        (E,), and ``observation``/``state`` to act on next (a new episode's where one ended)."""
        out = {key: [] for key in ("next_observation", "next_state", "reward", "terminated", "truncated",
                                   "observation", "state")}
        for m, env in enumerate(self.envs):
            observation, reward, terminated, truncated = env.step_arrays(actions[m])
            state = env.state()
            out["next_observation"].append(observation)
            out["next_state"].append(state)
            out["reward"].append(reward)
            out["terminated"].append(bool(terminated[0]))
            out["truncated"].append(bool(truncated[0]))
            self.returns[m] += float(reward.mean())
            if terminated[0] or truncated[0]:
                goals = env.current_infos(env.possible_agents[:1])[env.possible_agents[0]]["episode_goals"]
                self.ended.append((float(self.returns[m]), int(goals[0]) > 0))
                self.returns[m] = 0.0
                observation, state = env.reset_arrays(), env.state()
            out["observation"].append(observation)
            out["state"].append(state)
        return {key: np.asarray(value) for key, value in out.items()}

    def take_ended(self) -> list[tuple[float, bool]]:
        ended, self.ended = self.ended, []
        return ended


def build_modules(observation_size: int, state_size: int, players: int):
    """(actor, critic): the actor maps each player's observation through one shared network to a
    TanhNormal over the 5 actions in [-1, 1]; the critic gives each player a value of the global
    state, from a network of its own."""
    policy_net = torch.nn.Sequential(
        MultiAgentMLP(n_agent_inputs=observation_size, n_agent_outputs=2 * ACTION_SIZE, n_agents=players,
                      centralized=False, share_params=True, depth=DEPTH, num_cells=HIDDEN,
                      activation_class=torch.nn.Tanh),
        NormalParamExtractor())
    actor = ProbabilisticActor(
        TensorDictModule(policy_net, in_keys=[("agents", "observation")], out_keys=[("agents", "loc"),
                                                                                   ("agents", "scale")]),
        in_keys=[("agents", "loc"), ("agents", "scale")], out_keys=[("agents", "action")],
        distribution_class=TanhNormal, distribution_kwargs={"low": -1.0, "high": 1.0}, return_log_prob=True,
        log_prob_key=("agents", "sample_log_prob"))
    critic = TensorDictModule(StateCritic(state_size, players), in_keys=["state"], out_keys=[("agents", "state_value")])
    return actor, critic


class StateCritic(torch.nn.Module):
    """Each player's value of the global state ``(..., S)``: the state given to every player's
    own MLP, ``(..., N, 1)``."""

    def __init__(self, state_size: int, players: int) -> None:
        super().__init__()
        self.players = players
        self.net = MultiAgentMLP(n_agent_inputs=state_size, n_agent_outputs=1, n_agents=players, centralized=False,
                                 share_params=False, depth=DEPTH, num_cells=HIDDEN, activation_class=torch.nn.Tanh)

    def forward(self, state: torch.Tensor) -> torch.Tensor:
        return self.net(state.unsqueeze(-2).expand(*state.shape[:-1], self.players, state.shape[-1]))


def _rollout(matches: Matches, actor, observation: np.ndarray, state: np.ndarray, steps: int):
    """``steps`` steps of every match with the actor's sampled actions: (the rollout as a
    TensorDict of batch (E, T), the observation and state to continue from)."""
    columns = {key: [] for key in ("observation", "state", "action", "log_prob", "next_observation", "next_state",
                                   "reward", "terminated", "truncated")}
    with torch.no_grad(), set_exploration_type(ExplorationType.RANDOM):
        for _ in range(steps):
            shape = observation.shape[:2]
            acting = TensorDict({"agents": TensorDict({"observation": torch.as_tensor(observation,
                                                                                      dtype=torch.float32)},
                                                      batch_size=shape)}, batch_size=shape[:1])
            acted = actor(acting)
            action = acted["agents", "action"].numpy()
            result = matches.step(action.astype(np.float64))
            for key, value in (("observation", observation), ("state", state), ("action", action),
                               ("log_prob", acted["agents", "sample_log_prob"].numpy())):
                columns[key].append(value)
            for key in ("next_observation", "next_state", "reward", "terminated", "truncated"):
                columns[key].append(result[key])
            observation, state = result["observation"], result["state"]

    def tensor(key: str, dtype=torch.float32):
        return torch.as_tensor(np.stack(columns[key], axis=1), dtype=dtype)  # (E, T, ...)

    E, T, N = observation.shape[0], steps, observation.shape[1]
    terminated = tensor("terminated", torch.bool)
    done = terminated | tensor("truncated", torch.bool)
    per_player = (E, T, N, 1)
    data = TensorDict({
        "agents": TensorDict({"observation": tensor("observation"), "action": tensor("action"),
                              "sample_log_prob": tensor("log_prob")}, batch_size=[E, T, N]),
        "state": tensor("state"),
        "next": TensorDict({
            "agents": TensorDict({"observation": tensor("next_observation"),
                                  "reward": tensor("reward").unsqueeze(-1),
                                  "done": done[..., None, None].expand(per_player),
                                  "terminated": terminated[..., None, None].expand(per_player)},
                                 batch_size=[E, T, N]),
            "state": tensor("next_state")}, batch_size=[E, T]),
    }, batch_size=[E, T])
    return data, observation, state


def _loss(actor, critic, settings: Settings):
    loss = ClipPPOLoss(actor_network=actor, critic_network=critic, clip_epsilon=CLIP, entropy_bonus=False,
                       critic_coeff=CRITIC_COEFFICIENT, loss_critic_type="l2", normalize_advantage=True)
    loss.set_keys(reward=("agents", "reward"), action=("agents", "action"), sample_log_prob=("agents", "sample_log_prob"),
                  value=("agents", "state_value"), done=("agents", "done"), terminated=("agents", "terminated"),
                  advantage=("agents", "advantage"), value_target=("agents", "value_target"))
    loss.make_value_estimator(ValueEstimators.GAE, gamma=settings.gamma, lmbda=settings.gae_lambda)
    return loss


def _update(loss, optimizer, data, settings: Settings, generator) -> None:
    """GAE over the rollout, then ``n_epochs`` passes over shuffled minibatches."""
    with torch.no_grad():
        loss.value_estimator(data, params=loss.critic_network_params, target_params=loss.target_critic_network_params)
    flat = data.reshape(-1)
    size = flat.batch_size[0]
    parameters = list(loss.parameters())
    for _ in range(settings.n_epochs):
        order = torch.randperm(size, generator=generator)
        for start in range(0, size, settings.batch_size):
            values = loss(flat[order[start:start + settings.batch_size]])
            total = values["loss_objective"] + values["loss_critic"]
            optimizer.zero_grad()
            total.backward()
            torch.nn.utils.clip_grad_norm_(parameters, MAX_GRAD_NORM)
            optimizer.step()


def policy_path(run_dir: Path, env_steps: int) -> Path:
    """The actor saved whole at ``env_steps`` (what the evaluation loads)."""
    return run_dir / "policies" / f"steps-{env_steps:09d}.pt"


def train(settings: Settings, run_dir: Path, budget: int) -> int:
    """Train the MAPPO run in ``run_dir`` up to ``budget`` environment steps from its last
    checkpoint; returns the environment steps reached."""
    from experiments.results.files import write_file

    check_settings(run_dir, settings)
    for folder in ("checkpoints", "policies"):
        (run_dir / folder).mkdir(parents=True, exist_ok=True)
    torch.set_num_threads(1)
    matches = Matches(settings)
    saved = checkpoints(run_dir, ALGORITHM)
    done = saved[-1][0] if saved else 0
    curve = read_curve(run_dir / "curve.csv", done)
    players = matches.players
    for chunk, target in enumerate(checkpoint_targets(budget, settings.checkpoint_every)):
        if done >= target:
            continue
        seed = chunk_seed(settings.seed, chunk)
        torch.manual_seed(seed)
        generator = torch.Generator().manual_seed(seed)
        observation, state = matches.reset(seed)
        actor, critic = build_modules(observation.shape[-1], state.shape[-1], players)
        loss = _loss(actor, critic, settings)
        optimizer = torch.optim.Adam(loss.parameters(), lr=settings.learning_rate, eps=ADAM_EPS)
        if done:
            stored = torch.load(checkpoint_path(run_dir, done, ALGORITHM), map_location="cpu", weights_only=True)
            actor.load_state_dict(stored["actor"])
            critic.load_state_dict(stored["critic"])
            optimizer.load_state_dict(stored["optimizer"])
        matches.take_ended()
        wall_before, start = (curve[-1]["wall_s"] if curve else 0.0), time.perf_counter()
        print(f"{run_dir}: chunk {chunk} from {done} to {target} environment steps (seed {seed})", flush=True)
        while done < target:
            data, observation, state = _rollout(matches, actor, observation, state, settings.n_steps)
            _update(loss, optimizer, data, settings, generator)
            done += settings.rollout_env_steps
            ended = matches.take_ended()
            curve.append({"env_steps": done, "agent_steps": done * players, "episodes": len(ended),
                          "mean_return": round(float(np.mean([r for r, _ in ended])), 6) if ended else float("nan"),
                          "goal_rate": round(float(np.mean([g for _, g in ended])), 6) if ended else float("nan"),
                          "wall_s": round(wall_before + time.perf_counter() - start, 1)})
        write_file(policy_path(run_dir, done), lambda temporary: torch.save(actor, temporary))
        write_file(checkpoint_path(run_dir, done, ALGORITHM), lambda temporary: torch.save(
            {"actor": actor.state_dict(), "critic": critic.state_dict(), "optimizer": optimizer.state_dict()},
            temporary))
        write_curve(run_dir / "curve.csv", curve)
        last = curve[-1]
        print(f"{run_dir}: checkpoint at {done} environment steps, {last['wall_s']:.0f} s, last rollout: "
              f"return {last['mean_return']:+.3f}, goals in {100 * last['goal_rate']:.1f} % of "
              f"{last['episodes']} episodes", flush=True)
    return done
