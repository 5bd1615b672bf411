"""``soccer-sim bench assignment``: runtime and quality of the role-assignment methods.

Two tables in the manner of "SCRAM: Scalable Collision-avoiding Role
Assignment with Minimal-makespan for Formational Positioning":

(a) median wall-clock time of one ``assign`` call (distances included) per
    method / algorithm and number of robots n (= number of targets), with
    robots and targets at random integer coordinates on a square grid of side
    n². Cells that would exceed the algorithm's size limit or the time limit
    (predicted from the previous size and the algorithm's growth rate) are
    skipped and the reason is printed under the table.
(b) quality over many random instances of 10 robots and 10 targets on a
    100 x 100 integer grid: average makespan, average distance per robot, and
    the standard deviation of the distances within an assignment (averaged
    over instances).

While the runtime table is measured on a terminal, each cell's time is shown on stderr as it is made.
"""

from __future__ import annotations

import argparse
import time

from experiments.errors import StudyArgumentError
from experiments.limits import ranged, ranged_list

#: Rows of the runtime table: (label, method, algorithm).
RUNTIME_ROWS: tuple[tuple[str, str, str | None], ...] = (
    ("mmd+msd2", "mmd+msd2", None),
    ("mmdr (fast)", "mmdr", "fast"),
    ("mmdr (bitvector)", "mmdr", "bitvector"),
    ("mmdr (dp)", "mmdr", "dp"),
    ("mmdr (brute)", "mmdr", "brute"),
    ("bottleneck", "bottleneck", None),
    ("msd", "msd", None),
    ("msd2", "msd2", None),
    ("greedy", "greedy", None),
    ("random", "random", None),
)

#: Hard size limits (largest n) and why.
SIZE_LIMITS: dict[str, tuple[int, str]] = {
    "mmdr (brute)": (8, "brute force enumerates n! assignments; limited to n <= 8"),
    "mmdr (dp)": (20, "subset dynamic programming needs 2^n states; limited to n <= 20"),
}


def _size_limits() -> dict[str, tuple[int, str]]:
    """SIZE_LIMITS plus the bitvector algorithm's memory limit (imported only when running)."""
    import math

    from agents.assignment.lexicographic_reference import BITVECTOR_MAX_PAIRS

    reason = f"bitvector weights need about (n*m)^2/16 bytes; limited to n*m <= {BITVECTOR_MAX_PAIRS:,}"
    return {**SIZE_LIMITS, "mmdr (bitvector)": (math.isqrt(BITVECTOR_MAX_PAIRS), reason)}

#: Growth exponent used to predict the next size's runtime from the previous one.
GROWTH: dict[str, float] = {
    "mmd+msd2": 2.0,  # k-d tree candidate graph: a few tens of pairs per robot
    "mmdr (fast)": 2.0,
    "bottleneck": 2.0,
    "mmdr (bitvector)": 4.0,
    "mmdr (dp)": 8.0,
    "msd": 3.0,  # dense shortest augmenting path (scipy)
    "msd2": 3.0,
    "greedy": 2.2,  # sorting all n² pairs
    "random": 2.0,
}
DEFAULT_GROWTH = 2.5
#: Dense methods hold a few n x n float64 matrices; refuse above this many bytes.
DENSE_MEMORY_LIMIT = 4e9
DENSE_ROWS = {"msd", "msd2", "greedy", "mmdr (bitvector)"}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--sizes", type=ranged_list("sizes"), default="10,20,100,300,1000,10000",
                        help="comma-separated robot counts n for the runtime table (default: %(default)s)")
    parser.add_argument("--repeats", type=ranged("repeats"), default=5,
                        help="random instances timed per cell; the median is reported (default: %(default)s)")
    parser.add_argument("--quality-instances", type=ranged("quality-instances"), default=20000,
                        help="random 10x10 instances for the quality table, 0 to skip (default: %(default)s)")
    parser.add_argument("--time-limit", type=ranged("time-limit"), default=20.0,
                        help="skip a cell whose single call is predicted to take longer (seconds, default: %(default)s)")
    parser.add_argument("--methods", default="",
                        help="comma-separated row labels to run (default: all), e.g. 'mmd+msd2,mmdr (fast)'")
    parser.add_argument("--seed", type=ranged("seed"), default=2013, help="seed of the random instances (default: %(default)s)")


BenchmarkArgumentError = StudyArgumentError
"""A value the benchmark cannot use: the one argument error of studies and benchmarks."""


def _parse_methods(text: str) -> set[str]:
    """Row labels chosen with ``--methods`` (empty: all); unknown labels are an error."""
    wanted = {part.strip() for part in text.split(",") if part.strip()}
    unknown = sorted(wanted - {label for label, *_ in RUNTIME_ROWS})
    if unknown:
        valid = ", ".join(repr(label) for label, *_ in RUNTIME_ROWS)
        raise BenchmarkArgumentError(f"--methods: unknown row label(s) {', '.join(map(repr, unknown))}; valid: {valid}")
    return wanted


def _grid_instance(rng, n: int, side: int, d: int = 2):
    robots = rng.integers(0, side, (n, d)).astype(float)
    targets = rng.integers(0, side, (n, d)).astype(float)
    return robots, targets


