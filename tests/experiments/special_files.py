"""Special files for the tests of the rules on the files commands read and write: FIFOs,
private device nodes and a small private disk, all made inside the test's own temporary
directory (never the machine's own ``/dev`` entries).

* :func:`device_node` makes a character device with the numbers of ``/dev/full`` (1, 7),
  ``/dev/null`` (1, 3), ``/dev/zero`` (1, 5) or ``/dev/urandom`` (1, 9) in a temporary
  directory, and skips the test where the platform does not let it (``os.mknod`` needs root).
* :func:`run_on_small_disk` runs ``soccer-sim`` in a private mount namespace (``unshare -m``)
  with a tmpfs of a few KiB mounted on a directory of the test, so a full disk (or, with
  ``read_only``, a read-only file system) is real and nobody else sees it; it skips where
  namespaces or mounts are not allowed.
"""

from __future__ import annotations

import os
import shutil
import stat
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

DEVICES = {"full": (1, 7), "null": (1, 3), "zero": (1, 5), "urandom": (1, 9)}
"""Linux's numbers of the devices whose behaviour the tests need."""


def device_node(directory: Path, kind: str) -> Path:
    """A private character device ``directory/kind`` with the numbers of ``/dev/<kind>``."""
    path = directory / kind
    major, minor = DEVICES[kind]
    try:
        os.mknod(path, 0o666 | stat.S_IFCHR, os.makedev(major, minor))
    except (OSError, AttributeError) as exc:
        pytest.skip(f"cannot make a private device node here ({exc})")
    return path


def fifo(directory: Path, name: str = "fifo") -> Path:
    """A FIFO ``directory/name`` (skipped where the platform has none)."""
    path = directory / name
    if not hasattr(os, "mkfifo"):
        pytest.skip("no FIFOs on this platform")
    os.mkfifo(path)
    return path


def is_char_device(path: Path) -> bool:
    return stat.S_ISCHR(os.lstat(path).st_mode)


def is_fifo(path: Path) -> bool:
    return stat.S_ISFIFO(os.lstat(path).st_mode)


def command(*args: str) -> list[str]:
    """``soccer-sim ARGS`` as this checkout's code runs it."""
    return [sys.executable, "-m", "experiments.cli", *args]


def environment() -> dict[str, str]:
    return {**os.environ, "PYTHONPATH": str(ROOT), "SOCCER_SIM_TRACEBACK": "0"}


@dataclass
class DiskRun:
    """A command run with a small disk: its status, output and the files left on the disk."""

    returncode: int
    stdout: str
    stderr: str
    left: list[str]


def run_on_small_disk(tmp_path: Path, args: list[str], size: str = "24k", read_only: bool = False,
                      timeout: float = 300) -> DiskRun:
    """Run ``soccer-sim ARGS`` in ``tmp_path`` with a private tmpfs of ``size`` on
    ``tmp_path/disk`` (``ARGS`` name files under ``disk/``); what the command left there is
    listed before the private mount goes away."""
    if shutil.which("unshare") is None or subprocess.run(["unshare", "-m", "true"], capture_output=True).returncode:
        pytest.skip("no private mount namespace here (unshare -m)")
    disk = tmp_path / "disk"
    disk.mkdir(exist_ok=True)
    listing = tmp_path / "left-on-disk.txt"
    options = f"size={size}" + (",ro" if read_only else "")
    script = ('mount -t tmpfs -o "$1" tmpfs "$2" || exit 99; shift 2; "$@"; status=$?; '
              f'ls -A disk > "{listing}"; exit $status')
    done = subprocess.run(["unshare", "-m", "sh", "-c", script, "sh", options, str(disk), *command(*args)],
                          cwd=tmp_path, env=environment(), capture_output=True, text=True, timeout=timeout)
    if done.returncode == 99:
        pytest.skip(f"cannot mount a private tmpfs here: {done.stderr.strip()}")
    left = listing.read_text().split() if listing.exists() else []
    return DiskRun(done.returncode, done.stdout, done.stderr, left)


def one_error_line(stderr: str) -> str:
    """The one ``error:`` line a failed command printed (asserting it is the only line)."""
    lines = [line for line in stderr.strip().splitlines() if line.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), lines
    return lines[0]
