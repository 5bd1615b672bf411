"""The environment under partial observation: each agent's observation from its own view only,
the say action and heard messages, the options, PettingZoo's checks, arrays, vectors, pickling."""

from __future__ import annotations

import pickle
from dataclasses import fields, replace

import numpy as np
import pytest
from pettingzoo.test import api_test, parallel_api_test, parallel_seed_test

from soccer_sim import MatchConfig, run_match
from soccer_sim.env import PolicyTeam, env, parallel_env
from soccer_sim.env.partial_spaces import (BALL_AGE_CAP, UNIDENTIFIED_SLOTS, PartialObservationBuilder,
                                           partial_observation_size)
from soccer_sim.env.say_codec import ALPHABET, LEVELS, SayCodec
from soccer_sim.env.vector import vector_env
from soccer_sim.perception import SAY_CHARACTERS, AudioParams
from soccer_sim.perception.config import ObservationConfig
from soccer_sim.perception.views import PlayerViews
from soccer_sim.trivial_teams import IdleTeam

pytestmark = pytest.mark.filterwarnings("ignore::UserWarning")
PARTIAL = dict(observation="partial", opponent="chaser")
STEP = 1.0 / (LEVELS - 1)
"""Half a quantisation step of the codec: the most a decoded value is off."""


def _random_run(environment, steps: int, seed: int) -> list[np.ndarray]:
    size = environment.action_space(environment.possible_agents[0]).shape[0]
    rng = np.random.default_rng(seed)
    seen = [environment.reset_arrays(seed=seed)]
    for _ in range(steps):
        if not environment.agents:  # the episode ended
            break
        obs, *_ = environment.step_arrays(rng.uniform(-1, 1, (len(environment.possible_agents), size)))
        seen.append(obs)
    return seen


def test_pettingzoo_api_tests_pass_under_partial_observation_and_with_the_say_action() -> None:
    parallel_api_test(parallel_env(**PARTIAL, controlled="left", max_cycles=12), num_cycles=12)
    parallel_api_test(parallel_env(**PARTIAL, controlled="both", say_values=3, max_cycles=12), num_cycles=12)
    api_test(env(**PARTIAL, controlled="right", max_cycles=10), num_cycles=10)
    api_test(env(**PARTIAL, scenario="3-vs-1-with-keeper", say_values=3, max_cycles=10), num_cycles=10)
    parallel_seed_test(lambda: parallel_env(**PARTIAL, controlled="left", say_values=2, max_cycles=10), num_cycles=10)


def test_spaces_sizes_and_observations_within_the_space() -> None:
    environment = parallel_env(**PARTIAL, controlled="both", say_values=2, max_cycles=60)
    space = environment.observation_space("left_0")
    assert space.shape == (partial_observation_size(11, 2),) == (16 + 66 + 4 * UNIDENTIFIED_SLOTS + 14 + 5,)
    assert np.isfinite(space.low).all() and np.isfinite(space.high).all()
    assert environment.action_space("right_4").shape == (5 + 1 + 2,)
    assert parallel_env(**PARTIAL).observation_space("left_0").shape == (partial_observation_size(11),)
    for obs in _random_run(environment, 60, seed=2):
        assert obs.dtype == np.float32 and np.isfinite(obs).all()
        assert all(space.contains(row) for row in obs)
    assert environment.state_space.contains(environment.state())


