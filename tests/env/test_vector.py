"""The vector environment: the same numbers as single environments with the same seeds, in
process and in worker processes, auto-reset at episode ends, clear errors."""

from __future__ import annotations

import functools

import numpy as np
import pytest
from pettingzoo.utils import BaseParallelWrapper

from soccer_sim.env import parallel_env
from soccer_sim.env.vector import SubprocVectorEnv, SyncVectorEnv, vector_env

OPTIONS = {"controlled": "left", "opponent": "chaser", "max_cycles": 12}


def _actions(steps: int, envs: int, agents: int = 11, seed: int = 0) -> list[np.ndarray]:
    rng = np.random.default_rng(seed)
    return [rng.uniform(-1, 1, (envs, agents, 5)).astype(np.float32) for _ in range(steps)]


def _single_run(seed: int, actions: list[np.ndarray], options: dict) -> list[tuple]:
    """What one parallel environment gives for ``actions`` (one match's rows), resetting without
    a seed after each episode: (observations, rewards, terminated, truncated) per step."""
    environment = parallel_env(**options)
    observations, _ = environment.reset(seed=seed)
    agents = environment.possible_agents
    out = [(np.stack([observations[a] for a in agents]),)]
    for action in actions:
        observations, rewards, terminations, truncations, _ = environment.step(
            {a: action[k] for k, a in enumerate(agents)})
        row = (np.stack([observations[a] for a in agents]), np.array([rewards[a] for a in agents]),
               np.array([terminations[a] for a in agents]), np.array([truncations[a] for a in agents]))
        if not environment.agents:
            observations, _ = environment.reset()
            row = (np.stack([observations[a] for a in agents]), *row[1:], row[0])
        out.append(row)
    return out


def _vector_run(vector, seed: int, actions: list[np.ndarray]) -> list[tuple]:
    observations, infos = vector.reset(seed=seed)
    out = [(observations,)]
    for action in actions:
        observations, rewards, terminated, truncated, infos = vector.step(action)
        out.append((observations, rewards, terminated, truncated, infos))
    return out


def _assert_match_equals_single(vector_out: list[tuple], e: int, single: list[tuple]) -> None:
    assert np.array_equal(vector_out[0][0][e], single[0][0])
    for step, (got, want) in enumerate(zip(vector_out[1:], single[1:]), start=1):
        observations, rewards, terminated, truncated, infos = got
        assert np.array_equal(observations[e], want[0]), f"observations differ at step {step}"
        assert np.array_equal(rewards[e], want[1]) and np.array_equal(terminated[e], want[2])
        assert np.array_equal(truncated[e], want[3])
        if len(want) == 5:  # the episode ended: its last observations are kept in the info
            assert np.array_equal(infos[e]["final_observation"], want[4])
            assert set(infos[e]["final_info"]) == set(infos[e]) - {"final_observation", "final_info"}
        else:
            assert "final_observation" not in infos[e]


def test_in_process_matches_equal_single_environments_across_an_auto_reset() -> None:
    actions = _actions(30, 3)  # 12-cycle episodes: two automatic resets per match
    with vector_env(3, **OPTIONS) as vector:
        assert isinstance(vector, SyncVectorEnv)
        assert all(slot.arrays for slot in vector._slots)  # the batched interface, not the dicts
        assert vector.num_agents == 11 and vector.possible_agents[0] == "left_0"
        assert vector.observation_space == parallel_env(**OPTIONS).observation_space("left_0")
        out = _vector_run(vector, 7, actions)
    assert out[0][0].shape == (3, 11, vector.observation_space.shape[0]) and out[0][0].dtype == np.float32
    ends = [step for step, row in enumerate(out[1:], start=1) if row[3].all()]
    assert ends == [12, 24]
    for e in range(3):
        _assert_match_equals_single(out, e, _single_run(7 + e, [a[e] for a in actions], OPTIONS))
    # Different seeds give different matches.
    assert not np.array_equal(out[5][0][0], out[5][0][1])


