"""One match in rcssserver, from start to end: the server in a private network namespace,
both teams connected to it, the match played, every process ended by its id.

Two parts, two processes:

* :func:`play_in_namespace` (the caller's process) writes the :class:`MatchPlan` to the
  match's work directory and starts the **host**, ``unshare -rn python -m rcss_bridge.match
  PLAN``: a process in a new user and network namespace, where nothing is reachable but
  127.0.0.1 (rcssserver listens on every address and has no option to change that). It waits
  for the host (at most ``match_timeout`` plus a margin) and reads its
  :class:`MatchOutcome`; on Ctrl-C or any failure it ends the host, whose own cleanup ends
  the rest.
* :class:`MatchHost` (the host) brings the loopback up, starts rcssserver (synchronous mode,
  ``auto_mode``: it kicks off once both teams are connected and exits after time over; game
  log ``match.rcg`` and text log ``match.rcl`` in the work directory), waits until it listens,
  starts the home side and waits until all its players are connected (the server's output
  says so; the first team connected plays on the left), then the away side, and waits for
  the server to end the match. A side that exits with an error before the match is over
  ends the match: a :class:`SideFailed` with the side's last output line (a team of the
  project names the player and the step there). Every process is ended by its id in the end
  (:class:`~rcss_bridge.processes.ChildProcess`), also after a failure, ``SIGTERM`` or
  Ctrl-C.

A side is any program (:class:`SideProgram`) that connects a full team to the host and port
it is given: one of the project's teams through :class:`~rcss_bridge.client.TeamClient`
(``experiments.rcss_engine``), or helios-base's ``start.sh``.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from dataclasses import asdict, dataclass, field
from pathlib import Path

from rcss_bridge.errors import BridgeError, ServerError
from rcss_bridge.install import RcssInstall
from rcss_bridge.processes import ChildProcess, die_with_parent

PLAYERS_PORT = 6000
"""rcssserver's players' port (``server::port``); the online coaches' is 6002."""

GAME_LOG = "match"
"""The name (without ``.rcg`` / ``.rcl``) of the game and text logs in the work directory."""

SERVER_START_SECONDS = 15.0
"""How long the server may take to listen on its port."""

NO_CONNECT_LIMIT = 1_000_000
"""rcssserver's ``connect_wait`` (steps before kick-off it waits for both teams; then it plays
with what it has): out of reach, the host limits each side's connection itself
(``MatchPlan.connect_timeout``)."""

POLL_SECONDS = 0.2
"""How often the host looks at its processes."""

_CONNECTED = re.compile(r"A new \(v\d+\) player \((\S+) (\d+)\) connected")
"""rcssserver's line for a player that connected (``A new (v19) player (NAME 3) connected.``)."""

_SERVER_NAME = re.compile(r"^[A-Za-z0-9_-]{1,15}$")
"""A team name rcssserver takes (letters, digits, ``-``, ``_``; at most 15 characters)."""


class SideFailed(BridgeError, RuntimeError):
    """A side's program ended with an error, or did not connect its team in time."""

    def __init__(self, label: str, message: str) -> None:
        super().__init__(f"{label}: {message}")
        self.label = label
        self.message = message

    def __reduce__(self):
        return type(self), (self.label, self.message)


class MatchTimeout(BridgeError, TimeoutError):
    """The match did not end within its time limit."""


def server_team_name(label: str, taken: str = "") -> str:
    """The name a team of label ``label`` plays under in the server: the label with every
    character the server refuses as ``_``, at most 15 characters, and different from
    ``taken`` (the other side's: the server would put both in one team)."""
    name = re.sub(r"[^A-Za-z0-9_-]", "_", label)[:15] or "team"
    if name == taken:
        name = name[:13] + "_2"
    return name


@dataclass(frozen=True)
class SideProgram:
    """One side of a match: the program that connects its team."""

    label: str
    """The team's name in the report (``mmdr``, ``helios-base``)."""
    server_name: str
    """The name its players give the server (:func:`server_team_name`)."""
    argv: tuple[str, ...]
    """The program and its arguments."""
    cwd: str | None = None
    env: dict[str, str] = field(default_factory=dict)
    """Variables added to the host's environment."""
    players: int = 11
    """Players it connects (the host waits for all of them before starting the other side)."""

    def __post_init__(self) -> None:
        if not _SERVER_NAME.match(self.server_name):
            raise BridgeError(f"team name {self.server_name!r} is not one rcssserver takes (letters, digits, - and _, "
                              "at most 15 characters)")
        if not self.argv:
            raise BridgeError(f"side {self.label!r} has no program to run")


