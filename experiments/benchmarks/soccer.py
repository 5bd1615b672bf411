"""``soccer-sim bench soccer``: what the play between built-in teams looks like, in numbers.

With neither ``--home`` nor ``--away`` it plays the default set of pairings
(:data:`~experiments.benchmarks.soccer_pairings.PAIRINGS`: 8 pairings, each on both sides
with the same seeds, ``--matches`` seeds per pairing and side: 48 matches by default); with
both, that one pairing, sides as given. It prints the mean per match, with its standard
error, of every figure of :mod:`experiments.benchmarks.soccer_match` (both teams together
unless the name says otherwise): goals, shots, passes, kicks, tackles, set plays, offsides,
catches, retakes, dropped balls, distance run per team and by role, team length and width
(also with the ball in midfield), the share of outfield player-cycles short of stamina, and
the players near the ball. ``--rcg FILE...`` computes the same figures, with the same
definitions, from rcssserver game logs instead (:mod:`experiments.benchmarks.soccer_rcg`;
``--roles`` names the formation file that labels the players' roles), and ``--compare``
sets the real server's figures (helios-base v helios-base,
``tests/data/rcssserver/helios_matches.json``) beside ours. Speed is ``bench match``'s job.
"""

from __future__ import annotations

import argparse
import json
import math
from collections.abc import Iterable, Sequence
from pathlib import Path



REAL_SERVER_FIGURES = Path(__file__).resolve().parents[2] / "tests" / "data" / "rcssserver" / "helios_matches.json"
"""The real server's figures per match (helios-base v helios-base), as ``--compare`` reads them."""

