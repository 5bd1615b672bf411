"""``soccer-sim experiment penalty-shot``: the penalty-shot experiment of "Dynamic multi-robot
coordination" (Vail and Veloso) in this simulator.

Attackers score on an empty goal, starting from a fixed sequence of ball markers spread over
the field, half in each half, in the same order for every condition. Trial ``i`` places the
ball, still, on marker ``i``; the attackers start where they stood when trial ``i - 1``'s goal
was scored (at rest; the first trial starts them on their own goal line), so a trial begins
from wherever the previous play left them, as after an opponent's clearance in a game. The
trial ends with a goal (its time to score) or at ``--limit`` cycles (a timeout, counted at the
limit). There are no set plays: a ball out over a line is put back a metre inside, where it
left, and play goes on.

Three conditions, the same team code (``--team``, potential-field bidding by default):

* ``one``: a single robot;
* ``uncoordinated``: ``--robots`` robots that each run the one-robot team on their own, blind
  to each other (so all of them chase the ball);
* ``coordinated``: ``--robots`` robots as one team, coordinated by the team's role assigner
  (with ``bidding``: one robot wins the ball role, the others take supporting roles).

Each condition's times are compared marker by marker with the Wilcoxon signed-rank test
(``scipy.stats.wilcoxon``, two-sided). Then the same again with a goalkeeper (``--keeper``'s
team, one player) defending the goal. Prints the tables (mean, standard deviation and median
time per condition, timeouts, p-values) and writes ``penalty_shot_trials.csv`` (one row per
trial), ``penalty_shot_summary.csv``, ``penalty_shot_tests.csv``, ``penalty_shot.md`` and
``penalty_shot.png`` (box plots) to ``--tables``.

The six chains (setting x condition) run on the shared runner (:mod:`experiments.runner`), one
chain per runner spec (:attr:`~experiments.runner.spec.MatchSpec.play` names
:func:`play_chain`): progress, a results file (``--out``) that a re-run continues, a time
budget per chain (``--match-timeout``), and a team that fails forfeits its chain without
stopping the others. A chain's key names the attackers (team, condition, robots), the defence
(empty goal or the keeper's team), the trial count and limit, and ``--seed``, so a results file
never mixes chains of other parameters; ``soccer-sim results show FILE`` prints the tables again.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Sequence
from dataclasses import astuple, fields
from pathlib import Path

from experiments.commands import doc_summary
from experiments.studies.penalty_trials import (CONDITIONS, KEEPER_START, MARKER_INSET, SETTINGS, Trial, Uncoordinated,
                                                first_positions, markers, run_chain, settle, trial_scenario)

__all__ = ["CONDITIONS", "KEEPER_START", "KIND", "MARKER_INSET", "PAIRS", "PLAY", "SETTINGS", "Trial", "Uncoordinated",
           "add_arguments", "build_specs", "first_positions", "markers", "play_chain", "report", "run", "run_chain",
           "settle", "signed_rank_p", "stored_trials", "summarise", "trial_scenario"]

KIND = "penalty-shot"
PLAY = "experiments.studies.penalty_shot:play_chain"
"""What the runner calls to play one chain (see :attr:`experiments.runner.spec.MatchSpec.play`)."""
PAIRS = (("one", "uncoordinated"), ("one", "coordinated"), ("uncoordinated", "coordinated"))
"""The condition pairs compared by the signed-rank test."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.limits import ranged
    from experiments.commands.run_options import add_run_arguments

    parser.description = doc_summary(__doc__)
    parser.add_argument("--trials", type=ranged("trials"), default=60,
                        help="markers visited per condition and setting (default: %(default)s)")
    parser.add_argument("--robots", type=ranged("robots"), default=3,
                        help="attackers in the uncoordinated and coordinated conditions (default: %(default)s)")
    parser.add_argument("--team", default="bidding",
                        help="the attackers' team (a registered name; default: %(default)s, potential-field bidding)")
    parser.add_argument("--keeper", default="static",
                        help="the goalkeeper's team in the second setting, played with one player (default: %(default)s)")
    parser.add_argument("--limit", type=ranged("limit"), default=1200,
                        help="cycles a trial may last before it counts as a timeout (default: %(default)s, 2 minutes)")
    add_run_arguments(parser, "penalty-shot.sqlite")


# ---------------------------------------------------------------------------------- on the runner
def chain_names(setting: str, condition: str, params: dict) -> tuple[str, str]:
    """(home, away) naming one chain in a results file: the attackers (team, condition, robots)
    and the defence with the trial count and limit; with ``--seed`` the key of the chain."""
    robots = 1 if condition == "one" else params["robots"]
    home = f"{params['team']} ({condition}, {robots} robot{'' if robots == 1 else 's'})"
    defence = "empty goal" if setting == "empty goal" else f"{params['keeper']} goalkeeper"
    return home, f"{defence}, {params['trials']} trials of {params['limit']} cycles"


