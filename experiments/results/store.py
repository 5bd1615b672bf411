"""The results store: one embedded SQLite file per run, one row per match.

The parent process writes every finished match in its own transaction, so an interrupted run
(Ctrl-C, ``kill -9``, a crashed worker) leaves only whole rows behind, and the primary key
(home, away, seed, configuration hash) makes re-running the same command play only what is
missing. The file also records what made it (the command's kind and parameters and the match
configuration): results of a different configuration or command are never mixed into it, and
only rows of the file's configuration are read or counted. Several runs may share one file on a
local disk: creating it and checking its settings is one transaction (of two runs starting on a
new file with different settings, one is refused), and work is split between them through
leases (:mod:`experiments.results.leases`).

Reading never changes a file: :meth:`ResultStore.open` opens it read-only (no journal-mode
switch, no new tables, nothing written into an empty or foreign file), which also works on
read-only media. Writing checkpoints the write-ahead log after every stored match and on
close, so the ``.sqlite`` file alone holds every stored row even after ``kill -9`` (a leftover
``-wal`` file is merged by the next writer, and read as it is by readers).
"""

from __future__ import annotations

import contextlib
import errno
import json
import os
import sqlite3
import time
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path

from experiments.errors import ExperimentError
from experiments.results.connections import connect_read_only, connect_writable, damaged_pages, pending_logs
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
CREATE TABLE IF NOT EXISTS leases (
    home TEXT NOT NULL, away TEXT NOT NULL, seed INTEGER NOT NULL, owner TEXT NOT NULL, expires_at REAL NOT NULL,
    PRIMARY KEY (home, away, seed)
);
"""

COLUMNS = ("home", "away", "seed", "config_hash", "code_version", "home_goals", "away_goals", "cycles",
           "wall_time", "home_stats", "away_stats", "error", "traceback", "forfeit")


class ResultsError(ExperimentError):
    """A results file cannot be used: unreadable, unwritable, not a results file, or made by a
    different configuration or command. The message names the file and says what to do."""


class StorageError(ExperimentError):
    """Writing to a results file failed (disk full, I/O error, permission lost): every match
    stored before is kept. The message names the file and what was kept."""


class ResultStore:
    """An open results file. Use :meth:`create` to run into it and :meth:`open` to read it."""

    def __init__(self, path: Path, connection: sqlite3.Connection, writable: bool = False,
                 cleanup: Callable[[], None] | None = None, config_hash: str | None = None) -> None:
        self.path = path
        self._db = connection
        self._writable = writable
        self._cleanup = cleanup
        self.config_hash = config_hash
        """The configuration of the file's rows: only rows of it are read, counted or deleted."""
        self.lease_owner: str | None = None
        """The run whose lease on a match :meth:`add` releases (see :mod:`experiments.results.leases`)."""

    # -- opening ----------------------------------------------------------------------------
    @classmethod
    def open(cls, path: str | os.PathLike) -> ResultStore:
        """Open an existing results file read-only (it is never changed, even when it is not a
        results file); ResultsError naming the file if it is missing or not a results file."""
        from formations.input_files import check_input  # the project's one rule for files it reads

        path = Path(path)
        try:
            check_input(path)                  # a regular file: a FIFO or a device is never opened
        except FileNotFoundError:
            raise ResultsError(f"{path}: no such results file") from None
        except OSError as exc:
            if exc.errno == errno.EISDIR:
                raise ResultsError(f"{path}: is a directory, not a results file") from None
            raise ResultsError(f"{path}: cannot be read ({exc.strerror or exc})") from None
        try:
            connection, cleanup = connect_read_only(path)
        except sqlite3.OperationalError as exc:                  # e.g. no permission to read it
            raise ResultsError(f"{path}: cannot be read ({exc})") from None
        except (sqlite3.DatabaseError, UnicodeDecodeError) as exc:  # SQLite decodes damaged text too
            raise ResultsError(f"{path}: not a soccer-sim results file ({exc})") from None
        store = cls(path, connection, cleanup=cleanup)
        try:
            meta = store.meta()
        except (sqlite3.DatabaseError, UnicodeDecodeError) as exc:
            store.close()
            raise ResultsError(f"{path}: not a soccer-sim results file ({exc})") from None
        if "kind" not in meta:
            contents = _contents(path, connection)
            store.close()
            raise ResultsError(f"{path}: not a soccer-sim results file ({contents})")
        store.config_hash = meta.get("config_hash")
        return store

    @classmethod
    def create(cls, path: str | os.PathLike, kind: str, config_hash: str, config: str,
               params: dict[str, object]) -> ResultStore:
        """Open ``path`` to store matches of command ``kind`` played with configuration
        ``config_hash`` (``config``: its description), creating the file if needed. An existing
        file must hold the same kind and configuration (checked read-only, before anything is
        written: another program's database is refused untouched); ``params`` (the command's
        parameters) replace the stored ones, so ``results show`` repeats the latest run's tables.
        StorageError when the file cannot be written (disk full)."""
        from experiments.results.files import file_problem

        problem = file_problem(path, database=True)     # the rule for every file a command writes
        path = Path(path)
        if problem and path.is_dir():
            raise ResultsError(f"{path}: is a directory; give a file name for the results (e.g. {path / 'results.sqlite'})")
        if problem:
            raise ResultsError(f"{path}: {problem}")
        if path.exists() and path.stat().st_size > 0:
            _check_existing(path, kind, config_hash, config)
        try:
            store = cls(path, connect_writable(path), writable=True, config_hash=config_hash)
        except sqlite3.DatabaseError as exc:
            raise _write_failure(path, exc, "no match was played") from None
        try:
            # One write transaction checks the settings and writes them: of two runs creating the
            # same new file at once, the second sees the first's settings (and may be refused).
            with store.immediate() as db:
                refusal = _refusal(path, _meta(db), _tables(db), kind, config_hash, config)
                if refusal is None:
                    for statement in _SCHEMA.split(";"):
                        if statement.strip():
                            db.execute(statement)
                    for key, value in (("schema", SCHEMA_VERSION), ("kind", kind), ("config_hash", config_hash),
                                       ("config", config), ("params", json.dumps(params, sort_keys=True))):
                        db.execute("INSERT OR REPLACE INTO meta VALUES (?, ?)", (key, value))
        except sqlite3.DatabaseError as exc:
            store.close()
            raise _write_failure(path, exc, "no match was played") from None
        if refusal is not None:
            store.close()
            raise ResultsError(refusal)
        return store

    @contextlib.contextmanager
    def immediate(self) -> Iterator[sqlite3.Connection]:
        """A write transaction taken at once (``BEGIN IMMEDIATE``): what is read in it cannot be
        changed by another process before it commits (rolled back on an exception)."""
        self._db.execute("BEGIN IMMEDIATE")
        try:
            yield self._db
        except BaseException:
            self._db.rollback()
            raise
        self._db.commit()

    # -- reading ----------------------------------------------------------------------------
    def meta(self) -> dict[str, str]:
        return _meta(self._db)

    @property
    def kind(self) -> str:
        return self.meta()["kind"]

    @property
    def engine(self) -> str:
        """Where the file's matches were played: ``simulator`` or another engine's name (the
        ``engine`` of its configuration's description)."""
        return _engine(self.meta().get("config", ""))

    @property
    def params(self) -> dict[str, object]:
        """The parameters of the command that made the file; ResultsError if they are damaged."""
        try:
            params = json.loads(self.meta().get("params", "{}"))
        except ValueError as exc:
            raise ResultsError(f"{self.path}: damaged results file, its stored parameters are not JSON ({exc})") from None
        if not isinstance(params, dict):
            raise ResultsError(f"{self.path}: damaged results file, its stored parameters are not a JSON object")
        return params

    def keys(self) -> set[tuple[str, str, int]]:
        """(home, away, seed) of every stored match of the file's configuration."""
        with self._reading():
            return {tuple(row) for row in self._db.execute(f"SELECT home, away, seed FROM matches{self._own()}",
                                                           self._own_args())}

    def records(self, keys: Iterable[tuple[str, str, int]] | None = None) -> list[MatchRecord]:
        """Stored matches of the file's configuration (all, or those of ``keys``), sorted by key:
        the same list whatever order the matches finished in."""
        with self._reading():
            cursor = self._db.execute(f"SELECT {', '.join(COLUMNS)} FROM matches{self._own()} "
                                      "ORDER BY home, away, seed", self._own_args())
            records = [MatchRecord.from_row(dict(zip(COLUMNS, row))) for row in cursor]
        if keys is not None:
            wanted = set(keys)
            records = [r for r in records if r.key in wanted]
        return records

    def count(self) -> int:
        with self._reading():
            return int(self._db.execute(f"SELECT COUNT(*) FROM matches{self._own()}", self._own_args()).fetchone()[0])

    def code_versions(self) -> set[str]:
        """The code versions that played the stored matches of the file's configuration."""
        with self._reading():
            return {row[0] for row in self._db.execute(f"SELECT DISTINCT code_version FROM matches{self._own()}",
                                                       self._own_args())}

    def _own(self, conjunction: str = " WHERE") -> str:
        """The SQL condition keeping rows of the file's configuration (none for a file without one)."""
        return f"{conjunction} config_hash = ?" if self.config_hash is not None else ""

    def _own_args(self) -> tuple[str, ...]:
        return (self.config_hash,) if self.config_hash is not None else ()

    @contextlib.contextmanager
    def _reading(self) -> Iterator[None]:
        """Reads of stored rows: a damaged file (SQLite finds a malformed page only when it
        reads it; a damaged row's JSON or text fails to decode) becomes a ResultsError naming
        the file."""
        try:
            yield
        except (sqlite3.DatabaseError, ValueError, TypeError, KeyError) as exc:  # damaged pages or row text
            raise ResultsError(f"{self.path}: damaged results file, its rows cannot be read "
                               f"({type(exc).__name__}: {exc})") from None

    # -- writing ----------------------------------------------------------------------------
    def add(self, record: MatchRecord) -> None:
        """Store one finished match in its own transaction (a key already stored is kept), which
        also releases this run's lease on it (:attr:`lease_owner`); then copy it from the
        write-ahead log into the file itself. ValueError for a record of another configuration."""
        if self.config_hash is not None and record.config_hash != self.config_hash:
            raise ValueError(f"{self.path}: a match of configuration {record.config_hash} cannot be stored in a "
                             f"file of configuration {self.config_hash}")
        row = record.to_row()
        with self._db:
            self._db.execute(f"INSERT OR IGNORE INTO matches ({', '.join(COLUMNS)}) VALUES "
                             f"({', '.join('?' for _ in COLUMNS)})", [row[c] for c in COLUMNS])
            if self.lease_owner is not None:
                self._db.execute("DELETE FROM leases WHERE home = ? AND away = ? AND seed = ? AND owner = ?",
                                 (*record.key, self.lease_owner))
        self._checkpoint("PASSIVE")

    def forget_errors(self, keys: Iterable[tuple[str, str, int]], unattributed_only: bool = False) -> int:
        """Delete the failed matches among ``keys`` so they are played again (only those no team
        is blamed for, e.g. a worker that died, with ``unattributed_only``); their number."""
        extra = f" AND forfeit = {FORFEIT_NONE}" if unattributed_only else ""
        with self._db:
            return sum(self._db.execute("DELETE FROM matches WHERE home = ? AND away = ? AND seed = ? "
                                        f"AND error IS NOT NULL{extra}{self._own(' AND')}",
                                        (*key, *self._own_args())).rowcount for key in keys)

    def _checkpoint(self, mode: str) -> None:
        """Copy committed rows from the ``-wal`` file into the database file (``TRUNCATE`` also
        empties the log). A failure is harmless: the rows stay committed in the log, which the
        next writer merges and readers read, so it is not an error of the run."""
        try:
            self._db.execute(f"PRAGMA wal_checkpoint({mode})").fetchall()
        except sqlite3.Error:
            pass

    def close(self) -> None:
        """Close the file; a writer first checkpoints, so the ``.sqlite`` file is complete on its own."""
        try:
            if self._writable:
                self._checkpoint("TRUNCATE")
        finally:
            self._db.close()
            if self._cleanup is not None:
                self._cleanup()
                self._cleanup = None

    def __enter__(self) -> ResultStore:
        return self

    def __exit__(self, *exc) -> None:
        self.close()


