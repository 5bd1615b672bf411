"""``soccer-sim experiment assigners`` on the shared runner: a failing or hanging team is a
forfeit, not the end of the study; a stopped study resumes; the tables do not depend on the
number of workers or on resuming; ``results show`` repeats them; the study's own figures of
a match are the same whether the match is played in a worker or here."""

from __future__ import annotations

import json

import pytest

from experiments.cli import main
from experiments.runner import MatchSpec, config_for, run_matches
from experiments.studies.assigners import SET_PLAY_PREFIX, STALL_FIGURE, MatchSummary, StudyFigures
from tests.experiments.helpers import SCRIPTED, outcome

STUDY = ["experiment", "assigners", "--cycles", "60", "--no-progress"]


def tables_only(out: str) -> list[str]:
    """The printed tables and lines of the study, without the runner's and the file lines."""
    return [line for line in out.splitlines() if " matches in " not in line and not line.startswith("wrote ")]


@pytest.mark.slow  # test_runner_failures and test_play_robustness keep both cases in the default suite
def test_a_failing_and_a_hanging_team_forfeit_and_the_study_goes_on(tmp_path, capsys) -> None:
    raising, hanging = SCRIPTED + "RaisingTeam", SCRIPTED + "HangingTeam"
    code = main([*STUDY, "--part", "league", "--league", f"idle,chaser,{raising},{hanging}", "--league-games", "2",
                 "--workers", "2", "--match-timeout", "2", "--out", str(tmp_path / "a.sqlite")])
    out, err = capsys.readouterr()
    assert code == 0, err
    assert "Traceback" not in err and "error" not in err
    assert "league: 2 matches between 4 teams" in out              # idle v chaser, both seeds' sides
    assert f"forfeited by {raising}" in out and "MatchTimeout" in out
    assert (tmp_path / "a-tables" / "league.csv").is_file() and (tmp_path / "a-tables" / "assigners.md").is_file()


@pytest.mark.slow  # test_runner_resume keeps resumed runs in the default suite
def test_a_resumed_study_gives_the_same_tables_as_one_run_and_as_results_show(tmp_path, capsys) -> None:
    from experiments.results.store import ResultStore

    whole, resumed = tmp_path / "whole.sqlite", tmp_path / "resumed.sqlite"
    forward = SCRIPTED + "Forward"
    chaser_part = [*STUDY, "--part", "chaser", "--league-games", "2", "--json"]
    teams = ["--league", f"idle,{forward}", "--assigners", forward]
    assert main([*chaser_part, *teams, "--workers", "2", "--out", str(whole)]) == 0
    reference = json.loads(capsys.readouterr().out)["tables"]
    (table,) = reference
    assert table["title"] == "every team against chaser"
    assert [row[:2] for row in table["rows"]] == [["idle", 2], [forward, 2]]
    # Half of the study first (as if stopped), then all of it: only the rest is played.
    assert main([*chaser_part, "--league", "idle", "--assigners", "idle", "--workers", "1", "--out", str(resumed)]) == 0
    capsys.readouterr()
    with ResultStore.open(resumed) as store:
        first = {record.key: record for record in store.records()}
    assert main([*chaser_part, *teams, "--workers", "1", "--out", str(resumed)]) == 0
    assert json.loads(capsys.readouterr().out)["tables"] == reference
    with ResultStore.open(resumed) as store, ResultStore.open(whole) as one_run:
        records = store.records()
        assert outcome(records) == outcome(one_run.records())
    assert len(first) == 2 and len(records) == 4
    assert all(record == first[record.key] for record in records if record.key in first)    # not played again
    assert main(["results", "show", str(resumed), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["tables"] == reference


def test_the_studys_figures_are_the_same_in_a_worker_and_here(tmp_path) -> None:
    from soccer_sim import run_match

    spec = MatchSpec("chaser", "static", 3, 400)
    (record,) = run_matches([spec], tmp_path / "f.sqlite", "assigners", {}, cycles=400, workers=1, progress=False,
                            figures=StudyFigures).records
    here = StudyFigures()
    result = run_match("chaser", "static", seed=3, config=config_for(400), recorders=[here])
    summary = MatchSummary.of(record)
    assert summary.score == tuple(int(g) for g in result.score)
    assert summary.longest_stall == here.longest > 0
    assert summary.set_plays == dict(here.set_plays) and summary.set_plays   # a kick-off at least
    assert record.home_stats[STALL_FIGURE] == record.away_stats[STALL_FIGURE]
    assert all(name.startswith(SET_PLAY_PREFIX) for name in record.home_stats if "set_play" in name)


@pytest.mark.slow  # Ray start-up: the default suite keeps one Ray run of each kind
def test_on_ray_the_study_records_the_same_figures_as_on_the_local_pool(tmp_path, capsys) -> None:
    pytest.importorskip("ray")
    from experiments.results.store import ResultStore

    common = [*STUDY, "--part", "chaser", "--league", "idle", "--assigners", "idle", "--league-games", "2",
              "--workers", "2"]
    assert main([*common, "--backend", "ray", "--out", str(tmp_path / "ray.sqlite")]) == 0
    on_ray = tables_only(capsys.readouterr().out)
    assert main([*common, "--out", str(tmp_path / "local.sqlite")]) == 0
    assert tables_only(capsys.readouterr().out) == on_ray
    with ResultStore.open(tmp_path / "ray.sqlite") as ray, ResultStore.open(tmp_path / "local.sqlite") as local:
        figures = [{k: v for k, v in r.home_stats.items() if k == STALL_FIGURE or k.startswith(SET_PLAY_PREFIX)}
                   for r in ray.records()]
        assert figures and all(STALL_FIGURE in f for f in figures)
        assert figures == [{k: v for k, v in r.home_stats.items() if k == STALL_FIGURE or k.startswith(SET_PLAY_PREFIX)}
                           for r in local.records()]
