"""Several runs on one results file: creation races, rows of other configurations, runs that
split the matches through leases, leases of killed runs, and resumes across code versions."""

from __future__ import annotations

import hashlib
import multiprocessing
import socket
import sqlite3
import subprocess
import threading
import time
from pathlib import Path

import pytest

from experiments.cli import main
from experiments.results.record import MatchRecord
from experiments.results.store import ResultsError, ResultStore
from experiments.runner import paired_specs, run_matches
from experiments.runner.spec import code_version, config_description, config_for, config_hash
from tests.experiments.helpers import outcome

CYCLES = 20
QUICK = ["--cycles", str(CYCLES), "--workers", "1", "--no-progress"]


def _create(path: str, config_hash: str, barrier, results) -> None:
    """One process of the creation race: open a new file with ``config_hash`` at the barrier."""
    barrier.wait()
    try:
        ResultStore.create(path, "tournament", config_hash, "{}", {}).close()
        results.put((config_hash, "accepted"))
    except ResultsError as exc:
        results.put((config_hash, str(exc)))


def test_of_two_runs_creating_one_file_with_different_configurations_one_is_refused(tmp_path) -> None:
    context = multiprocessing.get_context("fork")
    for trial in range(20):
        path = str(tmp_path / f"race{trial}.sqlite")
        barrier, results = context.Barrier(2), context.Queue()
        processes = [context.Process(target=_create, args=(path, digest, barrier, results))
                     for digest in ("aaaa1111", "bbbb2222")]
        for process in processes:
            process.start()
        outcomes = dict(results.get(timeout=60) for _ in processes)
        for process in processes:
            process.join(30)
        winners = [digest for digest, text in outcomes.items() if text == "accepted"]
        assert len(winners) == 1, (trial, outcomes)
        (refused,) = set(outcomes) - set(winners)
        message = outcomes[refused]
        assert path in message and "different match configuration" in message
        assert f"hash {winners[0]}" in message and f"this run: hash {refused}" in message
        with ResultStore.open(path) as store:
            assert store.config_hash == winners[0]


def test_a_file_that_reads_as_damaged_while_another_run_writes_it_is_read_again(tmp_path, monkeypatch) -> None:
    """The creation race's rare turn: the other run's first pages are being written while this
    run looks, so the file reads as damaged once; it is read again and the run is refused for
    the configuration, not for a damaged file. A damaged file nobody writes is refused at once."""
    import experiments.results.store as store_module

    path = tmp_path / "r.sqlite"
    ResultStore.create(path, "tournament", "aaaa1111", "{}", {}).close()
    real = store_module.connect_read_only
    reads = []

    def half_written(at):
        reads.append(at)
        if len(reads) == 1:  # the writer is at work: the file changes while it is read
            at.write_bytes(at.read_bytes() + b"\0" * 4096)
            raise sqlite3.DatabaseError("database disk image is malformed")
        return real(at)

    monkeypatch.setattr(store_module, "connect_read_only", half_written)
    with pytest.raises(ResultsError, match="different match configuration"):
        ResultStore.create(path, "tournament", "bbbb2222", "{}", {})
    assert len(reads) == 2

    reads.clear()
    still = tmp_path / "still.sqlite"
    still.write_bytes(b"SQLite format 3\0" + b"\1" * 4000)
    monkeypatch.setattr(store_module, "connect_read_only", real)
    with pytest.raises(ResultsError, match="cannot be used as a results file"):
        ResultStore.create(still, "tournament", "bbbb2222", "{}", {})
    assert still.read_bytes() == b"SQLite format 3\0" + b"\1" * 4000


