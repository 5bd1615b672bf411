"""Statistics of stored matches against values computed by hand."""

from __future__ import annotations

import math

import pytest

from experiments.results.record import MatchRecord
from experiments.stats import (estimate, goal_differences, league_table, paired_comparison, paired_test,
                               pairing_summary, team_figure)


def match(home, away, seed, goals, contacts=(0, 0), error=None, forfeit=-1) -> MatchRecord:
    record = MatchRecord(home, away, seed, "h", error=error, forfeit=forfeit)
    if error is None:
        record.home_goals, record.away_goals = goals
        record.home_stats = {"goals": goals[0], "teammate_contacts": contacts[0]}
        record.away_stats = {"goals": goals[1], "teammate_contacts": contacts[1]}
    return record


def test_estimate_by_hand() -> None:
    # values 1, -1, 2, 0: mean 0.5, sample variance (0.25 + 2.25 + 2.25 + 0.25) / 3 = 5/3
    result = estimate([1, -1, 2, 0])
    se = math.sqrt(5 / 3) / 2
    assert result.n == 4 and result.mean == pytest.approx(0.5) and result.se == pytest.approx(se)
    t = 3.182446305284263                                   # Student's t, 97.5%, 3 degrees of freedom
    assert (result.low, result.high) == pytest.approx((0.5 - t * se, 0.5 + t * se))
    assert math.isnan(estimate([3]).se) and estimate([]).n == 0
    assert estimate([2, 2, 2]).se == 0.0


def test_pairing_summary_and_forfeits() -> None:
    records = [match("A", "B", 0, (2, 0)), match("B", "A", 0, (1, 1)), match("A", "B", 1, (0, 3)),
               match("B", "A", 1, None, error="TeamError: x", forfeit=1),       # A forfeits (away)
               match("C", "A", 0, None, error="WorkerDied", forfeit=-1),        # nobody blamed: left out
               match("A", "C", 0, (4, 0))]
    a_vs_b = pairing_summary(records, "A", "B")
    assert (a_vs_b.wins, a_vs_b.draws, a_vs_b.losses, a_vs_b.forfeits) == (1, 1, 2, 1)
    assert (a_vs_b.goals_for, a_vs_b.goals_against, a_vs_b.points) == (3, 4, 4)
    assert a_vs_b.goal_difference.n == 3 and a_vs_b.goal_difference.mean == pytest.approx((2 + 0 - 3) / 3)
    b_vs_a = pairing_summary(records, "B", "A")
    assert (b_vs_a.wins, b_vs_a.draws, b_vs_a.losses, b_vs_a.forfeits) == (2, 1, 1, 0)
    assert list(goal_differences(records, "A")) == [2, 0, -3, 4]
    table = league_table(records, ["C", "B", "A"])
    assert [row.team for row in table] == ["A", "B", "C"]           # A 7 points, B 7 points (GD lower), C 0
    assert [row.points for row in table] == [7, 7, 0]


def test_paired_comparison_by_hand() -> None:
    # A and B both meet O on seeds 0, 1, 2 with each side; A's GDs minus B's in the twin matches.
    records = []
    a_gd = {(0, 0): 2, (0, 1): 1, (1, 0): 0, (1, 1): 3, (2, 0): -1, (2, 1): 1}
    b_gd = {(0, 0): 1, (0, 1): 1, (1, 0): -1, (1, 1): 0, (2, 0): -1, (2, 1): 2}
    for team, gds in (("A", a_gd), ("B", b_gd)):
        for (seed, side), gd in gds.items():
            goals = (max(gd, 0), max(-gd, 0))
            records.append(match(team, "O", seed, goals) if side == 0 else match("O", team, seed, goals[::-1]))
    records.append(match("A", "B", 0, (5, 0)))                       # their own meeting is not a twin
    result = paired_comparison(records, "A", "B")
    differences = [a_gd[k] - b_gd[k] for k in sorted(a_gd)]
    from scipy import stats

    expected = stats.ttest_1samp(differences, 0.0)
    assert result.difference.n == 6
    assert result.difference.mean == pytest.approx(sum(differences) / 6)
    assert result.p_value == pytest.approx(expected.pvalue)
    assert math.isnan(paired_test([1.0, 1.0])[1])


def test_team_figure_mean_and_standard_error() -> None:
    records = [match("A", "B", 0, (1, 0), contacts=(2, 9)), match("B", "A", 0, (0, 0), contacts=(9, 4)),
               match("A", "B", 1, None, error="x", forfeit=0)]
    contacts = team_figure(records, "A", "teammate_contacts")
    assert contacts.n == 2 and contacts.mean == 3.0 and contacts.se == pytest.approx(1.0)
    assert team_figure(records, "A", "role_switches_per_minute").n == 0
