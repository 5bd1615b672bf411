"""The one rule for every file a command writes: destinations checked before any work, never
onto an input or a special file, and written whole or not at all.

Every command that writes (``results export``, the tables of a run, ``play --record``/``--rcg``,
``replay --out``/``--png``, ``formation show``/``import``, the studies' and benchmarks' ``--out``)
checks where it will write with :func:`file_problem` (a file) or :func:`directory_problem` (a
directory of outputs) before it reads or plays anything, and refuses a destination that

* has an empty name (``--out ''`` would otherwise become ``.`` or a hidden ``.png``);
* is one of its inputs, by identity rather than by name (the same file through a symbolic or
  hard link, an input's SQLite ``-wal``/``-shm``/``-journal`` companion, or a file inside an
  input directory);
* exists and is not a regular file (a directory, FIFO, socket or device: such a file is never
  replaced, and never opened, so a FIFO cannot block the check);
* is an SQLite database (a results file, most likely), unless the command stores results in it;
* cannot be written (the real reason: "Read-only file system", "Permission denied"), or lies in
  a missing or unwritable directory.

Each file is then written by :func:`atomic_output`: into a temporary file in the same directory,
renamed over the target only once complete and only if the target is still a regular file or
absent. A full disk or a lost permission leaves the previous file (or none), never a 0-byte or
partial one. ``-`` (or a path that is this process's standard output, e.g. ``/dev/stdout``)
means standard output where the option's help says so (``results export --csv -``), and is
refused elsewhere (:func:`is_standard_output`).

The rule for the files a command reads (regular files only, bounded sizes) is
:mod:`formations.input_files`.
"""

from __future__ import annotations

import contextlib
import errno
import os
import stat
import sys
import tempfile
from collections.abc import Callable, Iterable, Iterator
from pathlib import Path
from typing import TextIO

SQLITE_COMPANIONS = ("", "-wal", "-shm", "-journal")
"""Suffixes of the files SQLite keeps for a database ``X``: ``X`` itself, then ``X-wal`` ..."""

SQLITE_HEADER = b"SQLite format 3\x00"

STANDARD_OUTPUT = "-"
"""The name that means standard output, for the options that can write there."""


def is_standard_output(path: str | os.PathLike) -> bool:
    """True for ``-`` and for a path that is this process's standard output itself (the same
    device and inode: ``/dev/stdout``, ``/proc/self/fd/1``, or the file stdout is redirected to)."""
    if os.fspath(path) == STANDARD_OUTPUT:
        return True
    try:
        target, ours = os.stat(path), os.fstat(1)
    except (OSError, ValueError):
        return False
    return (target.st_dev, target.st_ino) == (ours.st_dev, ours.st_ino)


def written_input(target: str | os.PathLike, inputs: Iterable[str | os.PathLike]) -> str | None:
    """The input that writing ``target`` would write onto (the same file by path or by inode,
    through symbolic or hard links, or the input's SQLite ``-wal``/``-shm``/``-journal``
    file), or None. An input directory counts too: a target inside it would change what the
    command reads."""
    target = Path(target)
    resolved = target.resolve()
    for source in inputs:
        if Path(source).is_dir():
            if _inside(target, Path(source)):
                return str(source)
            continue
        for suffix in SQLITE_COMPANIONS:
            companion = Path(f"{source}{suffix}")
            if companion.resolve() == resolved:
                return str(companion)
            with contextlib.suppress(OSError):
                if target.exists() and companion.exists() and os.path.samefile(target, companion):
                    return str(companion)
    return None


def _inside(target: Path, directory: Path) -> bool:
    """Whether ``target`` (existing or not) lies inside ``directory``, by identity: one of its
    existing ancestors (or itself) is the directory, through whatever links."""
    with contextlib.suppress(OSError):
        if target.resolve().is_relative_to(directory.resolve()):
            return True
        for ancestor in (target, *target.parents):
            if ancestor.exists():
                return os.path.samefile(ancestor, directory) or any(
                    os.path.samefile(above, directory) for above in ancestor.resolve().parents)
    return False


def special_file_problem(path: str | os.PathLike) -> str | None:
    """Why an existing ``path`` (links followed) may not be replaced by an output: it is not a
    regular file (a directory, FIFO, socket or device); None when it is one or does not exist.
    The file is only looked at (``stat``), never opened."""
    from formations.input_files import kind_of

    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        return None
    except OSError as exc:
        return f"cannot be reached ({exc.strerror or exc})"
    if stat.S_ISDIR(mode):
        return "is a directory; give a file name"
    if not stat.S_ISREG(mode):
        return f"is not a regular file ({kind_of(mode)}); it is never replaced by an output"
    return None


