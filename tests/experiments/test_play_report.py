"""The match report of ``soccer-sim play`` and its edge cases (errors, Ctrl-C, long matches)."""

from __future__ import annotations

import json

import pytest

import soccer_sim
import soccer_sim.statistics
from experiments.cli import main
from experiments.commands import play
from experiments.match_report import match_report
from soccer_sim import EventKind, EventLog, PlayMode, TeamError
from soccer_sim.state import AWAY, HOME, NO_TEAM


@pytest.fixture(scope="module")
def full_match():
    return soccer_sim.run_match("chaser", "chaser", seed=0)


def test_report_agrees_with_the_match(full_match):
    report = match_report(full_match)
    assert report.score == tuple(full_match.score)
    assert len(report.goals) == sum(report.score)
    assert [g.cycle for g in report.goals] == sorted(g.cycle for g in report.goals)
    for team in (HOME, AWAY):
        assert sum(1 for g in report.goals if g.team == team) == report.score[team]
    assert all(g.shirt is None or 1 <= g.shirt <= 11 for g in report.goals)
    # Half time at cycle 3000: the goals before it make the half-time score.
    first_half = [sum(1 for g in report.goals if g.team == t and g.cycle < 3000) for t in (HOME, AWAY)]
    assert report.half_time_score == tuple(first_half)
    # Kick-offs: the opening one, the one after half time, one after every goal.
    assert report.set_plays[HOME]["kick_off"] + report.set_plays[AWAY]["kick_off"] == 2 + sum(report.score)
    offsides = full_match.events.of_kind(EventKind.OFFSIDE)
    assert sum(report.offsides) == len(offsides)


def _result_with(events: EventLog):
    class Result:
        team_names = ("a", "b")
        seed, cycles, score = 3, 100, (1, 1)
        scenario, end_reason = "full-match", "time_over"
        statistics = (soccer_sim.statistics.TeamStatistics(), soccer_sim.statistics.TeamStatistics())

    result = Result()
    result.events = events
    return result


def test_report_counts_set_plays_retakes_offsides_and_own_goals():
    log = EventLog()
    log.add(0, EventKind.SET_PLAY, HOME, detail=int(PlayMode.KICK_OFF))
    log.add(10, EventKind.OUT, HOME, 4, detail=1)
    log.add(10, EventKind.SET_PLAY, AWAY, detail=int(PlayMode.GOAL_KICK))
    log.add(12, EventKind.SET_PLAY, NO_TEAM, detail=int(PlayMode.PLAY_ON))
    log.add(13, EventKind.SET_PLAY, AWAY, detail=int(PlayMode.GOAL_KICK))  # retaken: no ball out since
    log.add(20, EventKind.OFFSIDE, HOME, 8)
    log.add(20, EventKind.SET_PLAY, AWAY, detail=int(PlayMode.FREE_KICK))
    log.add(30, EventKind.GOAL, AWAY, 2, detail=1)  # own goal: home's shirt 3 last touched
    log.add(50, EventKind.HALF_TIME)
    log.add(60, EventKind.GOAL, HOME, 9, detail=0)
    report = match_report(_result_with(log))
    assert report.set_plays[AWAY]["goal_kick"] == 1 and report.set_plays[AWAY]["goal_kick_retake"] == 1
    assert report.set_plays[HOME]["kick_off"] == 1 and report.set_plays[AWAY]["free_kick"] == 1
    assert report.offsides == (1, 0) and report.half_time_score == (0, 1)
    data = report.as_dict()
    assert data["goals"] == [
        {"cycle": 30, "team": "away", "scorer_shirt": 3, "own_goal": True},
        {"cycle": 60, "team": "home", "scorer_shirt": 10, "own_goal": False},
    ]
    json.dumps(data)


def test_play_prints_the_report(capsys):
    assert main(["play", "chaser", "idle", "--cycles", "400"]) == 0
    out = capsys.readouterr().out
    assert "stopped before half time" in out and "Goals" in out and "offsides" in out and "kick offs" in out
    assert "#" in out  # scorers by shirt number


def test_play_json(capsys):
    assert main(["play", "chaser", "idle", "--cycles", "300", "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["teams"] == {"home": "chaser", "away": "idle"} and data["cycles"] == 300
    assert data["half_time_score"] is None
    assert set(data["set_plays"]["home"]) >= {"kick_off", "corner_kick", "goal_kick", "free_kick", "kick_in"}
    assert data["score"]["home"] == data["statistics"]["home"]["goals"]


def test_error_text_with_brackets_is_printed(monkeypatch, capsys):
    def failing(*args, **kwargs):
        raise TeamError("x", "command.dash is not finite: [nan, nan]", player=3)

    monkeypatch.setattr(soccer_sim, "run_match", failing)
    assert main(["play", "--cycles", "5"]) == 1  # a team failing during the match: a failed run
    captured = capsys.readouterr()
    assert "command.dash is not finite: [nan, nan]" in captured.err and captured.out == ""


def test_ctrl_c_prints_interrupted_and_exits_130(monkeypatch, capsys):
    import experiments.runner.local

    def interrupted(*args, **kwargs):  # Ctrl-C reaches play while its match's worker plays (the worker ignores it)
        raise KeyboardInterrupt

    monkeypatch.setattr(experiments.runner.local, "play_in_worker", interrupted)
    assert main(["play", "--cycles", "5"]) == 130
    captured = capsys.readouterr()
    assert captured.err.strip() == "interrupted" and "Traceback" not in captured.out + captured.err


def test_long_matches_lengthen_both_halves():
    assert play.match_config(None).total_cycles == 6000
    assert play.match_config(1000).total_cycles == 1000 and play.match_config(1000).rules.half_cycles == 3000
    long = play.match_config(100_001)
    assert long.total_cycles == 100_001 and long.rules.half_cycles == 50_001


def test_play_json_into_a_closed_pipe_ends_quietly() -> None:
    import subprocess
    import sys

    reader = subprocess.Popen([sys.executable, "-c", "pass"], stdin=subprocess.PIPE)
    reader.wait(timeout=60)  # the reader is gone before anything is written: every write fails
    player = subprocess.run([sys.executable, "-m", "experiments.cli", "play", "chaser", "idle", "--cycles", "100",
                             "--json"], stdout=reader.stdin, stderr=subprocess.PIPE, text=True, timeout=120)
    reader.stdin.close()
    assert player.returncode == 0
    assert "Traceback" not in player.stderr