def test_the_layout_follows_each_agents_own_view() -> None:
    environment = parallel_env(**PARTIAL, controlled="left", max_cycles=40)
    obs = environment.reset_arrays(seed=4)
    match, half = environment._match, environment.config.field.length / 2
    rng = np.random.default_rng(0)
    last_ball, last_cycle = np.zeros((11, 2)), np.full(11, -10 ** 9)
    for _ in range(30):
        views = match.observer.views[0]
        seen = views.ball_seen
        last_ball[seen], last_cycle[seen] = views.ball[seen], views.cycle
        np.testing.assert_allclose(obs[:, 0:2], views.position / half, atol=1e-6)
        assert np.abs(views.position - match.state.pos[:11]).max() < 1.5  # the belief is near the truth
        np.testing.assert_allclose(obs[:, 6], np.cos(np.radians(views.body_direction)), atol=1e-6)
        assert np.array_equal(obs[:, 8], views.saw) and np.array_equal(obs[:, 15], seen)
        np.testing.assert_allclose(obs[:, 10:12], last_ball / half, atol=1e-6)
        np.testing.assert_allclose(obs[:, 14], np.minimum(views.cycle - last_cycle, BALL_AGE_CAP) / BALL_AGE_CAP)
        for i in np.flatnonzero(views.saw):  # the slots of a see: identified players by number
            me = views.player(i)
            for where, side, number in zip(me.players, me.player_sides, me.player_numbers):
                if number >= 0:
                    col = 16 + 3 * number + (33 if side < 0 else 0)
                    np.testing.assert_allclose(obs[i, col:col + 3], [*(where / half), 1.0], atol=1e-6)
            assert obs[i, 16 + 3 * i + 2] == 1.0  # its own slot
            anonymous = me.player_numbers < 0
            filled = obs[i, 82:82 + 4 * UNIDENTIFIED_SLOTS].reshape(-1, 4)
            assert filled[:, 3].sum() == min(anonymous.sum(), UNIDENTIFIED_SLOTS)
        obs, *_ = environment.step_arrays(rng.uniform(-1, 1, (11, 5)))
    assert views.saw.sum() < 11 or views.ball_seen.sum() < 11  # partial: not everyone sees everything


def _copy(views: PlayerViews) -> PlayerViews:
    return replace(views, **{f.name: getattr(views, f.name).copy() for f in fields(views)
                             if isinstance(getattr(views, f.name), np.ndarray)})


def _scramble(views: PlayerViews, keep: int, rng: np.random.Generator) -> PlayerViews:
    """``views`` with every row but ``keep`` replaced by other perceptions and messages."""
    out = _copy(views)
    others = np.array([i for i in range(views.n) if i != keep])
    for f in fields(out):
        array = getattr(out, f.name)
        if isinstance(array, np.ndarray) and f.name != "player_types":
            if array.dtype == bool:
                array[others] = rng.random(array[others].shape) < 0.5
            elif array.dtype.kind in "iu":
                array[others] = rng.integers(0 if f.name == "seen_count" else -1, 3, array[others].shape)
            else:
                array[others] = rng.uniform(-40, 40, array[others].shape)
    out.heard_mates = tuple(views.heard_mates[i] if i == keep else ((0, "AbCdEf"),) for i in range(views.n))
    out.heard_opponents = tuple(views.heard_opponents[i] if i == keep else ("x",) for i in range(views.n))
    return out


def test_an_agents_observation_uses_only_its_own_row_of_the_views() -> None:
    environment = parallel_env(**PARTIAL, controlled="both", say_values=3, max_cycles=30)
    environment.reset_arrays(seed=1)
    config, rng = environment.config, np.random.default_rng(9)
    real, scrambled = (PartialObservationBuilder(11, 11, 0, config, say_values=3) for _ in range(2))
    keep = 6
    for t in range(25):
        views = environment._match.observer.views[0]
        a = real.build(_copy(views))
        b = scrambled.build(_scramble(views, keep, rng))
        assert np.array_equal(a[keep], b[keep]), t  # memories included: over 25 cycles
        assert not np.array_equal(np.delete(a, keep, 0), np.delete(b, keep, 0))
        speak = np.zeros((22, 9))
        speak[:, 5], speak[:, 6:] = 1.0, rng.uniform(-1, 1, (22, 3))  # everyone talks
        environment.step_arrays(speak)


def _kick_off_run(goalie_dash: float, observation: str = "partial", steps: int = 20) -> list[np.ndarray]:
    environment = parallel_env(observation=observation, controlled="both", max_cycles=steps)
    seen = [environment.reset_arrays(seed=3)]
    for _ in range(steps):
        actions = np.zeros((22, 5))
        actions[0, 1] = goalie_dash  # the left goalkeeper runs along its goal line, far behind left_6
        seen.append(environment.step_arrays(actions)[0])
    return seen


