"""``soccer-sim evaluate``: the protocol's seeds, the reported figures, the results store, bad input;
``tournament --scenario`` and a learned policy's own name in tables."""

from __future__ import annotations

import csv
import math

import pytest

from experiments.cli import main
from experiments.evaluation import EVALUATION_SEED_BASE, evaluation_seeds, summarise
from experiments.results.record import MatchRecord
from experiments.results.store import ResultStore
from experiments.stats import proportion

POLICY = "examples.high_level_team:team"


def test_evaluate_stores_its_episodes_and_reports_rates_with_intervals(tmp_path, capsys) -> None:
    out, tables = tmp_path / "e.sqlite", tmp_path / "t"
    arguments = ["evaluate", POLICY, "--scenario", "empty-goal", "--episodes", "3", "--workers", "1",
                 "--no-progress", "--out", str(out), "--tables", str(tables)]
    assert main(arguments) == 0
    printed = capsys.readouterr().out
    assert "high-level" in printed and POLICY not in printed.split("# goal rate")[0].split("\n", 2)[2]
    with ResultStore.open(out) as store:
        assert store.kind == "evaluation"
        assert sorted(r.seed for r in store.records()) == list(evaluation_seeds(3))
    row = next(csv.DictReader(open(tables / "evaluation.csv")))
    assert row["policy_name"] == "high-level" and row["policy"] == POLICY and row["episodes"] == "3"
    assert int(row["first_seed"]) == EVALUATION_SEED_BASE
    assert 0.0 <= float(row["goal_rate_low"]) <= float(row["goal_rate"]) <= float(row["goal_rate_high"]) <= 1.0
    assert main(arguments) == 0  # resumed: nothing left to play
    assert "played 0" in capsys.readouterr().out


@pytest.mark.parametrize("arguments, message", [
    (["nobody-at-all", "--scenario", "empty-goal"], "POLICY: unknown team 'nobody-at-all'"),
    (["static", "--scenario", "no-such-scenario"], "--scenario 'no-such-scenario': "),
    (["static", "--scenario", "empty-goal", "--opponent", "nobody-at-all"], "--opponent: unknown team"),
    (["static", "--scenario", "empty-goal", "--seed", str(2 ** 63 - 10)], "--seed must be at most"),
    (["static", "--scenario", "empty-goal", "--episodes", "0"], "--episodes: must be a positive integer"),
    (["static"], "required: --scenario"),
])
def test_bad_input_is_one_line_with_status_2_and_leaves_no_file(tmp_path, capsys, arguments, message) -> None:
    out = tmp_path / "e.sqlite"
    assert _status(["evaluate", *arguments, "--workers", "1", "--no-progress", "--out", str(out)]) == 2
    error = capsys.readouterr().err
    assert message in error and error.count("\n") == 1
    assert not out.exists()


def _status(arguments: list[str]) -> int:
    """The exit status of the command line (argparse's own errors exit)."""
    try:
        return main(arguments)
    except SystemExit as exit:
        return exit.code


def test_tournament_refuses_an_unknown_scenario(tmp_path, capsys) -> None:
    assert main(["tournament", "--teams", "static,idle", "--scenario", "nowhere", "--games", "2",
                 "--out", str(tmp_path / "r.sqlite"), "--no-progress"]) == 2
    assert "--scenario 'nowhere'" in capsys.readouterr().err
    assert not (tmp_path / "r.sqlite").exists()


def test_summary_counts_the_policys_forfeits_as_episodes_without_a_goal() -> None:
    records = []
    for seed, (home, away) in enumerate([(1, 0), (0, 2), (3, 1)]):
        record = MatchRecord("p", "o", seed, "h")
        record.home_goals, record.away_goals = home, away
        records.append(record)
    forfeited = MatchRecord("p", "o", 3, "h")
    forfeited.forfeit, forfeited.error = 0, "TeamError: boom"
    other = MatchRecord("p", "o", 4, "h")
    other.forfeit, other.error = 1, "TeamError: the opponent broke"
    summary = summarise([*records, forfeited, other], "p", "o")
    assert summary.episodes == 4 and summary.forfeits == 1
    assert summary.goal_rate.mean == pytest.approx(0.5)
    assert summary.score_difference.mean == pytest.approx((1 - 2 + 2) / 3)
    assert (summary.goals_for, summary.goals_against) == (4, 3)


