"""run_match end to end: result fields, score against events, statistics, recorders, cycles."""

from __future__ import annotations

import numpy as np
import pytest
from tests.soccer_sim.core_helpers import Scripted

from soccer_sim import (AWAY, HOME, EventKind, Match, MatchConfig, MatchResult, PlayMode, TeamCommand,
                        TeamStatistics, run_match)
from soccer_sim.trivial_teams import ChaserTeam


@pytest.fixture(scope="module")
def chaser_match() -> MatchResult:
    return run_match("chaser", "chaser", seed=3, config=MatchConfig(max_cycles=1500))


def test_result_has_score_events_statistics_and_final_state(chaser_match: MatchResult) -> None:
    result = chaser_match
    assert isinstance(result.score, tuple) and len(result.score) == 2
    assert result.team_names == ("chaser", "chaser")
    assert result.cycles == 1500 == result.state.cycle
    assert result.state.play_mode == PlayMode.TIME_OVER
    goals = result.events.of_kind(EventKind.GOAL)
    assert sum(1 for g in goals if g[1] == HOME) == result.score[0]
    assert sum(1 for g in goals if g[1] == AWAY) == result.score[1]
    assert sum(result.score) > 0  # chasers do score
    home, away = result.statistics
    assert isinstance(home, TeamStatistics)
    assert (home.goals, away.goals) == result.score


def test_statistics_are_consistent_with_the_events(chaser_match: MatchResult) -> None:
    result = chaser_match
    events = result.events.as_arrays()
    for team, stats in zip((HOME, AWAY), result.statistics):
        mine = events["team"] == team
        assert stats.kicks == np.count_nonzero(mine & (events["kind"] == EventKind.KICK)) > 0
        assert stats.shots == np.count_nonzero(mine & (events["kind"] == EventKind.SHOT))
        assert stats.passes == np.count_nonzero(mine & (events["kind"] == EventKind.PASS))
        assert stats.teammate_contacts > 0  # eleven chasers bump into each other
        # Eleven players running most of 1500 cycles at up to 1.05 m/cycle.
        assert 1000.0 < stats.distance_run < 11 * 1500 * 1.05
    assert result.statistics[0].possession + result.statistics[1].possession == pytest.approx(1.0)
    # Every goal (own goals aside) is a shot, even when the ball's noise carried in a kick
    # whose noiseless path fell short.
    goals = result.events.of_kind(EventKind.GOAL)
    for team, stats in zip((HOME, AWAY), result.statistics):
        assert stats.shots >= sum(1 for g in goals if g[1] == team and g[5] == 0)


def test_idle_players_run_nowhere_and_concede(chaser_match: MatchResult) -> None:
    result = run_match("chaser", "idle", seed=1, config=MatchConfig(max_cycles=1500))
    assert result.score[0] > 0 and result.score[1] == 0
    assert result.statistics[1].distance_run < 0.05 * result.statistics[0].distance_run
    assert result.statistics[1].kicks == 0
    assert result.statistics[1].passes == 0  # balls bouncing between idle bodies are not passes
    assert result.statistics[0].shots >= result.score[0]


def test_max_cycles_and_recorders_see_every_cycle() -> None:
    calls: list[str] = []

    class Counter:
        def on_start(self, match: Match) -> None:
            calls.append(f"start {match.state.cycle}")

        def on_cycle(self, match: Match) -> None:
            calls.append("cycle")

        def on_end(self, match: Match) -> None:
            calls.append(f"end {match.state.cycle}")

    run_match("idle", "idle", config=MatchConfig(max_cycles=25), recorders=[Counter()])
    assert calls[0] == "start 0" and calls[-1] == "end 25"
    assert calls.count("cycle") == 25


def test_team_reported_statistics_are_merged() -> None:
    class Reporting(ChaserTeam):
        def statistics(self) -> dict[str, float]:
            return {"role_switches": 7}

    result = run_match(Reporting(), "idle", config=MatchConfig(max_cycles=10))
    assert result.statistics[0].reported == {"role_switches": 7.0}
    assert result.statistics[0].as_dict()["role_switches"] == 7.0
    assert "role_switches" not in result.statistics[1].as_dict()


def test_kick_off_moves_place_players_in_their_own_half() -> None:
    n = MatchConfig().players_per_team
    targets = np.column_stack([np.linspace(-40, -5, n), np.linspace(-20, 20, n)])
    home = Scripted(move=targets)
    result = run_match(home, Scripted(), config=MatchConfig(max_cycles=2))
    assert np.allclose(result.state.pos[:n], targets, atol=1e-6)
    # Away's targets are in its own frame: the same numbers land turned around.
    away = Scripted(move=targets)
    result = run_match(Scripted(), away, config=MatchConfig(max_cycles=2))
    assert np.allclose(result.state.pos[n:], -targets, atol=1e-6)


