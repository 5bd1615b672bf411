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
from collections.abc import Callable, Sequence
from dataclasses import astuple, dataclass, fields
from pathlib import Path

import numpy as np

from experiments.commands import doc_summary

KIND = "penalty-shot"
PLAY = "experiments.studies.penalty_shot:play_chain"
"""What the runner calls to play one chain (see :attr:`experiments.runner.spec.MatchSpec.play`)."""
CONDITIONS = ("one", "uncoordinated", "coordinated")
SETTINGS = ("empty goal", "goalkeeper")
PAIRS = (("one", "uncoordinated"), ("one", "coordinated"), ("uncoordinated", "coordinated"))
"""The condition pairs compared by the signed-rank test."""
MARKER_INSET = 3.0
"""Markers lie at least this far (m) inside the lines."""
ROBOT_SPACING = 4.0
"""Metres between the attackers on their goal line at the first trial."""
KEEPER_START = (51.5, 0.0)
"""Where the goalkeeper starts every trial (on the line of the goal the attackers attack)."""


@dataclass(frozen=True)
class Trial:
    """One trial: a marker, a condition, a setting and how long the attackers took."""

    setting: str
    condition: str
    trial: int
    marker_x: float
    marker_y: float
    cycles: int
    seconds: float
    scored: bool


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.arguments import positive_int
    from experiments.commands.run_options import add_run_arguments

    parser.description = doc_summary(__doc__)
    parser.add_argument("--trials", type=positive_int, default=60,
                        help="markers visited per condition and setting (default: %(default)s)")
    parser.add_argument("--robots", type=positive_int, default=3,
                        help="attackers in the uncoordinated and coordinated conditions (default: %(default)s)")
    parser.add_argument("--team", default="bidding",
                        help="the attackers' team (a registered name; default: %(default)s, potential-field bidding)")
    parser.add_argument("--keeper", default="static",
                        help="the goalkeeper's team in the second setting, played with one player (default: %(default)s)")
    parser.add_argument("--limit", type=positive_int, default=1200,
                        help="cycles a trial may last before it counts as a timeout (default: %(default)s, 2 minutes)")
    add_run_arguments(parser, "penalty-shot.sqlite")


# ---------------------------------------------------------------------------------- the design
def markers(count: int, seed: int, half_length: float = 52.5, half_width: float = 34.0,
            goal_area_length: float = 5.5, goal_area_half_width: float = 9.16) -> np.ndarray:
    """(count, 2) the fixed marker sequence (absolute frame, the attackers attack +x):
    alternately in the attackers' own half and in the opponents' half, uniform within
    ``MARKER_INSET`` of the lines, none in or next to the goal area they attack."""
    rng = np.random.default_rng([seed, 0x5E7])
    out = np.empty((count, 2))
    x_max, y_max = half_length - MARKER_INSET, half_width - MARKER_INSET
    for i in range(count):
        while True:
            x = rng.uniform(-x_max, 0.0) if i % 2 == 0 else rng.uniform(0.0, x_max)
            y = rng.uniform(-y_max, y_max)
            near_goal = x > half_length - goal_area_length - 1.0 and abs(y) < goal_area_half_width + 1.0
            if not near_goal:
                break
        out[i] = (x, y)
    return out


def first_positions(robots: int, half_length: float = 52.5) -> np.ndarray:
    """(robots, 2) the attackers on their own goal line at the first trial, ``ROBOT_SPACING`` apart."""
    y = (np.arange(robots) - (robots - 1) / 2.0) * ROBOT_SPACING
    return np.column_stack([np.full(robots, -half_length + 0.5), y])


