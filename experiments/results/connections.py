"""Opening a results file's SQLite database: for writing (WAL, waiting for other writers) and
for reading without changing anything on disk (see :func:`connect_read_only`).
"""

from __future__ import annotations

import shutil
import sqlite3
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

BUSY_SECONDS = 30.0
"""How long a writer waits for another process's write transaction on the same file."""


def connect_writable(path: Path) -> sqlite3.Connection:
    """A connection that writes to ``path`` in WAL mode (every commit atomic, a reader beside a
    writer sees whole rows), waiting up to BUSY_SECONDS for another writer."""
    db = sqlite3.connect(str(path), timeout=BUSY_SECONDS)
    deadline = time.monotonic() + BUSY_SECONDS
    try:
        while True:
            try:
                db.execute("PRAGMA journal_mode = WAL")   # each commit is atomic and survives kill -9
                break
            except sqlite3.OperationalError as exc:
                # Switching a new file to WAL while another process does the same can report
                # "locked" at once, without SQLite's busy wait: wait here instead.
                if "locked" not in str(exc) or time.monotonic() > deadline:
                    raise
                time.sleep(0.01)
        db.execute("PRAGMA synchronous = NORMAL")
    except sqlite3.DatabaseError:
        db.close()
        raise
    return db


def damaged_pages(db: sqlite3.Connection) -> str | None:
    """SQLite's first complaint about the database's pages (``PRAGMA quick_check``, which reads
    every page and changes nothing), or None when they are sound. A damaged page otherwise shows
    only when a query reaches it, after a writer may already have changed the file."""
    verdict = db.execute("PRAGMA quick_check(1)").fetchone()[0]
    return None if verdict == "ok" else str(verdict)


def pending_logs(path: Path) -> list[Path]:
    """The ``-wal`` and ``-journal`` files beside ``path``: a writer at work, or one killed."""
    return [Path(f"{path}{suffix}") for suffix in ("-wal", "-journal") if Path(f"{path}{suffix}").exists()]


def connect_read_only(path: Path) -> tuple[sqlite3.Connection, Callable[[], None] | None]:
    """A read-only connection to ``path`` that changes nothing on disk, and its clean-up.

    Without a ``-wal`` (or ``-journal``) file the database file is complete, and ``immutable``
    reads it as it is: SQLite creates no ``-wal``/``-shm`` files and takes no locks (which
    read-only media could not hold). With one (a run in progress, or killed), plain
    ``mode=ro`` reads the file and its log through the shared ``-shm`` index, as a reader next
    to a writer must (``immutable`` would ignore the log's rows); where that index cannot be
    created (read-only media), the files are read from a private copy instead."""
    pending = pending_logs(path)
    uri = path.resolve().as_uri() + ("?mode=ro" if pending else "?mode=ro&immutable=1")
    db = None
    try:
        db = sqlite3.connect(uri, uri=True, timeout=30.0)
        db.execute("SELECT COUNT(*) FROM sqlite_master").fetchone()      # the file is opened lazily
    except sqlite3.DatabaseError as exc:
        if db is not None:
            db.close()
        if pending and cannot_open(exc):
            return private_copy(path, pending)
        raise
    return db, None


def cannot_open(exc: sqlite3.DatabaseError) -> bool:
    """True when SQLite could not open (or would have to write) the files to read them."""
    name = getattr(exc, "sqlite_errorname", "") or ""
    text = str(exc).lower()
    return name.startswith(("SQLITE_CANTOPEN", "SQLITE_READONLY")) or "unable to open" in text or "readonly" in text


def private_copy(path: Path, companions: list[Path]) -> tuple[sqlite3.Connection, Callable[[], None]]:
    """A connection to a copy of ``path`` and its ``companions`` in a temporary directory (where
    SQLite may merge the log), and the clean-up that removes the copy."""
    directory = tempfile.mkdtemp(prefix="soccer-sim-results-")
    try:
        copy = Path(directory) / path.name
        shutil.copyfile(path, copy)
        for companion in companions:
            shutil.copyfile(companion, Path(f"{copy}{companion.name[len(path.name):]}"))
        db = sqlite3.connect(str(copy))
        db.execute("SELECT COUNT(*) FROM sqlite_master").fetchone()
    except BaseException:
        shutil.rmtree(directory, ignore_errors=True)
        raise
    return db, lambda: shutil.rmtree(directory, ignore_errors=True)
