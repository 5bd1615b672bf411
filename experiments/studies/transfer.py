"""``soccer-sim experiment transfer``: do the role assigners' results carry over from the
simulator to the real RoboCup 2D server? The same pairings played in both engines and reported
side by side.

Each of ``--teams`` (our teams, any role assigner) plays each of ``--opponents`` and the
``--mirror`` pairings, on paired seeds (sides swapped, the same seeds for every pairing), in the
simulator (``--games-sim`` per pairing) and in rcssserver through the bridge (``--games-real``;
helios-base and ``--external`` teams play there only). Both engines play our teams under partial
observation: the bridge builds each player's views from what the server told it, so the
simulator's half is played under ``--observation partial`` too. Each engine's matches go to a
results file of its own (``--out-sim``, ``--out-real``: a results file never mixes engines, the
engine is part of its configuration's hash), so each half can be played, stopped and resumed
on its own (``--engine-only``); ``--plan`` says what a run would play, ``--report-only`` writes
the report from the files alone, and ``--read-sim`` / ``--read-real`` add more files of an
engine (e.g. those of ``experiment case-study --observation partial`` and ``experiment
case-study --engine rcssserver`` with the same teams and seeds).

The report (:mod:`experiments.studies.transfer_report`): per pairing the goal difference (SE) in
each engine with the games each row holds; each team minus ``--baseline`` paired on the same
opponent, seed and side in each engine; the teams' rankings per engine and Kendall's tau-b
between the engines' rankings; the match statistics of our teams in the server beside
helios-base's. Written as CSV and Markdown to ``--tables``.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence
from pathlib import Path

from experiments.commands import doc_summary
from experiments.rcss_runs import ENGINES, RCSS
from experiments.runner.spec import SIMULATOR

KIND = "transfer"
DEFAULT_TEAMS = ("mmdr", "mmd+msd2", "static", "greedy", "bidding")
DEFAULT_OPPONENTS = ("counter-442", "helios-base")
DEFAULT_MIRROR = ("mmd+msd2", "static")
DEFAULT_BASELINE = "static"
DEFAULT_GAMES = {SIMULATOR: 300, RCSS: 30}
"""Games per pairing each engine plays unless ``--games-sim`` / ``--games-real`` say otherwise."""

OPTIONS = {SIMULATOR: ("--out-sim", "--read-sim", "--games-sim"), RCSS: ("--out-real", "--read-real", "--games-real")}
"""Each engine's options: its results file, the more files the report reads, its games."""


def option_value(args: argparse.Namespace, option: str):
    """The value of ``option`` (e.g. ``--out-sim``) in ``args``."""
    return getattr(args, option[2:].replace("-", "_"))


