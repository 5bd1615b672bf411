"""Progress of a run: a live bar on a terminal, a few quiet lines otherwise (logs, pipes, CI)."""

from __future__ import annotations

import sys
import time
from typing import TextIO

QUIET_EVERY_SECONDS = 30.0
"""When not on a terminal, a line at least this often (and at every tenth of the run)."""

COUNT_EVERY_SECONDS = 10.0
"""When not on a terminal, a line of :class:`CountProgress` at least this often (and at every
tenth of the count)."""


class RunProgress:
    """Counts finished matches and failures; shows done/total, rate, ETA and errors (and how
    many of them no team is blamed for: those matches are missing from the tables)."""

    def __init__(self, total: int, label: str, stream: TextIO | None = None, enabled: bool = True) -> None:
        self.total, self.label = total, label
        self.stream = stream if stream is not None else sys.stderr
        self.enabled = enabled and total > 0
        self.done = self.errors = self.unblamed = 0
        self._start = time.monotonic()
        self._live = None
        self._last_line = self._start
        self._last_tenth = 0

    def __enter__(self) -> RunProgress:
        if self.enabled and self.stream.isatty():
            from rich.console import Console
            from rich.progress import (BarColumn, MofNCompleteColumn, Progress, TextColumn, TimeElapsedColumn,
                                       TimeRemainingColumn)

            self._live = Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                                  TextColumn("{task.fields[rate]}"), TextColumn("ETA"), TimeRemainingColumn(),
                                  TimeElapsedColumn(), TextColumn("{task.fields[errors]}"),
                                  console=Console(file=self.stream), transient=False)
            self._live.start()
            self._task = self._live.add_task(self.label, total=self.total, rate="", errors="0 errors")
        return self

    def advance(self, failed: bool = False, unblamed: bool = False) -> None:
        """One more match finished; ``failed``: not played to its end; ``unblamed``: failed
        with no team at fault."""
        self.done += 1
        self.errors += int(failed)
        self.unblamed += int(unblamed)
        if not self.enabled:
            return
        elapsed = max(time.monotonic() - self._start, 1e-9)
        rate = self.done / elapsed
        if self._live is not None:
            self._live.update(self._task, advance=1, rate=f"{rate * 60:.1f} matches/min",
                              errors=f"[red]{self._errors_text()}[/red]" if self.errors else "0 errors")
            return
        tenth = 10 * self.done // self.total
        now = time.monotonic()
        if tenth > self._last_tenth or now - self._last_line >= QUIET_EVERY_SECONDS or self.done == self.total:
            self._last_tenth, self._last_line = tenth, now
            eta = (self.total - self.done) / rate
            print(f"{self.label}: {self.done}/{self.total} matches, {rate * 60:.1f}/min, ETA {eta:.0f} s, "
                  f"{self._errors_text()}", file=self.stream, flush=True)

    def _errors_text(self) -> str:
        unblamed = f" ({self.unblamed} with no team at fault)" if self.unblamed else ""
        return f"{self.errors} errors{unblamed}"

    def __exit__(self, *exc) -> None:
        if self._live is not None:
            self._live.stop()


class CountProgress:
    """Progress of work counted in like pieces that is done out of sight (compiling kernels in
    helper processes): ``label: done/total unit, S s``. On a terminal one line rewritten in
    place at every :meth:`show`; elsewhere (a log, a pipe) a line at every tenth of the count,
    at least every :data:`COUNT_EVERY_SECONDS` while nothing changes, and at the end."""

    def __init__(self, total: int, label: str, unit: str, stream: TextIO | None = None) -> None:
        self.total, self.label, self.unit = total, label, unit
        self.stream = stream if stream is not None else sys.stderr
        self._live = _is_terminal(self.stream)
        self._start = self._last_line = time.monotonic()
        self._last_tenth = 0
        self._shown = -1

    def text(self, done: int) -> str:
        """The progress line for ``done`` pieces, with the seconds elapsed since the start."""
        return f"{self.label}: {done}/{self.total} {self.unit}, {time.monotonic() - self._start:.0f} s"

    def show(self, done: int) -> None:
        """Report that ``done`` of the pieces are finished (called as often as wanted)."""
        now = time.monotonic()
        if self._live:
            self.stream.write("\r" + self.text(done))
            self.stream.flush()
            self._shown = done
            return
        tenth = 10 * done // max(self.total, 1)
        if tenth > self._last_tenth or now - self._last_line >= COUNT_EVERY_SECONDS:
            self._last_tenth, self._last_line, self._shown = tenth, now, done
            print(self.text(done), file=self.stream, flush=True)

    def close(self, done: int) -> None:
        """The last report: the final count (unless just shown), and the end of the live line."""
        if self._live:
            self.show(done)
            self.stream.write("\n")
            self.stream.flush()
        elif done != self._shown:
            self._shown = done
            print(self.text(done), file=self.stream, flush=True)


def _is_terminal(stream: TextIO) -> bool:
    isatty = getattr(stream, "isatty", None)
    try:
        return bool(isatty and isatty())
    except ValueError:  # a closed stream
        return False
