"""``soccer-sim play HOME AWAY --engine rcssserver``: one match in the real RoboCup 2D server
(:mod:`experiments.rcss_engine`), reported as ``play`` reports a match of the simulator,
from the server's game log.

HOME plays on the server's left. Each team is one of the project's teams (it plays through
the bridge under partial observation, whatever ``--observation`` says) or ``helios-base``
from the kit's build (``--rcss-home``, else ``$RCSS_HOME``, else ``~/.cache/rcss-reference``).
``--rcg FILE`` keeps the server's game log, ``--rcss-logs DIR`` every log of the match;
``--cycles`` must be a multiple of 20 there (the server's halves are whole seconds);
``--scenario`` and ``--record`` are the simulator's only.

After the report come the checks the server's logs allow: for each of our teams the steps at
which one of its players sent no ``(done)`` (the text log), and the score the server printed.
Exit status as ``play``: 0 for a match played, 2 for bad input (an unknown team, a team that
cannot play under partial observation, a missing build: one line saying how to build it),
1 for a match that failed (a team raised or missed the server's step: the line names the
player and the step), 130 after Ctrl-C (every process the match started is ended).
"""

from __future__ import annotations

import argparse
import json
import sys


def run_rcss(args: argparse.Namespace) -> int:
    from experiments.commands.errors import fail
    from experiments.commands.report_printing import print_report, report_console
    from experiments.commands.run_options import RunInputError
    from experiments.rcss_engine import play_rcss_match
    from experiments.recording import rcg_destination
    from rcss_bridge.errors import BridgeError
    from rcss_bridge.install import MissingBuild
    from soccer_sim import TeamNotFoundError
    from soccer_sim.rcg import RcgError

    for option, value in (("--scenario", getattr(args, "scenario", None)), ("--record", getattr(args, "record", None))):
        if value is not None:
            return fail(f"{option} is not available with --engine rcssserver (the simulator's only)", 2)
    try:
        with rcg_destination(getattr(args, "rcg", None), "--rcg") as log:
            result = play_rcss_match(args.home, args.away, args.seed, getattr(args, "rcss_home", None), args.cycles,
                                     log, getattr(args, "rcss_logs", None), args.match_timeout)
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except MissingBuild as exc:
        return fail(str(exc), 2)
    except BridgeError as exc:
        return fail(f"match stopped: {exc}", 1)
    except (TeamNotFoundError, RunInputError, RcgError, ValueError) as exc:
        return fail(str(exc), 2)
    report = result.report
    try:
        if args.json:
            data = report.as_dict()
            data.update(engine="rcssserver", wall_time=round(result.wall_time, 2),
                        connect_seconds=round(result.connect_seconds, 2),
                        missed_cycles={team: {str(k): v for k, v in shirts.items()}
                                       for team, shirts in result.missed.items()},
                        server_score=None if result.server_score is None else list(result.server_score))
            print(json.dumps(data, indent=2))
        else:
            console = report_console()
            print_report(console, report, result.wall_time)
            for team, shirts in result.missed.items():
                if shirts:
                    listed = ", ".join(f"#{shirt}: {count}" for shirt, count in sorted(shirts.items()))
                    console.print(f"rcssserver: {team} missed steps ({listed})")
                else:
                    console.print(f"rcssserver: {team} missed no step")
            if result.server_score is not None:
                console.print(f"rcssserver's result: {result.server_score[0]} - {result.server_score[1]}")
            console.print(f"rcssserver: {result.wall_time:.1f} s from its start to its end, "
                          f"{result.connect_seconds:.1f} s of them connecting the teams")
            if args.rcg is not None:
                console.print(f"rcssserver game log written to {args.rcg}")
        sys.stdout.flush()
    except BrokenPipeError:
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    return 0
