"""``soccer-sim play --engine rcssserver``: bad input and a missing build are one line and
status 2, before anything starts; a match (a stand-in server and helios-base stand-ins in a
private network namespace) is reported from the server's game log."""

from __future__ import annotations

import json
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from experiments.cli import main
from soccer_sim import run_match
from soccer_sim.config import MatchConfig
from soccer_sim.rcg import RcgRecorder

PROGRAMS = Path(__file__).resolve().parents[1] / "rcss_bridge" / "programs"


def kit(home: Path, helios: bool = True) -> Path:
    """A kit build whose server and helios-base are the tests' stand-ins."""
    (home / "install" / "bin").mkdir(parents=True)
    (home / "install" / "lib").mkdir()
    server = home / "install" / "bin" / "rcssserver"
    shutil.copyfile(PROGRAMS / "fake_rcssserver.py", server)
    server.chmod(0o755)
    if helios:
        bin_dir = home / "src" / "helios-base" / "build" / "bin"
        bin_dir.mkdir(parents=True)
        start = bin_dir / "start.sh"
        start.write_text(f"""#!/bin/sh
# helios-base's start.sh as the tests need it: -t NAME -p PORT [-P COACH_PORT]
while [ $# -gt 0 ]; do case $1 in -t) name=$2; shift;; -p) port=$2; shift;; esac; shift; done
exec {sys.executable} {PROGRAMS / 'fake_side.py'} "$name" "$port" ok
""")
        start.chmod(0o755)
        (bin_dir / "sample_player").write_text("")
        (bin_dir / "sample_player").chmod(0o755)
    return home


def test_a_missing_build_is_one_line_saying_how_to_build_it(tmp_path, capsys):
    assert main(["play", "static", "static", "--engine", "rcssserver", "--rcss-home", str(tmp_path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "rcssserver is not built" in err and "build.sh --server-only" in err
    kit(tmp_path / "server-only", helios=False)
    assert main(["play", "static", "helios-base", "--engine", "rcssserver",
                 "--rcss-home", str(tmp_path / "server-only")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "helios-base is not built" in err


@pytest.mark.parametrize("args, words", [
    (["nosuchteam", "static"], "nosuchteam"),
    (["static", "static", "--cycles", "30"], "multiple of 20"),
    (["static", "static", "--scenario", "kick-off"], "--scenario is not available"),
    (["static", "static", "--record", "x.rrd"], "--record is not available"),
])
def test_bad_input_is_one_line_and_status_2(tmp_path, capsys, args, words):
    home = kit(tmp_path / "kit")
    assert main(["play", *args, "--engine", "rcssserver", "--rcss-home", str(home)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err


def _namespace_works() -> bool:
    try:
        return subprocess.run(["unshare", "-rn", "true"], capture_output=True, timeout=10).returncode == 0
    except (OSError, subprocess.TimeoutExpired):
        return False


@pytest.mark.skipif(not _namespace_works(), reason="no private network namespace here (unshare -rn)")
def test_a_match_is_reported_from_the_servers_game_log(tmp_path, capsys, monkeypatch):
    recorded = tmp_path / "recorded.rcg"
    recorder = RcgRecorder(recorded)
    result = run_match("static", "chaser", seed=2, config=MatchConfig(max_cycles=400), recorders=[recorder])
    monkeypatch.setenv("FAKE_RCSS_RCG", str(recorded))
    monkeypatch.setenv("FAKE_RCSS_SCORE", f"{result.score[0]} - {result.score[1]}")
    home = kit(tmp_path / "kit")
    kept, logs = tmp_path / "kept.rcg", tmp_path / "logs"
    assert main(["play", "helios-base", "helios-base", "--engine", "rcssserver", "--rcss-home", str(home),
                 "--json", "--rcg", str(kept), "--rcss-logs", str(logs)]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["engine"] == "rcssserver" and report["teams"] == {"home": "helios-base", "away": "helios-base"}
    assert [report["score"]["home"], report["score"]["away"]] == list(result.score) == report["server_score"]
    assert report["cycles"] == 400 and report["missed_cycles"] == {}
    assert kept.read_text() == recorded.read_text()
    assert {"match.rcg", "match.rcl", "server.out", "helios-base.out", "helios-base_2.out"} <= {
        p.name for p in logs.iterdir()}
