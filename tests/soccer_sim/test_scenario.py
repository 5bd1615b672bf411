"""Scenarios: bad input refused by name, end conditions, uneven and empty sides, start states,
rule switches, files and the library (with the trivial teams; the built-in teams are in
test_scenario_teams.py)."""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest

from experiments.cli import main
from soccer_sim import EventKind, Match, MatchConfig, PlayMode, Scenario, ScenarioError, run_match
from soccer_sim.scenarios import (
    BallStart,
    Side,
    get_scenario,
    library,
    load_scenario,
    save_scenario,
    scenario_from_dict,
    scenario_names,
)
from soccer_sim.team import TeamCommand

CONFIG = MatchConfig()


class Recording:
    """Stands still; keeps what the match told it (side info, view shapes)."""

    def reset(self, side_info, config, rng):
        self.info = side_info
        self.shapes = set()
        n = side_info.players_per_team
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view):
        self.shapes.add((view.own_pos.shape, view.opp_pos.shape, view.stamina.shape))
        return self.command


def nobody(**kwargs) -> Scenario:
    """0 v 0 with the ball as given, one period."""
    return Scenario(name="empty", home=Side(players=0), away=Side(players=0), start_mode="play_on",
                    half_time=False, **kwargs)


# ---------------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("make, field", [
    (lambda: Scenario(home=Side(players=12)), "home.players"),
    (lambda: Scenario(away=Side(positions=[(float(i), 0.0) for i in range(12)])), "away.positions"),
    (lambda: Scenario(home=Side(players=3, goalie=3)), "home.goalie"),
    (lambda: Scenario(away=Side(positions=[(1.0, 1.0), (2.0, 2.0)], goalie=5)), "away.goalie"),
    (lambda: Scenario(home=Side(positions=[(1.0, 1.0), (5.0, 5.0), (1.0, 1.0)])), "home.positions[2]"),
    (lambda: Scenario(home=Side(players=2, positions=[(1.0, 1.0)])), "home.positions"),
    (lambda: Scenario(away=Side(players=0), end_on=("lost",)), "end_on"),
    (lambda: nobody(end_on=("goal",)), "end_on"),
    (lambda: Scenario(end_on=("goal", "offside")), "end_on"),
    (lambda: Scenario(start_mode="penalty"), "start_mode"),
    (lambda: Scenario(start_mode="corner_kick", set_plays=False), "start_mode"),
    (lambda: Scenario(cycle_limit=0), "cycle_limit"),
    (lambda: Scenario(attacker="left"), "attacker"),
    (lambda: Scenario(ball=BallStart(area=((10.0, 5.0), (0.0, 0.0)))), "ball.area"),
    (lambda: Scenario(home=Side(jitter=-1.0)), "home.jitter"),
    (lambda: Scenario(start_mode=[]), "start_mode"),
    (lambda: Scenario(start_team=["home"]), "start_team"),
    (lambda: Scenario(attacker={}), "attacker"),
    (lambda: Scenario(home=Side(positions=[(1.0, 1.0), (1.0, 1.0)], relative_to_ball=True),
                      ball=BallStart(area=((0.0, 0.0), (5.0, 5.0)))), "home.positions[1]"),
])
def test_bad_scenarios_are_refused_naming_the_field(make, field):
    with pytest.raises(ScenarioError) as info:
        make()
    assert info.value.field == field
    assert f"Scenario.{field}:" in str(info.value)


def test_end_conditions_that_cannot_fire_are_allowed_with_a_cycle_limit():
    Scenario(away=Side(players=0), end_on=("lost",), cycle_limit=100)
    nobody(end_on=("goal", "out"), cycle_limit=10)
    nobody(end_on=("goal",), ball=BallStart(velocity=(1.0, 0.0)))