def settle(positions: np.ndarray, half_length: float, half_width: float, gap: float,
           fixed: Sequence[tuple[float, float]] = ()) -> np.ndarray:
    """``positions`` moved onto the field (a scorer may stand behind the goal line), half a metre
    inside the lines, and apart by at least ``gap`` (m), so that they are a valid start for the
    next trial: each overlapping pair is pushed apart symmetrically until none is left. An
    attacker closer than ``gap`` to one of the ``fixed`` players (the goalkeeper's start on its
    line) is moved sideways off it."""
    pos = positions.astype(float).copy()
    x_max, y_max = half_length - 0.5, half_width - 0.5
    for _ in range(100):
        np.clip(pos[:, 0], -x_max, x_max, out=pos[:, 0])
        np.clip(pos[:, 1], -y_max, y_max, out=pos[:, 1])
        moved = False
        for i in range(len(pos)):
            for j in range(i + 1, len(pos)):
                d = pos[j] - pos[i]
                dist = float(np.hypot(*d))
                if dist < gap:
                    # Apart along their line, or across the field when they coincide.
                    direction = d / dist if dist > 1e-9 else np.array([0.0, 1.0])
                    shift = direction * (gap - dist + 1e-6) / 2.0
                    pos[i] -= shift
                    pos[j] += shift
                    moved = True
        for q in fixed:
            for i in range(len(pos)):
                d = pos[i] - q
                if float(np.hypot(*d)) < gap:
                    # Sideways: a scorer on the goal line cannot go further back.
                    side = 1.0 if d[1] >= 0 else -1.0
                    pos[i, 1] = q[1] + side * (math.sqrt(max(gap * gap - d[0] * d[0], 0.0)) + 1e-6)
                    moved = True
        if not moved:
            return pos
    raise ValueError(f"cannot place {len(pos)} attackers {gap} m apart on the field")


def trial_scenario(marker: np.ndarray, attackers: np.ndarray, keeper: bool, limit: int):
    """One trial: the attackers (home, no goalkeeper) at rest at ``attackers``, the ball still
    on ``marker``, an empty goal or a goalkeeper on its line; ends at the goal or ``limit``."""
    from soccer_sim.scenarios import BallStart, Scenario, Side

    away = Side(positions=[KEEPER_START], goalie=0) if keeper else Side(players=0)
    return Scenario(name="penalty-shot", description="attackers score from a marker",
                    home=Side(positions=[tuple(p) for p in attackers.tolist()], goalie=None), away=away,
                    ball=BallStart(position=tuple(marker.tolist())), start_mode="play_on", end_on=("scored",),
                    cycle_limit=limit, offside=False, set_plays=False, half_time=False)


class Uncoordinated:
    """``robots`` players, each running its own one-player copy of a team, blind to the others
    (they are neither team-mates nor opponents to it): the "no coordination" condition.

    ``factory`` makes a fresh team object; each copy gets its own random stream."""

    def __init__(self, factory: Callable[[], object], robots: int, name: str = "uncoordinated") -> None:
        self.factory = factory
        self.robots = robots
        self.name = name

    def reset(self, side_info, config, rng: np.random.Generator) -> None:
        from soccer_sim import SideInfo, TeamCommand, TeamError, TeamView

        n = side_info.players_per_team
        if n != self.robots:
            raise TeamError(self.name, f"plays {self.robots} robots, not {n}")
        m = side_info.opponents
        self.copies = [self.factory() for _ in range(n)]
        self.views = []
        for k, (team, child) in enumerate(zip(self.copies, rng.spawn(n))):
            team.reset(SideInfo(side_info.team, f"{self.name}[{k}]", side_info.opponent_name, 1, -1, m,
                                side_info.opponent_goalie_index), config, child)
            self.views.append(TeamView(own_pos=np.zeros((1, 2)), own_vel=np.zeros((1, 2)), opp_pos=np.zeros((m, 2)),
                                       opp_vel=np.zeros((m, 2)), ball=np.zeros(2), ball_vel=np.zeros(2),
                                       stamina=np.zeros(1), effort=np.ones(1), capacity=np.full(1, np.inf)))
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view):
        command = self.command
        command.catch = False
        command.move = None
        for k, (team, own) in enumerate(zip(self.copies, self.views)):
            own.own_pos[0] = view.own_pos[k]
            own.own_vel[0] = view.own_vel[k]
            own.opp_pos[:] = view.opp_pos
            own.opp_vel[:] = view.opp_vel
            own.ball[:] = view.ball
            own.ball_vel[:] = view.ball_vel
            own.stamina[0] = view.stamina[k]
            own.effort[0] = view.effort[k]
            own.capacity[0] = view.capacity[k]
            own.play_mode, own.mode_ours, own.score = view.play_mode, view.mode_ours, view.score
            own.cycle, own.half, own.ball_holder = view.cycle, view.half, -1
            decision = team.act(own)
            command.dash[k] = decision.dash[0]
            command.kick[k] = decision.kick[0]
        return command


