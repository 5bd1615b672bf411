"""The options every command that runs matches shares, and running its specs with clear
messages for bad input (unknown teams, unusable results files, Ray missing, Ctrl-C)."""

from __future__ import annotations

import argparse
import os
import sys
import warnings
from collections.abc import Collection
from pathlib import Path
from typing import TYPE_CHECKING

from experiments.limits import ranged
from experiments.commands.errors import fail
from experiments.errors import ExperimentError

if TYPE_CHECKING:  # the runner imports the simulator: only when a command runs
    from experiments.runner.run import RunSummary
    from experiments.runner.spec import MatchSpec


class RunInputError(ExperimentError):
    """Bad input to a command that runs matches; the message says what and how to fix it."""


def add_run_arguments(parser: argparse.ArgumentParser, default_out: str | None, seed_help: str | None = None,
                      observation: bool = True, tables_default: str | None = None) -> None:
    """(``seed_help``: the help of --seed where a command reads it otherwise) --games, --seed,
    --cycles, --observation (not with ``observation`` False: a command that fixes it), --workers,
    --backend, --address, --out (not with ``default_out`` None: a command that names its results
    files with options of its own), --tables (``tables_default``: what its help says the default
    is, where it is not derived from --out),
    --match-timeout, --retry-errors, --record-dir, --rcg-dir, --record-every, --no-progress, --same-code."""
    from experiments.runner.run import BACKENDS, DEFAULT_MATCH_TIMEOUT

    parser.add_argument("--seed", type=ranged("seed"), default=0,
                        help=seed_help or "first seed; a pairing plays seeds seed, seed+1, ... (default: 0)")
    parser.add_argument("--cycles", type=ranged("cycles"), default=None,
                        help="cycles per match (default: a regulation match of 6000); part of the configuration hash")
    if observation:
        parser.add_argument("--observation", choices=("full", "partial"), default="full",
                            help="what the teams perceive: the exact state (full, default) or each player's own "
                                 "noisy view and the say/hear channel (partial; teams must support it); part of the "
                                 "configuration hash")
    parser.add_argument("--workers", type=ranged("workers"), default=os.cpu_count() or 1,
                        help="worker processes (default: every core); with --backend ray: at most this many CPUs "
                             "of a local Ray instance")
    parser.add_argument("--backend", choices=BACKENDS, default="local",
                        help="local process pool (default) or a Ray cluster (needs: pip install 'soccer-sim[ray]')")
    parser.add_argument("--address", default=None,
                        help="Ray cluster to join: HOST:PORT or 'auto' (default: the cluster RAY_ADDRESS names, "
                             "else a private local Ray instance)")
    parser.add_argument("--ship-code", action=argparse.BooleanOptionalAction, default=True,
                        help="with --backend ray: send this machine's project code to every node with the job "
                             "(default: on); --no-ship-code: the nodes must have the same code installed")
    if default_out is not None:
        parser.add_argument("--out", default=default_out,
                            help=f"SQLite results file; re-running the same command continues it (default: {default_out})")
    parser.add_argument("--tables", default=None, metavar="DIR",
                        help="where the CSV/Markdown tables and the PNG go (default: "
                             f"{tables_default or 'the --out name without its extension, plus ' + repr('-tables')})")
    parser.add_argument("--match-timeout", type=ranged("match-timeout"), default=DEFAULT_MATCH_TIMEOUT, metavar="SECONDS",
                        help=f"a match taking longer is stopped and forfeited (default: {DEFAULT_MATCH_TIMEOUT:g})")
    parser.add_argument("--retry-errors", action="store_true", help="play stored forfeits again")
    parser.add_argument("--record-dir", default=None, metavar="DIR",
                        help="write rerun replays of a sample of the matches played into DIR "
                             "(watch one with `soccer-sim replay FILE.rrd`)")
    parser.add_argument("--rcg-dir", default=None, metavar="DIR",
                        help="write rcssserver game logs (.rcg) of a sample of the matches played into DIR "
                             "(replay one with rcssmonitor or soccerwindow2)")
    parser.add_argument("--record-every", type=ranged("record-every"), default=10, metavar="K",
                        help="with --record-dir or --rcg-dir: record every K-th match of the run (default: 10)")
    parser.add_argument("--no-progress", action="store_true", help="no progress bar or progress lines")
    parser.add_argument("--same-code", action="store_true",
                        help="refuse to resume into a --out holding matches of another code version (default: warn)")