def add_arguments(parser: argparse.ArgumentParser) -> None:
    from experiments.commands.run_options import add_run_arguments, add_team_option
    from experiments.limits import ranged
    from experiments.rcss_runs import DEFAULT_WORKERS, add_server_arguments

    parser.description = doc_summary(__doc__)
    add_team_option(parser, "--teams", DEFAULT_TEAMS, "our teams compared (each plays in both engines)")
    add_team_option(parser, "--opponents", DEFAULT_OPPONENTS,
                    "their opponents (helios-base and --external teams play in rcssserver only)")
    parser.add_argument("--mirror", action="append", default=None, metavar="TEAM,TEAM",
                        help=f"a pairing of two compared teams played besides (default: {','.join(DEFAULT_MIRROR)}; "
                             "repeat for more)")
    parser.add_argument("--no-mirror", action="store_true", help="no mirror pairing")
    parser.add_argument("--baseline", default=DEFAULT_BASELINE,
                        help=f"the team the others are compared with, match by match (default: {DEFAULT_BASELINE})")
    parser.add_argument("--games-sim", type=ranged("games"), default=None, metavar="N",
                        help=f"matches per pairing in the simulator, rounded up to even (default: "
                             f"{DEFAULT_GAMES[SIMULATOR]}; with --report-only: the number the file's run asked for)")
    parser.add_argument("--games-real", type=ranged("games"), default=None, metavar="N",
                        help=f"matches per pairing in rcssserver, rounded up to even (default: {DEFAULT_GAMES[RCSS]}; "
                             "with --report-only: the number the file's run asked for)")
    parser.add_argument("--out-sim", default="transfer-sim.sqlite", metavar="FILE",
                        help="the simulator's results file; re-running continues it (default: transfer-sim.sqlite)")
    parser.add_argument("--out-real", default="transfer-real.sqlite", metavar="FILE",
                        help="rcssserver's results file; re-running continues it (default: transfer-real.sqlite)")
    parser.add_argument("--read-sim", action="append", default=[], metavar="FILE",
                        help="another results file of the simulator's matches the report reads, never written "
                             "(repeatable)")
    parser.add_argument("--read-real", action="append", default=[], metavar="FILE",
                        help="another results file of rcssserver's matches the report reads, never written "
                             "(repeatable)")
    parser.add_argument("--engine-only", choices=ENGINES, default=None,
                        help="play (or, with --report-only, report) one engine's half only; the report still reads "
                             "the other engine's --out file when it exists")
    what = parser.add_mutually_exclusive_group()
    what.add_argument("--report-only", action="store_true",
                      help="play nothing: the report from the results files (each must exist)")
    what.add_argument("--plan", action="store_true",
                      help="play nothing: print the matches each engine's run would play and those already stored")
    add_run_arguments(parser, None, observation=False, tables_default="transfer-tables beside --out-real")
    parser.add_argument("--workers-real", type=ranged("workers"), default=None, metavar="N",
                        help=f"matches played at once in rcssserver (default: {DEFAULT_WORKERS}; one keeps about two "
                             "cores busy); --workers, --backend, --address and --record-dir are the simulator's")
    add_server_arguments(parser, "in rcssserver")


# ---------------------------------------------------------------------------------- parameters
def half_args(args: argparse.Namespace, engine: str) -> argparse.Namespace:
    """The options of one engine's run, as a command that plays in that engine reads them
    (``--engine``, ``--out``, ``--workers`` ...): the simulator's half takes ``--workers``,
    ``--backend`` and ``--record-dir``; the server's ``--workers-real`` (default
    :data:`~experiments.rcss_runs.DEFAULT_WORKERS`), the local pool, the
    server's build and the external teams. ``--rcg-dir`` gets a sub-directory per engine (the
    two halves' logs have the same names)."""
    half = argparse.Namespace(**vars(args))
    half.engine = engine
    half.out = option_value(args, OPTIONS[engine][0])
    if args.rcg_dir is not None:
        half.rcg_dir = str(Path(args.rcg_dir) / engine)
    if engine == RCSS:
        from experiments.rcss_runs import DEFAULT_WORKERS

        half.workers = args.workers_real or DEFAULT_WORKERS
        half.backend, half.address, half.record_dir = "local", None, None
    else:
        half.external, half.rcss_home = [], None
    return half


