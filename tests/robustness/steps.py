"""What a robustness-audit case finds in its directory before the command runs.

Each step makes one thing in the case's fresh temporary directory: a copy of a shared fixture
(a results file, a recording, a formation), a text file, a FIFO, a *private* device node, a
symbolic link, a directory, a tampered results file, a directory nobody may write. A step that
the platform does not allow (``os.mknod`` without the privilege, ``chattr`` on a file system
without immutable files) raises :class:`Unsupported` and the case is counted as skipped.

Device nodes are always made inside the case's directory with ``os.mknod``; the machine's own
``/dev`` entries are never opened, written or named as a destination.
"""

from __future__ import annotations

import os
import shutil
import sqlite3
import stat
import subprocess
import sys
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

PROJECT_ROOT = Path(__file__).resolve().parents[2]
"""The checkout this audit belongs to: the code every case runs."""

DEVICES: dict[str, tuple[int, int]] = {"null": (1, 3), "zero": (1, 5), "full": (1, 7), "urandom": (1, 9)}
"""Linux character devices (major, minor) the private nodes stand in for."""


class Unsupported(Exception):
    """The platform does not let this case be set up (it is skipped, with this reason)."""


def cli_command(*argv: str) -> list[str]:
    """The command line that runs this checkout's ``soccer-sim`` with ``argv``."""
    return [sys.executable, "-m", "experiments.cli", *argv]


def child_environment() -> dict[str, str]:
    """The environment every case runs in: this checkout first on the import path, no display
    (no viewer opens), no traceback switch (the user's view of an error), no Ray address."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("DISPLAY", "WAYLAND_DISPLAY", "SOCCER_SIM_TRACEBACK", "RAY_ADDRESS", "COLUMNS", "LINES")}
    env["PYTHONPATH"] = os.pathsep.join([str(PROJECT_ROOT), *filter(None, [os.environ.get("PYTHONPATH")])])
    env["MPLBACKEND"] = "Agg"
    return env


# ------------------------------------------------------------------------------ shared fixtures
MISBEHAVING_TEAMS = '''\
"""Teams that misbehave on purpose from cycle 2 on (the audit's `misbehaving:Name` paths)."""
import os
import signal
import sys
import time

import numpy as np

from soccer_sim import TeamCommand


class Still:
    def reset(self, side_info, config, rng):
        n = side_info.players_per_team
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view):
        if view.cycle >= 2:
            self.misbehave()
        return self.command

    def misbehave(self):
        pass


class Sleeping(Still):
    def misbehave(self):
        time.sleep(10_000)


class Deaf(Still):
    """Disarms the alarm a match timer may rely on, then never returns."""
    def misbehave(self):
        signal.signal(signal.SIGALRM, signal.SIG_IGN)
        while True:
            time.sleep(0.05)


class BaseRaising(Still):
    def misbehave(self):
        raise BaseException("a team raising BaseException")


class SelfKilling(Still):
    def misbehave(self):
        os.kill(os.getpid(), signal.SIGKILL)


class Quitting(Still):
    def misbehave(self):
        os._exit(0)


class Printing(Still):
    def act(self, view):
        print("the team prints this line", view.cycle)
        return self.command


class Shouting(Still):
    def act(self, view):
        self.command.say = ["\\x1b[31m" * 1000] + [None] * (len(self.command.dash) - 1)
        return self.command