def check_observation(teams: list[str], observation: str) -> None:
    """A RunInputError naming the first of ``teams`` that cannot play under ``observation``
    (``--observation partial`` needs teams that take per-player views), before any match."""
    from experiments.runner.worker import make_team
    from soccer_sim.team_hooks import observation_modes

    for name in teams:
        team, _ = make_team(name)
        modes = observation_modes(team)
        if observation not in modes:
            raise RunInputError(f"team {name!r} cannot play under --observation {observation}: it plays under "
                                f"{', '.join(modes)} only (a team that takes per-player views declares "
                                "observation_modes = ('full', 'partial') or ('partial',))")


def scenario_named(text: str | None):
    """The scenario ``--scenario`` names: a library name, or a path to a .json/.toml file (None:
    none); a ScenarioError (a ValueError) for an unknown name or a bad file."""
    if text is None:
        return None
    from soccer_sim.scenarios import get_scenario, load_scenario

    if text.lower().endswith((".json", ".toml")):
        return load_scenario(text)
    return get_scenario(text)


def scenario_option(text: str | None, config=None):
    """:func:`scenario_named`, checked against ``config`` (None: the defaults), with a bad name or
    file, or a scenario that does not fit the field, as a RunInputError naming ``--scenario``."""
    from soccer_sim.setup import MatchSetup

    try:
        scenario = scenario_named(text)
        if scenario is not None:
            MatchSetup.resolve(config, scenario)
    except (ValueError, OSError) as exc:
        raise RunInputError(f"--scenario {text!r}: {exc}") from None
    return scenario


def team_labels(names: list[str]) -> dict[str, str]:
    """How tables show each of ``names``: a team given by a ``package.module:Attribute`` path by
    its own ``name`` (e.g. a PolicyTeam's), when it has one that no other team of ``names`` is
    called or shown by; every other team by the name given. A path that cannot be loaded now
    (e.g. ``results show`` elsewhere) keeps its path."""
    from experiments.runner.worker import make_team

    labels = {}
    for name in names:
        own = None
        if ":" in name:
            try:
                own = getattr(make_team(name)[0], "name", None)
            except Exception:  # noqa: BLE001 - a label only: the path stands for the team
                own = None
        labels[name] = own if isinstance(own, str) and own.strip() else name
    shown = list(labels.values())
    return {name: label if shown.count(label) == 1 and (label == name or label not in names) else name
            for name, label in labels.items()}


def add_team_option(parser: argparse.ArgumentParser, option: str, defaults: tuple[str, ...], what: str) -> None:
    """A comma-separated team-list option whose help names the defaults and the registered teams."""
    parser.add_argument(option, default=",".join(defaults),
                        help=f"{what}, comma-separated (default: {','.join(defaults)}): registered names "
                             "(`soccer-sim teams` lists them), package.module:Attribute paths or saved RL checkpoints "
                             "checkpoint:KIND:PATH?OPTION=VALUE&... (docs/env.md)")


