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
    out = capsys.readouterr().out
    assert "unknown team 'nobody'" in out and "chaser" in out


def test_bench_match_reports_times(capsys) -> None:
    assert main(["bench", "match", "--matches", "2", "--cycles", "100", "--profile", "--top", "5"]) == 0
    out = capsys.readouterr().out
    assert "µs" in out and "100 cycles" in out and "function calls" in out


def test_bench_match_rejects_bad_arguments_with_a_message(capsys) -> None:
    assert main(["bench", "match", "--home", "nobody", "--matches", "1", "--cycles", "10"]) == 2
    assert "unknown team 'nobody'" in capsys.readouterr().out
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
