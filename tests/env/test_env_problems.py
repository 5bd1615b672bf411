"""One test for each way the environment used to fail a user: scenarios and uneven sides, text in
the infos, the state space, the spaces' memory leak, pickling, action masks, observation bounds,
seeds, and bad actions in the AEC form."""

from __future__ import annotations

import copy
import gc
import pickle
import weakref
from pathlib import Path

import numpy as np
import pytest
from gymnasium import spaces

from soccer_sim import EventKind
from soccer_sim.env import OBSERVATION_SLOTS, env, observation_size, parallel_env
from soccer_sim.scenarios import get_scenario, save_scenario
from soccer_sim.state import PlayMode

pytestmark = pytest.mark.filterwarnings("ignore:Agent's (minimum|maximum) observation space value")


def _random_steps(environment, steps: int, seed: int = 0) -> list:
    rng = np.random.default_rng(seed)
    environment.action_space(environment.possible_agents[0]).seed(seed)  # the one space of every agent
    seen = []
    for _ in range(steps):
        if not environment.agents:
            break
        actions = {a: environment.action_space(a).sample() for a in environment.agents} if isinstance(
            environment.action_space(environment.agents[0]), spaces.Discrete) else {
            a: rng.uniform(-1, 1, 5).astype(np.float32) for a in environment.agents}
        seen.append(environment.step(actions))
    return seen


def test_scenarios_size_the_sides_and_pad_the_observations(tmp_path: Path) -> None:
    environment = parallel_env(scenario="3-vs-1-with-keeper", controlled="both")
    assert environment.possible_agents == ["left_0", "left_1", "left_2", "right_0", "right_1"]
    observations, _ = environment.reset(seed=0)
    k = OBSERVATION_SLOTS
    space = environment.observation_space("left_0")
    assert space is environment.observation_space("right_1") and space.shape == (observation_size(k, k),)
    presence = 12 + 8 * k + 14
    left, right = observations["left_1"], observations["right_0"]
    assert left[presence:presence + k].tolist() == [1] * 3 + [0] * (k - 3)  # three team-mates, then padding
    assert left[presence + k:].tolist() == [1] * 2 + [0] * (k - 2)  # two opponents
    assert right[presence:presence + k].tolist() == [1] * 2 + [0] * (k - 2)
    assert not left[12 + 4 * 3:12 + 4 * k].any() and not left[12 + 4 * k + 4 * 2:12 + 8 * k].any()  # zeros
    state = environment._match.state
    np.testing.assert_allclose(right[12 + 4 * k:12 + 4 * k + 2], -state.pos[0] / 52.5, rtol=1e-6)  # away's frame
    # An uneven scenario steps to its own end; a file and a Scenario object work as the name does.
    while environment.agents:
        *_, terminations, truncations, _ = environment.step({a: np.ones(5, np.float32) for a in environment.agents})
    assert all(terminations.values()) and environment._match.end_reason in ("goal", "out", "lost")
    path = save_scenario(get_scenario("counter-attack"), tmp_path / "mine.json")
    for scenario in (str(path), get_scenario("counter-attack")):
        assert parallel_env(scenario=scenario, controlled="left").possible_agents == [f"left_{i}" for i in range(4)]
    with pytest.raises(ValueError, match="fields no players on the controlled side"):
        parallel_env(scenario="empty-goal", controlled="right")
    with pytest.raises(ValueError, match="no scenario called 'nowhere'"):
        parallel_env(scenario="nowhere")
    with pytest.raises(ValueError, match="observation_slots must be an integer of at least the larger side"):
        parallel_env(observation_slots=5)
    small = parallel_env(scenario="3-vs-1-with-keeper", observation_slots=3)
    assert small.observation_space("left_0").shape == (observation_size(3, 3),)


def test_a_scenario_ends_terminated_on_its_conditions_and_truncated_at_its_cycle_limit() -> None:
    environment = parallel_env(scenario="empty-goal", action_mode="high_level")
    for action, reason in ((12, "cycle_limit"), (None, "goal")):  # idle all along; intercept and shoot
        environment.reset(seed=3)
        steps = 0
        while environment.agents:
            choice = action if action is not None else (10 if environment.action_masks()[0, 10] else 9)
            _, _, terminations, truncations, _ = environment.step({"left_0": choice})
            steps += 1
        assert environment._match.end_reason == reason
        assert (terminations["left_0"], truncations["left_0"]) == ((False, True) if reason == "cycle_limit"
                                                                  else (True, False))
        assert steps == 300 if reason == "cycle_limit" else steps < 300


