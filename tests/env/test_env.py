"""The PettingZoo environment: PettingZoo's own tests, determinism, bad input, PolicyTeam."""

from __future__ import annotations

import numpy as np
import pytest
from gymnasium import spaces
from pettingzoo.test import api_test, max_cycles_test, parallel_api_test, render_test, seed_test

import soccer_sim.env as soccer_env
from examples.random_team import RandomTeam
from examples.scripted_team import ScriptedTeam, scripted_policy
from experiments.cli import main
from soccer_sim import EventKind, MatchConfig, TeamError, run_match
from soccer_sim.env import PolicyTeam, env, observation_size, parallel_env

pytestmark = pytest.mark.filterwarnings("ignore:Agent's (minimum|maximum) observation space value")


def test_pettingzoo_parallel_api() -> None:
    parallel_api_test(parallel_env(max_cycles=40), num_cycles=40)
    parallel_api_test(parallel_env(controlled="right", opponent="chaser", max_cycles=20), num_cycles=20)


def test_pettingzoo_aec_api_and_seed() -> None:
    api_test(env(max_cycles=30), num_cycles=30)
    seed_test(lambda: env(max_cycles=30), num_cycles=30)


def test_pettingzoo_max_cycles_and_render() -> None:
    max_cycles_test(soccer_env)
    def rgb_only(render_mode=None):  # "human" needs a viewer on a display, tested below
        environment = env(max_cycles=10, render_mode="rgb_array")
        environment.metadata = {**environment.metadata, "render_modes": ["rgb_array"]}
        return environment

    render_test(rgb_only)


def _episode(seed: int, steps: int) -> list[dict[str, np.ndarray]]:
    environment = parallel_env(controlled="left", opponent="mmdr", max_cycles=steps)
    observations, _ = environment.reset(seed=seed)
    rng = np.random.default_rng(5)
    seen = [observations]
    while environment.agents:
        actions = {a: rng.uniform(-1, 1, 5).astype(np.float32) for a in environment.agents}
        observations, *_ = environment.step(actions)
        seen.append(observations)
    return seen


def test_a_whole_episode_is_determined_by_the_seed_and_actions() -> None:
    first, second = _episode(3, 250), _episode(3, 250)
    assert len(first) == len(second) == 251
    for a, b in zip(first, second):
        assert a.keys() == b.keys() and all(np.array_equal(a[k], b[k]) for k in a)
    other = _episode(4, 250)
    assert not all(np.array_equal(a["left_5"], b["left_5"]) for a, b in zip(first, other))


def test_observations_follow_the_documented_layout() -> None:
    environment = parallel_env(controlled="both")
    observations, _ = environment.reset(seed=0)
    n = 11
    assert environment.observation_space("left_3").shape == (observation_size(n, n),)
    left, right = observations["left_9"], observations["right_9"]
    state = environment._match.state
    half = 52.5
    # Own position, in each team's own frame (the home team attacks +x, the away team -x).
    np.testing.assert_allclose(left[0:2], state.pos[9] / half, rtol=1e-6)
    np.testing.assert_allclose(right[0:2], -state.pos[11 + 9] / half, rtol=1e-6)
    assert left[5] == 0 and observations["left_0"][5] == 1  # the goalkeeper flag
    np.testing.assert_allclose(left[12 + 4 * 9:12 + 4 * 9 + 2], left[0:2])  # self among the team-mates
    tail = 12 + 8 * n
    assert left[tail + 1] == 1 and left[tail + 9] == 1  # kick-off, and it is ours
    assert right[tail + 9] == 0
    presence = tail + 14  # after the 9 play modes, ours, two scores, time and half
    assert left.shape == (presence + 2 * n,) and (left[presence:] == 1).all()
    state.present[[3, 11 + 4]] = False  # a left player and a right player sent off
    observations, *_ = environment.step({agent: np.zeros(5, dtype=np.float32) for agent in environment.agents})
    left, right = observations["left_9"], observations["right_9"]
    assert np.flatnonzero(left[presence:] == 0).tolist() == [3, n + 4]  # team-mates, then opponents
    assert np.flatnonzero(right[presence:] == 0).tolist() == [4, n + 3]


def test_spaces_are_the_same_objects_every_call() -> None:
    environment = parallel_env()
    assert environment.observation_space("left_1") is environment.observation_space("left_1")
    assert environment.action_space("right_0") is environment.action_space("right_0")
    with pytest.raises(ValueError, match="unknown agent 'left_11'"):
        environment.action_space("left_11")