@dataclass(frozen=True)
class MatchPlan:
    """Everything the host needs, as JSON (:meth:`to_json`, :meth:`from_json`)."""

    rcss_home: str
    """The kit's build (:class:`~rcss_bridge.install.RcssInstall`)."""
    workdir: str
    """Where the logs, the processes' output and the outcome go."""
    home: SideProgram
    """The side that connects first: rcssserver's left."""
    away: SideProgram
    port: int = PLAYERS_PORT
    """The players' port (``server::port``; the trainer's is the next, the online coaches' the
    one after, as in rcssserver's defaults)."""
    half_time: int = 300
    """rcssserver's ``half_time`` (seconds of 10 cycles: 300 is a regulation half of 3000 cycles)."""
    connect_timeout: float = 180.0
    """How long a side may take to connect all its players (a team of the project loads its
    compiled kernels first)."""
    match_timeout: float = 1800.0
    """How long the whole match may take (seconds, from the server's start)."""
    leave_timeout: float = 5.0
    """How long the teams may take to leave by themselves once the server has ended the match
    (then they are ended)."""
    server_options: tuple[str, ...] = ()
    """Further ``server::key=value`` options."""

    def to_json(self) -> str:
        return json.dumps(asdict(self))

    @classmethod
    def from_json(cls, text: str) -> MatchPlan:
        data = json.loads(text)
        data["home"] = SideProgram(**{**data["home"], "argv": tuple(data["home"]["argv"])})
        data["away"] = SideProgram(**{**data["away"], "argv": tuple(data["away"]["argv"])})
        data["server_options"] = tuple(data.get("server_options", ()))
        return cls(**data)

    def server_argv(self, install: RcssInstall) -> list[str]:
        """rcssserver's command line: synchronous mode, ``auto_mode``, two halves of
        ``half_time`` and nothing after them, uncompressed game and text logs named
        :data:`GAME_LOG` in the work directory, and ``player::allow_mult_default_type``: the
        simulator's rule for player types (``pt_max`` limits each non-default type; without
        it rcssserver 19 also limits the default type to ``pt_max`` players and gives the
        others types of its own at kick-off, ``Team::assignPlayerTypes``)."""
        options = {
            "synch_mode": "true", "auto_mode": "true", "nr_normal_halfs": "2", "half_time": str(self.half_time),
            "nr_extra_halfs": "0", "penalty_shoot_outs": "false", "coach": "false",
            "game_logging": "true", "text_logging": "true", "game_log_compression": "0",
            "text_log_compression": "0", "game_log_fixed": "true", "text_log_fixed": "true",
            "game_log_fixed_name": GAME_LOG, "text_log_fixed_name": GAME_LOG,
            "game_log_dir": self.workdir, "text_log_dir": self.workdir, "keepaway_logging": "false",
            "port": str(self.port), "coach_port": str(self.port + 1), "olcoach_port": str(self.port + 2),
            "connect_wait": str(NO_CONNECT_LIMIT),
        }
        player_options = {"allow_mult_default_type": "true"}
        return ([str(install.server)] + [f"server::{key}={value}" for key, value in options.items()]
                + [f"player::{key}={value}" for key, value in player_options.items()] + list(self.server_options))


@dataclass(frozen=True)
class MatchOutcome:
    """What a match in the server left."""

    rcg: str
    """The game log (``.rcg``)."""
    rcl: str
    """The text log (``.rcl``: every command the server received, with its time)."""
    wall_time: float
    """Seconds from the server's start to its end."""
    connect_seconds: float
    """Seconds from the server's start until both teams were connected (our teams load their
    compiled code first): the match itself took ``wall_time - connect_seconds``."""
    server_output: str
    """The server's output (its ``stdout``), a file."""