def test_infos_hold_only_numbers_and_fixed_shape_arrays() -> None:
    environment = parallel_env(scenario="3-vs-1-with-keeper", controlled="both", action_mode="high_level")
    _, infos = environment.reset(seed=4)
    environment.action_space("left_0").seed(4)  # one space for all agents: the sampled actions repeat
    shapes = {key: np.shape(value) for key, value in infos["left_0"].items()}
    assert set(shapes) >= {"play_mode", "cycle", "score", "events", "episode_goals", "episode_shots",
                           "episode_passes", "episode_possession", "action_mask"}
    seen_events = np.zeros(len(EventKind), dtype=np.int64)
    every = [infos]
    while environment.agents:  # random actions among those the masks allow
        every.append(environment.step({a: environment.action_space(a).sample(infos[a]["action_mask"])
                                       for a in environment.agents})[4])
        infos = every[-1]
    for infos in every:
        for info in infos.values():
            assert {key: np.shape(value) for key, value in info.items()} == shapes
            for value in info.values():
                assert isinstance(value, (int, np.ndarray)) and np.asarray(value).dtype.kind in "iuf"
        seen_events += infos["left_0"]["events"]
    assert seen_events[EventKind.KICK] > 0 and infos["left_0"]["play_mode"] in tuple(PlayMode)
    texts = parallel_env(controlled="left", opponent="idle", event_texts=True, max_cycles=3)
    _, infos = texts.reset(seed=0)
    assert infos["left_0"]["play_mode_name"] == "kick_off" and infos["left_0"]["event_texts"] == []


def test_episode_statistics_are_in_the_last_infos_and_agree_with_the_match() -> None:
    environment = parallel_env(controlled="left", opponent="chaser", max_cycles=600)
    environment.reset(seed=2)
    infos = _random_steps(environment, 600)[-1][4]["left_5"]
    statistics = environment._match.finish().statistics
    for team in (0, 1):
        assert infos["episode_goals"][team] == statistics[team].goals
        assert infos["episode_shots"][team] == statistics[team].shots
        assert infos["episode_passes"][team] == statistics[team].passes
        assert infos["episode_possession"][team] == pytest.approx(statistics[team].possession, abs=1e-6)
    assert infos["episode_passes"].sum() > 0 and infos["episode_possession"].sum() == pytest.approx(1.0)


def test_the_state_space_is_a_space_and_the_state_lies_in_it() -> None:
    environment = parallel_env(scenario="counter-attack", opponent="chaser", controlled="left")
    assert isinstance(environment.state_space, spaces.Box) and environment.state_space is environment.state_space
    assert np.isfinite(environment.state_space.low).all() and np.isfinite(environment.state_space.high).all()
    environment.reset(seed=0)
    states = [environment.state()]
    for _ in _random_steps(environment, 60):
        states.append(environment.state())
    assert all(environment.state_space.contains(s) for s in states)
    assert np.abs(np.array(states)).max() <= 2.0  # normalised, not metres and cycles


def test_a_closed_and_deleted_environment_is_freed() -> None:
    environment = parallel_env(controlled="left", opponent="idle", max_cycles=5)
    environment.observation_space("left_0"), environment.action_space("left_3")  # noqa: B018 - the old leak
    environment.reset(seed=0)
    _random_steps(environment, 3)
    reference = weakref.ref(environment)
    environment.close()
    del environment
    gc.collect()
    assert reference() is None


@pytest.mark.parametrize("copier", [lambda e: pickle.loads(pickle.dumps(e)), copy.deepcopy])
def test_a_reset_environment_round_trips_through_pickle_and_steps_identically(copier) -> None:
    environment = parallel_env(controlled="left", opponent="mmdr", scenario="counter-attack", rewards="dense")
    environment.reset(seed=8)
    _random_steps(environment, 25, seed=1)
    twin = copier(environment)
    assert twin.agents == environment.agents and np.array_equal(twin.state(), environment.state())
    rng = np.random.default_rng(3)
    while environment.agents:
        actions = {a: rng.uniform(-1, 1, 5) for a in environment.agents}
        mine, theirs = environment.step(actions), twin.step(actions)
        for a, b in zip(mine[:4], theirs[:4]):
            assert a.keys() == b.keys() and all(np.array_equal(a[k], b[k]) for k in a)
    assert not twin.agents
    fresh = copier(parallel_env(controlled="both", action_mode="high_level"))  # never reset: copies too
    assert fresh.reset(seed=1)[0].keys() == parallel_env(controlled="both").reset(seed=1)[0].keys()
    aec = env(scenario="3-vs-1-with-keeper", opponent="chaser")
    aec.reset(seed=0)
    aec.step(np.zeros(5, np.float32))
    aec_twin = pickle.loads(pickle.dumps(aec))
    for _ in range(10):
        action = np.full(5, 0.3, np.float32)
        aec.step(action)
        aec_twin.step(action)
    assert np.array_equal(aec.state(), aec_twin.state()) and aec.agent_selection == aec_twin.agent_selection