@pytest.mark.parametrize("scenario, field", [
    (Scenario(home=Side(positions=[(60.0, 0.0)])), "home.positions[0]"),
    (Scenario(away=Side(positions=[(0.0, -34.5)])), "away.positions[0]"),
    (Scenario(ball=BallStart(position=(0.0, 40.0))), "ball.position"),
    (Scenario(ball=BallStart(area=((0.0, 0.0), (53.0, 1.0)))), "ball.area[1]"),
    (Scenario(home=Side(positions=[(10.0, 0.0)]), away=Side(positions=[(10.2, 0.1)])), "away.positions[0]"),
    (Scenario(home=Side(positions=[(10.0, 0.0)], velocities=[(2.0, 0.0)])), "home.velocities[0]"),
    (Scenario(ball=BallStart(velocity=(3.5, 0.0))), "ball.velocity"),
    (Scenario(home=Side(players=0)), None),
    # randomised starts: the layout before the draws must not overlap
    (Scenario(home=Side(positions=[(10.0, 0.0)], jitter=0.5), away=Side(positions=[(10.0, 0.0)])), "away.positions[0]"),
    (Scenario(home=Side(positions=[(1.0, 1.0), (1.2, 1.0)], relative_to_ball=True), away=Side(players=0),
              ball=BallStart(area=((0.0, 0.0), (5.0, 5.0)))), "home.positions[1]"),
    (Scenario(home=Side(positions=[(1.0, 1.0)], relative_to_ball=True), away=Side(positions=[(1.0, 1.1)]),
              ball=BallStart(area=((0.0, 0.0), (5.0, 5.0)))), None),  # apart or not depends on the draw
])
def test_what_depends_on_the_field_is_checked_when_the_match_is_made(scenario, field):
    if field is None:
        Match("idle", "idle", scenario=scenario)
        return
    with pytest.raises(ScenarioError) as info:
        Match("idle", "idle", config=CONFIG, scenario=scenario)
    assert info.value.field == field


def test_the_goalie_index_of_the_configuration_must_fit_an_explicit_side():
    scenario = Scenario(home=Side(players=2, goalie=1))
    with pytest.raises(ScenarioError, match="home.goalie"):
        Match("idle", "idle", scenario=Scenario(home=Side(goalie=11)))
    assert Match("idle", "idle", scenario=scenario).goalies == (1, 0)


def test_an_unknown_library_name_lists_the_library():
    with pytest.raises(ScenarioError, match="empty-goal"):
        run_match("idle", "idle", scenario="no-such-scenario")


# ---------------------------------------------------------------------------------- end conditions
def test_a_goal_ends_the_match_and_counts():
    result = run_match("chaser", "idle", seed=1, scenario="empty-goal")
    assert result.end_reason == "goal" and result.score == (1, 0)
    assert result.cycles < 300
    kinds, details = result.events.kind, result.events.detail
    goal = kinds.index(EventKind.GOAL)
    assert kinds[goal + 1:] == [EventKind.SET_PLAY, EventKind.TIME_OVER, EventKind.SET_PLAY]
    assert details[goal + 1] == PlayMode.AFTER_GOAL and details[-1] == PlayMode.TIME_OVER
    assert result.state.play_mode == PlayMode.TIME_OVER


def test_a_ball_rolling_in_with_nobody_on_the_field_is_a_goal_for_home():
    result = run_match("idle", "idle", scenario=nobody(end_on=("goal",), ball=BallStart((40.0, 0.0), (2.0, 0.0))))
    assert result.end_reason == "goal" and result.score == (1, 0)
    assert result.statistics[0].distance_run == 0.0 and result.statistics[1].distance_run == 0.0


def test_scored_ends_the_match_only_on_a_goal_of_the_attacking_side():
    ball = BallStart((-40.0, 0.0), (-2.0, 0.0))  # into home's goal: a goal for away
    against = run_match("idle", "idle", scenario=nobody(end_on=("scored",), ball=ball, cycle_limit=80))
    assert against.score == (0, 1) and against.end_reason == "cycle_limit" and against.cycles == 80
    for_away = run_match("idle", "idle", scenario=nobody(end_on=("scored",), ball=ball, attacker="away"))
    assert for_away.end_reason == "scored" and for_away.cycles < 80


