"""``soccer-sim play [HOME] [AWAY] --seed N [--cycles N] [--json] [--scenario NAME|FILE]
[--record FILE.rrd] [--rcg FILE.rcg] [--match-timeout SECONDS]``: play one match and print its report: half-time
and final score, the goals (cycle, team, scorer's shirt number), set plays of each kind, offside
calls and both teams' statistics; ``--json`` prints the same as one JSON object. ``--record`` also
writes the match as a rerun replay (see :mod:`soccer_sim.replay`; watch it with
``soccer-sim replay FILE.rrd``); ``--rcg`` writes it as an rcssserver game log, which RoboCup's
tools (rcssmonitor, soccerwindow2, log analysers) replay (see :mod:`soccer_sim.rcg`).

``--cycles`` up to a regulation match (2 x 3000 cycles) stops the match early; a longer count
lengthens both halves to half of it each (half time stays in the middle).

Stdout carries only the report; every error is one line on stderr. Exit status: 0 for a match
played (also when the reader of stdout went away, ``play --json | head -1``), 2 for bad input
(an unknown or unimportable team, a bad scenario file, an unwritable replay or game log,
checked before the match), 1 for a match that
failed (a team raised, returned a malformed command or called ``sys.exit`` in its code, or the
match overran ``--match-timeout``), 130 after Ctrl-C ("interrupted").

``--match-timeout`` has the tournament's meaning and default (600 s) and its mechanism: a timer
signal that stops the match where it hangs (in a team's ``act`` or anywhere else in Python
code); the match is played in this process as without the option, so output and speed do not
change. Code that never returns to the interpreter (a compiled loop) cannot be stopped this way;
a tournament also kills its worker process in that case.
"""

from __future__ import annotations

import argparse

from experiments.limits import ranged
from experiments.configuration import match_config

__all__ = ["match_config", "register", "run"]


