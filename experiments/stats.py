"""Statistics of stored matches: goal difference per pairing with standard errors and
confidence intervals, league tables, paired comparisons on shared seeds, per-team figures.

Every function takes :class:`~experiments.results.record.MatchRecord` lists. A forfeited match
(a team raised, sent a malformed command or overran its time budget) counts as a loss for the
team at fault and a win for the other in W/D/L and points, but it has no score, so it never
enters goals or goal differences. Failures no team is blamed for are left out everywhere.
Intervals use Student's t with n - 1 degrees of freedom.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

import numpy as np

from experiments.results.record import FORFEIT_NONE, MatchRecord

LEVEL = 0.95
"""Confidence level of every interval."""


@dataclass(frozen=True)
class Estimate:
    """Mean of ``n`` values with its standard error and confidence interval (nan where undefined)."""

    n: int
    mean: float
    se: float
    low: float
    high: float

    def text(self, signed: bool = True, digits: int = 2) -> str:
        """``+0.52 (0.11)``: mean and standard error."""
        if self.n == 0:
            return "-"
        sign = "+" if signed else ""
        se = "-" if math.isnan(self.se) else f"{self.se:.{digits}f}"
        return f"{self.mean:{sign}.{digits}f} ({se})"


def estimate(values: Iterable[float], level: float = LEVEL) -> Estimate:
    """Mean, standard error (sample standard deviation / sqrt(n)) and the Student-t interval."""
    from scipy import stats

    data = np.asarray(list(values), dtype=float)
    n = data.size
    if n == 0:
        return Estimate(0, math.nan, math.nan, math.nan, math.nan)
    mean = float(data.mean())
    if n < 2:
        return Estimate(1, mean, math.nan, math.nan, math.nan)
    se = float(data.std(ddof=1) / math.sqrt(n))
    half = float(stats.t.ppf(0.5 + level / 2, n - 1)) * se
    return Estimate(n, mean, se, mean - half, mean + half)


def proportion(successes: int, n: int, level: float = LEVEL) -> Estimate:
    """The share ``successes / n`` with its standard error and Wilson's score interval (which
    stays within [0, 1] and is not empty at 0 or n successes, unlike the normal one); nan where
    undefined (n = 0)."""
    from scipy import stats

    if n == 0:
        return Estimate(0, math.nan, math.nan, math.nan, math.nan)
    share = successes / n
    z = float(stats.norm.ppf(0.5 + level / 2))
    centre = (share + z * z / (2 * n)) / (1 + z * z / n)
    half = z / (1 + z * z / n) * math.sqrt(share * (1 - share) / n + z * z / (4 * n * n))
    return Estimate(n, share, math.sqrt(share * (1 - share) / n), max(0.0, centre - half), min(1.0, centre + half))


def sides_of(record: MatchRecord, team: str) -> list[int]:
    """The sides ``team`` plays in ``record``: [0], [1], [] or, against itself, [0] only (the
    home side stands for the team; the away side mirrors it)."""
    return [side for side, name in enumerate(record.names()) if name == team][:1]


def goal_difference(record: MatchRecord, side: int) -> int:
    """Goals for minus goals against of ``side`` in a played match."""
    goals = record.goals()
    return goals[side] - goals[1 - side]


def goal_differences(records: Iterable[MatchRecord], team: str, opponent: str | None = None) -> np.ndarray:
    """Goal difference of ``team`` in each of its played matches (against ``opponent`` only, if given)."""
    values = [goal_difference(r, side) for r in records if r.played for side in sides_of(r, team)
              if opponent is None or r.names()[1 - side] == opponent]
    return np.array(values, dtype=float)


@dataclass(frozen=True)
class PairingSummary:
    """A team's record against one opponent (or all of them, ``opponent`` None)."""

    team: str
    opponent: str | None
    wins: int
    draws: int
    losses: int
    forfeits: int
    """Matches the team lost by forfeit (included in ``losses``)."""
    goals_for: int
    goals_against: int
    goal_difference: Estimate
    """Per played match."""

    @property
    def games(self) -> int:
        return self.wins + self.draws + self.losses

    @property
    def points(self) -> int:
        return 3 * self.wins + self.draws