def _check_existing(path: Path, kind: str, config_hash: str, config: str) -> None:
    """Refuse (ResultsError) to run into ``path`` unless it is an empty database or holds the
    results of the same command and configuration; read-only, so a refused file is left as it
    was. A file another run is creating at this moment can read as damaged (its first pages
    are being written): while the file changes, or a writer's log is beside it, it is read
    again, for up to :data:`CREATION_WAIT` seconds."""
    deadline = time.monotonic() + CREATION_WAIT
    while True:
        before = _file_state(path)
        try:
            refusal = _existing_refusal(path, kind, config_hash, config)
            break
        except sqlite3.DatabaseError as exc:
            being_written = _file_state(path) != before or bool(pending_logs(path))
            if not being_written or time.monotonic() > deadline:
                raise ResultsError(_UNUSABLE.format(path=path, why=exc)) from None
            time.sleep(0.02)
    if refusal is not None:
        raise ResultsError(refusal)


CREATION_WAIT = 2.0
"""Seconds :func:`_check_existing` reads again a file that another run is creating."""


def _file_state(path: Path) -> tuple[int, int]:
    """(size, modification time in ns) of ``path``: whether someone is writing it."""
    stat = path.stat()
    return stat.st_size, stat.st_mtime_ns


def _existing_refusal(path: Path, kind: str, config_hash: str, config: str) -> str | None:
    """:func:`_refusal` for the database at ``path``, read read-only; sqlite3.DatabaseError
    when it cannot be read."""
    connection, cleanup = connect_read_only(path)
    store = ResultStore(path, connection, cleanup=cleanup)
    try:
        meta, tables = store.meta(), _tables(connection)
        refusal = _refusal(path, meta, tables, kind, config_hash, config, lambda: _contents(path, connection))
        if refusal is None and tables and (damage := damaged_pages(connection)):
            # refused read-only, before the writer touches it (its journal mode included)
            refusal = f"{path}: damaged results file ({damage}); it is left untouched: use another results file"
        return refusal
    finally:
        store.close()