def register(subparsers: argparse._SubParsersAction) -> None:
    parser = subparsers.add_parser(
        "play", help="play one match and print the score and statistics",
        description="Play one match between two teams (registered names or package.module:Attribute "
                    "paths) and print the score and per-team statistics.")
    parser.add_argument("home", nargs="?", default="mmd+msd2", help="home team (default: mmd+msd2)")
    parser.add_argument("away", nargs="?", default="press-433", help="away team (default: press-433)")
    parser.add_argument("--seed", type=ranged("seed"), default=0, help="match seed (default: 0)")
    parser.add_argument("--cycles", type=ranged("cycles"), default=None,
                        help="stop after this many cycles (default: the full two halves of 3000); more than "
                             "6000 lengthens both halves to half of it each")
    parser.add_argument("--observation", choices=("full", "partial"), default="full",
                        help="what the teams perceive: the exact state (default) or each player's own noisy view "
                             "and the say/hear channel (partial; both teams must support it)")
    parser.add_argument("--json", action="store_true", help="print the match report as one JSON object")
    parser.add_argument("--scenario", default=None, metavar="NAME|FILE",
                        help="play a scenario: a name from `soccer-sim scenarios` or a .json/.toml file "
                             "(default: the regular match)")
    parser.add_argument("--record", default=None, metavar="FILE.rrd",
                        help="also write the match as a rerun replay (watch it with `soccer-sim replay FILE.rrd`)")
    parser.add_argument("--rcg", default=None, metavar="FILE.rcg",
                        help="also write the match as an rcssserver game log (replay it with rcssmonitor or "
                             "soccerwindow2)")
    from experiments.runner.run import DEFAULT_MATCH_TIMEOUT

    parser.add_argument("--match-timeout", type=ranged("match-timeout"), default=DEFAULT_MATCH_TIMEOUT, metavar="SECONDS",
                        help=f"stop the match with an error if it takes longer, e.g. a team that never returns "
                             f"from act() (default: {DEFAULT_MATCH_TIMEOUT:g}, as for tournaments)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    import json
    import sys
    import time

    from rich.markup import escape

    from experiments.commands.run_options import RunInputError, check_observation
    from experiments.match_report import match_report
    from experiments.recording import rcg_recording, replay_recording
    from experiments.runner.worker import MatchTimeout, arm_timer, disarm_timer
    from experiments.warmup import warm_kernels
    from soccer_sim import ConfigError, TeamError, TeamNotFoundError, run_match
    from soccer_sim.rcg import RcgError
    from soccer_sim.replay import ReplayError

    timeout = getattr(args, "match_timeout", None)
    try:
        config = match_config(args.cycles, getattr(args, "observation", "full"))
        scenario = _scenario(getattr(args, "scenario", None))
        with replay_recording(getattr(args, "record", None), "--record") as replays, \
                rcg_recording(getattr(args, "rcg", None), "--rcg") as logs:
            recorders = [*replays, *logs]
            check_observation([args.home, args.away], config.observation.mode)
            # a cold cache is filled here, not on the match's clock
            warm_kernels((args.home, args.away), observation=config.observation.mode)
            start = time.perf_counter()
            alarm = arm_timer(timeout)  # the tournament's timer: MatchTimeout where the match hangs
            try:
                result = run_match(args.home, args.away, seed=args.seed, config=config, scenario=scenario,
                                   recorders=recorders)
            finally:
                disarm_timer(alarm)
            elapsed = time.perf_counter() - start
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except MatchTimeout as exc:
        return _fail(f"match stopped: it exceeded its time budget of {exc.seconds:g} s (--match-timeout)", 1)
    except TeamError as exc:  # a team failed during the match: a failed run
        if isinstance(exc.__cause__, MatchTimeout):
            method = exc.message.split("(", 1)[0]
            return _fail(f"match stopped: it exceeded its time budget of {exc.__cause__.seconds:g} s "
                         f"(--match-timeout) while team {exc.team_name!r} was in {method}()", 1)
        return _fail(str(exc), 1)
    except (TeamNotFoundError, ConfigError, ValueError, ReplayError, RcgError, RunInputError) as exc:  # bad input
        return _fail(str(exc), 2)
    report = match_report(result)
    try:
        if args.json:
            data = report.as_dict()
            if scenario is not None:
                data.update(scenario=result.scenario, end_reason=result.end_reason)
            print(json.dumps(data, indent=2))
        else:
            console = _report_console()
            _print_report(console, report, elapsed)
            if scenario is not None:
                console.print(f"scenario {escape(result.scenario)}: ended by {result.end_reason} after "
                              f"{result.cycles} cycles")
            if replays:
                console.print(f"replay written to {escape(args.record)} (watch it: soccer-sim replay "
                              f"{escape(args.record)})")
            if logs:
                console.print(f"rcssserver game log written to {escape(args.rcg)}")
        sys.stdout.flush()
    except BrokenPipeError:  # the reader went away (``soccer-sim play --json | head``): not an error
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # no second error at exit
    return 0


def _fail(message: str, status: int) -> int:
    """``error: message`` as one line on stderr (stdout carries only the report); the status."""
    from experiments.commands.errors import fail

    return fail(message, status)


def _report_console():
    """A rich console for the report that lets a closed stdout raise BrokenPipeError (rich's
    own handling would exit with status 1 where ``--json`` exits with 0)."""
    from rich.console import Console

    class ReportConsole(Console):
        def on_broken_pipe(self) -> None:
            self.quiet = True
            raise BrokenPipeError

    return ReportConsole()


def _scenario(text: str | None):
    """The scenario ``--scenario`` names: a library name, or a path to a .json/.toml file."""
    if text is None:
        return None
    from soccer_sim.scenarios import get_scenario, load_scenario

    if text.lower().endswith((".json", ".toml")):
        return load_scenario(text)
    return get_scenario(text)


def _print_report(console, report, elapsed: float) -> None:
    """The report as a person reads it (team names escaped: rich would take [..] for markup)."""
    from rich.markup import escape
    from rich.table import Table

    from experiments.match_report import SIDES

    names = [escape(name) for name in report.team_names]
    half = report.half_time_score
    half_text = f"half time {half[0]} - {half[1]}" if half is not None else "stopped before half time"
    console.print(f"[bold]{names[0]} {report.score[0]} - {report.score[1]} {names[1]}[/bold]  "
                  f"({half_text}; seed {report.seed}, {report.cycles} cycles, {elapsed:.2f} s)")
    if report.goals:
        goals = Table(title="Goals")
        for column in ("cycle", "team", "scorer (shirt)", "score"):
            goals.add_column(column, justify="right" if column != "team" else "left")
        score = [0, 0]
        for goal in report.goals:
            score[goal.team] += 1
            shirt = "-" if goal.shirt is None else f"#{goal.shirt}"
            if goal.own_goal:
                shirt = f"own goal by {SIDES[1 - goal.team]} {shirt}"
            goals.add_row(str(goal.cycle), f"{names[goal.team]} ({SIDES[goal.team]})", shirt,
                          f"{score[0]} - {score[1]}")
        console.print(goals)
    table = Table(title="Statistics")
    table.add_column("")
    table.add_column(f"{names[0]} (home)", justify="right")
    table.add_column(f"{names[1]} (away)", justify="right")
    home, away = report.statistics
    for key in list(home) + [k for k in away if k not in home]:
        table.add_row(key.replace("_", " "), _format(key, home.get(key)), _format(key, away.get(key)))
    table.add_section()
    for key in report.set_plays[0]:
        table.add_row(key.replace("_", " ") + "s", str(report.set_plays[0][key]), str(report.set_plays[1][key]))
    table.add_row("offsides", str(report.offsides[0]), str(report.offsides[1]))
    console.print(table)
    if report.drop_balls:
        console.print(f"{report.drop_balls} set play(s) not taken in time: ball dropped")


def _format(key: str, value: float | None) -> str:
    if value is None:
        return "-"
    if key == "possession":
        return f"{100 * value:.1f} %"
    if key == "distance_run":
        return f"{value / 1000:.2f} km"
    if float(value).is_integer():
        return str(int(value))
    return f"{value:.3g}"
