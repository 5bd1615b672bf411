"""``soccer-sim bench lazy-assignment`` on tiny workspaces: the table, the files, equal totals."""

from __future__ import annotations

import csv

import numpy as np
import pytest

from experiments.benchmarks import grid_assignment
from experiments.cli import main

TINY = ["--sizes", "20,30", "--robots", "6,12", "--densities", "0.2,0.1", "--sizes-3d", "8", "--repeats", "2"]


def test_tiny_table_writes_csv_and_plot_and_both_methods_agree(tmp_path, capsys) -> None:
    out = tmp_path / "lazy"
    assert main(["bench", "lazy-assignment", *TINY, "--seed", "3", "--out", str(out)]) == 0
    printed = capsys.readouterr().out
    assert "both totals equal on every one" in printed
    with (out / "table.csv").open() as handle:
        table = list(csv.DictReader(handle))
    # 2 sizes x 2 robot counts at 20%, 1 extra density at the smallest size, 1 cube.
    assert [(r["workspace"], float(r["density"]), int(r["robots"])) for r in table] == [
        ("20x20", 0.2, 6), ("30x30", 0.2, 6), ("20x20", 0.2, 12), ("30x30", 0.2, 12), ("20x20", 0.1, 6),
        ("8x8x8", 0.2, 6)]
    for r in table:
        assert 0 < float(r["pairs_lazy_mean"]) <= int(r["pairs_all"]) == int(r["robots"]) ** 2
    with (out / "trials.csv").open() as handle:
        assert len(list(csv.DictReader(handle))) == 12
    assert (out / "speedup.png").stat().st_size > 1000


def test_same_seed_same_instances(tmp_path) -> None:
    totals = []
    for run in range(2):
        out = tmp_path / str(run)
        assert main(["bench", "lazy-assignment", *TINY, "--out", str(out)]) == 0
        with (out / "trials.csv").open() as handle:
            totals.append([(r["pairs_lazy"], r["total"]) for r in csv.DictReader(handle)])
    assert totals[0] == totals[1]


@pytest.mark.parametrize("bad, message", [
    (["--sizes", "ten"], "argument --sizes: each value must be an integer from 2 to 10000 (cells a side), got ten"),
    (["--densities", "0.2,1.5"], "argument --densities: each value must be a number in [0, 0.99] (obstacle share)"),
    (["--repeats", "0"], "argument --repeats: must be a positive integer up to 1000 (repetitions), got 0"),
    (["--robots", "0"], "argument --robots: each value must be a positive integer up to 100000 (robots), got 0"),
    (["--sizes-3d", "100000"], "argument --sizes-3d: each value must be an integer from 2 to 500"),
    (["--seed", "-1"], "argument --seed: must be a non-negative integer"),
])
def test_bad_options_are_named(bad, message, capsys) -> None:
    with pytest.raises(SystemExit) as usage:
        main(["bench", "lazy-assignment", *bad])
    assert usage.value.code == 2
    assert message in capsys.readouterr().err


def test_an_empty_list_is_named(capsys) -> None:
    assert main(["bench", "lazy-assignment", "--robots", ""]) == 2
    assert "--sizes, --robots and --densities need at least one value each" in capsys.readouterr().err


def test_unequal_totals_stop_the_benchmark(monkeypatch) -> None:
    """A lazy method that returned a worse assignment would be caught, not reported."""
    real = grid_assignment.assign_on_grid

    def worse(grid, robots, goals, method):
        result = real(grid, robots, goals, method=method)
        if method == "lazy":
            result.distances = np.asarray(result.distances) + 1.0
        return result

    monkeypatch.setattr(grid_assignment, "assign_on_grid", worse)
    row = grid_assignment.Row((20, 20), 0.2, 5)
    with pytest.raises(grid_assignment.AssignmentError, match="differs from all-pairs total"):
        grid_assignment.play_row(row, 1, np.random.default_rng(0))


def test_paper_figures_are_found_for_its_rows() -> None:
    assert grid_assignment.Row((400, 400), 0.2, 200).paper == (1901, 355, 22, 16.1)
    assert grid_assignment.Row((40, 40, 40), 0.2, 100).paper is None
    # the paper's density block at 200 x 200 with 200 robots
    assert grid_assignment.Row((200, 200), 0.25, 200).paper == (2312, 81, 10, 8.1)
    assert grid_assignment.Row((300, 300), 0.2, 100).paper == (732, 94, 5, 18.8)