def test_the_refusal_names_the_parameters_that_differ(tmp_path) -> None:
    path = tmp_path / "r.sqlite"
    first, second = config_for(30), config_for(40)
    ResultStore.create(path, "tournament", config_hash(first), config_description(first), {}).close()
    with pytest.raises(ResultsError) as refused:
        ResultStore.create(path, "tournament", config_hash(second), config_description(second), {})
    assert str(refused.value).startswith(f"{path} holds results of a different match configuration (hash "
                                         f"{config_hash(first)}: max_cycles=30; this run: hash "
                                         f"{config_hash(second)}: max_cycles=40;")


def _foreign_row(path: Path, key: tuple[str, str, int], config_hash: str, error: str | None = None) -> None:
    """A row of another configuration written into ``path`` behind the store's back."""
    with sqlite3.connect(path) as db:
        db.execute("INSERT INTO matches (home, away, seed, config_hash, code_version, home_goals, away_goals, "
                   "cycles, wall_time, home_stats, away_stats, error, forfeit) VALUES (?, ?, ?, ?, 'v', 5, 0, 9, "
                   "0.1, '{}', '{}', ?, -1)", (*key, config_hash, error))
    db.close()


def test_rows_of_another_configuration_are_neither_read_nor_counted(tmp_path) -> None:
    path = tmp_path / "r.sqlite"
    with ResultStore.create(path, "tournament", "aaa", "{}", {}) as store:
        store.add(MatchRecord("A", "B", 1, "aaa", home_goals=1, away_goals=0))
    _foreign_row(path, ("A", "B", 2), "bbb", error="WorkerDied: gone")
    _foreign_row(path, ("A", "B", 1), "bbb")
    for opened in (lambda: ResultStore.open(path), lambda: ResultStore.create(path, "tournament", "aaa", "{}", {})):
        with opened() as store:
            assert store.keys() == {("A", "B", 1)}
            assert store.count() == 1
            assert [(r.key, r.config_hash, r.home_goals) for r in store.records()] == [(("A", "B", 1), "aaa", 1)]
            assert store.code_versions() == {""}
    with ResultStore.create(path, "tournament", "aaa", "{}", {}) as store:
        assert store.forget_errors([("A", "B", 2)]) == 0              # another configuration's row is kept
    with sqlite3.connect(path) as db:
        assert db.execute("SELECT COUNT(*) FROM matches").fetchone()[0] == 3
    db.close()
    with ResultStore.create(path, "tournament", "aaa", "{}", {}) as store, \
            pytest.raises(ValueError, match="configuration bbb cannot be stored in a file of configuration aaa"):
        store.add(MatchRecord("A", "B", 3, "bbb", home_goals=1, away_goals=0))


def test_a_run_plays_the_matches_only_another_configuration_has_stored(tmp_path) -> None:
    path = tmp_path / "r.sqlite"
    specs = paired_specs("idle", "chaser", 2, 0, CYCLES)
    run_matches(specs[:1], path, "tournament", {}, cycles=CYCLES, workers=1, progress=False)
    _foreign_row(path, specs[1].key, "another-config")
    summary = run_matches(specs, path, "tournament", {}, cycles=CYCLES, workers=1, progress=False)
    assert (summary.already_stored, summary.played) == (1, 1)
    assert [r.config_hash for r in summary.records] == [config_hash(config_for(CYCLES))] * 2


# -- two runs sharing a file ---------------------------------------------------------------------

SHARED_SPECS = [spec for seed in range(8) for spec in paired_specs("idle", "chaser", 2, seed * 10, CYCLES)] + \
    paired_specs("idle", "idle", 8, 100, CYCLES)


def _drive(path: str, barrier, results) -> None:
    """One of two runs of the same specs on one file, started together at the barrier."""
    barrier.wait()
    try:
        summary = run_matches(SHARED_SPECS, path, "tournament", {}, cycles=CYCLES, workers=1, progress=False)
        results.put({**vars(summary), "records": outcome(summary.records)})
    except Exception as exc:  # noqa: BLE001 - reported to the test, which fails with it
        results.put(f"{type(exc).__name__}: {exc}")


