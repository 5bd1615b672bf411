"""The benchmark's table and learning curves from a runs' folder of ``benchmark_baselines.py``
(``python examples/benchmark_baselines.py report --out DIR``; no torch needed).

* **Table**: per scenario, random actions (one evaluation: Wilson's interval of the goal rate,
  Student's t interval of the score difference over its episodes) and each trained baseline
  (PPO, MAPPO) over the seeds whose run is *finished* (trained to the budget and evaluated): the
  mean of the runs' goal rates and of their mean score differences with Student's t 95 %
  interval over seeds (none for a single seed; a goal rate's cut to [0, 1]). Runs not finished
  are listed with where they stand, never counted. The full match has a row per rung of the
  ladder and policy (``full-match v RUNG``): random actions and each baseline evaluated against
  that rung, aggregated the same way. It replaces the part of ``benchmark.md`` between
  :data:`BEGIN` and :data:`END`.
* **Curves**: every run's ``curve.csv`` up to its last checkpoint, gathered into
  ``figures/benchmark_curves.csv`` and drawn in ``figures/benchmark_curves.png`` (share of
  training episodes with a goal and mean episode return against environment steps, one line a
  run, a colour an algorithm; random actions' evaluated goal rate against the opponent the runs
  trained against dashed).
* ``figures/benchmark_evaluations.csv``: one row per evaluation the table uses.
"""

from __future__ import annotations

import csv
import math
from collections.abc import Sequence
from dataclasses import dataclass, replace
from pathlib import Path

from examples.benchmark_baselines import (ALGORITHMS, CURVE_FIELDS, FULL_MATCH, MAPPO, OPPONENT, PPO, RANDOM,
                                          BenchmarkError, RunSpec, RunStatus, evaluations, plan, random_dir,
                                          read_curve, run_status, training_opponent)
from experiments.stats import Estimate, estimate

BEGIN = "<!-- benchmark table: written by examples/benchmark_baselines.py report -->"
END = "<!-- end of benchmark table -->"
SMOOTHING = 10
"""Rollouts averaged (weighted by their episodes) in each point of the drawn curves."""
COLOURS = {PPO: "tab:blue", MAPPO: "tab:orange"}
LINES = ("-", "--", ":")
"""Line styles of the seeds (seed modulo 3)."""


@dataclass(frozen=True)
class Evaluation:
    """One ``soccer-sim evaluate`` result (its evaluation.csv)."""

    episodes: int
    goal_rate: Estimate
    score_difference: Estimate


def read_evaluation(directory: Path) -> Evaluation | None:
    """The evaluation written in ``directory``, None when it has not finished."""
    path = directory / "evaluation.csv"
    if not path.is_file():
        return None
    with open(path, newline="") as handle:
        row = next(csv.DictReader(handle))
    episodes = int(row["episodes"])
    rate = Estimate(episodes, float(row["goal_rate"]), math.nan, float(row["goal_rate_low"]),
                    float(row["goal_rate_high"]))
    difference = Estimate(episodes, float(row["mean_score_diff"]), float(row["score_diff_se"]),
                          float(row["score_diff_low"]), float(row["score_diff_high"]))
    return Evaluation(episodes, rate, difference)


@dataclass(frozen=True)
class TableRow:
    """A row of the baseline table: one policy on one scenario."""

    scenario: str
    policy: str
    env_steps: int | None
    """The training budget (None for random actions)."""
    runs: int
    """Evaluations averaged: finished seeds (1 for random actions)."""
    goal_rate: Estimate
    score_difference: Estimate
    per_seed: tuple[float, ...] = ()
    """The finished seeds' goal rates."""
    interval: str = "over seeds"
    opponent: str = OPPONENT
    """The away side of the evaluations: :data:`OPPONENT`, or a rung of the full match's ladder."""

    @property
    def situation(self) -> str:
        """The table's first cell: the scenario, with the rung on the full match (``full-match v idle``)."""
        return f"{self.scenario} v {self.opponent}" if self.scenario == FULL_MATCH else self.scenario