def test_the_ball_going_out_ends_the_match_in_that_cycle():
    result = run_match("idle", "idle", scenario=nobody(end_on=("goal", "out"), ball=BallStart((0.0, 30.0), (0.0, 2.0))))
    assert result.end_reason == "out"
    (cycle, *_), = result.events.of_kind(EventKind.OUT)
    assert result.cycles == cycle + 1


def test_a_defender_playing_the_ball_is_the_ball_lost():
    scenario = Scenario(home=Side(positions=[(-30.0, 0.0)], goalie=None), away=Side(positions=[(10.0, 0.0)], goalie=None),
                        ball=BallStart((5.0, 0.0), (1.0, 0.0)), start_mode="play_on", end_on=("goal", "lost"),
                        half_time=False)
    result = run_match("idle", "idle", scenario=scenario)
    assert result.end_reason == "lost"
    assert result.events.of_kind(EventKind.TOUCH)[0][1] == 1  # the away player touched it


def test_the_cycle_limit_ends_the_match():
    result = run_match("chaser", "chaser", seed=2, scenario=Scenario(cycle_limit=57))
    assert result.cycles == 57 and result.end_reason == "cycle_limit"
    assert run_match("idle", "idle", config=MatchConfig(max_cycles=40)).end_reason == "time_over"


def test_without_end_conditions_goals_do_not_end_the_match():
    scenario = Scenario(home=Side(players=2), away=Side(players=1), cycle_limit=1500, half_time=False)
    result = run_match("chaser", "idle", seed=0, scenario=scenario)
    assert result.cycles == 1500 and sum(result.score) >= 2


# ---------------------------------------------------------------------------------- sides
def test_uneven_and_empty_sides_reach_the_teams():
    home, away = Recording(), Recording()
    scenario = Scenario(home=Side(players=3, goalie=None), away=Side(players=0), cycle_limit=5)
    run_match(home, away, scenario=scenario)
    assert (home.info.players_per_team, home.info.goalie_index, home.info.opponents) == (3, -1, 0)
    assert (away.info.players_per_team, away.info.goalie_index, away.info.opponents) == (0, -1, 3)
    assert home.shapes == {((3, 2), (0, 2), (3,))}
    assert away.shapes == {((0, 2), (3, 2), (0,))}


def test_a_side_of_nobody_against_chasers_plays_a_whole_regular_length_match():
    result = run_match("chaser", "idle", seed=3, scenario=Scenario(away=Side(players=0)))
    assert result.cycles == CONFIG.total_cycles
    assert result.score[0] >= 5 and result.score[1] == 0
    assert result.statistics[1].kicks == 0 and result.statistics[1].possession == 0.0


def test_uneven_sides_keep_rows_and_events_apart():
    scenario = Scenario(home=Side(players=2), away=Side(players=5), cycle_limit=2000, half_time=True)
    match = Match("chaser", "chaser", seed=4, scenario=scenario, config=MatchConfig(rules=CONFIG.rules))
    result = match.run()
    assert match.state.pos.shape == (7, 2) and match.state.sizes == (2, 5)
    events = result.events.as_arrays()
    for team, n in ((0, 2), (1, 5)):
        players = events["player"][(events["team"] == team) & (events["kind"] == EventKind.KICK)]
        assert players.size and players.max() < n
    assert sum(s.possession for s in result.statistics) == pytest.approx(1.0)


def test_a_goalkeeper_less_side_cannot_catch():
    class Catcher(Recording):
        def act(self, view):
            # Tries once the ball is within the catchable length (an attempt bans the next
            # ones for a few cycles, and a fast ball passes a body rather than waiting at it).
            self.command.catch = bool(np.hypot(*(view.ball - view.own_pos[0])) < 1.2)
            return self.command

    scenario = Scenario(home=Side(players=1), away=Side(positions=[(48.0, 0.0)], goalie=None),
                        ball=BallStart((44.0, 0.0), (1.5, 0.0)), start_mode="play_on", cycle_limit=60,
                        half_time=False)
    result = run_match("idle", Catcher(), scenario=scenario)
    assert not result.events.of_kind(EventKind.CATCH)
    with_keeper = Scenario(**{**scenario.__dict__, "away": Side(positions=[(48.0, 0.0)], goalie=0)})
    assert run_match("idle", Catcher(), scenario=with_keeper).events.of_kind(EventKind.CATCH)


