"""The SQLite results store: atomic rows, no duplicates, and refusal to mix runs."""

from __future__ import annotations

import os

import pytest

from experiments.results.record import MatchRecord
from experiments.results.store import ResultsError, ResultStore


def make(path, config_hash="aaa", kind="tournament") -> ResultStore:
    return ResultStore.create(path, kind, config_hash, "{}", {"teams": ["A", "B"]})


def test_rows_round_trip_and_keys_are_unique(tmp_path) -> None:
    path = tmp_path / "r.sqlite"
    record = MatchRecord("A", "B", 3, "aaa", "v1", 2, 1, 6000, 1.5, {"goals": 2, "role_switches_per_minute": 3.5},
                         {"goals": 1})
    with make(path) as store:
        store.add(record)
        store.add(MatchRecord("A", "B", 3, "aaa", home_goals=9, away_goals=9))       # same key: kept as first
        store.add(MatchRecord("B", "A", 3, "aaa", error="TeamError: x", traceback="tb", forfeit=0))
        assert store.count() == 2 and store.keys() == {("A", "B", 3), ("B", "A", 3)}
    with ResultStore.open(path) as store:
        first, second = store.records()
        assert first == record
        assert (second.played, second.forfeit, second.traceback) == (False, 0, "tb")
        assert store.params == {"teams": ["A", "B"]} and store.kind == "tournament"
    with make(path) as store:                                  # (open() is read-only)
        assert store.forget_errors([("B", "A", 3)], unattributed_only=True) == 0
        assert store.forget_errors([("B", "A", 3)]) == 1 and store.count() == 1


def test_refuses_other_configurations_and_commands(tmp_path) -> None:
    path = tmp_path / "r.sqlite"
    make(path).close()
    with pytest.raises(ResultsError, match="different match configuration.*to start fresh, delete"):
        make(path, config_hash="bbb")
    with pytest.raises(ResultsError, match="holds the results of 'tournament', not 'case-study'"):
        make(path, kind="case-study")
    make(path).close()                                         # the same run continues


def test_bad_paths_have_clear_messages(tmp_path) -> None:
    with pytest.raises(ResultsError, match="does not exist"):
        make(tmp_path / "missing" / "r.sqlite")
    with pytest.raises(ResultsError, match="is a directory"):
        make(tmp_path)
    locked = tmp_path / "locked"
    locked.mkdir()
    os.chmod(locked, 0o500)
    try:
        if not os.access(locked, os.W_OK):                     # (root may write anyway)
            with pytest.raises(ResultsError, match="not writable"):
                make(locked / "r.sqlite")
    finally:
        os.chmod(locked, 0o700)
    junk = tmp_path / "junk.sqlite"
    junk.write_text("not a database")
    with pytest.raises(ResultsError, match="junk.sqlite"):
        ResultStore.open(junk)
    with pytest.raises(ResultsError, match="no such results file"):
        ResultStore.open(tmp_path / "none.sqlite")


def test_a_results_file_whose_matches_table_is_gone_is_refused_untouched(tmp_path) -> None:
    import sqlite3

    path = tmp_path / "r.sqlite"
    ResultStore.create(path, "tournament", "h1", "{}", {}).close()
    with sqlite3.connect(path) as db:
        db.executescript("PRAGMA journal_mode=DELETE; DROP TABLE matches;")
    before = path.read_bytes()
    with pytest.raises(ResultsError, match="damaged results file .its matches table is missing"):
        ResultStore.create(path, "tournament", "h1", "{}", {})
    assert path.read_bytes() == before
