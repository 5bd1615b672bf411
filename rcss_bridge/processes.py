"""The processes a match in rcssserver starts, and how they end.

Every process is started in a session of its own (so a team's script and the players it
starts form one process group, and a Ctrl-C on the terminal reaches only the program that
started them) and, where the platform allows it, with a parent-death signal (Linux
``PR_SET_PDEATHSIG``: if the program that started it dies, it is killed too). It is ended
by its id (:meth:`ChildProcess.end`): ``SIGTERM`` to the group it leads, a grace period,
then ``SIGKILL``; never by name.
"""

from __future__ import annotations

import ctypes
import os
import signal
import subprocess
import sys
import time
from collections.abc import Mapping, Sequence
from pathlib import Path

PR_SET_PDEATHSIG = 1
"""``prctl`` option: the signal this process gets when its parent dies (Linux)."""

END_GRACE_SECONDS = 3.0
"""How long a process may take to leave after ``SIGTERM`` before it is killed."""


def die_with_parent(sig: int = signal.SIGKILL) -> None:
    """Ask the kernel to send ``sig`` to this process when its parent dies (Linux; elsewhere
    nothing). Called in a child before it runs its program, and by a program that must not
    outlive the one that started it."""
    if not sys.platform.startswith("linux"):
        return
    try:
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(PR_SET_PDEATHSIG, int(sig), 0, 0, 0)
    except (OSError, AttributeError):
        pass


class ChildProcess:
    """One program started for a match (:meth:`start`), known by its id; ``name`` names it in
    errors. Its output goes to ``log`` (stdout and stderr together)."""

    def __init__(self, name: str, process: subprocess.Popen, log: Path) -> None:
        self.name = name
        self.process = process
        self.log = log

    @property
    def pid(self) -> int:
        return self.process.pid

    @classmethod
    def start(cls, name: str, argv: Sequence[str], log: Path, cwd: str | os.PathLike | None = None,
              env: Mapping[str, str] | None = None) -> ChildProcess:
        """Start ``argv`` in a session of its own, its output appended to ``log``."""
        with open(log, "ab") as out:
            process = subprocess.Popen(list(argv), cwd=cwd, env=None if env is None else dict(env),
                                       stdin=subprocess.DEVNULL, stdout=out, stderr=subprocess.STDOUT,
                                       start_new_session=True, preexec_fn=die_with_parent)
        return cls(name, process, log)

    def poll(self) -> int | None:
        """Its exit status, or None while it runs."""
        return self.process.poll()

    def wait(self, timeout: float) -> int | None:
        """Wait at most ``timeout`` s for it to end; its status, or None if it still runs."""
        try:
            return self.process.wait(timeout)
        except subprocess.TimeoutExpired:
            return None

    def end(self, grace: float = END_GRACE_SECONDS) -> int | None:
        """End it and every process of the group it leads: ``SIGTERM``, then after ``grace``
        seconds ``SIGKILL``. Returns its exit status (None if even that did not end it)."""
        status = self.process.poll()
        self._signal_group(signal.SIGTERM)
        if status is None:
            status = self.wait(grace)
        if status is None or self._group_alive():
            deadline = time.monotonic() + (grace if status is not None else 0.0)
            while status is not None and self._group_alive() and time.monotonic() < deadline:
                time.sleep(0.05)
            self._signal_group(signal.SIGKILL)
            if status is None:
                status = self.wait(grace)
        return status

    def _signal_group(self, sig: int) -> None:
        try:
            os.killpg(self.pid, sig)
        except (ProcessLookupError, PermissionError):
            pass

    def _group_alive(self) -> bool:
        try:
            os.killpg(self.pid, 0)
        except (ProcessLookupError, PermissionError):
            return False
        return True

    def last_line(self, default: str = "") -> str:
        """The last non-empty line of its output (an error line, for a program that failed)."""
        try:
            lines = [line.strip() for line in self.log.read_text(errors="replace").splitlines() if line.strip()]
        except OSError:
            return default
        return lines[-1] if lines else default

    def error_line(self, default: str = "") -> str:
        """The first line of its output that says ``error``, else its last line (a program that
        failed at start often prints its usage after the error)."""
        try:
            lines = [line.strip() for line in self.log.read_text(errors="replace").splitlines() if line.strip()]
        except OSError:
            return default
        return next((line for line in lines if "error" in line.lower()), lines[-1] if lines else default)
