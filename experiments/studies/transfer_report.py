"""The transfer study's report (``soccer-sim experiment transfer``): the same pairings in the
simulator and in rcssserver, side by side, from results files alone.

**What it reads.** Per engine, one or more results files of that engine (:class:`EngineResults`,
:func:`read_engine`). A results file keys its matches by (home, away, seed) within one
configuration, and every command of :data:`READABLE_KINDS` plays a pairing on the same paired
seeds (:func:`experiments.runner.spec.paired_specs`: seed ``s`` once with each team at home), so
the report takes, for each pairing, every stored match between its two teams, whichever of
those commands stored it: the transfer command's own files, ``experiment case-study --engine
rcssserver`` and ``experiment case-study --observation partial`` files with the same teams and
opponents, or tournaments. The simulator's files must hold partial observation (what the bridge
plays in the server); one engine's files must share one configuration and never hold the same
match twice. A file's engine is the ``engine`` of its configuration (a file never mixes them).

**Tables** (:func:`transfer_tables`), per engine read:

* goal difference per match, mean (SE), of each pairing (the first team's view), with the games
  each row holds (forfeits counted in games, never in the goal difference);
* each team minus the ``baseline`` team, paired match by match against the same reference
  opponent on the same seed and side (:func:`experiments.stats.paired_comparison`), with its SE,
  p-value and number of pairs;
* the teams ranked by their mean goal difference against each reference opponent, and Kendall's
  tau-b between each of the simulator's rankings and each of rcssserver's
  (:func:`experiments.stats.rank_agreement`, over the teams both rank);
* the match statistics per match (goals, shots, passes, kicks, tackles, possession, distance run,
  and in the server the steps our players missed) of each pairing's first team and, for an
  external opponent (helios-base) and a mirror pairing, of the other team too.

A pairing an engine cannot play (an external team in the simulator) shows ``-``. The reference
opponents are the opponents that are not among the compared teams (as in the case study).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from experiments.errors import ExperimentError
from experiments.rcss_runs import RCSS
from experiments.runner.spec import SIMULATOR

ENGINE_ORDER = (SIMULATOR, RCSS)
"""The engines' columns, left to right."""

READABLE_KINDS = ("transfer", "case-study", "tournament")
"""Commands whose results files the report reads (their matches are paired seeds keyed by the
teams' own names)."""

STATISTICS = (("goals", "goals", 1.0), ("shots", "shots", 1.0), ("passes", "passes", 1.0),
              ("kicks", "kicks", 1.0), ("tackles", "tackles", 1.0), ("possession (share)", "possession", 1.0),
              ("distance run (km)", "distance_run", 1e-3), ("missed steps", "missed_steps", 1.0))
"""(column, statistic, scale) of the match-statistics table: a team's figures per match
(``missed_steps``: the steps after kick-off at which one of our players sent the server no
``(done)``, summed over the players, :func:`experiments.rcss_runs.row_statistics`; only in the
server)."""


class TransferInputError(ExperimentError):
    """Results files the report cannot use together; the message names the option and file."""


def engine_name(engine: str) -> str:
    """How messages name an engine."""
    return "the simulator" if engine == SIMULATOR else engine


@dataclass(frozen=True)
class Pairing:
    """Two teams that meet; the goal difference is ``team``'s."""

    team: str
    opponent: str
    mirror: bool = False
    """Both teams are compared teams (e.g. mmd+msd2 v static), not a team and a reference."""

    @property
    def label(self) -> str:
        return f"{self.team} v {self.opponent}"


@dataclass(frozen=True)
class Design:
    """What the study compares: ``teams`` against each of ``opponents``, the ``mirror``
    pairings, the ``baseline`` team the paired differences are taken from, and the teams that
    are programs of their own (they play in the server only)."""

    teams: tuple[str, ...]
    opponents: tuple[str, ...]
    mirror: tuple[tuple[str, str], ...]
    baseline: str
    external: frozenset[str]

    @classmethod
    def from_params(cls, params: dict, external: Sequence[str] = ()) -> Design:
        """The design of a transfer run's stored parameters (``external``: more external names)."""
        from experiments.rcss_engine import EXTERNAL_TEAMS

        return cls(tuple(params["teams"]), tuple(params["opponents"]),
                   tuple((str(a), str(b)) for a, b in params.get("mirror", ())), str(params["baseline"]),
                   frozenset((*EXTERNAL_TEAMS, *dict(params.get("external") or {}), *external)))

    @property
    def pairings(self) -> list[Pairing]:
        """Every team against every opponent, then the mirror pairings (each once)."""
        found = [Pairing(team, opponent) for team in self.teams for opponent in self.opponents]
        for a, b in self.mirror:
            if not any({p.team, p.opponent} == {a, b} for p in found):
                found.append(Pairing(a, b, mirror=True))
        return found

    @property
    def references(self) -> list[str]:
        """The opponents that are not compared teams: the paired differences and rankings are
        taken against them."""
        return [o for o in self.opponents if o not in self.teams]

    def plays(self, engine: str, *names: str) -> bool:
        """Whether ``engine`` can play a match of ``names`` (external teams: the server only)."""
        return engine != SIMULATOR or not any(name in self.external for name in names)

    def names(self) -> list[str]:
        """Every team the design names, each once."""
        return list(dict.fromkeys([*self.teams, *self.opponents, *(n for pair in self.mirror for n in pair)]))


