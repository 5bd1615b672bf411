"""Progress of a run: a live bar on a terminal, a few quiet lines otherwise (logs, pipes, CI)."""

from __future__ import annotations

import sys
import time
from typing import TextIO

QUIET_EVERY_SECONDS = 30.0
"""When not on a terminal, a line at least this often (and at every tenth of the run)."""


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
