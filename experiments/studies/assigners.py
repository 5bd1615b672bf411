"""``soccer-sim experiment assigners``: does positioning matter, and what do the role assigners do?

Four parts, each a set of matches on paired seeds: seed ``s`` is played twice, once with each
team at home, so that both sides of the pitch and both halves' noise are shared.

* **league**: every pairing of the built-in teams given with ``--league`` (default: the
  assigner variants and the reference opponents): goals, shots and passes per match, every
  kind of set play, and the longest stretch of play on with the ball barely moving (within
  3 m) -- is it soccer?
* **chaser**: each of those teams against ``chaser`` (everybody runs at the ball).
* **baselines**: ``mmd+msd2`` against ``random`` and against ``statues`` (outfield players who
  never leave their kick-off spots): the mean goal difference with its standard error and
  95% confidence interval -- does positioning matter?
* **claims**: each assigner of ``--assigners`` against the same opponent (``--opponent``):
  role switches per minute, teammate contacts and distances to the role targets per match --
  SCRAM's claims in our game (MMDR switches least, SCRAM teams collide least).

The matches run on the local worker pool of every command that plays many matches
(``--workers``, ``--match-timeout``) and are stored in a results file (``--out``): re-running
the same command continues it, and a team that fails forfeits its match without stopping the
study. The tables (from the matches played to their end) are printed and written as Markdown
and CSV to ``--tables``.
"""

from __future__ import annotations

import argparse
import itertools
import math
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from experiments.limits import ranged

if TYPE_CHECKING:
    from experiments.reporting import Table

KIND = "assigners"
PARTS = ("league", "chaser", "baselines", "claims")
STALL_RADIUS = 3.0
"""The ball 'barely moves' while it stays within this distance of where it was (m)."""
STALL_FIGURE = "match_longest_stall"
SET_PLAY_PREFIX = "match_set_play_"
"""The study's figures of the whole match, stored with both teams' statistics."""

DEFAULT_LEAGUE = ("mmdr", "mmd+msd2", "static", "greedy", "bidding", "counter-442", "press-433", "possession")
DEFAULT_CLAIMS = ("mmdr", "mmd+msd2", "greedy", "greedy-offense", "static", "bidding")


@dataclass
class MatchSummary:
    """What the study keeps of one match (home first)."""

    home: str
    away: str
    seed: int
    score: tuple[int, int]
    shots: tuple[int, int]
    passes: tuple[int, int]
    contacts: tuple[int, int]
    reported: tuple[dict[str, float], dict[str, float]]
    """Each side's statistics, the figures its team reports included."""
    set_plays: dict[str, int] = field(default_factory=dict)
    longest_stall: int = 0
    """Longest run of play-on cycles with the ball within STALL_RADIUS of one point."""
    seconds: float = 0.0

    @classmethod
    def of(cls, record) -> MatchSummary:
        """The summary of a stored match played to its end (a
        :class:`~experiments.results.record.MatchRecord` with the study's figures)."""
        home, away = record.home_stats, record.away_stats
        set_plays = {name[len(SET_PLAY_PREFIX):]: int(count) for name, count in home.items()
                     if name.startswith(SET_PLAY_PREFIX)}
        return cls(record.home, record.away, record.seed, record.goals(), (home["shots"], away["shots"]),
                   (home["passes"], away["passes"]), (home["teammate_contacts"], away["teammate_contacts"]),
                   (dict(home), dict(away)), set_plays, int(home.get(STALL_FIGURE, 0)), record.wall_time)


class StudyFigures:
    """Recorder run in the worker with every match of the study: the longest stretch of play
    on with the ball barely moving, and the set plays of each kind (see
    :class:`~experiments.runner.worker.MatchFigures`)."""

    def on_start(self, match) -> None:
        import numpy as np

        self.anchor: np.ndarray | None = None
        self.since = 0
        self.longest = 0
        self.set_plays: Counter[str] = Counter()

    def on_cycle(self, match) -> None:
        from soccer_sim.state import PlayMode

        state = match.state
        if state.play_mode != PlayMode.PLAY_ON:
            self.anchor = None
            return
        if self.anchor is None or math.dist(state.ball, self.anchor) > STALL_RADIUS:
            self.anchor, self.since = state.ball.copy(), state.cycle
        self.longest = max(self.longest, state.cycle - self.since)

    def on_end(self, match) -> None:
        from soccer_sim import EventKind, PlayMode

        events = match.events.as_arrays()
        modes = events["detail"][events["kind"] == EventKind.SET_PLAY]
        self.set_plays = Counter(PlayMode(int(m)).name.lower() for m in modes
                                 if m not in (PlayMode.PLAY_ON, PlayMode.TIME_OVER))

    def figures(self) -> dict[str, float]:
        return {STALL_FIGURE: self.longest,
                **{SET_PLAY_PREFIX + kind: count for kind, count in sorted(self.set_plays.items())}}


