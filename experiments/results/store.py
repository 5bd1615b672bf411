"""The results store: one embedded SQLite file per run, one row per match.

The parent process writes every finished match in its own transaction, so an interrupted run
(Ctrl-C, ``kill -9``, a crashed worker) leaves only whole rows behind, and the primary key
(home, away, seed, configuration hash) makes re-running the same command play only what is
missing. The file also records what made it (the command's kind and parameters and the match
configuration): results of a different configuration or command are never mixed into it.
"""

from __future__ import annotations

import json
import os
import sqlite3
from collections.abc import Iterable
from pathlib import Path

from experiments.results.record import FORFEIT_NONE, MatchRecord

SCHEMA_VERSION = "1"

_SCHEMA = """
CREATE TABLE IF NOT EXISTS meta (key TEXT PRIMARY KEY, value TEXT NOT NULL);
CREATE TABLE IF NOT EXISTS matches (
    home TEXT NOT NULL, away TEXT NOT NULL, seed INTEGER NOT NULL, config_hash TEXT NOT NULL,
    code_version TEXT NOT NULL, home_goals INTEGER, away_goals INTEGER, cycles INTEGER NOT NULL,
    wall_time REAL NOT NULL, home_stats TEXT NOT NULL, away_stats TEXT NOT NULL,
    error TEXT, traceback TEXT, forfeit INTEGER NOT NULL,
    finished_at TEXT NOT NULL DEFAULT (strftime('%Y-%m-%dT%H:%M:%fZ', 'now')),
    PRIMARY KEY (home, away, seed, config_hash)
);
"""

COLUMNS = ("home", "away", "seed", "config_hash", "code_version", "home_goals", "away_goals", "cycles",
           "wall_time", "home_stats", "away_stats", "error", "traceback", "forfeit")


class ResultsError(Exception):
    """A results file cannot be used: unreadable, unwritable, not a results file, or made by a
    different configuration or command. The message names the file and says what to do."""