@dataclass
class EngineResults:
    """One engine's stored matches, as the report reads them."""

    engine: str
    records: list = field(default_factory=list)
    """The :class:`~experiments.results.record.MatchRecord` of every file read."""
    files: tuple[str, ...] = ()
    cycles: int | None = None
    """Cycles per match of the files' runs (None: regulation)."""
    asked: int | None = None
    """Games per pairing the first file's run asked for (None: not known)."""
    external: tuple[str, ...] = ()
    """External team names the files' runs declared (``--external``)."""


def read_engine(engine: str, files: Sequence[tuple[str, str]]) -> EngineResults:
    """The matches of ``files`` ((option, path) pairs, the option naming the file in messages),
    all of ``engine``; a :class:`TransferInputError` (one line) for a file that is missing or
    not a results file, of a command or engine the report cannot read, of another configuration
    than the first, holding a match another file holds, or, in the simulator, of full observation."""
    from experiments.results.store import ResultsError, ResultStore

    results = EngineResults(engine)
    first: tuple[str, str, str] | None = None           # (option, path, configuration hash)
    owner: dict[tuple[str, str, int], tuple[str, str]] = {}
    for option, path in files:
        try:
            with ResultStore.open(path) as store:
                kind, stored, params, records = store.kind, store.engine, store.params, store.records()
                digest = store.config_hash or ""
        except ResultsError as exc:
            raise TransferInputError(f"{option} {exc}") from None
        where = f"{option} {path}"
        if kind not in READABLE_KINDS:
            raise TransferInputError(f"{where}: holds the results of '{kind}'; the transfer report reads the "
                                     f"files of {', '.join(READABLE_KINDS)}")
        if stored != engine:
            raise TransferInputError(f"{where}: holds matches played in {engine_name(stored)}, not in "
                                     f"{engine_name(engine)}; give each engine's file to its own option")
        if engine == SIMULATOR and params.get("observation", "full") != "partial":
            raise TransferInputError(f"{where}: holds matches under full observation; the study compares the "
                                     "simulator under partial observation, as the bridge plays in rcssserver "
                                     "(e.g. a file of experiment case-study --observation partial)")
        if first is None:
            first = (option, path, digest)
            results.cycles, results.asked = params.get("cycles"), params.get("games")
        elif digest != first[2]:
            raise TransferInputError(f"{where}: holds matches of another configuration (hash {digest}) than "
                                     f"{first[0]} {first[1]} (hash {first[2]}), e.g. another number of cycles; "
                                     "one engine's files must share one configuration")
        for record in records:
            if record.key in owner:
                other = owner[record.key]
                raise TransferInputError(f"{where}: the match {record.home} v {record.away}, seed {record.seed} "
                                         f"is also in {other[0]} {other[1]}; give each match once")
            owner[record.key] = (option, path)
        results.records.extend(records)
        results.files += (str(path),)
        results.external += tuple(name for name in dict(params.get("external") or {}) if name not in results.external)
    return results


def check_names(design: Design, halves: dict[str, EngineResults]) -> None:
    """A :class:`TransferInputError` naming the first team of ``design`` that no match of the
    files read holds (an external team is looked for only in rcssserver's files, and only when
    they were read)."""
    for name in design.names():
        engines = [e for e in halves if design.plays(e, name)]
        if not engines:
            continue
        if not any(name in record.names() for e in engines for record in halves[e].records):
            files = " or ".join(f for e in engines for f in halves[e].files)
            raise TransferInputError(f"no match of {name!r} in {files}: name the teams the files hold "
                                     "(--teams, --opponents, --mirror)")


def pairing_records(records: Sequence, a: str, b: str) -> list:
    """The matches between ``a`` and ``b`` (either at home)."""
    wanted = sorted((a, b))
    return [r for r in records if sorted(r.names()) == wanted]