def run_command(args: argparse.Namespace, kind: str, params_of, build_specs, report, figures=None) -> int:
    """The body of every command that runs matches: parameters from ``args`` (``params_of``
    may raise RunInputError), the run, the report into ``--tables``. Exit status 2 with a
    message for bad input (the tables directory included: it is checked before the first
    match); 1 when the results or the tables cannot be written (the message says what is
    kept), when the failure policy stopped the run, or when a match could not be played for a
    reason other than a team's own fault (the tables are written without it; one line says how
    many); 130 after Ctrl-C. 0 only when the tables are complete (forfeits are results).
    ``figures``: see :func:`~experiments.runner.run.run_matches`."""
    from experiments.results.store import StorageError
    from experiments.runner.run import RunStopped

    try:
        params = params_of(args)
        tables = tables_dir(args)
        summary = execute(args, kind, build_specs(params), params, figures)
        try:
            tables.mkdir(parents=True, exist_ok=True)
            report(summary.records, params, tables)
        except BrokenPipeError:
            raise                            # the reader of stdout went away: not a --tables problem
        except OSError as exc:
            from experiments.results.files import describe

            raise StorageError(f"--tables {tables}: cannot write {describe(exc)}; the {len(summary.records)} "
                               f"matches are stored in {args.out}: `soccer-sim results show {args.out} --tables "
                               f"{tables}` writes the tables again") from None
    except RunInputError as exc:
        return fail(str(exc))
    except (StorageError, RunStopped) as exc:
        return fail(str(exc), 1)
    except KeyboardInterrupt:
        return interrupted(args.out)
    print_failures(summary)
    if summary.unfinished:                   # another run on the same file still plays some of them
        return fail(summary.incomplete(), 1)
    return incomplete(summary)


def incomplete(summary: RunSummary) -> int:
    """Exit status 1 with one line on stderr when some matches of ``summary`` failed with no
    team at fault (missing from the tables), else 0."""
    if not summary.unplayed:
        return 0
    return fail(f"{summary.unplayed} of the {summary.total} matches could not be played (no team at fault), so the "
                f"tables leave them out; they are kept as failed in {summary.path} and the same command plays them "
                "again", 1)


def team_list(text: str, option: str, minimum: int = 1, external: Collection[str] = ()) -> list[str]:
    """Comma-separated team names, each resolvable (a registered name, an importable
    ``module:Attribute`` path or a loadable checkpoint team ``checkpoint:KIND:PATH?...``) or
    one of ``external`` (programs that play in the real server, ``--engine rcssserver``); a
    RunInputError naming the closest registered names, or what is wrong with the checkpoint,
    otherwise (:func:`soccer_sim.registry.unknown_team_message`), and one saying that
    helios-base plays only in the real server when it is named outside ``external``."""
    from rcss_bridge.install import HELIOS_TEAM
    from soccer_sim import TeamNotFoundError, available_teams, resolve_team
    from soccer_sim.env.checkpoint_teams import CheckpointError, checkpoint_team, is_checkpoint_name
    from soccer_sim.registry import unknown_team_message

    names = [name.strip() for name in text.split(",") if name.strip()]
    if len(names) != len(set(names)):
        raise RunInputError(f"{option}: a team is named twice in {text!r}")
    if len(names) < minimum:
        raise RunInputError(f"{option}: needs at least {minimum} team(s), got {text!r}")
    known = available_teams()
    for name in names:
        if name in external:
            continue
        if name == HELIOS_TEAM:
            raise RunInputError(f"{option}: {name} plays only in the real server (rcssserver): add --engine "
                                "rcssserver where the command offers it")
        if is_checkpoint_name(name):
            try:
                checkpoint_team(name)
            except CheckpointError as exc:
                raise RunInputError(f"{option}: {exc}") from None
        elif ":" in name:
            try:
                resolve_team(name)
            except TeamNotFoundError as exc:
                hint = ""
                if "cannot import module" in str(exc):
                    hint = ("; the module must be importable: installed, on PYTHONPATH, or under the directory "
                            "soccer-sim runs in (examples.* paths: run from the checkout)")
                raise RunInputError(f"{option}: {exc}{hint}") from None
        elif name not in known:
            raise RunInputError(f"{option}: {unknown_team_message(name, known)}")
    return names


