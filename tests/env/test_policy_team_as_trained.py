"""PolicyTeam plays a policy as it was trained: the same observations, bit for bit, as the
environment gave for the same match; high-level (masked) actions; one call a cycle when batched."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim import MatchConfig, TeamError, run_match
from soccer_sim.env import PolicyTeam, parallel_env


class _RecordingPolicy:
    """A deterministic policy of the observation that keeps every observation it was given.
    ``choices``: a discrete mode's action count (None: low-level actions)."""

    def __init__(self, choices: int | None = None) -> None:
        self.choices = choices
        self.seen: list[np.ndarray] = []

    def act(self, observation):
        self.seen.append(np.array(observation["observation"] if isinstance(observation, dict) else observation))
        values = self.seen[-1]
        if self.choices is None:
            return np.tanh(3.0 * values[[6, 7, 10, 11, 0]] + values[4])
        if isinstance(observation, dict):  # the first allowed action after a value of the observation
            allowed = np.flatnonzero(observation["action_mask"])
            return int(allowed[int(abs(values[10]) * 97) % len(allowed)])
        return int(abs(values[10]) * 97) % self.choices


def _environment_observations(env, policy, seed: int) -> list[np.ndarray]:
    """Every observation of the controlled agents over one episode, agent by agent and cycle by cycle."""
    observations, _ = env.reset(seed=seed)
    seen = []
    while env.agents:
        seen.extend(np.array(observations[a]["observation"] if isinstance(observations[a], dict)
                             else observations[a]) for a in env.agents)
        observations, *_ = env.step({a: policy.act(observations[a]) for a in env.agents})
    return seen


@pytest.mark.parametrize("options", [
    dict(scenario="empty-goal"),
    dict(scenario="3-vs-1-with-keeper", opponent="chaser"),
    dict(scenario="empty-goal", action_mode="high_level"),
    dict(scenario="3-vs-1-with-keeper", opponent="chaser", action_mode="high_level",
         action_mask_in_observation=True),
])
def test_a_policy_team_sees_exactly_what_the_environment_gave(options) -> None:
    env = parallel_env(controlled="left", **options)
    choices = env.action_space(env.possible_agents[0]).n if options.get("action_mode") else None
    trained = _environment_observations(env, _RecordingPolicy(choices), seed=3)
    assert len(trained) >= 5 * len(env.possible_agents)  # several cycles, not only the first
    replayed = _RecordingPolicy(choices)
    team = PolicyTeam.for_env(replayed, env, name="learned")
    opponent = options.get("opponent", "static")
    run_match(team, opponent, seed=env.match_seed, scenario=options["scenario"], config=env.config)
    n = len(trained)
    assert len(replayed.seen) >= n
    assert all(np.array_equal(a, b) for a, b in zip(trained, replayed.seen[:n]))
    assert max(float(o[-2 * env.observation_slots - 2]) for o in trained) > 0.01  # the time feature ran


def test_the_time_feature_follows_the_scenario_horizon_not_the_match_length() -> None:
    seen = {}
    for horizon_of in ("empty-goal", None):
        policy = _RecordingPolicy()
        run_match(PolicyTeam(policy, scenario=horizon_of), "static", seed=0, scenario="empty-goal")
        seen[horizon_of] = policy.seen[-1]
    env = parallel_env(controlled="left", scenario="empty-goal")
    time_column = env.observation_space("left_0").shape[0] - 2 * env.observation_slots - 2
    assert env.horizon == 300
    assert seen["empty-goal"][time_column] == pytest.approx(20 * seen[None][time_column])  # 6000 / 300


class _BatchedPolicy:
    def __init__(self) -> None:
        self.calls = 0

    def act_batch(self, observations: np.ndarray) -> np.ndarray:
        self.calls += 1
        assert observations.ndim == 2
        return np.zeros(len(observations), dtype=np.int64) + 9  # everyone intercepts


def test_a_batched_high_level_policy_is_called_once_a_cycle_and_plays() -> None:
    policy = _BatchedPolicy()
    result = run_match(PolicyTeam(policy, name="interceptors", action_mode="high_level"), "idle", seed=1,
                       config=MatchConfig(max_cycles=40))
    assert policy.calls == result.cycles
    assert result.team_names[0] == "interceptors"
    moved = run_match(PolicyTeam(lambda rows: np.ones((len(rows), 5)), batched=True), "idle", seed=1,
                      config=MatchConfig(max_cycles=20))
    assert moved.cycles == 20


def test_bad_actions_and_options_are_refused_naming_what_is_wrong() -> None:
    config = MatchConfig(max_cycles=5)
    with pytest.raises(TeamError, match=r"action of player 0 must be in 0\.\.23, got 99"):
        run_match(PolicyTeam(lambda o: 99, action_mode="high_level"), "idle", config=config)
    with pytest.raises(TeamError, match="action of player 0 must be one integer"):
        run_match(PolicyTeam(lambda o: np.zeros(5), action_mode="high_level"), "idle", config=config)
    with pytest.raises(TeamError, match=r"one action per player \(11\), got 3"):
        run_match(PolicyTeam(lambda rows: np.zeros((3, 5)), batched=True), "idle", config=config)
    with pytest.raises(ValueError, match="unknown action_mode 'nope'"):
        PolicyTeam(lambda o: 0, action_mode="nope")
    with pytest.raises(ValueError, match="action_mask_in_observation needs a discrete action mode"):
        PolicyTeam(lambda o: 0, action_mask_in_observation=True)
    with pytest.raises(ValueError, match="max_cycles must be a positive integer"):
        PolicyTeam(lambda o: 0, max_cycles=0)


@pytest.mark.parametrize("mode", ["low_level", "high_level"])
def test_a_side_without_players_does_not_ask_the_policy(mode) -> None:
    def refuse(batch):
        raise AssertionError(f"asked for {len(batch)} players")

    result = run_match("static", PolicyTeam(refuse, action_mode=mode, batched=True), seed=0, scenario="empty-goal",
                       config=MatchConfig(max_cycles=30))
    assert result.cycles > 0
