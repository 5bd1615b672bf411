"""``--engine rcssserver`` on the commands that run many matches (``soccer-sim tournament``,
``soccer-sim experiment case-study``): their matches played in the real RoboCup 2D server,
through the same runner and results store as the simulator's.

* **Options** (:func:`add_engine_arguments`): ``--engine``, ``--rcss-home`` (the kit's build,
  :class:`rcss_bridge.install.RcssInstall`) and ``--external NAME=COMMAND`` (a team that is a
  program of its own; :func:`experiments.rcss_engine.external_argv` says what the command is
  given). ``helios-base`` is a team name with this engine (from the kit's build) and refused
  under the simulator (:func:`experiments.commands.run_options.team_list`).
* **Parameters** (:class:`EngineChoice`, read from the options before anything runs): the
  team names the command's lists may hold besides the project's teams, the observation our
  teams play under (partial: the bridge builds each player's views from what the server told
  it, whatever ``--observation`` says), and what the run's stored parameters add
  (``engine``, ``external``; nothing under the simulator, so its results files keep their
  parameters).
* **The run** (:func:`engine_run`): the pre-flight (a missing build or helios-base is one line
  saying how to build it; options the server cannot honour, ``--backend ray`` and
  ``--record-dir``, are refused), the number of workers (:data:`DEFAULT_WORKERS` unless
  ``--workers`` says otherwise: a real-server match keeps about two cores busy) and the
  specs: each of the command's matches with ``engine="rcssserver"``, which puts the engine
  into the configuration's hash (:func:`experiments.runner.spec.config_description`: one
  results file never mixes engines, a resume with the other engine is refused in one line),
  the configuration of partial observation, and :func:`play_in_server` as the function that
  plays it, ordered by seed (:func:`in_seed_order`). The runner compiles our teams' kernels before any worker starts, as for every run
  (``MatchSpec.plays_teams``: our teams only).
* **A match** (:func:`play_in_server`, in a runner worker): played by
  :func:`experiments.rcss_engine.play_rcss_match` (server and both teams in a private network
  namespace); the row's score, cycles and statistics come from the server's game log
  (:func:`experiments.rcg_report.rcg_match_report`), with each of our teams' ``missed_steps``
  from the server's text log. A side whose program failed (one of our teams raised or missed
  the server's step, an external program exited) forfeits the match; a failure of the server
  or the host is nobody's fault, so a re-run plays the match again.
"""

from __future__ import annotations

import argparse
import shutil
import sys
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path

from experiments.runner.spec import SIMULATOR

RCSS = "rcssserver"
"""The engine's name (``--engine``, ``MatchSpec.engine``, the configuration's ``engine``)."""

ENGINES = (SIMULATOR, RCSS)
"""What ``--engine`` chooses from."""

PLAY = "experiments.rcss_runs:play_in_server"
"""The runner's ``MatchSpec.play`` for a match in the server."""

DEFAULT_WORKERS = 1
"""Matches played at once in the server unless ``--workers`` says otherwise."""

CORES_PER_MATCH = 2
"""About how many cores one real-server match keeps busy (the server, 22 players, 2 coaches)."""


def add_engine_arguments(parser: argparse.ArgumentParser) -> None:
    """``--engine``, ``--rcss-home`` and ``--external`` (after the run's options: ``--workers``
    then defaults to None, read as every core in the simulator and :data:`DEFAULT_WORKERS` in
    the server)."""
    parser.add_argument("--engine", choices=ENGINES, default=SIMULATOR,
                        help="where the matches are played: soccer-sim's simulator (default) or the real RoboCup 2D "
                             "server from the reference kit's build (our teams play through the bridge under partial "
                             f"observation; helios-base may be a team; --workers defaults to {DEFAULT_WORKERS} there, "
                             f"a match keeping about {CORES_PER_MATCH} cores busy; part of the configuration hash)")
    add_server_arguments(parser)
    parser.set_defaults(workers=None)


def add_server_arguments(parser: argparse.ArgumentParser, when: str = "with --engine rcssserver") -> None:
    """``--rcss-home`` and ``--external``: where the server's build is and the teams that are
    programs of their own (:func:`add_engine_arguments`, and commands that play in both
    engines); ``when``: when they apply, as their help says it."""
    parser.add_argument("--rcss-home", default=None, metavar="DIR",
                        help=f"{when}: the kit's build (default: $RCSS_HOME, else ~/.cache/rcss-reference)")
    parser.add_argument("--external", action="append", default=[], metavar="NAME=COMMAND",
                        help=f"{when}: a team NAME that is a program of its own, started by COMMAND "
                             "in the current directory to connect a full team; {host}, {port}, {coach_port} and {team} "
                             "in it become the server's host, players' port, online coach's port and the team name to "
                             "give the server (repeat for several teams)")


