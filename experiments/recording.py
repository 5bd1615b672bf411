"""Writing a match's rerun replay to a file only once the match has been played.

The replay is recorded into a temporary file beside the target and renamed onto it at the
end, so a match that fails or is interrupted leaves no partial replay, and an earlier file of
that name stays as it was. Used by ``play --record`` and ``replay --results ... --out``.
"""

from __future__ import annotations

import contextlib
import sys
from collections.abc import Iterator
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
    from experiments.results.files import atomic_output, describe
    from soccer_sim.replay import ReplayError, RerunRecorder

    target = Path(path)
    if target.suffix != ".rrd":
        raise ReplayError(f"{option} {path}: a replay file must end in .rrd")
    if not target.parent.is_dir():
        raise ReplayError(f"{option} {path}: directory {target.parent} does not exist")
    output = atomic_output(target)
    try:
        temporary = output.__enter__()
    except OSError as exc:
        raise ReplayError(f"{option} {path}: cannot write it ({describe(exc)})") from None
    try:
        yield [RerunRecorder(temporary)]
    except BaseException:
        output.__exit__(*sys.exc_info())    # removes the temporary file; the exception goes on
        raise
    try:
        output.__exit__(None, None, None)
    except OSError as exc:
        raise ReplayError(f"{option} {path}: cannot write it ({describe(exc)})") from None
