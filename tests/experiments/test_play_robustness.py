"""`soccer-sim play` (and the commands sharing its inputs) on bad input: one line on stderr
naming what is at fault, nothing on stdout, exit 2 for bad input and 1 for a failed match."""

from __future__ import annotations

import subprocess
import sys

import pytest

from experiments.cli import main

TEAM_SOURCE = """
import sys
import time

import numpy as np

from soccer_sim import TeamCommand


class Exiting:
    def reset(self, side_info, config, rng):
        self.n = side_info.players_per_team

    def act(self, view):
        if view.cycle >= 2:
            sys.exit(3)
        return TeamCommand(dash=np.zeros((self.n, 2)), kick=np.zeros((self.n, 2)))


class Hanging(Exiting):
    def act(self, view):
        while True:
            time.sleep(0.01)
"""


def one_error_line(capsys) -> str:
    """The single error line play wrote on stderr (stdout must stay empty)."""
    captured = capsys.readouterr()
    assert captured.out == "", captured.out
    assert captured.err.count("\n") == 1 and captured.err.startswith("error: "), captured.err
    assert "Traceback" not in captured.err
    return captured.err.strip()


def test_a_team_module_with_a_syntax_error(team_module, capsys) -> None:
    module = team_module("play_syntax_team", "def broken(:\n    pass\n")
    assert main(["play", f"{module}:X", "chaser", "--cycles", "5"]) == 2
    line = one_error_line(capsys)
    assert f"team path '{module}:X'" in line and "syntax error" in line and f"{module}.py:1" in line


def test_a_team_module_raising_on_import(team_module, capsys) -> None:
    module = team_module("play_raising_team", "raise RuntimeError('licence file missing')\n")
    assert main(["play", "chaser", f"{module}:X", "--cycles", "5"]) == 2
    line = one_error_line(capsys)
    assert f"team path '{module}:X'" in line and "RuntimeError: licence file missing" in line


def test_the_tournament_reports_a_broken_team_module_the_same_way(team_module, tmp_path, capsys) -> None:
    module = team_module("tournament_syntax_team", "x = = 1\n")
    assert main(["tournament", "--teams", f"chaser,{module}:X", "--out", str(tmp_path / "t.sqlite"),
                 "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"{module}.py:1" in err and "syntax error" in err
    assert not (tmp_path / "t.sqlite").exists()


def test_a_binary_scenario_file(tmp_path, capsys) -> None:
    path = tmp_path / "bad.toml"
    path.write_bytes(b"\x89PNG\r\n\x1a\n\x00\x00")
    assert main(["scenarios", str(path)]) == 2
    assert one_error_line(capsys) == f"error: Scenario: {path} is not a UTF-8 text TOML file (byte 0 is not UTF-8)"
    assert main(["play", "chaser", "idle", "--scenario", str(path), "--cycles", "5"]) == 2
    assert one_error_line(capsys) == f"error: Scenario: {path} is not a UTF-8 text TOML file (byte 0 is not UTF-8)"


def test_a_ball_starting_off_the_field_names_the_bounds(tmp_path, capsys) -> None:
    path = tmp_path / "off.toml"
    path.write_text('name = "off"\nstart_mode = "play_on"\ncycle_limit = 5\n[ball]\nposition = [60.0, 0.0]\n')
    assert main(["play", "chaser", "idle", "--scenario", str(path)]) == 2
    assert one_error_line(capsys) == ("error: Scenario.ball.position: (60.0, 0.0) is outside the field "
                                      "(|x| <= 52.5, |y| <= 34.0)")


def test_a_team_calling_sys_exit_fails_the_match_with_one_line(team_module, capsys) -> None:
    module = team_module("play_exiting_team", TEAM_SOURCE)
    assert main(["play", "idle", f"{module}:Exiting", "--cycles", "10"]) == 1
    assert one_error_line(capsys) == f"error: team '{module}:Exiting': called sys.exit(3) in act()"


def test_a_team_that_never_returns_is_stopped_by_the_match_timeout(team_module, capsys) -> None:
    from soccer_sim import MatchConfig, run_match

    run_match("idle", "idle", config=MatchConfig(max_cycles=1))  # kernels loaded before the clock runs
    module = team_module("play_hanging_team", TEAM_SOURCE)
    assert main(["play", f"{module}:Hanging", "idle", "--cycles", "10", "--match-timeout", "2"]) == 1
    assert one_error_line(capsys) == (f"error: match stopped (--match-timeout): match exceeded its time budget of 2 s "
                                      f"while team '{module}:Hanging' was in act()")


def test_match_timeout_is_checked_and_defaults_to_the_tournaments(capsys) -> None:
    from experiments.cli import build_parser
    from experiments.runner.run import DEFAULT_MATCH_TIMEOUT

    assert build_parser().parse_args(["play"]).match_timeout == DEFAULT_MATCH_TIMEOUT
    with pytest.raises(SystemExit) as usage:
        main(["play", "--match-timeout", "0"])
    assert usage.value.code == 2 and "must be a number in [1, 604800] (seconds), got 0" in capsys.readouterr().err


def test_the_report_into_a_closed_pipe_ends_quietly_with_status_0() -> None:
    reader = subprocess.Popen([sys.executable, "-c", "pass"], stdin=subprocess.PIPE)
    reader.wait(timeout=60)  # the reader is gone before anything is written
    player = subprocess.run([sys.executable, "-m", "experiments.cli", "play", "chaser", "idle", "--cycles", "20"],
                            stdout=reader.stdin, stderr=subprocess.PIPE, text=True, timeout=300)
    reader.stdin.close()
    assert player.returncode == 0 and player.stderr == ""


def test_json_piped_into_head_ends_quietly() -> None:
    pipeline = subprocess.run(f"{sys.executable} -m experiments.cli play chaser idle --cycles 20 --json | head -1",
                              shell=True, capture_output=True, text=True, timeout=300)
    assert pipeline.stdout == "{\n" and pipeline.stderr == ""


def test_a_failed_match_leaves_no_partial_replay_and_an_earlier_one_unchanged(team_module, tmp_path, capsys) -> None:
    module = team_module("play_exiting_team_rec", TEAM_SOURCE)
    fresh = tmp_path / "fresh.rrd"
    assert main(["play", "idle", f"{module}:Exiting", "--cycles", "10", "--record", str(fresh)]) == 1
    assert not fresh.exists()
    earlier = tmp_path / "earlier.rrd"
    earlier.write_bytes(b"an earlier replay")
    assert main(["play", "idle", f"{module}:Exiting", "--cycles", "10", "--record", str(earlier)]) == 1
    assert earlier.read_bytes() == b"an earlier replay"
    assert sorted(p.name for p in tmp_path.iterdir() if p.suffix == ".rrd") == ["earlier.rrd"]
    capsys.readouterr()
    assert main(["play", "chaser", "idle", "--cycles", "10", "--record", str(fresh)]) == 0
    assert fresh.stat().st_size > 1000