def test_worker_processes_give_what_the_in_process_vector_gives() -> None:
    actions = _actions(15, 3, seed=1)
    with vector_env(3, **OPTIONS) as vector:
        local = _vector_run(vector, 2, actions)
    # fork starts faster than spawn; the spawn start is tested in the slow test below.
    with vector_env(3, processes=2, context="fork", **OPTIONS) as vector:
        assert isinstance(vector, SubprocVectorEnv)
        assert vector.observation_space == parallel_env(**OPTIONS).observation_space("left_0")
        remote = _vector_run(vector, 2, actions)
        processes = list(vector._processes)
    assert not any(process.is_alive() for process in processes)
    for got, want in zip(remote, local):
        for a, b in zip(got[:4], want[:4]):
            assert np.array_equal(a, b)
    assert np.array_equal(remote[12][4][1]["final_observation"], local[12][4][1]["final_observation"])


def test_seed_list_and_high_level_actions() -> None:
    options = {"controlled": "right", "opponent": "chaser", "max_cycles": 6, "action_mode": "high_level"}
    rng = np.random.default_rng(3)
    with vector_env(2, **options) as vector:
        assert vector.action_space.shape == ()
        actions = [rng.integers(0, vector.action_space.n, (2, 11)) for _ in range(8)]
        out = _vector_run(vector, [11, 4], actions)
        with pytest.raises(ValueError, match="must be integers"):
            vector.step(np.zeros((2, 11)))
        too_big = np.zeros((2, 11), dtype=np.int64)
        too_big[0, 3] = vector.action_space.n
        with pytest.raises(ValueError, match=rf"action of right_3 in match 0 must be in 0..{vector.action_space.n - 1}"):
            vector.step(too_big)
    assert vector.possible_agents[0] == "right_0"
    _assert_match_equals_single(out, 1, _single_run(4, [a[1] for a in actions], options))


class _DoubledRewards(BaseParallelWrapper):
    """A wrapper the vector environment must go through (it has no batched interface)."""

    def step(self, actions):
        observations, rewards, terminations, truncations, infos = self.env.step(actions)
        return observations, {a: 2 * r for a, r in rewards.items()}, terminations, truncations, infos


def _doubled(**options):
    return _DoubledRewards(parallel_env(**options))


def test_uneven_scenario_wrapped_environments_and_no_infos() -> None:
    options = {"scenario": "3-vs-1-with-keeper", "controlled": "both", "rewards": "dense", "max_cycles": 40}
    actions = _actions(60, 2, agents=5, seed=4)
    with vector_env(2, **options) as vector:
        assert vector.possible_agents == ["left_0", "left_1", "left_2", "right_0", "right_1"]
        out = _vector_run(vector, 9, actions)
    for e in range(2):
        _assert_match_equals_single(out, e, _single_run(9 + e, [a[e] for a in actions], options))
    ended = [row[4][e] for row in out[1:] for e in range(2) if "final_info" in row[4][e]]
    assert ended and all(info["final_info"]["left_0"]["episode_goals"].shape == (2,) for info in ended)
    assert any(row[1].any() for row in out[1:])  # the dense terms reward something
    with vector_env(2, env_fn=functools.partial(_doubled, **options), infos=False) as vector:
        assert not any(slot.arrays for slot in vector._slots)  # through the wrapper's step
        doubled = _vector_run(vector, 9, actions)
    for got, want in zip(doubled[1:], out[1:]):
        assert np.array_equal(got[0], want[0]) and np.allclose(got[1], 2 * want[1])
        assert all(info == {} or set(info) == {"final_observation", "final_info"} for info in got[4])


