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
import sys
from collections.abc import Callable, Iterator
from pathlib import Path


@contextlib.contextmanager
def replay_recording(path: str | None, option: str) -> Iterator[list]:
    """The recorders for a replay at ``path`` (none when ``path`` is None): a
    :class:`~soccer_sim.replay.RerunRecorder` writing a temporary file that replaces ``path``
    when the block ends without an exception. ReplayError naming ``option`` and the file when
    it cannot be written."""
    if path is None:
        yield []
        return
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
        finally:
            _close(made)


@contextlib.contextmanager
def _atomic_destination(path: str, option: str, suffix: str, what: str, error: type[Exception]) -> Iterator[Path]:
    """A temporary file beside ``path`` that replaces it at the end of the block (and is removed
    if the block raises); ``error`` naming ``option`` and ``path`` when it cannot be written."""
    from experiments.results.files import atomic_output, describe

    target = Path(path)
    if target.suffix != suffix:
        raise error(f"{option} {path}: {what} must end in {suffix}")
    if not target.parent.is_dir():
        raise error(f"{option} {path}: directory {target.parent} does not exist")
    output = atomic_output(target)
    try:
        temporary = output.__enter__()
    except OSError as exc:
        raise error(f"{option} {path}: cannot write it ({describe(exc)})") from None
    try:
        yield temporary
    except BaseException:
        output.__exit__(*sys.exc_info())    # removes the temporary file; the exception goes on
        raise
    try:
        output.__exit__(None, None, None)
    except OSError as exc:
        raise error(f"{option} {path}: cannot write it ({describe(exc)})") from None


def _close(recorder: object) -> None:
    """Close a recorder that holds its file open (a game log whose match failed part-way)."""
    close = getattr(recorder, "close", None)
    if close is not None:
        close()
