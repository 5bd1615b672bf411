"""``soccer-sim experiment NAME``: the project's studies (case studies and reproductions).

Each study is a module in :mod:`experiments.studies` exposing ``add_arguments(parser)`` and
``run(args) -> int``; it is imported only when its parser is built, so adding a study means
adding one line to :data:`STUDIES`.

Every study prints its tables through :class:`experiments.reporting.Table` and takes
``--json``. The studies that stand alone write CSV files and figures only with ``--out DIR``;
those that run many matches (``case-study``, ``transfer``, ``ablation``, ``drop-in``) store them in a results file
(``--out``) and write their tables beside it (``--tables``).
"""

from __future__ import annotations

import argparse

from experiments.commands import add_module_commands

#: Study name -> (module, one-line help).
STUDIES: dict[str, tuple[str, str]] = {
    "assigners": ("experiments.studies.assigners", "does positioning matter: league, baselines and SCRAM's claims"),
    "distributed": ("experiments.studies.distributed", "distributed assignment under limited communication: completion-time scaling"),
    "incremental": ("experiments.studies.incremental", "tunable incremental assignment: routes of a new pair versus lambda (Fig. 8)"),
    "case-study": ("experiments.studies.case_study", "SCRAM's Table 5: each role assigner against the reference opponents"),
    "transfer": ("experiments.studies.transfer", "the same pairings in the simulator and in rcssserver, side by side"),
    "ablation": ("experiments.studies.ablation", "one limit of partial observation off at a time, for both teams"),
    "drop-in": ("experiments.studies.drop_in", "ad hoc teamwork: a SCRAM player and a static-roles player in mixed teams"),
    "penalty-shot": ("experiments.studies.penalty_shot", "time to score from field markers: one robot, uncoordinated robots, coordinated robots"),
}


def register(subparsers: argparse._SubParsersAction) -> None:
    add_module_commands(subparsers, "experiment", "run a study and print its tables", "study", "NAME", STUDIES)
