"""The robustness audit: run every case of :mod:`tests.robustness.cases` and count the outcomes.

    python -m tests.robustness.audit [--only CLASS] [--case TEXT] [--timeout S] [--jobs N] [--verbose]

Each case runs in a fresh temporary directory as its own process group (this checkout's code:
``python -m experiments.cli`` with the project root first on ``PYTHONPATH``), under an
address-space limit, and is stopped (the whole group killed) at the time bound. Its outcome is
one of:

* **input changed**: a file the steps made changed its bytes, or a special file was replaced,
  removed or changed kind (checked first: it is the worst);
* **hang**: still running at the bound;
* **traceback**: a Python traceback on stderr, the last-resort ``error: unexpected ...`` line,
  death by a signal or an undocumented exit status; for a snippet, an exception that is none of
  the project's errors;
* **silent**: exit 0 (a snippet returned) where it should have refused, or with wrong or lost
  output;
* **unclear error**: a refusal, but not one line, not the documented status for this cause, or
  worded wrongly;
* **slow**: right, but slower than the case allows (first contact: ``--help``);
* **clear error**: the one-line refusal with the documented status that the case asks for;
* **ok**: a right success;
* **skipped**: the platform does not let the case be set up (e.g. no ``os.mknod``).

It prints a table of counts per outcome, and per class the issue filed the cases under, and
with ``--verbose`` one line per case. Exit status 0 when every case is right or skipped.
"""

from __future__ import annotations

import argparse
import concurrent.futures
import fcntl
import json
import os
import pty
import re
import resource
import shlex
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import termios
import threading
import time
from dataclasses import dataclass
from pathlib import Path

from tests.robustness.cases import CASES
from tests.robustness.model import FILED_AS, Case, Run
from tests.robustness.steps import Context, Fixtures, Unsupported, child_environment, cli_command, make_device
from tests.robustness.watch import changed, snapshot

OUTCOMES = ("input changed", "hang", "traceback", "silent", "unclear error", "slow", "clear error", "ok", "skipped")
BAD = frozenset(OUTCOMES[:6])
DOCUMENTED_STATUSES = frozenset({0, 1, 2, 130})
DEFAULT_BOUND = 40.0
"""Seconds a case may run (times its ``bound_factor``) before it counts as a hang."""

SNIPPET = '''\
import json
def _project_errors():
    from soccer_sim import SoccerSimError
    from formations.errors import FormationError
    from agents.errors import AgentsError
    from experiments.errors import ExperimentError
    return (SoccerSimError, FormationError, AgentsError, ExperimentError)
result = None
try:
{body}
except BaseException as exc:
    outcome = {{"raised": type(exc).__name__, "project": isinstance(exc, _project_errors()), "message": str(exc)[:500]}}
else:
    outcome = {{"raised": None, "result": result}}
print("AUDIT-OUTCOME " + json.dumps(outcome, default=lambda o: o.item() if hasattr(o, "item") else repr(o)))
'''
"""How a Python case's snippet runs: whatever it raises or sets as ``result`` is printed as one line."""


@dataclass
class Verdict:
    case: Case
    outcome: str
    detail: str
    run: Run | None


# ------------------------------------------------------------------------------ running one case
def command_of(case: Case) -> list[str]:
    if case.argv is not None:
        return cli_command(*case.argv)
    if case.shell is not None:
        cli = " ".join(shlex.quote(word) for word in cli_command())
        return ["bash", "-c", case.shell.format(cli=cli)]
    body = "\n".join("    " + line for line in case.python.splitlines())
    return [sys.executable, "-c", SNIPPET.format(body=body)]


def with_disk(case: Case, command: list[str], directory: Path) -> list[str]:
    """``command`` run in a private mount namespace where ``disk`` is a tiny file system,
    filled up (``full``) or mounted read-only (``read-only``)."""
    if case.disk is None:
        return command
    if shutil.which("unshare") is None:
        raise Unsupported("unshare is not installed")
    probe = subprocess.run(["unshare", "-m", "true"], capture_output=True)
    if probe.returncode != 0:
        raise Unsupported(f"unshare -m is not permitted here: {probe.stderr.decode().strip()}")
    disk = directory / "disk"
    disk.mkdir()
    if case.disk == "full":
        prepare = (f"mount -t tmpfs -o size=64k tmpfs {shlex.quote(str(disk))} && "
                   f"(yes > {shlex.quote(str(disk / 'filler'))} 2> {shlex.quote(str(directory / '.fill-log'))}; true)")
    else:
        prepare = f"mount -t tmpfs -o ro,size=64k tmpfs {shlex.quote(str(disk))}"
    script = f"{prepare} && exec {' '.join(shlex.quote(word) for word in command)}"
    return ["unshare", "-m", "--propagation", "private", "sh", "-c", script]


def limit_memory(pid: int, megabytes: int | None) -> None:
    if megabytes is None:
        return
    try:
        limit = megabytes * 1024 * 1024
        resource.prlimit(pid, resource.RLIMIT_AS, (limit, limit))
    except (OSError, ValueError, AttributeError):  # the process is gone already, or no prlimit here
        pass


