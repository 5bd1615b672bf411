"""``soccer-sim bench WHAT``: the project's benchmarks.

Each benchmark is a module in :mod:`experiments.benchmarks` exposing
``add_arguments(parser)`` and ``run(args) -> int``; it is imported only when
chosen, so one benchmark's heavy imports never slow another.
"""

from __future__ import annotations

import argparse
import importlib

#: Benchmark name -> (module, one-line help).
BENCHMARKS: dict[str, tuple[str, str]] = {
    "assignment": ("experiments.benchmarks.assignment", "runtime and quality of the role-assignment methods"),
    "formation": ("experiments.benchmarks.formation", "speed of formation queries"),
    "match": ("experiments.benchmarks.match", "speed of whole matches between two teams"),
    "skills": ("experiments.benchmarks.skills", "microseconds per call of every soccer skill"),
    "soccer": ("experiments.benchmarks.soccer", "goals, shots, passes and crowding near the ball between two teams"),
}


def register(subparsers: argparse._SubParsersAction) -> None:
    parser = subparsers.add_parser("bench", help="run a benchmark and print its tables")
    bench_sub = parser.add_subparsers(dest="benchmark", metavar="WHAT", required=True)
    for name, (module_name, help_text) in BENCHMARKS.items():
        bench_parser = bench_sub.add_parser(name, help=help_text)
        _add_benchmark(bench_parser, module_name)


def _add_benchmark(parser: argparse.ArgumentParser, module_name: str) -> None:
    module = importlib.import_module(module_name)
    module.add_arguments(parser)
    parser.set_defaults(func=module.run)
