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
    :class:`~experiments.lazy_parser.LazyParser`), so listing the commands stays fast."""
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
    parser.set_defaults(func=module.run)