_UNUSABLE = "{path}: cannot be used as a results file ({why}); delete it or use another results file"


def _refusal(path: Path, meta: dict[str, str], tables: list[str], kind: str, config_hash: str, config: str,
             contents: Callable[[], str] | None = None) -> str | None:
    """Why a database with ``meta`` and ``tables`` cannot take the results of command ``kind``
    with configuration ``config_hash`` (described by ``config``), or None when it can: it is
    empty or holds results of the same command and configuration."""
    if not tables:
        return None                                           # an empty database: ours to fill
    if "kind" not in meta:
        what = contents() if contents is not None else f"an SQLite database with tables {', '.join(tables)}"
        return f"{path}: not a soccer-sim results file ({what}); it is left untouched: use another results file"
    if "matches" not in tables:                                # a results file whose matches are gone
        return f"{path}: damaged results file (its matches table is missing); it is left untouched: " \
               "use another results file"
    fresh = f"to start fresh, delete {path} or use another results file"
    if meta["kind"] != kind:
        return f"{path} holds the results of '{meta['kind']}', not '{kind}'; {fresh}"
    if meta.get("config_hash") not in (None, config_hash):
        stored_engine, this_engine = _engine(meta.get("config", "")), _engine(config)
        if stored_engine != this_engine:
            return mixed_engines(path, stored_engine, this_engine)
        stored, this = _difference(meta.get("config", ""), config)
        return (f"{path} holds results of a different match configuration (hash {meta['config_hash']}{stored}; "
                f"this run: hash {config_hash}{this}; e.g. another number of cycles); results of different "
                f"configurations are never mixed; {fresh}")
    return None