def test_each_team_gets_its_own_seeded_rng_and_side_info() -> None:
    home, away = Scripted(), Scripted()
    match = Match(home, away, seed=11, config=MatchConfig(max_cycles=1))
    match.run()
    assert home.side_info.team == HOME and away.side_info.team == AWAY
    assert home.side_info.players_per_team == 11 and home.side_info.goalie_index == 0
    a, b = home.rng.random(), away.rng.random()
    assert a != b
    again_home = Scripted()
    Match(again_home, Scripted(), seed=11, config=MatchConfig(max_cycles=1)).run()
    assert np.isclose(again_home.rng.random(), a)


def test_a_match_is_played_once_and_a_team_object_plays_one_side() -> None:
    match = Match("idle", "idle", config=MatchConfig(max_cycles=1))
    match.run()
    with pytest.raises(RuntimeError, match="only once"):
        match.run()
    assert match.state.play_mode == PlayMode.TIME_OVER
    with pytest.raises(RuntimeError, match="match is over"):
        match.step()
    team = ChaserTeam()
    with pytest.raises(ValueError, match="both sides"):
        Match(team, team)
    with pytest.raises(ValueError, match="seed"):
        Match("idle", "idle", seed=-1)
    with pytest.raises(TypeError, match="MatchConfig"):
        Match("idle", "idle", config={"max_cycles": 3})


def test_the_state_owns_its_arrays_and_what_is_written_into_them_is_played() -> None:
    """The state's arrays cannot be replaced (so nothing can fall out of step with the
    physics); a position written into them in place is where the physics moves the player from."""
    match = Match("idle", "idle", config=MatchConfig(max_cycles=5))
    match.start()
    state = match.state
    arrays = {name: getattr(state, name) for name in
              ("pos", "vel", "ball", "ball_vel", "stamina", "effort", "recovery", "capacity", "score", "bodies")}
    for name in arrays:
        with pytest.raises(AttributeError):
            setattr(state, name, arrays[name].copy())
    state.pos[5] = (-20.0, 10.0)
    state.vel[5] = (0.5, 0.0)
    match.step()
    assert all(getattr(state, name) is array for name, array in arrays.items())
    assert state.pos[5].tolist() == pytest.approx([-19.5, 10.0], abs=0.05)  # moved on from there
    assert np.shares_memory(state.bodies, state.pos) and np.shares_memory(state.bodies, state.ball)


def test_chaser_kicks_towards_the_opponents_goal_in_its_own_frame() -> None:
    from soccer_sim.config import MatchConfig as Config
    from soccer_sim.team import SideInfo, TeamView

    team = ChaserTeam()
    team.reset(SideInfo(AWAY, "c", "x", 2, 0, 2, 0), Config(players_per_team=2), np.random.default_rng(0))
    view = TeamView(own_pos=np.array([[-1.0, 0.0], [-10.0, 5.0]]), own_vel=np.zeros((2, 2)),
                    opp_pos=np.zeros((2, 2)), opp_vel=np.zeros((2, 2)), ball=np.array([0.0, 0.0]),
                    ball_vel=np.zeros(2), stamina=np.ones(2))
    command = team.act(view)
    assert isinstance(command, TeamCommand)
    # one body command each: the player with the ball in reach kicks, the other runs at the ball
    assert np.allclose(command.kick, [[2.7, 0.0], [0.0, 0.0]])
    assert not command.dash[0].any() and command.dash[1, 0] > 0 and command.dash[1, 1] < 0


def test_distance_run_counts_running_not_standing() -> None:
    from tests.soccer_sim.core_helpers import quiet_config

    def run_right(view):
        dash = np.zeros((11, 2))
        dash[1] = (1.0, 0.0)  # along the left wing: nobody in the way
        return dash, np.zeros((11, 2))

    result = run_match(Scripted(run_right), Scripted(), config=quiet_config(max_cycles=30))
    # A full-power dash gives 0.6 m/cycle²: the speed in cycle k is 0.6 (1 + 0.4 + ... + 0.4^(k-1)).
    expected = sum(0.6 * (1 - 0.4 ** k) / (1 - 0.4) for k in range(1, 31))
    assert result.statistics[0].distance_run == pytest.approx(expected)
    assert result.statistics[1].distance_run == 0.0
    assert result.statistics[0].possession == result.statistics[1].possession == 0.0  # nobody touched the ball


