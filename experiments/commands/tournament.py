"""``soccer-sim tournament --teams A,B,C --games N``: a round robin with goal differences and
standard errors.

Every pairing plays ``N`` matches (rounded up to even) on paired seeds: seed ``s`` once with
each team at home, the same seeds for every pairing, so two teams' results against a common
opponent can be compared match by match. Matches are stored in ``--out`` as they finish;
re-running the same command plays only what is missing. Prints the league table (points,
W/D/L, goals, mean goal difference and its standard error) and the pairwise goal-difference
matrix, and writes both to ``--tables`` as CSV (``league.csv``, ``pairwise.csv``), as Markdown
(``tournament.md``) and as a PNG (``tournament.png``: mean goal difference with 95% intervals;
the pairwise heatmap). Each file is written whole or not at all.
"""

from __future__ import annotations

import argparse
import itertools
import math
from collections.abc import Sequence
from pathlib import Path

from experiments.commands import add_json_option, doc_summary, table_command
from experiments.limits import ranged

KIND = "tournament"
DEFAULT_GAMES = 20
"""Matches per pairing of the default tournament: small enough to finish in minutes on a laptop."""
DEFAULT_TEAMS = ("mmdr", "mmd+msd2", "static", "greedy")


def register(subparsers: argparse._SubParsersAction) -> None:
    subparsers.add_parser(
        "tournament", help="round robin: league table and pairwise goal differences with standard errors",
        description=doc_summary(__doc__), populate=_add_arguments)


def _add_arguments(parser: argparse.ArgumentParser) -> None:
    """The options (built only when the command is chosen: listing the teams imports the simulator)."""
    from experiments.commands.run_options import add_run_arguments, add_team_option

    add_team_option(parser, "--teams", DEFAULT_TEAMS, "the teams")
    parser.add_argument("--games", type=ranged("games"), default=DEFAULT_GAMES,
                        help="matches per pairing, rounded up to even: sides swapped on paired seeds "
                             f"(default: {DEFAULT_GAMES}, a few minutes on two cores)")
    parser.add_argument("--scenario", default=None, metavar="NAME|FILE",
                        help="play a scenario instead of the regular match: a name from `soccer-sim scenarios` or "
                             "a .json/.toml file (teams on the away side play the scenario's defence)")
    add_run_arguments(parser, "results.sqlite")
    from experiments.rcss_runs import add_engine_arguments

    add_engine_arguments(parser)
    add_json_option(parser)
    parser.set_defaults(func=table_command(run))


def build_specs(params: dict) -> list:
    """Every match of the round robin described by ``params`` (teams, games, seed, cycles)."""
    from experiments.commands.run_options import scenario_named
    from experiments.runner.spec import paired_specs

    scenario = scenario_named(params.get("scenario"))
    return [spec for a, b in itertools.combinations(params["teams"], 2)
            for spec in paired_specs(a, b, params["games"], params["seed"], params["cycles"],
                                     params.get("observation", "full"), scenario)]


def run(args: argparse.Namespace) -> int:
    from experiments.commands.run_options import run_command
    from experiments.rcss_runs import engine_specs

    return run_command(args, KIND, _params, engine_specs(args, build_specs), report)


def _params(args: argparse.Namespace) -> dict:
    from experiments.commands.run_options import RunInputError, check_observation, scenario_option, team_list
    from experiments.configuration import match_config
    from experiments.rcss_runs import EngineChoice

    engine = EngineChoice.from_args(args)
    teams = team_list(args.teams, "--teams", minimum=2, external=engine.external_names)
    if args.scenario is not None and engine.in_server:
        raise RunInputError("--scenario is not available with --engine rcssserver (the simulator's only)")
    observation = engine.observation(args.observation)
    scenario_option(args.scenario, match_config(args.cycles, observation))
    check_observation(engine.ours(teams), observation)
    params = {"teams": teams, "games": args.games, "seed": args.seed, "cycles": args.cycles,
              "observation": observation, **engine.params()}
    if args.scenario is not None:  # (without one the parameters stay as results files have always stored them)
        params["scenario"] = args.scenario
    return params


LEAGUE_COLUMNS = ["#", "team", "P", "Pts", "W", "D", "L", "FF", "GF", "GA", "mean GD (SE)"]
"""The league table's columns, short enough for the table to fit 80 columns of a terminal."""
LEAGUE_LEGEND = ("P played, Pts points (3 a win, 1 a draw), W/D/L won/drawn/lost, FF forfeits (a match the team "
                 "lost by its own failure, counted as lost without goals), GF/GA goals for/against, mean GD (SE): "
                 "mean goal difference per match and its standard error")
"""What the league table's short column names mean (printed under it)."""