def _time_call(call, min_seconds: float = 0.05) -> float:
    """Seconds per call, looping fast calls until ``min_seconds`` have passed."""
    start = time.perf_counter()
    call()
    elapsed = time.perf_counter() - start
    if elapsed >= min_seconds:
        return elapsed
    loops = max(1, int(min_seconds / max(elapsed, 1e-7)))
    start = time.perf_counter()
    for _ in range(loops):
        call()
    return (time.perf_counter() - start) / loops


def _format_ms(seconds: float) -> str:
    ms = seconds * 1e3
    if ms < 1:
        return f"{ms:.4f}"
    if ms < 100:
        return f"{ms:.2f}"
    return f"{ms:,.0f}"


def _runtime_table(args) -> None:
    import sys

    import numpy as np

    from agents.assignment import assign
    from experiments.reporting import Table

    sizes = args.sizes
    wanted = _parse_methods(args.methods)
    rows = [row for row in RUNTIME_ROWS if not wanted or row[0] in wanted]
    table = Table("Median time of one assign() call in milliseconds "
                  "(n robots, n targets, random integer points on an n² x n² grid)",
                  ["method", *(f"n = {n}" for n in sizes)])
    notes: list[str] = []
    rng = np.random.default_rng(args.seed)
    instances = {n: [_grid_instance(rng, n, n * n) for _ in range(max(1, args.repeats))] for n in sizes}
    # Warm-up: load numba's compiled kernels once so the first cell is not charged for it.
    warm = _grid_instance(rng, 6, 36)
    for _, method, algorithm in rows:
        assign(*warm, method=method, algorithm=algorithm, rng=0 if method == "random" else None)
    size_limits = _size_limits()
    for label, method, algorithm in rows:
        cells = []
        previous: tuple[int, float] | None = None
        skipped_reason = None
        for n in sizes:
            limit = size_limits.get(label)
            if skipped_reason is None and limit and n > limit[0]:
                skipped_reason = limit[1]
            if skipped_reason is None and label in DENSE_ROWS and 3 * 8 * n * n > DENSE_MEMORY_LIMIT:
                skipped_reason = f"dense n x n matrices need {3 * 8 * n * n / 1e9:.0f} GB"
            if skipped_reason is None and previous is not None:
                n0, t0 = previous
                predicted = t0 * (n / n0) ** GROWTH.get(label, DEFAULT_GROWTH)
                if predicted > args.time_limit:
                    skipped_reason = (f"predicted {predicted:,.0f} s per call at n = {n} "
                                      f"(from {t0:.3g} s at n = {n0}), over the {args.time_limit:g} s limit")
            if skipped_reason is not None:
                cells.append("—")
                continue
            times = []
            for robots, targets in instances[n]:
                times.append(_time_call(lambda: assign(robots, targets, method=method, algorithm=algorithm,
                                                        rng=1 if method == "random" else None)))
                if times[-1] > args.time_limit:
                    break
            median = float(np.median(times))
            previous = (n, median)
            cells.append(_format_ms(median))
            if sys.stderr.isatty():  # progress for a person watching; nothing in a log
                print(f"  {label:18s} n = {n:6d}: {_format_ms(median)} ms", file=sys.stderr, flush=True)
        if skipped_reason is not None:
            notes.append(f"{label}: {skipped_reason}")
        table.rows.append([label, *cells])
    table.print()
    for note in notes:
        print(f"  — {note}")


def _quality_table(args) -> None:
    import numpy as np

    from agents.assignment import assign
    from experiments.reporting import Table

    count = args.quality_instances
    labels = ("mmd+msd2", "mmdr", "msd2", "msd", "random", "greedy")
    makespans = {label: np.empty(count) for label in labels}
    means = {label: np.empty(count) for label in labels}
    spreads = {label: np.empty(count) for label in labels}
    rng = np.random.default_rng(args.seed + 1)
    pick = np.random.default_rng(args.seed + 2)
    for k in range(count):
        robots, targets = _grid_instance(rng, 10, 100)
        for label in labels:
            result = assign(robots, targets, method=label, rng=pick if label == "random" else None)
            makespans[label][k] = result.makespan
            means[label][k] = result.distances.mean()
            spreads[label][k] = result.distances.std()
    table = Table(f"Quality over {count:,} random instances: 10 robots, 10 targets, 100 x 100 integer grid",
                  ["method", "average makespan", "average distance", "distance std. dev."],
                  caption="distance std. dev.: standard deviation of the 10 distances of one assignment, "
                          "averaged over instances")
    for label in labels:
        table.rows.append([label, f"{makespans[label].mean():.2f}", f"{means[label].mean():.2f}",
                           f"{spreads[label].mean():.2f}"])
    table.print()


def run(args: argparse.Namespace) -> int:
    from experiments.commands.errors import fail

    try:
        _parse_methods(args.methods)
    except BenchmarkArgumentError as exc:
        return fail(str(exc))
    if args.sizes:
        _runtime_table(args)
    if args.quality_instances > 0:
        _quality_table(args)
    return 0
