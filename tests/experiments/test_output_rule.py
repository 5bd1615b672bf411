"""The one rule for every file a command writes (:mod:`experiments.results.files`): a
destination that is the command's own input (by identity, or inside an imported directory),
a special file, an empty name or an unwritable place is refused before any work; files are
written whole or not at all, and only a regular file (or nothing) is replaced; a failed write
(a full disk, standard output included) is one line and exit status 1 in every command."""

from __future__ import annotations

import hashlib
import os
import sqlite3
import stat
import subprocess
import sys
from pathlib import Path

import pytest

from experiments.cli import main
from experiments.results.files import atomic_output, directory_problem, file_problem
from experiments.results.record import MatchRecord
from experiments.results.store import ResultsError, ResultStore
from tests.experiments.special_files import (command, device_node, environment, fifo, is_char_device, is_fifo,
                                             one_error_line, run_on_small_disk)
from tests.experiments.test_results_safety import stored
from tests.formations.agent2d_samples import dt_v2_text

def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def error(capsys) -> str:
    return one_error_line(capsys.readouterr().err)


def played(seeds: int) -> list[MatchRecord]:
    """``seeds`` played matches of chaser and idle, of the configuration :func:`stored` files have."""
    from experiments.runner.spec import config_for, config_hash

    return [MatchRecord("chaser", "idle", seed, config_hash(config_for(30)), home_goals=seed % 3, away_goals=0,
                        cycles=30) for seed in range(seeds)]


@pytest.fixture
def results(tmp_path) -> Path:
    """A tournament results file of two played matches."""
    return stored(tmp_path / "r.sqlite", played(2))


@pytest.fixture
def helios_file(tmp_path) -> Path:
    path = tmp_path / "hg.conf"
    path.write_text(dt_v2_text())
    return path


# -- a command's own input is never its output ----------------------------------------------
def test_formation_import_refuses_to_write_onto_its_input(helios_file, capsys) -> None:
    before = digest(helios_file)
    assert main(["formation", "import", "helios", str(helios_file), str(helios_file)]) == 2
    assert "which this command reads" in error(capsys)
    assert digest(helios_file) == before


def test_formation_import_refuses_to_write_into_the_imported_directory(tmp_path, capsys) -> None:
    directory = tmp_path / "formations-dt"
    directory.mkdir()
    normal = directory / "normal-formation.conf"
    normal.write_text(dt_v2_text())
    before = digest(normal)
    assert main(["formation", "import", "helios", str(directory), str(normal)]) == 2
    assert f"would write into {directory}" in error(capsys)
    assert main(["formation", "import", "helios", str(directory), str(directory)]) == 2  # DIR/NAME.json
    assert f"would write into {directory}" in error(capsys)
    assert digest(normal) == before and sorted(p.name for p in directory.iterdir()) == [normal.name]


def test_formation_show_refuses_to_draw_onto_the_formation_it_reads(tmp_path, capsys) -> None:
    formation = tmp_path / "fs.png"                  # a formation file, whatever its name
    assert main(["formation", "import", "helios", _helios(tmp_path), str(formation)]) == 0
    before = digest(formation)
    capsys.readouterr()
    assert main(["formation", "show", str(formation), "--out", str(formation)]) == 2
    assert "which this command reads" in error(capsys)
    assert digest(formation) == before


def test_a_hard_link_to_the_input_is_the_input(helios_file, tmp_path) -> None:
    link = tmp_path / "other-name.json"
    os.link(helios_file, link)
    assert "which this command reads" in file_problem(link, inputs=[helios_file])


def test_a_damaged_results_file_is_refused_without_a_change(tmp_path) -> None:
    path = stored(tmp_path / "r.sqlite", played(40))
    with sqlite3.connect(path) as db:                    # as another tool would leave it
        db.execute("PRAGMA journal_mode = DELETE")
        root, size = db.execute("SELECT rootpage FROM sqlite_master WHERE name = 'matches'").fetchone()[0], \
            db.execute("PRAGMA page_size").fetchone()[0]
    data = bytearray(path.read_bytes())
    data[(root - 1) * size:root * size] = b"\xff" * size
    path.write_bytes(bytes(data))
    before = digest(path)
    with ResultStore.open(path) as store:
        config_hash = store.config_hash
    with pytest.raises(ResultsError, match="damaged results file"):
        ResultStore.create(path, "tournament", config_hash, "{}", {})
    assert digest(path) == before and sorted(p.name for p in tmp_path.iterdir()) == ["r.sqlite"]


