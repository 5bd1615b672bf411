"""Tables of a run: printed for a person or a script, as CSV and as Markdown (same rows).

:meth:`Table.print` is the one table printer of the command line. On a terminal it draws
the table with rich. Anywhere else (a pipe, a file) it prints it plain, one line per row
with the cells separated by tabs and never wrapped, under a ``# title`` line, so that
``soccer-sim bench roles | cut -f1,2`` or a CSV reader with a tab delimiter reads it. A
command run with ``--json`` (see :func:`json_output`) prints instead one JSON object holding
every table it made and its other lines of output.
"""

from __future__ import annotations

import contextlib
import csv
import io
import json
import re
import sys
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path


ESTIMATE_COLUMNS = ["mean_gd", "se", "ci95_low", "ci95_high"]
"""CSV columns of a goal-difference estimate (:class:`experiments.stats.Estimate`)."""

_collected: list[Table] | None = None
"""While a command runs with ``--json``: the tables it printed, in order."""


@dataclass
class Table:
    """A titled table of text cells; the leading ``labels`` columns are labels."""

    title: str
    header: list[str]
    rows: list[list[str]] = field(default_factory=list)
    labels: int = 1
    """Leading label columns (left-aligned; the rest are right-aligned numbers)."""
    caption: str = ""
    """A note printed under the table."""

    def print(self, console=None) -> None:
        """Print the table: drawn on a terminal, plain text elsewhere (see the module's
        docstring), or kept for the JSON document when the command runs with ``--json``."""
        if _collected is not None:
            _collected.append(self)
            return
        from rich.console import Console

        console = console or Console()
        if console.is_terminal or console.is_jupyter:
            console.print(self._fitting(console))
        else:
            console.file.write(self.plain())

    def _fitting(self, console):
        """The boxed table, or the compact one where only that fits the console's width
        without wrapping a cell (where neither fits, the boxed one, whose labels fold)."""
        unlimited = console.options.update(max_width=1_000_000)
        boxed = self.rich()
        if console.measure(boxed, options=unlimited).maximum <= console.width:
            return boxed
        compact = self.rich(compact=True)
        return compact if console.measure(compact, options=unlimited).maximum <= console.width else boxed

    def rich(self, compact: bool = False):
        """The table as a rich renderable (labels fold rather than lose their end to "…");
        ``compact``: without vertical rules or outer edge, a rule under the header only (some
        20 columns narrower for a table of ten columns: what a terminal of 80 columns gets
        when the boxed table would not fit)."""
        from rich import box
        from rich.markup import escape
        from rich.table import Table as RichTable

        layout = dict(box=box.SIMPLE_HEAD, show_edge=False, pad_edge=False, collapse_padding=True) if compact else {}
        table = RichTable(title=escape(self.title), caption=escape(self.caption) or None, **layout)
        for i, name in enumerate(self.header):
            table.add_column(escape(name), justify="left" if i < self.labels else "right",
                             overflow="fold" if i < self.labels else "ellipsis")
        for row in self.rows:
            table.add_row(*(escape(cell) for cell in row))
        return table

    def plain(self) -> str:
        """``# title``, the header and one line per row, cells separated by tabs (a tab or line
        break inside a cell becomes a space), ``# caption`` and a blank line."""
        def line(cells: Sequence[str]) -> str:
            return "\t".join(_flat(cell) for cell in cells)

        lines = [f"# {_flat(self.title)}", line(self.header), *(line(row) for row in self.rows)]
        if self.caption:
            lines.append(f"# {_flat(self.caption)}")
        return "\n".join(lines) + "\n\n"

    def as_dict(self) -> dict[str, object]:
        """The table for JSON: title, columns and rows (a cell that is a plain number becomes a
        number, every other cell stays the text printed)."""
        data: dict[str, object] = {"title": self.title, "columns": list(self.header),
                                   "rows": [[_json_cell(cell) for cell in row] for row in self.rows]}
        if self.caption:
            data["caption"] = self.caption
        return data

    def markdown(self) -> str:
        def line(cells: Sequence[str]) -> str:
            return "| " + " | ".join(cell.replace("|", "\\|") for cell in cells) + " |"

        caption = [f"{self.caption}", ""] if self.caption else []
        return "\n".join([f"**{self.title}**", "", line(self.header),
                          line(["---"] * len(self.header)), *(line(row) for row in self.rows), "", *caption])


def _flat(text: str) -> str:
    return re.sub(r"[\t\r\n]+", " ", str(text))


_INT = re.compile(r"[+-]?\d+")
_FLOAT = re.compile(r"[+-]?(\d+\.\d*|\.\d+|\d+)([eE][+-]?\d+)?")


def _json_cell(text: str) -> object:
    if _INT.fullmatch(text):
        return int(text)
    if _FLOAT.fullmatch(text):
        return float(text)
    return text


@contextlib.contextmanager
def collecting_tables() -> Iterator[list[Table]]:
    """Within the block, :meth:`Table.print` keeps each table in the list yielded instead of
    printing it."""
    global _collected
    previous, _collected = _collected, []
    try:
        yield _collected
    finally:
        _collected = previous


def json_output(run: Callable[[], int]) -> int:
    """Run a command (``run()`` returns its exit status) with its output as one JSON object on
    stdout: ``{"tables": [...], "notes": [...]}``, the tables it printed (:meth:`Table.as_dict`)
    and the other lines it printed to stdout. Errors still go to stderr; a command that fails
    prints what it printed, unchanged, and no JSON."""
    buffer = io.StringIO()
    with collecting_tables() as tables, contextlib.redirect_stdout(buffer):
        status = run()
    if status != 0:
        sys.stdout.write(buffer.getvalue())
        return status
    notes = [line.rstrip() for line in buffer.getvalue().splitlines() if line.strip()]
    print(json.dumps({"tables": [table.as_dict() for table in tables], "notes": notes}, indent=2))
    return status


def write_csv(path: Path, header: Sequence[str], rows: Sequence[Sequence[object]]) -> Path:
    """One CSV file with a header row (numbers as Python prints them), written whole or not at
    all (:func:`~experiments.results.files.atomic_output`: a full disk leaves no partial file)."""
    from experiments.results.files import atomic_output

    with atomic_output(path) as temporary, open(temporary, "w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        writer.writerows(rows)
    return path


def write_markdown(path: Path, tables: Sequence[Table], preface: str = "") -> Path:
    """The tables as Markdown, written whole or not at all (as :func:`write_csv`)."""
    from experiments.results.files import atomic_output

    with atomic_output(path) as temporary:
        temporary.write_text((preface + "\n\n" if preface else "") + "\n".join(t.markdown() for t in tables))
    return path