def test_high_level_action_masks() -> None:
    environment = parallel_env(scenario="empty-goal", action_mode="high_level", max_cycles=300)
    observations, infos = environment.reset(seed=3)
    mask = infos["left_0"]["action_mask"]
    assert mask.dtype == np.int8 and mask.shape == (13 + OBSERVATION_SLOTS,)
    assert mask[:10].all() and mask[12] and not mask[10] and not mask[11] and not mask[13:].any()  # ball 1.5 m off
    assert np.array_equal(environment.action_masks()[0], mask)
    for _ in range(40):  # intercept until the ball is at the player's feet
        observations, _, _, _, infos = environment.step({"left_0": 9})
        if infos["left_0"]["action_mask"][10]:
            break
    mask = infos["left_0"]["action_mask"]
    assert np.hypot(*observations["left_0"][10:12]) * 52.5 < 1.2  # kickable now
    assert mask[10] and mask[11] and mask[13] and not mask[14:].any()  # shoot, dribble, keep it; no team-mates
    speed = np.hypot(*environment._match.state.ball_vel)
    environment.step({"left_0": 10})
    assert np.hypot(*environment._match.state.ball_vel) > speed + 0.5  # the shot was taken
    dicts = parallel_env(scenario="empty-goal", action_mode="high_level", action_mask_in_observation=True)
    observations, infos = dicts.reset(seed=3)
    assert isinstance(dicts.observation_space("left_0"), spaces.Dict)
    assert set(observations["left_0"]) == {"observation", "action_mask"}
    assert dicts.observation_space("left_0").contains(observations["left_0"])
    assert "action_mask" not in infos["left_0"]  # in one place only (TorchRL's specs take it from either)
    with pytest.raises(ValueError, match="action_mask_in_observation needs a discrete action mode"):
        parallel_env(action_mask_in_observation=True)
    assert parallel_env().reset(seed=0)[1]["left_0"].get("action_mask") is None  # no mask for low-level actions


def test_observation_bounds_are_finite_and_hold() -> None:
    environment = parallel_env(controlled="both", max_cycles=200)
    space = environment.observation_space("left_0")
    assert np.isfinite(space.low).all() and np.isfinite(space.high).all() and (space.high <= 6000).all()
    assert space.high[0] == pytest.approx(57.5 / 52.5) and space.high[2] == 2.0  # field + margin, velocities
    observations, _ = environment.reset(seed=0)
    for step in [(observations,)] + _random_steps(environment, 200):
        assert all(space.contains(o) for o in step[0].values())


def test_seeds_are_checked_as_run_match_checks_them() -> None:
    environment = parallel_env(controlled="left", opponent="idle")
    for bad in (1.5, -1, "3", True):
        with pytest.raises(ValueError, match="seed must be a non-negative integer or None"):
            environment.reset(seed=bad)
    first = environment.reset(seed=np.int64(7))[0]["left_4"]
    assert np.array_equal(first, environment.reset(seed=7)[0]["left_4"])


def test_the_aec_form_reports_a_bad_action_at_its_own_agents_step() -> None:
    aec = env(controlled="left", opponent="idle", max_cycles=5)
    aec.reset(seed=0)
    assert aec.agent_selection == "left_0"
    with pytest.raises(ValueError, match="action of left_0 is not finite"):
        aec.step(np.array([np.nan, 0, 0, 0, 0], np.float32))
    assert aec.agent_selection == "left_0"  # nothing stored: left_0 may act again
    aec.step(np.zeros(5, np.float32))
    with pytest.raises(ValueError, match=r"action of left_1 must have shape \(5,\)"):
        aec.step(np.zeros(3))
    high = env(controlled="left", opponent="idle", action_mode="high_level", max_cycles=5)
    high.reset(seed=0)
    with pytest.raises(ValueError, match="action of left_0 must be in 0..23, got 99"):
        high.step(99)


def test_a_discrete_action_may_be_an_integral_float_but_not_a_fraction() -> None:
    """Some libraries' random policies give 5.0 for a Discrete space: taken as 5; 5.5 is refused."""
    environment = parallel_env(scenario="empty-goal", action_mode="high_level")
    environment.reset(seed=1)
    environment.step({"left_0": np.float32(5.0)})
    with pytest.raises(ValueError, match="action of left_0 must be one integer"):
        environment.step({"left_0": 5.5})
