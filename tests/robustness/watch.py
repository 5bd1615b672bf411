"""What a command must leave alone: the files and special files set up before it ran.

:func:`snapshot` records each entry under a directory without opening anything but regular
files (a FIFO or a device node is only ``lstat``-ed); :func:`changed` names the entries that
are no longer what they were: a regular file with other bytes, or a FIFO, device node or link
that was replaced (another inode), removed or turned into something else.
"""

from __future__ import annotations

import hashlib
import os
import stat
from pathlib import Path


def snapshot(root: Path, writes: tuple[str, ...]) -> dict[str, tuple]:
    """What each set-up file is: a regular file's bytes (digest); any other kind's type, inode,
    device number and link target. Never opens anything that is not a regular file."""
    seen: dict[str, tuple] = {}
    for path in sorted(root.rglob("*")):
        name = path.relative_to(root).as_posix()
        if name == ".fill-log" or any(name == w or name.startswith(w + "/") for w in writes):
            continue
        info = path.lstat()
        if stat.S_ISREG(info.st_mode):
            seen[name] = ("file", hashlib.sha256(path.read_bytes()).hexdigest())
        elif not stat.S_ISDIR(info.st_mode):
            target = os.readlink(path) if stat.S_ISLNK(info.st_mode) else None
            seen[name] = (stat.S_IFMT(info.st_mode), info.st_ino, info.st_rdev, target)
        else:
            seen[name] = ("dir",)
    return seen


def changed(before: dict[str, tuple], root: Path, writes: tuple[str, ...]) -> list[str]:
    after = snapshot(root, writes)
    return [name for name, what in before.items() if after.get(name) != what]