@dataclass
class TransferTables:
    """The report's tables (printed and Markdown) and CSV rows."""

    tables: list = field(default_factory=list)
    notes: list[str] = field(default_factory=list)
    goal_rows: list[list] = field(default_factory=list)
    paired_rows: list[list] = field(default_factory=list)
    rank_rows: list[list] = field(default_factory=list)
    agreement_rows: list[list] = field(default_factory=list)
    statistic_rows: list[list] = field(default_factory=list)


def transfer_tables(design: Design, halves: dict[str, EngineResults],
                    asked: dict[str, int | None] | None = None) -> TransferTables:
    """Every table of the report (module docstring) for the engines of ``halves``; ``asked``:
    the games per pairing asked for in each engine (default: what each engine's first file
    asked), to name the rows that hold fewer."""
    engines = [e for e in ENGINE_ORDER if e in halves] + [e for e in halves if e not in ENGINE_ORDER]
    asked = {e: (asked or {}).get(e) or halves[e].asked for e in engines}
    out = TransferTables()
    _goal_table(design, halves, engines, asked, out)
    _paired_table(design, halves, engines, out)
    _rank_tables(design, halves, engines, out)
    _statistics_table(design, halves, engines, out)
    return out


def _goal_table(design: Design, halves: dict, engines: list[str], asked: dict, out: TransferTables) -> None:
    from experiments.reporting import Table
    from experiments.stats import pairing_summary

    table = Table("goal difference per match, mean (SE), and the games each row holds",
                  ["pairing", *(column for e in engines for column in (e, f"games ({e})"))])
    short: list[str] = []
    for pairing in design.pairings:
        cells = [pairing.label + (" (mirror)" if pairing.mirror else "")]
        for engine in engines:
            if not design.plays(engine, pairing.team, pairing.opponent):
                cells += ["-", "not played"]
                continue
            pair = pairing_summary(halves[engine].records, pairing.team, pairing.opponent)
            gd = pair.goal_difference
            cells += [gd.text(), f"{pair.games}" + (f" ({pair.forfeits} forfeited)" if pair.forfeits else "")]
            out.goal_rows.append([engine, pairing.team, pairing.opponent, pair.games, asked[engine], pair.wins,
                                  pair.draws, pair.losses, pair.forfeits, pair.goals_for, pair.goals_against,
                                  gd.mean, gd.se, gd.low, gd.high])
            if asked[engine] is not None and pair.games < _even(asked[engine], pairing):
                short.append(f"{pairing.label} in {engine} ({pair.games} of {_even(asked[engine], pairing)})")
        table.rows.append(cells)
    if short:
        out.notes.append("fewer games than asked: " + "; ".join(short))
    out.tables.append(table)


def _even(games: int, pairing: Pairing) -> int:
    """The games a pairing plays for ``games`` asked: rounded up to even (sides swapped on
    paired seeds), except a team against itself (:func:`experiments.runner.spec.paired_specs`)."""
    return games if pairing.team == pairing.opponent else games + games % 2


def _paired_table(design: Design, halves: dict, engines: list[str], out: TransferTables) -> None:
    from experiments.reporting import Table
    from experiments.stats import p_text, paired_comparison

    columns = [(e, o) for e in engines for o in design.references if design.plays(e, o)]
    if design.baseline not in design.teams or len(design.teams) < 2 or not columns:
        return                                              # nobody to compare with the baseline
    table = Table(f"goal difference minus {design.baseline}'s, paired on the same opponent, seed and side: "
                  "mean (SE), p, pairs", ["team", *(f"{e} v {o}" for e, o in columns)])
    for team in design.teams:
        if team == design.baseline:
            continue
        cells = [team]
        for engine, opponent in columns:
            paired = paired_comparison(halves[engine].records, team, design.baseline, [opponent])
            difference = paired.difference
            cells.append("-" if difference.n == 0 else
                         f"{difference.text()}, p {p_text(paired.p_value)}, {difference.n} pairs")
            out.paired_rows.append([engine, team, design.baseline, opponent, difference.n, difference.mean,
                                    difference.se, paired.p_value])
        table.rows.append(cells)
    out.tables.append(table)