def test_two_runs_on_one_file_split_the_matches_and_both_end_complete(tmp_path) -> None:
    path = str(tmp_path / "shared.sqlite")
    run_matches(SHARED_SPECS[:1], path, "tournament", {}, cycles=CYCLES, workers=1, progress=False)  # kernels
    context = multiprocessing.get_context("spawn")
    barrier, results = context.Barrier(2), context.Queue()
    drivers = [context.Process(target=_drive, args=(path, barrier, results)) for _ in range(2)]
    for driver in drivers:
        driver.start()
    outcomes = [results.get(timeout=600) for _ in drivers]
    for driver in drivers:
        driver.join(60)
    assert not any(isinstance(result, str) for result in outcomes), outcomes
    a, b = outcomes
    assert len(SHARED_SPECS) == 24
    assert a["played"] + b["played"] == len(SHARED_SPECS) - 1     # every match played once in all
    assert (a["unfinished"], b["unfinished"]) == (0, 0)
    assert a["records"] == b["records"] and len(a["records"]) == len(SHARED_SPECS)
    assert (a["by_others"], b["by_others"]) == (b["played"], a["played"])
    with sqlite3.connect(path) as db:
        assert db.execute("SELECT COUNT(*) FROM leases").fetchone()[0] == 0
    db.close()


def _lease(path: Path, key: tuple[str, str, int], owner: str, expires_in: float) -> None:
    """Another run's lease on ``key`` (its owner id, expiring ``expires_in`` seconds from now)."""
    with sqlite3.connect(path) as db:
        db.execute("CREATE TABLE IF NOT EXISTS leases (home TEXT NOT NULL, away TEXT NOT NULL, seed INTEGER NOT "
                   "NULL, owner TEXT NOT NULL, expires_at REAL NOT NULL, PRIMARY KEY (home, away, seed))")
        db.execute("INSERT INTO leases VALUES (?, ?, ?, ?, ?)", (*key, owner, time.time() + expires_in))
    db.close()


def _dead_pid() -> int:
    process = subprocess.Popen(["true"])
    process.wait()
    return process.pid


def _prepared(path: Path, specs) -> None:
    """A results file of ``specs``' configuration holding none of them."""
    config = config_for(CYCLES)
    ResultStore.create(path, "tournament", config_hash(config), config_description(config), {}).close()


def test_leases_of_killed_runs_are_taken_over_and_a_live_runs_match_is_waited_for(tmp_path) -> None:
    path = tmp_path / "r.sqlite"
    specs = paired_specs("idle", "chaser", 6, 0, CYCLES)
    _prepared(path, specs)
    _lease(path, specs[0].key, "elsewhere:1234:feed", expires_in=-1.0)                      # expired
    _lease(path, specs[1].key, f"{socket.gethostname()}:{_dead_pid()}:dead", expires_in=3600)  # process gone
    other = "elsewhere:99:live"
    _lease(path, specs[2].key, other, expires_in=3600)                                      # another live run
    digest = config_hash(config_for(CYCLES))

    def other_run() -> None:                 # stores its match once the first run has played the rest
        deadline = time.monotonic() + 300
        while time.monotonic() < deadline:
            with ResultStore.open(path) as store:
                if len(store.keys()) >= len(specs) - 1:
                    break
            time.sleep(0.05)
        with ResultStore.create(path, "tournament", digest, config_description(config_for(CYCLES)), {}) as store:
            store.lease_owner = other
            store.add(MatchRecord(*specs[2].key, digest, "v", 7, 7, CYCLES))

    thread = threading.Thread(target=other_run)
    thread.start()
    try:
        summary = run_matches(specs, path, "tournament", {}, cycles=CYCLES, workers=1, progress=False)
    finally:
        thread.join()
    assert summary.played == len(specs) - 1
    assert (summary.by_others, summary.unfinished) == (1, 0)
    assert sorted(r.key for r in summary.records) == sorted(spec.key for spec in specs)
    assert [r.home_goals for r in summary.records if r.key == specs[2].key] == [7]     # not played again
    with sqlite3.connect(path) as db:
        assert db.execute("SELECT COUNT(*) FROM leases").fetchone()[0] == 0
    db.close()


