"""``soccer-sim tournament``, ``results export|show``, ``experiment case-study`` and
``experiment drop-in`` end to end with the trivial and scripted teams, and their bad input."""

from __future__ import annotations

import csv
import sys

import pytest

from experiments.cli import main
from tests.experiments.helpers import SCRIPTED

QUICK = ["--cycles", "200", "--workers", "2", "--no-progress"]


def test_tournament_tables_files_show_and_export(tmp_path, capsys) -> None:
    out = tmp_path / "t.sqlite"
    assert main(["tournament", "--teams", f"chaser,idle,{SCRIPTED}Forward", "--games", "3", "--out", str(out),
                 *QUICK]) == 0
    printed = capsys.readouterr().out
    assert "12 matches in" in printed and "0 failed" in printed          # 3 pairings x 4 (3 rounded up to even)
    assert "league: 3 teams, 12 matches" in printed and "mean goal difference of the row team" in printed
    tables = tmp_path / "t-tables"
    with open(tables / "league.csv") as handle:
        league = list(csv.DictReader(handle))
    assert [row["games"] for row in league] == ["8", "8", "8"]
    assert sum(int(row["goals_for"]) for row in league) == sum(int(row["goals_against"]) for row in league)
    with open(tables / "pairwise.csv") as handle:
        pairs = {(row["team"], row["opponent"]): float(row["mean_gd"]) for row in csv.DictReader(handle)}
    assert pairs[("chaser", "idle")] == -pairs[("idle", "chaser")]
    assert (tables / "tournament.png").stat().st_size > 10_000

    assert main(["results", "show", str(out)]) == 0
    shown = capsys.readouterr().out
    assert "tournament, 12 of 12 matches stored (0 failed)" in shown
    assert printed.split("league:", 1)[1].split("wrote")[0] == shown.split("league:", 1)[1]

    assert main(["results", "export", str(out), "--csv", str(tmp_path / "m.csv")]) == 0
    with open(tmp_path / "m.csv") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) == 12 and {"home_teammate_contacts", "away_distance_run", "traceback"} <= set(rows[0])
    pytest.importorskip("pyarrow")
    import pyarrow.parquet as pq

    assert main(["results", "export", str(out), "--parquet", str(tmp_path / "m.parquet")]) == 0
    table = pq.read_table(tmp_path / "m.parquet")
    assert table.num_rows == 12 and table.column("home_goals").to_pylist() == [int(r["home_goals"]) for r in rows]


def test_parquet_without_pyarrow_says_what_to_install(tmp_path, capsys, monkeypatch) -> None:
    out = tmp_path / "t.sqlite"
    assert main(["tournament", "--teams", "chaser,idle", "--games", "1", "--out", str(out), *QUICK]) == 0
    monkeypatch.setitem(sys.modules, "pyarrow", None)
    assert main(["results", "export", str(out), "--parquet", str(tmp_path / "m.parquet")]) == 2
    assert "pip install 'soccer-sim[parquet]'" in capsys.readouterr().err