def _attackers(condition: str, team: str, robots: int):
    from soccer_sim import resolve_team

    if condition == "uncoordinated":
        return Uncoordinated(lambda: resolve_team(team)[0], robots), robots
    return resolve_team(team)[0], (1 if condition == "one" else robots)


def run_chain(setting: str, condition: str, team: str, keeper_team: str, robots: int, marker_list: np.ndarray,
              limit: int, seed: int, watch: Callable[[object, int], object] | None = None) -> list[Trial]:
    """Play one condition's trials in order, each starting where the previous goal left the
    attackers. ``watch(team, side)`` wraps each team object played (0: the attackers, 1: the
    keeper), e.g. so the runner can blame the side whose code fails."""
    from soccer_sim import MatchConfig, resolve_team, run_match

    watch = watch or (lambda team_object, side: team_object)
    config = MatchConfig()
    f, phys = config.field, config.physics
    keeper = setting == "goalkeeper"
    attackers, count = _attackers(condition, team, robots)
    attackers = watch(attackers, 0)
    keeper_side = watch(resolve_team(keeper_team)[0], 1) if keeper else "idle"
    positions = first_positions(count, f.half_length)
    trials = []
    for i, marker in enumerate(marker_list):
        start = settle(positions, f.half_length, f.half_width, 2.0 * phys.player_radius + 0.05,
                       fixed=[KEEPER_START] if keeper else [])
        result = run_match(attackers, keeper_side, seed=seed + i, config=config,
                           scenario=trial_scenario(marker, start, keeper, limit))
        scored = result.end_reason == "scored"
        trials.append(Trial(setting, condition, i, float(marker[0]), float(marker[1]), result.cycles,
                            result.cycles * phys.cycle_seconds, scored))
        positions = result.state.pos[:count].copy()
    return trials


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
    rows = sorted((t for t in trials if t.setting == setting and t.condition == condition), key=lambda t: t.trial)
    return np.array([t.seconds for t in rows])


def signed_rank_p(a: np.ndarray, b: np.ndarray) -> float:
    """Two-sided p-value of the Wilcoxon signed-rank test on the paired times; 1.0 when every
    pair is equal, NaN with fewer than two pairs (or unpaired times: a forfeited chain)."""
    from scipy.stats import wilcoxon

    if len(a) < 2 or len(a) != len(b):
        return math.nan
    if np.all(a == b):
        return 1.0
    return float(wilcoxon(a, b).pvalue)


def summarise(trials: Sequence[Trial]) -> tuple[list[dict], list[dict]]:
    """(per setting and condition: trials, mean, sd, median, timeouts; per setting and pair:
    the mean paired difference and the signed-rank p-value)."""
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
    from soccer_sim.scenarios import MAX_PLAYERS

    if args.robots > MAX_PLAYERS:
        raise RunInputError(f"--robots must be at most {MAX_PLAYERS} (players a side), got {args.robots}")
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
    return {"trials": args.trials, "robots": args.robots, "team": args.team, "keeper": args.keeper,
            "limit": args.limit, "seed": args.seed, "cycles": None}


def report(records: Sequence, params: dict, out_dir: Path | None = None) -> list[Path]:
    """Print the tables from the chains played to their end (a forfeited chain's row is empty,
    its tests ``-``); with ``out_dir`` write the trials, the summary and the tests as CSV, the
    tables as Markdown and the box plot there. Returns the files written."""
    from experiments.reporting import write_csv, write_markdown

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
        _plot(trials, params, out_dir / "penalty_shot.png"),
    ]
    print("wrote " + ", ".join(str(path) for path in written))
    return written
