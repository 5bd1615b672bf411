"""The example programs run as documented and their teams behave as described."""

from __future__ import annotations

import runpy
from pathlib import Path

import numpy as np
import pytest

import soccer_sim

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_assign_robots_prints_every_method(capsys) -> None:
    runpy.run_path(str(EXAMPLES / "assign_robots.py"), run_name="__main__")
    lines = capsys.readouterr().out.splitlines()
    methods = [line.split()[0] for line in lines[1:]]
    from agents.assignment import METHODS

    assert methods == list(METHODS)
    makespans = {line.split()[0]: float(line.split()[1]) for line in lines[1:]}
    # Minimal-makespan methods can never be beaten on makespan by a baseline.
    assert makespans["mmdr"] == makespans["mmd+msd2"] == min(makespans.values())


def test_formation_team_keeps_its_shape_against_chaser() -> None:
    module = runpy.run_path(str(EXAMPLES / "formation_team.py"))
    team = module["FormationTeam"]()
    result = soccer_sim.run_match(team, "chaser", seed=3, config=soccer_sim.MatchConfig(max_cycles=400))
    assert result.cycles == 400
    own = result.state.pos[:11]
    # Unlike the chaser, a formation team stays spread over the field.
    spread = np.ptp(own, axis=0)
    assert spread[0] > 20.0 and spread[1] > 20.0


def test_scripted_vs_random_prints_a_win(monkeypatch, capsys) -> None:
    monkeypatch.setattr("sys.argv", ["scripted_vs_random.py"])
    runpy.run_path(str(EXAMPLES / "scripted_vs_random.py"), run_name="__main__")
    printed = capsys.readouterr().out
    score = printed.split("score (", 1)[1].split(")", 1)[0]
    home, away = (int(g) for g in score.split(","))
    assert home > away


@pytest.mark.slow
def test_scripted_in_tournament_plays_the_built_in_teams(tmp_path, monkeypatch, capsys) -> None:
    monkeypatch.chdir(tmp_path)  # the script writes its results next to where it runs
    with pytest.raises(SystemExit) as finished:
        runpy.run_path(str(EXAMPLES / "scripted_in_tournament.py"), run_name="__main__")
    assert finished.value.code == 0
    printed = capsys.readouterr().out
    assert "6 matches in scripted-tournament.sqlite" in printed and "0 failed" in printed
    import csv

    with open(tmp_path / "scripted-tournament-tables" / "league.csv") as handle:
        league = {row["team"]: int(row["games"]) for row in csv.DictReader(handle)}
    assert league == {"static": 4, "greedy": 4, "scripted": 4}  # the path team by its own name


def test_formation_team_refuses_a_smaller_side_by_name() -> None:
    module = runpy.run_path(str(EXAMPLES / "formation_team.py"))
    with pytest.raises(soccer_sim.TeamError, match="plays 11 players with a goalkeeper, not 3"):
        soccer_sim.run_match(module["FormationTeam"](), "chaser", seed=0, scenario="3-vs-1-with-keeper")


def test_partial_team_plays_from_its_own_views_and_beats_idle() -> None:
    from dataclasses import replace

    from examples.partial_team import PartialTeam
    from soccer_sim import MatchConfig, TeamError, run_match
    from soccer_sim.perception.config import ObservationConfig

    config = MatchConfig(observation=ObservationConfig("partial"), max_cycles=600)
    result = run_match(PartialTeam(), "idle", seed=1, config=config)
    assert result.score[0] >= 1 and result.score[1] == 0
    with pytest.raises(TeamError, match="cannot play under full observation"):
        run_match(PartialTeam(), "idle", seed=1, config=replace(config, observation=ObservationConfig()))


def test_self_play_enters_the_frozen_copy_as_the_opponent_and_refreshes_it(capsys) -> None:
    from examples.self_play import FrozenPolicy, main, make_env

    calls = {"first": [], "second": []}

    def recording(key):
        def act(observations):
            calls[key].append(np.array(observations))
            return np.zeros((len(observations), 5))
        return act

    frozen = FrozenPolicy(recording("first"))
    env = make_env(frozen, max_cycles=6)
    env.reset(seed=0)
    while env.agents:
        env.step({a: env.action_space(a).sample() for a in env.agents})
    assert len(calls["first"]) == 6 and all(batch.shape == (3, env.observation_space("left_0").shape[0])
                                            for batch in calls["first"])  # once a cycle, the right side's 3
    frozen.refresh(recording("second"))
    env.reset(seed=1)
    env.step({a: env.action_space(a).sample() for a in env.agents})
    assert len(calls["first"]) == 6 and len(calls["second"]) == 1 and frozen.version == 1

    summary = main(["--smoke"])  # the whole loop without the rl extra
    assert summary["episodes"] == 6 and len(summary["returns"]) == 6
    assert summary["refreshes"] == summary["kept"] // 2
    assert "self-play smoke" in capsys.readouterr().out


def test_the_bidding_ablations_change_one_part_of_the_bidding_team_each() -> None:
    from agents.roles import BiddingParams
    from agents.roles.base import RoleAssigner
    from examples import bidding_ablations as ablations

    names = set()
    for make in ablations.ABLATIONS:
        team = make()
        names.add(team.name)
        assigner = team.assigner
        assert team.assigner_name.startswith("bidding") and team.style == ablations.FormationTeam().style
        unsteered = type(assigner).steer is RoleAssigner.steer
        assert unsteered == (team.name == "bidding-no-steer")
        assigner.reset(3, np.random.default_rng(0))
        players = np.array([[0.0, 0.0], [10.0, 0.0], [-10.0, 0.0]])
        assigner.assign(players, players.copy(), np.array([1, 0, 2]), None, _role_context())
        assert (assigner.ball_player() is None) == (team.name == "bidding-no-ball-role")
        changed = {f for f in ("min_hold", "switch_margin", "angle_weight", "ball_cap")
                   if getattr(assigner.params, f) != getattr(BiddingParams(), f)}
        changed |= {f"field.{f}" for f in vars(assigner.params.field)
                    if getattr(assigner.params.field, f) != getattr(BiddingParams().field, f)}
        assert bool(changed) != (team.name in ("bidding-no-steer", "bidding-no-ball-role")), team.name
    assert len(names) == len(ablations.ABLATIONS)


def _role_context():
    from tests.agents.roles.role_situations import context

    return context((5.0, 0.0))