def _rank_tables(design: Design, halves: dict, engines: list[str], out: TransferTables) -> None:
    from experiments.reporting import Table
    from experiments.stats import pairing_summary, rank_agreement, ranking

    columns = [(e, o) for e in engines for o in design.references if design.plays(e, o)]
    if len(design.teams) < 2 or not columns:
        return
    scores = {column: [pairing_summary(halves[column[0]].records, team, column[1]).goal_difference.mean
                       for team in design.teams] for column in columns}
    ranks = {column: ranking(values) for column, values in scores.items()}
    table = Table("the teams ranked by mean goal difference (rank 1 the best; ties share their mean rank)",
                  ["team", *(f"{e} v {o}" for e, o in columns)])
    for k, team in enumerate(design.teams):
        cells = [team]
        for column in columns:
            score, rank = scores[column][k], ranks[column][k]
            cells.append("-" if math.isnan(score) else f"{score:+.2f} ({rank:g})")
            out.rank_rows.append([column[0], column[1], team, score, rank])
        table.rows.append(cells)
    out.tables.append(table)
    pairs = [(a, b) for a in columns if a[0] == SIMULATOR for b in columns if b[0] != SIMULATOR]
    if not pairs:
        return
    agreement = Table("rank agreement between the engines: Kendall's tau-b of the two rankings (1 the same order, "
                      "-1 the reverse), its two-sided p-value and the teams both rank",
                      ["simulator ranking", "rcssserver ranking", "Kendall's tau-b", "p", "teams"], labels=2)
    for a, b in pairs:
        result = rank_agreement(scores[a], scores[b])
        tau = "-" if math.isnan(result.tau) else f"{result.tau:+.2f}"
        p = "-" if math.isnan(result.p_value) else f"{result.p_value:.3g}"
        agreement.rows.append([f"{a[0]} v {a[1]}", f"{b[0]} v {b[1]}", tau, p, str(result.n)])
        out.agreement_rows.append([a[0], a[1], b[0], b[1], result.tau, result.p_value, result.n])
    out.tables.append(agreement)


def _statistics_table(design: Design, halves: dict, engines: list[str], out: TransferTables) -> None:
    from experiments.reporting import Table
    from experiments.stats import figure_cell, pairing_summary

    table = Table("match statistics per match, mean (SE), of each team against the opponent named",
                  ["engine", "team", "against", "games", *(column for column, _, _ in STATISTICS)], labels=3)
    for engine in engines:
        for pairing in design.pairings:
            if not design.plays(engine, pairing.team, pairing.opponent):
                continue
            records = pairing_records(halves[engine].records, pairing.team, pairing.opponent)
            shown = [(pairing.team, pairing.opponent)]
            if pairing.mirror or pairing.opponent in design.external:
                shown.append((pairing.opponent, pairing.team))
            for team, against in shown:
                games = pairing_summary(records, team, against).games
                cells, row = [engine, team, against, str(games)], [engine, team, against, games]
                for _, figure, scale in STATISTICS:
                    text, mean, se = figure_cell(records, team, figure, scale)
                    cells.append(text)
                    row += [mean, se]
                table.rows.append(cells)
                out.statistic_rows.append(row)
    out.tables.append(table)


def write_report(out_dir: Path, result: TransferTables, preface: str) -> list[Path]:
    """The report's CSV files and transfer.md in ``out_dir``; the files written."""
    from experiments.reporting import ESTIMATE_COLUMNS, write_csv, write_markdown

    written = [
        write_csv(out_dir / "transfer-goals.csv", ["engine", "team", "opponent", "games", "games_asked", "wins",
                                                   "draws", "losses", "forfeits", "goals_for", "goals_against",
                                                   *ESTIMATE_COLUMNS], result.goal_rows),
        write_csv(out_dir / "transfer-paired.csv", ["engine", "team", "baseline", "opponent", "pairs",
                                                    "gd_difference", "gd_difference_se", "p_value"],
                  result.paired_rows),
        write_csv(out_dir / "transfer-ranks.csv", ["engine", "opponent", "team", "mean_gd", "rank"], result.rank_rows),
        write_csv(out_dir / "transfer-rank-agreement.csv", ["simulator", "simulator_opponent", "engine", "opponent",
                                                            "kendall_tau_b", "p_value", "teams"],
                  result.agreement_rows),
        write_csv(out_dir / "transfer-statistics.csv",
                  ["engine", "team", "against", "games",
                   *(f"{figure}{suffix}" for _, figure, _ in STATISTICS for suffix in ("", "_se"))],
                  result.statistic_rows),
        write_markdown(out_dir / "transfer.md", result.tables,
                       "\n\n".join([preface, *result.notes])),
    ]
    return written


def describe(halves: dict[str, EngineResults]) -> str:
    """One line per engine: its files, matches and cycles per match."""
    parts = []
    for engine, half in halves.items():
        cycles = half.cycles or "regulation (6000)"
        parts.append(f"{engine}: {len(half.records)} matches from {', '.join(half.files) or '(no file)'}, "
                     f"cycles per match: {cycles}")
    return "Transfer study, partial observation in both engines. " + "; ".join(parts) + "."