def goal_differences(summaries: list[MatchSummary], team: str) -> np.ndarray:
    """Goal difference of ``team`` in each of its matches."""
    import numpy as np

    return np.array([(s.score[0] - s.score[1]) * (1 if s.home == team else -1) for s in summaries
                     if team in (s.home, s.away)], dtype=float)


def mean_interval(values: np.ndarray, level: float = 0.95) -> tuple[float, float, float, float]:
    """(mean, standard error, low, high) of ``values``, the interval from Student's t."""
    from scipy import stats

    n = values.size
    mean = float(values.mean()) if n else math.nan
    if n < 2:
        return mean, math.nan, math.nan, math.nan
    se = float(values.std(ddof=1) / math.sqrt(n))
    half = float(stats.t.ppf(0.5 + level / 2, n - 1)) * se
    return mean, se, mean - half, mean + half


def team_figure(summaries: list[MatchSummary], team: str, figure: str) -> np.ndarray:
    """Per match, one of ``team``'s figures: a reported one or ``contacts``."""
    import numpy as np

    values = []
    for s in summaries:
        for side, name in enumerate((s.home, s.away)):
            if name == team:
                values.append(s.contacts[side] if figure == "contacts" else s.reported[side].get(figure, math.nan))
    return np.array(values, dtype=float)


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.commands import doc_summary
    from experiments.commands.run_options import add_run_arguments

    parser.description = doc_summary(__doc__)
    parser.add_argument("--part", choices=("all", *PARTS), default="all")
    parser.add_argument("--games", type=ranged("games"), default=100,
                        help="matches per pairing, sides swapped on paired seeds (default: 100)")
    parser.add_argument("--league", default=",".join(DEFAULT_LEAGUE), help="teams of the league part")
    parser.add_argument("--league-games", type=ranged("league-games"), default=8,
                        help="matches per pairing in the league part (default: 8)")
    parser.add_argument("--assigners", default=",".join(DEFAULT_CLAIMS), help="teams of the claims part")
    parser.add_argument("--opponent", default="press-433", help="opponent of the claims part")
    add_run_arguments(parser, "assigners.sqlite")


def run(args: argparse.Namespace) -> int:
    from experiments.commands.run_options import run_command

    return run_command(args, KIND, _params, build_specs, report, figures=StudyFigures)


def _params(args: argparse.Namespace) -> dict:
    """The study's parameters, every team list checked (a RunInputError naming the option)."""
    from experiments.commands.run_options import RunInputError, team_list

    parts = list(PARTS) if args.part == "all" else [args.part]
    league = team_list(args.league, "--league", 2 if "league" in parts else 0)
    claims = team_list(args.assigners, "--assigners", 1 if "claims" in parts else 0)
    opponent = team_list(args.opponent, "--opponent", 1)
    if len(opponent) != 1:
        raise RunInputError(f"--opponent: give one team, got {args.opponent!r}")
    if "chaser" in parts and not (league or claims):
        raise RunInputError("the chaser part needs a team in --league or --assigners")
    return {"parts": parts, "league": league, "claims": claims, "opponent": opponent[0], "games": args.games,
            "league_games": args.league_games, "seed": args.seed, "cycles": args.cycles}


def groups(params: dict) -> list[tuple[str, str, list]]:
    """(part, team or opponent, specs) of every table row of the study, in table order."""
    from experiments.runner.spec import paired_specs

    seed, cycles, league, claims = params["seed"], params["cycles"], params["league"], params["claims"]
    found = []
    if "league" in params["parts"]:
        found.append(("league", "", [spec for a, b in itertools.combinations(league, 2)
                                     for spec in paired_specs(a, b, params["league_games"], seed, cycles)]))
    if "chaser" in params["parts"]:
        found += [("chaser", team, paired_specs(team, "chaser", params["league_games"], seed, cycles))
                  for team in dict.fromkeys([*league, *claims])]
    if "baselines" in params["parts"]:
        found += [("baselines", opponent, paired_specs("mmd+msd2", opponent, params["games"], seed, cycles))
                  for opponent in ("random", "statues")]
    if "claims" in params["parts"]:
        found += [("claims", team, paired_specs(team, params["opponent"], params["games"], seed, cycles))
                  for team in claims]
    return found


def build_specs(params: dict) -> list:
    """Every match of the study once (parts share the matches they have in common)."""
    return list(dict.fromkeys(spec for _, _, specs in groups(params) for spec in specs))


