"""``soccer-sim play`` and ``soccer-sim bench match`` end to end (short matches)."""

from __future__ import annotations

import pytest

from experiments.cli import main


def test_play_prints_score_and_statistics(capsys) -> None:
    assert main(["play", "chaser", "idle", "--seed", "2", "--cycles", "300"]) == 0
    out = capsys.readouterr().out
    assert "chaser" in out and "idle" in out and "300 cycles" in out
    for row in ("goals", "possession", "teammate contacts", "distance run"):
        assert row in out


def test_play_defaults_and_bad_team(capsys) -> None:
    assert main(["play", "nobody", "--cycles", "5"]) == 2
    captured = capsys.readouterr()
    assert "unknown team 'nobody'" in captured.err and "soccer-sim teams" in captured.err and captured.out == ""


def test_bench_match_reports_times(capsys) -> None:
    assert main(["bench", "match", "--matches", "2", "--cycles", "100", "--profile", "--top", "5"]) == 0
    out = capsys.readouterr().out
    assert "µs" in out and "100 cycles" in out and "function calls" in out


def test_bench_match_rejects_bad_arguments_with_a_message(capsys) -> None:
    assert main(["bench", "match", "--home", "nobody", "--matches", "1", "--cycles", "10"]) == 2
    assert "unknown team 'nobody'" in capsys.readouterr().err
    for bad in (["--cycles", "0"], ["--matches", "-1"]):
        with pytest.raises(SystemExit) as usage_error:
            main(["bench", "match", *bad])
        assert usage_error.value.code == 2
        assert "must be a positive integer" in capsys.readouterr().err


def test_play_finds_a_team_module_in_the_working_directory(tmp_path, monkeypatch, capsys) -> None:
    package = tmp_path / "my_local_teams"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "squad.py").write_text("from soccer_sim.trivial_teams import ChaserTeam as Squad\n")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr("sys.path", [p for p in __import__("sys").path if p not in ("", ".", str(tmp_path))])
    assert main(["play", "my_local_teams.squad:Squad", "idle", "--cycles", "50"]) == 0
    assert "my_local_teams.squad:Squad" in capsys.readouterr().out


def test_bench_soccer_reports_the_figures_of_the_play(capsys) -> None:
    assert main(["bench", "soccer", "--home", "chaser", "--away", "chaser", "--matches", "2", "--cycles", "300"]) == 0
    out = capsys.readouterr().out
    for figure in ("goals", "shots", "shots ending on a body", "passes", "tackles", "fouls", "free kicks",
                   "offside calls", "teammate contacts", "players within 2 m", "corners", "kick-ins", "goal kicks",
                   "goalkeeper catches", "set-play retakes", "dropped balls", "distance run per team",
                   "team length", "team width, ball in midfield", "stamina below 100",
                   "stamina below recovery threshold"):
        assert figure in out
    assert main(["bench", "soccer", "--home", "no-such-team", "--away", "chaser", "--matches", "1",
                 "--cycles", "10"]) == 2
    assert "unknown team" in capsys.readouterr().err
    assert main(["bench", "soccer", "--home", "chaser", "--matches", "1"]) == 2
    assert "--away" in capsys.readouterr().err


def test_bench_soccer_counts_what_the_match_records() -> None:
    from experiments.benchmarks.soccer import measure
    from soccer_sim import MatchConfig, run_match
    from soccer_sim.analysis.shots import shot_endings

    figures = measure("mmdr", "press-433", 1, seed=2, cycles=1500)
    result = run_match("mmdr", "press-433", seed=2, config=MatchConfig(max_cycles=1500))
    home, away = result.statistics
    assert figures["shots"][0] == home.shots + away.shots
    assert figures["shots ending on a body"][0] == sum(end == "body" for _, end in shot_endings(result.events))
    assert figures["tackles"][0] == home.tackles + away.tackles
    assert figures["tackles won"][0] == home.tackles_won + away.tackles_won
    # the per-cycle distance is the statistics' distance run (one definition)
    assert figures["distance run per team (km)"][0] * 2000 == pytest.approx(home.distance_run + away.distance_run)
    # the built-in teams report their roles: every kind of the formation has a distance
    for kind in ("goalkeeper", "defender", "midfielder", "forward"):
        assert figures[f"distance run by {kind} (km per player)"][0] > 0


def test_near_ball_figure_counts_players_within_two_metres() -> None:
    import numpy as np

    from experiments.benchmarks.soccer_match import FiguresRecorder
    from soccer_sim import Match, MatchConfig, PlayMode

    match = Match("idle", "idle", config=MatchConfig(max_cycles=5))
    match.start()
    state = match.state
    state.play_mode = PlayMode.PLAY_ON
    state.ball[:] = (30.0, 0.0)
    state.pos[3] = (31.0, 0.0)   # 1 m away
    state.pos[14] = (30.0, 1.9)  # 1.9 m away
    state.pos[15] = (32.5, 0.0)  # 2.5 m away: not near
    recorder = FiguresRecorder()
    recorder.on_start(match)
    recorder.on_cycle(match)
    cycles = recorder.cycles
    assert cycles.play_on == 1 and cycles.figures()["players within 2 m of the ball"] == 2.0
    state.play_mode = PlayMode.KICK_IN  # set plays are not counted
    recorder.on_cycle(match)
    assert cycles.play_on == 1 and np.isclose(cycles.figures()["players within 2 m of the ball"], 2.0)


def test_bench_skills_times_every_skill(capsys) -> None:
    assert main(["bench", "skills", "--views", "1", "--number", "2"]) == 0
    out = capsys.readouterr().out
    for call in ("ball_race", "decide_on_ball", "best_pass", "dash_to_points"):
        assert call in out


def test_play_defaults_to_two_built_in_teams(capsys) -> None:
    assert main(["play", "--cycles", "60"]) == 0
    out = capsys.readouterr().out
    assert "mmd+msd2" in out and "press-433" in out


def test_bench_roles_times_every_assigner(capsys) -> None:
    assert main(["bench", "roles", "--situations", "1", "--number", "2"]) == 0
    out = capsys.readouterr().out
    for name in ("mmdr", "mmd+msd2", "bidding", "static"):
        assert name in out
