"""``soccer-sim results export FILE --csv OUT.csv | --parquet OUT.parquet`` and
``soccer-sim results show FILE``: a stored run's matches as a flat table, or its tables again.

``show`` prints the same tables as the command that made the file (``tournament``,
``experiment case-study``, ``experiment transfer`` (one engine's half), ``experiment ablation``, ``experiment drop-in``, ``experiment assigners``,
``experiment penalty-shot``), from the stored
matches alone.

Both only read the results file: it is opened read-only and never changed (so they work on
read-only media too), and an output that would land on it is refused. Exit status 2 for bad
input (with a one-line message), 1 when an output cannot be written (nothing partial is left).
"""

from __future__ import annotations

import argparse

from experiments.commands import add_json_option, table_command
from experiments.commands.errors import fail as _fail

#: Kind stored in a results file -> the module that made it (``build_specs``, ``report``).
REPORTERS: dict[str, str] = {
    "tournament": "experiments.commands.tournament",
    "evaluation": "experiments.commands.evaluate",
    "case-study": "experiments.studies.case_study",
    "transfer": "experiments.studies.transfer",
    "ablation": "experiments.studies.ablation",
    "drop-in": "experiments.studies.drop_in",
    "assigners": "experiments.studies.assigners",
    "penalty-shot": "experiments.studies.penalty_shot",
}


def register(subparsers: argparse._SubParsersAction) -> None:
    parser = subparsers.add_parser("results", help="export or show a stored run (SQLite results file)")
    sub = parser.add_subparsers(dest="action", metavar="ACTION", required=True)
    export = sub.add_parser("export", help="write one row per match as CSV or Parquet")
    export.add_argument("file", metavar="FILE", help="results file (e.g. results.sqlite)")
    target = export.add_mutually_exclusive_group(required=True)
    target.add_argument("--csv", metavar="OUT.csv", help="write CSV (- for standard output)")
    target.add_argument("--parquet", metavar="OUT.parquet", help="write Parquet (needs pyarrow: the 'parquet' extra)")
    export.set_defaults(func=run_export)
    show = sub.add_parser("show", help="print the tables of a stored run")
    show.add_argument("file", metavar="FILE", help="results file (e.g. results.sqlite)")
    show.add_argument("--tables", metavar="DIR", default=None, help="also write the CSV/Markdown tables and PNG here")
    add_json_option(show)
    show.set_defaults(func=table_command(run_show))


def run_export(args: argparse.Namespace) -> int:
    from pathlib import Path

    from experiments.results.export import ExportError, export_csv, export_parquet, parquet_library
    from experiments.results.files import describe, file_problem, is_standard_output
    from experiments.results.store import ResultsError, ResultStore

    option, out = ("--csv", args.csv) if args.csv is not None else ("--parquet", args.parquet)
    problem = file_problem(out, inputs=[args.file], standard_output=option == "--csv")
    if problem:
        return _fail(f"{option} {out}: {problem}")
    try:
        if args.parquet:
            parquet_library()
        with ResultStore.open(args.file) as store:
            records = store.records()
    except (ResultsError, ExportError) as exc:
        return _fail(str(exc))
    try:
        path = export_csv(records, Path(out)) if option == "--csv" else export_parquet(records, Path(out))
    except BrokenPipeError:
        raise                                # the reader of stdout went away: not an error
    except OSError as exc:
        return _fail(f"{option}: cannot write {describe(exc)}; nothing was written", 1)
    if not is_standard_output(out):          # standard output carries the CSV alone
        print(f"wrote {path}: {len(records)} matches")
    return 0


def run_show(args: argparse.Namespace) -> int:
    import importlib
    from pathlib import Path

    from experiments.results.files import describe, directory_problem
    from experiments.results.store import ResultsError, ResultStore

    out_dir = Path(args.tables) if args.tables else None
    problem = directory_problem(out_dir) if out_dir is not None else None
    if problem:
        return _fail(f"--tables {out_dir}: {problem}")
    try:
        with ResultStore.open(args.file) as store:
            kind, params, records, meta = store.kind, store.params, store.records(), store.meta()
    except ResultsError as exc:
        return _fail(str(exc))
    if kind not in REPORTERS:
        return _fail(f"{args.file}: made by an unknown command {kind!r}; known: {', '.join(REPORTERS)}")
    module = importlib.import_module(REPORTERS[kind])
    try:
        wanted = {spec.key for spec in module.build_specs(params)}
    except (KeyError, TypeError, ValueError, AttributeError) as exc:  # parameters edited by hand or damaged
        return _fail(f"{args.file}: damaged results file, its stored parameters do not describe a {kind} run "
                     f"({type(exc).__name__}: {exc})")
    mine = [r for r in records if r.key in wanted]
    failed = sum(not r.played for r in mine)
    versions = ", ".join(sorted({r.code_version for r in mine})) or "-"
    _print_note(f"{args.file}: {kind}, {len(mine)} of {len(wanted)} matches stored ({failed} failed), "
                f"configuration {meta.get('config_hash')}, code {versions}")
    try:
        if out_dir is not None:
            out_dir.mkdir(parents=True, exist_ok=True)
        module.report(mine, params, out_dir)
    except BrokenPipeError:
        raise                                # the reader of stdout went away: not a --tables problem
    except OSError as exc:
        return _fail(f"--tables {out_dir}: cannot write {describe(exc)}", 1)
    return 0


def _print_note(text: str) -> None:
    """One line of text; on a terminal wrapped to its width (piped: one line, as scripts read it)."""
    import shutil
    import sys
    import textwrap

    if sys.stdout.isatty():
        text = textwrap.fill(text, width=shutil.get_terminal_size().columns, subsequent_indent="  ")
    print(text)