def test_bad_actions_name_the_agents() -> None:
    environment = parallel_env(controlled="left", opponent="idle", max_cycles=5)
    environment.reset(seed=1)
    good = {a: np.zeros(5, np.float32) for a in environment.agents}
    with pytest.raises(ValueError, match="action of left_4 is not finite"):
        environment.step({**good, "left_4": np.array([0, np.nan, 0, 0, 0])})
    with pytest.raises(ValueError, match=r"action of left_2 must have shape \(5,\), got \(4,\)"):
        environment.step({**good, "left_2": np.zeros(4)})
    with pytest.raises(ValueError, match="not live: right_0"):
        environment.step({**good, "right_0": np.zeros(5)})
    with pytest.raises(ValueError, match="no action for the live agents left_7, left_8"):
        environment.step({a: v for a, v in good.items() if a not in ("left_7", "left_8")})


def test_actions_outside_the_box_are_clipped() -> None:
    one, two = parallel_env(controlled="left", opponent="idle"), parallel_env(controlled="left", opponent="idle")
    one.reset(seed=2)
    two.reset(seed=2)
    for _ in range(20):
        big = {a: np.array([5.0, -3.0, 0, 0, 0]) for a in one.agents}
        unit = {a: np.array([1.0, -1.0, 0, 0, 0]) for a in two.agents}
        a, *_ = one.step(big)
        b, *_ = two.step(unit)
    assert all(np.array_equal(a[k], b[k]) for k in a)


def test_a_goal_rewards_the_scorers_and_ends_the_episode_when_asked() -> None:
    environment = parallel_env(controlled="left", opponent="idle", end_on_goal=True, max_cycles=1500)
    observations, _ = environment.reset(seed=0)
    total = 0.0
    while environment.agents:
        actions = {a: scripted_policy(observations[a]) for a in environment.agents}
        observations, rewards, terminations, truncations, infos = environment.step(actions)
        total += rewards["left_3"]
    assert terminations["left_3"] and not truncations["left_3"] and total == 1.0
    assert infos["left_3"]["score"].tolist() == [1, 0] and infos["left_3"]["events"][EventKind.GOAL] == 1


def test_rgb_array_and_human_render_modes(tmp_path, monkeypatch) -> None:
    environment = parallel_env(render_mode="rgb_array")
    environment.reset(seed=0)
    image = environment.render()
    assert image.dtype == np.uint8 and image.ndim == 3 and image.shape[2] == 3
    assert (image == [220, 50, 47]).all(axis=2).any() and (image == [38, 139, 210]).all(axis=2).any()
    for name in ("DISPLAY", "WAYLAND_DISPLAY"):
        monkeypatch.delenv(name, raising=False)
    (tmp_path / "a-file").write_text("")
    with pytest.raises(ValueError, match="record_dir .*a-file/rrd.*cannot make the folder"):
        parallel_env(render_mode="human", record_dir=str(tmp_path / "a-file" / "rrd"))  # refused when made
    tmp_path = tmp_path / "new" / "folder"  # made at construction
    human = parallel_env(render_mode="human", max_cycles=5, record_dir=str(tmp_path))
    assert tmp_path.is_dir()
    with pytest.warns(UserWarning, match="no display here, so the episode is recorded into .*rrd"):
        human.reset(seed=0)
    while human.agents:
        human.step({a: np.zeros(5, np.float32) for a in human.agents})
    assert human.render() is None
    files = list(tmp_path.glob("*.rrd"))
    assert len(files) == 1 and files[0].stat().st_size > 0  # the episode, recorded for a viewer elsewhere
    with pytest.raises(ValueError, match="render_mode must be"):
        parallel_env(render_mode="window")


def test_options_are_checked() -> None:
    with pytest.raises(ValueError, match="controlled must be"):
        parallel_env(controlled="middle")
    with pytest.raises(Exception, match="no-such-team"):
        parallel_env(controlled="left", opponent="no-such-team")
    with pytest.raises(ValueError, match="max_cycles"):
        parallel_env(max_cycles=0)


