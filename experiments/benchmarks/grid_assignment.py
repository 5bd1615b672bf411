"""``soccer-sim bench lazy-assignment``: lazy path-cost goal assignment against the all-pairs
baseline on random grid workspaces, in the shape of Table 1 of "It Costs to Get Costs! A
Heuristic-Based Scalable Goal Assignment Algorithm for Multi-Robot Systems".

Every row is a workspace size, an obstacle density and a number of robots (as many goals):
``--repeats`` random instances (:func:`agents.assignment.grid.random_instance`, drawn from
``--seed``), each solved by both methods of :func:`agents.assignment.assign_on_grid`. The
table gives the pairs whose true path cost was computed (lazy; the baseline computes all
``n * n``), both wall times, the speed-up (baseline mean over lazy mean) and the paper's
figures for the same row where it has one. Both methods must reach the same optimal total on
every instance; a difference stops the benchmark with an error.

Rows: every ``--sizes`` x ``--robots`` at the first of ``--densities``; the other densities
at the smallest size and the first robot count (the paper's density block); and the
``--sizes-3d`` cubes (26-connected) at the first density with the first robot count.

The command prints the table; with ``--out DIR`` it also writes ``trials.csv`` (one line per
instance), ``table.csv`` (one per row) and ``speedup.png`` there. Without ``--out`` nothing
is written. The command's options are in :mod:`experiments.benchmarks.lazy_assignment`, which
``--help`` reads without importing the assignment code.
"""

from __future__ import annotations

import argparse
import csv
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from agents.assignment import AssignmentError, assign_on_grid
from agents.assignment.grid import random_instance
from experiments.errors import ExperimentError, StudyArgumentError
from experiments.results.files import make_output_directory, write_file

#: Table 1 of the paper: (side, density %, robots) -> (pairs explored, baseline s, lazy s, speed-up).
#: Where the paper lists a row twice, the first is kept.
PAPER_TABLE_1: dict[tuple[int, int, int], tuple[int, float, float, float]] = {
    (100, 20, 100): (798, 10, 1, 10.0), (200, 20, 100): (812, 40, 3, 13.3),
    (300, 20, 100): (732, 94, 5, 18.8), (400, 20, 100): (642, 175, 7, 25.0),
    (100, 20, 200): (2388, 23, 5, 4.6), (200, 20, 200): (1764, 85, 8, 10.6),
    (300, 20, 200): (1853, 197, 14, 14.1), (400, 20, 200): (1901, 355, 22, 16.1),
    (100, 20, 300): (4027, 38, 11, 3.5), (100, 20, 400): (5238, 55, 18, 3.1),
    (100, 10, 100): (581, 12, 1, 12.0), (100, 15, 100): (677, 11, 1, 11.0),
    (100, 25, 100): (900, 9, 1, 9.0),
    (200, 20, 300): (3336, 137, 20, 6.9), (200, 20, 400): (5054, 193, 35, 5.5),
    (200, 10, 200): (1427, 104, 8, 13.0), (200, 15, 200): (1661, 95, 9, 10.6),
    (200, 25, 200): (2312, 81, 10, 8.1),
}


class TotalsDiffer(AssignmentError, ExperimentError):
    """The lazy method and the all-pairs baseline reached different totals on one instance."""


@dataclass(frozen=True)
class Row:
    """One row of the table: a workspace shape, an obstacle density and a robot count."""

    shape: tuple[int, ...]
    density: float
    robots: int

    @property
    def label(self) -> str:
        return "x".join(str(side) for side in self.shape)

    @property
    def paper(self) -> tuple[int, float, float, float] | None:
        """The paper's Table 1 figures for this row (square 2-D workspaces only)."""
        if len(self.shape) != 2 or self.shape[0] != self.shape[1]:
            return None
        return PAPER_TABLE_1.get((self.shape[0], round(self.density * 100), self.robots))


@dataclass(frozen=True)
class Trial:
    """Both methods on one random instance."""

    row: Row
    instance: int
    pairs_lazy: int
    pairs_all: int
    rounds: int
    seconds_lazy: float
    seconds_all: float
    total: float