@dataclass(frozen=True)
class Baselines:
    rows: list[TableRow]
    unfinished: list[RunStatus]


def aggregate(out: Path, scenarios: Sequence[str], seeds: Sequence[int], budget: int,
              algorithms: Sequence[str] = ALGORITHMS) -> Baselines:
    """The table's rows and the runs not finished (see the module docstring)."""
    rows, unfinished = [], []
    for scenario in scenarios:
        finished: dict[str, list[tuple[RunSpec, int]]] = {}   # algorithm: (run, its environment steps)
        for algorithm in algorithms:
            finished[algorithm] = []
            for spec in plan([scenario], seeds, [algorithm]):
                status = run_status(spec, out, budget)
                if status.state == "finished":
                    finished[algorithm].append((spec, status.env_steps))
                else:
                    unfinished.append(status)
        for opponent, directory in evaluations(scenario, random_dir(out, scenario)):
            baseline = read_evaluation(directory)
            if baseline is not None:
                rows.append(TableRow(scenario, RANDOM, None, 1, baseline.goal_rate, baseline.score_difference,
                                     interval=f"{baseline.episodes} episodes", opponent=opponent))
            for algorithm in algorithms:
                results = [read_evaluation(dict(evaluations(scenario, spec.directory(out), steps))[opponent])
                           for spec, steps in finished[algorithm]]
                if results:
                    rates = [result.goal_rate.mean for result in results]
                    rows.append(TableRow(scenario, algorithm, budget, len(results), share_estimate(rates),
                                         estimate(result.score_difference.mean for result in results), tuple(rates),
                                         opponent=opponent))
    return Baselines(rows, unfinished)


def share_estimate(shares: Sequence[float]) -> Estimate:
    """The mean of ``shares`` (goal rates) with Student's t interval over them, cut to [0, 1]
    where a share lies (three seeds give t = 4.30, an interval often past 0 or 1)."""
    value = estimate(shares)
    if math.isnan(value.low):
        return value
    return replace(value, low=max(0.0, value.low), high=min(1.0, value.high))


def interval_text(value: Estimate, signed: bool = False) -> str:
    """``0.57 [0.39, 0.73]`` (the mean alone where the interval is undefined)."""
    sign = "+" if signed else ""
    if value.n == 0 or math.isnan(value.mean):
        return "-"
    if math.isnan(value.low):
        return f"{value.mean:{sign}.2f}"
    return f"{value.mean:{sign}.2f} [{value.low:{sign}.2f}, {value.high:{sign}.2f}]"


def above_random(row: TableRow, baseline: TableRow | None) -> str:
    """Whether the row's goal-rate interval lies wholly above random actions' (the sanity bar)."""
    if row.policy == RANDOM or baseline is None or math.isnan(row.goal_rate.low):
        return "-"
    if row.goal_rate.low > baseline.goal_rate.high:
        return "yes"
    if row.goal_rate.high < baseline.goal_rate.low:
        return "below"
    return "no (intervals overlap)"


def markdown(baselines: Baselines, budget: int) -> str:
    """The table and the list of runs not finished, as Markdown."""
    lines = ["| scenario | policy | env steps | runs | goal rate [95 % CI] | score difference [95 % CI] | "
             "goal rate per seed | above random |", "| --- | --- | ---: | ---: | --- | --- | --- | --- |"]
    randoms = {row.situation: row for row in baselines.rows if row.policy == RANDOM}
    for row in baselines.rows:
        steps = "-" if row.env_steps is None else f"{row.env_steps:,}"
        seeds = ", ".join(f"{rate:.2f}" for rate in row.per_seed) or "-"
        runs = f"{row.runs} ({row.interval})" if row.policy == RANDOM else str(row.runs)
        lines.append(f"| {row.situation} | {row.policy} | {steps} | {runs} | {interval_text(row.goal_rate)} | "
                     f"{interval_text(row.score_difference, signed=True)} | {seeds} | "
                     f"{above_random(row, randoms.get(row.situation))} |")
    if baselines.unfinished:
        lines += ["", "Runs not finished (not in the table):", ""]
        lines += [f"- {status.spec.name}: {status.state}, {status.env_steps:,} of {budget:,} environment steps"
                  + (f", evaluated against {status.evaluations_done} of "
                     f"{len(evaluations(status.spec.scenario, Path()))} opponents" if status.state == "trained" else "")
                  for status in baselines.unfinished]
    return "\n".join(lines) + "\n"


