"""``soccer-sim evaluate POLICY --scenario NAME [--episodes N] [--opponent TEAM] [--seed S]``:
a policy's goal rate and mean score difference on a scenario, with 95 % intervals, over fixed
evaluation seeds disjoint from training seeds.

POLICY is a registered team name, a ``package.module:Attribute`` path (a PolicyTeam, or a
factory making one, for a learned policy) or a saved RL checkpoint named
``checkpoint:KIND:PATH?OPTION=VALUE&...`` (:mod:`soccer_sim.env.checkpoint_teams`). It plays the home side of every episode against
``--opponent``; episode k plays the match seed 2**32 + S + k (the protocol:
:mod:`experiments.evaluation`). Episodes are stored in ``--out`` as they finish (re-running the
same command plays only what is missing); the table is printed and written to ``--tables``
(``evaluation.csv``, ``evaluation.md``).
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from pathlib import Path

from experiments.commands import add_json_option, doc_summary, table_command
from experiments.limits import ranged

KIND = "evaluation"


def register(subparsers: argparse._SubParsersAction) -> None:
    subparsers.add_parser(
        "evaluate", help="a policy's goal rate and mean score difference on a scenario, over fixed evaluation seeds",
        description=doc_summary(__doc__), populate=_add_arguments)


def _add_arguments(parser: argparse.ArgumentParser) -> None:
    """The options (built only when the command is chosen)."""
    from experiments.commands.run_options import add_run_arguments
    from experiments.evaluation import DEFAULT_EPISODES, DEFAULT_OPPONENT

    parser.add_argument("policy", metavar="POLICY",
                        help="the team evaluated: a registered name, a package.module:Attribute path (a PolicyTeam "
                             "or a factory making one) or a saved RL checkpoint checkpoint:KIND:PATH?OPTION=VALUE&... "
                             "(KIND: sb3, torch, torchrl, tianshou, rllib; docs/env.md)")
    parser.add_argument("--scenario", required=True, metavar="NAME|FILE",
                        help="the scenario: a name from `soccer-sim scenarios` (full-match for the regular match) or "
                             "a .json/.toml file")
    parser.add_argument("--episodes", type=ranged("episodes"), default=DEFAULT_EPISODES,
                        help=f"episodes played (default: {DEFAULT_EPISODES})")
    parser.add_argument("--opponent", default=DEFAULT_OPPONENT,
                        help=f"the team on the other side (default: {DEFAULT_OPPONENT}, the environment's default "
                             "opponent): a registered name or a package.module:Attribute path")
    add_run_arguments(parser, "evaluation.sqlite",
                      seed_help="offset of the evaluation seeds: episode k plays seed 2**32 + SEED + k, above every "
                                "seed of a training episode (default: 0)")
    add_json_option(parser)
    parser.set_defaults(func=table_command(run))


def build_specs(params: dict) -> list:
    """Every episode of the evaluation ``params`` describe (policy, opponent, episodes, seed,
    scenario, cycles, observation)."""
    from experiments.commands.run_options import scenario_named
    from experiments.configuration import match_config
    from experiments.evaluation import evaluation_specs

    config = match_config(params["cycles"], params.get("observation", "full"))
    return evaluation_specs(params["policy"], params["opponent"], params["episodes"], params["seed"],
                            scenario_named(params["scenario"]), config)


def run(args: argparse.Namespace) -> int:
    from experiments.commands.run_options import run_command

    return run_command(args, KIND, _params, build_specs, report)


def _params(args: argparse.Namespace) -> dict:
    from experiments.commands.run_options import RunInputError, check_observation, scenario_option, team_list
    from experiments.configuration import match_config
    from experiments.evaluation import EVALUATION_SEED_BASE
    from experiments.limits import MAX_SEED

    policy = team_list(args.policy, "POLICY")
    opponent = team_list(args.opponent, "--opponent")
    if len(policy) != 1 or len(opponent) != 1:
        raise RunInputError(f"POLICY and --opponent name one team each, got {args.policy!r} and {args.opponent!r}")
    scenario_option(args.scenario, match_config(args.cycles, args.observation))
    check_observation([*policy, *opponent], args.observation)
    last = MAX_SEED - EVALUATION_SEED_BASE - args.episodes + 1
    if args.seed > last:
        raise RunInputError(f"--seed must be at most {last} with --episodes {args.episodes} (evaluation seeds start "
                            f"at 2**32 + SEED and a results file stores seeds up to {MAX_SEED})")
    return {"policy": policy[0], "opponent": opponent[0], "episodes": args.episodes, "seed": args.seed,
            "scenario": args.scenario, "cycles": args.cycles, "observation": args.observation}


COLUMNS = ["policy", "opponent", "scenario", "episodes", "goal rate [95% CI]", "mean score diff [95% CI]", "GF",
           "GA", "FF"]
LEGEND = ("goal rate: share of episodes the policy scored in (Wilson interval); mean score diff: goals for minus "
          "against per episode (Student's t interval); GF/GA goals for/against; FF episodes the policy forfeited "
          "(counted as without a goal); seeds 2**32 + SEED + k")


def _interval(value, digits: int = 2, signed: bool = False) -> str:
    """``0.57 [0.39, 0.73]``: the estimate and its 95 % interval (``-`` where undefined)."""
    import math

    if value.n == 0:
        return "-"
    sign = "+" if signed else ""
    if math.isnan(value.low):
        return f"{value.mean:{sign}.{digits}f}"
    return f"{value.mean:{sign}.{digits}f} [{value.low:{sign}.{digits}f}, {value.high:{sign}.{digits}f}]"


def report(records: Sequence, params: dict, out_dir: Path | None = None) -> list[Path]:
    """Print the evaluation's table; with ``out_dir``, write evaluation.csv and evaluation.md
    there (each whole or not at all). Returns the files written."""
    from experiments.commands.run_options import team_labels
    from experiments.evaluation import EVALUATION_SEED_BASE, summarise
    from experiments.reporting import Table, write_csv, write_markdown

    summary = summarise(records, params["policy"], params["opponent"])
    labels = team_labels([params["policy"], params["opponent"]])
    policy, opponent = labels[params["policy"]], labels[params["opponent"]]
    rate, difference = summary.goal_rate, summary.score_difference
    table = Table(f"evaluation of {policy} on {params['scenario']}", COLUMNS, labels=3, caption=LEGEND)
    table.rows.append([policy, opponent, params["scenario"], str(summary.episodes), _interval(rate),
                       _interval(difference, signed=True), str(summary.goals_for), str(summary.goals_against),
                       str(summary.forfeits)])
    table.print()
    if out_dir is None:
        return []
    first = EVALUATION_SEED_BASE + params["seed"]
    header = ["policy_name", "policy", "opponent", "scenario", "episodes", "first_seed", "goal_rate", "goal_rate_low",
              "goal_rate_high", "mean_score_diff", "score_diff_se", "score_diff_low", "score_diff_high", "goals_for",
              "goals_against", "forfeits"]
    row = [policy, params["policy"], params["opponent"], params["scenario"], summary.episodes, first, rate.mean,
           rate.low, rate.high, difference.mean, difference.se, difference.low, difference.high, summary.goals_for,
           summary.goals_against, summary.forfeits]
    written = [write_csv(out_dir / "evaluation.csv", header, [row]),
               write_markdown(out_dir / "evaluation.md", [table],
                              f"Evaluation: {summary.episodes} episodes on seeds from {first}.")]
    print("wrote " + ", ".join(str(path) for path in written))
    return written
