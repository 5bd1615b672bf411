"""``soccer-sim experiment ablation``: which limit of partial observation costs a team what.

Each team of ``--teams`` plays each opponent of ``--opponents`` under partial observation,
``--games`` matches per pairing on paired seeds (sides swapped; the same seeds for every
pairing and switch), once per switch of ``--switches``. A switch turns ONE limit of partial
observation off for BOTH teams of the match; ``baseline`` turns none off. The switches are the
entries of :data:`SWITCHES`:

* ``baseline``: partial observation as it is;
* ``exact-self``: each player knows its own position and velocity exactly
  (``SeeParams.exact_self``);
* ``omni``: no view cone: every object within range is seen with its identity
  (``SeeParams.omnidirectional``);
* ``all-heard``: no hearing capacity: every message said within ``audio_cut_dist`` is heard
  (``AudioParams.hear_decay`` 0; the distance limit stays);
* ``no-noise``: no observation noise: distances and directions reported exactly, no identity
  lost with distance (:meth:`SeeParams.without_noise <soccer_sim.perception.params.SeeParams.without_noise>`).

One table, one row per team and switch: the mean goal difference (SE) against each opponent,
its paired difference from the same team's ``baseline`` row (same opponents, seeds and sides;
paired t-test p-value), and, over all opponents, the team's makespan as its players believe
it, its believed role conflicts, the share of play-on cycles in which all its players follow
one assignment, the median agreement latency and the teammate contacts per match (the figures
of the partial-observation case study, :data:`FIGURES`). Teams that do not report a figure
show "-". Written as CSV and Markdown to ``--tables``; the matches go to the results file
``--out``, which a re-run of the same command continues.

In the results file a match is stored under the team's name with its switch in brackets
(``mmdr [omni]`` against ``counter-442``): the switch applies to the whole match, opponent
included. Each match is played by :func:`play_ablated` (the runner's
:attr:`~experiments.runner.spec.MatchSpec.play`), which applies the switch to the stored
partial-observation configuration, so one results file holds every switch.
"""

from __future__ import annotations

import argparse
from collections.abc import Callable, Sequence
from dataclasses import dataclass, replace
from pathlib import Path
from typing import TYPE_CHECKING

from experiments.commands import doc_summary

if TYPE_CHECKING:  # annotations only: importing the simulator is left to what plays matches
    from soccer_sim import MatchConfig
    from soccer_sim.perception.config import ObservationConfig

KIND = "ablation"
PLAY = "experiments.studies.ablation:play_ablated"
"""What the runner calls to play one match of the study (see :attr:`experiments.runner.spec.MatchSpec.play`)."""
DEFAULT_TEAMS = ("mmdr", "mmd+msd2", "static")
DEFAULT_OPPONENTS = ("counter-442",)
BASELINE = "baseline"
"""The switch that turns nothing off: every other switch's row is compared with it."""


def _unchanged(observation: ObservationConfig) -> ObservationConfig:
    return observation


def _exact_self(observation: ObservationConfig) -> ObservationConfig:
    return replace(observation, see=replace(observation.see, exact_self=True))


def _omnidirectional(observation: ObservationConfig) -> ObservationConfig:
    return replace(observation, see=replace(observation.see, omnidirectional=True))


def _every_message_heard(observation: ObservationConfig) -> ObservationConfig:
    return replace(observation, audio=replace(observation.audio, hear_decay=0))


def _noiseless(observation: ObservationConfig) -> ObservationConfig:
    return replace(observation, see=observation.see.without_noise())


@dataclass(frozen=True)
class Switch:
    """One row of the ablation: the limit of partial observation it turns off, as a change of
    the match's observation configuration and/or team options given to both teams."""

    name: str
    removes: str
    """The limit turned off, in words (the table's caption, ``--help``)."""
    observation: Callable[[ObservationConfig], ObservationConfig] = _unchanged
    """The match's observation configuration with the limit off."""
    team_options: tuple[tuple[str, object], ...] = ()
    """(keyword, value) options both teams' factories are called with
    (:func:`soccer_sim.resolve_team`); a team whose factory does not take them is refused
    before any match."""

    def configured(self, config: MatchConfig) -> MatchConfig:
        """``config`` with this switch's limit off (validated: a ConfigError if it is not a
        configuration a match can play)."""
        return replace(config, observation=self.observation(config.observation))


