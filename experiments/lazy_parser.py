"""An argparse parser whose arguments are added only when it is used.

``soccer-sim --help`` lists every command, and building every command's arguments would
import what the commands need (numpy, the simulator, every benchmark and study): most of a
second before anything is printed. A :class:`LazyParser` is created with its name and help
at once but runs its ``populate(parser)`` callback only when it parses arguments or prints
its own help, i.e. when its command is the one chosen.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable

from experiments.commands.errors import CommandParser


class LazyParser(CommandParser):
    """An ``ArgumentParser`` that calls ``populate(self)`` once, before its first parse or help
    (a :class:`~experiments.commands.errors.CommandParser`: its usage errors are one line).

    Use it as a sub-parser: ``subparsers.add_parser(name, help=..., populate=fn)`` on a
    sub-parsers action made with ``parser_class=LazyParser``."""

    def __init__(self, *args, populate: Callable[[argparse.ArgumentParser], None] | None = None, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self._populate = populate

    def populate(self) -> LazyParser:
        """Add the deferred arguments now (once); returns the parser."""
        populate, self._populate = self._populate, None
        if populate is not None:
            populate(self)
        return self

    def parse_known_args(self, args=None, namespace=None):
        self.populate()
        return super().parse_known_args(args, namespace)

    def format_usage(self) -> str:
        self.populate()
        return super().format_usage()

    def format_help(self) -> str:
        self.populate()
        return super().format_help()