def test_tables_that_are_the_results_file_are_refused_before_any_match(tmp_path, capsys) -> None:
    out = tmp_path / "X"
    assert main(["tournament", "--teams", "idle,chaser", "--games", "2", "--cycles", "20", "--workers", "1",
                 "--no-progress", "--out", str(out), "--tables", str(out)]) == 2
    assert "a file this command uses" in error(capsys)
    assert not out.exists()


# -- special files are never replaced, and never opened ---------------------------------------
@pytest.mark.parametrize("kind", ["fifo", "full", "null"])
def test_results_export_never_replaces_a_special_file(results, tmp_path, kind, capsys) -> None:
    target = fifo(tmp_path) if kind == "fifo" else device_node(tmp_path, kind)
    assert main(["results", "export", str(results), "--csv", str(target)]) == 2
    assert "not a regular file" in error(capsys)
    assert is_fifo(target) if kind == "fifo" else is_char_device(target)


@pytest.mark.parametrize("option,name", [("--record", "m.rrd"), ("--rcg", "m.rcg")])
def test_play_never_replaces_a_special_file(tmp_path, option, name, capsys) -> None:
    target = fifo(tmp_path, name)
    assert main(["play", "idle", "chaser", "--cycles", "5", option, str(target)]) == 2
    assert "not a regular file (a FIFO)" in error(capsys)
    assert is_fifo(target)


def test_replay_out_never_replaces_a_special_file(results, tmp_path, capsys) -> None:
    target = fifo(tmp_path, "m.rrd")
    assert main(["replay", "--results", str(results), "--row", "0", "--out", str(target)]) == 2
    assert "not a regular file (a FIFO)" in error(capsys)
    assert is_fifo(target)


def test_a_special_file_inside_the_tables_is_never_replaced(results, tmp_path) -> None:
    from experiments.commands.tournament import report

    tables = tmp_path / "tables"
    tables.mkdir()
    target = fifo(tables, "league.csv")
    with ResultStore.open(results) as store:
        records, params = store.records(), store.params
    with pytest.raises(OSError, match="not a regular file"):
        report(records, params, tables)
    assert is_fifo(target)


def test_atomic_output_renames_only_over_a_regular_file(tmp_path) -> None:
    target = tmp_path / "out.csv"
    with pytest.raises(OSError, match="not a regular file"):
        with atomic_output(target) as temporary:
            temporary.write_text("new")
            os.mkfifo(target)                  # a FIFO appears while the file is written
    assert is_fifo(target) and [p.name for p in tmp_path.iterdir()] == ["out.csv"]