SWITCHES: dict[str, Switch] = {switch.name: switch for switch in (
    Switch(BASELINE, "nothing: partial observation as it is"),
    Switch("exact-self", "self-localisation: each player knows its own position and velocity", _exact_self),
    Switch("omni", "the view cone: every object within range is seen, with its identity", _omnidirectional),
    Switch("all-heard", "hearing capacity: every message said within audio_cut_dist is heard",
           _every_message_heard),
    Switch("no-noise", "observation noise: exact distances and directions, no identity lost with distance",
           _noiseless),
    Switch("agreement", "disagreement: every player follows one assignment, computed on one player's belief "
                        "and known to all at once", team_options=(("shared_assignment", True),)),
)}
"""Every switch by name, in table order."""

FIGURES = ("target_distance_max", "role_conflict_share", "all_follow_one_share", "agreement_latency_median",
           "teammate_contacts")
"""The team statistics the table shows, as the case study defines and labels them
(:data:`experiments.studies.case_study.BEHAVIOUR`, :data:`~experiments.studies.case_study.PARTIAL_BEHAVIOUR`)."""


def figure_columns() -> tuple[tuple[str, str, float], ...]:
    """(column, statistic, scale) of each of :data:`FIGURES`, from the case study's definitions."""
    from experiments.studies.case_study import BEHAVIOUR, PARTIAL_BEHAVIOUR

    defined = {statistic: (column, statistic, scale) for column, statistic, scale in BEHAVIOUR + PARTIAL_BEHAVIOUR}
    return tuple(defined[statistic] for statistic in FIGURES)


def ablated_name(team: str, switch: str) -> str:
    """How the results file names ``team`` playing under ``switch``: ``team [switch]``."""
    return f"{team} [{switch}]"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.limits import ranged
    from experiments.commands.run_options import add_run_arguments, add_team_option

    parser.description = doc_summary(__doc__)
    add_team_option(parser, "--teams", DEFAULT_TEAMS, "the teams whose rows the table shows")
    add_team_option(parser, "--opponents", DEFAULT_OPPONENTS, "their opponents")
    parser.add_argument("--switches", default=",".join(SWITCHES),
                        help="the switches played, comma-separated, baseline among them (default: all): "
                             + "; ".join(f"{s.name}: {s.removes}" for s in SWITCHES.values()))
    parser.add_argument("--games", type=ranged("games"), default=300,
                        help="matches per pairing and switch, rounded up to even: sides swapped on paired seeds "
                             "(default: 300)")
    add_run_arguments(parser, "ablation.sqlite", observation=False)  # always partial observation


def run(args: argparse.Namespace) -> int:
    from experiments.commands.run_options import run_command

    return run_command(args, KIND, _params, build_specs, report)


def switch_list(text: str) -> list[str]:
    """The switch names of ``--switches``, checked: a RunInputError naming an unknown one and
    every known one, a repeated one, or a list without ``baseline``."""
    from experiments.commands.run_options import RunInputError

    names = [name.strip() for name in text.split(",") if name.strip()]
    for name in names:
        if name not in SWITCHES:
            raise RunInputError(f"--switches: unknown switch {name!r}; known switches: {', '.join(SWITCHES)}")
    if len(names) != len(set(names)):
        raise RunInputError(f"--switches: a switch is named twice in {text!r}")
    if BASELINE not in names:
        raise RunInputError(f"--switches: must include {BASELINE} (every other switch is compared with it), "
                            f"got {text!r}")
    return names


def _params(args: argparse.Namespace) -> dict:
    from experiments.commands.run_options import check_observation, team_list

    teams = team_list(args.teams, "--teams")
    opponents = team_list(args.opponents, "--opponents")
    switches = switch_list(args.switches)
    everyone = teams + [o for o in opponents if o not in teams]
    check_observation(everyone, "partial")
    check_switches(switches, everyone, args.cycles)
    return {"teams": teams, "opponents": opponents, "switches": switches, "games": args.games, "seed": args.seed,
            "cycles": args.cycles}


def check_switches(switches: Sequence[str], teams: Sequence[str], cycles: int | None) -> None:
    """Before any match: each switch gives a configuration a match can play, and every team
    takes its team options; a RunInputError naming the switch otherwise."""
    from experiments.commands.run_options import RunInputError
    from experiments.configuration import match_config
    from experiments.errors import ExperimentError
    from experiments.runner.worker import make_team
    from soccer_sim import TeamNotFoundError
    from soccer_sim.config_checks import ConfigError

    base = match_config(cycles, "partial")
    for name in switches:
        switch = SWITCHES[name]
        try:
            switch.configured(base)
        except ConfigError as exc:
            raise RunInputError(f"switch {name!r} gives a configuration no match can play: {exc}") from None
        if switch.team_options:
            for team in teams:
                try:
                    make_team(team, dict(switch.team_options))
                except (TeamNotFoundError, ExperimentError) as exc:
                    raise RunInputError(f"switch {name!r}: {exc}") from None