def _engine(description: str) -> str:
    """The engine a configuration description names (its ``engine``; ``simulator`` when it
    names none, as every description of the simulator's matches: see
    :func:`experiments.runner.spec.config_description`)."""
    try:
        described = json.loads(description)
    except (ValueError, TypeError):
        return "simulator"
    engine = described.get("engine") if isinstance(described, dict) else None
    return "simulator" if engine is None else str(engine)


def mixed_engines(path: Path, stored: str, this: str) -> str:
    """Why a results file of engine ``stored`` refuses a run in engine ``this``."""
    def named(engine: str) -> str:
        return "the simulator" if engine == "simulator" else engine

    return (f"{path} holds matches played in {named(stored)}, and this run plays in {named(this)}; one results "
            f"file never mixes engines: use another results file, or resume it with --engine {stored}")


def stored_engine(path: str | os.PathLike) -> str | None:
    """The engine of the matches in results file ``path`` (read-only), or None when there is
    no results file there (or one that cannot be read: :meth:`ResultStore.create` says why)."""
    path = Path(path)
    if not path.is_file() or path.stat().st_size == 0:
        return None
    try:
        with ResultStore.open(path) as store:
            return store.engine
    except (ResultsError, sqlite3.Error):
        return None


def _difference(stored: str, this: str, limit: int = 4) -> tuple[str, str]:
    """The parameters in which two configuration descriptions (JSON objects) differ, as
    ``": name=value, ..."`` for each (empty strings when they cannot be compared)."""
    try:
        old, new = _flat(json.loads(stored)), _flat(json.loads(this))
    except (ValueError, TypeError, AttributeError):
        return "", ""
    names = sorted(name for name in old.keys() | new.keys() if old.get(name) != new.get(name))[:limit]
    if not names:
        return "", ""
    return tuple(": " + ", ".join(f"{name}={side.get(name, '(none)')}" for name in names)
                 for side in (old, new))


