"""Run one call in a forked child with a time bound (not a test module).

The fuzz tests that hand commands FIFOs, device nodes and huge numbers cannot run them in the
test process: a command blocked on a FIFO, or a compiled kernel spinning on a 1e308 m field,
would hang the test run. :func:`run_forked` forks the test process (so the modules and kernels
it loaded are there at no cost), runs the call in the child as its own process group, with
standard output and error going to files, an address-space limit (``memory_mb`` on top of
what the test process maps) and a working directory,
and kills the whole group at the bound.
"""

from __future__ import annotations

import io
import os
import pickle
import resource
import signal
import sys
import tempfile
import time
import traceback
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

def project_errors() -> tuple[type[BaseException], ...]:
    """The roots of the project's errors (every error it raises on purpose derives from one)."""
    from agents.errors import AgentsError
    from experiments.errors import ExperimentError
    from formations.errors import FormationError
    from soccer_sim import SoccerSimError

    return (SoccerSimError, FormationError, AgentsError, ExperimentError)


@dataclass
class Forked:
    """What the call did in the child."""

    timed_out: bool
    seconds: float
    stdout: str
    stderr: str
    exit_signal: int | None = None
    """The signal that ended the child, if one did (e.g. SIGALRM: 'Alarm clock')."""
    returned: object = None
    raised: str | None = None
    """The type name of the exception the call raised (None if it returned)."""
    project_error: bool = False
    """The exception is one of the project's errors."""
    message: str = ""
    exited: int | None = None
    """The call ended the child with ``sys.exit`` / ``os._exit`` (this status)."""

    def describe(self) -> str:
        if self.timed_out:
            return f"still running after {self.seconds:.0f} s"
        if self.exit_signal is not None:
            return f"killed by signal {self.exit_signal}"
        if self.raised:
            return f"raised {self.raised}: {self.message[:300]}"
        if self.exited is not None:
            return f"exited {self.exited}"
        return f"returned {self.returned!r}"[:300]


def run_forked(call: Callable[[], object], *, bound: float, cwd: Path, memory_mb: int = 4096,
               env: dict[str, str] | None = None) -> Forked:
    """``call()`` in a forked child in ``cwd`` (environment updated by ``env``), stopped at
    ``bound`` seconds. Its return value must pickle."""
    with tempfile.TemporaryDirectory(prefix="forked-") as scratch:
        out_path, err_path, result_path = (Path(scratch) / name for name in ("out", "err", "result"))
        sys.stdout.flush()
        sys.stderr.flush()
        started = time.monotonic()
        pid = os.fork()
        if pid == 0:  # the child: never returns
            _child(call, cwd, memory_mb, env or {}, out_path, err_path, result_path)
        timed_out, status = False, None
        while True:
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                break
            if time.monotonic() - started > bound:
                timed_out = True
                _kill_group(pid)
                _, status = os.waitpid(pid, 0)
                break
            time.sleep(0.01)
        _kill_group(pid)  # workers the call started, if any outlived it
        seconds = time.monotonic() - started
        result = Forked(timed_out, seconds, _text(out_path), _text(err_path))
        if not timed_out and os.WIFSIGNALED(status):
            result.exit_signal = os.WTERMSIG(status)
        if result_path.is_file() and result_path.stat().st_size:
            kind, value, *rest = pickle.loads(result_path.read_bytes())
            if kind == "returned":
                result.returned = value
            elif kind == "raised":
                result.raised, (result.project_error, result.message) = value, rest
            else:
                result.exited = value
        elif not timed_out and os.WIFEXITED(status):
            result.exited = os.WEXITSTATUS(status)
        return result


def _child(call, cwd: Path, memory_mb: int, env: dict[str, str], out_path: Path, err_path: Path,
           result_path: Path) -> None:
    status = 0
    try:
        os.setpgid(0, 0)
        # the cap is on top of what the test process already maps (a worker that loaded Ray or
        # compiled many kernels maps gigabytes; a fixed cap below that fails every allocation)
        limit = _address_space() + memory_mb * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
        signal.signal(signal.SIGINT, signal.SIG_DFL)
        for fd, path in ((1, out_path), (2, err_path)):
            target = os.open(path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o600)
            os.dup2(target, fd)
            os.close(target)
        sys.stdout = io.TextIOWrapper(os.fdopen(1, "wb", closefd=False), write_through=True)
        sys.stderr = io.TextIOWrapper(os.fdopen(2, "wb", closefd=False), write_through=True)
        stdin = os.open(os.devnull, os.O_RDONLY)  # the test process's stdin is never read
        os.dup2(stdin, 0)
        os.environ.update(env)
        os.chdir(cwd)
        try:
            record = ("returned", call())
        except SystemExit as exc:
            code = exc.code
            record = ("exited", code if isinstance(code, int) else (0 if code is None else 1))
        except BaseException as exc:  # noqa: BLE001 - the child reports everything
            traceback.print_exc()
            record = ("raised", type(exc).__name__, isinstance(exc, project_errors()), str(exc)[:2000])
        result_path.write_bytes(pickle.dumps(record))
    except BaseException:  # noqa: BLE001 - the child must never return into the test run
        status = 70
        try:
            traceback.print_exc()
        except BaseException:  # noqa: BLE001
            pass
    finally:
        try:
            sys.stdout.flush()
            sys.stderr.flush()
        except BaseException:  # noqa: BLE001
            pass
        os._exit(status)


def _address_space() -> int:
    """The bytes of address space this process maps now (``/proc/self/statm``'s size)."""
    with open("/proc/self/statm") as statm:
        return int(statm.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")


def _kill_group(pid: int) -> None:
    try:
        os.killpg(pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def _text(path: Path) -> str:
    return path.read_bytes().decode("utf-8", "replace") if path.is_file() else ""
