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
    ``run(args) -> int`` and is imported when the parser is built."""
    import importlib

    parser = subparsers.add_parser(name, help=help_text)
    sub = parser.add_subparsers(dest=dest, metavar=metavar, required=True)
    for sub_name, (module_name, sub_help) in modules.items():
        sub_parser = sub.add_parser(sub_name, help=sub_help)
        module = importlib.import_module(module_name)
        module.add_arguments(sub_parser)
        sub_parser.set_defaults(func=module.run)
