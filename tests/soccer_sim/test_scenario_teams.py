"""Every shipped scenario with every built-in team, on either side.

Fast: each registered team in every scenario (home or away in turn, against a rotating
opponent) over the first 40 cycles; every team scores on the empty goal. Slow: each team on
both sides of every scenario over 300 cycles, and every pairing of teams in every scenario
played to the scenario's end.
"""

from __future__ import annotations

import pytest

from soccer_sim import EventKind, MatchConfig, PlayMode, available_teams, run_match
from soccer_sim.scenarios import library

TEAMS = sorted(available_teams())
SCENARIOS = list(library())
SHORT = MatchConfig(max_cycles=40)


def check(result, scenario_name: str) -> None:
    scenario = library()[scenario_name]
    assert result.scenario == scenario_name
    assert result.state.play_mode == PlayMode.TIME_OVER
    assert result.end_reason in ("time_over", "cycle_limit", *scenario.end_on)
    home, away = scenario.sizes(MatchConfig())
    assert result.state.pos.shape == (home + away, 2)
    kicks = result.events.as_arrays()
    for team, n in ((0, home), (1, away)):
        players = kicks["player"][(kicks["team"] == team) & (kicks["kind"] == EventKind.KICK)]
        assert players.size == 0 or players.max() < n


def test_the_built_in_teams_are_all_there():
    for name in ("idle", "chaser", "mmdr", "mmd+msd2", "static", "greedy", "greedy-offense", "bidding", "msd",
                 "msd2", "random", "statues", "counter-442", "press-433", "possession"):
        assert name in TEAMS


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_every_team_plays_every_scenario(scenario):
    """Each team once per scenario, home and away in turn (the opponent plays the other side)."""
    k = SCENARIOS.index(scenario)
    for i, team in enumerate(TEAMS):
        opponent = TEAMS[(i + 1 + k) % len(TEAMS)]
        home, away = (team, opponent) if (i + k) % 2 == 0 else (opponent, team)
        check(run_match(home, away, seed=i, config=SHORT, scenario=scenario), scenario)


@pytest.mark.slow
@pytest.mark.parametrize("scenario", SCENARIOS)
def test_every_team_plays_every_scenario_on_either_side(scenario):
    for i, team in enumerate(TEAMS):
        opponent = TEAMS[(i + 1 + SCENARIOS.index(scenario)) % len(TEAMS)]
        for home, away in ((team, opponent), (opponent, team)):
            check(run_match(home, away, seed=i, config=MatchConfig(max_cycles=300), scenario=scenario), scenario)


@pytest.mark.parametrize("team", [t for t in TEAMS if t != "idle"])
def test_every_team_scores_on_the_empty_goal(team):
    result = run_match(team, "idle", seed=5, scenario="empty-goal")
    assert result.end_reason == "goal" and result.score == (1, 0)


@pytest.mark.slow
@pytest.mark.parametrize("scenario", [s for s in SCENARIOS if not library()[s].is_regular])
def test_every_pairing_plays_every_scenario_to_its_end(scenario):
    for i, home in enumerate(TEAMS):
        for j, away in enumerate(TEAMS):
            check(run_match(home, away, seed=i * len(TEAMS) + j, scenario=scenario), scenario)