def replace_table(document: str, table: str) -> str:
    """``document`` with the part between :data:`BEGIN` and :data:`END` replaced by ``table``."""
    start, end = document.find(BEGIN), document.find(END)
    if start < 0 or end < start:
        raise BenchmarkError(f"benchmark.md has no table markers ({BEGIN!r} then {END!r}) to write between")
    return document[:start + len(BEGIN)] + "\n" + table + document[end:]


def curve_rows(out: Path, scenarios: Sequence[str], seeds: Sequence[int], budget: int,
               algorithms: Sequence[str] = ALGORITHMS) -> list[dict]:
    """Every run's curve up to its last checkpoint, with its algorithm, scenario and seed."""
    rows = []
    for spec in plan(scenarios, seeds, algorithms):
        status = run_status(spec, out, budget)
        for row in read_curve(spec.directory(out) / "curve.csv", status.env_steps):
            rows.append({"algorithm": spec.algorithm, "scenario": spec.scenario, "seed": spec.seed, **row})
    return rows


def smoothed(steps: Sequence[int], values: Sequence[float], weights: Sequence[int], window: int) -> tuple[list, list]:
    """Points of a curve averaged over ``window`` consecutive rollouts, weighted by their episodes
    (rollouts without an ended episode left out)."""
    kept = [(s, v, w) for s, v, w in zip(steps, values, weights) if w > 0 and not math.isnan(v)]
    xs, ys = [], []
    for start in range(0, len(kept), window):
        block = kept[start:start + window]
        total = sum(w for _, _, w in block)
        xs.append(block[-1][0])
        ys.append(sum(v * w for _, v, w in block) / total)
    return xs, ys