def test_a_player_out_of_view_moving_differently_leaves_the_observation_unchanged() -> None:
    still, moving = _kick_off_run(0.0), _kick_off_run(1.0)
    environment = parallel_env(observation="partial", controlled="both")
    environment.reset(seed=3)
    pos, left_6 = environment._match.state.pos, 6
    behind = pos[0] - pos[left_6]
    assert behind[0] < -30 and abs(behind[1]) < 1  # straight behind left_6, which faces the ball ahead
    assert not np.array_equal(still[-1][0], moving[-1][0])  # the goalkeeper knows it moved
    full_still, full_moving = _kick_off_run(0.0, "full"), _kick_off_run(1.0, "full")
    assert not np.array_equal(full_still[-1][left_6], full_moving[-1][left_6])  # full observation shows it
    for a, b in zip(still, moving):
        assert np.array_equal(a[left_6], b[left_6])


def test_a_message_reaches_the_team_mates_in_range_decoded_next_step() -> None:
    environment = parallel_env(**PARTIAL, controlled="both", say_values=3, max_cycles=20)
    environment.reset_arrays(seed=5)
    hear = partial_observation_size(11, 0)  # the hear part follows the rest
    said = np.array([0.25, -0.731, 1.0])
    actions = np.zeros((22, 9))
    actions[3, 5], actions[3, 6:] = 1.0, said  # left_3 speaks
    pos = environment._match.state.pos.copy()  # where everyone is when left_3 speaks
    obs, *_ = environment.step_arrays(actions)
    in_range = np.hypot(*(pos - pos[3]).T) <= 50.0  # the channel's audio_cut_dist, from where it spoke
    in_range[3] = False
    mates = np.flatnonzero(in_range[:11])
    assert len(mates) >= 5 and not in_range[:11].all()
    for i in mates:
        np.testing.assert_allclose(obs[i, hear:hear + 3], said, atol=STEP + 1e-6)
        assert obs[i, hear + 3] == 1.0 and obs[i, hear + 4] == pytest.approx(3 / 10)
    assert not obs[:11][~in_range[:11] & (np.arange(11) != 3), hear + 3].any()  # out of range: nothing
    opponents = 11 + np.flatnonzero(in_range[11:])
    assert len(opponents) and (obs[opponents, hear + 5] == 1.0).all()  # an opponent was heard ...
    assert not obs[opponents, hear + 3].any()  # ... but its message is not theirs to decode
    quiet, *_ = environment.step_arrays(np.zeros((22, 9)))  # nobody spoke: nothing heard
    assert not quiet[:, hear:].any()


def test_the_codec_round_trips_and_refuses_foreign_messages_quietly() -> None:
    codec = SayCodec(5)
    values = np.array([[-1.0, 1.0, 0.0, 0.123456, -0.5], [2.0, -3.0, 0.9999, -0.0001, 0.5]])
    messages = codec.encode(values, np.array([True, True]))
    assert all(len(m) == 10 and set(m) <= set(ALPHABET) for m in messages)
    assert set(ALPHABET) <= set(SAY_CHARACTERS) and not set(ALPHABET) & set(" ()") and len(ALPHABET) == 71
    for message, row in zip(messages, values):
        np.testing.assert_allclose(codec.decode(message), np.clip(row, -1, 1), atol=STEP + 1e-12)
    assert codec.decode(messages[0]) [0] == -1.0 and codec.decode(messages[0])[1] == 1.0
    assert codec.encode(values, np.array([False, True]))[0] is None
    for foreign in ("abc", messages[0][:8], "(" + messages[0][1:], "é" * 10, None, 42):
        assert codec.decode(foreign) is None
    with pytest.raises(ValueError, match="1 to 5 values"):
        SayCodec(6)


def test_undecodable_team_mate_messages_count_as_nothing_heard() -> None:
    environment = parallel_env(**PARTIAL, controlled="left", say_values=2, max_cycles=5)
    environment.reset_arrays(seed=0)
    views = _copy(environment._match.observer.views[0])
    good = SayCodec(2).encode(np.array([[0.5, -0.5]]), np.array([True]))[0]
    views.heard_mates = ((3, "hello"),), ((4, "(*)"),), ((2, "hello"), (5, good)), *((),) * 8
    builder = PartialObservationBuilder(11, 11, 0, environment.config, say_values=2)
    hear = builder.build(views)[:, partial_observation_size(11, 0):]
    assert not hear[:2].any()  # foreign messages: flag 0, values 0
    np.testing.assert_allclose(hear[2], [0.5, -0.5, 1.0, 0.5, 0.0], atol=STEP + 1e-6)  # the decodable one, from 5


