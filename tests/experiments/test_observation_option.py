"""``--observation`` on the commands that play matches: the configuration it selects, and a
clear refusal of teams that cannot play under it, before any match."""

from __future__ import annotations

import csv

import pytest

from experiments.cli import main
from experiments.configuration import match_config
from experiments.runner.spec import config_hash, paired_specs


def test_partial_observation_is_its_own_configuration():
    full, partial = match_config(None), match_config(None, "partial")
    assert full.observation.mode == "full" and partial.observation.mode == "partial"
    assert config_hash(full) != config_hash(partial)
    # full observation keeps the hash results files of earlier versions hold
    assert config_hash(full) == config_hash(match_config(None, "full"))
    specs = paired_specs("chaser", "idle", 2, 0, 100, "partial")
    assert [s.config().observation.mode for s in specs] == ["partial", "partial"]
    assert all(s.configuration is None for s in paired_specs("chaser", "idle", 2, 0, 100))


def test_a_team_that_cannot_play_partial_is_refused_before_any_match(tmp_path, capsys):
    out = tmp_path / "r.sqlite"
    full_only = "examples.formation_team:FormationTeam"
    code = main(["tournament", "--teams", f"chaser,{full_only}", "--games", "2", "--cycles", "50", "--observation",
                 "partial", "--out", str(out), "--no-progress", "--workers", "1"])
    assert code == 2
    assert f"team '{full_only}' cannot play under --observation partial" in capsys.readouterr().err
    assert not out.exists()
    assert main(["play", "chaser", "idle", "--cycles", "20", "--observation", "partial"]) == 0
    assert main(["play", full_only, "idle", "--cycles", "20", "--observation", "partial"]) == 2


@pytest.mark.slow  # the default suite keeps the refusal and `play --observation partial` above
def test_a_partial_tournament_plays_and_play_takes_the_option(tmp_path, capsys):
    out = tmp_path / "r.sqlite"
    code = main(["tournament", "--teams", "chaser,idle", "--games", "2", "--cycles", "60", "--observation",
                 "partial", "--out", str(out), "--no-progress", "--workers", "1"])
    assert code == 0 and out.exists()
    assert main(["play", "chaser", "idle", "--cycles", "40", "--observation", "partial"]) == 0
    assert main(["play", "examples.formation_team:FormationTeam", "idle", "--cycles", "40", "--observation",
                 "partial"]) == 2
    assert "cannot play under --observation partial" in capsys.readouterr().err


def test_a_partial_case_study_reports_the_decentralised_assignments_conflicts(tmp_path, capsys):
    out, tables = tmp_path / "cs.sqlite", tmp_path / "tables"
    assert main(["experiment", "case-study", "--teams", "mmdr,static", "--opponents", "idle", "--baseline", "static",
                 "--games", "2", "--cycles", "150", "--observation", "partial", "--out", str(out), "--tables",
                 str(tables), "--no-progress", "--workers", "1"]) == 0
    with open(tables / "behaviour.csv") as handle:
        rows = {row["team"]: row for row in csv.DictReader(handle)}
    for team in ("mmdr", "static"):
        assert 0.0 <= float(rows[team]["role_conflict_share"]) <= 1.0
        assert 0.0 <= float(rows[team]["believed_unfilled_share"]) <= 1.0
        assert float(rows[team]["target_distance_max"]) > 0.0
    assert "role conflicts (share)" in (tables / "case-study.md").read_text()