def draw(rows: Sequence[dict], randoms: dict[str, float], scenarios: Sequence[str], budget: int, path: Path) -> None:
    """The learning curves' figure (module docstring), written whole to ``path``."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from experiments.results.files import write_file

    figure, axes = plt.subplots(2, len(scenarios), figsize=(3.6 * len(scenarios), 6), sharex=True, squeeze=False)
    for column, scenario in enumerate(scenarios):
        top, bottom = axes[0][column], axes[1][column]
        mine = [row for row in rows if row["scenario"] == scenario]
        for (algorithm, seed) in sorted({(row["algorithm"], row["seed"]) for row in mine}):
            run = [row for row in mine if (row["algorithm"], row["seed"]) == (algorithm, seed)]
            style = {"color": COLOURS.get(algorithm, "black"), "linestyle": LINES[seed % len(LINES)], "linewidth": 1}
            args = ([row["env_steps"] for row in run], [row["episodes"] for row in run])
            top.plot(*smoothed(args[0], [row["goal_rate"] for row in run], args[1], SMOOTHING),
                     label=f"{algorithm} seed {seed}", **style)
            bottom.plot(*smoothed(args[0], [row["mean_return"] for row in run], args[1], SMOOTHING), **style)
        if scenario in randoms:
            top.axhline(randoms[scenario], color="grey", linestyle="--", label="random (evaluated)")
        if not mine:
            top.text(0.5, 0.5, "no checkpoint yet", ha="center", transform=top.transAxes)
        top.set_title(scenario, fontsize=10)
        top.set_ylim(-0.02, 1.02)
        bottom.set_xlim(0, budget)
        bottom.set_xlabel("environment steps")
        for axis in (top, bottom):
            axis.grid(alpha=0.3)
        if column == 0:
            top.set_ylabel("training episodes with a goal")
            bottom.set_ylabel("mean episode return")
        if top.get_legend_handles_labels()[0]:
            top.legend(fontsize=7)
    figure.suptitle(f"Training curves, {SMOOTHING} rollouts a point")
    figure.tight_layout()
    write_file(path, lambda temporary: figure.savefig(temporary, dpi=90, format="png"))
    plt.close(figure)


def write_csv(path: Path, header: Sequence[str], rows: Sequence[dict]) -> Path:
    from experiments.results.files import text_output

    with text_output(path, newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=header)
        writer.writeheader()
        writer.writerows(rows)
    return path


def evaluation_rows(out: Path, scenarios: Sequence[str], seeds: Sequence[int], budget: int,
                    algorithms: Sequence[str] = ALGORITHMS) -> list[dict]:
    """One row per finished evaluation (random actions and the finished runs)."""
    rows = []
    for scenario in scenarios:
        found = [(RANDOM, "", "", opponent, directory)
                 for opponent, directory in evaluations(scenario, random_dir(out, scenario))]
        for spec in plan([scenario], seeds, algorithms):
            status = run_status(spec, out, budget)
            if status.state == "finished":
                found += [(spec.algorithm, spec.seed, status.env_steps, opponent, directory)
                          for opponent, directory in evaluations(scenario, spec.directory(out), status.env_steps)]
        for policy, seed, steps, opponent, directory in found:
            result = read_evaluation(directory)
            if result is not None:
                rows.append({"policy": policy, "scenario": scenario, "opponent": opponent, "seed": seed,
                             "env_steps": steps, "episodes": result.episodes, "goal_rate": result.goal_rate.mean,
                             "goal_rate_low": result.goal_rate.low, "goal_rate_high": result.goal_rate.high,
                             "mean_score_diff": result.score_difference.mean,
                             "score_diff_low": result.score_difference.low,
                             "score_diff_high": result.score_difference.high})
    return rows


EVALUATION_FIELDS = ("policy", "scenario", "opponent", "seed", "env_steps", "episodes", "goal_rate", "goal_rate_low",
                     "goal_rate_high", "mean_score_diff", "score_diff_low", "score_diff_high")


def write_report(out: Path, docs: Path, scenarios: Sequence[str], seeds: Sequence[int], budget: int,
                 algorithms: Sequence[str] = ALGORITHMS) -> list[Path]:
    """The table in ``docs/benchmark.md``, the curves and the evaluations in ``docs/figures``."""
    from experiments.results.files import text_output

    document = docs / "benchmark.md"
    if not document.is_file():
        raise BenchmarkError(f"{document} does not exist: give --docs the folder holding benchmark.md")
    if not out.is_dir():
        raise BenchmarkError(f"{out} does not exist: give --out the runs' folder of benchmark_baselines.py run")
    baselines = aggregate(out, scenarios, seeds, budget, algorithms)
    updated = replace_table(document.read_text(), markdown(baselines, budget))
    figures = docs / "figures"
    curves = curve_rows(out, scenarios, seeds, budget, algorithms)
    randoms = {row.scenario: row.goal_rate.mean for row in baselines.rows
               if row.policy == RANDOM and row.opponent == training_opponent(row.scenario)}
    written = [write_csv(figures / "benchmark_curves.csv", ["algorithm", "scenario", "seed", *CURVE_FIELDS], curves),
               write_csv(figures / "benchmark_evaluations.csv", EVALUATION_FIELDS,
                         evaluation_rows(out, scenarios, seeds, budget, algorithms))]
    draw(curves, randoms, scenarios, budget, figures / "benchmark_curves.png")
    written.append(figures / "benchmark_curves.png")
    with text_output(document) as handle:
        handle.write(updated)
    written.append(document)
    return written
