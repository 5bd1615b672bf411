"""``soccer-sim replay``: watch a recorded match, draw it, or re-create a stored match.

- ``soccer-sim replay match.rrd`` opens the rerun viewer on the file (the ``rerun`` program
  that rerun-sdk installs; without a display it says so and suggests ``--png``).
- ``soccer-sim replay match.rrd --png field.png [--cycle N]`` draws the field at one cycle
  from the recorded data (players, ball trail, role targets and assignment lines), no viewer
  needed.
- ``soccer-sim replay --results results.sqlite --row K --out match.rrd`` plays match ``K``
  (0-based, in the order of ``soccer-sim results export``) of a stored run again and records
  it: a match is a pure function of its teams, configuration and seed, so the replay is the
  match that was stored (on the same platform; the command checks the score). A row whose
  match failed (a team raised, sent a malformed command or ran out of time, or its worker
  died) holds no match to re-create: the command says which failure it was and stops.
"""

from __future__ import annotations

import argparse
import sys

from experiments.commands.errors import fail as _fail


def register(subparsers: argparse._SubParsersAction) -> None:
    parser = subparsers.add_parser(
        "replay", help="watch or draw a recorded match (.rrd), or re-create a stored match",
        description="Open a rerun replay in the viewer, draw it as a PNG, or re-create a match of a results "
                    "file by its row and record it.")
    parser.add_argument("file", nargs="?", metavar="FILE.rrd", help="a replay written by `play --record`")
    parser.add_argument("--png", metavar="OUT.png", help="draw the field at --cycle instead of opening the viewer")
    parser.add_argument("--cycle", type=int, default=None, help="cycle drawn by --png (default: the last goal, "
                                                                "else the middle of the match)")
    parser.add_argument("--results", metavar="RESULTS.sqlite", help="re-create a stored match from this results file")
    parser.add_argument("--row", type=int, default=None, help="with --results: the match's row (0-based, in "
                                                              "`soccer-sim results export` order)")
    parser.add_argument("--out", metavar="OUT.rrd", default="replay.rrd",
                        help="with --results: where to write the replay (default: %(default)s)")
    parser.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    from soccer_sim.replay import ReplayError

    try:
        if args.results is not None:
            return _recreate(args)
        if args.file is None:
            return _fail("give a replay file (FILE.rrd), or --results FILE --row K")
        if args.png is not None:
            return _draw(args.file, args.png, args.cycle)
        return _open_viewer(args.file)
    except ReplayError as exc:
        return _fail(str(exc))


def _open_viewer(path: str) -> int:
    import os
    import shutil
    import subprocess

    from formations.input_files import check_input  # the project's one rule for files it reads

    try:
        check_input(path)
    except FileNotFoundError:
        return _fail(f"{path}: no such replay file")
    except OSError as exc:
        return _fail(f"{path}: cannot read it ({exc.strerror or exc})")
    if _is_game_log(path):
        return _fail(f"{path} is an rcssserver game log, not a rerun replay: open it with rcssmonitor or "
                     f"soccerwindow2 (soccer-sim play --record writes rerun replays)")
    viewer = shutil.which("rerun")
    if viewer is None:
        return _fail("the rerun viewer is not installed: pip install rerun-sdk (it provides the `rerun` program)")
    from soccer_sim.replay.recorder import has_display

    if not has_display():
        return _fail(f"no display to open the viewer on; copy {path} to a machine with one and run "
                     f"`rerun {path}`, or draw it here: soccer-sim replay {path} --png field.png")
    return subprocess.call([viewer, path])


def _is_game_log(path: str) -> bool:
    """Whether ``path`` starts like an rcssserver game log (``ULG`` and its version)."""
    from formations.input_files import open_input

    with open_input(path) as file:
        return file.read(3) == b"ULG"


