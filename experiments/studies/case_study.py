"""``soccer-sim experiment case-study``: Table 5 of "SCRAM: Scalable Collision-avoiding Role
Assignment with Minimal-makespan for Formational Positioning" in this simulator.

The built-in team with each role assigner (``--teams``) plays each reference opponent and the
``mmd+msd2`` team (``--opponents``), ``--games`` matches per pairing on paired seeds (sides
swapped; the same seeds for every pairing). Tables: mean goal difference (standard error) per
assigner and opponent; per assigner its role switches per minute, teammate contacts and
distance run per match, and the paired difference of its goal difference from the
``--baseline`` assigner's against the same reference opponents on the same seeds (with the
paired t-test's p-value). Written as CSV, Markdown and a PNG to ``--tables``.

By default ``--teams`` are the nine assigner variants (the team's default ``ball_role``,
"keep") and ``mmdr``, ``mmd+msd2`` and ``static`` with the other setting (``-leave``: the
player who goes for the ball out of the matching, :mod:`agents.teams.ball_role`). The
behaviour table also carries the mechanism the built-in team measures
(:mod:`agents.teams.mechanism`, every 10th play-on cycle): the share of cycles in which the
fixed shirt-number roles, and the roles held at the previous cycle, already were a
minimal-makespan assignment, the mean makespan gap of the fixed roles (m), and the share of
role-cycles a role was unfilled (its player more than 10 m from its target). Under partial
observation (``--observation partial``) it adds the makespan the players believe in and the
role conflicts their decentralised assignment leaves (:data:`PARTIAL_BEHAVIOUR`). Teams that
do not report a figure show "-".
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from pathlib import Path

from experiments.commands import doc_summary

KIND = "case-study"
DEFAULT_TEAMS = ("mmdr", "mmd+msd2", "static", "greedy", "greedy-offense", "bidding", "msd", "msd2", "random",
                 "mmdr-leave", "mmd+msd2-leave", "static-leave")
DEFAULT_OPPONENTS = ("counter-442", "press-433", "possession", "mmd+msd2")
BEHAVIOUR = (("role switches / min", "role_switches_per_minute", 1.0),
             ("teammate contacts", "teammate_contacts", 1.0),
             ("distance run (km)", "distance_run", 1e-3),
             ("fixed roles optimal (share)", "fixed_roles_optimal_share", 1.0),
             ("fixed roles' makespan gap (m)", "makespan_gap", 1.0),
             ("held roles optimal (share)", "held_roles_optimal_share", 1.0),
             ("role unfilled (share)", "role_unfilled_share", 1.0))
"""(column, statistic, scale) of the behaviour table."""
PARTIAL_BEHAVIOUR = (("makespan (m)", "target_distance_max", 1.0),
                     ("role conflicts (share)", "role_conflict_share", 1.0),
                     ("roles nobody believes held (share)", "believed_unfilled_share", 1.0),
                     ("all follow one (share)", "all_follow_one_share", 1.0),
                     ("agreement latency (cycles)", "agreement_latency_median", 1.0))
"""The columns added under partial observation: the makespan as the players believe it (the
largest distance from a player to the target of the role it follows, per cycle), the shares
of play-on cycles with a role two players believe they hold, or one nobody does, or in which
all follow one assignment, and the median spell (cycles) until they all follow one again."""


def behaviour_columns(params: dict) -> tuple:
    """The behaviour table's (column, statistic, scale) for a run's ``params``."""
    return BEHAVIOUR + (PARTIAL_BEHAVIOUR if params.get("observation", "full") == "partial" else ())


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.limits import ranged
    from experiments.commands.run_options import add_run_arguments, add_team_option

    parser.description = doc_summary(__doc__)
    add_team_option(parser, "--teams", DEFAULT_TEAMS, "the assigner variants compared")
    add_team_option(parser, "--opponents", DEFAULT_OPPONENTS, "their opponents")
    parser.add_argument("--baseline", default="mmd+msd2",
                        help="the variant the others are compared with, match by match (default: mmd+msd2)")
    parser.add_argument("--games", type=ranged("games"), default=1000,
                        help="matches per pairing, rounded up to even: sides swapped on paired seeds (default: 1000)")
    add_run_arguments(parser, "case-study.sqlite")
    from experiments.rcss_runs import add_engine_arguments

    add_engine_arguments(parser)


def build_specs(params: dict) -> list:
    from experiments.runner.spec import paired_specs

    return [spec for team in params["teams"] for opponent in params["opponents"]
            for spec in paired_specs(team, opponent, params["games"], params["seed"], params["cycles"],
                                     params.get("observation", "full"))]


def run(args: argparse.Namespace) -> int:
    from experiments.commands.run_options import run_command
    from experiments.rcss_runs import engine_specs

    return run_command(args, KIND, _params, engine_specs(args, build_specs), report)


def _params(args: argparse.Namespace) -> dict:
    from experiments.commands.run_options import RunInputError, check_observation, team_list
    from experiments.rcss_runs import EngineChoice

    engine = EngineChoice.from_args(args)
    # Each list on its own first, so a bad --opponents is named as such before --baseline is
    # checked against --teams.
    teams = team_list(args.teams, "--teams", external=engine.external_names)
    opponents = team_list(args.opponents, "--opponents", external=engine.external_names)
    if args.baseline not in teams:
        raise RunInputError(f"--baseline {args.baseline!r} must be one of --teams ({', '.join(teams)})")
    observation = engine.observation(args.observation)
    check_observation(engine.ours(teams + [o for o in opponents if o not in teams]), observation)
    return {"teams": teams, "opponents": opponents, "baseline": args.baseline,
            "games": args.games, "seed": args.seed, "cycles": args.cycles, "observation": observation,
            **engine.params()}


def tables(records: Sequence, params: dict) -> tuple:
    """(goal-difference table, behaviour table, CSV rows of each)."""
    from experiments.reporting import Table
    from experiments.stats import figure_cell, paired_cells, pairing_summary

    teams, opponents, baseline = params["teams"], params["opponents"], params["baseline"]
    goal_table = Table(f"goal difference per match, mean (SE); {params['games']} games per pairing",
                       ["team (assigner)", *(f"vs {o}" for o in opponents)])
    goal_rows = []
    for team in teams:
        cells = [team]
        for opponent in opponents:
            pair = pairing_summary(records, team, opponent)
            gd = pair.goal_difference
            cells.append(gd.text())
            goal_rows.append([team, opponent, pair.games, pair.wins, pair.draws, pair.losses, pair.forfeits,
                              pair.goals_for, pair.goals_against, gd.mean, gd.se, gd.low, gd.high])
        goal_table.rows.append(cells)
    references = [o for o in opponents if o not in teams]
    behaviour = Table(f"behaviour per match, mean (SE), all opponents; paired with {baseline} against "
                      f"{', '.join(references) or '(no common opponent)'}",
                      ["team (assigner)", *(name for name, _, _ in behaviour_columns(params)),
                       f"GD minus {baseline} (SE)", "p"])
    behaviour_rows = []
    for team in teams:
        cells, row = [team], [team]
        for _, figure, scale in behaviour_columns(params):
            text, mean, se = figure_cell(records, team, figure, scale)
            cells.append(text)
            row += [mean, se]
        paired_text, paired_numbers = paired_cells(records, team, baseline, references)
        cells += paired_text
        row += paired_numbers
        behaviour.rows.append(cells)
        behaviour_rows.append(row)
    return goal_table, behaviour, goal_rows, behaviour_rows


def report(records: Sequence, params: dict, out_dir: Path | None = None) -> list[Path]:
    """Print both tables; with ``out_dir`` write case-study.csv, behaviour.csv, case-study.md
    and case-study.png there. Returns the files written."""
    from experiments.reporting import ESTIMATE_COLUMNS, write_csv, write_markdown
    from experiments.results.files import write_file

    goal_table, behaviour, goal_rows, behaviour_rows = tables(records, params)
    goal_table.print()
    behaviour.print()
    if out_dir is None:
        return []
    cycles = params["cycles"] or "regulation (6000)"
    written = [
        write_csv(out_dir / "case-study.csv", ["team", "opponent", "games", "wins", "draws", "losses", "forfeits",
                                               "goals_for", "goals_against", *ESTIMATE_COLUMNS], goal_rows),
        write_csv(out_dir / "behaviour.csv",
                  ["team", *(f"{figure}{suffix}" for _, figure, _ in behaviour_columns(params)
                             for suffix in ("", "_se")),
                   f"gd_minus_{params['baseline']}", "gd_difference_se", "p_value"], behaviour_rows),
        write_markdown(out_dir / "case-study.md", [goal_table, behaviour],
                       f"Case study: {len(records)} matches, seeds from {params['seed']}, cycles per match: {cycles}."),
        write_file(out_dir / "case-study.png", lambda path: _figure(path, params, goal_rows, behaviour_rows)),
    ]
    print("wrote " + ", ".join(str(path) for path in written))
    return written


def _figure(path: Path, params: dict, goal_rows: list, behaviour_rows: list) -> Path:
    """Grouped bars: mean goal difference (± SE) per assigner against each opponent; and the
    role switches and teammate contacts per assigner."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    teams, opponents = params["teams"], params["opponents"]
    figure, (goals, switches, contacts) = plt.subplots(1, 3, figsize=(15, 4.5),
                                                        gridspec_kw={"width_ratios": [2, 1, 1]})
    width = 0.8 / len(opponents)
    x = np.arange(len(teams))
    for k, opponent in enumerate(opponents):
        rows = [r for r in goal_rows if r[1] == opponent]
        goals.bar(x + (k - (len(opponents) - 1) / 2) * width, [r[9] for r in rows], width,
                  yerr=np.nan_to_num([r[10] for r in rows]), capsize=2, label=f"vs {opponent}")
    goals.axhline(0.0, color="black", linewidth=0.8)
    goals.set_xticks(x, teams, rotation=30, ha="right")
    goals.set_ylabel("mean goal difference per match (± SE)")
    goals.legend(fontsize=8)
    for axis, column, label in ((switches, 1, "role switches per minute"), (contacts, 3, "teammate contacts per match")):
        axis.bar(x, [r[column] for r in behaviour_rows], yerr=np.nan_to_num([r[column + 1] for r in behaviour_rows]),
                 capsize=3, color="tab:gray")
        axis.set_xticks(x, teams, rotation=30, ha="right")
        axis.set_title(label)
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    plt.close(figure)
    return path
