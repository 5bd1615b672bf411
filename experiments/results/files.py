"""Writing output files safely: destinations checked before any work, never onto an input, and
written whole or not at all.

Commands that write (``results export``, the tables of a run, ``replay --out``) check where
they will write before they read or play anything, refuse a destination that is one of their
inputs (or its SQLite ``-wal``/``-shm``/``-journal`` companion), and write each file to a
temporary file in the same directory that is renamed over the target only once complete: a
full disk or a lost permission leaves the previous file (or none), never a 0-byte or partial one.
"""

from __future__ import annotations

import contextlib
import errno
import os
import tempfile
from collections.abc import Iterable, Iterator
from pathlib import Path

SQLITE_COMPANIONS = ("", "-wal", "-shm", "-journal")
"""Suffixes of the files SQLite keeps for a database ``X``: ``X`` itself, then ``X-wal`` ..."""

SQLITE_HEADER = b"SQLite format 3\x00"


def written_input(target: str | os.PathLike, inputs: Iterable[str | os.PathLike]) -> str | None:
    """The input that writing ``target`` would write onto (the same file by path or by inode,
    through symbolic or hard links, or the input's SQLite ``-wal``/``-shm``/``-journal``
    file), or None."""
    target = Path(target)
    resolved = target.resolve()
    for source in inputs:
        for suffix in SQLITE_COMPANIONS:
            companion = Path(f"{source}{suffix}")
            if companion.resolve() == resolved:
                return str(companion)
            with contextlib.suppress(OSError):
                if target.exists() and companion.exists() and os.path.samefile(target, companion):
                    return str(companion)
    return None


def make_output_directory(directory: str | os.PathLike) -> str | None:
    """Create ``directory`` (and its parents) for a command's output files; why it cannot be
    made (one line), or None."""
    try:
        Path(directory).mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        return f"cannot make the directory ({exc.strerror or exc})"
    return None


def directory_problem(directory: str | os.PathLike) -> str | None:
    """Why files cannot be written into ``directory`` (created later if missing), or None.

    A missing directory is fine when its nearest existing ancestor is a directory we can write
    in. Writability is probed by creating (and removing) a temporary file: the check meets
    whatever a write would (permissions, a read-only mount, no free inodes)."""
    directory = Path(directory)
    existing = directory
    while not existing.exists():
        if existing.parent == existing:
            break
        existing = existing.parent
    if not existing.is_dir():
        return f"{existing} is a file, not a directory" if existing != directory else "is a file, not a directory"
    try:
        with tempfile.TemporaryFile(dir=existing):
            pass
    except OSError as exc:
        where = "" if existing == directory else f" (in {existing})"
        return f"cannot write there{where} ({exc.strerror or exc})"
    return None


def file_problem(path: str | os.PathLike, inputs: Iterable[str | os.PathLike] = ()) -> str | None:
    """Why the output file ``path`` cannot be written (before any work is done), or None: it is
    one of ``inputs``, a directory, an SQLite database (a results file, most likely), read-only, in a
    missing or unwritable directory."""
    path = Path(path)
    source = written_input(path, inputs)
    if source is not None:
        return f"would overwrite {source}, which this command reads; give another output file"
    if path.is_dir():
        return "is a directory; give a file name"
    if is_sqlite(path):
        return "is an SQLite database, never overwritten by an output; give another file name"
    if path.exists() and not os.access(path, os.W_OK):
        return "not writable (permission denied)"
    parent = path.parent
    if not parent.is_dir():
        return f"directory {parent} does not exist"
    problem = directory_problem(parent)
    return f"directory {parent}: {problem}" if problem else None


@contextlib.contextmanager
def atomic_output(path: str | os.PathLike) -> Iterator[Path]:
    """Yield a temporary path (same directory and suffix as ``path``) to write; on success it
    replaces ``path`` in one rename, on any failure it is removed and ``path`` is untouched.

    OSErrors come out naming ``path``. An existing SQLite database at ``path`` is never replaced
    (an output name that collides with a results file is a mistake, not a wish)."""
    path = Path(path)
    if path.is_symlink():
        path = path.resolve()               # write where the link points, as open() would
    if is_sqlite(path):
        raise FileExistsError(errno.EEXIST, "is an SQLite database, not overwritten", str(path))
    try:
        handle, name = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=path.suffix)
        os.close(handle)
    except OSError as exc:
        raise OSError(exc.errno, exc.strerror, str(path)) from None
    temporary = Path(name)
    try:
        os.chmod(temporary, _mode_for(path))    # mkstemp makes 0600; give the file the usual mode
        yield temporary
        os.replace(temporary, path)
    except OSError as exc:
        temporary.unlink(missing_ok=True)
        raise OSError(exc.errno, exc.strerror or str(exc), str(path)) from None
    except BaseException:
        temporary.unlink(missing_ok=True)
        raise


def _mode_for(path: Path) -> int:
    """The mode of the file being replaced, else what ``open`` would give (0666 less the umask)."""
    try:
        return path.stat().st_mode & 0o7777
    except OSError:
        mask = os.umask(0)
        os.umask(mask)
        return 0o666 & ~mask


def is_sqlite(path: str | os.PathLike) -> bool:
    """True when ``path`` is an SQLite database file (by its header)."""
    try:
        with open(path, "rb") as handle:
            return handle.read(len(SQLITE_HEADER)) == SQLITE_HEADER
    except OSError:
        return False


def describe(exc: OSError) -> str:
    """``FILE (reason)`` of an OSError, for one-line messages."""
    reason = exc.strerror or str(exc)
    return f"{exc.filename} ({reason})" if exc.filename else reason