def _draw(path: str, png: str, cycle: int | None) -> int:
    from soccer_sim.replay import read_replay
    from soccer_sim.replay.picture import draw_replay

    from pathlib import Path

    from experiments.commands.errors import FAILED
    from experiments.results.files import atomic_output, describe, file_problem

    problem = file_problem(png, inputs=[path])
    if problem:
        return _fail(f"--png {png!r}: {problem}")
    target = Path(png)
    if not target.suffix:                    # what matplotlib would write: say so, and write it whole
        target = target.with_name(target.name + ".png")
        problem = file_problem(target, inputs=[path])
        if problem:
            return _fail(f"--png {target}: {problem}")
    replay = read_replay(path)
    try:
        with atomic_output(target) as temporary:
            _, shown = draw_replay(replay, temporary, cycle)
    except OSError as exc:                   # a write that started and failed (a full disk): exit 1
        return _fail(f"--png: cannot write {describe(exc)}; nothing was written", FAILED)
    except ValueError as exc:                # a format matplotlib does not know
        return _fail(f"--png {png}: cannot write the picture ({exc})")
    print(f"wrote {target} (cycle {shown})")
    return 0


def _recreate(args: argparse.Namespace) -> int:
    from experiments.results.store import ResultsError, ResultStore
    from experiments.runner.spec import config_for, config_hash
    from experiments.runner.worker import make_team
    from soccer_sim import TeamError, TeamNotFoundError, run_match
    from experiments.recording import replay_recording
    from soccer_sim.replay import ReplayError

    if args.row is None:
        return _fail("--results needs --row K (the match's row, 0-based)")
    try:
        with ResultStore.open(args.results) as store:
            records = store.records()
            params = store.params
    except ResultsError as exc:
        return _fail(str(exc))
    if not 0 <= args.row < len(records):
        return _fail(f"--row {args.row}: {args.results} holds rows 0 to {len(records) - 1}")
    record = records[args.row]
    if not record.played:
        return _fail(f"--row {args.row}: {_failure(record)}; only a match played to its end can be re-created")
    config = config_for(params.get("cycles"))
    if config_hash(config) != record.config_hash:
        return _fail(f"row {args.row} was played with configuration {record.config_hash}, which this version "
                     f"cannot rebuild (it builds {config_hash(config)})")
    problem = _unwritable_replay(args.out, args.results)
    if problem:
        return _fail(f"--out {args.out}: {problem}")
    try:
        home, away = make_team(record.home)[0], make_team(record.away)[0]
    except TeamNotFoundError as exc:
        return _fail(f"row {args.row}: {exc}")
    try:
        with replay_recording(args.out, "--out") as recorders:
            result = run_match(home, away, seed=record.seed, config=config, recorders=recorders)
    except ReplayError as exc:
        return _fail(str(exc))
    except TeamError as exc:
        return _fail(f"row {args.row}: the match failed this time ({type(exc).__name__}: {exc}), though it was "
                     "played to its end when stored: the team's code has changed since", 1)
    except KeyboardInterrupt:
        print(f"interrupted: no replay written to {args.out}", file=sys.stderr)
        return 130
    stored = (record.home_goals, record.away_goals)
    print(f"{record.home} {result.score[0]} - {result.score[1]} {record.away} (seed {record.seed}); "
          f"replay written to {args.out}")
    if tuple(int(g) for g in result.score) != stored:
        print(f"note: the stored score was {stored[0]} - {stored[1]}: this machine or library versions "
              f"differ from the ones that played it (a match is bit-identical only on the same platform)")
    return 0


def _failure(record) -> str:
    """Which failure a stored row holds, in one line: the match, who forfeited it, the error."""
    from experiments.stats import blamed_team

    who = blamed_team(record)
    blame = f"forfeited by {who}" if who else "not played to its end (no team blamed)"
    error = (record.error or "").strip().splitlines()
    return (f"{record.home} v {record.away}, seed {record.seed}, was {blame}: "
            f"{error[0] if error else 'no error message stored'}")


def _unwritable_replay(path: str, results: str) -> str | None:
    """Why a replay cannot be written to ``path`` (before the match is played), or None."""
    from pathlib import Path

    from experiments.results.files import file_problem

    if Path(path).suffix != ".rrd":
        return "a replay file must end in .rrd"
    return file_problem(path, inputs=[results])
