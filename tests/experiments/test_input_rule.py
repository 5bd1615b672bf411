"""The one rule for every file a command reads (:mod:`formations.input_files`): only a
regular file, of a bounded size where the format has a bound, so a FIFO, ``/dev/zero`` or
``/dev/urandom`` given as a scenario, formation, replay, game log or results file is one line
naming it "not a regular file", at once (never a hang, never memory filled)."""

from __future__ import annotations

import os
import subprocess

import pytest

from experiments.cli import main
from tests.experiments.special_files import command, device_node, environment, fifo, one_error_line

KINDS = ["fifo", "zero", "urandom"]


def special(tmp_path, kind: str, name: str):
    """A FIFO or a private node with the numbers of /dev/zero or /dev/urandom, linked as ``name``
    (the name a command expects, e.g. ``s.toml``)."""
    target = fifo(tmp_path, "fifo-node") if kind == "fifo" else device_node(tmp_path, kind)
    link = tmp_path / name
    link.symlink_to(target)
    return link


def run(tmp_path, *args: str) -> subprocess.CompletedProcess:
    """``soccer-sim ARGS`` in a process of its own: a reader that blocked would fail the test by
    its time limit instead of hanging the suite."""
    try:
        return subprocess.run(command(*args), cwd=tmp_path, env=environment(), capture_output=True, text=True,
                              timeout=240, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        pytest.fail(f"soccer-sim {' '.join(args)} did not end: it blocked on (or kept reading) a special file")


@pytest.mark.parametrize("kind", KINDS)
def test_a_special_scenario_file_is_refused_at_once(tmp_path, kind) -> None:
    scenario = special(tmp_path, kind, "s.toml")
    done = run(tmp_path, "play", "idle", "chaser", "--cycles", "5", "--scenario", str(scenario))
    assert done.returncode == 2
    assert "not a regular file" in one_error_line(done.stderr)


@pytest.mark.parametrize("kind", KINDS)
def test_a_special_formation_file_is_refused_at_once(tmp_path, kind) -> None:
    formation = special(tmp_path, kind, "f.conf")
    done = run(tmp_path, "formation", "validate", str(formation))
    assert done.returncode == 2
    assert "not a regular file" in one_error_line(done.stderr)


@pytest.mark.parametrize("kind", ["fifo", "null"])
def test_a_special_results_file_is_not_a_regular_file(tmp_path, kind, capsys) -> None:
    target = fifo(tmp_path) if kind == "fifo" else device_node(tmp_path, "null")
    link = tmp_path / "r.sqlite"
    link.symlink_to(target)                      # a link to a (private) /dev/null-like device
    assert main(["results", "show", str(link)]) == 2
    line = one_error_line(capsys.readouterr().err)
    assert "not a regular file" in line and "no such results file" not in line


def test_a_special_replay_file_is_refused_at_once(tmp_path) -> None:
    replay = special(tmp_path, "fifo", "m.rrd")
    done = run(tmp_path, "replay", str(replay))
    assert done.returncode == 2
    assert "not a regular file (a FIFO)" in one_error_line(done.stderr)


def test_a_special_game_log_is_refused_at_once(tmp_path) -> None:
    log = special(tmp_path, "fifo", "m.rcg")
    code = ("import sys\nfrom soccer_sim.rcg import RcgError, read_rcg\ntry:\n    read_rcg(sys.argv[1])\n"
            "except RcgError as exc:\n    print(exc)\n")
    done = subprocess.run([command()[0], "-c", code, str(log)], cwd=tmp_path, env=environment(), capture_output=True,
                          text=True, timeout=240)
    assert "not a regular file (a FIFO)" in done.stdout


def test_a_scenario_file_larger_than_its_limit_is_refused(tmp_path, capsys) -> None:
    from soccer_sim.scenarios.files import SCENARIO_FILE_LIMIT

    scenario = tmp_path / "s.toml"
    with open(scenario, "wb") as handle:
        handle.truncate(SCENARIO_FILE_LIMIT + 1)  # sparse: no disk used
    assert main(["play", "idle", "chaser", "--cycles", "5", "--scenario", str(scenario)]) == 2
    assert "larger than the 1 MiB a scenario file may hold" in one_error_line(capsys.readouterr().err)
    assert os.path.getsize(scenario) == SCENARIO_FILE_LIMIT + 1


@pytest.mark.parametrize("change", [
    "UPDATE meta SET value = '{not json' WHERE key = 'params'",
    "UPDATE meta SET value = '[1, 2]' WHERE key = 'params'",
    "UPDATE meta SET value = '{}' WHERE key = 'params'",
    "UPDATE matches SET home_goals = 'many'",
    "UPDATE matches SET home_goals = NULL",
])
def test_tampered_results_are_one_line(tmp_path, change, capsys) -> None:
    import sqlite3

    from tests.experiments.test_output_rule import played
    from tests.experiments.test_results_safety import stored

    path = stored(tmp_path / "r.sqlite", played(2))
    with sqlite3.connect(path) as db:
        db.execute(change)
    assert main(["results", "show", str(path)]) == 2
    assert "damaged results file" in one_error_line(capsys.readouterr().err)