def rows_of(args: argparse.Namespace) -> list[Row]:
    """The table's rows from the command's options (see the module docstring); ValueError
    naming the option that is wrong."""
    sizes, robots, densities, cubes = args.sizes, args.robots, args.densities, args.sizes_3d
    if not sizes or not robots or not densities:
        raise StudyArgumentError("--sizes, --robots and --densities need at least one value each")
    rows = [Row((side, side), densities[0], count) for count in robots for side in sizes]
    rows += [Row((min(sizes),) * 2, density, robots[0]) for density in densities[1:]]
    rows += [Row((side,) * 3, densities[0], robots[0]) for side in cubes]
    return rows


def play_row(row: Row, repeats: int, rng: np.random.Generator) -> list[Trial]:
    """``repeats`` instances of ``row`` solved by both methods; TotalsDiffer if their totals differ
    (an AssignmentError of another kind: the row's instance cannot be made, e.g. too many robots)."""
    trials = []
    for k in range(repeats):
        grid, robots, goals = random_instance(row.shape, row.density, row.robots, row.robots, rng)
        start = time.perf_counter()
        lazy = assign_on_grid(grid, robots, goals, method="lazy")
        middle = time.perf_counter()
        full = assign_on_grid(grid, robots, goals, method="all-pairs")
        end = time.perf_counter()
        if not np.isclose(lazy.total, full.total, rtol=1e-12, atol=1e-9):
            raise TotalsDiffer(f"row {row.label} density {row.density} robots {row.robots}, instance {k}: "
                                  f"lazy total {lazy.total} differs from all-pairs total {full.total}")
        trials.append(Trial(row, k, lazy.pairs_computed, full.pairs_computed, lazy.rounds, middle - start,
                            end - middle, float(lazy.total)))
    return trials


def summarise(trials: list[Trial]) -> dict[str, object]:
    """Means and standard deviations of one row's trials, and the speed-up of the means."""
    row = trials[0].row
    pairs = np.array([t.pairs_lazy for t in trials], float)
    lazy = np.array([t.seconds_lazy for t in trials])
    full = np.array([t.seconds_all for t in trials])
    paper = row.paper
    return {
        "workspace": row.label, "density": row.density, "robots": row.robots, "instances": len(trials),
        "pairs_lazy_mean": pairs.mean(), "pairs_lazy_sd": pairs.std(), "pairs_all": trials[0].pairs_all,
        "rounds_mean": float(np.mean([t.rounds for t in trials])),
        "seconds_all_mean": full.mean(), "seconds_all_sd": full.std(),
        "seconds_lazy_mean": lazy.mean(), "seconds_lazy_sd": lazy.std(), "speedup": full.mean() / lazy.mean(),
        "paper_pairs": paper[0] if paper else None, "paper_speedup": paper[3] if paper else None,
    }


def _warm_up() -> None:
    """Compile and load both methods' kernels once, so the first row's times are not compile times.

    The lazy method's kernels come in two versions, for the 16-bit search states of small
    grids and the 32-bit ones of large grids (:func:`agents.assignment.pathcost.state_dtype`):
    the 130 x 130 grid loads the second.
    """
    rng = np.random.default_rng(0)
    for shape in ((12, 12), (6, 6, 6), (130, 130)):
        grid, robots, goals = random_instance(shape, 0.2, 4, 4, rng)
        assign_on_grid(grid, robots, goals, method="lazy")
        assign_on_grid(grid, robots, goals, method="all-pairs")


def write_outputs(trials: list[Trial], summaries: list[dict[str, object]], out: Path) -> list[Path]:
    """``trials.csv`` (one line per instance), ``table.csv`` (one per row) and ``speedup.png``."""
    out.mkdir(parents=True, exist_ok=True)
    trial_path, table_path, plot_path = out / "trials.csv", out / "table.csv", out / "speedup.png"
    write_file(trial_path, lambda path: _write_trials(path, trials))
    write_file(table_path, lambda path: _write_table(path, summaries))
    write_file(plot_path, lambda path: _plot(summaries, path))    # each whole or not at all
    return [trial_path, table_path, plot_path]