class ResultStore:
    """An open results file. Use :meth:`create` to run into it and :meth:`open` to read it."""

    def __init__(self, path: Path, connection: sqlite3.Connection) -> None:
        self.path = path
        self._db = connection

    # -- opening ----------------------------------------------------------------------------
    @classmethod
    def open(cls, path: str | os.PathLike) -> ResultStore:
        """Open an existing results file for reading."""
        path = Path(path)
        if not path.is_file():
            raise ResultsError(f"{path}: no such results file")
        store = cls(path, _connect(path))
        try:
            meta = store.meta()
        except sqlite3.DatabaseError as exc:
            store.close()
            raise ResultsError(f"{path}: not a soccer-sim results file ({exc})") from None
        if "kind" not in meta:
            store.close()
            raise ResultsError(f"{path}: not a soccer-sim results file (no run description)")
        return store

    @classmethod
    def create(cls, path: str | os.PathLike, kind: str, config_hash: str, config: str,
               params: dict[str, object]) -> ResultStore:
        """Open ``path`` to store matches of command ``kind`` played with configuration
        ``config_hash`` (``config``: its description), creating the file if needed. An existing
        file must hold the same kind and configuration; ``params`` (the command's parameters)
        replace the stored ones, so ``results show`` repeats the latest run's tables."""
        path = Path(path)
        parent = path.parent if str(path.parent) else Path(".")
        if path.is_dir():
            raise ResultsError(f"{path}: is a directory; give a file name for the results (e.g. {path / 'results.sqlite'})")
        if not parent.is_dir():
            raise ResultsError(f"{path}: directory {parent} does not exist")
        if not os.access(parent, os.W_OK) or (path.exists() and not os.access(path, os.W_OK)):
            raise ResultsError(f"{path}: not writable (permission denied)")
        existed = path.exists() and path.stat().st_size > 0
        try:
            store = cls(path, _connect(path))
            if existed:
                meta = store.meta()
                store._check_same_run(meta, kind, config_hash)
            with store._db:
                store._db.executescript(_SCHEMA)
                for key, value in (("schema", SCHEMA_VERSION), ("kind", kind), ("config_hash", config_hash),
                                   ("config", config), ("params", json.dumps(params, sort_keys=True))):
                    store._db.execute("INSERT OR REPLACE INTO meta VALUES (?, ?)", (key, value))
        except sqlite3.DatabaseError as exc:
            raise ResultsError(f"{path}: cannot be used as a results file ({exc}); delete it or give another --out") from None
        return store

    def _check_same_run(self, meta: dict[str, str], kind: str, config_hash: str) -> None:
        if not meta:
            return
        fresh = f"to start fresh, delete {self.path} or give another --out"
        if meta.get("kind") not in (None, kind):
            self.close()
            raise ResultsError(f"{self.path} holds the results of '{meta['kind']}', not '{kind}'; {fresh}")
        if meta.get("config_hash") not in (None, config_hash):
            self.close()
            raise ResultsError(f"{self.path} holds results of a different match configuration "
                               f"(hash {meta['config_hash']}, this run: {config_hash}; e.g. another --cycles); "
                               f"results of different configurations are never mixed; {fresh}")

    # -- reading ----------------------------------------------------------------------------
    def meta(self) -> dict[str, str]:
        tables = {row[0] for row in self._db.execute("SELECT name FROM sqlite_master WHERE type = 'table'")}
        if "meta" not in tables:
            return {}
        return dict(self._db.execute("SELECT key, value FROM meta").fetchall())

    @property
    def kind(self) -> str:
        return self.meta()["kind"]

    @property
    def params(self) -> dict[str, object]:
        return json.loads(self.meta().get("params", "{}"))

    def keys(self) -> set[tuple[str, str, int]]:
        """(home, away, seed) of every stored match."""
        return {tuple(row) for row in self._db.execute("SELECT home, away, seed FROM matches")}

    def records(self, keys: Iterable[tuple[str, str, int]] | None = None) -> list[MatchRecord]:
        """Stored matches (all, or those of ``keys``), sorted by key: the same list whatever
        order the matches finished in."""
        cursor = self._db.execute(f"SELECT {', '.join(COLUMNS)} FROM matches ORDER BY home, away, seed")
        records = [MatchRecord.from_row(dict(zip(COLUMNS, row))) for row in cursor]
        if keys is not None:
            wanted = set(keys)
            records = [r for r in records if r.key in wanted]
        return records

    def count(self) -> int:
        return int(self._db.execute("SELECT COUNT(*) FROM matches").fetchone()[0])

    # -- writing ----------------------------------------------------------------------------
    def add(self, record: MatchRecord) -> None:
        """Store one finished match in its own transaction (a key already stored is kept)."""
        row = record.to_row()
        with self._db:
            self._db.execute(f"INSERT OR IGNORE INTO matches ({', '.join(COLUMNS)}) VALUES "
                             f"({', '.join('?' for _ in COLUMNS)})", [row[c] for c in COLUMNS])

    def forget_errors(self, keys: Iterable[tuple[str, str, int]], unattributed_only: bool = False) -> int:
        """Delete the failed matches among ``keys`` so they are played again (only those no team
        is blamed for, e.g. a worker that died, with ``unattributed_only``); their number."""
        extra = f" AND forfeit = {FORFEIT_NONE}" if unattributed_only else ""
        with self._db:
            return sum(self._db.execute("DELETE FROM matches WHERE home = ? AND away = ? AND seed = ? "
                                        f"AND error IS NOT NULL{extra}", key).rowcount for key in keys)

    def close(self) -> None:
        self._db.close()

    def __enter__(self) -> ResultStore:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def _connect(path: Path) -> sqlite3.Connection:
    try:
        db = sqlite3.connect(str(path), timeout=30.0)
        db.execute("PRAGMA journal_mode = WAL")       # each commit is atomic and survives kill -9
        db.execute("PRAGMA synchronous = NORMAL")
    except sqlite3.DatabaseError as exc:
        raise ResultsError(f"{path}: cannot open as a results file ({exc})") from None
    return db