def chain_specs(params: dict) -> list[tuple[str, str, object]]:
    """(setting, condition, runner spec) of every chain, in table order."""
    from experiments.runner.spec import MatchSpec

    found = []
    for setting in SETTINGS:
        for condition in CONDITIONS:
            home, away = chain_names(setting, condition, params)
            arguments = (("setting", setting), ("condition", condition), ("team", params["team"]),
                         ("keeper", params["keeper"]), ("robots", params["robots"]), ("trials", params["trials"]),
                         ("limit", params["limit"]))
            teams = (params["team"], params["keeper"]) if setting == "goalkeeper" else (params["team"], "idle")
            found.append((setting, condition, MatchSpec(home, away, params["seed"], None, play=PLAY,
                                                        play_args=arguments, plays_teams=teams)))
    return found


def build_specs(params: dict) -> list:
    """The six chains of the study as runner specs."""
    return [spec for _, _, spec in chain_specs(params)]


def play_chain(spec, record, watch) -> None:
    """Play the chain of ``spec`` in a runner worker (see
    :attr:`~experiments.runner.spec.MatchSpec.play`) and fill ``record``: the home goals are the
    trials scored, the cycles those of all trials, and the home statistics hold each trial's
    cycles and whether it scored (``trial_0000_cycles``, ``trial_0000_scored``, ...)."""
    args = dict(spec.play_args)
    names = (spec.home, spec.away)
    trials = run_chain(args["setting"], args["condition"], args["team"], args["keeper"], args["robots"],
                       markers(args["trials"], spec.seed), args["limit"], spec.seed,
                       watch=lambda team, side: watch(team, names[side], side))
    record.home_goals, record.away_goals = sum(t.scored for t in trials), 0
    record.cycles = sum(t.cycles for t in trials)
    record.home_stats = {name: value for t in trials
                         for name, value in ((f"trial_{t.trial:04d}_cycles", t.cycles),
                                             (f"trial_{t.trial:04d}_scored", int(t.scored)))}
    record.away_stats = {}


def stored_trials(records: Sequence, params: dict) -> list[Trial]:
    """Every trial of the chains played to their end among ``records`` (forfeited chains have
    none), rebuilt from the stored statistics."""
    from soccer_sim import MatchConfig

    cycle_seconds = MatchConfig().physics.cycle_seconds
    marker_list = markers(params["trials"], params["seed"])
    by_key = {record.key: record for record in records if record.played}
    trials = []
    for setting, condition, spec in chain_specs(params):
        record = by_key.get(spec.key)
        if record is None:
            continue
        for i, marker in enumerate(marker_list):
            cycles = int(record.home_stats[f"trial_{i:04d}_cycles"])
            trials.append(Trial(setting, condition, i, float(marker[0]), float(marker[1]), cycles,
                                cycles * cycle_seconds, bool(record.home_stats[f"trial_{i:04d}_scored"])))
    return trials


# ---------------------------------------------------------------------------------- statistics
def times(trials: Sequence[Trial], setting: str, condition: str) -> np.ndarray:
    """The seconds to score of one chain, in marker order."""
    import numpy as np

    rows = sorted((t for t in trials if t.setting == setting and t.condition == condition), key=lambda t: t.trial)
    return np.array([t.seconds for t in rows])


def signed_rank_p(a: np.ndarray, b: np.ndarray) -> float:
    """Two-sided p-value of the Wilcoxon signed-rank test on the paired times; 1.0 when every
    pair is equal, NaN with fewer than two pairs (or unpaired times: a forfeited chain)."""
    from scipy.stats import wilcoxon
    import numpy as np

    if len(a) < 2 or len(a) != len(b):
        return math.nan
    if np.all(a == b):
        return 1.0
    return float(wilcoxon(a, b).pvalue)


def summarise(trials: Sequence[Trial]) -> tuple[list[dict], list[dict]]:
    """(per setting and condition: trials, mean, sd, median, timeouts; per setting and pair:
    the mean paired difference and the signed-rank p-value)."""
    import numpy as np

    summary, tests = [], []
    for setting in SETTINGS:
        for condition in CONDITIONS:
            t = times(trials, setting, condition)
            scored = [x.scored for x in trials if x.setting == setting and x.condition == condition]
            summary.append({"setting": setting, "condition": condition, "trials": len(t),
                            "mean_s": float(t.mean()) if len(t) else math.nan,
                            "sd_s": float(t.std(ddof=1)) if len(t) > 1 else math.nan,
                            "median_s": float(np.median(t)) if len(t) else math.nan,
                            "timeouts": int(len(scored) - sum(scored))})
        for first, second in PAIRS:
            a, b = times(trials, setting, first), times(trials, setting, second)
            tests.append({"setting": setting, "pair": f"{first} vs {second}",
                          "mean_difference_s": float((a - b).mean()) if len(a) and len(a) == len(b) else math.nan,
                          "p_value": signed_rank_p(a, b)})
    return summary, tests


