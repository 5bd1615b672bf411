"""The match host (:mod:`rcss_bridge.match`) with stand-ins for rcssserver and the teams'
programs (``tests/rcss_bridge/programs``): it starts the server and both sides in order,
waits for each side's players, ends every process it started by its id (after a match, a
side's error, a side that never connects, a server that never ends, a SIGTERM), and says
what failed in one line. No real server is needed."""

from __future__ import annotations

import os
import shutil
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

from rcss_bridge.errors import ServerError
from rcss_bridge.install import MissingBuild, RcssInstall
from rcss_bridge.match import (MatchHost, MatchPlan, MatchTimeout, SideFailed, SideProgram, play_in_namespace,
                               server_team_name)

PROGRAMS = Path(__file__).with_name("programs")


def free_udp_port() -> int:
    """A UDP port free on 127.0.0.1 with the two after it (the trainer's and the coaches')."""
    for _ in range(50):
        with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as s:
            s.bind(("127.0.0.1", 0))
            port = s.getsockname()[1]
        if port < 65000:
            return port
    raise RuntimeError("no free port")


@pytest.fixture
def rcss_home(tmp_path) -> Path:
    """A kit build whose server is the stand-in."""
    home = tmp_path / "rcss-home"
    (home / "install" / "bin").mkdir(parents=True)
    (home / "install" / "lib").mkdir()
    server = home / "install" / "bin" / "rcssserver"
    shutil.copyfile(PROGRAMS / "fake_rcssserver.py", server)
    server.chmod(0o755)
    return home


def side(name: str, port: int, mode: str, workdir: Path) -> SideProgram:
    return SideProgram(name, name, (sys.executable, str(PROGRAMS / "fake_side.py"), name, str(port), mode),
                       cwd=str(workdir))


def plan_for(rcss_home: Path, workdir: Path, home_mode: str = "ok", away_mode: str = "ok", **changes) -> MatchPlan:
    port = free_udp_port()
    values = dict(rcss_home=str(rcss_home), workdir=str(workdir), home=side("HOME", port, home_mode, workdir),
                  away=side("AWAY", port, away_mode, workdir), port=port, connect_timeout=10.0, match_timeout=20.0,
                  leave_timeout=0.2)
    values.update(changes)
    return MatchPlan(**values)


def pids(workdir: Path) -> dict[str, int]:
    return {p.stem: int(p.read_text()) for p in workdir.glob("*.pid") if p.read_text().strip()}


def alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    try:  # a zombie waiting for its parent counts as ended
        return Path(f"/proc/{pid}/stat").read_text().split(") ")[1][0] != "Z"
    except OSError:
        return False


def assert_all_ended(workdir: Path, expected: set[str]) -> None:
    started = pids(workdir)
    assert expected <= set(started)
    assert not [name for name, pid in started.items() if alive(pid)]


def test_a_match_starts_both_sides_in_order_and_ends_every_process(rcss_home, tmp_path):
    work = tmp_path / "work"
    work.mkdir()
    outcome = MatchHost(plan_for(rcss_home, work)).play()
    assert Path(outcome.rcg).read_text() == "ULG6\n" and Path(outcome.rcl).is_file()
    output = Path(outcome.server_output).read_text()
    assert output.index("(HOME 11) connected") < output.index("(AWAY 1) connected")  # home first: the left
    assert outcome.wall_time > 0
    assert_all_ended(work, {"fake-server", "HOME", "AWAY"})


def test_a_side_that_fails_ends_the_match_with_its_error_line(rcss_home, tmp_path):
    work = tmp_path / "work"
    work.mkdir()
    with pytest.raises(SideFailed, match=r"^AWAY: error: team 'AWAY', every player .*, step 7 \(server time 5\): "
                                         r"act\(\) raised ValueError: boom$"):
        MatchHost(plan_for(rcss_home, work, away_mode="fail", connect_timeout=10.0)).play()
    assert_all_ended(work, {"fake-server", "HOME", "AWAY"})


