"""``soccer-sim play [HOME] [AWAY] --seed N [--cycles N] [--json] [--scenario NAME|FILE]
[--record FILE.rrd] [--rcg FILE.rcg] [--match-timeout SECONDS]``: play one match and print its report: half-time
and final score, the goals (cycle, team, scorer's shirt number), set plays of each kind, offside
calls and both teams' statistics; ``--json`` prints the same as one JSON object. ``--record`` also
writes the match as a rerun replay (see :mod:`soccer_sim.replay`; watch it with
``soccer-sim replay FILE.rrd``); ``--rcg`` writes it as an rcssserver game log, which RoboCup's
tools (rcssmonitor, soccerwindow2, log analysers) replay (see :mod:`soccer_sim.rcg`).

``--engine rcssserver`` plays the match in the real RoboCup 2D server instead
(:mod:`experiments.commands.play_rcss`; ``--rcss-home``, ``--rcss-logs``).

``--cycles`` up to a regulation match (2 x 3000 cycles) stops the match early; a longer count
lengthens both halves to half of it each (half time stays in the middle).

Stdout carries only the report; every error is one line on stderr. Exit status: 0 for a match
played (also when the reader of stdout went away, ``play --json | head -1``), 2 for bad input
(an unknown or unimportable team, a bad scenario file, an unwritable replay or game log,
checked before the match), 1 for a match that
failed (a team raised anything, returned a malformed command, called ``sys.exit`` or ended or
killed its process, or the match overran ``--match-timeout``; the line names the team whose
code was running and what happened), 130 after Ctrl-C ("interrupted").

The match is played as a tournament plays each of its matches: in a worker process
(:func:`experiments.runner.local.play_in_worker`), started once the kernels are in the cache,
whose record (and report, and recordings) comes back to this process. So ``--match-timeout``
(the tournament's meaning and default, 600 s) holds against any team code: the worker's timer
stops a match where it hangs, and a worker that does not answer a moment later is killed.
What a team prints goes to stderr, never into the report on stdout.
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
    parser.add_argument("--engine", choices=("simulator", "rcssserver"), default="simulator",
                        help="where the match is played: soccer-sim's simulator (default) or the real RoboCup 2D "
                             "server from the reference kit's build (our teams play through the bridge under "
                             "partial observation; a team may also be helios-base)")
    parser.add_argument("--rcss-home", default=None, metavar="DIR",
                        help="with --engine rcssserver: the kit's build (default: $RCSS_HOME, else "
                             "~/.cache/rcss-reference)")
    parser.add_argument("--rcss-logs", default=None, metavar="DIR",
                        help="with --engine rcssserver: also keep the server's game and text logs and every "
                             "process's output in DIR")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    if getattr(args, "engine", "simulator") == "rcssserver":
        from experiments.commands.play_rcss import run_rcss

        return run_rcss(args)
    import contextlib
    import json
    import sys

    from rich.markup import escape

    from experiments.commands.run_options import RunInputError, check_observation, scenario_named
    from experiments.match_report import match_report
    from experiments.recording import rcg_destination, replay_destination
    from experiments.runner.local import MatchFailed, play_in_worker
    from experiments.runner.spec import MatchSpec
    from soccer_sim import ConfigError, TeamNotFoundError
    from soccer_sim.rcg import RcgError
    from soccer_sim.replay import ReplayError
    from soccer_sim.setup import MatchSetup

    timeout = getattr(args, "match_timeout", None)
    try:
        config = match_config(args.cycles, getattr(args, "observation", "full"))
        scenario = scenario_named(getattr(args, "scenario", None))
        MatchSetup.resolve(config, scenario)  # a scenario that does not fit the field is bad input, found here
        with replay_destination(getattr(args, "record", None), "--record") as replay, \
                rcg_destination(getattr(args, "rcg", None), "--rcg") as log:
            with contextlib.redirect_stdout(sys.stderr):  # what a team prints while it loads is not the report
                check_observation([args.home, args.away], config.observation.mode)
            spec = MatchSpec(args.home, args.away, args.seed, configuration=config, scenario=scenario,
                             record=None if replay is None else str(replay), rcg=None if log is None else str(log))
            # played in a worker process of its own, as in a tournament, so --match-timeout holds
            # whatever the teams' code does; kernels are compiled first, off the match's clock
            record = play_in_worker(spec, timeout, report=match_report)  # MatchFailed: no recording is kept
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except MatchFailed as failed:
        return _fail(_stopped_line(failed.error), 1)
    except (TeamNotFoundError, ConfigError, ValueError, ReplayError, RcgError, RunInputError) as exc:  # bad input
        return _fail(str(exc), 2)
    from experiments.commands.report_printing import print_report, report_console

    report, elapsed = record.report, record.wall_time
    try:
        if args.json:
            data = report.as_dict()
            if scenario is not None:
                data.update(scenario=report.scenario, end_reason=report.end_reason)
            print(json.dumps(data, indent=2))
        else:
            console = report_console()
            print_report(console, report, elapsed)
            if scenario is not None:
                console.print(f"scenario {escape(report.scenario)}: ended by {report.end_reason} after "
                              f"{report.cycles} cycles")
            if replay is not None:
                console.print(f"replay written to {escape(args.record)} (watch it: soccer-sim replay "
                              f"{escape(args.record)})")
            if log is not None:
                console.print(f"rcssserver game log written to {escape(args.rcg)}")
        sys.stdout.flush()
    except BrokenPipeError:  # the reader went away (``soccer-sim play --json | head``): not an error
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())  # no second error at exit
    return 0


def _stopped_line(error: str) -> str:
    """The error line of a match that did not finish (``error``: its record's ``Kind: what
    happened``): a team's failure as the TeamError words it (naming the team and its method);
    a timeout or a worker that ended as the runner words it (naming the team whose code was
    running); any other exception with its kind."""
    kind, _, text = error.partition(": ")
    if kind == "TeamError":
        return text
    if kind == "MatchTimeout":
        return f"match stopped (--match-timeout): {text}"
    if kind == "WorkerDied":
        return f"match stopped: {text}"
    return f"match stopped: {error}"


def _fail(message: str, status: int) -> int:
    """``error: message`` as one line on stderr (stdout carries only the report); the status."""
    from experiments.commands.errors import fail

    return fail(message, status)