def test_goalkeeper_kicks_a_held_ball_away_through_its_own_body() -> None:
    from tests.soccer_sim.core_helpers import quiet_config

    from soccer_sim.state import NO_PLAYER

    def clear(view):
        kick = np.zeros((11, 2))
        if view.ball_holder == 0:
            kick[0] = (2.0, 0.5)  # own frame: away from the own goal
        return np.zeros((11, 2)), kick

    match = Match(Scripted(clear), Scripted(), config=quiet_config(max_cycles=10))
    match.start()
    state = match.state
    state.pos[0] = (-48.0, 2.0)
    state.play_mode, state.mode_team, state.ball_holder = PlayMode.GOALIE_HOLDS, HOME, 0
    state.ball[:] = state.pos[0]
    state.ball_vel[:] = 0.0
    match.step()
    assert state.ball_holder == NO_PLAYER and state.play_mode == PlayMode.PLAY_ON
    assert 0 not in match.touchers.tolist()
    assert state.ball[0] == pytest.approx(-46.0) and state.ball[1] == pytest.approx(2.5)
    assert state.ball_vel[0] == pytest.approx(2.0 * CONFIG_BALL_DECAY)


CONFIG_BALL_DECAY = MatchConfig().physics.ball_decay


class RuleWatcher:
    """Recorder checking, after every cycle of a real match, what the referee must guarantee."""

    def on_start(self, match: Match) -> None:
        self.broken: list[str] = []
        self.mode_cycles = 0
        self.previous = (match.state.play_mode, match.state.mode_start)

    def on_cycle(self, match: Match) -> None:
        state, config = match.state, match.config
        f, n = config.field, state.players_per_team
        cycle = state.cycle - 1
        if np.abs(state.pos[:, 0]).max() > f.half_length + f.margin or np.abs(state.pos[:, 1]).max() > f.half_width + f.margin:
            self.broken.append(f"{cycle}: a player beyond the field's margin")
        out_x = abs(state.ball[0]) > f.half_length + config.physics.ball_radius
        out_y = abs(state.ball[1]) > f.half_width + config.physics.ball_radius
        if state.play_mode != PlayMode.TIME_OVER and (out_x or out_y):
            self.broken.append(f"{cycle}: the ball left the field and play went on")
        mode = state.play_mode
        if mode not in (PlayMode.PLAY_ON, PlayMode.TIME_OVER):
            if cycle - state.mode_start + 1 > config.rules.set_play_timeout:
                self.broken.append(f"{cycle}: {mode.name} outlasted its time limit")
        if mode == PlayMode.GOALIE_HOLDS:
            row = state.ball_holder
            if row != state.mode_team * n + config.rules.goalie_index:
                self.broken.append(f"{cycle}: the ball is held by row {row}, not the goalkeeper")
            depth = state.attack_direction(state.mode_team) * state.pos[row, 0] + f.half_length
            if not (0 <= depth <= f.penalty_area_length and abs(state.pos[row, 1]) <= f.penalty_area_width / 2):
                self.broken.append(f"{cycle}: the goalkeeper holds the ball outside its penalty area")
        if mode in (PlayMode.KICK_OFF, PlayMode.KICK_IN, PlayMode.CORNER_KICK, PlayMode.GOAL_KICK, PlayMode.FREE_KICK):
            other = slice((1 - state.mode_team) * n, (2 - state.mode_team) * n)
            gap = np.hypot(*(state.pos[other] - state.ball).T).min()
            if gap < config.rules.set_play_clearance - 1e-9:
                self.broken.append(f"{cycle}: an opponent {gap:.2f} m from the ball at a {mode.name}")

    def on_end(self, match: Match) -> None:
        pass


@pytest.mark.parametrize("home, away, seed", [("chaser", "chaser", 5), ("chaser", "idle", 6)])
def test_a_real_match_keeps_the_rules_every_cycle(home: str, away: str, seed: int) -> None:
    watcher = RuleWatcher()
    result = run_match(home, away, seed=seed, config=MatchConfig(max_cycles=2000), recorders=[watcher])
    assert watcher.broken == []
    events = list(zip(result.events.cycle, result.events.kind, result.events.team, result.events.detail))
    goals = [i for i, e in enumerate(events) if e[1] == EventKind.GOAL]
    assert goals
    pause = MatchConfig().rules.goal_pause_cycles
    for i in goals:  # a pause from the goal's cycle, then the team that conceded kicks off
        cycle, _, scorer, _ = events[i]
        assert events[i + 1] == (cycle, EventKind.SET_PLAY, 1 - scorer, PlayMode.AFTER_GOAL)
        assert events[i + 2] == (cycle + pause, EventKind.SET_PLAY, 1 - scorer, PlayMode.KICK_OFF)