# ---------------------------------------------------------------------------------- start states
def test_randomised_start_states_come_from_the_seed():
    def start(seed):
        match = Match("idle", "idle", seed=seed, scenario="counter-attack")
        return match.state.pos.copy(), match.state.ball.copy()

    (p0, b0), (p0_again, b0_again), (p1, b1) = start(0), start(0), start(1)
    assert np.array_equal(p0, p0_again) and np.array_equal(b0, b0_again)
    assert not np.array_equal(b0, b1)
    f = CONFIG.field
    for pos in (p0, p1):
        assert (np.abs(pos[:, 0]) <= f.half_length).all() and (np.abs(pos[:, 1]) <= f.half_width).all()
    scenario = get_scenario("counter-attack")
    assert -5.0 <= b0[0] <= 10.0 and -8.0 <= b0[1] <= 8.0
    assert np.allclose(p0[0], b0 + scenario.home.positions[0], atol=scenario.home.jitter)


def test_start_positions_velocities_and_the_starting_set_play():
    result_match = Match("idle", "idle", scenario="corner")
    result_match.start()
    state = result_match.state
    assert state.play_mode == PlayMode.CORNER_KICK and state.mode_team == 0
    assert tuple(state.ball) == (51.5, 33.0)
    away = state.pos[11:]
    clearance = CONFIG.rules.set_play_clearance
    assert (np.hypot(*(away - state.ball).T) >= clearance - 1e-9).all()
    moving = Match("idle", "idle", scenario=Scenario(home=Side(positions=[(0.0, 5.0)], velocities=[(0.5, 0.0)]),
                                                     away=Side(players=0), start_mode="play_on"))
    assert tuple(moving.state.vel[0]) == (0.5, 0.0)


def test_a_kick_off_start_puts_the_players_in_their_halves():
    scenario = Scenario(home=Side(positions=[(-20.0, 0.0), (10.0, 3.0)]), away=Side(positions=[(30.0, 0.0)]),
                        start_mode="kick_off", start_team="away")
    match = Match("idle", "idle", scenario=scenario)
    match.start()
    assert match.state.mode_team == 1 and match.state.play_mode == PlayMode.KICK_OFF
    assert (match.state.pos[:2, 0] <= 0).all() and match.state.pos[2, 0] >= 0


# ---------------------------------------------------------------------------------- rule switches
def test_without_set_plays_a_ball_out_is_dropped_inside_and_play_goes_on():
    scenario = nobody(ball=BallStart((0.0, 30.0), (0.0, 2.0)), set_plays=False, cycle_limit=20)
    result = run_match("idle", "idle", scenario=scenario)
    drops = result.events.of_kind(EventKind.DROP_BALL)
    assert len(drops) == 1 and drops[0][5] == PlayMode.KICK_IN
    assert drops[0][4] == pytest.approx(CONFIG.field.half_width - 1.0)
    modes = [e[5] for e in result.events.of_kind(EventKind.SET_PLAY)]
    assert PlayMode.KICK_IN not in modes and result.cycles == 20


def test_without_set_plays_a_goal_is_followed_by_a_dropped_ball_on_the_centre_spot():
    scenario = nobody(ball=BallStart((40.0, 0.0), (2.5, 0.0)), set_plays=False, cycle_limit=30)
    result = run_match("idle", "idle", scenario=scenario)
    assert result.score == (1, 0)
    (drop,) = result.events.of_kind(EventKind.DROP_BALL)
    assert drop[3:5] == (0.0, 0.0) and drop[5] == PlayMode.KICK_OFF
    assert PlayMode.AFTER_GOAL not in [e[5] for e in result.events.of_kind(EventKind.SET_PLAY)]


