"""The match report read from a game log (:mod:`experiments.rcg_report`, how ``play --engine
rcssserver`` reports a match of the real server) agrees with the simulator's own report of the
same match written as an rcssserver log (:class:`soccer_sim.rcg.RcgRecorder`)."""

from __future__ import annotations

import pytest

from experiments.configuration import match_config
from experiments.match_report import match_report
from experiments.rcg_report import NOT_IN_A_LOG, rcg_match_report
from soccer_sim.match import run_match
from soccer_sim.rcg import GameLog, RcgRecorder, read_rcg


@pytest.fixture(scope="module")
def both_reports(tmp_path_factory):
    path = tmp_path_factory.mktemp("rcg") / "match.rcg"
    recorder = RcgRecorder(path)
    result = run_match("static", "chaser", seed=1, config=match_config(1200), recorders=[recorder])
    return match_report(result), rcg_match_report(read_rcg(path), ("static", "chaser"), 1)


def test_score_goals_and_set_plays_agree(both_reports):
    simulated, logged = both_reports
    assert logged.team_names == ("static", "chaser") and logged.seed == 1 and logged.cycles == simulated.cycles
    assert logged.score == simulated.score and sum(logged.score) >= 2
    assert logged.set_plays == simulated.set_plays and logged.offsides == simulated.offsides
    assert logged.drop_balls == simulated.drop_balls
    assert [(g.team, g.shirt, g.own_goal) for g in logged.goals] == [(g.team, g.shirt, g.own_goal)
                                                                     for g in simulated.goals]
    # the log shows the goal's play mode from the cycle after the ball crossed the line
    assert all(0 <= b.cycle - a.cycle <= 1 for a, b in zip(simulated.goals, logged.goals))


def test_statistics_agree_except_what_a_log_does_not_hold(both_reports):
    simulated, logged = both_reports
    for team in (0, 1):
        ours, theirs = simulated.statistics[team], logged.statistics[team]
        for key in ("goals", "kicks", "passes", "shots", "tackles", "tackles_won", "fouls", "yellow_cards",
                    "red_cards"):
            assert theirs[key] == ours[key], key
        assert theirs["possession"] == pytest.approx(ours["possession"])
        assert theirs["distance_run"] == pytest.approx(ours["distance_run"], rel=1e-3)
        assert all(theirs[key] is None for key in NOT_IN_A_LOG)
    assert simulated.statistics[0]["kicks"] > 10


def test_a_log_without_shows_or_parameters_is_a_clear_error():
    with pytest.raises(ValueError, match="no show lines"):
        rcg_match_report(GameLog(), ("a", "b"), 0)