def test_policy_team_plays_matches_and_reports_failing_policies() -> None:
    result = run_match(ScriptedTeam(), RandomTeam(), seed=0, config=MatchConfig(max_cycles=1500))
    assert result.score[0] > result.score[1]  # the scripted team beats the random one

    def broken(observation):
        raise RuntimeError("boom")

    with pytest.raises(TeamError, match="policy of player 0 raised RuntimeError: boom"):
        run_match(PolicyTeam(broken, name="broken"), "idle", config=MatchConfig(max_cycles=5))
    with pytest.raises(TeamError, match="action of player 0 must have shape"):
        run_match(PolicyTeam(lambda o: np.zeros(3)), "idle", config=MatchConfig(max_cycles=5))
    with pytest.raises(TeamError, match="observation_slots must be an integer of at least the larger side"):
        run_match(PolicyTeam(scripted_policy, observation_slots=4), "idle", config=MatchConfig(max_cycles=5))
    environment = parallel_env(scenario="3-vs-1-with-keeper", controlled="left", opponent="idle", observation_slots=3)
    observations, _ = environment.reset(seed=0)
    seen = []
    team = PolicyTeam(lambda o: seen.append(o) or np.zeros(5), observation_slots=3)
    run_match(team, "idle", seed=environment._match_seed, scenario="3-vs-1-with-keeper")
    assert np.array_equal(seen[0], observations["left_0"])  # the same match: the same numbers
    with pytest.raises(TeamError, match=r"no policy for players \[1, 2"):
        run_match(PolicyTeam({0: scripted_policy}), "idle", config=MatchConfig(max_cycles=5))


@pytest.mark.slow  # tests/examples' scripted_in_tournament keeps a tournament of it in the default suite
def test_the_scripted_team_enters_a_tournament_from_the_command_line(tmp_path, capsys) -> None:
    assert main(["tournament", "--teams", "static,examples.scripted_team:ScriptedTeam", "--games", "2",
                 "--cycles", "300", "--workers", "2", "--out", str(tmp_path / "r.sqlite"),
                 "--tables", str(tmp_path / "t"), "--no-progress"]) == 0
    printed = capsys.readouterr().out
    assert "scripted" in printed and "examples.scripted_team" not in printed  # the team by its own name
    assert "2 matches" in printed and "0 failed" in printed


def test_high_level_actions_pass_the_api_tests_and_score() -> None:
    parallel_api_test(parallel_env(max_cycles=30, action_mode="high_level"), num_cycles=30)
    environment = parallel_env(controlled="left", opponent="idle", action_mode="high_level", max_cycles=1500,
                               end_on_goal=True)
    assert environment.action_space("left_0").n == 13 + 11
    observations, _ = environment.reset(seed=0)
    while environment.agents:  # intercept, and shoot when the ball is at one's feet
        actions = {a: 10 if np.hypot(*observations[a][10:12]) * 52.5 < 1.0 else 9 for a in environment.agents}
        observations, rewards, terminations, *_ = environment.step(actions)
    assert rewards["left_4"] == 1.0 and terminations["left_4"]


def test_high_level_pass_sends_the_ball_to_the_team_mate() -> None:
    environment = parallel_env(controlled="left", opponent="idle", action_mode="high_level")
    observations, _ = environment.reset(seed=0)
    state = environment._match.state
    nearest = min(environment.agents, key=lambda a: np.hypot(*observations[a][10:12]))
    for _ in range(60):  # the kick-off taker runs to the ball
        if np.hypot(*observations[nearest][10:12]) * 52.5 < 0.7:
            break
        observations, *_ = environment.step({a: 9 if a == nearest else 12 for a in environment.agents})
    receiver = 3
    before = np.hypot(*(state.ball - state.pos[receiver]))
    observations, *_ = environment.step({a: 13 + receiver if a == nearest else 12 for a in environment.agents})
    for _ in range(5):
        observations, *_ = environment.step({a: 12 for a in environment.agents})
    assert np.hypot(*(state.ball - state.pos[receiver])) < before - 3.0


def test_high_level_actions_are_checked() -> None:
    environment = parallel_env(controlled="left", opponent="idle", action_mode="high_level")
    environment.reset(seed=0)
    good = {a: 12 for a in environment.agents}
    with pytest.raises(ValueError, match=r"action of left_1 must be in 0..23, got 24"):
        environment.step({**good, "left_1": 24})
    with pytest.raises(ValueError, match="action of left_2 must be one integer"):
        environment.step({**good, "left_2": np.zeros(5)})
    with pytest.raises(ValueError, match="unknown action_mode 'fancy'; known: low_level, high_level"):
        parallel_env(action_mode="fancy")


def test_bench_env_reports_the_ratio(capsys) -> None:
    assert main(["bench", "env", "--cycles", "50", "--repeats", "1"]) == 0
    printed = capsys.readouterr().out
    words = " ".join(printed.split())
    assert "PettingZoo environment, 22 agents" in words and "env step / plain" in words