def write_problem(path: str | os.PathLike) -> str | None:
    """Why the existing regular file ``path`` cannot be written, in the system's words ("Read-only
    file system", "Permission denied"), or None. It is opened for writing without truncation
    and closed at once: nothing in it changes."""
    try:
        os.close(os.open(path, os.O_WRONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0)))
    except FileNotFoundError:
        return None
    except OSError as exc:
        return f"cannot be written ({exc.strerror or exc})"
    return None


def make_output_directory(directory: str | os.PathLike) -> str | None:
    """Create ``directory`` (and its parents) for a command's output files; why it cannot be
    made (one line), or None."""
    problem = name_problem(directory)
    if problem:
        return problem
    try:
        Path(directory).mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        return f"cannot make the directory ({exc.strerror or exc})"
    return None


def name_problem(path: str | os.PathLike) -> str | None:
    """Why ``path`` is no file name at all (empty, or ``.``-like), or None."""
    text = os.fspath(path)
    if not text.strip():
        return "an empty file name; give a file name"
    return None


def output_path(text: str) -> Path:
    """An argparse ``type`` for an output file or directory option: the path, refusing an empty
    name (``Path('')`` would quietly be ``.``)."""
    problem = name_problem(text)
    if problem:
        import argparse

        raise argparse.ArgumentTypeError(problem)
    return Path(text)


def is_directory_name(path: str | os.PathLike) -> bool:
    """True when ``path`` names an existing directory (an empty name, which ``Path`` reads as
    ``.``, names none)."""
    return name_problem(path) is None and os.path.isdir(path)


def directory_problem(directory: str | os.PathLike, used: Iterable[str | os.PathLike] = ()) -> str | None:
    """Why files cannot be written into ``directory`` (created later if missing), or None.

    ``used``: files the command reads or writes besides (its results file): the directory may
    not be one of them. A missing directory is fine when its nearest existing ancestor is a
    directory we can write in. Writability is probed by creating (and removing) a temporary
    file: the check meets whatever a write would (permissions, a read-only mount, no free
    inodes)."""
    problem = name_problem(directory)
    if problem:
        return problem
    directory = Path(directory)
    source = written_input(directory, [u for u in used if not Path(u).is_dir()])
    if source is not None:
        return f"is {source}, a file this command uses; give another directory"
    existing = directory
    try:
        while not existing.exists():
            if existing.parent == existing:
                break
            existing = existing.parent
        is_directory = existing.is_dir()
    except OSError as exc:
        return f"cannot be reached ({exc.strerror or exc})"
    if not is_directory:
        return f"{existing} is a file, not a directory" if existing != directory else "is a file, not a directory"
    try:
        with tempfile.TemporaryFile(dir=existing):
            pass
    except OSError as exc:
        where = "" if existing == directory else f" (in {existing})"
        return f"cannot write there{where} ({exc.strerror or exc})"
    if existing == directory:
        special = _special_entry(directory)
        if special is not None:
            return special
    return None


def _special_entry(directory: Path) -> str | None:
    """Why an output directory that holds something other than regular files and directories
    (a FIFO, a device, a socket) is refused before any work (the command writes its files into
    it, and never over such an entry), or None."""
    from formations.input_files import kind_of

    try:
        with os.scandir(directory) as entries:
            for entry in entries:
                try:
                    mode = entry.stat().st_mode
                except FileNotFoundError:  # a link to nothing: writing through it makes a file
                    continue
                if not (stat.S_ISREG(mode) or stat.S_ISDIR(mode)):
                    return f"holds {entry.name}, which is not a regular file ({kind_of(mode)}); " \
                           "the command writes its files here and never replaces such a file"
    except OSError as exc:
        return f"cannot be read ({exc.strerror or exc})"
    return None


def file_problem(path: str | os.PathLike, inputs: Iterable[str | os.PathLike] = (), *,
                 database: bool = False, standard_output: bool = False) -> str | None:
    """Why the output file ``path`` cannot be written (before any work is done), or None: the
    rule of the module docstring. ``database``: ``path`` is a results file the command stores
    into (an SQLite database there is expected). ``standard_output``: the option takes ``-``
    (or ``/dev/stdout``) for standard output; without it, standard output is refused."""
    problem = name_problem(path)
    if problem:
        return problem
    if is_standard_output(path):
        return None if standard_output else "standard output cannot take this output; give a file name"
    path = Path(path)
    source = written_input(path, inputs)
    if source is not None:
        verb = "write into" if Path(source).is_dir() else "overwrite"
        return f"would {verb} {source}, which this command reads; give another output file"
    problem = special_file_problem(path) or write_problem(path)
    if problem:
        return problem
    if not database and is_sqlite(path):
        return "is an SQLite database, never overwritten by an output; give another file name"
    parent = path.parent
    try:
        if not parent.is_dir():
            return f"directory {parent} does not exist"
    except OSError as exc:
        return f"directory {parent} cannot be reached ({exc.strerror or exc})"
    problem = directory_problem(parent)
    return f"directory {parent}: {problem}" if problem else None