def test_the_memories_last_between_sightings_and_over_half_time_and_end_with_the_match() -> None:
    environment = parallel_env(**PARTIAL, controlled="left", max_cycles=5)
    environment.reset_arrays(seed=0)
    views = _copy(environment._match.observer.views[0])
    builder = PartialObservationBuilder(11, 11, 0, environment.config)
    seen = builder.build(views)
    assert seen[:, 15].any() and seen[:, 8].any()
    blind = _copy(views)
    blind.ball_seen[:], blind.saw[:], blind.cycle = False, False, views.cycle + 7
    later = builder.build(blind)
    kept = views.ball_seen
    np.testing.assert_array_equal(later[kept, 10:12], seen[kept, 10:12])  # where it last saw the ball
    np.testing.assert_allclose(later[kept, 14], 7 / BALL_AGE_CAP)
    np.testing.assert_array_equal(later[:, 16:82], seen[:, 16:82])  # the last see's slots
    blind.half = 1  # the teams keep their ends: what was seen is where it was
    second = builder.build(blind)
    np.testing.assert_array_equal(second[kept, 10:12], seen[kept, 10:12])
    np.testing.assert_array_equal(second[:, 16:82], seen[:, 16:82])
    builder.reset()  # a new match
    second = builder.build(blind)
    assert not second[:, 10:12].any() and (second[:, 14] == 1.0).all() and (second[:, 9] == 1.0).all()
    own = 16 + 3 * np.arange(11)
    assert second[:, 16:82].sum() == pytest.approx(second[np.arange(11)[:, None], own[:, None] + [0, 1, 2]].sum())


class _FullOnly(IdleTeam):
    """A team written for the exact TeamView only."""

    name = "full-only"
    observation_modes = ("full",)


def test_bad_options_are_refused_naming_the_option() -> None:
    cases = [(dict(observation="partly"), "observation must be 'full' or 'partial'"),
             (dict(say_values=2), "say_values=2 needs partial observation"),
             (dict(observation="partial", say_values=6), "say_values must be an integer from 0 to 5"),
             (dict(observation="partial", say_values=-1), "say_values must be"),
             (dict(observation="partial", say_values=True), "say_values must be"),
             (dict(observation="partial", say_values=2.0), "say_values must be"),
             (dict(observation="partial", action_mode="high_level"), "action_mode 'high_level' needs the exact"),
             (dict(observation="partial", controlled="left", opponent=_FullOnly()),
              "opponent 'full-only' cannot play under partial"),
             (dict(observation="full", config=MatchConfig(observation=ObservationConfig("partial"))),
              "observation='full' contradicts"),
             (dict(observation="partial", say_values=5, config=MatchConfig(observation=ObservationConfig(
                 "partial", audio=AudioParams(say_msg_size=8)))), "more than the config's say_msg_size 8")]
    for options, message in cases:
        with pytest.raises(ValueError, match=message.replace("(", r"\(")):
            parallel_env(**options)
    from_config = parallel_env(config=MatchConfig(observation=ObservationConfig("partial")), controlled="both")
    assert from_config.partial and from_config.observation_space("left_0").shape == (partial_observation_size(11),)
    assert parallel_env(observation="partial", controlled="left", scenario="empty-goal").partial  # no opponent
    environment = parallel_env(**PARTIAL, controlled="left", say_values=1)
    environment.reset(seed=0)
    with pytest.raises(ValueError, match=r"action of left_2 must have shape \(7,\)"):
        environment.step({a: np.zeros(5 if a == "left_2" else 7) for a in environment.agents})


def test_full_observation_is_unchanged_by_the_option() -> None:
    default, explicit = parallel_env(controlled="left", opponent="chaser", max_cycles=15), \
        parallel_env(controlled="left", opponent="chaser", max_cycles=15, observation="full")
    assert not default.partial and default.observation_space("left_0") == explicit.observation_space("left_0")
    for a, b in zip(_random_run(default, 15, 1), _random_run(explicit, 15, 1)):
        assert np.array_equal(a, b)


