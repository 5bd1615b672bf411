"""``soccer-sim experiment incremental``: routes of a new robot-target pair versus the diagonal scaling.

Reproduces the simulation study of "Tunable Routing Solutions for Multi-Robot
Navigation via the Assignment Problem: A 3D Representation of the Matching
Graph" (Liu and Shell) with :class:`agents.assignment.IncrementalAssignment`:
``n`` robots (300, as the paper) are deployed on uniformly random sites of a
square of side ``--side`` (metres), each connected to its ``--degree`` nearest
neighbours (10, as the paper); a new robot appears in the bottom-left corner
and a new target in the top-right one, and one Hungarian stage routes the team.
For every ``lam`` it reports, over ``--trials`` random deployments (ten in the
paper), the paper's Fig. 8 quantities: robots that move (the new one
included), finishing time (longest move, robots moving at once at unit speed)
and mean distance per moving robot; and it compares the smallest ``lam``'s
route with Dijkstra's shortest path on the same graph (Section VI-A).

With ``--out DIR`` it writes ``incremental_trials.csv`` (one row per trial and
``lam``), ``incremental_summary.csv`` and ``incremental.png`` (the three
curves, and the routes of one deployment for a few ``lam``).
"""

from __future__ import annotations

import argparse
import csv
import math
import time
from dataclasses import asdict, dataclass
from pathlib import Path

from typing import TYPE_CHECKING

from experiments.errors import StudyArgumentError
from experiments.limits import ranged, ranged_list
from experiments.results.files import make_output_directory, output_path, write_file

if TYPE_CHECKING:  # the assignment code compiles kernels: imported when the study runs, not for --help
    from agents.assignment import IncrementalAssignment


@dataclass(frozen=True)
class Trial:
    """One route: a deployment, a ``lam``, and what the stage did."""

    trial: int
    lam: float
    moved: int
    reassigned: int
    total_distance: float
    mean_distance: float
    finishing_time: float
    dijkstra_distance: float
    stage_ms: float


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--n", type=ranged("n"), default=300, help="deployed robots (default: %(default)s, as the paper)")
    parser.add_argument("--degree", type=degree_value, default="10",
                        help="nearest neighbours per robot, or 'all' for the complete graph (default: %(default)s)")
    parser.add_argument("--lambdas", type=ranged_list("lambdas"), default="0,0.1,0.2,0.3,0.4,0.5,0.6,0.7,0.8,0.9,1",
                        help="diagonal scalings in [0, 1] (default: %(default)s)")
    parser.add_argument("--trials", type=ranged("trials"), default=10, help="random deployments (default: %(default)s, as the paper)")
    parser.add_argument("--side", type=ranged("side"), default=100.0, help="side of the square, metres (default: %(default)s)")
    parser.add_argument("--seed", type=ranged("seed"), default=0, help="seed of the deployments (default: %(default)s)")
    parser.add_argument("--out", type=output_path, default=None,
                        help="directory for the CSV files and the PNG figure (created if missing)")


def _check_args(args: argparse.Namespace) -> tuple[list[float], int | None]:
    """The distinct diagonal scalings in increasing order and the degree (None: the complete
    graph); each number was range-checked by its option's type."""
    if not args.lambdas:
        raise StudyArgumentError("--lambdas: give at least one value")
    return sorted(set(args.lambdas)), args.degree


def degree_value(text: str) -> int | None:
    """The ``--degree`` type: ``all`` (None: the complete graph) or a count of neighbours
    within its range."""
    if text.strip() == "all":
        return None
    try:
        return ranged("degree")(text)
    except argparse.ArgumentTypeError as exc:
        raise argparse.ArgumentTypeError(f"{exc}; or 'all' for the complete graph") from None


def corners(side: float) -> tuple[np.ndarray, np.ndarray]:
    """The new robot's start (bottom-left corner) and the new target (top-right corner)."""
    import numpy as np

    return np.array([0.0, 0.0]), np.array([side, side])


def route(sites: np.ndarray, lam: float, degree: int | None, side: float) -> tuple[IncrementalAssignment, object, float]:
    """Deploy robots on ``sites``, insert the corner pair; the team, the Reassignment and the stage's ms."""
    from agents.assignment import IncrementalAssignment

    team = IncrementalAssignment(sites, sites, lam=lam, degree=degree)
    start = time.perf_counter()
    step = team.add(*corners(side))
    return team, step, 1e3 * (time.perf_counter() - start)


def collect(lambdas: list[float], degree: int | None, args: argparse.Namespace) -> list[Trial]:
    from agents.assignment import IncrementalAssignment
    import numpy as np

    rng = np.random.default_rng(args.seed)
    trials = []
    for trial in range(args.trials):
        sites = rng.random((args.n, 2)) * args.side
        probe = IncrementalAssignment(sites, sites, lam=lambdas[0], degree=degree)
        shortest = probe.shortest_route(*corners(args.side))
        if not math.isfinite(shortest):  # the sparse graph does not join the corners: no route at any lam
            continue
        for lam in lambdas:
            _, step, ms = route(sites, lam, degree, args.side)
            trials.append(Trial(trial, lam, step.moved, step.reassigned, step.total, step.mean,
                                step.finishing_time, shortest, ms))
    return trials