def build_specs(params: dict) -> list:
    """Every match of the study: the case study's paired seeds (:func:`paired_specs`) for each
    team, opponent and switch, the team named with its switch (:func:`ablated_name`)."""
    from experiments.runner.spec import paired_specs

    return [switched_spec(spec, team, switch)
            for team in params["teams"] for opponent in params["opponents"]
            for switch in params["switches"]
            for spec in paired_specs(team, opponent, params["games"], params["seed"], params["cycles"], "partial")]


def switched_spec(spec, team: str, switch: str):
    """The case study's ``spec`` of ``team`` played by :func:`play_ablated` under ``switch``,
    ``team`` named with the switch."""
    def named(side: str) -> str:
        return ablated_name(side, switch) if side == team else side

    return replace(spec, home=named(spec.home), away=named(spec.away), play=PLAY,
                   play_args=(("switch", switch), ("teams", (spec.home, spec.away))), plays_teams=(spec.home, spec.away))


def play_ablated(spec, record, watch) -> None:
    """Play one match of the study in a runner worker (see
    :attr:`~experiments.runner.spec.MatchSpec.play`): the two teams of ``spec.play_args``, each
    made with its switch's team options, on the spec's configuration with the switch applied;
    the replay (``--record-dir``) and game log (``--rcg-dir``) as for any match."""
    from experiments.recording import rcg_recording
    from experiments.runner.worker import make_team, record_result
    from soccer_sim import run_match

    args = dict(spec.play_args)
    switch = SWITCHES[args["switch"]]
    options = dict(switch.team_options)
    home, away = (watch(make_team(team, options)[0], label, side)
                  for side, (team, label) in enumerate(zip(args["teams"], (spec.home, spec.away))))
    recorders = []
    if spec.record is not None:
        from soccer_sim.replay import RerunRecorder

        recorders.append(RerunRecorder(spec.record))
    with rcg_recording(spec.rcg, "--rcg-dir") as logs:  # written whole or not at all
        result = run_match(home, away, seed=spec.seed, config=switch.configured(spec.config()),
                           recorders=[*recorders, *logs])
    record_result(record, result)


def tables(records: Sequence, params: dict) -> tuple:
    """(the table, its CSV rows): one row per team and switch."""
    from experiments.reporting import Table
    from experiments.stats import figure_cell, paired_cells, pairing_summary

    opponents, columns = params["opponents"], figure_columns()
    table = Table(f"ablation under partial observation: goal difference per match, mean (SE), {params['games']} games "
                  f"per pairing and switch; each switch turns one limit off for both teams",
                  ["team", "switch", *(f"vs {o}" for o in opponents), f"GD minus {BASELINE} (SE)", "p",
                   *(column for column, _, _ in columns)],
                  labels=2,
                  caption="switches: " + "; ".join(f"{name}: {SWITCHES[name].removes}" for name in params["switches"]))
    rows = []
    for team in params["teams"]:
        baseline = ablated_name(team, BASELINE)
        for switch in params["switches"]:
            name = ablated_name(team, switch)
            cells = [team, switch, *(pairing_summary(records, name, o).goal_difference.text() for o in opponents)]
            overall = pairing_summary(records, name)
            gd = overall.goal_difference
            row = [team, switch, overall.games, overall.wins, overall.draws, overall.losses, overall.forfeits,
                   gd.mean, gd.se]
            paired_text, paired_numbers = paired_cells(records, name, baseline, opponents)
            cells += paired_text
            row += paired_numbers
            for _, figure, scale in columns:
                text, mean, se = figure_cell(records, name, figure, scale)
                cells.append(text)
                row += [mean, se]
            table.rows.append(cells)
            rows.append(row)
    return table, rows


def report(records: Sequence, params: dict, out_dir: Path | None = None) -> list[Path]:
    """Print the table; with ``out_dir`` write ablation.csv and ablation.md there. Returns the
    files written."""
    from experiments.reporting import write_csv, write_markdown

    table, rows = tables(records, params)
    table.print()
    if out_dir is None:
        return []
    cycles = params["cycles"] or "regulation (6000)"
    header = ["team", "switch", "games", "wins", "draws", "losses", "forfeits", "mean_gd", "se",
              f"gd_minus_{BASELINE}", "gd_difference_se", "p_value",
              *(f"{figure}{suffix}" for _, figure, _ in figure_columns() for suffix in ("", "_se"))]
    written = [write_csv(out_dir / "ablation.csv", header, rows),
               write_markdown(out_dir / "ablation.md", [table],
                              f"Ablation: {len(records)} matches under partial observation, seeds from "
                              f"{params['seed']}, cycles per match: {cycles}.")]
    print("wrote " + ", ".join(str(path) for path in written))
    return written
