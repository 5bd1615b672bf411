"""``soccer-sim experiment distributed``: scaling of distributed assignment under limited communication.

Reproduces the completion-time results of "Monotonic Target Assignment for
Robotic Networks" (Smith and Bullo) with the simulations of
:func:`agents.assignment.distributed_assign` (communication range ``r_comm``,
speed 1, as in the paper's Fig. 9):

* ``grid-dense``: GRID ASSGMT, agents and targets uniformly random in a dense
  environment of area ``r_comm^2 n / (6 ln n)`` (the paper's Fig. 9(b);
  Theorem 6.7: completion time O(sqrt(|E|)) with high probability). Unlike the
  paper, trials with an empty cell are kept (the share is reported).
* ``etsp-uniform``: ETSP ASSGMT, uniformly random, area ``4 r_comm^2 n`` (Fig. 9(a)).
* ``etsp-worst``: ETSP ASSGMT on the construction of Theorem 4.2: targets at the
  centres of squares of side ``2.5 r_comm`` (no two within communication range),
  every agent but one already on a target and the free target the last one on
  the searching agent's tour (Theorem 5.1: O(sqrt(n |E|)), attained here).
* ``sweep``: both algorithms at a fixed n across environment sizes, from dense to
  sparse (the paper's Remark 6.6 compares their worst cases).

Each series' completion time is fitted by a power law (least squares in log-log
coordinates) against the quantity the paper's bound names. The command prints
tables; with ``--out DIR`` it writes ``distributed_trials.csv`` (one row per
run), ``distributed_summary.csv`` and two PNG figures.
"""

from __future__ import annotations

import argparse
import csv
import math
import time
from dataclasses import dataclass
from pathlib import Path

from experiments.errors import StudyArgumentError
from experiments.limits import ranged, ranged_list
from experiments.results.files import make_output_directory, output_path, write_file

#: Side of the squares of the worst-case construction, in units of r_comm (> 2: isolated targets).
WORST_CASE_SPACING = 2.5
#: The paper's empirical band for GRID ASSGMT in dense environments: T / sqrt(|E|) in [1.5, 2.5].
PAPER_GRID_BAND = (1.5, 2.5)


@dataclass(frozen=True)
class Run:
    """One simulated run and its outcome."""

    series: str
    algorithm: str
    n: int
    side: float
    trial: int
    completion_time: float
    mean_distance: float
    max_distance: float
    rounds: int
    messages: int
    empty_cells: int
    wall_seconds: float


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--grid-sizes", type=ranged_list("grid-sizes"), default="50,100,250,500,1000,2000,4000,8000,16000",
                        help="agent counts n of the grid-dense series (default: %(default)s; '' to skip)")
    parser.add_argument("--grid-trials", type=ranged("grid-trials"), default=30,
                        help="random instances per size in the grid-dense series (default: %(default)s, as the paper)")
    parser.add_argument("--etsp-sizes", type=ranged_list("etsp-sizes"), default="25,50,100,250,500,1000",
                        help="agent counts n of the etsp-uniform series (default: %(default)s; '' to skip)")
    parser.add_argument("--worst-sizes", type=ranged_list("worst-sizes"), default="16,36,64,144,256,576",
                        help="agent counts n of the etsp-worst series (default: %(default)s; '' to skip)")
    parser.add_argument("--trials", type=ranged("trials"), default=10,
                        help="random instances per point of the etsp-uniform and sweep series (default: %(default)s)")
    parser.add_argument("--sweep-n", type=ranged("sweep-n"), default=200, help="agent count of the sweep (default: %(default)s)")
    parser.add_argument("--sweep-areas", type=ranged_list("sweep-areas"), default="0.03,0.1,0.3,1,3,10",
                        help="area per agent |E|/n of the sweep, in units of r_comm^2 (default: %(default)s; '' to skip)")
    parser.add_argument("--r-comm", type=ranged("r-comm"), default=10.0, help="communication range (default: %(default)s)")
    parser.add_argument("--round-fraction", type=ranged("round-fraction"), default=0.1,
                        help="time between rounds as a fraction of r_comm / v_max (default: %(default)s)")
    parser.add_argument("--seed", type=ranged("seed"), default=0, help="seed of the random instances (default: %(default)s)")
    parser.add_argument("--out", type=output_path, default=None,
                        help="directory for the CSV files and the PNG figures (created if missing)")


def _check_args(args: argparse.Namespace) -> dict:
    """The series to run: the lists parsed by their options' types (each value within its
    range in :data:`experiments.limits.OPTION_RANGES`)."""
    return {"grid": args.grid_sizes, "etsp": args.etsp_sizes, "worst": args.worst_sizes, "areas": args.sweep_areas}