def test_the_wilson_interval() -> None:
    low_high = proportion(17, 30)
    assert (low_high.low, low_high.high) == pytest.approx((0.3920, 0.7262), abs=1e-4)
    assert proportion(0, 10).low == 0.0 and proportion(0, 10).high > 0.2  # not empty at 0 successes
    assert math.isnan(proportion(0, 0).mean)


def test_a_path_team_is_shown_by_its_own_name_unless_that_name_is_taken() -> None:
    from experiments.commands.run_options import team_labels

    assert team_labels(["static", POLICY]) == {"static": "static", POLICY: "high-level"}
    same = "examples.high_level_team:team.__call__"  # another path to a team of the same own name
    assert team_labels([POLICY, same]) == {POLICY: POLICY, same: same}
    assert team_labels(["examples.scripted_team:ScriptedTeam", "examples.scripted_team:ScriptedTeam"]) == {
        "examples.scripted_team:ScriptedTeam": "scripted"}


def test_the_default_opponent_is_the_environments() -> None:
    from experiments.evaluation import DEFAULT_OPPONENT
    from soccer_sim.env.options import DEFAULT_OPPONENT as ENVIRONMENTS

    assert DEFAULT_OPPONENT == ENVIRONMENTS


def test_a_saved_checkpoint_is_evaluated_and_plays_in_a_tournament_by_its_own_name(tmp_path, monkeypatch,
                                                                                  capsys) -> None:
    """A checkpoint team name through the command line, its library a stand-in on the path that
    the worker processes import too (tests/env/rl_standins.py): no RL library is installed."""
    import numpy as np

    from tests.env import rl_standins

    module = rl_standins.sb3_module(tmp_path / "site")
    monkeypatch.setitem(__import__("sys").modules, "stable_baselines3", module)
    monkeypatch.syspath_prepend(str(tmp_path / "site"))  # spawned workers get the parent's path
    weights = np.random.default_rng(0).normal(size=(136, 5)).astype(np.float32) * 0.2
    path = rl_standins.write_sb3_checkpoint(tmp_path / "ppo.zip", weights, discrete=False)
    team = f"checkpoint:sb3:{path}?scenario=empty-goal&name=ppo-standin"
    out = tmp_path / "e.sqlite"
    assert main(["evaluate", team, "--scenario", "empty-goal", "--episodes", "2", "--workers", "1", "--no-progress",
                 "--out", str(out), "--tables", str(tmp_path / "t")]) == 0
    assert "ppo-standin" in capsys.readouterr().out
    with ResultStore.open(out) as store:
        records = store.records()
    assert len(records) == 2 and all(r.played and r.home == team for r in records)
    assert main(["tournament", "--teams", f"static,{team}", "--scenario", "empty-goal", "--games", "2",
                 "--workers", "1", "--no-progress", "--out", str(tmp_path / "r.sqlite")]) == 0
    league = capsys.readouterr().out
    assert "ppo-standin" in league and team not in league


@pytest.mark.parametrize("team, message", [
    ("checkpoint:sb3:nowhere.zip", "needs Stable-Baselines3 (module 'stable_baselines3')"),
    ("checkpoint:onnx:model.onnx", "KIND one of sb3, torch"),
])
def test_a_checkpoint_that_cannot_load_is_one_line_before_any_episode(tmp_path, monkeypatch, capsys, team,
                                                                       message) -> None:
    monkeypatch.setitem(__import__("sys").modules, "stable_baselines3", None)  # not installed
    out = tmp_path / "e.sqlite"
    assert _status(["evaluate", team, "--scenario", "empty-goal", "--workers", "1", "--no-progress",
                    "--out", str(out)]) == 2
    error = capsys.readouterr().err
    assert f"POLICY: team {team!r}: " in error and message in error and error.count("\n") == 1
    assert not out.exists()