def report(records: Sequence, params: dict, out_dir: Path | None = None) -> list[Path]:
    """Print the tables of the parts run, from the matches played to their end (in the order
    the study lists them); with ``out_dir`` write them as assigners.md and one CSV per part."""
    from experiments.reporting import write_csv, write_markdown

    by_key = {record.key: record for record in records if record.played}
    tables: dict[str, Table] = {}
    league_lines: list[str] = []
    for part, name, specs in groups(params):
        done = [MatchSummary.of(by_key[spec.key]) for spec in specs if spec.key in by_key]
        if part == "league":
            league_lines = _league(done, params, tables)
        else:
            _row(part, name, done, params, tables)
    for part in PARTS:
        if part in tables:
            tables[part].print()
        if part == "league":
            for line in league_lines:
                print(line)
    if out_dir is None:
        return []
    written = [write_csv(out_dir / f"{part}.csv", table.header, table.rows) for part, table in tables.items()]
    cycles = params["cycles"] or "regulation (6000)"
    written.append(write_markdown(out_dir / "assigners.md", list(tables.values()),
                                  f"Assigners study: seeds from {params['seed']}, cycles per match: {cycles}."
                                  + "".join(f"\n\n{line}" for line in league_lines)))
    print("wrote " + ", ".join(str(path) for path in written))
    return written


def _table(tables: dict[str, Table], part: str, title: str, header: list[str]) -> Table:
    """The table of ``part`` (made on its first row)."""
    from experiments.reporting import Table

    if part not in tables:
        tables[part] = Table(title, header)
    return tables[part]


def _league(done: list[MatchSummary], params: dict, tables: dict[str, Table]) -> list[str]:
    """The league table (added to ``tables``) and its two lines of text."""
    import numpy as np

    if not done:
        return ["league: no match was played to its end"]
    goals = np.array([sum(s.score) for s in done], float)
    shots = np.array([sum(s.shots) for s in done], float)
    passes = np.array([sum(s.passes) for s in done], float)
    stalls = np.array([s.longest_stall for s in done], float)
    kinds = Counter()
    for s in done:
        kinds.update({k: 1 for k in s.set_plays})
    table = _table(tables, "league", f"league: {len(done)} matches between {len(params['league'])} teams",
                   ["per match (both teams)", "mean", "std. error", "max"])
    table.rows += [[name, f"{v.mean():.2f}", f"{v.std(ddof=1) / math.sqrt(v.size):.2f}", f"{v.max():.0f}"]
                   for name, v in (("goals", goals), ("shots", shots), ("passes received", passes),
                                   ("longest stall (cycles)", stalls))]
    worst = max(done, key=lambda s: s.longest_stall)
    return ["matches with each kind of set play: " + ", ".join(f"{k} {v}" for k, v in sorted(kinds.items())),
            f"longest stall: {worst.longest_stall} cycles, {worst.home} v {worst.away}, seed {worst.seed}"]


def _row(part: str, name: str, done: list[MatchSummary], params: dict, tables: dict[str, Table]) -> None:
    """One row of the chaser, baselines or claims table (``-`` where no match was played)."""
    if part == "chaser":
        gd = goal_differences(done, name)
        table = _table(tables, part, "every team against chaser", ["team", "games", "mean GD", "worst GD"])
        table.rows.append([name, str(gd.size), f"{gd.mean():+.2f}" if gd.size else "-",
                           f"{gd.min():+.0f}" if gd.size else "-"])
    elif part == "baselines":
        gd = goal_differences(done, "mmd+msd2")
        mean, se, low, high = mean_interval(gd)
        wins, draws = int((gd > 0).sum()), int((gd == 0).sum())
        table = _table(tables, part, "baselines: goal difference of mmd+msd2",
                       ["pairing", "games", "mean GD", "SE", "95% CI", "W/D/L"])
        table.rows.append([f"mmd+msd2 vs {name}", str(gd.size), f"{mean:+.2f}", f"{se:.2f}",
                           f"[{low:+.2f}, {high:+.2f}]", f"{wins}/{draws}/{gd.size - wins - draws}"])
    else:
        gd = goal_differences(done, name)
        table = _table(tables, part, f"claims: each assigner against {params['opponent']}, {params['games']} games, "
                                     "mean (SE) per match",
                       ["team", "GD", "role switches / min", "teammate contacts", "mean distance to target (m)",
                        "largest distance to target (m)"])
        cells = [name, _mean_se(gd, signed=True)]
        for figure in ("role_switches_per_minute", "contacts", "target_distance_mean", "target_distance_max"):
            cells.append(_mean_se(team_figure(done, name, figure)))
        table.rows.append(cells)


def _mean_se(values: np.ndarray, signed: bool = False) -> str:
    """``mean (SE)`` of ``values`` (``-`` for none)."""
    if values.size == 0:
        return "-"
    return f"{values.mean():{'+' if signed else ''}.2f} ({values.std(ddof=1) / math.sqrt(values.size):.2f})"
