"""On Ray as on the local pool, a worker that dies inside a team's code forfeits the match for
that team (read from the slot file the task keeps on its node), and that failure does not
count against the node; a worker that dies outside any team's code is the node's failure."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest

from experiments.results.record import FORFEIT_NONE
from experiments.runner.slots import STALE_AFTER, FileSlot, slot_path, sweep_stale, take_slot
from tests.experiments.helpers import SCRIPTED

# ---- the slot file (no Ray) ----------------------------------------------------------------------

DIE_IN_AWAY_CODE = """
import os, sys
from experiments.runner.slots import FileSlot
slot = FileSlot(sys.argv[1])
slot.values[1] = 0      # the home side's act returned last
slot.values[0] = 1      # the away side's code runs now...
os._exit(3)             # ...and its process dies
"""


def test_a_slot_written_by_a_process_that_dies_tells_the_side_and_is_removed(tmp_path) -> None:
    token = "ab12" * 8
    died = subprocess.run([sys.executable, "-c", DIE_IN_AWAY_CODE, token], timeout=60)
    assert died.returncode == 3
    assert slot_path(token).exists()
    assert take_slot(token) == 1
    assert not slot_path(token).exists()
    assert take_slot(token) == FORFEIT_NONE  # no file (the task returned, or it was read): nobody


def test_a_slot_starts_unblamed_and_its_file_goes_when_the_task_returns() -> None:
    token = "cd34" * 8
    with FileSlot(token) as slot:
        assert list(slot.values) == [FORFEIT_NONE, FORFEIT_NONE]
        slot.values[0] = 0
        assert slot_path(token).read_bytes() != b""
    assert not slot_path(token).exists()


def test_slot_files_nobody_read_are_swept_once_stale(tmp_path) -> None:
    stale, fresh, other = tmp_path / "a.slot", tmp_path / "b.slot", tmp_path / "c.txt"
    for path in (stale, fresh, other):
        path.write_bytes(b"x")
    now = stale.stat().st_mtime + STALE_AFTER + 1
    os.utime(fresh, (now, now))
    os.utime(other, (0, 0))
    sweep_stale(tmp_path, now)
    assert not stale.exists() and fresh.exists() and other.exists()


def test_a_slot_token_must_be_hex() -> None:
    with pytest.raises(ValueError, match="slot token '../x'"):
        slot_path("../x")


# ---- on a local Ray instance ---------------------------------------------------------------------

pytest.importorskip("ray")
pytestmark = pytest.mark.xdist_group("ray")  # one Ray instance at a time on the machine


@pytest.mark.slow  # the local backend's crash blame stays in the default run (test_run_exit_codes)
def test_on_ray_a_team_that_crashes_its_worker_forfeits_and_the_node_stays(tmp_path, capsys) -> None:
    from experiments.cli import main
    from experiments.results.store import ResultStore

    crasher = SCRIPTED + "CrashingTeam"
    out = tmp_path / "ray.sqlite"
    # Four crashes on the only node: counted as the node's failures they would take it out.
    status = main(["tournament", "--teams", f"{crasher},idle", "--games", "4", "--cycles", "60", "--workers", "1",
                   "--no-progress", "--backend", "ray", "--out", str(out)])
    err = capsys.readouterr().err
    assert status == 0, err
    assert "excluded" not in err
    with ResultStore.open(out) as store:
        records = store.records()
    assert len(records) == 4
    for record in records:
        side = (record.home, record.away).index(crasher)
        assert record.forfeit == side
        assert record.error.startswith("WorkerDied: the Ray worker process on node ")
        assert record.error.endswith(f"it was running the code of the {('home', 'away')[side]} team {crasher!r}")


@pytest.mark.slow  # Ray start-up: the default suite keeps one Ray run of each kind
def test_on_ray_a_worker_that_dies_outside_team_code_is_the_nodes_failure(monkeypatch) -> None:
    from experiments.runner import ray_backend
    from experiments.runner.ray_backend import MATCH_RETRIES, NODE_FAILURE_LIMIT, RayPool
    from experiments.runner.spec import MatchSpec, code_version, config_for, config_hash
    from tests.experiments.scripted_teams import CrashingFigures

    monkeypatch.delenv("RAY_ADDRESS", raising=False)
    monkeypatch.setattr(ray_backend, "NODE_WAIT", 0.0)
    pool = RayPool(1, config_hash(config_for(60)), code_version(), None, figures=CrashingFigures)
    try:
        specs = [MatchSpec("chaser", "idle", 0, 60)]
        pool.warm_up(specs)
        records = list(pool.run(specs))
        node = next(iter(pool._nodes.values()))
    finally:
        pool.close()
    assert MATCH_RETRIES + 1 == NODE_FAILURE_LIMIT  # so the one match takes the node out
    assert len(records) == 1 and records[0].forfeit == FORFEIT_NONE
    assert records[0].error.startswith("RayTaskFailed on node ") and "WorkerCrashedError" in records[0].error
    assert node.state == "out" and node.failures == NODE_FAILURE_LIMIT


@pytest.mark.slow
def test_on_ray_a_team_hung_deaf_to_the_timer_forfeits_when_its_task_is_cancelled(tmp_path, monkeypatch,
                                                                                   capsys) -> None:
    from experiments.cli import main
    from experiments.results.store import ResultStore
    from experiments.runner import ray_backend

    monkeypatch.setattr(ray_backend, "RAY_GRACE", 0.5)
    hanging = SCRIPTED + "DeafHangingTeam"
    out = tmp_path / "ray.sqlite"
    status = main(["tournament", "--teams", f"{hanging},idle", "--games", "2", "--cycles", "60", "--workers", "2",
                   "--match-timeout", "4", "--no-progress", "--backend", "ray", "--out", str(out)])
    err = capsys.readouterr().err
    assert status == 0, err
    with ResultStore.open(out) as store:
        records = store.records()
    assert len(records) == 2
    for record in records:
        side = (record.home, record.away).index(hanging)
        assert record.forfeit == side
        assert record.error == ("MatchTimeout: match exceeded its time budget of 4 s and its Ray task was cancelled; "
                                f"it was running the code of the {('home', 'away')[side]} team {hanging!r}")