'''
"""A module of teams written into every case directory that names one."""


def _make_results(root: Path) -> None:
    """A real tournament results file (idle v chaser, 2 matches of 5 cycles), by this checkout's CLI."""
    subprocess.run(cli_command("tournament", "--teams", "idle,chaser", "--games", "2", "--cycles", "5",
                               "--workers", "1", "--no-progress", "--out", "results.sqlite"),
                   cwd=root, env=child_environment(), check=True, capture_output=True, timeout=600)


def _make_recording(root: Path) -> None:
    """A rerun recording of a 5-cycle match, by this checkout's CLI."""
    subprocess.run(cli_command("play", "idle", "chaser", "--cycles", "5", "--record", "match.rrd"),
                   cwd=root, env=child_environment(), check=True, capture_output=True, timeout=600)


def _make_agent2d(root: Path) -> None:
    """An agent2d 'Method Delaunay' formation file, written by the formation tests' helper."""
    from tests.formations.agent2d_samples import dt_v2_text

    (root / "agent2d.conf").write_text(dt_v2_text(), encoding="utf-8")


def _make_formation(root: Path) -> None:
    """The built-in 4-4-2 set in this project's JSON layout."""
    from formations.builtin import builtin_path

    (root / "formation.json").write_bytes(builtin_path("4-4-2").read_bytes())


FIXTURES: dict[str, Callable[[Path], None]] = {
    "results.sqlite": _make_results,
    "match.rrd": _make_recording,
    "agent2d.conf": _make_agent2d,
    "formation.json": _make_formation,
}
"""Shared input files, made once per audit run (by name) and copied into the cases that use them."""


class Fixtures:
    """The shared input files of one audit run, made on first use in ``root``."""

    def __init__(self, root: Path) -> None:
        self.root = root
        self._failed: dict[str, str] = {}

    def path(self, name: str) -> Path:
        target = self.root / name
        if name in self._failed:
            raise Unsupported(f"fixture {name} could not be made: {self._failed[name]}")
        if not target.exists():
            try:
                FIXTURES[name](self.root)
            except (OSError, subprocess.SubprocessError, ImportError) as exc:
                detail = getattr(exc, "stderr", b"") or b""
                self._failed[name] = f"{type(exc).__name__}: {exc} {detail[-300:]!r}"
                raise Unsupported(f"fixture {name} could not be made: {self._failed[name]}") from exc
        return target


# ------------------------------------------------------------------------------ the steps
class _Step:
    """What every step has: the shared fixtures it copies (none by default)."""

    needs: tuple[str, ...] = ()


@dataclass
class Context:
    """Where a case's steps work: its directory, the shared fixtures, and undo actions that
    must run before the directory can be removed."""

    dir: Path
    fixtures: Fixtures
    cleanups: list[Callable[[], None]]


@dataclass(frozen=True)
class Copy(_Step):
    """A copy of the shared fixture ``fixture`` named ``name``."""

    fixture: str
    name: str

    @property
    def needs(self) -> tuple[str, ...]:
        return (self.fixture,)

    def make(self, ctx: Context) -> None:
        shutil.copyfile(ctx.fixtures.path(self.fixture), ctx.dir / self.name)


@dataclass(frozen=True)
class Text(_Step):
    """A text file ``name`` holding ``text`` (``text`` may name a constant: ``teams``)."""

    name: str
    text: str

    def make(self, ctx: Context) -> None:
        (ctx.dir / self.name).parent.mkdir(parents=True, exist_ok=True)
        (ctx.dir / self.name).write_text(self.text, encoding="utf-8")


def Teams() -> Text:  # noqa: N802 - reads as a step like the classes
    """The misbehaving teams' module, importable as ``misbehaving`` from the case directory."""
    return Text("misbehaving.py", MISBEHAVING_TEAMS)


@dataclass(frozen=True)
class AgentDir(_Step):
    """An agent2d formations-dt directory ``name`` with one formation file ``file`` in it."""

    name: str
    file: str = "normal-formation.conf"
    needs = ("agent2d.conf",)

    def make(self, ctx: Context) -> None:
        (ctx.dir / self.name).mkdir()
        shutil.copyfile(ctx.fixtures.path("agent2d.conf"), ctx.dir / self.name / self.file)


@dataclass(frozen=True)
class Fifo(_Step):
    """A named pipe ``name`` (nobody writes into it)."""

    name: str

    def make(self, ctx: Context) -> None:
        if not hasattr(os, "mkfifo"):
            raise Unsupported("os.mkfifo is not available")
        (ctx.dir / self.name).parent.mkdir(parents=True, exist_ok=True)
        os.mkfifo(ctx.dir / self.name)


@dataclass(frozen=True)
class Device(_Step):
    """A private character-device node ``name`` standing in for ``/dev/<kind>`` (made with
    ``os.mknod`` in the case directory; skipped where that is not permitted)."""

    name: str
    kind: str

    def make(self, ctx: Context) -> None:
        make_device(ctx.dir / self.name, self.kind)


def make_device(path: Path, kind: str) -> None:
    """A private ``kind`` device node at ``path``, or Unsupported."""
    if not hasattr(os, "mknod") or not sys.platform.startswith("linux"):
        raise Unsupported("private device nodes need Linux and os.mknod")
    major, minor = DEVICES[kind]
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        os.mknod(path, 0o666 | stat.S_IFCHR, os.makedev(major, minor))
    except OSError as exc:
        raise Unsupported(f"os.mknod is not permitted here: {exc}") from exc


@dataclass(frozen=True)
class Link(_Step):
    """A symbolic link ``name`` pointing at ``target`` (relative to the case directory, or absolute)."""

    name: str
    target: str

    def make(self, ctx: Context) -> None:
        os.symlink(self.target, ctx.dir / self.name)


@dataclass(frozen=True)
class Directory(_Step):
    """An empty directory ``name``."""

    name: str

    def make(self, ctx: Context) -> None:
        (ctx.dir / self.name).mkdir(parents=True)


@dataclass(frozen=True)
class Tamper(_Step):
    """Run the SQL ``statements`` on the (already copied) SQLite file ``name``."""

    name: str
    statements: str

    def make(self, ctx: Context) -> None:
        connection = sqlite3.connect(ctx.dir / self.name)
        try:
            connection.executescript(self.statements)
            connection.commit()
        finally:
            connection.close()


@dataclass(frozen=True)
class Unwritable(_Step):
    """A directory ``name`` that nobody, root included, may write into (``chattr +i``; made
    writable again before the case directory is removed)."""

    name: str

    def make(self, ctx: Context) -> None:
        path = ctx.dir / self.name
        path.mkdir(parents=True, exist_ok=True)
        if shutil.which("chattr") is None:
            raise Unsupported("chattr is not installed")
        done = subprocess.run(["chattr", "+i", str(path)], capture_output=True, text=True)
        if done.returncode != 0:
            raise Unsupported(f"chattr +i is not permitted here: {done.stderr.strip()}")
        ctx.cleanups.append(lambda: subprocess.run(["chattr", "-i", str(path)], capture_output=True))


Step = Copy | Text | AgentDir | Fifo | Device | Link | Directory | Tamper | Unwritable