def plan_params(args: argparse.Namespace) -> dict[str, dict]:
    """Each engine's stored parameters (the design, its games, the seed and cycles, partial
    observation and, in the server, the external teams), checked; a RunInputError naming the
    option for bad input."""
    from experiments.commands.run_options import RunInputError, check_observation, team_list
    from experiments.rcss_runs import EngineChoice
    from experiments.studies.transfer_report import Design

    real = EngineChoice.from_args(half_args(args, RCSS))
    teams = team_list(args.teams, "--teams", external=real.external_names)
    if foreign := [team for team in teams if team not in real.ours([team])]:
        raise RunInputError(f"--teams: {foreign[0]} plays in rcssserver only, and the compared teams play in both "
                            "engines: name it in --opponents")
    opponents = team_list(args.opponents, "--opponents", minimum=0, external=real.external_names)
    if args.no_mirror and args.mirror:
        raise RunInputError("--no-mirror and --mirror contradict each other: give one")
    given = [] if args.no_mirror else (args.mirror or [",".join(DEFAULT_MIRROR)])
    mirror = [_mirror(text, real.external_names) for text in given]
    if args.baseline not in teams:
        raise RunInputError(f"--baseline {args.baseline!r} must be one of --teams ({', '.join(teams)})")
    if not opponents and not mirror:
        raise RunInputError("--opponents is empty and there is no --mirror pairing: nothing to compare")
    if args.out_real == args.out_sim:
        raise RunInputError(f"--out-real and --out-sim are both {args.out_sim!r}: one results file never mixes "
                            "engines, give each its own")
    if not args.report_only:
        check_observation(real.ours([*teams, *opponents, *(n for pair in mirror for n in pair)]), "partial")
    design = Design(tuple(teams), tuple(opponents), tuple((a, b) for a, b in mirror), args.baseline,
                    frozenset(real.external_names))
    params = {}
    for engine in ENGINES:
        choice = real if engine == RCSS else EngineChoice(SIMULATOR, {})
        params[engine] = {"teams": teams, "opponents": [o for o in opponents if design.plays(engine, o)],
                          "baseline": args.baseline,
                          "mirror": [[a, b] for a, b in mirror if design.plays(engine, a, b)],
                          "games": games_of(args, engine) or DEFAULT_GAMES[engine], "seed": args.seed,
                          "cycles": args.cycles, "observation": "partial", **choice.params()}
    return params


def _mirror(text: str, external: Sequence[str]) -> list[str]:
    """``TEAM,TEAM`` of ``--mirror`` as two names."""
    from experiments.commands.run_options import RunInputError, team_list

    names = team_list(text, "--mirror", minimum=2, external=external)
    if len(names) != 2:
        raise RunInputError(f"--mirror {text!r}: give two teams, TEAM,TEAM")
    return names


def games_of(args: argparse.Namespace, engine: str) -> int | None:
    """The games per pairing the options give ``engine`` (None: not given)."""
    return option_value(args, OPTIONS[engine][2])


def build_specs(params: dict) -> list:
    """Every match of one engine's half (``params``: :func:`plan_params`'s): each team against
    each opponent and the mirror pairings, on paired seeds under partial observation (the
    simulator's specs; :func:`experiments.rcss_runs.engine_specs` makes them play in the server)."""
    from experiments.runner.spec import paired_specs

    pairs = [(team, opponent) for team in params["teams"] for opponent in params["opponents"]]
    pairs += [(a, b) for a, b in params.get("mirror", ())]
    specs = [spec for a, b in pairs
             for spec in paired_specs(a, b, params["games"], params["seed"], params["cycles"], "partial")]
    return list(dict.fromkeys(specs))


def engines_of(args: argparse.Namespace) -> tuple[str, ...]:
    """The engines this run plays (or reports with ``--report-only``)."""
    return (args.engine_only,) if args.engine_only else ENGINES