def test_bad_input_is_named() -> None:
    with pytest.raises(ValueError, match="num_envs must be a positive integer"):
        vector_env(0, **OPTIONS)
    with pytest.raises(ValueError, match="processes must be a non-negative integer"):
        vector_env(2, processes=-1, **OPTIONS)
    with pytest.raises(ValueError, match="either env_fn or parallel_env options"):
        vector_env(2, env_fn=functools.partial(parallel_env, **OPTIONS), max_cycles=3)
    with vector_env(2, env_fn=functools.partial(parallel_env, **OPTIONS)) as vector:
        with pytest.raises(ValueError, match=r"one per match"):
            vector.reset(seed=[1, 2, 3])
        vector.reset(seed=0)
        with pytest.raises(ValueError, match=r"must have shape \(2, 11, 5\)"):
            vector.step(np.zeros((2, 10, 5)))
        before = [slot.env.state().copy() for slot in vector._slots]
        bad = np.zeros((2, 11, 5))
        bad[1, 4, 0] = np.nan
        with pytest.raises(ValueError, match="action of left_4 in match 1 must be finite"):
            vector.step(bad)
        # Refused before any match stepped: both are where they were.
        assert all(np.array_equal(b, slot.env.state()) for b, slot in zip(before, vector._slots))


class _RefusesKicks(BaseParallelWrapper):
    """Raises a LookupError (an error of the worker's own making) for any kick."""

    def step(self, actions):
        if any(np.any(np.asarray(action)[2:4] != 0) for action in actions.values()):
            raise LookupError("kicks refused")
        return self.env.step(actions)


def _refusing(**options):
    return _RefusesKicks(parallel_env(**options))


def test_an_error_in_a_worker_is_raised_in_the_parent_with_its_type() -> None:
    with pytest.raises(ValueError, match="controlled must be"):
        vector_env(2, processes=1, context="fork", controlled="middle")
    with pytest.raises(ValueError, match="processes must be between 1 and num_envs=2"):
        vector_env(2, processes=3, context="fork", **OPTIONS)
    with vector_env(2, processes=2, context="fork", **OPTIONS) as vector:
        vector.reset(seed=1)
        bad = np.zeros((2, 11, 5))
        bad[1, 7, 2] = np.inf
        with pytest.raises(ValueError, match="left_7 in match 1"):
            vector.step(bad)
        vector.step(np.zeros((2, 11, 5)))  # the workers live on after an error
    with vector_env(2, processes=2, context="fork", env_fn=functools.partial(_refusing, **OPTIONS)) as vector:
        vector.reset(seed=1)
        kick = np.zeros((2, 11, 5))
        kick[1, 2, 3] = 0.5
        with pytest.raises(LookupError, match="kicks refused"):
            vector.step(kick)
        vector.step(np.zeros((2, 11, 5)))
    with pytest.raises(RuntimeError, match="closed"):
        vector.step(np.zeros((2, 11, 5)))


@pytest.mark.slow
def test_spawned_workers_give_the_same_as_single_environments() -> None:
    actions = _actions(14, 4, seed=2)
    with vector_env(4, processes=2, **OPTIONS) as vector:  # spawn, the default start method
        out = _vector_run(vector, 20, actions)
    for e in range(4):
        _assert_match_equals_single(out, e, _single_run(20 + e, [a[e] for a in actions], OPTIONS))


@pytest.mark.slow  # starts a worker process
def test_bench_env_reports_the_throughput_of_every_way(capsys) -> None:
    from experiments.cli import main

    assert main(["bench", "env", "--cycles", "30", "--repeats", "1", "--envs", "2", "--processes", "1"]) == 0
    lines = capsys.readouterr().out.splitlines()
    rows = {line.split("\t")[0]: line.split("\t")[1:] for line in lines if "\t" in line}
    for label in ("single environment (dict API)", "single environment, step_arrays",
                  "vector environment, 2 matches in process", "vector environment, 2 matches on 1 process"):
        matches, steps, agent_steps, ratio = rows[label]
        assert float(steps.replace(",", "")) > 0
        assert float(agent_steps.replace(",", "")) == pytest.approx(22 * float(steps.replace(",", "")), rel=0.01)
