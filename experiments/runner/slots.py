"""A worker's deciding slot kept in a small file on its node, for a driver on another machine.

The local pool shares two integers with each worker in shared memory ([side running team
code now, side whose act returned last], see :class:`experiments.runner.worker._Watched`).
A Ray task has no memory in common with its driver, so the task maps the two integers from a
file on its node instead (:class:`FileSlot`), named by a token the driver chose. Writes to a
shared file mapping outlive the process that made them, so when the worker dies the driver
runs :func:`take_slot` on the same node to learn whose code was running, at no cost per act.
"""

from __future__ import annotations

import mmap
import os
import re
import struct
import tempfile
import time
from pathlib import Path

from experiments.results.record import FORFEIT_NONE

SLOT_DIR = "soccer-sim-slots"
"""Directory under the node's temporary directory that holds the slot files."""

STALE_AFTER = 24 * 3600.0
"""Seconds after which a slot file no task removed (its driver was killed too) is swept away."""

_FORMAT = "=2q"
_TOKEN = re.compile(r"[0-9a-f]{8,64}")


def slot_path(token: str) -> Path:
    """The slot file of ``token`` (lower-case hex, as the driver makes it) on this node."""
    if not _TOKEN.fullmatch(token):
        raise ValueError(f"slot token {token!r}: expected 8 to 64 lower-case hex digits")
    return Path(tempfile.gettempdir()) / SLOT_DIR / f"{token}.slot"


class FileSlot:
    """Two int64 mapped from the slot file of ``token``, both FORFEIT_NONE at first; used as a
    context manager, whose exit unmaps and removes the file (a process that dies leaves it for
    :func:`take_slot`). ``values`` is the sequence of two integers to pass as ``deciding``.
    Slot files older than :data:`STALE_AFTER` are removed first."""

    def __init__(self, token: str) -> None:
        self.path = slot_path(token)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        sweep_stale(self.path.parent)
        with open(self.path, "wb") as file:
            file.write(struct.pack(_FORMAT, FORFEIT_NONE, FORFEIT_NONE))
        with open(self.path, "r+b") as file:
            self._map = mmap.mmap(file.fileno(), struct.calcsize(_FORMAT))
        self.values = memoryview(self._map).cast("q")

    def __enter__(self) -> FileSlot:
        return self

    def __exit__(self, *exc_info) -> None:
        self.values.release()
        self._map.close()
        self.path.unlink(missing_ok=True)


def take_slot(token: str) -> int:
    """Run on the node of a task that died: the side whose code its worker was running (the
    slot's first integer), FORFEIT_NONE if none or if there is no slot file; removes the file."""
    path = slot_path(token)
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        return FORFEIT_NONE
    finally:
        path.unlink(missing_ok=True)
    if len(data) != struct.calcsize(_FORMAT):
        return FORFEIT_NONE
    side = struct.unpack(_FORMAT, data)[0]
    return side if side in (0, 1) else FORFEIT_NONE


def sweep_stale(directory: Path, now: float | None = None) -> None:
    """Remove the slot files in ``directory`` last changed more than :data:`STALE_AFTER` ago:
    those of tasks whose worker and driver both died, so nobody read them."""
    now = time.time() if now is None else now
    with os.scandir(directory) as entries:
        for entry in entries:
            try:
                if entry.name.endswith(".slot") and entry.stat().st_mtime < now - STALE_AFTER:
                    os.unlink(entry.path)
            except FileNotFoundError:  # read or removed meanwhile by its own task
                pass


def new_token() -> str:
    """A token no other task uses: 32 random hex digits."""
    return os.urandom(16).hex()
