"""Exporting a results file: one row per match, every team statistic in its own column
(``home_goals``, ``away_teammate_contacts``, ``home_role_switches_per_minute``, ...)."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from experiments.errors import ExperimentError
from experiments.results.files import atomic_output, text_output
from experiments.results.record import MatchRecord

BASE_COLUMNS = ("home", "away", "seed", "config_hash", "code_version", "home_goals", "away_goals", "cycles",
                "wall_time", "error", "forfeit", "traceback")


class ExportError(ExperimentError):
    """An export cannot be made (a missing optional dependency)."""


def flat_rows(records: Sequence[MatchRecord]) -> tuple[list[str], list[dict[str, object]]]:
    """(columns, rows): the base columns, then ``home_X``/``away_X`` for every statistic X any
    match has (missing ones are None)."""
    figures = sorted({key for r in records for key in (*r.home_stats, *r.away_stats)} - {"goals"})
    columns = [*BASE_COLUMNS, *(f"{side}_{name}" for name in figures for side in ("home", "away"))]
    rows = []
    for record in records:
        row: dict[str, object] = {name: getattr(record, name) for name in BASE_COLUMNS}
        for name in figures:
            row[f"home_{name}"] = record.home_stats.get(name)
            row[f"away_{name}"] = record.away_stats.get(name)
        rows.append(row)
    return columns, rows


def export_csv(records: Sequence[MatchRecord], path: Path) -> Path:
    """Write ``records`` to ``path`` as CSV, whole or not at all (OSError naming ``path``);
    ``-`` (or ``/dev/stdout``) writes it to standard output."""
    import csv

    columns, rows = flat_rows(records)
    with text_output(path, newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=columns)
        writer.writeheader()
        writer.writerows(rows)
    return path


def parquet_library():
    """(pyarrow, pyarrow.parquet), or ExportError saying how to install them."""
    try:
        import pyarrow as pa
        import pyarrow.parquet as pq
    except ImportError:
        raise ExportError("Parquet export needs pyarrow: pip install 'soccer-sim[parquet]' (or pip install pyarrow); "
                          "CSV export needs nothing extra") from None
    return pa, pq


def export_parquet(records: Sequence[MatchRecord], path: Path) -> Path:
    """Parquet through pyarrow (the optional ``parquet`` extra), whole or not at all."""
    pa, pq = parquet_library()
    columns, rows = flat_rows(records)
    table = pa.Table.from_pylist(rows, schema=_schema(pa, columns, rows))
    with atomic_output(path) as temporary:
        pq.write_table(table, str(temporary))
    return path


def _schema(pa, columns: list[str], rows: list[dict[str, object]]):
    """Explicit column types, so an all-None column (no failures) still has one."""
    text = {"home", "away", "config_hash", "code_version", "error", "traceback"}
    integer = {"seed", "home_goals", "away_goals", "cycles", "forfeit"}
    return pa.schema([(name, pa.string() if name in text else pa.int64() if name in integer else pa.float64())
                      for name in columns])
