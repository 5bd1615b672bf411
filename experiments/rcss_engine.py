"""``--engine rcssserver``: one match played in the real RoboCup 2D server instead of the
simulator, reported as ``soccer-sim play`` reports one.

:func:`play_rcss_match` checks the input (each team is one of the project's teams that plays
under partial observation, or ``helios-base`` from the kit's build, :data:`EXTERNAL_TEAMS`),
compiles every kernel our teams call into the on-disk cache (:func:`experiments.warmup.warm_kernels`:
nothing may compile once the server waits), plays the match through
:func:`rcss_bridge.match.play_in_namespace` (the server and both teams in a private network
namespace, ended by their ids) and builds the report from the server's game log
(:func:`experiments.rcg_report.rcg_match_report`). It also counts, from the server's text log,
the steps at which each of our players sent no ``(done)`` (:func:`rcss_bridge.textlog.missed_steps`).

One of our teams is a process of its own (``python -m experiments.rcss_engine TEAM ...``,
:func:`team_main`): it loads the team's kernels, plays a few cycles of the simulator with the
team to load whatever the kernels' manifest missed, then connects its 11 players and online
coach and plays through :func:`rcss_bridge.team_runner.play_team`. An error (the team raised,
overran the server's step, a server that went away) is one line on its stderr naming the
player and the step, and exit status 1; the match host then ends the match with that line.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import sys
import tempfile
from dataclasses import dataclass
from collections.abc import Mapping
from pathlib import Path
from typing import TextIO

from experiments.match_report import MatchReport
from rcss_bridge.install import HELIOS_TEAM

HELIOS = HELIOS_TEAM
"""The external team found in the kit's build."""

EXTERNAL_TEAMS = (HELIOS,)
"""Team names that are not the project's teams but programs of the kit's build."""

WARM_UP_CYCLES = 60
"""Cycles of the simulator a team process plays with its team before connecting (kernels the
manifest does not list are compiled or loaded there, not inside the server's step)."""



@dataclass(frozen=True)
class RcssMatchResult:
    """A match played in the server: its report and what the server's logs say."""

    report: MatchReport
    wall_time: float
    """Seconds from the server's start to its end."""
    connect_seconds: float
    """Of them, seconds until both teams were connected (our teams load their code first)."""
    missed: dict[str, dict[int, int]]
    """Per team of ours (its label), shirt number -> steps without its ``(done)`` after kick-off."""
    server_score: tuple[int, int] | None
    """The score the server printed at the end (None if it printed none)."""


def check_teams(home: str, away: str, install, external: Mapping[str, str] | None = None) -> list[str]:
    """Our teams among ``home`` and ``away`` (a RunInputError for a team that cannot play
    under partial observation, a TeamNotFoundError for an unknown one; a MissingBuild when
    helios-base is asked for and not built). ``external``: name -> command of the external
    teams given by the user (:func:`external_argv`)."""
    from experiments.commands.run_options import check_observation

    install.require_server()
    if HELIOS in (home, away):
        install.require_helios()
    ours = [team for team in (home, away) if not is_external(team, external)]
    check_observation(ours, "partial")
    return ours


def half_time_seconds(cycles: int | None) -> int:
    """rcssserver's ``half_time`` (seconds of 10 cycles) for ``--cycles`` (None: a regulation
    match, 300); a ValueError for a count the server cannot play (not a multiple of 20)."""
    if cycles is None:
        return 300
    if cycles <= 0 or cycles % 20:
        raise ValueError(f"--cycles {cycles} with --engine rcssserver must be a positive multiple of 20 "
                         "(two halves of whole seconds of 10 cycles)")
    return cycles // 20


