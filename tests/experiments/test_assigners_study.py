"""``soccer-sim experiment assigners`` on tiny matches, and its statistics by hand."""

from __future__ import annotations

import numpy as np
import pytest

from experiments.cli import main
from experiments.runner import MatchSpec
from experiments.studies.assigners import MatchSummary, build_specs, goal_differences, mean_interval, team_figure


def summary(home, away, score, contacts=(0, 0), reported=({}, {})):
    return MatchSummary(home, away, 0, score, (0, 0), (0, 0), contacts, reported)


def test_each_seed_is_played_with_both_sides_at_home_and_parts_share_their_matches() -> None:
    params = {"parts": ["baselines", "claims"], "league": [], "claims": ["mmd+msd2"], "opponent": "random",
              "games": 3, "league_games": 2, "seed": 5, "cycles": 100}
    assert build_specs(params) == [MatchSpec("mmd+msd2", "random", 5, 100), MatchSpec("random", "mmd+msd2", 5, 100),
                                   MatchSpec("mmd+msd2", "random", 6, 100), MatchSpec("random", "mmd+msd2", 6, 100),
                                   MatchSpec("mmd+msd2", "statues", 5, 100), MatchSpec("statues", "mmd+msd2", 5, 100),
                                   MatchSpec("mmd+msd2", "statues", 6, 100), MatchSpec("statues", "mmd+msd2", 6, 100)]


def test_goal_differences_and_interval_by_hand() -> None:
    done = [summary("a", "b", (2, 0)), summary("b", "a", (1, 1)), summary("b", "a", (3, 0)), summary("c", "d", (9, 0))]
    gd = goal_differences(done, "a")
    assert gd.tolist() == [2.0, 0.0, -3.0]
    mean, se, low, high = mean_interval(gd)
    assert mean == pytest.approx(-1 / 3)
    assert se == pytest.approx(np.std([2, 0, -3], ddof=1) / np.sqrt(3))
    assert (high - mean) == pytest.approx(4.302653 * se, rel=1e-5)  # Student's t, 2 degrees of freedom
    figures = [summary("a", "b", (0, 0), contacts=(4, 9), reported=({"x": 1.5}, {"x": 7.0})),
               summary("b", "a", (0, 0), contacts=(2, 6), reported=({"x": 3.0}, {"x": 2.5}))]
    assert team_figure(figures, "a", "contacts").tolist() == [4.0, 6.0]
    assert team_figure(figures, "a", "x").tolist() == [1.5, 2.5]


def test_the_study_runs_end_to_end(capsys, tmp_path) -> None:
    code = main(["experiment", "assigners", "--league", "static,press-433", "--league-games", "2", "--games", "2",
                 "--assigners", "static", "--cycles", "120", "--workers", "1", "--out", str(tmp_path / "a.sqlite"),
                 "--no-progress"])
    assert code == 0
    out = capsys.readouterr().out
    for heading in ("league", "every team against chaser", "baselines", "claims", "longest stall", "95% CI"):
        assert heading in out


def test_an_unknown_team_is_refused(capsys) -> None:
    assert main(["experiment", "assigners", "--part", "claims", "--assigners", "nobody", "--workers", "1"]) == 2
    assert "unknown team 'nobody'" in capsys.readouterr().err
