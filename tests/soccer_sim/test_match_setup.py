"""MatchSetup: one resolution of configuration and scenario that the match, the referee and the
environment share; MatchEnd: the one place that decides when a match or an episode ends."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from soccer_sim import Match, MatchConfig, RuleConfig, ScenarioError, run_match
from soccer_sim.ending import CLOCK_RUNS, HALF_TIME_DUE, TIME_OVER_DUE, MatchEnd
from soccer_sim.referee import Referee
from soccer_sim.rules import OffsideJudge
from soccer_sim.scenarios import Scenario, Side
from soccer_sim.setup import MatchSetup
from soccer_sim.state import AWAY, HOME, NO_PLAYER, NO_TEAM, EventKind, EventLog, PlayMode, WorldState

SHORT = MatchConfig(rules=RuleConfig(half_cycles=30))


def test_the_regular_setup_comes_from_the_configuration() -> None:
    setup = MatchSetup.resolve(SHORT)
    assert setup.config is SHORT and setup.scenario.is_regular
    assert setup.sizes == (11, 11) and setup.goalies == (0, 0) and setup.goalie_rows == (0, 11)
    assert setup.set_plays and setup.half_time and setup.offside
    assert (setup.start_mode, setup.start_side, setup.attacking_side) == (PlayMode.KICK_OFF, HOME, HOME)
    assert setup.end == MatchEnd(end_cycle=60, full_cycles=60, half_end=30, conditions=(), defender=AWAY)
    assert MatchSetup.resolve() == MatchSetup.resolve(MatchConfig(), None)


def test_a_scenario_switches_rules_sides_and_end() -> None:
    scenario = Scenario(name="s", home=Side(players=3, goalie=None), away=Side(players=2, goalie=1),
                        offside=False, set_plays=False, half_time=False, start_mode="play_on", start_team="away",
                        attacker="away", end_on=("goal", "lost"), cycle_limit=45)
    setup = MatchSetup.resolve(SHORT, scenario)
    assert setup.sizes == (3, 2) and setup.goalies == (NO_PLAYER, 1) and setup.goalie_rows == (NO_PLAYER, 4)
    assert not setup.offside and not setup.config.rules.offside and SHORT.rules.offside
    assert not setup.set_plays and not setup.half_time
    assert (setup.start_mode, setup.start_side, setup.attacking_side) == (PlayMode.PLAY_ON, AWAY, AWAY)
    assert setup.end == MatchEnd(end_cycle=45, full_cycles=60, half_end=-1, conditions=("goal", "lost"),
                                 defender=HOME)


def test_resolve_refuses_what_cannot_be_played() -> None:
    with pytest.raises(TypeError, match="config must be a MatchConfig"):
        MatchSetup.resolve("regular")  # type: ignore[arg-type]
    with pytest.raises(ScenarioError, match="expected a Scenario, a library name or None"):
        MatchSetup.resolve(None, 3)  # type: ignore[arg-type]
    with pytest.raises(ScenarioError, match="no scenario called"):
        MatchSetup.resolve(None, "no-such-scenario")
    with pytest.raises(ScenarioError, match=r"home.goalie"):
        MatchSetup.resolve(MatchConfig(players_per_team=2), Scenario(home=Side(goalie=5)))


def test_side_info_names_both_sides_explicitly() -> None:
    setup = MatchSetup.resolve(None, Scenario(home=Side(players=3, goalie=None), away=Side(players=1)))
    home, away = (setup.side_info(team, ("h", "a")) for team in (HOME, AWAY))
    assert (home.name, home.opponent_name, home.players_per_team, home.goalie_index) == ("h", "a", 3, NO_PLAYER)
    assert (home.opponents, home.opponent_goalie_index) == (1, 0)
    assert (away.name, away.opponent_name, away.players_per_team, away.goalie_index) == ("a", "h", 1, 0)
    assert (away.opponents, away.opponent_goalie_index) == (3, NO_PLAYER)


def test_the_referee_and_the_match_are_built_from_the_setup() -> None:
    setup = MatchSetup.resolve(SHORT, Scenario(offside=False, set_plays=False, start_mode="play_on"))
    referee = Referee(setup, EventLog())
    assert referee.setup is setup and not referee.modes.set_plays
    assert not any(isinstance(judge, OffsideJudge) for judge in referee.judges)
    assert any(isinstance(judge, OffsideJudge) for judge in Referee(MatchSetup.resolve(SHORT), EventLog()).judges)
    match = Match("idle", "idle", setup=setup)
    assert match.setup is setup and match.config is setup.config and match.end_cycle == 60
    with pytest.raises(TypeError, match="setup must be a MatchSetup"):
        Referee(SHORT, EventLog())  # type: ignore[arg-type]
    with pytest.raises(TypeError, match="not both"):
        Match("idle", "idle", config=SHORT, setup=setup)


def test_the_clock_calls_half_time_and_time_over() -> None:
    end = MatchEnd(end_cycle=50, full_cycles=60, half_end=30, conditions=(), defender=AWAY)
    assert [end.clock(c) for c in (1, 29, 30, 31, 49, 50, 51)] == [
        CLOCK_RUNS, CLOCK_RUNS, HALF_TIME_DUE, CLOCK_RUNS, CLOCK_RUNS, TIME_OVER_DUE, TIME_OVER_DUE]
    one_period = replace(end, half_end=-1)
    assert one_period.clock(30) == CLOCK_RUNS


def test_the_reason_a_match_ended() -> None:
    end = MatchEnd(end_cycle=50, full_cycles=60, half_end=30, conditions=("out",), defender=AWAY)
    assert end.reason(50, None) == "cycle_limit"
    assert end.reason(12, None) == "time_over"  # stopped before any limit (an environment that finished early)
    assert end.reason(12, "out") == "out"
    assert replace(end, end_cycle=60).reason(60, None) == "time_over"


def _state(cycle: int, mode: PlayMode = PlayMode.PLAY_ON) -> WorldState:
    return WorldState(pos=np.zeros((2, 2)), vel=np.zeros((2, 2)), stamina=np.zeros(2), ball=np.zeros(2),
                      ball_vel=np.zeros(2), cycle=cycle, play_mode=mode, mode_team=NO_TEAM)


def test_is_over_after_the_last_cycle_or_once_time_is_called() -> None:
    end = MatchEnd(end_cycle=50, full_cycles=60, half_end=30, conditions=(), defender=AWAY)
    assert not end.is_over(_state(49)) and end.is_over(_state(50))
    assert end.is_over(_state(3, PlayMode.TIME_OVER))


def test_end_conditions_are_judged_on_the_cycles_events_in_their_order() -> None:
    end = MatchEnd(end_cycle=50, full_cycles=60, half_end=-1, conditions=("scored", "out", "lost"), defender=AWAY)
    events = EventLog()
    events.add(3, EventKind.KICK, HOME, 1, 0.0, 0.0, 0)
    assert end.condition_met(events, 0, len(events)) is None
    events.add(4, EventKind.TOUCH, AWAY, 2, 0.0, 0.0, 0)
    events.add(4, EventKind.OUT, AWAY, 2, 0.0, 0.0, 0)
    assert end.condition_met(events, 1, len(events)) == "out"  # "out" comes before "lost"
    assert end.condition_met(events, 1, 2) == "lost"
    events.add(5, EventKind.GOAL, HOME, 1, 0.0, 0.0, 0)
    assert end.condition_met(events, 3, 4) == "scored"
    assert replace(end, defender=HOME).condition_met(events, 3, 4) is None  # a goal of the defenders
    assert replace(end, conditions=()).condition_met(events, 0, 4) is None


def test_episode_end() -> None:
    end = MatchEnd(end_cycle=50, full_cycles=60, half_end=30, conditions=(), defender=AWAY)
    playing, over = _state(10), _state(50)
    assert end.episode_end(over, goal_scored=False, end_on_goal=False, steps=50, max_cycles=None) == (True, False)
    assert end.episode_end(playing, goal_scored=True, end_on_goal=True, steps=10, max_cycles=None) == (True, False)
    assert end.episode_end(playing, goal_scored=True, end_on_goal=False, steps=10, max_cycles=None) == (False, False)
    assert end.episode_end(playing, goal_scored=False, end_on_goal=False, steps=10, max_cycles=10) == (False, True)
    assert end.episode_end(over, goal_scored=False, end_on_goal=False, steps=50, max_cycles=50) == (True, False)


def test_a_match_ends_where_its_setup_says() -> None:
    limited = run_match("idle", "idle", config=SHORT, scenario=Scenario(cycle_limit=37))
    assert (limited.cycles, limited.end_reason) == (37, "cycle_limit")
    full = run_match("idle", "idle", config=SHORT)
    assert (full.cycles, full.end_reason) == (60, "time_over")
    assert [e[0] for e in full.events.of_kind(EventKind.HALF_TIME)] == [29]
