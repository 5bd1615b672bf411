"""Tables of a run, three ways: printed with rich, as CSV and as Markdown (same rows)."""

from __future__ import annotations

import csv
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path


ESTIMATE_COLUMNS = ["mean_gd", "se", "ci95_low", "ci95_high"]
"""CSV columns of a goal-difference estimate (:class:`experiments.stats.Estimate`)."""


@dataclass
class Table:
    """A titled table of text cells; the leading ``labels`` columns are labels."""

    title: str
    header: list[str]
    rows: list[list[str]] = field(default_factory=list)
    labels: int = 1
    """Leading label columns (left-aligned; the rest are right-aligned numbers)."""

    def print(self, console=None) -> None:
        from rich.console import Console
        from rich.markup import escape
        from rich.table import Table as RichTable

        table = RichTable(title=escape(self.title))
        for i, name in enumerate(self.header):
            # A label (a team's module:Attribute path) wraps rather than losing its end to "…".
            table.add_column(escape(name), justify="left" if i < self.labels else "right",
                             overflow="fold" if i < self.labels else "ellipsis")
        for row in self.rows:
            table.add_row(*(escape(cell) for cell in row))
        (console or Console()).print(table)

    def markdown(self) -> str:
        def line(cells: Sequence[str]) -> str:
            return "| " + " | ".join(cell.replace("|", "\\|") for cell in cells) + " |"

        return "\n".join([f"**{self.title}**", "", line(self.header),
                          line(["---"] * len(self.header)), *(line(row) for row in self.rows), ""])


def write_csv(path: Path, header: Sequence[str], rows: Sequence[Sequence[object]]) -> Path:
    """One CSV file with a header row (numbers as Python prints them)."""
    with open(path, "w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(header)
        writer.writerows(rows)
    return path


def write_markdown(path: Path, tables: Sequence[Table], preface: str = "") -> Path:
    path.write_text((preface + "\n\n" if preface else "") + "\n".join(t.markdown() for t in tables))
    return path
