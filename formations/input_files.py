"""The one rule for every file the project reads: only a regular file (or a directory where a
directory is expected), and no more bytes than its format can hold.

A FIFO would block a reader for ever, ``/dev/zero`` or ``/dev/urandom`` would fill memory, a
terminal would wait for typing: none of them is a file a formation, a scenario, a game log, a
replay or a results file can be in. A file is opened without blocking (``O_NONBLOCK``, so
opening a FIFO returns at once), checked with ``fstat`` on the descriptor itself (no race
between the check and the read) and read only if it is a regular file no larger than the
format's limit. Every refusal is an ``OSError`` with the file's name and a reason worded for
people ("not a regular file (a FIFO)", "larger than the 16 MiB a formation file may hold"), so a
reader's existing ``except OSError`` reports it in one line.

It lives in this package, the lowest of the project's (pure: the standard library only), so
the simulator (scenarios, game logs, replays), the formations and the experiments (results
files) share one definition.
"""

from __future__ import annotations

import errno
import os
import stat
from typing import BinaryIO

MiB = 1 << 20

_KINDS = (
    (stat.S_ISFIFO, "a FIFO"),
    (stat.S_ISCHR, "a character device"),
    (stat.S_ISBLK, "a block device"),
    (stat.S_ISSOCK, "a socket"),
    (stat.S_ISDIR, "a directory"),
)


def kind_of(mode: int) -> str:
    """What a file of ``st_mode`` ``mode`` is, for messages: "a FIFO", "a directory", ..."""
    for test, name in _KINDS:
        if test(mode):
            return name
    return "a regular file" if stat.S_ISREG(mode) else "a special file"


def not_regular(path: str | os.PathLike, mode: int) -> OSError:
    """The error for ``path`` (of ``st_mode`` ``mode``) that is not a regular file: an
    ``OSError`` with errno ``EINVAL`` (``IsADirectoryError`` for a directory)."""
    code = errno.EISDIR if stat.S_ISDIR(mode) else errno.EINVAL
    return OSError(code, f"not a regular file ({kind_of(mode)})", os.fspath(path))


def too_large(path: str | os.PathLike, limit: int, what: str) -> OSError:
    """The error (errno ``EFBIG``) for ``path`` holding more than ``limit`` bytes, the most
    ``what`` may hold."""
    return OSError(errno.EFBIG, f"larger than the {_size(limit)} {what} may hold", os.fspath(path))


def check_input(path: str | os.PathLike, *, limit: int | None = None, what: str = "this file",
                directory: bool = False) -> os.stat_result:
    """The ``stat`` of ``path`` (links followed) if a reader may read it: a regular file of at
    most ``limit`` bytes, or with ``directory`` a directory. ``OSError`` otherwise (missing,
    unreachable, not a regular file, too large). For readers that hand the path to a library
    which opens it itself (SQLite, rerun); readers that open the file use :func:`open_input`."""
    info = os.stat(path)
    if directory and stat.S_ISDIR(info.st_mode):
        return info
    if not stat.S_ISREG(info.st_mode):
        raise not_regular(path, info.st_mode)
    if limit is not None and info.st_size > limit:
        raise too_large(path, limit, what)
    return info


def open_input(path: str | os.PathLike, *, limit: int | None = None, what: str = "this file") -> BinaryIO:
    """``path`` opened for reading in binary, only if it is a regular file of at most ``limit``
    bytes (``what`` names the format in the message); ``OSError`` otherwise. Opening never
    blocks: a FIFO is refused without waiting for a writer."""
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0) | getattr(os, "O_BINARY", 0)
    descriptor = os.open(path, flags)
    try:
        info = os.fstat(descriptor)
        if not stat.S_ISREG(info.st_mode):
            raise not_regular(path, info.st_mode)
        if limit is not None and info.st_size > limit:
            raise too_large(path, limit, what)
        if hasattr(os, "set_blocking"):
            os.set_blocking(descriptor, True)
        return os.fdopen(descriptor, "rb")
    except BaseException:
        os.close(descriptor)
        raise


def read_input(path: str | os.PathLike, *, limit: int | None = None, what: str = "this file") -> bytes:
    """The bytes of ``path`` under the rule of :func:`open_input`; a file that grows past
    ``limit`` while it is read is refused too."""
    with open_input(path, limit=limit, what=what) as handle:
        data = handle.read() if limit is None else handle.read(limit + 1)
    if limit is not None and len(data) > limit:
        raise too_large(path, limit, what)
    return data


def _size(limit: int) -> str:
    return f"{limit // MiB} MiB" if limit >= MiB and limit % MiB == 0 else f"{limit} bytes"