Figures = dict[str, float | None]
"""One match's figures by name (None: not defined for that match)."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.limits import ranged

    parser.add_argument("--home", default=None, help="home team (with --away: play this one pairing)")
    parser.add_argument("--away", default=None, help="away team (with --home)")
    parser.add_argument("--matches", type=ranged("matches"), default=3,
                        help="seeds per pairing and side (default: 3; 48 matches over the default pairings)")
    parser.add_argument("--cycles", type=ranged("cycles"), default=None, help="cycles per match (default: a full match)")
    parser.add_argument("--seed", type=ranged("seed"), default=0, help="seed of the first match; seed i is seed + i")
    parser.add_argument("--workers", type=ranged("workers"), default=1, help="matches played at once (default: 1)")
    parser.add_argument("--observation", choices=("full", "partial"), default="full",
                        help="full (default) or partial observation (each player decides from its own view)")
    parser.add_argument("--rcg", nargs="+", metavar="FILE", default=None,
                        help="compute the figures from these rcssserver game logs instead of playing")
    parser.add_argument("--roles", metavar="FILE", default=None,
                        help="with --rcg: a helios-base formation file naming every shirt number's role")
    parser.add_argument("--compare", action="store_true",
                        help="also show the real server's figures (helios-base v helios-base) beside ours")


def matches_to_play(home: str | None, away: str | None, seeds: int, seed: int = 0) -> list[tuple[str, str, int]]:
    """(home, away, seed) of every match: the one pairing given, or every default pairing on
    both sides with the same seeds; a ValueError if only one of the teams is given."""
    from experiments.benchmarks.soccer_pairings import PAIRINGS

    if (home is None) != (away is None):
        raise ValueError("give both --home and --away (one pairing) or neither (the default pairings)")
    if home is not None:
        return [(home, away, seed + i) for i in range(seeds)]
    return [(a, b, seed + i) for first, second in PAIRINGS for a, b in ((first, second), (second, first))
            for i in range(seeds)]


def _play(task: tuple[str, str, int, int | None, str]) -> Figures:
    from experiments.benchmarks.soccer_match import match_figures

    home, away, seed, cycles, observation = task
    return match_figures(home, away, seed, cycles, observation=observation)


def play_all(tasks: Sequence[tuple[str, str, int]], cycles: int | None, workers: int = 1,
             observation: str = "full") -> list[Figures]:
    """The figures of every match of ``tasks``, in order (``workers`` processes at once)."""
    jobs = [(home, away, seed, cycles, observation) for home, away, seed in tasks]
    if workers <= 1 or len(jobs) <= 1:
        return [_play(job) for job in jobs]
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(max_workers=min(workers, len(jobs))) as pool:
        return list(pool.map(_play, jobs))


def measure(home: str, away: str, matches: int, seed: int = 0, cycles: int | None = None) -> dict[str, np.ndarray]:
    """Play one pairing on ``matches`` consecutive seeds; one array per figure (one value per
    match, NaN where a match does not define it)."""
    return by_figure(play_all(matches_to_play(home, away, matches, seed), cycles))


def by_figure(rows: Iterable[Figures]) -> dict[str, np.ndarray]:
    """Per figure name (in first-seen order), its values over the matches (NaN: undefined)."""
    import numpy as np

    rows = list(rows)
    names: dict[str, None] = {}
    for row in rows:
        names.update(dict.fromkeys(row))
    return {name: np.array([np.nan if row.get(name) is None else float(row[name]) for row in rows])
            for name in names}


def mean_and_error(values: np.ndarray) -> tuple[float, float]:
    """Mean and standard error of the defined (non-NaN) values; NaN for what cannot be had."""
    import numpy as np

    defined = values[~np.isnan(values)]
    if defined.size == 0:
        return math.nan, math.nan
    error = float(defined.std(ddof=1) / np.sqrt(defined.size)) if defined.size > 1 else math.nan
    return float(defined.mean()), error


def real_server_rows(path: Path = REAL_SERVER_FIGURES) -> list[Figures]:
    """The real server's per-match figures stored at ``path``; a ValueError naming the file if
    it is missing or malformed."""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        return [dict(match["figures"]) for match in data["matches"]]
    except (OSError, ValueError, KeyError, TypeError) as exc:
        raise ValueError(f"{path}: cannot read the real server's figures ({exc})") from None


def _cell(value: float, digits: int = 2) -> str:
    return "-" if math.isnan(value) else f"{value:.{digits}f}"


def figure_table(title: str, ours: dict[str, np.ndarray], real: dict[str, np.ndarray] | None = None):
    """The table of means and standard errors (and the real server's beside them)."""
    from experiments.reporting import Table
    import numpy as np

    columns = ["per match (both teams)", "mean", "std. error"]
    if real is not None:
        columns += ["real server", "std. error "]
    table = Table(title, columns)
    names = list(ours) + [name for name in (real or {}) if name not in ours]
    for name in names:
        mean, error = mean_and_error(ours.get(name, np.array([np.nan])))
        row = [name, _cell(mean), _cell(error)]
        if real is not None:
            real_mean, real_error = mean_and_error(real.get(name, np.array([np.nan])))
            row += [_cell(real_mean), _cell(real_error)]
        table.rows.append(row)
    retakes = ours.get("set-play retakes")
    if retakes is not None and not np.isnan(retakes).all():
        table.rows.append(["set-play retakes, most in one match", _cell(float(np.nanmax(retakes)), 0), "-"]
                          + (["-", "-"] if real is not None else []))
    return table


def run(args: argparse.Namespace) -> int:
    from experiments.commands.errors import fail
    from soccer_sim import ConfigError, TeamError, TeamNotFoundError
    from soccer_sim.rcg import RcgError

    try:
        real = by_figure(real_server_rows()) if args.compare else None
        if args.rcg is not None:
            rows, title = _from_logs(args.rcg, args.roles), f"{len(args.rcg)} game logs"
        else:
            if args.roles is not None:
                raise ValueError("--roles goes with --rcg")
            tasks = matches_to_play(args.home, args.away, args.matches, args.seed)
            rows = play_all(tasks, args.cycles, args.workers, args.observation)
            what = f"{args.home} vs {args.away}" if args.home else "8 default pairings, both sides"
            title = (f"{what}: {len(tasks)} matches (seeds {args.seed}..{args.seed + args.matches - 1}), "
                     f"{args.observation} observation")
    except (TeamNotFoundError, TeamError, ConfigError, RcgError, ValueError) as exc:
        return fail(str(exc))
    figure_table(title, by_figure(rows), real).print()
    return 0


def _from_logs(paths: Sequence[str], roles: str | None) -> list[Figures]:
    from experiments.benchmarks.helios_roles import KINDS, helios_labels
    from experiments.benchmarks.soccer_rcg import rcg_figures
    from soccer_sim.rcg import read_rcg

    labels = None
    if roles is not None:
        shirts = helios_labels(roles)
        labels = {"l": shirts, "r": shirts}
    return [rcg_figures(read_rcg(path), labels, KINDS if labels is not None else None) for path in paths]