def summarise(trials: list[Trial]) -> list[dict]:
    import numpy as np

    rows = []
    for lam in sorted({t.lam for t in trials}):
        group = [t for t in trials if t.lam == lam]
        row = {"lam": lam, "trials": len(group)}
        row["trials"] = len(group)
        for field in ("moved", "finishing_time", "mean_distance", "total_distance", "stage_ms"):
            values = np.array([getattr(t, field) for t in group], dtype=float)
            row[field] = float(values.mean())
            row[field + "_sd"] = float(values.std(ddof=1)) if len(values) > 1 else 0.0
        # relative excess of the route's length over Dijkstra's; rounding noise (~1e-16) shown as 0
        excess = np.array([t.total_distance / t.dijkstra_distance - 1.0 for t in group])
        excess[np.abs(excess) < 1e-12] = 0.0
        row["excess_over_dijkstra_mean"] = float(excess.mean())
        row["excess_over_dijkstra_max"] = float(excess.max())
        rows.append(row)
    return rows


def _print_tables(summary: list[dict], degree: int | None, args) -> None:
    from experiments.reporting import Table

    table = Table(f"new pair corner to corner, n = {args.n}, degree {degree or 'all'}, {args.trials} deployments "
                  "(mean ± sd)", ["λ", "moved", "finish time", "mean dist", "total dist", "vs Dijkstra", "stage ms"],
                  labels=0)
    for row in summary:
        table.rows.append([f"{row['lam']:.2g}", f"{row['moved']:.1f}±{row['moved_sd']:.1f}",
                           f"{row['finishing_time']:.2f}±{row['finishing_time_sd']:.2f}",
                           f"{row['mean_distance']:.2f}±{row['mean_distance_sd']:.2f}",
                           f"{row['total_distance']:.1f}", f"{row['excess_over_dijkstra_mean']:+.2%}",
                           f"{row['stage_ms']:.1f}"])
    table.print()
    first = summary[0]
    print(f"λ = {first['lam']:g} route vs Dijkstra's shortest path: mean {first['excess_over_dijkstra_mean']:+.4%}, "
          f"worst {first['excess_over_dijkstra_max']:+.4%} longer")


def _write_csv(path: Path, rows: list[dict]) -> None:
    with path.open("w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)


def _plot(summary: list[dict], degree: int | None, args, path: Path) -> None:
    import matplotlib
    import numpy as np

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    lam = [row["lam"] for row in summary]
    fig, axes = plt.subplots(1, 4, figsize=(17, 4))
    for ax, field, label in zip(axes, ("moved", "finishing_time", "mean_distance"),
                                ("robots moved", "finishing time (s at 1 m/s)", "mean distance per moving robot (m)")):
        ax.errorbar(lam, [row[field] for row in summary], yerr=[row[field + "_sd"] for row in summary],
                    marker="o", capsize=3)
        ax.set_xlabel("λ")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    sites = np.random.default_rng(args.seed).random((args.n, 2)) * args.side
    ax = axes[3]
    ax.scatter(sites[:, 0], sites[:, 1], s=4, color="0.6")
    shown = sorted({lam[0], lam[len(lam) // 2], lam[-1]})
    for value, colour in zip(shown, ("tab:blue", "tab:orange", "tab:red")):
        team, step, _ = route(sites, value, degree, args.side)
        targets = team.targets
        start = np.vstack([corners(args.side)[0], targets[step.from_targets[1:]]])
        for (x0, y0), (x1, y1) in zip(start, targets[step.to_targets]):
            ax.annotate("", (x1, y1), (x0, y0), arrowprops={"arrowstyle": "->", "color": colour, "lw": 1.2})
        ax.plot([], [], color=colour, label=f"λ = {value:g}: {step.moved} robots")
    ax.set_aspect("equal")
    ax.set_title("routes of the first deployment")
    ax.legend(fontsize=8, loc="upper left")
    fig.suptitle(f"incremental assignment, n = {args.n}, degree {degree or 'all'}, {args.trials} deployments")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def run(args: argparse.Namespace) -> int:
    from agents.assignment import AssignmentError
    from experiments.commands.errors import FAILED, fail

    try:
        lambdas, degree = _check_args(args)
        if args.out is not None and (problem := make_output_directory(args.out)):
            raise StudyArgumentError(f"--out {args.out}: {problem}")
    except StudyArgumentError as exc:
        return fail(str(exc))
    start = time.perf_counter()
    try:
        trials = collect(lambdas, degree, args)
    except AssignmentError as exc:
        return fail(str(exc), FAILED)
    if not trials:
        return fail(f"no deployment's degree-{degree} graph joins the corners", FAILED)
    summary = summarise(trials)
    _print_tables(summary, degree, args)
    skipped = args.trials - len({t.trial for t in trials})
    if skipped:
        print(f"{skipped} of {args.trials} deployments skipped: their graph does not join the corners")
    print(f"{len(trials)} routes in {time.perf_counter() - start:.1f} s")
    if args.out is not None:
        # each file whole or not at all: a full disk leaves no partial CSV or 0-byte PNG
        write_file(args.out / "incremental_trials.csv", lambda path: _write_csv(path, [asdict(t) for t in trials]))
        write_file(args.out / "incremental_summary.csv", lambda path: _write_csv(path, summary))
        write_file(args.out / "incremental.png", lambda path: _plot(summary, degree, args, path))
        names = ("incremental_trials.csv", "incremental_summary.csv", "incremental.png")
        print(f"wrote {', '.join(str(args.out / name) for name in names)}")
    else:
        print("tables only; --out DIR also writes the routes and the summary (CSV) and the figure")
    return 0