@pytest.mark.slow  # test_run_exit_codes keeps a run that exits 1 for missing matches in the default suite
def test_a_run_that_stops_waiting_for_another_runs_matches_exits_1(tmp_path, capsys, monkeypatch) -> None:
    import experiments.runner.run as run_module

    path = tmp_path / "t.sqlite"
    assert main(["tournament", "--teams", "idle,chaser", "--games", "2", "--out", str(path), *QUICK]) == 0
    capsys.readouterr()
    specs = paired_specs("idle", "chaser", 4, 0, CYCLES)
    _lease(path, specs[3].key, "elsewhere:1234:live", expires_in=3600)
    monkeypatch.setattr(run_module, "LEASE_SECONDS", 0.0, raising=False)   # wait: the match timeout only
    status = main(["tournament", "--teams", "idle,chaser", "--games", "4", "--out", str(path),
                   "--match-timeout", "2", *QUICK])
    captured = capsys.readouterr()
    assert status == 1, captured.err
    assert captured.err.strip().splitlines()[-1] == (
        "error: tables incomplete: 1 matches are being played by another driver; run the same command again "
        "when it finishes")
    assert "(2 already stored): played 1" in captured.out
    with ResultStore.open(path) as store:
        assert len(store.keys()) == 3


# -- code versions ---------------------------------------------------------------------------------

def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.mark.slow  # slow: the default run keeps the other store-sharing checks
def test_a_resume_mixing_code_versions_warns_and_same_code_refuses(tmp_path, capsys) -> None:
    import sqlite3

    path = tmp_path / "t.sqlite"
    command = ["tournament", "--teams", "idle,chaser", "--out", str(path), *QUICK]
    assert main([*command, "--games", "2"]) == 0
    with sqlite3.connect(path) as db:               # as if an older version of the code played them
        db.execute("UPDATE matches SET code_version = '0.0.1+old'")
    db.close()
    capsys.readouterr()
    assert main([*command, "--games", "2"]) == 0                  # nothing to play: nothing mixed
    assert "warning" not in capsys.readouterr().err

    assert main([*command, "--games", "4"]) == 0
    warnings = [line for line in capsys.readouterr().err.splitlines() if line.startswith("warning:")]
    assert warnings == [f"warning: {path} holds matches played by another code version (0.0.1+old); this run "
                        f"plays the rest with {code_version()}, so its tables mix code versions (--same-code "
                        "refuses this)"]
    with ResultStore.open(path) as store:
        assert store.code_versions() == {"0.0.1+old", code_version()}

    before = _digest(path)
    assert main([*command, "--games", "6", "--same-code"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith(f"error: {path} holds matches played by another code version "
                                               f"(0.0.1+old), not by this code ({code_version()})"), err
    assert "--same-code" in err[0]
    assert _digest(path) == before
    assert main([*command, "--games", "6"]) == 0                  # mixed already: said again
    assert "another code version (0.0.1+old); this run plays" in capsys.readouterr().err

    from experiments.runner.run import MixedCodeVersions, MixedCodeWarning

    specs = paired_specs("idle", "chaser", 8, 0, CYCLES)               # the library: a warning, an error
    with pytest.warns(MixedCodeWarning, match="same_code refuses this"):
        run_matches(specs, path, "tournament", {}, cycles=CYCLES, workers=1, progress=False)
    with pytest.raises(MixedCodeVersions) as refused:
        run_matches(paired_specs("idle", "chaser", 10, 0, CYCLES), path, "tournament", {}, cycles=CYCLES, workers=1,
                    progress=False, same_code=True)
    assert "--" not in str(refused.value) and refused.value.others == "0.0.1+old"