def tables(records: Sequence, teams: Sequence[str], label: dict[str, str] | None = None) -> tuple:
    """(league table, pairwise matrix) as :class:`experiments.reporting.Table`, and the CSV rows
    of both; ``label``: how each team is shown (default:
    :func:`~experiments.commands.run_options.team_labels`, a learned policy by its own name)."""
    from experiments.reporting import Table
    from experiments.stats import league_table, pairing_summary

    from experiments.commands.run_options import team_labels

    league = league_table(records, teams)
    label = label if label is not None else team_labels(list(teams))
    league_table_text = Table(f"league: {len(teams)} teams, {len(records)} matches", LEAGUE_COLUMNS, labels=2,
                              caption=LEAGUE_LEGEND)
    league_rows = []
    for rank, row in enumerate(league, 1):
        league_table_text.rows.append([str(rank), label[row.team], str(row.games), str(row.points), str(row.wins),
                                       str(row.draws), str(row.losses), str(row.forfeits), str(row.goals_for),
                                       str(row.goals_against), row.goal_difference.text()])
        gd = row.goal_difference
        league_rows.append([rank, label[row.team], row.games, row.points, row.wins, row.draws, row.losses, row.forfeits,
                            row.goals_for, row.goals_against, gd.mean, gd.se, gd.low, gd.high])
    matrix = Table("mean goal difference of the row team against the column team (SE)",
                   ["team", *(label[team] for team in teams)])
    pair_rows = []
    for team in teams:
        cells = [label[team]]
        for opponent in teams:
            if opponent == team:
                cells.append("")
                continue
            pair = pairing_summary(records, team, opponent)
            cells.append(pair.goal_difference.text())
            gd = pair.goal_difference
            pair_rows.append([label[team], label[opponent], pair.games, pair.wins, pair.draws, pair.losses,
                              pair.forfeits,
                              pair.goals_for, pair.goals_against, gd.mean, gd.se, gd.low, gd.high])
        matrix.rows.append(cells)
    return league_table_text, matrix, league_rows, pair_rows


def report(records: Sequence, params: dict, out_dir: Path | None = None) -> list[Path]:
    """Print the league table and the pairwise matrix; with ``out_dir``, write league.csv,
    pairwise.csv, tournament.md and tournament.png there, each through a temporary file (an
    OSError naming the file leaves no partial one). Returns the files written."""
    from experiments.reporting import ESTIMATE_COLUMNS, write_csv, write_markdown
    from experiments.results.files import atomic_output

    from experiments.commands.run_options import team_labels

    teams = params["teams"]
    label = team_labels(list(teams))
    league, matrix, league_rows, pair_rows = tables(records, teams, label)
    league.print()
    matrix.print()
    if out_dir is None:
        return []
    cycles = params["cycles"] or "regulation (6000)"
    scenario = f", scenario {params['scenario']}" if params.get("scenario") else ""
    writers = {
        "league.csv": lambda path: write_csv(path, ["rank", "team", "games", "points", "wins", "draws", "losses",
                                                    "forfeits", "goals_for", "goals_against", *ESTIMATE_COLUMNS],
                                             league_rows),
        "pairwise.csv": lambda path: write_csv(path, ["team", "opponent", "games", "wins", "draws", "losses",
                                                      "forfeits", "goals_for", "goals_against", *ESTIMATE_COLUMNS],
                                               pair_rows),
        "tournament.md": lambda path: write_markdown(path, [league, matrix],
                                                     f"Tournament: {len(records)} matches, seeds from "
                                                     f"{params['seed']}, cycles per match: {cycles}{scenario}."),
        "tournament.png": lambda path: _figure(path, [label[team] for team in teams], league_rows, pair_rows),
    }
    written = []
    for name, write in writers.items():
        with atomic_output(out_dir / name) as temporary:
            write(temporary)
        written.append(out_dir / name)
    print("wrote " + ", ".join(str(path) for path in written))
    return written


def _figure(path: Path, teams: Sequence[str], league_rows: list, pair_rows: list) -> Path:
    """Left: each team's mean goal difference with its 95% interval; right: the pairwise heatmap."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    order = [row[1] for row in league_rows]
    means = np.array([row[10] for row in league_rows], dtype=float)
    half = np.array([(row[13] - row[10]) if not math.isnan(row[13]) else 0.0 for row in league_rows])
    index = {team: i for i, team in enumerate(teams)}
    grid = np.full((len(teams), len(teams)), np.nan)
    for row in pair_rows:
        grid[index[row[0]], index[row[1]]] = row[9]
    figure, (bars, heat) = plt.subplots(1, 2, figsize=(12, 4.8), gridspec_kw={"width_ratios": [1, 1.2]})
    bars.barh(range(len(order)), means, xerr=half, color="tab:blue", alpha=0.8, capsize=3)
    bars.set_yticks(range(len(order)), order)
    bars.invert_yaxis()
    bars.axvline(0.0, color="black", linewidth=0.8)
    bars.set_xlabel("mean goal difference per match (95% interval)")
    bars.set_title("league")
    limit = float(np.nanmax(np.abs(grid))) if np.isfinite(grid).any() else 1.0
    image = heat.imshow(grid, cmap="RdBu", vmin=-limit or -1.0, vmax=limit or 1.0)
    heat.set_xticks(range(len(teams)), teams, rotation=45, ha="right")
    heat.set_yticks(range(len(teams)), teams)
    for (i, j), value in np.ndenumerate(grid):
        if np.isfinite(value):
            heat.text(j, i, f"{value:+.2f}", ha="center", va="center", fontsize=8)
    heat.set_title("mean goal difference, row team vs column team")
    figure.colorbar(image, ax=heat, shrink=0.8)
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)
    return path