@dataclass(frozen=True)
class EngineChoice:
    """The engine options of a command, checked."""

    engine: str
    external: dict[str, str]
    """Name -> command of the ``--external`` teams."""

    @classmethod
    def from_args(cls, args: argparse.Namespace) -> EngineChoice:
        """The choice ``args`` make; a RunInputError naming the option for a bad one."""
        from experiments.commands.run_options import RunInputError

        engine = getattr(args, "engine", SIMULATOR)
        given = list(getattr(args, "external", None) or [])
        if engine != RCSS:
            for option in ("external", "rcss_home"):
                if getattr(args, option, None):
                    raise RunInputError(f"--{option.replace('_', '-')} needs --engine rcssserver")
            return cls(engine, {})
        external: dict[str, str] = {}
        for text in given:
            external.update([_external_team(text)])
        return cls(engine, external)

    @property
    def in_server(self) -> bool:
        return self.engine == RCSS

    @property
    def external_names(self) -> tuple[str, ...]:
        """The team names besides the project's teams the command's lists may hold."""
        from experiments.rcss_engine import EXTERNAL_TEAMS

        return (*EXTERNAL_TEAMS, *self.external) if self.in_server else ()

    def ours(self, teams: list[str]) -> list[str]:
        """The project's teams among ``teams``."""
        from experiments.rcss_engine import is_external

        return [team for team in teams if not is_external(team, self.external if self.in_server else {})]

    def observation(self, requested: str) -> str:
        """The observation our teams play under: partial in the server, ``requested`` otherwise."""
        return "partial" if self.in_server else requested

    def params(self) -> dict[str, object]:
        """What the run's stored parameters add (nothing under the simulator)."""
        if not self.in_server:
            return {}
        return {"engine": RCSS, "external": dict(sorted(self.external.items()))}


def _external_team(text: str) -> tuple[str, str]:
    """``NAME=COMMAND`` as (name, command); a RunInputError for a malformed one or a name that
    is one of the project's teams or helios-base."""
    from experiments.commands.run_options import RunInputError
    from experiments.rcss_engine import EXTERNAL_TEAMS, external_argv
    from soccer_sim import available_teams

    name, equals, command = text.partition("=")
    name = name.strip()
    if not equals or not name or not command.strip():
        raise RunInputError(f"--external {text!r}: give NAME=COMMAND")
    if name in EXTERNAL_TEAMS or name in available_teams() or "," in name or ":" in name:
        raise RunInputError(f"--external {text!r}: {name!r} is already a team's name (or has ',' or ':'); "
                            "give the external team a name of its own")
    try:
        external_argv(command, name)
    except ValueError as exc:
        raise RunInputError(f"--external {text!r}: cannot read the command ({exc})") from None
    return name, command


def engine_specs(args: argparse.Namespace, build_specs: Callable[[dict], list]) -> Callable[[dict], list]:
    """A command's ``build_specs`` (parameters -> the run's specs) that, for parameters of a
    run in the server (``engine``), also runs the pre-flight and makes the specs play there
    (:func:`engine_run`); the simulator's specs as they were otherwise."""
    def specs_of(params: dict) -> list:
        specs = build_specs(params)
        return specs if params.get("engine") is None else engine_run(args, params, specs)

    return specs_of


