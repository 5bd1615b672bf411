"""``soccer-sim bench WHAT``: the project's benchmarks.

Each benchmark is a module in :mod:`experiments.benchmarks` exposing
``add_arguments(parser)`` and ``run(args) -> int``; it is imported only when
chosen, so one benchmark's heavy imports never slow another.

Every benchmark prints its tables through :class:`experiments.reporting.Table` (plain and
tab-separated when stdout is not a terminal) and takes ``--json``; only ``lazy-assignment``
writes files, and only with ``--out DIR``.
"""

from __future__ import annotations

import argparse

from experiments.commands import add_module_commands

#: Benchmark name -> (module, one-line help).
BENCHMARKS: dict[str, tuple[str, str]] = {
    "assignment": ("experiments.benchmarks.assignment", "runtime and quality of the role-assignment methods"),
    "env": ("experiments.benchmarks.env", "steps per second of the PettingZoo environment against a plain match"),
    "formation": ("experiments.benchmarks.formation", "speed of formation queries"),
    "lazy-assignment": ("experiments.benchmarks.lazy_assignment",
                        "lazy path-cost goal assignment vs all pairs on random grids (Table 1's shape)"),
    "match": ("experiments.benchmarks.match", "speed of whole matches between two teams"),
    "replay": ("experiments.benchmarks.replay", "time and file size of recording a rerun replay of a match"),
    "roles": ("experiments.benchmarks.roles", "microseconds per call of every role assigner"),
    "skills": ("experiments.benchmarks.skills", "microseconds per call of every soccer skill"),
    "soccer": ("experiments.benchmarks.soccer",
               "play figures (goals, set plays, shape, stamina, distance by role) of built-in teams or game logs"),
    "startup": ("experiments.benchmarks.startup",
                "wall time of a first play with a cold and a warm kernel cache, and of --help"),
}


def register(subparsers: argparse._SubParsersAction) -> None:
    add_module_commands(subparsers, "bench", "run a benchmark and print its tables", "benchmark", "WHAT", BENCHMARKS)
