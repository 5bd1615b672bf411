"""``soccer-sim experiment drop-in``: the drop-in player (ad hoc teamwork) study of "SCRAM:
Scalable Collision-avoiding Role Assignment with Minimal-makespan for Formational Positioning".

In a drop-in game every player runs some team's code without knowing how its team-mates
decide (:mod:`experiments.mixed_team`): each game draws its 21 other players from ``--pool``
and one outfield slot, on one side, for the candidate player. The same game (same seed, same
team-mates and opponents, same slot) is played once with each of ``--candidates`` in that slot,
so the candidates are compared match by match: a player using SCRAM (``mmd+msd2``) against one
using static roles (``static``), by the mean goal difference of the games it played in.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from experiments.commands import doc_summary

KIND = "drop-in"
DEFAULT_CANDIDATES = ("mmd+msd2", "static")
DEFAULT_POOL = ("static", "mmdr", "greedy", "bidding", "counter-442", "press-433", "possession")
LINEUP_STREAM = 0xD0
"""Mixed into a game's seed to draw its line-ups (so they do not share the match's streams)."""


@dataclass(frozen=True)
class DropInGame:
    """One drop-in game and the match each candidate plays in it."""

    seed: int
    side: int
    """The side (0 home, 1 away) of the candidate's team."""
    slot: int
    """The candidate's player index (an outfield player)."""
    specs: dict
    """Candidate -> MatchSpec."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.limits import ranged
    from experiments.commands.run_options import add_run_arguments, add_team_option

    parser.description = doc_summary(__doc__)
    add_team_option(parser, "--candidates", DEFAULT_CANDIDATES, "the players compared, the first against each other one")
    add_team_option(parser, "--pool", DEFAULT_POOL, "the teams the other 21 players are drawn from")
    parser.add_argument("--games", type=ranged("games"), default=200,
                        help="drop-in games; each is played once per candidate (default: 200)")
    add_run_arguments(parser, "drop-in.sqlite")


def lineups(params: dict) -> list[DropInGame]:
    """Every game of the study: its seed, the candidate's side and slot, and each candidate's
    match (both mixed teams' member lists drawn from the pool with the game's own generator)."""
    import numpy as np

    from experiments.mixed_team import mixed_name
    from experiments.runner.spec import MatchSpec, config_for

    config = config_for(params["cycles"])
    n, goalie = config.players_per_team, config.rules.goalie_index
    outfield = [i for i in range(n) if i != goalie]
    pool = params["pool"]
    games = []
    for game in range(params["games"]):
        seed = params["seed"] + game
        rng = np.random.default_rng(np.random.SeedSequence([seed, LINEUP_STREAM]))
        others = [pool[k] for k in rng.integers(0, len(pool), size=2 * n - 1)]
        slot = int(outfield[rng.integers(0, len(outfield))])
        side = game % 2
        specs = {}
        for candidate in params["candidates"]:
            own = others[:n - 1]
            own = [*own[:slot], candidate, *own[slot:]]
            teams = [mixed_name(own), mixed_name(others[n - 1:])]
            home, away = teams if side == 0 else teams[::-1]
            specs[candidate] = MatchSpec(home, away, seed, params["cycles"])
        games.append(DropInGame(seed, side, slot, specs))
    return games


def build_specs(params: dict) -> list:
    return [spec for game in lineups(params) for spec in game.specs.values()]


def run(args: argparse.Namespace) -> int:
    from experiments.commands.run_options import run_command

    return run_command(args, KIND, _params, build_specs, report)


def _params(args: argparse.Namespace) -> dict:
    from experiments.commands.run_options import team_list

    return {"candidates": team_list(args.candidates, "--candidates", minimum=2),
            "pool": team_list(args.pool, "--pool"), "games": args.games, "seed": args.seed, "cycles": args.cycles}


def candidate_results(records: Sequence, params: dict) -> dict[str, dict[int, tuple]]:
    """Candidate -> {seed: (record, side)} of the games stored."""
    by_key = {record.key: record for record in records}
    found: dict[str, dict[int, tuple]] = {c: {} for c in params["candidates"]}
    for game in lineups(params):
        for candidate, spec in game.specs.items():
            if spec.key in by_key:
                found[candidate][game.seed] = (by_key[spec.key], game.side)
    return found


def tables(records: Sequence, params: dict) -> tuple:
    """(candidates table, comparison table, CSV rows of each)."""
    from experiments.reporting import Table
    from experiments.stats import goal_difference, p_text as _p_text, paired_test, side_summary

    found = candidate_results(records, params)
    candidates = params["candidates"]
    table = Table(f"drop-in: goal difference of the games each candidate played in ({params['games']} games, "
                  f"team-mates and opponents from {', '.join(params['pool'])})",
                  ["candidate", "games", "W", "D", "L", "forfeits", "mean GD (SE)", "95% CI"])
    rows = []
    for candidate in candidates:
        summary = side_summary(found[candidate].values(), candidate)
        gd = summary.goal_difference
        interval = "-" if gd.n < 2 else f"[{gd.low:+.2f}, {gd.high:+.2f}]"
        table.rows.append([candidate, str(summary.games), str(summary.wins), str(summary.draws), str(summary.losses),
                           str(summary.forfeits), gd.text(), interval])
        rows.append([candidate, summary.games, summary.wins, summary.draws, summary.losses, summary.forfeits,
                     gd.mean, gd.se, gd.low, gd.high])
    first = candidates[0]
    comparison = Table("paired by game (same seed, team-mates, opponents and slot)",
                       ["comparison", "games", "mean difference (SE)", "95% CI", "p"])
    comparison_rows = []
    for other in candidates[1:]:
        differences = []
        for seed, (record, side) in found[first].items():
            twin = found[other].get(seed)
            if twin is not None and record.played and twin[0].played:
                differences.append(goal_difference(record, side) - goal_difference(twin[0], twin[1]))
        difference, p_value = paired_test(differences)
        interval = "-" if difference.n < 2 else f"[{difference.low:+.2f}, {difference.high:+.2f}]"
        comparison.rows.append([f"{first} minus {other}", str(difference.n), difference.text(), interval,
                                _p_text(p_value)])
        comparison_rows.append([first, other, difference.n, difference.mean, difference.se, difference.low,
                                difference.high, p_value])
    return table, comparison, rows, comparison_rows


def report(records: Sequence, params: dict, out_dir: Path | None = None) -> list[Path]:
    """Print both tables; with ``out_dir`` write drop-in.csv, drop-in-paired.csv and drop-in.md."""
    from experiments.reporting import ESTIMATE_COLUMNS, write_csv, write_markdown

    table, comparison, rows, comparison_rows = tables(records, params)
    table.print()
    comparison.print()
    if out_dir is None:
        return []
    written = [
        write_csv(out_dir / "drop-in.csv", ["candidate", "games", "wins", "draws", "losses", "forfeits",
                                            *ESTIMATE_COLUMNS], rows),
        write_csv(out_dir / "drop-in-paired.csv", ["candidate", "minus", "games", "mean_difference", "se",
                                                   "ci95_low", "ci95_high", "p_value"], comparison_rows),
        write_markdown(out_dir / "drop-in.md", [table, comparison],
                       f"Drop-in study: seeds from {params['seed']}, cycles per match: "
                       f"{params['cycles'] or 'regulation (6000)'}."),
    ]
    print("wrote " + ", ".join(str(path) for path in written))
    return written