def _empty_cells(targets: np.ndarray, side: float, r_comm: float) -> int:
    """Cells of GRID ASSGMT's partition that hold no target."""
    from agents.assignment.distributed import cells_per_side
    import numpy as np

    b = cells_per_side(side, r_comm)
    cells = np.minimum((targets / (side / b)).astype(np.int64), b - 1)
    return b * b - np.unique(cells[:, 0] * b + cells[:, 1]).size


def _simulate(series: str, algorithm: str, agents: np.ndarray, targets: np.ndarray, side: float, trial: int,
              args: argparse.Namespace) -> Run:
    from agents.assignment import distributed_assign

    start = time.perf_counter()
    result = distributed_assign(agents, targets, side, args.r_comm, algorithm=algorithm,
                                round_time=args.round_fraction * args.r_comm)
    wall = time.perf_counter() - start
    if not result.completed:
        raise RuntimeError(f"{series}: {algorithm} did not complete (n={len(agents)}, trial {trial})")
    return Run(series, algorithm, len(agents), side, trial, result.completion_time, result.mean_distance,
               result.max_distance, result.rounds, result.messages, _empty_cells(targets, side, args.r_comm), wall)


def _uniform_runs(series: str, algorithm: str, n: int, side: float, trials: int, args, code: int) -> list[Run]:
    import numpy as np

    runs = []
    for trial in range(trials):
        rng = np.random.default_rng([args.seed, code, n, trial])
        agents = rng.uniform(0.0, side, (n, 2))
        targets = rng.uniform(0.0, side, (n, 2))
        runs.append(_simulate(series, algorithm, agents, targets, side, trial, args))
    return runs


def worst_case_instance(n: int, r_comm: float) -> tuple[np.ndarray, np.ndarray, float]:
    """Theorem 4.2's construction for ETSP ASSGMT: ``(agents, targets, side)``.

    Targets sit at the centres of the first ``n`` squares of a ``k x k`` partition
    (``k = ceil(sqrt(n))``, square side ``2.5 r_comm``); agents ``0 .. n-2`` stand on
    the targets in tour order, agent ``n-1`` starts beside the first one, and the free
    target is the last of the tour, so the searching agent walks the whole ring.
    """
    from agents.assignment.etsp import etsp_tour
    import numpy as np

    k = math.isqrt(n - 1) + 1
    spacing = WORST_CASE_SPACING * r_comm
    cols, rows = np.meshgrid(np.arange(k), np.arange(k))
    targets = (np.c_[cols.ravel(), rows.ravel()][:n] + 0.5) * spacing
    order = etsp_tour(targets)
    agents = np.empty((n, 2))
    agents[: n - 1] = targets[order[: n - 1]]
    agents[n - 1] = targets[order[0]] + (0.2 * r_comm, 0.1 * r_comm)
    return agents, targets, k * spacing


def _collect(plan: dict, args) -> list[Run]:
    runs: list[Run] = []
    r = args.r_comm
    for n in plan["grid"]:
        side = math.sqrt(r * r * n / (6.0 * math.log(n)))
        runs += _uniform_runs("grid-dense", "grid", n, side, args.grid_trials, args, 1)
    for n in plan["etsp"]:
        runs += _uniform_runs("etsp-uniform", "etsp", n, math.sqrt(4.0 * r * r * n), args.trials, args, 2)
    for n in plan["worst"]:
        agents, targets, side = worst_case_instance(n, r)
        runs.append(_simulate("etsp-worst", "etsp", agents, targets, side, 0, args))
    for area in plan["areas"]:
        side = math.sqrt(area * r * r * args.sweep_n)
        for algorithm in ("etsp", "grid"):  # the same instances for both
            runs += _uniform_runs("sweep", algorithm, args.sweep_n, side, args.trials, args, 3)
    return runs


def _groups(runs: list[Run]) -> dict[tuple, list[Run]]:
    """Runs grouped by (series, algorithm, n, side), in the order they were made."""
    groups: dict[tuple, list[Run]] = {}
    for run in runs:
        groups.setdefault((run.series, run.algorithm, run.n, run.side), []).append(run)
    return groups


def _scale(series: str, n: int, area: float) -> float:
    """The quantity the paper's bound names: sqrt(|E|) for GRID ASSGMT, sqrt(n |E|) for ETSP ASSGMT."""
    return math.sqrt(area) if series == "grid-dense" else math.sqrt(n * area)


