"""``soccer-sim experiment NAME``: the project's studies (case studies and reproductions).

Each study is a module in :mod:`experiments.studies` exposing ``add_arguments(parser)`` and
``run(args) -> int``; it is imported only when its parser is built, so adding a study means
adding one line to :data:`STUDIES`.
"""

from __future__ import annotations

import argparse
import importlib

#: Study name -> (module, one-line help).
STUDIES: dict[str, tuple[str, str]] = {
    "assigners": ("experiments.studies.assigners", "does positioning matter: league, baselines and SCRAM's claims"),
    "distributed": ("experiments.studies.distributed", "distributed assignment under limited communication: completion-time scaling"),
}


def register(subparsers: argparse._SubParsersAction) -> None:
    parser = subparsers.add_parser("experiment", help="run a study and print its tables")
    study_sub = parser.add_subparsers(dest="study", metavar="NAME", required=True)
    for name, (module_name, help_text) in STUDIES.items():
        study_parser = study_sub.add_parser(name, help=help_text)
        module = importlib.import_module(module_name)
        module.add_arguments(study_parser)
        study_parser.set_defaults(func=module.run)
