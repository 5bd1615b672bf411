"""Reproducibility: the same specs give the same records with 1 or 2 workers, and a run killed
mid-way (kill -9, Ctrl-C) and run again loses and duplicates nothing."""

from __future__ import annotations

import os
import signal
import sqlite3
import subprocess
import sys
import time

import pytest

from experiments.results.store import ResultStore
from experiments.runner import paired_specs, run_matches
from tests.experiments.helpers import outcome


def _command(cycles: int) -> list[str]:
    """The interrupted tournament, with matches of ``cycles`` cycles."""
    return ["tournament", "--teams", "chaser,idle,tests.experiments.scripted_teams:Forward", "--games", "12",
            "--cycles", str(cycles), "--workers", "2", "--no-progress"]


def test_one_and_two_workers_give_identical_records(tmp_path) -> None:
    specs = paired_specs("chaser", "idle", 4, 3, 300) + paired_specs("chaser", "chaser", 2, 3, 300)
    one = run_matches(specs, tmp_path / "one.sqlite", "tournament", {}, cycles=300, workers=1, progress=False)
    two = run_matches(specs, tmp_path / "two.sqlite", "tournament", {}, cycles=300, workers=2, progress=False)
    assert (one.played, two.played, one.errors) == (6, 6, 0)
    assert outcome(one.records) == outcome(two.records)
    assert sum(r.home_goals + r.away_goals for r in one.records) > 0


def _run(args, cwd, **kwargs) -> subprocess.Popen:
    return subprocess.Popen([sys.executable, "-m", "experiments.cli", *args], cwd=cwd, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, start_new_session=True, **kwargs)


def _rows(path) -> int:
    try:
        with sqlite3.connect(path) as db:
            return db.execute("SELECT COUNT(*) FROM matches").fetchone()[0]
    except sqlite3.Error:
        return 0


def _interrupt_midway(args, path, sig, cwd) -> subprocess.Popen:
    process = _run(args, cwd)
    deadline = time.monotonic() + 60
    while _rows(path) < 3 and time.monotonic() < deadline and process.poll() is None:
        time.sleep(0.01)
    assert process.poll() is None, "the run finished before it could be interrupted"
    if sig == signal.SIGKILL:
        os.killpg(process.pid, signal.SIGKILL)          # the whole run, workers included
    else:
        process.send_signal(sig)
    process.wait(30)
    return process


@pytest.mark.parametrize("sig", [signal.SIGKILL, pytest.param(signal.SIGINT, marks=pytest.mark.slow)],
                         ids=["kill-9", "ctrl-c"])
def test_a_stopped_run_resumes_without_loss_or_duplicates(tmp_path, capsys, sig) -> None:
    from experiments.cli import main

    total = 3 * 12
    # Ctrl-C lets the matches under way finish: longer matches keep the run going well past the
    # moment the test sees its first rows, even on a loaded machine.
    command = _command(400 if sig == signal.SIGKILL else 1200)
    reference = tmp_path / "reference.sqlite"
    assert main([*command, "--out", str(reference)]) == 0
    out = capsys.readouterr().out
    assert "mean goal difference" in out

    name = "stopped"
    path = tmp_path / f"{name}.sqlite"
    stopped = _interrupt_midway([*command, "--out", str(path)], path, sig, os.getcwd())
    kept = _rows(path)
    assert 3 <= kept < total
    if sig == signal.SIGINT:
        assert stopped.returncode == 130
        assert "run the same command again" in stopped.stderr.read()
    assert main([*command, "--out", str(path)]) == 0
    out_resumed = capsys.readouterr().out
    assert f"({kept} already stored)" in out_resumed
    assert _rows(path) == total
    with ResultStore.open(path) as store, ResultStore.open(reference) as full:
        assert outcome(store.records()) == outcome(full.records())
    # The printed tables are the same as those of the uninterrupted run.
    assert out_resumed.split("\n", 1)[1] == out.split("\n", 1)[1].replace("reference", name)
