"""Writing a match's recordings (a rerun replay, an rcssserver game log) to files only once
the match has been played.

Each recording is written into a temporary file beside the target and renamed onto it at the
end, so a match that fails or is interrupted leaves no partial file, and an earlier file of
that name stays as it was. The destination is checked (its suffix, its directory, that a file
can be made there) when the block is entered, before the match. Used by ``play --record``,
``play --rcg`` (whose match's worker writes into the temporary files of
:func:`replay_destination` and :func:`rcg_destination`), ``replay --results ... --out`` and the
runner's ``--rcg-dir``.
"""

from __future__ import annotations

import contextlib
import errno
import os
import sys
from collections.abc import Callable, Iterator
from pathlib import Path


RERUN_LOG_FILTER = "warn,re_log_encoding=off,re_sdk=off"
"""rerun's log filter (``RUST_LOG``) while a replay is written, unless the user set one."""


@contextlib.contextmanager
def replay_recording(path: str | None, option: str) -> Iterator[list]:
    """The recorders for a replay at ``path`` (none when ``path`` is None): a
    :class:`~soccer_sim.replay.RerunRecorder` writing a temporary file that replaces ``path``
    when the block ends without an exception. ReplayError naming ``option`` and the file when
    it cannot be written."""
    if path is None:
        yield []
        return
    _quiet_rerun()
    from soccer_sim.replay import ReplayError, RerunRecorder

    with _atomic_recording(path, option, ".rrd", "a replay file", RerunRecorder, ReplayError) as recorders:
        yield recorders


@contextlib.contextmanager
def rcg_recording(path: str | None, option: str) -> Iterator[list]:
    """The recorders for an rcssserver game log at ``path`` (none when ``path`` is None): a
    :class:`~soccer_sim.rcg.RcgRecorder` writing a temporary file that replaces ``path`` when
    the block ends without an exception. RcgError (a ValueError) naming ``option`` and the
    file when it cannot be written."""
    if path is None:
        yield []
        return
    from soccer_sim.rcg import RcgError, RcgRecorder

    with _atomic_recording(path, option, ".rcg", "a game log", RcgRecorder, RcgError) as recorders:
        yield recorders


@contextlib.contextmanager
def replay_destination(path: str | None, option: str) -> Iterator[Path | None]:
    """The temporary file into which another process (a match's worker) writes the rerun replay
    for ``path``, checked as :func:`replay_recording` checks it; it replaces ``path`` when the
    block ends without an exception and is removed otherwise. None when ``path`` is None."""
    if path is None:
        yield None
        return
    _quiet_rerun()  # (before the worker starts: it inherits the environment)
    from soccer_sim.replay import ReplayError

    with _atomic_destination(path, option, ".rrd", "a replay file", ReplayError) as temporary:
        yield temporary


@contextlib.contextmanager
def rcg_destination(path: str | None, option: str) -> Iterator[Path | None]:
    """The same as :func:`replay_destination` for an rcssserver game log."""
    if path is None:
        yield None
        return
    from soccer_sim.rcg import RcgError

    with _atomic_destination(path, option, ".rcg", "a game log", RcgError) as temporary:
        yield temporary


@contextlib.contextmanager
def _atomic_recording(path: str, option: str, suffix: str, what: str, recorder: Callable[[Path], object],
                      error: type[Exception]) -> Iterator[list]:
    """One ``recorder(temporary)`` writing a temporary file that replaces ``path`` at the end
    of the block; ``error`` naming ``option`` and ``path`` when the file cannot be written."""
    with _atomic_destination(path, option, suffix, what, error) as temporary:
        made = None
        try:
            made = recorder(temporary)
            yield [made]
            _close(made)
        except BaseException:
            with contextlib.suppress(Exception):
                _close(made)                 # a full disk fails the close again: already said
            raise


@contextlib.contextmanager
def _atomic_destination(path: str, option: str, suffix: str, what: str, error: type[Exception]) -> Iterator[Path]:
    """A temporary file beside ``path`` that replaces it at the end of the block (and is removed
    if the block raises); ``error`` naming ``option`` and ``path`` when it cannot be written, an
    OSError naming ``path`` when a write failed (a full disk: exit 1)."""
    from experiments.results.files import atomic_output, describe, file_problem, write_failure

    target = Path(path)
    if target.suffix != suffix:
        raise error(f"{option} {path}: {what} must end in {suffix}")
    problem = file_problem(path)             # the rule for every file a command writes
    if problem:
        raise error(f"{option} {path}: {problem}")
    output = atomic_output(target)
    try:
        temporary = output.__enter__()
    except OSError as exc:
        raise error(f"{option} {path}: cannot write it ({describe(exc)})") from None
    try:
        yield temporary
    except BaseException as exc:
        failed = _failed_write(exc, temporary)
        output.__exit__(*sys.exc_info())    # removes the temporary file
        if failed is not None:              # one line naming the file, exit 1 (a write that failed)
            raise OSError(failed.errno, failed.strerror, str(path)) from None
        raise
    try:
        output.__exit__(None, None, None)
    except OSError as exc:
        if write_failure(exc):
            raise
        raise error(f"{option} {path}: cannot write it ({describe(exc)})") from None


def _quiet_rerun() -> None:
    """rerun's own log lines (its file writer's "No space left on device", ...) would come
    beside ours: every failure they report reaches us as an exception, worded in one line."""
    os.environ.setdefault("RUST_LOG", RERUN_LOG_FILTER)


def _failed_write(exc: BaseException, temporary: Path) -> OSError | None:
    """The OSError of a recording's failed write behind ``exc``, or None: an OSError of a full
    disk or an I/O error (a game log's own write), or any other failure of the match that wrote
    it (rerun's RuntimeError when its file writer stopped, a worker's report of it) on a file
    system with no space left."""
    from experiments.results.files import write_failure

    if isinstance(exc, OSError) and write_failure(exc):
        return exc
    if isinstance(exc, Exception):
        with contextlib.suppress(OSError):
            if os.statvfs(temporary.parent).f_bavail == 0:
                return OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
    return None


def _close(recorder: object) -> None:
    """Close a recorder that holds its file open (a game log whose match failed part-way)."""
    close = getattr(recorder, "close", None)
    if close is not None:
        close()