# ---------------------------------------------------------------------------------- the command
def run(args: argparse.Namespace) -> int:
    from experiments.commands.errors import fail
    from experiments.commands.run_options import (RunInputError, execute, incomplete, interrupted,
                                                  print_failures)
    from experiments.rcss_runs import engine_specs
    from experiments.results.store import StorageError
    from experiments.runner.run import RunStopped

    current, tables = args.out_sim, None
    try:
        params = plan_params(args)
        tables = _tables_dir(args)
        summaries = []
        if not args.report_only:
            halves = {engine: half_args(args, engine) for engine in engines_of(args)}
            # every pre-flight (a missing server build, a --cycles the server cannot play) before any match
            specs = {engine: engine_specs(half, build_specs)(params[engine]) for engine, half in halves.items()}
            if args.plan:
                print_plan(specs, halves)
                return 0
            if RCSS in halves and args.workers_real is None:
                print(f"rcssserver: {halves[RCSS].workers} match at a time (one keeps about two cores busy; "
                      "--workers-real N plays N at once)", file=sys.stderr)
            for engine, half in halves.items():
                if not specs[engine]:
                    print(f"{engine}: no pairing to play")
                    continue
                current = half.out
                summary = execute(half, KIND, specs[engine], params[engine])
                print_failures(summary)
                summaries.append(summary)
        written = report_files(args, params, tables, played=not args.report_only)
    except RunInputError as exc:
        return fail(str(exc))
    except (StorageError, RunStopped) as exc:
        return fail(str(exc), 1)
    except KeyboardInterrupt:
        return interrupted(current)
    except BrokenPipeError:
        raise                                # the reader of stdout went away: not a --tables problem
    except OSError as exc:
        from experiments.results.files import describe

        return fail(f"--tables {tables}: cannot write {describe(exc)}; the matches are stored in their results "
                    "files: the same command with --report-only writes the tables again", 1)
    if written:
        print("wrote " + ", ".join(str(path) for path in written))
    for summary in summaries:
        if summary.unfinished:
            return fail(summary.incomplete(), 1)
    for summary in summaries:
        if incomplete(summary):
            return 1
    return 0


def _tables_dir(args: argparse.Namespace) -> Path:
    """``--tables`` (default: transfer-tables beside --out-real), checked before any match: a
    RunInputError for a bad results file name or a directory that cannot be written in."""
    from experiments.commands.run_options import RunInputError
    from experiments.results.files import directory_problem, name_problem

    for option in ("--out-sim", "--out-real"):
        value = option_value(args, option)
        problem = name_problem(value)
        if problem:
            raise RunInputError(f"{option} {value!r}: {problem}")
    path = Path(args.tables) if args.tables is not None else Path(args.out_real).with_name("transfer-tables")
    problem = directory_problem(path, used=[args.out_sim, args.out_real, *args.read_sim, *args.read_real])
    if problem:
        raise RunInputError(f"--tables {path}: {problem}")
    return path


def print_plan(specs: dict[str, list], halves: dict[str, argparse.Namespace]) -> None:
    """Per engine and pairing: the matches its run holds and how many its results file already
    stores (read-only); per engine the total and, where the file has played matches, the time
    the rest would take at their median wall time."""
    import statistics

    from experiments.reporting import Table

    stored = {engine: _stored(halves[engine], specs[engine]) for engine in specs}
    pairings = list(dict.fromkeys(tuple(sorted((s.home, s.away))) for e in specs for s in specs[e]))
    table = Table("plan: matches stored / matches of the run, per pairing (either team at home)",
                  ["pairing", *specs])
    for pair in pairings:
        cells = [" v ".join(pair)]
        for engine, planned in specs.items():
            mine = [s for s in planned if tuple(sorted((s.home, s.away))) == pair]
            done = sum(s.key in stored[engine][0] for s in mine)
            cells.append(f"{done} / {len(mine)}" if mine else "-")
        table.rows.append(cells)
    table.print()
    for engine, planned in specs.items():
        keys, seconds = stored[engine]
        todo = sum(s.key not in keys for s in planned)
        line = (f"{engine}: {len(planned)} matches in {halves[engine].out}, {len(planned) - todo} stored, "
                f"{todo} to play")
        if todo and seconds:
            median = statistics.median(seconds)
            workers = halves[engine].workers or 1
            line += (f" (about {todo * median / workers / 3600:.1f} h at the stored matches' median of {median:.0f} s "
                     f"each on {workers} worker(s))")
        print(line)