# -- names that are no file, standard output -------------------------------------------------
@pytest.mark.parametrize("args", [
    ["results", "export", "{results}", "--csv", ""],
    ["results", "export", "{results}", "--parquet", ""],
    ["tournament", "--teams", "idle,chaser", "--games", "2", "--cycles", "20", "--out", ""],
    ["replay", "{replay}", "--png", ""],
    ["formation", "show", "4-3-3", "--out", ""],
])
def test_an_empty_file_name_is_one_line(results, tmp_path, args, capsys, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    replay = tmp_path / "m.rrd"
    replay.write_bytes(b"")
    args = [a.format(results=results, replay=replay) for a in args]
    assert main(args) == 2
    assert "an empty file name" in error(capsys)
    assert not any(p.name.startswith(".") for p in tmp_path.iterdir())


def test_replay_png_refuses_an_existing_directory(tmp_path, capsys) -> None:
    replay = tmp_path / "m.rrd"
    replay.write_bytes(b"")
    folder = tmp_path / "pictures"
    folder.mkdir()
    assert main(["replay", str(replay), "--png", str(folder)]) == 2
    assert "is a directory" in error(capsys)
    assert not (tmp_path / "pictures.png").exists() and not list(folder.iterdir())


def test_csv_dash_is_standard_output(results, tmp_path, capsys, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    assert main(["results", "export", str(results), "--csv", "-"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines()[0].startswith("home,away,seed") and len(out.splitlines()) == 3
    assert not (tmp_path / "-").exists()


@pytest.mark.parametrize("target", ["-", "/dev/stdout"])
def test_an_export_to_a_pipe_closed_early_ends_quietly(tmp_path, target) -> None:
    path = stored(tmp_path / "many.sqlite", played(400))    # more than a pipe holds (64 KiB)
    process = subprocess.Popen(command("results", "export", str(path), "--csv", target), cwd=tmp_path,
                               env=environment(), stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert process.stdout.readline().startswith(b"home,away")
    process.stdout.close()                               # `| head -1`
    try:
        status = process.wait(timeout=120)
    finally:
        process.kill()
    assert status == 0 and process.stderr.read() == b""


# -- unwritable places and full disks ----------------------------------------------------------
def test_an_unwritable_directory_is_one_line_before_any_work(results, tmp_path, capsys) -> None:
    if os.geteuid() != 0:
        pytest.skip("needs root to drop to another user for the check")
    closed = tmp_path / "closed"
    closed.mkdir(mode=0o555)
    shut = tmp_path / "shut"
    shut.mkdir(mode=0o000)
    os.chmod(tmp_path, 0o755)
    os.setegid(65534)
    os.seteuid(65534)
    try:
        problems = [file_problem(closed / "x.csv"), file_problem(shut / "x.csv"), directory_problem(closed / "t"),
                    directory_problem(shut / "t")]
    finally:
        os.seteuid(0)
        os.setegid(0)
    assert all(problem and "Permission denied" in problem for problem in problems), problems


def test_a_read_only_file_system_is_named_so(tmp_path) -> None:
    run = run_on_small_disk(tmp_path, ["tournament", "--teams", "idle,chaser", "--games", "2", "--cycles", "20",
                                       "--out", "disk/r.sqlite", "--tables", "t"], read_only=True)
    assert run.returncode == 2
    assert "Read-only file system" in one_error_line(run.stderr)


@pytest.mark.parametrize("args", [
    ["play", "idle", "chaser", "--cycles", "300", "--rcg", "disk/m.rcg"],
    ["play", "idle", "chaser", "--cycles", "300", "--record", "disk/m.rrd"],
    pytest.param(["formation", "show", "4-3-3", "--out", "disk/picture.png"], marks=pytest.mark.slow),
    pytest.param(["experiment", "incremental", "--n", "40", "--trials", "1", "--lambdas", "0,1", "--out", "disk/study"],
                 marks=pytest.mark.slow),
], ids=["rcg", "record", "formation-show", "incremental"])
def test_a_full_disk_is_one_line_exit_1_and_no_partial_file(tmp_path, args) -> None:
    run = run_on_small_disk(tmp_path, args)
    assert run.returncode == 1, run.stderr
    assert "No space left on device" in one_error_line(run.stderr)
    assert not [name for name in run.left if name.endswith((".rcg", ".rrd", ".png"))], run.left


@pytest.mark.slow
def test_a_full_disk_under_a_replay_picture_is_exit_1(tmp_path) -> None:
    assert main(["play", "idle", "chaser", "--cycles", "20", "--record", str(tmp_path / "m.rrd")]) == 0
    run = run_on_small_disk(tmp_path, ["replay", "m.rrd", "--png", "disk/field.png"])
    assert run.returncode == 1 and "No space left on device" in one_error_line(run.stderr)
    assert run.left == []


def test_a_full_standard_output_is_one_line_exit_1(tmp_path) -> None:
    full = device_node(tmp_path, "full")
    with open(full, "w") as stdout:
        done = subprocess.run(command("formation", "validate", "4-3-3"), cwd=tmp_path, env=environment(),
                              stdout=stdout, stderr=subprocess.PIPE, text=True, timeout=300)
    assert done.returncode == 1
    assert "cannot write standard output (No space left on device)" in one_error_line(done.stderr)


def _helios(tmp_path: Path) -> str:
    path = tmp_path / "source.conf"
    path.write_text(dt_v2_text())
    return str(path)


def test_a_fifo_inside_the_tables_directory_is_refused_before_any_match(tmp_path) -> None:
    """The tables are written into --tables; a FIFO there (where a table would go) is refused up
    front, before a match is played, and stays a FIFO."""
    tables = tmp_path / "tables"
    tables.mkdir()
    fifo = tables / "league.csv"
    os.mkfifo(fifo)
    run = subprocess.run([sys.executable, "-m", "experiments.cli", "tournament", "--teams", "idle,chaser",
                          "--games", "1", "--cycles", "5", "--out", str(tmp_path / "r.sqlite"),
                          "--tables", str(tables)], capture_output=True, text=True, timeout=120, cwd=tmp_path,
                         env={**os.environ, "PYTHONPATH": str(Path(__file__).resolve().parents[2])})
    assert run.returncode == 2, run.stderr
    assert "league.csv" in run.stderr and "not a regular file (a FIFO)" in run.stderr
    assert stat.S_ISFIFO(os.stat(fifo).st_mode)
    assert not (tmp_path / "r.sqlite").exists()  # refused before any match was stored
