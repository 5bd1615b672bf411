"""`soccer-sim play` plays its match in a worker process, as a tournament does: whatever a
team's code does (raise BaseException, end or kill its process, hang deaf to the timer, set
off a timer of its own, print), play ends with one error line naming the team and exit
status 1, or with its report alone on stdout. Each case runs play as its own process: the
code before the worker could end, kill or hang the process that ran the match."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

from tests.experiments.helpers import SCRIPTED, start_until_in_act

ROOT = Path(__file__).resolve().parents[2]

HANG_BOUND = 240.0
"""Seconds after which a play that has not ended counts as hanging (a bound, not a timing
assertion: each case ends within seconds)."""


def play(away: str, *options: str) -> subprocess.CompletedProcess:
    """``soccer-sim play idle SCRIPTED+away --cycles 40 options`` in its own process."""
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])}
    return subprocess.run([sys.executable, "-m", "experiments.cli", "play", "idle", SCRIPTED + away,
                           "--cycles", "40", *options],
                          capture_output=True, text=True, timeout=HANG_BOUND, cwd=ROOT, env=env)


def stopped_line(result: subprocess.CompletedProcess, team: str) -> str:
    """The one error line of a failed match, which names the away team ``team``."""
    assert result.returncode == 1, (result.returncode, result.stderr)
    assert result.stdout == ""
    assert result.stderr.count("\n") == 1 and result.stderr.startswith("error: "), result.stderr
    assert "Traceback" not in result.stderr
    assert f"team {SCRIPTED + team!r}" in result.stderr
    return result.stderr.strip()


def test_a_team_raising_a_base_exception() -> None:
    line = stopped_line(play("RaisingBaseException"), "RaisingBaseException")
    assert "BaseException: scripted base exception" in line and "away team" in line


def test_a_team_ending_its_process_with_status_0_is_a_failed_match() -> None:
    line = stopped_line(play("QuietlyExitingTeam"), "QuietlyExitingTeam")
    assert "ended with exit code 0" in line


def test_a_team_killing_its_own_process() -> None:
    line = stopped_line(play("SelfKillingTeam"), "SelfKillingTeam")
    assert "killed by signal SIGKILL" in line


def test_a_team_deaf_to_the_timer_is_stopped_by_the_match_timeout() -> None:
    line = stopped_line(play("DeafAtOnceTeam", "--match-timeout", "2"), "DeafAtOnceTeam")
    assert "(--match-timeout)" in line and "time budget of 2 s" in line and "killed" in line


def test_a_team_setting_off_its_own_alarm_does_not_end_play() -> None:
    # Before: SIGALRM with its default action ended play itself ("Alarm clock", status 142).
    line = stopped_line(play("SelfAlarmingTeam"), "SelfAlarmingTeam")
    assert "killed by signal SIGALRM" in line


def test_what_a_team_prints_stays_out_of_the_json_report() -> None:
    result = play("PrintingTeam", "--json")
    assert result.returncode == 0, result.stderr
    report = json.loads(result.stdout)  # stdout holds the JSON document and nothing else
    assert report["teams"]["away"] == SCRIPTED + "PrintingTeam" and report["cycles"] == 40
    assert "team says hello" in result.stderr and "team writes to fd 1" in result.stderr


def test_ctrl_c_while_the_worker_plays_stops_it_and_exits_130(tmp_path, monkeypatch) -> None:
    import signal

    monkeypatch.setenv("PYTHONFAULTHANDLER", "1")  # a play still alive at the bound shows where it is
    player = start_until_in_act([sys.executable, "-m", "experiments.cli", "play", "idle",
                                 SCRIPTED + "MarkingHangingTeam", "--cycles", "40"],
                                tmp_path / "match-under-way", ROOT, HANG_BOUND)
    try:
        player.send_signal(signal.SIGINT)
        try:
            out, err = player.communicate(timeout=HANG_BOUND)  # ends once play and its worker have ended
        except subprocess.TimeoutExpired:
            player.send_signal(signal.SIGABRT)  # faulthandler writes every thread's stack to stderr
            _, err = player.communicate(timeout=60)
            raise AssertionError(f"play did not end within {HANG_BOUND} s of Ctrl-C; its stacks:\n{err[-6000:]}")
    finally:
        if player.poll() is None:
            player.kill()
    assert (player.returncode, out, err) == (130, "", "interrupted\n")
