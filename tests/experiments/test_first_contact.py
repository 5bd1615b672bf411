"""What a newcomer meets first: a quick ``--help`` on every command, tables that are plain when
piped and fit a terminal of 80 columns, a short line for an unknown team, and the progress of
the one-time kernel compilation."""

from __future__ import annotations

import io
import json
from pathlib import Path

from experiments.cli import main
from tests.experiments.test_startup import TINY_KERNELS, TINY_MODULE
from tests.fresh_python import run_python

BOX = set("┏━┳┓┃┡╇┩│└┴┘─")


def test_no_command_help_imports_the_simulator_or_numba(tmp_path: Path) -> None:
    """Each ``--help`` in one fresh interpreter, in the order listed; the first command after
    which a heavy package is loaded is named."""
    done = run_python("""
import contextlib, io, json, sys
from experiments.cli import command_paths, main
HEAVY = {"soccer_sim", "agents", "numba", "numpy", "scipy", "pymunk", "formations"}
paths, found = command_paths(), {}
for path in paths:
    with contextlib.redirect_stdout(io.StringIO()) as out:
        try:
            main([*path, "--help"])
        except SystemExit:
            pass
    loaded = sorted({name.split(".")[0] for name in sys.modules} & HEAVY)
    if loaded:
        found[" ".join(path)] = loaded
        break
    assert "usage: soccer-sim" in out.getvalue(), path
print(json.dumps([len(paths), found]))
""", tmp_path)
    count, found = json.loads(done.stdout)
    assert found == {}
    assert count >= 30  # soccer-sim itself, every command and every sub-command


def test_command_paths_lists_every_command_and_sub_command() -> None:
    from experiments.cli import command_paths

    paths = command_paths()
    assert paths[0] == ()
    for expected in (("play",), ("teams",), ("tournament",), ("experiment", "case-study"), ("bench", "startup"),
                     ("bench", "lazy-assignment"), ("results", "show"), ("formation", "import")):
        assert expected in paths


def test_play_prints_plain_tables_when_piped(capsys) -> None:
    assert main(["play", "chaser", "idle", "--seed", "2", "--cycles", "300"]) == 0
    out = capsys.readouterr().out
    assert not BOX & set(out)
    lines = out.splitlines()
    assert "# Statistics" in lines
    header = lines[lines.index("# Statistics") + 1].split("\t")
    assert header == ["", "chaser (home)", "idle (away)"]
    assert any(line.split("\t")[0] == "goals" and len(line.split("\t")) == 3 for line in lines)


def test_the_league_table_fits_80_columns_without_wrapping() -> None:
    from rich.console import Console

    from experiments.commands.tournament import tables
    from experiments.results.record import MatchRecord

    teams = ["greedy-offense-leave", "mmd+msd2", "static", "bidding"]
    records = []
    for seed in range(150):
        for home, away in [(a, b) for a in teams for b in teams if a < b]:
            record = MatchRecord(home, away, seed, "h")
            record.home_goals, record.away_goals = seed % 5, (seed * 7) % 4
            record.home_stats, record.away_stats = {"goals": record.home_goals}, {"goals": record.away_goals}
            records.append(record)
    league, _, _, _ = tables(records, teams)
    screen = io.StringIO()
    league.print(Console(file=screen, width=80, force_terminal=True, color_system=None))
    lines = screen.getvalue().splitlines()
    assert max(len(line) for line in lines) <= 80
    for row in league.rows:  # every row on one line: rank, whole team name, ..., its goal difference
        assert any(line.split()[:2] == row[:2] and line.rstrip().endswith(row[-1]) for line in lines), row


def test_an_unknown_team_is_one_short_line_with_the_closest_names(capsys) -> None:
    assert main(["play", "mmdrr", "idle", "--cycles", "5"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and len(err) < 200
    assert "unknown team 'mmdrr'; did you mean mmdr" in err and "`soccer-sim teams` lists the" in err
    assert "possession" not in err and "statues" not in err  # not the whole list


def test_teams_lists_the_registered_names(capsys) -> None:
    from soccer_sim import available_teams

    assert main(["teams"]) == 0
    out = capsys.readouterr().out
    rows = [line.split("\t") for line in out.splitlines()[2:] if line]
    assert [row[0] for row in rows] == list(available_teams())
    assert ["chaser", "soccer_sim.trivial_teams:ChaserTeam"] in rows


def test_kernel_compilation_shows_kernels_done_of_total_and_seconds(tmp_path: Path) -> None:
    (tmp_path / "tinykernels.py").write_text(TINY_MODULE)
    done = run_python(TINY_KERNELS + """
from experiments.warmup import ensure_cached
if __name__ == "__main__":
    ensure_cached(KERNELS, processes=2)
""", tmp_path, tmp_path / "cache")
    lines = done.stderr.splitlines()
    assert lines[0] == "compiling kernels (first run only)"
    assert any(line.startswith("compiling kernels: 2/2 done, ") and line.endswith(" s") for line in lines), lines
    assert lines[-1].startswith("compiled 2 kernels in ")


def test_compilation_progress_on_a_terminal_is_one_line_kept_up_to_date() -> None:
    from experiments.runner.progress import CountProgress

    class Terminal(io.StringIO):
        def isatty(self) -> bool:
            return True

    screen = Terminal()
    progress = CountProgress(41, "compiling kernels", "done", screen)
    for done in (0, 5, 5, 41):
        progress.show(done)
    progress.close(41)
    text = screen.getvalue()
    assert text.count("\n") == 1 and text.endswith("\n")
    assert text.split("\r")[-1].startswith("compiling kernels: 41/41 done, ")