def test_bad_input_gets_a_message_and_a_non_zero_status(tmp_path, capsys) -> None:
    out = str(tmp_path / "t.sqlite")
    assert main(["tournament", "--teams", "chaser,nobody", "--out", out, *QUICK]) == 2
    err = capsys.readouterr().err
    assert "unknown team 'nobody'" in err and "`soccer-sim teams` lists the" in err
    assert main(["tournament", "--teams", "chaser", "--out", out, *QUICK]) == 2
    assert "at least 2" in capsys.readouterr().err
    for bad in (["--games", "0"], ["--games", "-3"], ["--match-timeout", "0"], ["--seed", "-1"]):
        with pytest.raises(SystemExit) as usage:
            main(["tournament", *bad])
        assert usage.value.code == 2
        assert "must be a " in capsys.readouterr().err
    assert main(["tournament", "--teams", "chaser,idle", "--out", str(tmp_path / "no" / "t.sqlite"), *QUICK]) == 2
    assert "does not exist" in capsys.readouterr().err
    assert main(["tournament", "--teams", "chaser,idle", "--games", "1", "--out", out, *QUICK]) == 0
    capsys.readouterr()
    assert main(["tournament", "--teams", "chaser,idle", "--games", "1", "--out", out, "--cycles", "100",
                 "--workers", "1", "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert "different match configuration" in err and "to start fresh" in err
    assert main(["experiment", "case-study", "--teams", "chaser", "--opponents", "idle", "--baseline", "chaser",
                 "--out", out, *QUICK]) == 2
    assert "holds the results of 'tournament'" in capsys.readouterr().err
    assert main(["results", "show", str(tmp_path / "none.sqlite")]) == 2
    assert "no such results file" in capsys.readouterr().err
    assert main(["tournament", "--teams", "chaser,idle", "--address", "auto", "--out", out, *QUICK]) == 2
    assert "--address needs --backend ray" in capsys.readouterr().err


def test_help_points_to_the_list_of_registered_teams(capsys) -> None:
    with pytest.raises(SystemExit):
        main(["tournament", "--help"])
    assert "`soccer-sim teams` lists them" in " ".join(capsys.readouterr().out.split())


def test_case_study_tables(tmp_path, capsys) -> None:
    out = tmp_path / "c.sqlite"
    assert main(["experiment", "case-study", "--teams", f"chaser,{SCRIPTED}Forward", "--opponents", "idle,chaser",
                 "--baseline", "chaser", "--games", "2", "--out", str(out), *QUICK]) == 0
    printed = capsys.readouterr().out
    assert "8 matches in" in printed                      # chaser against itself: 2 matches on distinct seeds
    assert "goal difference per match" in printed and "behaviour per match" in printed
    tables = tmp_path / "c-tables"
    markdown = (tables / "case-study.md").read_text()
    assert "| team (assigner) | vs idle | vs chaser |" in markdown and "GD minus chaser (SE)" in markdown
    with open(tables / "case-study.csv") as handle:
        rows = list(csv.DictReader(handle))
    assert [(r["team"], r["opponent"], r["games"]) for r in rows] == [
        ("chaser", "idle", "2"), ("chaser", "chaser", "2"), (f"{SCRIPTED}Forward", "idle", "2"),
        (f"{SCRIPTED}Forward", "chaser", "2")]
    assert (tables / "case-study.png").exists() and (tables / "behaviour.csv").exists()
    assert main(["results", "show", str(out)]) == 0
    assert "case-study, 8 of 8 matches stored" in capsys.readouterr().out


def test_drop_in_pairs_the_candidates_game_by_game(tmp_path, capsys) -> None:
    from experiments.mixed_team import member_names
    from experiments.studies.drop_in import lineups

    params = {"candidates": ["chaser", "idle"], "pool": ["chaser", "idle"], "games": 4, "seed": 0, "cycles": 200}
    for game in lineups(params):
        chaser_spec, idle_spec = game.specs["chaser"], game.specs["idle"]
        assert chaser_spec.seed == idle_spec.seed == game.seed
        ours = (chaser_spec.home, chaser_spec.away)[game.side]
        twin = (idle_spec.home, idle_spec.away)[game.side]
        assert member_names(ours)[game.slot] == "chaser" and member_names(twin)[game.slot] == "idle"
        others = [m for i, m in enumerate(member_names(ours)) if i != game.slot]
        assert others == [m for i, m in enumerate(member_names(twin)) if i != game.slot]
        assert game.slot != 0                                # never the goalkeeper
    assert main(["experiment", "drop-in", "--candidates", "chaser,idle", "--pool", "chaser,idle", "--games", "4",
                 "--out", str(tmp_path / "d.sqlite"), *QUICK]) == 0
    printed = capsys.readouterr().out
    assert "8 matches in" in printed and "chaser minus idle" in printed
    with open(tmp_path / "d-tables" / "drop-in.csv") as handle:
        assert [row["games"] for row in csv.DictReader(handle)] == ["4", "4"]


def test_an_unimportable_team_path_says_how_to_make_it_importable(tmp_path, capsys) -> None:
    assert main(["tournament", "--teams", "chaser,nowhere_pkg.teams:Mine", "--out", str(tmp_path / "t.sqlite"),
                 "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert "cannot import module 'nowhere_pkg.teams'" in err and "PYTHONPATH" in err and "Traceback" not in err
