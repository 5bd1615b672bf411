"""The ``soccer-sim`` command line.

Each sub-command lives in its own module under :mod:`experiments.commands`,
which exposes ``register(subparsers)``: it adds its parser and sets
``func(args) -> int`` as the parser's default. This module only wires them up,
so adding a command never means editing another command's code.

Listing the commands (``soccer-sim --help``) must stay quick, so building the parser imports
no numpy, numba or simulator code: command modules import what they need when they run, and a
command whose arguments are costly to build passes ``populate=`` to ``add_parser`` (the
sub-parsers are :class:`~experiments.lazy_parser.LazyParser`) to build them only when chosen.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from collections.abc import Sequence

from experiments.commands.errors import CommandParser, call
from experiments.lazy_parser import LazyParser

#: Modules that each contribute one top-level sub-command.
COMMAND_MODULES: tuple[str, ...] = (
    "experiments.commands.play",
    "experiments.commands.teams",
    "experiments.commands.scenarios",
    "experiments.commands.formation",
    "experiments.commands.bench",
    "experiments.commands.experiment",
    "experiments.commands.tournament",
    "experiments.commands.evaluate",
    "experiments.commands.results",
    "experiments.commands.replay",
)


def build_parser() -> argparse.ArgumentParser:
    """Return the parser with every sub-command registered."""
    parser = CommandParser(
        prog="soccer-sim",
        description="2D 11v11 soccer simulator for point robots and a lab for multi-robot role assignment.",
    )
    parser.add_argument("--version", action=_VersionAction)
    subparsers = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=LazyParser)
    for module_name in COMMAND_MODULES:
        importlib.import_module(module_name).register(subparsers)
    return parser


def command_paths(parser: argparse.ArgumentParser | None = None) -> list[tuple[str, ...]]:
    """Every command and sub-command of ``parser`` (default: :func:`build_parser`'s), as the
    words that choose it: ``()`` for ``soccer-sim`` itself, ``("play",)``,
    ``("bench", "match")``, ... in the order ``--help`` lists them. Read without building any
    command's deferred arguments (what ``soccer-sim bench startup`` times and the tests check)."""
    parser = parser if parser is not None else build_parser()
    paths: list[tuple[str, ...]] = []

    def walk(node: argparse.ArgumentParser, path: tuple[str, ...]) -> None:
        paths.append(path)
        for action in node._actions:  # (argparse keeps its sub-parsers only there)
            if isinstance(action, argparse._SubParsersAction):
                for name, child in action.choices.items():
                    walk(child, (*path, name))

    walk(parser, ())
    return paths


def main(argv: Sequence[str] | None = None) -> int:
    """Entry point of the ``soccer-sim`` console script; returns the exit status."""
    # Let `package.module:Attribute` team paths name modules in the working directory, as
    # `python -m` would; appended, so the directory never shadows an installed package.
    if os.getcwd() not in sys.path:
        sys.path.append(os.getcwd())
    parser = build_parser()
    args = parser.parse_args(argv)
    if not hasattr(args, "func"):
        parser.print_help()
        return 2
    return call(args.func, args)


class _VersionAction(argparse.Action):
    """``--version``: print ``soccer-sim VERSION`` and exit. The version is read from the
    installed distribution only when asked (reading it imports importlib.metadata, which every
    ``--help`` would otherwise pay for)."""

    def __init__(self, option_strings, dest=argparse.SUPPRESS, default=argparse.SUPPRESS, help=None) -> None:
        super().__init__(option_strings, dest=dest, default=default, nargs=0,
                         help=help or "show the program's version number and exit")

    def __call__(self, parser, namespace, values, option_string=None) -> None:
        print(f"{parser.prog} {installed_version()}")
        parser.exit()


def installed_version() -> str:
    """The installed distribution's version (``unknown`` when the code runs from a source tree
    that was never installed)."""
    from importlib import metadata

    try:
        return metadata.version("soccer-sim")
    except metadata.PackageNotFoundError:
        return "unknown"


if __name__ == "__main__":
    sys.exit(main())