def pairing_summary(records: Iterable[MatchRecord], team: str, opponent: str | None = None) -> PairingSummary:
    """W/D/L, goals for and against and mean goal difference of ``team`` (against ``opponent``)."""
    sides = [(record, side) for record in records for side in sides_of(record, team)
             if opponent is None or record.names()[1 - side] == opponent]
    return side_summary(sides, team, opponent)


def side_summary(sides: Iterable[tuple[MatchRecord, int]], team: str, opponent: str | None = None) -> PairingSummary:
    """W/D/L, goals and mean goal difference over (match, side played) pairs."""
    wins = draws = losses = forfeits = goals_for = goals_against = 0
    differences = []
    for record, side in sides:
        if not record.played:
            if record.forfeit == side:
                losses, forfeits = losses + 1, forfeits + 1
            elif record.forfeit == 1 - side:
                wins += 1
            continue
        goals = record.goals()
        goals_for, goals_against = goals_for + goals[side], goals_against + goals[1 - side]
        difference = goals[side] - goals[1 - side]
        differences.append(difference)
        wins, draws, losses = wins + (difference > 0), draws + (difference == 0), losses + (difference < 0)
    return PairingSummary(team, opponent, wins, draws, losses, forfeits, goals_for, goals_against,
                          estimate(differences))


def league_table(records: Sequence[MatchRecord], teams: Sequence[str]) -> list[PairingSummary]:
    """Every team's record against all the others, best first (points, then mean goal
    difference, then name)."""
    rows = [pairing_summary(records, team) for team in teams]
    return sorted(rows, key=lambda r: (-r.points, -np.nan_to_num(r.goal_difference.mean, nan=-np.inf), r.team))


@dataclass(frozen=True)
class PairedComparison:
    """Team ``a`` minus team ``b``: goal differences against the same opponents on the same
    seeds and sides, paired match by match."""

    a: str
    b: str
    difference: Estimate
    p_value: float
    """Two-sided paired t-test of a zero mean difference (nan when undefined)."""


def paired_comparison(records: Sequence[MatchRecord], a: str, b: str,
                      opponents: Iterable[str] | None = None) -> PairedComparison:
    """Compare ``a`` and ``b`` where both met the same opponent on the same seed and side:
    a's goal difference in that match minus b's in its twin."""
    wanted = None if opponents is None else set(opponents)

    def by_situation(team: str) -> dict[tuple[str, int, int], int]:
        found = {}
        for record in records:
            if not record.played:
                continue
            for side in sides_of(record, team):
                opponent = record.names()[1 - side]
                if opponent in (a, b) or (wanted is not None and opponent not in wanted):
                    continue
                found[(opponent, record.seed, side)] = goal_difference(record, side)
        return found

    mine, theirs = by_situation(a), by_situation(b)
    summary, p_value = paired_test([mine[key] - theirs[key] for key in sorted(mine.keys() & theirs.keys())])
    return PairedComparison(a, b, summary, p_value)


def paired_test(differences: Iterable[float]) -> tuple[Estimate, float]:
    """The mean of paired differences and the two-sided p-value of Student's paired t-test
    (nan with fewer than two pairs or no spread)."""
    from scipy import stats

    summary = estimate(differences)
    if summary.n < 2 or not summary.se > 0:
        return summary, math.nan
    return summary, float(2 * stats.t.sf(abs(summary.mean / summary.se), summary.n - 1))


def p_text(p_value: float) -> str:
    """A p-value for a table (``-`` when undefined)."""
    return "-" if math.isnan(p_value) else f"{p_value:.3g}"