def test_a_side_that_never_connects_is_named(rcss_home, tmp_path):
    work = tmp_path / "work"
    work.mkdir()
    with pytest.raises(SideFailed, match=r"^HOME: connected 0 of 11 players within 1 s"):
        MatchHost(plan_for(rcss_home, work, home_mode="silent", connect_timeout=1.0)).play()
    assert_all_ended(work, {"fake-server", "HOME"})


def test_a_server_that_never_ends_the_match_is_stopped(rcss_home, tmp_path, monkeypatch):
    monkeypatch.setenv("FAKE_RCSS_MODE", "hang")
    work = tmp_path / "work"
    work.mkdir()
    with pytest.raises(MatchTimeout, match="did not end within 3 s"):
        MatchHost(plan_for(rcss_home, work, match_timeout=3.0)).play()
    assert_all_ended(work, {"fake-server", "HOME", "AWAY"})


def test_a_server_that_exits_at_start_is_one_line(rcss_home, tmp_path, monkeypatch):
    monkeypatch.setenv("FAKE_RCSS_MODE", "crash")
    work = tmp_path / "work"
    work.mkdir()
    with pytest.raises(ServerError, match=r"rcssserver exited at start \(status 3\): cannot bind"):
        MatchHost(plan_for(rcss_home, work)).play()


def test_a_missing_build_says_how_to_build_it(tmp_path):
    with pytest.raises(MissingBuild, match=r"rcssserver is not built in .*build\.sh --server-only"):
        RcssInstall.find(tmp_path / "nothing").require_server()
    with pytest.raises(MissingBuild, match=r"helios-base is not built in .*build\.sh"):
        RcssInstall.find(tmp_path / "nothing").require_helios()
    with pytest.raises(MissingBuild):
        MatchHost(plan_for(tmp_path / "nothing", tmp_path)).play()


def test_the_host_ended_by_a_signal_ends_what_it_started(rcss_home, tmp_path):
    work = tmp_path / "work"
    work.mkdir()
    plan = plan_for(rcss_home, work, match_timeout=30.0)
    (work / "plan.json").write_text(plan.to_json())
    os.environ["FAKE_RCSS_MODE"] = "hang"
    try:
        host = subprocess.Popen([sys.executable, "-m", "rcss_bridge.match", str(work / "plan.json")],
                                stderr=subprocess.PIPE, text=True)
    finally:
        del os.environ["FAKE_RCSS_MODE"]
    deadline = time.monotonic() + 15
    while len(pids(work)) < 3 and time.monotonic() < deadline:
        time.sleep(0.05)
    host.send_signal(signal.SIGTERM)
    _, err = host.communicate(timeout=20)
    assert host.returncode == 1 and "ended by a signal" in err
    assert_all_ended(work, {"fake-server", "HOME", "AWAY"})


def test_plans_and_names():
    plan = MatchPlan("/x", "/w", SideProgram("a", "A", ("a",)), SideProgram("b", "B", ("b",)), half_time=5)
    assert MatchPlan.from_json(plan.to_json()) == plan
    argv = plan.server_argv(RcssInstall.find("/x"))
    assert "server::synch_mode=true" in argv and "server::half_time=5" in argv
    assert server_team_name("mmd+msd2") == "mmd_msd2" and server_team_name("mmdr", taken="mmdr") == "mmdr_2"
    assert server_team_name("a-very-long-team-name") == "a-very-long-tea"
    with pytest.raises(Exception, match="not one rcssserver takes"):
        SideProgram("x", "bad name", ("x",))


def _namespace_works() -> bool:
    try:
        return subprocess.run(["unshare", "-rn", "true"], capture_output=True, timeout=10).returncode == 0
    except (OSError, subprocess.TimeoutExpired):
        return False


@pytest.mark.skipif(not _namespace_works(), reason="no private network namespace here (unshare -rn)")
def test_a_match_in_a_private_network_namespace(rcss_home, tmp_path):
    work = tmp_path / "work"
    work.mkdir()
    outcome = play_in_namespace(plan_for(rcss_home, work))
    assert Path(outcome.rcg).is_file()
    assert_all_ended(work, {"fake-server", "HOME", "AWAY"})
