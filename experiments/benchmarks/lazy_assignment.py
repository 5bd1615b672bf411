"""``soccer-sim bench lazy-assignment``: the command's options, kept apart from the benchmark
(:mod:`experiments.benchmarks.grid_assignment`), which imports the assignment code and its
compiled kernels: ``soccer-sim bench lazy-assignment --help`` reads only this module."""

from __future__ import annotations

import argparse


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.limits import ranged, ranged_list

    parser.add_argument("--sizes", type=ranged_list("grid-sides"), default="100,200,400", help="sides of the square 2-D workspaces (default: %(default)s)")
    parser.add_argument("--robots", type=ranged_list("grid-robots"), default="100,200", help="robot counts, as many goals (default: %(default)s)")
    parser.add_argument("--densities", type=ranged_list("densities"), default="0.2,0.1,0.15,0.25",
                        help="obstacle densities; the first for every size, the others at the smallest size "
                             "and the first robot count (default: %(default)s)")
    parser.add_argument("--sizes-3d", type=ranged_list("cube-sides"), default="40,60",
                        help="sides of cubic 3-D workspaces (26-connected), at the first density and robot count; "
                             "'' for none (default: %(default)s)")
    parser.add_argument("--repeats", type=ranged("repeats"), default=3, help="random instances per row (default: %(default)s)")
    parser.add_argument("--seed", type=ranged("seed"), default=0, help="seed of the instances (default: %(default)s)")
    parser.add_argument("--out", default=None, metavar="DIR",
                        help="also write the CSV files and the PNG plot into DIR (created if missing; "
                             "default: print the table only)")



def run(args: argparse.Namespace) -> int:
    """Run the benchmark (:func:`experiments.benchmarks.grid_assignment.run`)."""
    from experiments.benchmarks import grid_assignment

    return grid_assignment.run(args)