def _write_trials(path: Path, trials: list[Trial]) -> None:
    with path.open("w", newline="") as handle:
        writer = csv.writer(handle)
        writer.writerow(["workspace", "density", "robots", "instance", "pairs_lazy", "pairs_all", "rounds",
                         "seconds_lazy", "seconds_all", "total"])
        for t in trials:
            writer.writerow([t.row.label, t.row.density, t.row.robots, t.instance, t.pairs_lazy, t.pairs_all,
                             t.rounds, f"{t.seconds_lazy:.6f}", f"{t.seconds_all:.6f}", t.total])


def _write_table(path: Path, summaries: list[dict[str, object]]) -> None:
    with path.open("w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(summaries[0]))
        writer.writeheader()
        writer.writerows(summaries)


def _plot(summaries: list[dict[str, object]], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    labels = [f"{s['workspace']}\n{round(100 * s['density'])}% R={s['robots']}" for s in summaries]
    x = np.arange(len(summaries))
    fig, ax = plt.subplots(figsize=(max(6.0, 0.9 * len(summaries)), 4.0))
    ax.bar(x - 0.2, [s["speedup"] for s in summaries], 0.4, label="measured")
    paper = [s["paper_speedup"] if s["paper_speedup"] is not None else np.nan for s in summaries]
    ax.bar(x + 0.2, paper, 0.4, label="paper, Table 1")
    ax.set_xticks(x, labels, fontsize=7)
    ax.set_ylabel("speed-up over all-pairs (x)")
    ax.set_yscale("log")
    ax.set_title("Lazy path-cost assignment vs Dijkstra from every robot + Hungarian")
    ax.legend()
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def _print_table(summaries: list[dict[str, object]]) -> None:
    from experiments.reporting import Table

    table = Table("Lazy path-cost assignment vs all pairs (mean ± sd over the instances)",
                  ["workspace", "obst.", "R", "pairs (lazy)", "all pairs", "all-pairs s", "lazy s", "speed-up",
                   "paper pairs", "paper speed-up"], labels=0)
    for s in summaries:
        table.rows.append([
            str(s["workspace"]), f"{round(100 * s['density'])}%", str(s["robots"]),
            f"{s['pairs_lazy_mean']:.0f} ± {s['pairs_lazy_sd']:.0f}", str(s["pairs_all"]),
            f"{s['seconds_all_mean']:.2f} ± {s['seconds_all_sd']:.2f}",
            f"{s['seconds_lazy_mean']:.3f} ± {s['seconds_lazy_sd']:.3f}", f"{s['speedup']:.1f}",
            "-" if s["paper_pairs"] is None else str(s["paper_pairs"]),
            "-" if s["paper_speedup"] is None else f"{s['paper_speedup']:.1f}",
        ])
    table.print()


def run(args: argparse.Namespace) -> int:
    from experiments.commands.errors import FAILED, fail

    try:
        rows = rows_of(args)
    except ValueError as exc:
        return fail(str(exc))
    if args.out is not None and (problem := make_output_directory(args.out)):
        return fail(f"--out {args.out!r}: {problem}")
    out = Path(args.out) if args.out is not None else None
    rng = np.random.default_rng(args.seed)
    _warm_up()
    started = time.perf_counter()
    trials: list[Trial] = []
    summaries = []
    for row in rows:
        try:
            row_trials = play_row(row, args.repeats, rng)
        except TotalsDiffer as exc:  # the benchmark's own check failed
            return fail(str(exc), FAILED)
        except AssignmentError as exc:  # the options ask for an impossible instance (too many robots)
            return fail(f"row {row.label}, density {row.density}, {row.robots} robots: {exc}")
        trials += row_trials
        summaries.append(summarise(row_trials))
    _print_table(summaries)
    print(f"{len(trials)} instances, both totals equal on every one; {time.perf_counter() - started:.1f} s")
    if out is None:
        print("table only; --out DIR also writes the instances and the table (CSV) and the speed-up plot")
        return 0
    try:
        paths = write_outputs(trials, summaries, out)
    except OSError as exc:
        return fail(f"--out {out}: cannot write ({exc.strerror or exc})")
    print(f"wrote {', '.join(str(p) for p in paths)}")
    return 0