def play_rcss_match(home: str, away: str, seed: int, rcss_home: str | None = None, cycles: int | None = None,
                    rcg: Path | None = None, logs: str | None = None, match_timeout: float = 1800.0,
                    stream: TextIO | None = None, external: Mapping[str, str] | None = None) -> RcssMatchResult:
    """Play ``home`` (the server's left) v ``away`` in rcssserver and report it (module
    docstring). ``rcg``: where to copy the game log; ``logs``: a directory that keeps every
    log of the match (game and text logs, the server's and the teams' output); ``external``:
    name -> command of external teams other than helios-base (:func:`external_argv`)."""
    from experiments.rcg_report import rcg_match_report
    from experiments.warmup import warm_kernels
    from rcss_bridge.errors import BridgeError
    from rcss_bridge.install import RcssInstall
    from rcss_bridge.match import MatchPlan, play_in_namespace, server_team_name
    from rcss_bridge.textlog import missed_steps
    from soccer_sim.rcg import RcgError, read_rcg

    install = RcssInstall.find(rcss_home)
    ours = check_teams(home, away, install, external)
    half_time = half_time_seconds(cycles)
    if ours:
        warm_kernels(ours, stream=stream, observation="partial")
    home_name = server_team_name(home)
    away_name = server_team_name(away, taken=home_name)
    with tempfile.TemporaryDirectory(prefix="soccer-sim-rcss-") as work:
        plan = MatchPlan(rcss_home=str(install.home), workdir=work,
                         home=side_program(home, home_name, away, seed, install, external=external),
                         away=side_program(away, away_name, home, seed + 1, install, external=external),
                         half_time=half_time, match_timeout=match_timeout)
        try:
            outcome = play_in_namespace(plan)
        finally:
            if logs is not None:
                keep_logs(Path(work), Path(logs))
        try:
            report = rcg_match_report(read_rcg(outcome.rcg), (home, away), seed)
        except (RcgError, ValueError) as exc:
            raise BridgeError(f"the server's game log cannot be read: {exc}") from None
        missed = {label: missed_steps(Path(outcome.rcl), name)
                  for label, name in ((home, home_name), (away, away_name)) if not is_external(label, external)}
        server_score = final_score(Path(outcome.server_output))
        if rcg is not None:
            shutil.copyfile(outcome.rcg, rcg)
    return RcssMatchResult(report, outcome.wall_time, outcome.connect_seconds, missed, server_score)


def is_external(team: str, external: Mapping[str, str] | None = None) -> bool:
    """Whether ``team`` is a program of its own (helios-base, or a name of ``external``), not
    one of the project's teams."""
    return team in EXTERNAL_TEAMS or team in (external or {})


EXTERNAL_PLACEHOLDERS = ("{host}", "{port}", "{coach_port}", "{team}")
"""What an external team's command may contain, replaced by the server's host, its players'
port, its online coach's port and the name the team must give the server."""


def external_argv(command: str, server_name: str, host: str = "127.0.0.1", port: int = 6000) -> tuple[str, ...]:
    """The program and arguments of an external team's ``command`` (split as a POSIX shell
    splits it, each of :data:`EXTERNAL_PLACEHOLDERS` replaced); a ValueError for a command
    that is empty or cannot be split (an unclosed quote)."""
    import shlex

    values = dict(zip(EXTERNAL_PLACEHOLDERS, (host, str(port), str(port + 2), server_name)))
    words = shlex.split(command)
    if not words:
        raise ValueError("the command is empty")
    for placeholder, value in values.items():
        words = [word.replace(placeholder, value) for word in words]
    return tuple(words)


def side_program(label: str, server_name: str, opponent: str, seed: int, install, port: int = 6000,
                 external: Mapping[str, str] | None = None):
    """The program that connects ``label``'s team to the server's players' ``port``:
    helios-base's ``start.sh`` in its build, an external team's command (``external``, run
    in the current directory), or one of our teams as a process of its own (:func:`team_main`)."""
    from rcss_bridge.match import SideProgram

    if external and label in external:
        return SideProgram(label, server_name, external_argv(external[label], server_name, port=port), cwd=os.getcwd())

    if label == HELIOS:
        return SideProgram(label, server_name, ("./start.sh", "-t", server_name, "-p", str(port),
                                                "-P", str(port + 2)),
                           cwd=str(install.helios_bin), env={"LD_LIBRARY_PATH": str(install.libraries)})
    return SideProgram(label, server_name, (sys.executable, "-m", "experiments.rcss_engine", label,
                                            "--server-name", server_name, "--opponent", opponent,
                                            "--seed", str(seed), "--port", str(port), "--coach-port", str(port + 2)))


