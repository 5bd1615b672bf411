"""``soccer-sim experiment incremental`` end to end on a small team."""

from __future__ import annotations

import csv

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


def test_incremental_study_refuses_a_bad_lambda(capsys) -> None:
    assert main(["experiment", "incremental", "--n", "10", "--trials", "1", "--lambdas", "0,1.5"]) == 2