def _flat(value: dict, prefix: str = "") -> dict[str, object]:
    """A nested JSON object as {"a.b": value}."""
    flat: dict[str, object] = {}
    for name, item in value.items():
        if isinstance(item, dict):
            flat.update(_flat(item, f"{prefix}{name}."))
        else:
            flat[f"{prefix}{name}"] = item
    return flat


def _meta(db: sqlite3.Connection) -> dict[str, str]:
    """The meta table of a results file ({} when there is none)."""
    if "meta" not in _tables(db):
        return {}
    return dict(db.execute("SELECT key, value FROM meta").fetchall())


def _tables(db: sqlite3.Connection) -> list[str]:
    return [row[0] for row in db.execute("SELECT name FROM sqlite_master WHERE type = 'table' ORDER BY name")]


def _contents(path: Path, connection: sqlite3.Connection) -> str:
    """What a file that is not a results file holds (read through ``connection``), for messages."""
    if path.stat().st_size == 0:
        return "an empty file"
    tables = _tables(connection)
    return f"an SQLite database with tables {', '.join(tables)}" if tables else "an empty SQLite database"


def _write_failure(path: Path, exc: sqlite3.DatabaseError, kept: str) -> Exception:
    """StorageError for a failed write (disk full, I/O error, read-only), else ResultsError."""
    if is_storage_failure(exc):
        return StorageError(f"{path}: cannot write ({exc}); {kept}")
    return ResultsError(f"{path}: cannot be used as a results file ({exc}); delete it or use another results file")


def is_storage_failure(exc: BaseException) -> bool:
    """True for an error of the disk or the file system rather than of the file's contents."""
    if isinstance(exc, OSError):
        return True
    name = getattr(exc, "sqlite_errorname", "") or ""
    text = str(exc).lower()
    return (name.startswith(("SQLITE_FULL", "SQLITE_IOERR", "SQLITE_READONLY", "SQLITE_CANTOPEN", "SQLITE_PERM"))
            or any(words in text for words in ("disk is full", "disk i/o error", "readonly database",
                                               "unable to open")))
