"""``soccer-sim experiment distributed`` end to end (small sizes)."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from agents.assignment import distributed_assign
from experiments.cli import main
from experiments.studies.distributed import fit_power_law, worst_case_instance

SMALL = ["experiment", "distributed", "--grid-sizes", "30,60", "--grid-trials", "2", "--etsp-sizes", "20,40",
         "--worst-sizes", "9,16", "--trials", "2", "--sweep-n", "30", "--sweep-areas", "0.1,1"]


def test_study_prints_tables_and_writes_csv_and_figures(tmp_path, capsys) -> None:
    assert main([*SMALL, "--out", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    for title in ("GRID ASSGMT, uniform, dense", "ETSP ASSGMT, uniform", "worst case of Theorem 4.2",
                  "fixed n across environment sizes", "fit: T ="):
        assert title in out
    with (tmp_path / "distributed_trials.csv").open() as handle:
        trials = list(csv.DictReader(handle))
    # 2 grid sizes x 2 + 2 etsp sizes x 2 + 2 worst cases + 2 areas x 2 algorithms x 2
    assert len(trials) == 4 + 4 + 2 + 8
    assert all(float(row["completion_time"]) > 0 for row in trials)
    with (tmp_path / "distributed_summary.csv").open() as handle:
        summary = list(csv.DictReader(handle))
    assert {row["series"] for row in summary} == {"grid-dense", "etsp-uniform", "etsp-worst", "sweep"}
    for name in ("distributed_scaling.png", "distributed_environment.png"):
        assert (tmp_path / name).read_bytes()[:4] == b"\x89PNG"


def test_study_is_reproducible(tmp_path) -> None:
    few = ["experiment", "distributed", "--grid-sizes", "30", "--grid-trials", "2", "--etsp-sizes", "20",
           "--worst-sizes", "", "--trials", "2", "--sweep-areas", ""]
    for folder in ("a", "b"):
        assert main([*few, "--out", str(tmp_path / folder)]) == 0
    columns = ("series", "algorithm", "n", "trial", "completion_time", "mean_distance", "rounds", "messages")
    rows = []
    for folder in ("a", "b"):
        with (tmp_path / folder / "distributed_trials.csv").open() as handle:
            rows.append([tuple(row[c] for c in columns) for row in csv.DictReader(handle)])
    assert rows[0] == rows[1]


@pytest.mark.parametrize(
    "option, value, message",
    [("--grid-sizes", "10,x", "argument --grid-sizes: each value must be an integer from 2 to 100000 (agents), got x"),
     ("--etsp-sizes", "1", "argument --etsp-sizes: each value must be an integer from 2 to 100000 (agents), got 1"),
     ("--worst-sizes", "99999999", "argument --worst-sizes: each value must be an integer from 2 to 100000"),
     ("--sweep-areas", "0", "argument --sweep-areas: each value must be a number in [1e-06, 1e+06]"),
     ("--trials", "0", "argument --trials: must be a positive integer up to 100000 (trials), got 0"),
     ("--grid-trials", "1e9", "argument --grid-trials: must be a positive integer up to 100000"),
     ("--sweep-n", "-3", "argument --sweep-n: must be a positive integer up to 100000"),
     ("--r-comm", "-1", "argument --r-comm: must be a positive number up to 1e+06 (metres), got -1"),
     ("--r-comm", "1e308", "argument --r-comm: must be a positive number up to 1e+06 (metres), got 1e308"),
     ("--round-fraction", "2", "argument --round-fraction: must be a positive number up to 1"),
     ("--seed", "-1", "argument --seed: must be a non-negative integer up to 9223372036854775807 (seed), got -1")],
)
def test_study_refuses_bad_options(option, value, message, capsys) -> None:
    with pytest.raises(SystemExit) as usage:
        main(["experiment", "distributed", option, value])
    assert usage.value.code == 2
    err = capsys.readouterr().err
    assert message in err and len(err.splitlines()) == 1


def test_worst_case_construction_makes_the_searcher_walk_the_ring() -> None:
    agents, targets, side = worst_case_instance(25, 10.0)
    result = distributed_assign(agents, targets, side, 10.0, algorithm="etsp")
    assert result.completed
    assert (result.distances[:-1] == 0).all()
    # The searcher visits every isolated target: at least the ring minus r_comm at each stop.
    assert result.distances[-1] > 24 * (25.0 - 2 * 10.0)
    assert result.completion_time == pytest.approx(result.distances[-1])


def test_power_law_fit_recovers_slope_and_factor() -> None:
    x = np.array([1.0, 10.0, 100.0])
    slope, factor = fit_power_law(x, 3.0 * x**0.5)
    assert slope == pytest.approx(0.5) and factor == pytest.approx(3.0)
