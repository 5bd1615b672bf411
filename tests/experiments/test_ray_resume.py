"""A Ray run whose driver is killed (kill -9) mid-way, then run again with the same command,
stores the same rows and writes the same tables as a run never interrupted.

The driver runs a private local Ray instance in its own session and its own Ray temporary
directory (``RAY_TMPDIR``), so every process of that instance can be found (by its command
line naming that directory) and none is left behind after the kill."""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

from experiments.results.store import ResultsError, ResultStore
from tests.experiments.helpers import outcome

pytest.importorskip("ray")
pytestmark = pytest.mark.xdist_group("ray")  # one Ray instance at a time on the machine

TEAMS = "chaser,idle,tests.experiments.scripted_teams:Forward"
GAMES = 8
TOTAL = 3 * GAMES


def _command(run: Path) -> list[str]:
    return [sys.executable, "-m", "experiments.cli", "tournament", "--teams", TEAMS, "--games", str(GAMES),
            "--cycles", "300", "--workers", "2", "--no-progress", "--backend", "ray",
            "--out", str(run / "results.sqlite"), "--tables", str(run / "tables")]


def _stored(path: Path) -> int:
    """Rows in ``path`` read as any reader would, read-only (0 before the file exists)."""
    try:
        with ResultStore.open(path) as store:
            return store.count()
    except ResultsError:
        return 0


def _ray_processes(ray_dir: str) -> list[int]:
    """PIDs of the live processes whose command line names ``ray_dir`` (the instance's own)."""
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            cmdline = (entry / "cmdline").read_bytes().decode(errors="replace")
            state = (entry / "stat").read_text().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if ray_dir in cmdline and state != "Z":
            found.append(int(entry.name))
    return found


def _kill_all(pids: list[int]) -> None:
    for pid in pids:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:
            pass


def _gone(ray_dir: str, seconds: float) -> bool:
    deadline = time.monotonic() + seconds
    while _ray_processes(ray_dir) and time.monotonic() < deadline:
        time.sleep(0.1)
    return not _ray_processes(ray_dir)


@pytest.mark.slow
def test_a_ray_run_killed_mid_way_resumes_to_the_rows_and_tables_of_an_uninterrupted_run(tmp_path) -> None:
    ray_dir = tempfile.mkdtemp(prefix="rk", dir="/tmp")  # short: Ray's socket paths live under it
    env = {key: value for key, value in os.environ.items() if key != "RAY_ADDRESS"}
    env["RAY_TMPDIR"] = ray_dir
    reference, stopped = tmp_path / "reference", tmp_path / "stopped"
    reference.mkdir()
    stopped.mkdir()
    try:
        done = subprocess.run(_command(reference), env=env, capture_output=True, text=True, timeout=600)
        assert done.returncode == 0, done.stderr
        assert _gone(ray_dir, 30), "an uninterrupted run left Ray processes behind"

        path = stopped / "results.sqlite"
        driver = subprocess.Popen(_command(stopped), env=env, stdout=subprocess.DEVNULL,
                                  stderr=subprocess.DEVNULL, start_new_session=True)
        deadline = time.monotonic() + 300
        while _stored(path) < 3 and time.monotonic() < deadline and driver.poll() is None:
            time.sleep(0.05)
        assert driver.poll() is None, "the run finished before it could be killed"
        os.killpg(driver.pid, signal.SIGKILL)  # the driver and whatever shares its session
        driver.wait(30)
        _kill_all(_ray_processes(ray_dir))      # what outlived its session (a worker may, briefly)
        assert _gone(ray_dir, 30), f"Ray processes left after the kill: {_ray_processes(ray_dir)}"
        kept = _stored(path)
        assert 3 <= kept < TOTAL

        resumed = subprocess.run(_command(stopped), env=env, capture_output=True, text=True, timeout=600)
        assert resumed.returncode == 0, resumed.stderr
        assert f"({kept} already stored)" in resumed.stdout
        with ResultStore.open(path) as store, ResultStore.open(reference / "results.sqlite") as full:
            assert store.count() == TOTAL
            assert outcome(store.records()) == outcome(full.records())
        names = sorted(p.name for p in (reference / "tables").iterdir())
        assert names and names == sorted(p.name for p in (stopped / "tables").iterdir())
        for name in names:
            assert (stopped / "tables" / name).read_bytes() == (reference / "tables" / name).read_bytes(), name
        # The printed tables too (the first line counts the matches and time of each run).
        assert resumed.stdout.split("\n", 1)[1] == done.stdout.split("\n", 1)[1].replace(str(reference), str(stopped))
    finally:
        _kill_all(_ray_processes(ray_dir))
        shutil.rmtree(ray_dir, ignore_errors=True)
