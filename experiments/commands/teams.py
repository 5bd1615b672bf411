"""``soccer-sim teams``: the registered team names, each with the ``module:attribute`` that makes
it. Any of them (or a ``package.module:Attribute`` path) can be given to ``play``,
``tournament`` and the studies. A team is registered by the Python entry-point group
``soccer_sim.teams`` of any installed package; the built-in ones are declared in
pyproject.toml."""

from __future__ import annotations

import argparse

from experiments.commands import add_json_option, doc_summary, table_command


def register(subparsers: argparse._SubParsersAction) -> None:
    parser = subparsers.add_parser("teams", help="list the registered team names",
                                   description=doc_summary(__doc__))
    add_json_option(parser)
    parser.set_defaults(func=table_command(run))


def run(args: argparse.Namespace) -> int:
    """Print the registered teams as a table (plain when piped)."""
    from experiments.reporting import Table
    from soccer_sim import available_teams

    teams = available_teams()
    table = Table(f"registered teams: {len(teams)}", ["team", "made by (module:attribute)"])
    table.rows = [[name, target] for name, target in teams.items()]
    table.print()
    return 0
