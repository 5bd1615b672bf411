"""The shape of a robustness-audit case and of the checks that say what its right outcome is.

A :class:`Case` is data: a name, the class of failure the issue filed it under, the steps that
set up its directory, the command (``argv`` for ``soccer-sim``, a shell line, or a Python
snippet) and an :class:`Expect` saying which outcomes are right. The runner
(:mod:`tests.robustness.audit`) turns what happened (a :class:`Run`) into one outcome class.
"""

from __future__ import annotations

import json
import re
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from tests.robustness.steps import Step

FILED_AS = ("input changed", "special file", "hang", "traceback", "silent", "first contact", "control")
"""The issue's classes a case can be filed under (``control``: valid runs that must stay right)."""


@dataclass
class Run:
    """What one case did."""

    dir: Path
    status: int | None = None
    """Exit status (negative: killed by that signal); None when it was stopped at the bound."""
    stdout: str = ""
    stderr: str = ""
    seconds: float = 0.0
    timed_out: bool = False
    changed: list[str] = field(default_factory=list)
    """Set-up files whose bytes changed, or special files replaced, removed or changed in kind."""
    outcome: dict | None = None
    """For a Python snippet: what it raised or returned."""

    @property
    def error_lines(self) -> list[str]:
        return self.stderr.splitlines()


Check = Callable[[Run], "str | None"]
"""A check returns None when the run is right, else why it is not."""


@dataclass(frozen=True)
class Expect:
    """The right outcomes of a case.

    ``errors``: the exit statuses of a right refusal (for a Python snippet: any non-empty set
    means raising one of the project's errors is right); ``success``: the check an exit-0 run
    (a snippet that returns) must pass, None when succeeding is wrong; ``message``: a check of
    the error line (or the exception's message); ``within``: seconds the run may take at most.
    """

    errors: frozenset[int] = frozenset()
    success: Check | None = None
    message: Check | None = None
    always: Check | None = None
    """A check every finished run must pass, error or not (e.g. nothing played before a refusal)."""
    within: float | None = None


def refused(*statuses: int, says: Check | None = None, always: Check | None = None) -> Expect:
    """The command must refuse: one ``error:`` line and one of ``statuses`` (default 2, bad input)."""
    return Expect(errors=frozenset(statuses or (2,)), message=says, always=always)


def fails(says: Check | None = None) -> Expect:
    """The run started and must fail: one ``error:`` line, status 1."""
    return Expect(errors=frozenset({1}), message=says)


def succeeds(check: Check | None = None, within: float | None = None) -> Expect:
    """The command must succeed (exit 0) and pass ``check``."""
    return Expect(success=check or nothing_more, within=within)


def refused_or_succeeds(check: Check, *statuses: int) -> Expect:
    """Either a one-line refusal or a success that passes ``check``."""
    return Expect(errors=frozenset(statuses or (2,)), success=check)


@dataclass(frozen=True)
class Case:
    """One input of the audit.

    Exactly one of ``argv`` (``soccer-sim`` arguments), ``shell`` (an ``sh -c`` line in which
    ``{cli}`` is the ``soccer-sim`` command) or ``python`` (a snippet that sets ``result``) is
    given. Every file the steps make is watched (bytes of regular files; kind, inode and device
    number of the others) except those named in ``writes``.
    """

    name: str
    filed_as: str
    expect: Expect
    argv: tuple[str, ...] | None = None
    shell: str | None = None
    python: str | None = None
    setup: tuple[Step, ...] = ()
    writes: tuple[str, ...] = ()
    disk: str | None = None
    """``full``: the directory ``disk`` is a private file system with no space left;
    ``read-only``: a private read-only one (both need ``unshare -m``)."""
    stdout_device: str | None = None
    """Standard output is a private device node of this kind (``full``: a full disk)."""
    tty_columns: int | None = None
    """Standard output is a terminal this many columns wide."""
    kill_parent_after_workers: bool = False
    """Kill the command's first process once it has child processes, then watch its workers."""
    bound_factor: float = 1.0
    memory_mb: int | None = 4096
    """Address-space limit of the command's processes (None: none, e.g. for Ray)."""

    def __post_init__(self) -> None:
        assert self.filed_as in FILED_AS, self.filed_as
        assert sum(x is not None for x in (self.argv, self.shell, self.python)) == 1, self.name


# ------------------------------------------------------------------------------ checks
def nothing_more(run: Run) -> str | None:
    return None


def all_of(*checks: Check) -> Check:
    def check(run: Run) -> str | None:
        return next((reason for reason in (c(run) for c in checks) if reason), None)

    return check


def no_file(name: str) -> Check:
    """``name`` was not created in the case directory."""
    return lambda run: f"{name!r} was created" if (run.dir / name).exists() or (run.dir / name).is_symlink() else None


def new_png_in(directory: str) -> Check:
    """A PNG was written inside ``directory``."""
    def check(run: Run) -> str | None:
        return None if any((run.dir / directory).glob("*.png")) else f"no PNG inside {directory}/"

    return check


def stdout_is_json(run: Run) -> str | None:
    try:
        json.loads(run.stdout)
    except ValueError as exc:
        return f"stdout is not one JSON object ({exc}); starts {run.stdout[:60]!r}"
    return None


BOX = re.compile("[\u2500-\u257f]")


def plain_tables(run: Run) -> str | None:
    """Piped output carries no box-drawing characters."""
    return "box-drawing characters in piped output" if BOX.search(run.stdout) else None


def stdout_has(text: str) -> Check:
    return lambda run: None if text in run.stdout else f"{text!r} not on stdout"


def stdout_lacks(pattern: str) -> Check:
    return lambda run: f"stdout says {pattern!r}" if re.search(pattern, run.stdout) else None


def width_at_most(columns: int) -> Check:
    """The printed lines fit ``columns`` columns on the terminal (colour and style escapes take none)."""
    def check(run: Run) -> str | None:
        shown = re.sub(r"\x1b\[[0-9;?]*[A-Za-z]", "", run.stdout)
        widest = max((len(line.rstrip("\r")) for line in shown.splitlines()), default=0)
        return f"a line {widest} columns wide" if widest > columns else None

    return check


def line_at_most(chars: int) -> Check:
    def check(run: Run) -> str | None:
        text = message_of(run)
        return f"the error is {len(text)} characters long" if len(text) > chars else None

    return check


def says(pattern: str) -> Check:
    return lambda run: None if re.search(pattern, message_of(run), re.I) else f"the error does not say {pattern!r}"


def never_says(pattern: str) -> Check:
    return lambda run: f"the error says {pattern!r}" if re.search(pattern, message_of(run), re.I) else None


def no_escape(run: Run) -> str | None:
    return "the error carries raw escape characters" if "\x1b" in message_of(run) else None


def result_is(predicate: Callable[[object], bool], what: str) -> Check:
    """A Python snippet's ``result`` passes ``predicate``."""
    def check(run: Run) -> str | None:
        value = (run.outcome or {}).get("result")
        return None if predicate(value) else f"returned {value!r}, expected {what}"

    return check


def message_of(run: Run) -> str:
    """The error a run gave: its exception's message (snippets), else its stderr."""
    if run.outcome is not None and run.outcome.get("raised"):
        return str(run.outcome.get("message", ""))
    return run.stderr.strip()
