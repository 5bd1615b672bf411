"""The sub-commands of ``soccer-sim``, one module each (see :mod:`experiments.cli`)."""

from __future__ import annotations


def doc_summary(doc: str | None) -> str:
    """The first paragraph of a module docstring as plain text for ``--help`` (no reST
    literal markers, lines joined)."""
    return " ".join((doc or "").split("\n\n")[0].replace("``", "").split())


def add_module_commands(subparsers, name: str, help_text: str, dest: str, metavar: str,
                        modules: dict[str, tuple[str, str]]) -> None:
    """Add command ``name`` whose sub-commands are modules: ``modules`` maps each sub-command
    to (module, one-line help); each module exposes ``add_arguments(parser)`` and
    ``run(args) -> int`` and is imported only when its sub-command is chosen (its parser is a
    :class:`~experiments.lazy_parser.LazyParser`), so listing the commands stays fast.

    Every sub-command also takes ``--json`` (its tables and other output as one JSON object,
    see :func:`experiments.reporting.json_output`) and runs under
    :func:`experiments.commands.errors.call` (one error line, exit 130 after Ctrl-C)."""
    import functools

    from experiments.lazy_parser import LazyParser

    parser = subparsers.add_parser(name, help=help_text)
    sub = parser.add_subparsers(dest=dest, metavar=metavar, required=True, parser_class=LazyParser)
    for sub_name, (module_name, sub_help) in modules.items():
        sub.add_parser(sub_name, help=sub_help, populate=functools.partial(_add_module_arguments, module_name))


def _add_module_arguments(module_name: str, parser) -> None:
    import importlib

    module = importlib.import_module(module_name)
    module.add_arguments(parser)
    add_json_option(parser)
    parser.set_defaults(func=table_command(module.run))


def add_json_option(parser) -> None:
    """``--json``: print the command's tables as one JSON object (honoured by :func:`table_command`)."""
    parser.add_argument("--json", action="store_true",
                        help="print the tables (and the other output lines, as notes) as one JSON object")


def table_command(run):
    """``run(args)`` as a command's ``func``: with ``args.json`` its output becomes one JSON
    object; errors, Ctrl-C and broken pipes end by the convention of :mod:`experiments.commands.errors`."""
    from experiments.commands.errors import guarded

    def command(args) -> int:
        if getattr(args, "json", False):
            from experiments.reporting import json_output

            return json_output(lambda: run(args))
        return run(args)

    command.__doc__ = run.__doc__
    return guarded(command)
