"""``soccer-sim experiment incremental`` end to end on a small team."""

from __future__ import annotations

import csv

import pytest

from experiments.cli import main


def test_incremental_study_prints_its_table_and_writes_csv_and_figure(tmp_path, capsys) -> None:
    code = main(["experiment", "incremental", "--n", "40", "--trials", "2", "--lambdas", "0,0.5,1",
                 "--out", str(tmp_path)])
    assert code == 0
    out = capsys.readouterr().out
    assert "0.5" in out
    files = {p.name for p in tmp_path.iterdir()}
    assert {"incremental_summary.csv", "incremental.png"} <= files
    with open(tmp_path / "incremental_summary.csv") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 3  # one row per lambda


@pytest.mark.parametrize("option, value, message", [
    ("--lambdas", "0,1.5", "argument --lambdas: each value must be a number in [0, 1] (diagonal scaling), got 1.5"),
    ("--seed", "-1", "argument --seed: must be a non-negative integer up to 9223372036854775807 (seed), got -1"),
    ("--n", "1", "argument --n: must be an integer from 2 to 100000 (robots), got 1"),
    ("--side", "1e308", "argument --side: must be a positive number up to 1e+06 (metres), got 1e308"),
    ("--degree", "0", "argument --degree: must be a positive integer up to 100000 (neighbours), got 0; or 'all'"),
])
def test_incremental_study_refuses_numbers_out_of_range(option, value, message, capsys) -> None:
    with pytest.raises(SystemExit) as usage:
        main(["experiment", "incremental", "--n", "10", "--trials", "1", option, value])
    assert usage.value.code == 2
    err = capsys.readouterr().err
    assert message in err and len(err.splitlines()) == 1


def test_incremental_study_needs_a_lambda(capsys) -> None:
    assert main(["experiment", "incremental", "--n", "10", "--trials", "1", "--lambdas", ","]) == 2
    assert "--lambdas: give at least one value" in capsys.readouterr().err