def not_replaceable(path: Path) -> OSError | None:
    """The error for a target that exists and is not a regular file (never renamed over)."""
    try:
        mode = os.stat(path).st_mode
    except FileNotFoundError:
        return None
    except OSError as exc:
        return OSError(exc.errno, exc.strerror, str(path))
    if stat.S_ISREG(mode):
        return None
    from formations.input_files import kind_of

    code = errno.EISDIR if stat.S_ISDIR(mode) else errno.EEXIST
    return OSError(code, f"not a regular file ({kind_of(mode)}), never replaced", str(path))


@contextlib.contextmanager
def atomic_output(path: str | os.PathLike) -> Iterator[Path]:
    """Yield a temporary path (same directory and suffix as ``path``) to write; on success it
    replaces ``path`` in one rename, on any failure it is removed and ``path`` is untouched.

    OSErrors come out naming ``path``. Only a regular file or nothing is replaced: a directory,
    FIFO, socket or device at ``path`` (checked before and again just before the rename) is an
    OSError. An existing SQLite database at ``path`` is never replaced either (an output name
    that collides with a results file is a mistake, not a wish)."""
    if name_problem(path):
        raise OSError(errno.ENOENT, "an empty file name", os.fspath(path))
    path = Path(path)
    if path.is_symlink():
        path = path.resolve()               # write where the link points, as open() would
    refusal = not_replaceable(path)
    if refusal is not None:
        raise refusal
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
        refusal = not_replaceable(path)      # something else may have appeared there meanwhile
        if refusal is not None:
            raise refusal
        os.replace(temporary, path)
    except OSError as exc:
        temporary.unlink(missing_ok=True)
        raise OSError(exc.errno, exc.strerror or str(exc), str(path)) from None
    except BaseException:
        temporary.unlink(missing_ok=True)
        raise


def write_file(path: str | os.PathLike, write: Callable[[Path], object]) -> Path:
    """``write(temporary)`` under :func:`atomic_output`: ``path`` written whole or not at all
    (a figure's ``savefig``, a CSV writer); returns ``path``."""
    with atomic_output(path) as temporary:
        write(temporary)
    return Path(path)


@contextlib.contextmanager
def text_output(path: str | os.PathLike, newline: str | None = None) -> Iterator[TextIO]:
    """A text stream for the output ``path``: standard output itself for ``-`` or a path that
    is standard output (:func:`is_standard_output`; flushed at the end, so a full disk or a
    closed pipe shows here), else a file written through :func:`atomic_output`."""
    if is_standard_output(path):
        yield sys.stdout
        sys.stdout.flush()
        return
    with atomic_output(path) as temporary, open(temporary, "w", newline=newline) as stream:
        yield stream


WRITE_FAILURES = frozenset({errno.ENOSPC, errno.EDQUOT, errno.EIO, errno.EFBIG, errno.EROFS})
"""errno values of a write that started and failed for want of room or a working disk: the
run failed (exit status 1), whichever command it was."""


def write_failure(exc: BaseException) -> str | None:
    """One line for an OSError of a failed write (a full disk, an I/O error), naming the file
    (or standard output, for an error without a file name); None for any other exception."""
    if not isinstance(exc, OSError) or exc.errno not in WRITE_FAILURES:
        return None
    where = exc.filename if exc.filename is not None else "standard output"
    return f"cannot write {where} ({exc.strerror or exc})"


def _mode_for(path: Path) -> int:
    """The mode of the file being replaced, else what ``open`` would give (0666 less the umask)."""
    try:
        return path.stat().st_mode & 0o7777
    except OSError:
        mask = os.umask(0)
        os.umask(mask)
        return 0o666 & ~mask


def is_sqlite(path: str | os.PathLike) -> bool:
    """True when ``path`` is a regular file holding an SQLite database (by its header); a
    special file is never opened (a FIFO would block)."""
    from formations.input_files import open_input

    try:
        with open_input(path) as handle:
            return handle.read(len(SQLITE_HEADER)) == SQLITE_HEADER
    except OSError:
        return False


def describe(exc: OSError) -> str:
    """``FILE (reason)`` of an OSError, for one-line messages (``standard output (reason)`` for
    an error without a file: a write to standard output is the one that has none)."""
    reason = exc.strerror or str(exc)
    return f"{exc.filename if exc.filename else 'standard output'} ({reason})"