def team_figure(records: Iterable[MatchRecord], team: str, figure: str, opponent: str | None = None) -> Estimate:
    """Mean per played match of one of ``team``'s statistics (``teammate_contacts``,
    ``distance_run``, or one the team reports, e.g. ``role_switches_per_minute``); matches
    where it is missing are left out."""
    values = [r.stats(side)[figure] for r in records if r.played for side in sides_of(r, team)
              if figure in r.stats(side) and (opponent is None or r.names()[1 - side] == opponent)]
    return estimate(values)


def failures(records: Iterable[MatchRecord]) -> list[MatchRecord]:
    """The failed matches (forfeits and failures no team is blamed for)."""
    return [r for r in records if not r.played]


def unblamed(record: MatchRecord) -> bool:
    """Whether ``record`` failed with no team at fault (a worker or node lost outside team
    code, a storage or set-up problem): the match is missing from the tables, not a forfeit."""
    return record.error is not None and record.forfeit == FORFEIT_NONE


def blamed_team(record: MatchRecord) -> str | None:
    """The team that forfeited ``record``, or None."""
    return None if record.forfeit == FORFEIT_NONE else record.names()[record.forfeit]


def paired_cells(records: Sequence, team: str, baseline: str, opponents: Sequence[str]) -> tuple[list[str], list[float]]:
    """A study row's paired difference from ``baseline`` (:func:`paired_comparison` over
    ``opponents``): its printed cells (difference with its SE, p) and its numbers (difference,
    SE, p); empty cells and NaN for the baseline's own row."""
    if team == baseline:
        return ["", ""], [float("nan")] * 3
    paired = paired_comparison(records, team, baseline, opponents)
    return [paired.difference.text(), p_text(paired.p_value)], [paired.difference.mean, paired.difference.se,
                                                                 paired.p_value]


def figure_cell(records: Sequence, team: str, figure: str, scale: float) -> tuple[str, float, float]:
    """A team statistic's mean (SE) over ``team``'s matches, scaled: its printed cell (``-``
    without matches), mean and SE."""
    value = team_figure(records, team, figure)
    text = "-" if value.n == 0 else f"{value.mean * scale:.2f} ({value.se * scale:.2f})"
    return text, value.mean * scale, value.se * scale


@dataclass(frozen=True)
class RankAgreement:
    """How far two rankings of the same teams agree: Kendall's tau-b (1: the same order, -1:
    the reverse, 0: unrelated; ties count as tau-b counts them) over the ``n`` teams both rank,
    with the two-sided p-value of no association (nan where undefined: fewer than two teams,
    or a ranking with every team tied)."""

    tau: float
    p_value: float
    n: int

    def text(self) -> str:
        """``+0.60 (p 0.23, 5 teams)``."""
        if math.isnan(self.tau):
            return f"- ({self.n} teams)"
        return f"{self.tau:+.2f} (p {p_text(self.p_value)}, {self.n} teams)"


def rank_agreement(first: Sequence[float], second: Sequence[float]) -> RankAgreement:
    """Kendall's tau-b between two scores of the same teams (``first[k]`` and ``second[k]``
    are team k's, e.g. its mean goal difference in two engines; a higher score ranks higher);
    teams without a score in either (nan) are left out."""
    import warnings

    from scipy import stats

    pairs = [(a, b) for a, b in zip(first, second, strict=True) if not (math.isnan(a) or math.isnan(b))]
    if len(pairs) < 2:
        return RankAgreement(math.nan, math.nan, len(pairs))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")   # a constant ranking: scipy warns and answers nan
        result = stats.kendalltau([a for a, _ in pairs], [b for _, b in pairs])
    return RankAgreement(float(result.statistic), float(result.pvalue), len(pairs))


def ranking(scores: Sequence[float]) -> list[float]:
    """Each team's rank by its score (1 the highest; tied teams share the mean of their ranks;
    nan for a team without a score, which takes no rank)."""
    from scipy import stats

    known = [k for k, score in enumerate(scores) if not math.isnan(score)]
    ranks = [math.nan] * len(scores)
    for k, rank in zip(known, stats.rankdata([-scores[k] for k in known])):
        ranks[k] = float(rank)
    return ranks