def test_the_state_is_the_truth_and_partial_observation_leaves_play_alone() -> None:
    full, partial = parallel_env(controlled="both", max_cycles=12), parallel_env(**PARTIAL, controlled="both",
                                                                                max_cycles=12)
    assert full.state_space == partial.state_space
    rng = np.random.default_rng(4)
    full.reset_arrays(seed=2)
    partial.reset_arrays(seed=2)
    for _ in range(12):
        actions = rng.uniform(-1, 1, (22, 5))
        full.step_arrays(actions)
        partial.step_arrays(actions)
        assert np.array_equal(full.state(), partial.state())


def test_episodes_are_determined_by_the_seed_and_copies_step_identically() -> None:
    options = dict(PARTIAL, controlled="left", say_values=2, scenario="counter-attack", max_cycles=40)
    first, second = _random_run(parallel_env(**options), 30, 5), _random_run(parallel_env(**options), 30, 5)
    assert len(first) == len(second) > 5 and all(np.array_equal(a, b) for a, b in zip(first, second))
    assert not np.array_equal(first[3], _random_run(parallel_env(**options), 30, 6)[3])
    environment = parallel_env(**options)
    _random_run(environment, 12, 7)  # memories, messages in flight: replayed by the copy
    twin = pickle.loads(pickle.dumps(environment))
    rng = np.random.default_rng(1)
    for _ in range(10):
        actions = rng.uniform(-1, 1, (len(environment.possible_agents), 8))
        for mine, theirs in zip(environment.step_arrays(actions), twin.step_arrays(actions)):
            assert np.array_equal(mine, theirs)


def test_step_and_arrays_and_the_vector_environment_agree_under_partial_observation() -> None:
    options = dict(PARTIAL, controlled="right", say_values=1, max_cycles=8)
    rng = np.random.default_rng(2)
    actions = rng.uniform(-1, 1, (8, 11, 7))
    arrays, dicts = parallel_env(**options), parallel_env(**options)
    arrays.reset_arrays(seed=3)
    observations, _ = dicts.reset(seed=3)
    with vector_env(2, **options) as vector:
        stacked, _ = vector.reset(seed=3)
        for step in range(8):
            obs, *_ = arrays.step_arrays(actions[step])
            observations, *_ = dicts.step({a: actions[step, k] for k, a in enumerate(dicts.possible_agents)})
            out, *_ = vector.step(np.stack([actions[step], actions[step]]))
            if step < 7:  # the vector resets a match at its end
                assert np.array_equal(out[0], obs)
            assert np.array_equal(np.stack([observations[a] for a in dicts.possible_agents]), obs)


def test_policy_team_plays_partial_observation_as_the_environment_builds_it() -> None:
    scenario, config = "3-vs-1-with-keeper", MatchConfig(observation=ObservationConfig("partial"))
    environment = parallel_env(observation="partial", scenario=scenario, controlled="left", opponent="idle",
                               say_values=2, observation_slots=3)
    first = environment.reset_arrays(seed=0)
    script = np.random.default_rng(6).uniform(-1, 1, (10, 3, 8))
    got = [first] + [environment.step_arrays(script[t])[0] for t in range(9)]
    seen: list[np.ndarray] = []
    calls = iter(range(10 ** 6))

    def policy(observation: np.ndarray) -> np.ndarray:
        k = next(calls)
        seen.append(observation)
        return script[min(k // 3, 9), k % 3]

    run_match(PolicyTeam(policy, observation_slots=3, say_values=2), "idle", seed=environment._match_seed,
              scenario=scenario, config=replace(config, max_cycles=10))
    time = 16 + 18 + 4 * UNIDENTIFIED_SLOTS + 12  # the time feature: the match's horizon, not the episode's
    for t in range(10):
        mine = np.delete(np.stack(seen[3 * t:3 * t + 3]), time, axis=1)
        assert np.array_equal(mine, np.delete(got[t], time, axis=1)), t
    assert got[9][:, -5:-2].any()  # messages were heard: the say action played in the match too