def test_the_scenario_switches_offside_in_the_configuration_the_teams_see():
    home = Recording()
    match = Match(home, "idle", scenario=Scenario(offside=False, cycle_limit=3))
    match.run()
    assert match.config.rules.offside is False and home.info is not None
    no_offside = MatchConfig(rules=dataclasses.replace(CONFIG.rules, offside=False))
    assert Match("idle", "idle", config=no_offside, scenario=Scenario(offside=True)).config.rules.offside is True
    assert Match("idle", "idle", config=no_offside, scenario=Scenario()).config is no_offside


def test_one_period_without_half_time():
    scenario = Scenario(home=Side(players=1), away=Side(players=1), half_time=False, cycle_limit=3500)
    result = run_match("chaser", "chaser", seed=0, scenario=scenario)
    assert not result.events.of_kind(EventKind.HALF_TIME) and result.state.half == 0


# ---------------------------------------------------------------------------------- files and library
def test_files_round_trip_and_toml_reads(tmp_path):
    scenario = get_scenario("counter-attack")
    assert load_scenario(save_scenario(scenario, tmp_path / "s.json")) == scenario
    (tmp_path / "s.toml").write_text('name = "x"\nend_on = ["goal"]\ncycle_limit = 10\n[home]\ngoalie = false\n'
                                     'positions = [[1.0, 2.0]]\n[away]\nplayers = 0\n')
    loaded = load_scenario(tmp_path / "s.toml")
    assert loaded.home.goalie is None and loaded.home.positions == ((1.0, 2.0),) and loaded.away.players == 0


@pytest.mark.parametrize("data, field", [
    ({"home": {"players": 3, "colour": "red"}}, "home.colour"),
    ({"kickoff": True}, "kickoff"),
    ({"home": {"positions": [[1.0, "a"]]}}, "home.positions[0]"),
    ({"ball": {"position": [1.0]}}, "ball.position"),
    ({"home": 3}, "home"),
])
def test_bad_files_name_the_key(data, field):
    with pytest.raises(ScenarioError) as info:
        scenario_from_dict(data)
    assert info.value.field == field


def test_unreadable_files_are_scenario_errors(tmp_path):
    (tmp_path / "bad.json").write_text("{")
    with pytest.raises(ScenarioError, match="not valid JSON"):
        load_scenario(tmp_path / "bad.json")
    with pytest.raises(ScenarioError, match="cannot read"):
        load_scenario(tmp_path / "missing.toml")
    with pytest.raises(ScenarioError, match=".json or .toml"):
        load_scenario(tmp_path / "scenario.yaml")


def test_the_library_has_the_named_scenarios_and_each_fits_the_default_field():
    names = scenario_names()
    for required in ("full-match", "kick-off", "empty-goal", "run-to-score-with-keeper", "3-vs-1-with-keeper",
                     "corner", "counter-attack"):
        assert required in names
    assert names[0] == "full-match" and library()["full-match"].is_regular
    for scenario in library().values():
        scenario.check(CONFIG)
        assert scenario.is_regular or scenario.end_on or scenario.cycle_limit


def test_cli_lists_the_library_and_reports_bad_scenarios_without_a_traceback(tmp_path, capsys):
    assert main(["scenarios"]) == 0
    assert "3-vs-1-with-keeper" in capsys.readouterr().out
    assert main(["scenarios", "corner"]) == 0
    assert json.loads(capsys.readouterr().out)["start_mode"] == "corner_kick"
    bad = tmp_path / "bad.toml"
    bad.write_text("[home]\nplayers = 3\ngoalie = 4\n")
    assert main(["scenarios", str(bad)]) == 2
    assert main(["play", "chaser", "idle", "--scenario", str(bad)]) == 2
    out = capsys.readouterr()
    text = out.out + out.err
    assert "Scenario.home.goalie" in text and "Traceback" not in text
    assert main(["play", "chaser", "idle", "--scenario", "empty-goal", "--seed", "1", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["end_reason"] == "goal" and report["scenario"] == "empty-goal"