def kill_group(process: subprocess.Popen) -> None:
    try:
        os.killpg(process.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass


def children_of(pid: int) -> list[int]:
    try:
        return [int(p) for p in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
    except OSError:
        return []


def execute(case: Case, directory: Path, bound: float) -> Run:
    """Run the case's command in ``directory`` and collect what it did."""
    run = Run(directory)
    command = with_disk(case, command_of(case), directory)
    stdout = subprocess.PIPE
    master = None
    if case.stdout_device:
        make_device(directory / f"stdout-{case.stdout_device}", case.stdout_device)
        stdout = open(directory / f"stdout-{case.stdout_device}", "wb")  # noqa: SIM115 - closed below
    elif case.tty_columns:
        master, slave = pty.openpty()
        fcntl.ioctl(slave, termios.TIOCSWINSZ, struct.pack("HHHH", 24, case.tty_columns, 0, 0))
        stdout = slave
    env = child_environment()
    if case.tty_columns:
        env.update(COLUMNS=str(case.tty_columns), LINES="24", TERM="xterm")
    started = time.monotonic()
    process = subprocess.Popen(command, cwd=directory, env=env, stdin=subprocess.DEVNULL, stdout=stdout,
                               stderr=subprocess.PIPE, start_new_session=True)
    limit_memory(process.pid, case.memory_mb)
    captured: list[bytes] = []
    reader = None
    if master is not None:
        os.close(stdout)
        reader = threading.Thread(target=_read_all, args=(master, captured), daemon=True)
        reader.start()
    elif case.stdout_device:
        stdout.close()
    try:
        if case.kill_parent_after_workers:
            _kill_parent_once_it_has_workers(process, started, bound)
        out, err = process.communicate(timeout=max(0.1, bound - (time.monotonic() - started)))
        run.status = process.returncode
    except subprocess.TimeoutExpired:
        run.timed_out = True
        kill_group(process)
        try:
            out, err = process.communicate(timeout=10)
        except subprocess.TimeoutExpired:  # something outside the group holds the pipes
            out, err = b"", b""
    finally:
        kill_group(process)  # leave nothing of the case behind
    run.seconds = time.monotonic() - started
    if reader is not None:
        reader.join(timeout=5)
        out = b"".join(captured)
    run.stdout = (out or b"").decode("utf-8", "replace")
    run.stderr = (err or b"").decode("utf-8", "replace")
    if case.python is not None:
        lines = [line for line in run.stdout.splitlines() if line.startswith("AUDIT-OUTCOME ")]
        run.outcome = json.loads(lines[-1].removeprefix("AUDIT-OUTCOME ")) if lines else None
    return run


def _read_all(fd: int, into: list[bytes]) -> None:
    while True:
        try:
            chunk = os.read(fd, 65536)
        except OSError:  # EIO: the terminal's last writer is gone
            break
        if not chunk:
            break
        into.append(chunk)
    os.close(fd)


def _kill_parent_once_it_has_workers(process: subprocess.Popen, started: float, bound: float) -> None:
    """SIGKILL the command's first process (only it) once it has had worker processes for two
    seconds; its workers are then on their own."""
    deadline = started + bound / 2
    while time.monotonic() < deadline and process.poll() is None:
        if len(children_of(process.pid)) >= 1:
            time.sleep(2)
            break
        time.sleep(0.2)
    if process.poll() is None:
        os.kill(process.pid, signal.SIGKILL)


# ------------------------------------------------------------------------------ judging a run
TRACEBACK = re.compile(r"Traceback \(most recent call last\)|^error: unexpected ", re.M)


def classify(case: Case, run: Run) -> tuple[str, str]:
    """The outcome class of ``run`` and a few words on why."""
    expect = case.expect
    first = next(iter(run.error_lines), "")
    if run.changed:
        return "input changed", f"changed or replaced: {', '.join(run.changed)}"
    if run.timed_out:
        return "hang", f"still running after {run.seconds:.0f} s"
    if TRACEBACK.search(run.stderr):
        line = next((l for l in reversed(run.error_lines) if l.strip() and not l.startswith(" ")), first)
        return "traceback", line[:160]
    if case.kill_parent_after_workers:
        return "ok", "the workers exited quietly"
    if case.python is not None:
        return _classify_snippet(case, run)
    if run.status is None or run.status not in DOCUMENTED_STATUSES:
        return "traceback", f"exit status {run.status}; {first[:120]}"
    if expect.within is not None and run.seconds > expect.within:
        return "slow", f"{run.seconds:.2f} s (at most {expect.within} s)"
    if run.status == 0:
        if expect.success is None:
            return "silent", f"exit 0 where a refusal was due; stdout {run.stdout.strip()[-100:]!r}"
        reason = expect.success(run) or (expect.always(run) if expect.always else None)
        return ("silent", reason) if reason else ("ok", "exit 0")
    if len(run.error_lines) != 1 or not first.startswith("error: "):
        return "unclear error", f"exit {run.status}, {len(run.error_lines)} stderr lines: {run.stderr.strip()[:140]!r}"
    if run.status not in expect.errors:
        wanted = "/".join(map(str, sorted(expect.errors))) or "0"
        return "unclear error", f"exit {run.status} (expected {wanted}): {first[:120]}"
    for check in (expect.message, expect.always):
        reason = check(run) if check else None
        if reason:
            return "unclear error", f"{reason}: {first[:120]}"
    return "clear error", f"exit {run.status}: {first[:120]}"


def _classify_snippet(case: Case, run: Run) -> tuple[str, str]:
    outcome, expect = run.outcome, case.expect
    if outcome is None:
        return "traceback", f"the snippet died (exit {run.status}): {run.stderr.strip()[-140:]!r}"
    if outcome["raised"]:
        said = f"{outcome['raised']}: {outcome['message'][:120]}"
        if not outcome["project"]:
            return "traceback", said
        if not expect.errors:
            return "unclear error", f"raised where it should succeed: {said}"
        reason = expect.message(run) if expect.message else None
        return ("unclear error", f"{reason}: {said}") if reason else ("clear error", said)
    if expect.success is None:
        return "silent", f"returned {outcome['result']!r} where a refusal was due"
    reason = expect.success(run)
    return ("silent", reason) if reason else ("ok", f"returned {outcome['result']!r}")


def audit_case(case: Case, fixtures: Fixtures, bound: float) -> Verdict:
    directory = Path(tempfile.mkdtemp(prefix="audit-"))
    context = Context(directory, fixtures, [])
    try:
        try:
            for step in case.setup:
                step.make(context)
            before = snapshot(directory, case.writes)
            run = execute(case, directory, bound * case.bound_factor)
        except Unsupported as exc:
            return Verdict(case, "skipped", str(exc), None)
        run.changed = changed(before, directory, case.writes)
        outcome, detail = classify(case, run)
        return Verdict(case, outcome, f"{detail} [{run.seconds:.1f} s]", run)
    finally:
        for undo in context.cleanups:
            undo()
        shutil.rmtree(directory, ignore_errors=True)


# ------------------------------------------------------------------------------ the report
def table(verdicts: list[Verdict]) -> str:
    filed = [name for name in FILED_AS if any(v.case.filed_as == name for v in verdicts)]
    header = ["outcome", "total", *filed]
    rows = [[outcome, sum(v.outcome == outcome for v in verdicts),
             *(sum(v.outcome == outcome and v.case.filed_as == name for v in verdicts) for name in filed)]
            for outcome in OUTCOMES]
    rows.append(["all", len(verdicts), *(sum(v.case.filed_as == name for v in verdicts) for name in filed)])
    widths = [max(len(str(row[i])) for row in [header, *rows]) for i in range(len(header))]
    lines = ["  ".join(str(cell).rjust(width) if i else str(cell).ljust(width) for i, (cell, width)
                       in enumerate(zip(row, widths))) for row in [header, *rows]]
    lines.insert(1, "-" * len(lines[0]))
    lines.insert(len(lines) - 1, "-" * len(lines[0]))
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m tests.robustness.audit", description=__doc__.split("\n\n")[0])
    parser.add_argument("--only", choices=[name.replace(" ", "-") for name in FILED_AS],
                        help="only the cases filed under this class")
    parser.add_argument("--case", default="", help="only the cases whose name contains this text")
    parser.add_argument("--timeout", type=float, default=DEFAULT_BOUND,
                        help=f"seconds before a case counts as a hang (default {DEFAULT_BOUND:g})")
    parser.add_argument("--jobs", type=int, default=1, help="cases run at once (default 1)")
    parser.add_argument("--verbose", "-v", action="store_true", help="one line per case")
    parser.add_argument("--list", action="store_true", help="list the cases and exit")
    args = parser.parse_args(argv)
    cases = [c for c in CASES if (args.only is None or c.filed_as == args.only.replace("-", " "))
             and args.case.lower() in c.name.lower()]
    if args.list:
        for case in cases:
            print(f"{case.filed_as:14}  {case.name}")
        return 0
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="audit-fixtures-") as root:
        fixtures = Fixtures(Path(root))
        lock = threading.Lock()

        def one(case: Case) -> Verdict:
            verdict = audit_case(case, fixtures, args.timeout)
            if args.verbose:
                with lock:
                    print(f"{verdict.outcome:13}  {case.filed_as:13}  {case.name}: {verdict.detail}", flush=True)
            return verdict

        for name in sorted({name for case in cases for step in case.setup for name in step.needs}):
            try:  # made once, before the cases run side by side
                fixtures.path(name)
            except Unsupported as exc:
                print(f"warning: {exc}", file=sys.stderr)
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            verdicts = list(pool.map(one, cases))
    print(table(verdicts))
    print(f"{len(verdicts)} cases in {time.monotonic() - started:.0f} s (bound {args.timeout:g} s a case, "
          f"{args.jobs} at a time)")
    return 1 if any(v.outcome in BAD for v in verdicts) else 0


if __name__ == "__main__":
    sys.exit(main())