class MatchHost:
    """Plays one :class:`MatchPlan` in this process's network namespace (module docstring)."""

    def __init__(self, plan: MatchPlan) -> None:
        self.plan = plan
        self.install = RcssInstall.find(plan.rcss_home)
        self.workdir = Path(plan.workdir)
        self.children: list[ChildProcess] = []

    def play(self) -> MatchOutcome:
        self.install.require_server()
        plan, work = self.plan, self.workdir
        env = {**os.environ, "HOME": str(work / "server-home"),
               "LD_LIBRARY_PATH": os.pathsep.join(filter(None, [str(self.install.libraries),
                                                                 os.environ.get("LD_LIBRARY_PATH", "")]))}
        (work / "server-home").mkdir(exist_ok=True)
        start = time.monotonic()
        try:
            server = self._start("rcssserver", plan.server_argv(self.install), work / "server.out",
                                 str(work / "server-home"), env)
            self._wait_listening(server)
            for side in (plan.home, plan.away):
                process = self._start(side.label, side.argv, work / f"{side.server_name}.out", side.cwd,
                                      {**os.environ, **side.env})
                self._wait_connected(server, side, process)
            connected = time.monotonic() - start
            deadline = start + plan.match_timeout
            while server.poll() is None:
                self._check_sides(server)
                if time.monotonic() > deadline:
                    raise MatchTimeout(f"the match did not end within {plan.match_timeout:g} s")
                time.sleep(POLL_SECONDS)
            wall = time.monotonic() - start
            self._let_sides_leave()
        finally:
            self.end_all()
        rcg, rcl = work / f"{GAME_LOG}.rcg", work / f"{GAME_LOG}.rcl"
        if not rcg.is_file():
            raise ServerError(f"rcssserver ended without a game log ({server.last_line('no output')})")
        return MatchOutcome(str(rcg), str(rcl), wall, connected, str(server.log))

    def _start(self, name: str, argv, log: Path, cwd: str | None, env) -> ChildProcess:
        try:
            child = ChildProcess.start(name, argv, log, cwd, env)
        except OSError as exc:
            raise SideFailed(name, f"cannot start {argv[0]}: {exc.strerror or exc}") from None
        self.children.append(child)
        return child

    def _wait_listening(self, server: ChildProcess) -> None:
        deadline = time.monotonic() + SERVER_START_SECONDS
        while not udp_port_bound(self.plan.port):
            if server.poll() is not None:
                raise ServerError(f"rcssserver exited at start (status {server.poll()}): "
                                  f"{server.error_line('no output')}")
            if time.monotonic() > deadline:
                raise ServerError(f"rcssserver did not listen on port {self.plan.port} within "
                                  f"{SERVER_START_SECONDS:g} s")
            time.sleep(0.05)

    def _wait_connected(self, server: ChildProcess, side: SideProgram, process: ChildProcess) -> None:
        deadline = time.monotonic() + self.plan.connect_timeout
        while len(connected_players(server.log, side.server_name)) < side.players:
            self._check_sides(server)
            status = process.poll()
            if status not in (None, 0):
                raise SideFailed(side.label, process.last_line(f"exited with status {status} before connecting"))
            if server.poll() is not None:
                raise ServerError(f"rcssserver exited while {side.label} connected: {server.last_line('no output')}")
            if time.monotonic() > deadline:
                got = len(connected_players(server.log, side.server_name))
                raise SideFailed(side.label, f"connected {got} of {side.players} players within "
                                 f"{self.plan.connect_timeout:g} s ({process.last_line('no output')})")
            time.sleep(POLL_SECONDS)

    def _check_sides(self, server: ChildProcess) -> None:
        """A side that exited with an error before the match ended fails the match."""
        for side, process in zip((self.plan.home, self.plan.away), self.children[1:]):
            status = process.poll()
            if status not in (None, 0) and server.poll() is None:
                raise SideFailed(side.label, process.last_line(f"exited with status {status}"))

    def _let_sides_leave(self) -> None:
        deadline = time.monotonic() + self.plan.leave_timeout
        for process in self.children[1:]:
            process.wait(max(deadline - time.monotonic(), 0.0))

    def end_all(self) -> None:
        """End every process this host started, the teams first, by their ids."""
        for child in reversed(self.children):
            child.end()


def udp_port_bound(port: int) -> bool:
    """Whether a UDP socket of this network namespace is bound to ``port`` (``/proc/net/udp``)."""
    try:
        text = Path("/proc/net/udp").read_text()
    except OSError:
        return False
    suffix = f":{port:04X}"
    return any(line.split()[1].endswith(suffix) for line in text.splitlines()[1:] if len(line.split()) > 1)