def tables_dir(args: argparse.Namespace) -> Path:
    """The directory for the tables and figures, checked (not created: nothing is left behind
    by a run refused later) before any match is played; a RunInputError if it is a file or
    cannot be written in."""
    from experiments.results.files import directory_problem, name_problem

    problem = name_problem(args.out)
    if problem:
        raise RunInputError(f"--out {args.out!r}: {problem}")
    path = Path(args.tables) if args.tables is not None else Path(args.out).with_name(Path(args.out).stem + "-tables")
    problem = directory_problem(args.tables if args.tables is not None else path, used=[args.out])
    if problem:
        raise RunInputError(f"--tables {args.tables if args.tables is not None else path}: {problem}")
    return path


def execute(args: argparse.Namespace, kind: str, specs: list[MatchSpec], params: dict[str, object],
            figures=None) -> RunSummary:
    """Run ``specs`` into ``args.out``; errors about the file, a parameter or the backend become
    RunInputError worded with the command's options (KeyboardInterrupt propagates: every
    finished match is stored)."""
    from experiments.errors import ParameterError
    from experiments.results.store import ResultsError
    from experiments.runner.ray_backend import RayUnavailable
    from experiments.runner.run import MixedCodeVersions, run_matches

    if args.address and args.backend != "ray":
        raise RunInputError("--address needs --backend ray")
    try:
        with warnings.catch_warnings():
            _show_mixed_code_as_options()
            summary = run_matches(specs, args.out, kind, params, cycles=args.cycles, workers=args.workers,
                                  backend=args.backend, address=args.address, match_timeout=args.match_timeout,
                                  retry_errors=args.retry_errors, progress=not args.no_progress,
                                  record_dir=args.record_dir, record_every=args.record_every,
                                  rcg_dir=getattr(args, "rcg_dir", None), figures=figures,
                                  ship_code=getattr(args, "ship_code", True),
                                  same_code=getattr(args, "same_code", False))
    except MixedCodeVersions as exc:
        raise RunInputError(f"{exc.path} holds matches played by another code version ({exc.others}), not by this "
                            f"code ({exc.version}); --same-code refuses to mix them: give another --out, or leave "
                            "out --same-code") from None
    except ParameterError as exc:
        option = OPTIONS.get(exc.parameter)
        raise RunInputError(f"{option} {exc.problem}" if option else str(exc)) from None
    except (ResultsError, RayUnavailable, ValueError) as exc:
        raise RunInputError(str(exc)) from None
    print(summary.line())
    return summary


OPTIONS = {"seed": "--seed", "record_every": "--record-every", "record_dir": "--record-dir", "rcg_dir": "--rcg-dir",
           "cycles": "--cycles"}
"""The option of each run_matches parameter a ParameterError can name."""


def _show_mixed_code_as_options() -> None:
    """Within ``warnings.catch_warnings()``: show every MixedCodeWarning at once as one
    ``warning:`` line worded with the options; other warnings as Python shows them."""
    from experiments.runner.run import MixedCodeWarning

    shown = warnings.showwarning

    def show(message, category, *rest) -> None:
        if isinstance(message, MixedCodeWarning):
            print(f"warning: {message.path} holds matches played by another code version ({message.others}); this "
                  f"run plays the rest with {message.version}, so its tables mix code versions (--same-code refuses "
                  "this)", file=sys.stderr)
        else:
            shown(message, category, *rest)

    warnings.simplefilter("always", MixedCodeWarning)
    warnings.showwarning = show


def interrupted(out: str) -> int:
    """After Ctrl-C: say what is kept and how to continue; exit status 130."""
    print(f"interrupted: every finished match is stored in {out}; run the same command again to continue",
          file=sys.stderr)
    return 130


def print_failures(summary: RunSummary, limit: int = 5) -> None:
    """A few lines about failed matches (the errors; ``results export`` has the tracebacks)."""
    from experiments.stats import blamed_team, failures

    failed = failures(summary.records)
    if not failed:
        return
    print(f"{len(failed)} match(es) failed (forfeited by the team named, or not played with no team at fault); "
          "first ones:")
    for record in failed[:limit]:
        who = blamed_team(record)
        blame = f"forfeited by {who}" if who else "no team blamed"
        print(f"  {record.home} v {record.away}, seed {record.seed}: {blame}: {record.error}")