def keep_logs(work: Path, destination: Path) -> None:
    """Copy the match's logs and outputs (not the server's home) into ``destination``."""
    destination.mkdir(parents=True, exist_ok=True)
    for item in work.iterdir():
        if item.is_file():
            shutil.copyfile(item, destination / item.name)


def final_score(server_output: Path) -> tuple[int, int] | None:
    """The score rcssserver printed at the end of the match (after ``Game Results:``, a line
    ``Score: L - R``, the left team's first)."""
    import re

    try:
        text = server_output.read_text(errors="replace")
    except OSError:
        return None
    found = re.findall(r"^\s*Score: (\d+) - (\d+)\s*$", text, flags=re.MULTILINE)
    return (int(found[-1][0]), int(found[-1][1])) if found else None


# ---------------------------------------------------------------------------------- a team's process
def team_main(argv: list[str] | None = None) -> int:
    """``python -m experiments.rcss_engine TEAM --server-name NAME --opponent TEAM --seed N
    [--port 6000]``: one of our teams in the server (module docstring)."""
    parser = argparse.ArgumentParser(prog="experiments.rcss_engine")
    parser.add_argument("team")
    parser.add_argument("--server-name", required=True)
    parser.add_argument("--opponent", default="opponent")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--host", default="127.0.0.1")
    parser.add_argument("--port", type=int, default=6000)
    parser.add_argument("--coach-port", type=int, default=6002)
    parser.add_argument("--transcript", default=None, metavar="FILE.jsonl.gz",
                        help="record every datagram of the team's exchange (rcss_bridge.transcripts)")
    args = parser.parse_args(argv)
    import contextlib
    import gzip

    from rcss_bridge import BridgeError, ClientSettings, TeamClient
    from rcss_bridge.team_runner import play_team
    from rcss_bridge.transcripts import TranscriptWriter

    try:
        team = prepare_team(args.team)
        with contextlib.ExitStack() as stack:
            recorder = None
            if args.transcript is not None:
                recorder = TranscriptWriter(stack.enter_context(gzip.open(args.transcript, "wt", encoding="utf-8")))
            client = TeamClient(args.server_name, ClientSettings(host=args.host, port=args.port,
                                                                 coach_port=args.coach_port), recorder)
            run = play_team(team, args.team, args.opponent, client, args.seed)
    except BridgeError as exc:
        print(f"error: {exc}", file=sys.stderr, flush=True)
        return 1
    print(json.dumps({"team": args.team, "steps": run.steps, "slowest_step_s": round(run.slowest, 4),
                      "decide_s": round(run.decide_seconds, 2), "missed_before_kick_off": run.missed_before_kick_off,
                      "commands": run.commands}), flush=True)
    return 0


def prepare_team(name: str):
    """A fresh ``name`` team whose code is loaded and compiled: its kernels from the cache,
    then :data:`WARM_UP_CYCLES` of the simulator under partial observation with it."""
    from experiments.configuration import match_config
    from experiments.runner.worker import make_team
    from experiments.warmup import kernels_for, load_kernels
    from soccer_sim.match import run_match

    load_kernels(kernels_for([name], "partial"))
    run_match(make_team(name)[0], make_team(name)[0], seed=0, config=match_config(WARM_UP_CYCLES, "partial"))
    return make_team(name)[0]


if __name__ == "__main__":
    sys.exit(team_main())