def connected_players(server_output: Path, team: str) -> set[int]:
    """Shirt numbers of ``team`` the server said connected (its output so far)."""
    try:
        text = server_output.read_text(errors="replace")
    except OSError:
        return set()
    return {int(m.group(2)) for m in _CONNECTED.finditer(text) if m.group(1) == team}


# ---------------------------------------------------------------------------------- the caller's side
NAMESPACE_COMMAND = ("unshare", "-rn")
"""A new user and network namespace for the host (no privilege needed where the kernel allows
unprivileged user namespaces)."""

HOST_MARGIN_SECONDS = 60.0
"""How much longer than the match's own limit the caller waits for the host."""


def play_in_namespace(plan: MatchPlan, python: str = sys.executable) -> MatchOutcome:
    """Play ``plan`` through a host in a private network namespace (module docstring) and
    return its outcome; the host's error as a :class:`BridgeError` (a :class:`SideFailed`
    naming the side, a :class:`MatchTimeout`, a :class:`ServerError`). Ctrl-C ends the host
    (which ends the server and the teams) and is raised again."""
    if shutil.which(NAMESPACE_COMMAND[0]) is None:
        raise BridgeError("cannot run rcssserver in a private network namespace: the 'unshare' command is missing")
    work = Path(plan.workdir)
    plan_file, outcome_file = work / "plan.json", work / "outcome.json"
    plan_file.write_text(plan.to_json())
    outcome_file.unlink(missing_ok=True)
    host = ChildProcess.start("match host", [*NAMESPACE_COMMAND, python, "-m", "rcss_bridge.match", str(plan_file)],
                              work / "host.out", env={**os.environ, "PYTHONPATH": _python_path()})
    try:
        status = host.wait(plan.match_timeout + 2 * plan.connect_timeout + HOST_MARGIN_SECONDS)
        if status is None:
            raise MatchTimeout(f"the match host did not end within {plan.match_timeout:g} s")
    finally:
        host.end(grace=10.0)
    return read_outcome(outcome_file, host)


def read_outcome(outcome_file: Path, host: ChildProcess) -> MatchOutcome:
    """The host's outcome, or its error raised as the kind it was."""
    try:
        data = json.loads(outcome_file.read_text())
    except (OSError, ValueError):
        raise BridgeError(f"the match host failed: {host.last_line('no output')}") from None
    if "error" in data:
        kind = {"SideFailed": SideFailed, "MatchTimeout": MatchTimeout, "ServerError": ServerError}.get(data["kind"])
        if kind is SideFailed:
            raise SideFailed(data["label"], data["message"])
        raise (kind or BridgeError)(data["error"])
    return MatchOutcome(**data)


def _python_path() -> str:
    """The caller's import path, so that the host imports the same ``rcss_bridge`` (and the
    sides the same project) as the caller."""
    return os.pathsep.join(p for p in sys.path if p)


def _host_main(argv: list[str]) -> int:
    """The host process: ``python -m rcss_bridge.match PLAN`` (in the namespace)."""
    die_with_parent(signal.SIGTERM)
    signal.signal(signal.SIGTERM, _interrupt)
    plan_file = Path(argv[0])
    outcome_file = plan_file.with_name("outcome.json")
    try:
        plan = MatchPlan.from_json(plan_file.read_text())
        subprocess.run(["ip", "link", "set", "lo", "up"], check=True, capture_output=True)
        outcome = MatchHost(plan).play()
        outcome_file.write_text(json.dumps(asdict(outcome)))
        return 0
    except SideFailed as exc:
        outcome_file.write_text(json.dumps({"error": str(exc), "kind": "SideFailed", "label": exc.label,
                                            "message": exc.message}))
    except (BridgeError, OSError, subprocess.CalledProcessError, ValueError, KeyboardInterrupt) as exc:
        text = str(exc) or type(exc).__name__
        if isinstance(exc, subprocess.CalledProcessError):
            text = f"cannot bring up the loopback of the private network namespace: {exc.stderr.decode().strip()}"
        outcome_file.write_text(json.dumps({"error": text, "kind": type(exc).__name__}))
    print(json.loads(outcome_file.read_text())["error"], file=sys.stderr)
    return 1


def _interrupt(signum, frame) -> None:
    raise KeyboardInterrupt("ended by a signal")


if __name__ == "__main__":
    sys.exit(_host_main(sys.argv[1:]))