# ---------------------------------------------------------------------------------- output
def _tables(summary: list[dict], tests: list[dict], params: dict):
    from experiments.reporting import Table

    def fmt(value: float, digits: int = 2) -> str:
        return "-" if math.isnan(value) else f"{value:.{digits}f}"

    times_table = Table(f"Time to score (s), {params['trials']} markers, {params['robots']} robots in the team conditions",
                        ["setting", "condition", "mean", "sd", "median", "timeouts"], labels=2)
    for row in summary:
        times_table.rows.append([row["setting"], row["condition"], fmt(row["mean_s"]), fmt(row["sd_s"]),
                                 fmt(row["median_s"]), str(row["timeouts"]) if row["trials"] else "-"])
    tests_table = Table("Wilcoxon signed-rank tests (paired by marker, two-sided)",
                        ["pair", *(f"{s}: mean diff (s)" for s in SETTINGS), *(f"{s}: p" for s in SETTINGS)])
    for first, second in PAIRS:
        pair = f"{first} vs {second}"
        cells = {(t["setting"], k): t[k] for t in tests if t["pair"] == pair for k in ("mean_difference_s", "p_value")}
        tests_table.rows.append([pair, *(fmt(cells[(s, "mean_difference_s")]) for s in SETTINGS),
                                 *(_p(cells[(s, "p_value")]) for s in SETTINGS)])
    return times_table, tests_table


def _p(value: float) -> str:
    if math.isnan(value):
        return "-"
    return f"{value:.2g}" if value >= 1e-4 else f"{value:.1e}"


def _plot(trials: Sequence[Trial], params: dict, path: Path) -> Path:
    import matplotlib
    import numpy as np

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, len(SETTINGS), figsize=(10, 4.2), sharey=True)
    for ax, setting in zip(np.atleast_1d(axes), SETTINGS):
        data = [times(trials, setting, c) for c in CONDITIONS]
        ax.boxplot(data, showmeans=True)
        ax.set_xticks(range(1, len(CONDITIONS) + 1), [f"{c}\n({1 if c == 'one' else params['robots']} robot"
                                                       f"{'' if c == 'one' else 's'})" for c in CONDITIONS])
        ax.set_title(setting)
        ax.grid(axis="y", alpha=0.3)
    np.atleast_1d(axes)[0].set_ylabel("time to score (s)")
    fig.suptitle(f"penalty shot: {params['trials']} markers, team {params['team']!r}, keeper {params['keeper']!r}")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def run(args: argparse.Namespace) -> int:
    from experiments.commands.run_options import run_command

    return run_command(args, KIND, _params, build_specs, report)


def _params(args: argparse.Namespace) -> dict:
    """The study's parameters; a RunInputError naming the option that cannot be used."""
    from experiments.commands.run_options import RunInputError
    from soccer_sim import TeamNotFoundError, resolve_team

    for option, name in (("--team", args.team), ("--keeper", args.keeper)):
        try:
            resolve_team(name)
        except TeamNotFoundError as exc:
            raise RunInputError(f"{option}: {exc}") from None
    # A chain is many scenario matches with no single configuration length or replay: these
    # options do not apply.
    if args.cycles is not None:
        raise RunInputError("--cycles does not apply to penalty-shot: a trial lasts at most --limit cycles")
    if args.record_dir is not None:
        raise RunInputError("--record-dir does not apply to penalty-shot (a chain is many short trials)")
    if getattr(args, "rcg_dir", None) is not None:
        raise RunInputError("--rcg-dir does not apply to penalty-shot (a chain is many short trials)")
    return {"trials": args.trials, "robots": args.robots, "team": args.team, "keeper": args.keeper,
            "limit": args.limit, "seed": args.seed, "cycles": None}


def report(records: Sequence, params: dict, out_dir: Path | None = None) -> list[Path]:
    """Print the tables from the chains played to their end (a forfeited chain's row is empty,
    its tests ``-``); with ``out_dir`` write the trials, the summary and the tests as CSV, the
    tables as Markdown and the box plot there. Returns the files written."""
    from experiments.reporting import write_csv, write_markdown
    from experiments.results.files import write_file

    trials = stored_trials(records, params)
    summary, tests = summarise(trials)
    tables = _tables(summary, tests, params)
    for table in tables:
        table.print()
    chains = len({(t.setting, t.condition) for t in trials})
    print(f"{len(trials)} trials in {chains} of {len(SETTINGS) * len(CONDITIONS)} chains")
    if out_dir is None:
        return []
    written = [
        write_csv(out_dir / "penalty_shot_trials.csv", [f.name for f in fields(Trial)], [astuple(t) for t in trials]),
        write_csv(out_dir / "penalty_shot_summary.csv", list(summary[0]), [list(r.values()) for r in summary]),
        write_csv(out_dir / "penalty_shot_tests.csv", list(tests[0]), [list(r.values()) for r in tests]),
        write_markdown(out_dir / "penalty_shot.md", list(tables),
                       f"Penalty shot: {params['trials']} markers, team {params['team']}, keeper {params['keeper']}, "
                       f"limit {params['limit']} cycles, seed {params['seed']}."),
        write_file(out_dir / "penalty_shot.png", lambda path: _plot(trials, params, path)),
    ]
    print("wrote " + ", ".join(str(path) for path in written))
    return written