def summarise(runs: list[Run], r_comm: float) -> list[dict]:
    """One row per (series, algorithm, n, side): means, standard deviations and normalised time."""
    import numpy as np

    rows = []
    for (series, algorithm, n, side), group in _groups(runs).items():
        times = np.array([run.completion_time for run in group])
        area = side * side
        rows.append({
            "series": series, "algorithm": algorithm, "n": n, "side": side, "area": area,
            "area_per_agent_r2": area / n / (r_comm * r_comm),
            "trials": len(group),
            "time_mean": float(times.mean()), "time_sd": float(times.std(ddof=1)) if len(group) > 1 else 0.0,
            "scale": _scale(series, n, area),
            "mean_distance": float(np.mean([run.mean_distance for run in group])),
            "max_distance": float(np.mean([run.max_distance for run in group])),
            "rounds": float(np.mean([run.rounds for run in group])),
            "empty_cell_share": float(np.mean([run.empty_cells > 0 for run in group])),
            "wall_seconds": float(np.mean([run.wall_seconds for run in group])),
        })
    return rows


def fit_power_law(x: np.ndarray, y: np.ndarray) -> tuple[float, float]:
    """``(slope, factor)`` of the least-squares line ``log y = slope log x + log factor``."""
    import numpy as np

    slope, intercept = np.polyfit(np.log(x), np.log(y), 1)
    return float(slope), float(math.exp(intercept))


def _fits(summary: list[dict]) -> dict[str, tuple[float, float]]:
    """Power-law fit of the mean completion time against the bound's quantity, per scaling series."""
    import numpy as np

    fits = {}
    for series in ("grid-dense", "etsp-uniform", "etsp-worst"):
        rows = [row for row in summary if row["series"] == series]
        if len(rows) >= 2:
            fits[series] = fit_power_law(np.array([row["scale"] for row in rows]),
                                         np.array([row["time_mean"] for row in rows]))
    return fits


SERIES_TITLES = {
    "grid-dense": "GRID ASSGMT, uniform, dense: |E| = r² n / (6 ln n)  (paper's Fig. 9(b), Theorem 6.7)",
    "etsp-uniform": "ETSP ASSGMT, uniform: |E| = 4 r² n  (paper's Fig. 9(a))",
    "etsp-worst": "ETSP ASSGMT, worst case of Theorem 4.2: isolated targets, one searching agent",
    "sweep": "Both algorithms at fixed n across environment sizes",
}


def _print_tables(summary: list[dict], fits: dict) -> None:
    from experiments.reporting import Table

    for series, title in SERIES_TITLES.items():
        rows = [row for row in summary if row["series"] == series]
        if not rows:
            continue
        normaliser = {"grid-dense": "T/√|E|", "sweep": None}.get(series, "T/√(n|E|)")
        columns = ["alg", "n", "|E|/nr²", "runs", "T", "sd", normaliser, "dist", "max", "s/run"]
        if series == "grid-dense":
            columns.insert(4, "empty")
        table = Table(title, [column for column in columns if column is not None])
        for row in rows:
            cells = [row["algorithm"], str(row["n"]), f"{row['area_per_agent_r2']:.2g}", str(row["trials"]),
                     f"{row['time_mean']:.1f}", f"{row['time_sd']:.1f}", f"{row['time_mean'] / row['scale']:.3f}",
                     f"{row['mean_distance']:.1f}", f"{row['max_distance']:.1f}", f"{row['wall_seconds']:.3f}"]
            if normaliser is None:
                del cells[6]
            if series == "grid-dense":
                cells.insert(4, f"{row['empty_cell_share']:.0%}")
            table.rows.append(cells)
        table.print()
        if series in fits:
            slope, factor = fits[series]
            quantity = "sqrt(|E|)" if series == "grid-dense" else "sqrt(n |E|)"
            print(f"fit: T = {factor:.3g} * {quantity}^{slope:.3f}")