def _stored(half: argparse.Namespace, specs: list) -> tuple[set, list[float]]:
    """The keys stored in ``half.out`` that the run would keep, and the wall times of its played
    matches (nothing when the file is absent); a RunInputError when the run would refuse it."""
    from experiments.commands.run_options import RunInputError
    from experiments.results.record import FORFEIT_NONE
    from experiments.results.store import ResultsError, ResultStore
    from experiments.runner.spec import config_hash

    path = Path(half.out)
    if not path.is_file() or path.stat().st_size == 0 or not specs:
        return set(), []
    option = OPTIONS[half.engine][0]
    try:
        with ResultStore.open(path) as store:
            kind, digest, records = store.kind, store.config_hash, store.records()
    except ResultsError as exc:
        raise RunInputError(f"{option} {exc}") from None
    wanted = config_hash(specs[0].config(), None, specs[0].engine)
    if kind != KIND or digest != wanted:
        raise RunInputError(f"{option} {path}: holds the results of '{kind}' (configuration {digest}), not of this "
                            f"run ('{KIND}', configuration {wanted}): the run would refuse it; use another file "
                            f"(and give this one to {OPTIONS[half.engine][1]} for the report)")
    keys = {r.key for r in records if r.played or (r.forfeit != FORFEIT_NONE and not half.retry_errors)}
    return keys, [r.wall_time for r in records if r.played]


# ---------------------------------------------------------------------------------- the report
def report_files(args: argparse.Namespace, params: dict[str, dict], out_dir: Path, played: bool) -> list[Path]:
    """Read each engine's results files, print the report and write it into ``out_dir``; the
    files written. With ``--report-only`` each file named must exist; after a run, the other
    engine's ``--out`` file is read when it exists. A RunInputError for files that cannot be
    used together or teams none of them holds (:mod:`experiments.studies.transfer_report`)."""
    from experiments.commands.run_options import RunInputError
    from experiments.studies.transfer_report import (Design, TransferInputError, check_names, describe,
                                                     read_engine, transfer_tables, write_report)

    chosen = engines_of(args)
    halves = {}
    try:
        for engine in ENGINES:
            if args.report_only and engine not in chosen:
                continue
            out_option, read_option, _ = OPTIONS[engine]
            out = option_value(args, out_option)
            files = [(read_option, path) for path in option_value(args, read_option)]
            if args.report_only or Path(out).is_file():
                files.insert(0, (out_option, out))
            if files:
                halves[engine] = read_engine(engine, files)
        if len({half.cycles for half in halves.values()}) > 1:
            raise TransferInputError("the engines' files hold matches of different lengths (" + ", ".join(
                f"{engine}: {half.cycles or 'regulation'} cycles" for engine, half in halves.items()) +
                "); goal differences compare only at one length")
        external = tuple(name for half in halves.values() for name in half.external)
        design = Design.from_params(params[RCSS], external)
        if args.report_only:
            check_names(design, halves)
    except TransferInputError as exc:
        raise RunInputError(str(exc)) from None
    asked = {engine: games_of(args, engine) or (params[engine]["games"] if played and engine in chosen else None)
             for engine in halves}
    result = transfer_tables(design, halves, asked)
    for table in result.tables:
        table.print()
    for note in result.notes:
        print(note)
    out_dir.mkdir(parents=True, exist_ok=True)
    return write_report(out_dir, result, describe(halves))


def report(records: Sequence, params: dict, out_dir: Path | None = None) -> list[Path]:
    """``results show`` of one engine's file of this command: that engine's half of the report
    (no rank agreement: that needs both); with ``out_dir``, its CSV and Markdown files there."""
    from experiments.studies.transfer_report import (Design, EngineResults, describe, transfer_tables,
                                                     write_report)

    engine = params.get("engine", SIMULATOR)
    halves = {engine: EngineResults(engine, list(records), cycles=params.get("cycles"), asked=params.get("games"))}
    result = transfer_tables(Design.from_params(params), halves)
    for table in result.tables:
        table.print()
    for note in result.notes:
        print(note)
    if out_dir is None:
        return []
    written = write_report(out_dir, result, describe(halves))
    print("wrote " + ", ".join(str(path) for path in written))
    return written