def test_malformed_actions_of_every_kind_name_the_agent() -> None:
    environment = parallel_env(controlled="left", opponent="idle", max_cycles=5)
    environment.reset(seed=1)
    good = {a: np.zeros(5, np.float32) for a in environment.agents}
    with pytest.raises(ValueError, match="action of left_6 must be 5 numbers"):
        environment.step({**good, "left_6": "dash"})
    with pytest.raises(ValueError, match=r"action of left_9 must have shape \(5,\), got \(1, 5\)"):
        environment.step({**good, "left_9": np.zeros((1, 5))})
    with pytest.raises(ValueError, match="action of left_1 is not finite"):
        environment.step({**good, "left_1": [0, 0, np.inf, 0, 0]})
    _, rewards, *_ , infos = environment.step({**good, "left_3": [0.5, 0.0, 0.0, 0.0, 0.0]})  # a list is fine
    infos["left_0"]["mine"] = 1
    assert "mine" not in infos["left_1"]  # every agent has its own info dict; its arrays are read-only
    with pytest.raises(ValueError, match="read-only"):
        infos["left_0"]["events"][0] = 5


@pytest.mark.slow
def test_an_environment_step_costs_at_most_twice_a_plain_cycle() -> None:
    """What `soccer-sim bench env` measures, in processor time (the machine may be shared)."""
    import statistics
    import time

    from experiments.benchmarks.env import _ReplayedPolicy

    table = np.random.default_rng(0).uniform(-1, 1, size=(997, 5)).astype(np.float32)
    cycles = 1000
    config = MatchConfig(max_cycles=cycles)
    ratios = []
    for repeat in range(6):  # the first is a warm-up
        environment = parallel_env(controlled="both", max_cycles=cycles, config=config)
        policy = _ReplayedPolicy(table)
        observations, _ = environment.reset(seed=repeat)
        start = time.process_time()
        while environment.agents:
            observations, *_ = environment.step({a: policy.act(observations[a]) for a in environment.agents})
        step = time.process_time() - start
        start = time.process_time()
        run_match(PolicyTeam(_ReplayedPolicy(table)), PolicyTeam(_ReplayedPolicy(table)), seed=repeat, config=config)
        plain = time.process_time() - start
        if repeat:
            ratios.append(step / plain)
    assert statistics.median(ratios) <= 2.0, ratios


def test_state_is_the_normalised_global_state_in_the_absolute_frame() -> None:
    environment = parallel_env(controlled="right", opponent="idle", max_cycles=3)
    environment.reset(seed=0)
    state = environment.state()
    assert isinstance(environment.state_space, spaces.Box) and environment.state_space.contains(state)
    assert state.dtype == np.float32 and state.shape == (12 * 11 + 20,)
    match = environment._match.state
    players = state[:12 * 11].reshape(22, 6)
    np.testing.assert_allclose(players[:, :2], match.pos / 52.5, rtol=1e-6)  # over the half length
    np.testing.assert_allclose(players[:, 4], 1.0)  # full stamina
    tail = state[12 * 11:]
    np.testing.assert_allclose(tail[0:2], match.ball / 52.5, rtol=1e-6, atol=1e-7)
    assert tail[6] == 0.0 and tail[8] == 1.0  # the time fraction; home attacks +x
    assert tail[9:18].tolist() == [0, 1, 0, 0, 0, 0, 0, 0, 0] and tail[18:].tolist() == [1, 0]  # home's kick-off
    environment.step({a: np.zeros(5, np.float32) for a in environment.agents})
    assert environment.state()[12 * 11 + 6] == pytest.approx(1 / 3)  # of the episode's 3 cycles


@pytest.mark.slow
def test_a_whole_match_is_determined_by_the_seed_and_actions() -> None:
    """The full-episode determinism test at full length: a regulation match, to its end."""
    def episode() -> list[dict[str, np.ndarray]]:
        environment = parallel_env(controlled="left", opponent="mmdr")
        observations, _ = environment.reset(seed=11)
        rng = np.random.default_rng(2)
        seen = [observations]
        while environment.agents:
            actions = {a: rng.uniform(-1, 1, 5).astype(np.float32) for a in environment.agents}
            observations, _, terminations, *_ = environment.step(actions)
            seen.append(observations)
        assert terminations["left_0"]
        return seen

    first, second = episode(), episode()
    assert len(first) == len(second) == 6001
    for a, b in zip(first, second):
        assert all(np.array_equal(a[k], b[k]) for k in a)