def _write_csv(path: Path, rows: list[dict]) -> None:
    with path.open("w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def _trial_rows(runs: list[Run]) -> list[dict]:
    return [{
        "series": run.series, "algorithm": run.algorithm, "n": run.n, "side": run.side, "trial": run.trial,
        "completion_time": run.completion_time, "mean_distance": run.mean_distance,
        "max_distance": run.max_distance, "rounds": run.rounds, "messages": run.messages,
        "empty_cells": run.empty_cells, "wall_seconds": run.wall_seconds,
    } for run in runs]


def _plot_scaling(summary: list[dict], fits: dict, path: Path, r_comm: float) -> None:
    import matplotlib
    import numpy as np

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    panels = ((axes[0], ("etsp-uniform", "etsp-worst"), "sqrt(n |E|)", "(a) ETSP ASSGMT"),
              (axes[1], ("grid-dense",), "sqrt(|E|)", "(b) GRID ASSGMT, dense"))
    for ax, series_list, quantity, title in panels:
        for series, marker in zip(series_list, ("o", "s")):
            rows = [row for row in summary if row["series"] == series]
            if not rows:
                continue
            x = np.array([row["scale"] for row in rows])
            y = np.array([row["time_mean"] for row in rows])
            sd = np.array([row["time_sd"] for row in rows])
            label = series
            if series in fits:
                slope, factor = fits[series]
                label += f": T = {factor:.2g} x^{slope:.2f}"
                grid = np.geomspace(x.min(), x.max(), 50)
                ax.plot(grid, factor * grid**slope, "--", lw=1, color="grey")
            ax.errorbar(x, y, yerr=sd, fmt=marker, capsize=3, label=label)
        if series_list == ("grid-dense",) and any(row["series"] == "grid-dense" for row in summary):
            x = np.array([row["scale"] for row in summary if row["series"] == "grid-dense"])
            for factor in PAPER_GRID_BAND:
                ax.plot(x, factor * x, ":", color="black", lw=1)
            ax.plot([], [], ":", color="black", label="paper's band: 1.5 and 2.5 sqrt(|E|)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(f"{quantity}  (r_comm = {r_comm:g}, v_max = 1)")
        ax.set_ylabel("completion time (mean ± sd)")
        ax.set_title(title)
        if ax.get_legend_handles_labels()[0]:  # a panel whose series were all skipped has none
            ax.legend(fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def _plot_sweep(summary: list[dict], path: Path) -> None:
    import matplotlib
    import numpy as np

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    rows = [row for row in summary if row["series"] == "sweep"]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for algorithm, marker, colour in (("etsp", "o", "tab:blue"), ("grid", "s", "tab:orange")):
        mine = [row for row in rows if row["algorithm"] == algorithm]
        if not mine:
            continue
        x = np.array([row["area_per_agent_r2"] for row in mine])
        axes[0].errorbar(x, [row["time_mean"] for row in mine], yerr=[row["time_sd"] for row in mine],
                         fmt=marker + "-", color=colour, capsize=3, label=algorithm)
        axes[1].plot(x, [row["mean_distance"] for row in mine], marker + "-", color=colour,
                     label=f"{algorithm}: mean per agent")
        axes[1].plot(x, [row["max_distance"] for row in mine], marker + ":", color=colour,
                     label=f"{algorithm}: longest")
    n = rows[0]["n"] if rows else 0
    for ax, ylabel in zip(axes, ("completion time (mean ± sd)", "distance travelled")):
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("area per agent |E| / n, in r_comm²")
        ax.set_ylabel(ylabel)
        ax.set_title(f"n = {n}, uniform agents and targets")
        ax.legend(fontsize=8)
        ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def run(args: argparse.Namespace) -> int:
    from experiments.commands.errors import fail

    try:
        plan = _check_args(args)
        if args.out is not None and (problem := make_output_directory(args.out)):
            raise StudyArgumentError(f"--out {args.out}: {problem}")
    except StudyArgumentError as exc:
        return fail(str(exc))
    start = time.perf_counter()
    runs = _collect(plan, args)
    summary = summarise(runs, args.r_comm)
    fits = _fits(summary)
    _print_tables(summary, fits)
    print(f"{len(runs)} runs in {time.perf_counter() - start:.1f} s")
    if args.out is not None and runs:
        # each file whole or not at all: a full disk leaves no partial CSV or 0-byte PNG
        write_file(args.out / "distributed_trials.csv", lambda path: _write_csv(path, _trial_rows(runs)))
        write_file(args.out / "distributed_summary.csv", lambda path: _write_csv(path, summary))
        written = ["distributed_trials.csv", "distributed_summary.csv"]
        if any(row["series"] != "sweep" for row in summary):
            write_file(args.out / "distributed_scaling.png", lambda path: _plot_scaling(summary, fits, path, args.r_comm))
            written.append("distributed_scaling.png")
        if any(row["series"] == "sweep" for row in summary):
            write_file(args.out / "distributed_environment.png", lambda path: _plot_sweep(summary, path))
            written.append("distributed_environment.png")
        print(f"wrote {', '.join(str(args.out / name) for name in written)}")
    elif args.out is None:
        print("tables only; --out DIR also writes the runs and the summary (CSV) and the figures")
    return 0