def engine_run(args: argparse.Namespace, params: dict, specs: list) -> list:
    """The pre-flight of a run in the server and its specs (module docstring); sets
    ``args.workers`` when ``--workers`` was not given. A RunInputError (one line) for a
    missing build, an option the server cannot honour or a ``--cycles`` it cannot play."""
    from experiments.commands.run_options import RunInputError
    from experiments.rcss_engine import HELIOS, half_time_seconds
    from experiments.results.store import mixed_engines, stored_engine
    from rcss_bridge.install import MissingBuild, RcssInstall

    if params.get("engine") != RCSS:
        raise RunInputError(f"unknown engine {params.get('engine')!r}; choose one of {', '.join(ENGINES)}")
    if getattr(args, "backend", "local") != "local":
        raise RunInputError("--engine rcssserver plays on the local pool only (--backend local)")
    if getattr(args, "record_dir", None) is not None:
        raise RunInputError("--record-dir is not available with --engine rcssserver (the simulator's replays); "
                            "--rcg-dir keeps the server's game logs")
    try:
        half_time_seconds(args.cycles)
    except ValueError as exc:
        raise RunInputError(str(exc)) from None
    install = RcssInstall.find(getattr(args, "rcss_home", None))
    external = dict(params.get("external") or {})
    try:
        install.require_server()
        if any(HELIOS in (spec.home, spec.away) for spec in specs):
            install.require_helios()
    except MissingBuild as exc:
        raise RunInputError(str(exc)) from None
    stored = stored_engine(args.out)
    if stored not in (None, RCSS):                            # refused before the workers' line below
        raise RunInputError(mixed_engines(Path(args.out), stored, RCSS))
    if shutil.which("unshare") is None:
        raise RunInputError("--engine rcssserver runs the server in a private network namespace: the 'unshare' "
                            "command is missing")
    if args.workers is None:
        args.workers = DEFAULT_WORKERS
        print(f"rcssserver: {DEFAULT_WORKERS} match at a time (one keeps about {CORES_PER_MATCH} cores busy; "
              "--workers N plays N at once)", file=sys.stderr)
    return [server_spec(spec, str(install.home), external) for spec in in_seed_order(specs)]


def in_seed_order(specs: list) -> list:
    """``specs`` ordered by seed (the command's order within a seed): the runner plays them in
    this order, so a run in the server stopped after hours leaves every pairing with about as
    many matches on the same seeds, ready for a paired comparison."""
    return sorted(specs, key=lambda spec: spec.seed)


def server_spec(spec, rcss_home: str, external: dict[str, str]):
    """``spec`` played in the server (module docstring): the engine, the configuration of
    partial observation for its cycles, :data:`PLAY` with the build and the external teams'
    commands as its arguments, and our teams as the ones whose kernels the runner warms."""
    from experiments.configuration import match_config
    from experiments.rcss_engine import is_external

    return replace(spec, engine=RCSS, configuration=match_config(spec.cycles, "partial"), play=PLAY,
                   play_args=(("rcss_home", rcss_home), ("external", tuple(sorted(external.items())))),
                   plays_teams=tuple(dict.fromkeys(t for t in (spec.home, spec.away) if not is_external(t, external))))


def play_in_server(spec, record, watch) -> None:
    """Play ``spec`` in the server and fill ``record`` (module docstring; the runner's
    ``MatchSpec.play`` protocol: ``watch`` does not apply, our teams play in processes of
    their own). A :class:`~rcss_bridge.errors.BridgeError` other than a side's failure is
    raised (nobody's fault); so is a game log whose score differs from the server's."""
    from experiments.rcss_engine import play_rcss_match
    from rcss_bridge.errors import BridgeError
    from rcss_bridge.match import SideFailed

    args = dict(spec.play_args)
    external = dict(args.get("external", ()))
    try:
        result = play_rcss_match(spec.home, spec.away, spec.seed, args.get("rcss_home"), spec.cycles,
                                 rcg=None if spec.rcg is None else Path(spec.rcg), stream=sys.stderr,
                                 external=external)
    except SideFailed as exc:
        side = failed_side(spec, exc.label)
        if side is None:
            raise
        record.forfeit, record.error, record.traceback = side, f"SideFailed: {exc}", str(exc)
        return
    report = result.report
    if result.server_score is not None and tuple(result.server_score) != tuple(report.score):
        raise BridgeError(f"the game log's score {report.score[0]}-{report.score[1]} differs from the one the server "
                          f"printed, {result.server_score[0]}-{result.server_score[1]}")
    record.home_goals, record.away_goals = (int(goals) for goals in report.score)
    record.cycles = int(report.cycles)
    record.home_stats, record.away_stats = (row_statistics(report.statistics[side], result.missed.get(label))
                                            for side, label in enumerate((spec.home, spec.away)))


def failed_side(spec, label: str) -> int | None:
    """The side (0 home, 1 away) whose program ``label`` names, or None when both sides have
    that name or neither has."""
    sides = [side for side, name in enumerate((spec.home, spec.away)) if name == label]
    return sides[0] if len(sides) == 1 else None


def row_statistics(statistics: dict, missed: dict[int, int] | None) -> dict[str, float]:
    """A team's stored statistics: the figures of its report the game log gives (those it
    cannot give, None, are left out) and, for our teams, ``missed_steps``: the steps after
    kick-off at which one of its players sent no ``(done)``, summed over the players."""
    row = {name: float(value) for name, value in statistics.items() if value is not None}
    if missed is not None:
        row["missed_steps"] = float(sum(missed.values()))
    return row
