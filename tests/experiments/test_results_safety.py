"""The results store and the commands around it never damage a file: reading changes nothing,
writing never lands on an input, a full disk or an unusable destination is one line on stderr
(checked before any match is played where possible) and never leaves a partial file, a stored
row survives ``kill -9`` in the ``.sqlite`` file itself, failed rows are not replayed, and seeds
a results file cannot hold are refused."""

from __future__ import annotations

import csv
import errno
import hashlib
import os
import shutil
import sqlite3
from pathlib import Path

import pytest

import experiments.results.connections as connections
import experiments.results.store as store_module
from experiments.cli import main
from experiments.results.record import MatchRecord
from experiments.results.store import ResultStore
from experiments.runner.run import MAX_SEED, check_seeds
from experiments.runner.spec import MatchSpec, config_description, config_for, config_hash

QUICK = ["--cycles", "30", "--workers", "1", "--no-progress"]
TEAMS = ["--teams", "idle,chaser", "--games", "2"]


def digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def files_in(directory: Path) -> dict[str, str]:
    """Name -> digest of every file in ``directory`` (what a command must leave as it was)."""
    return {p.name: digest(p) for p in sorted(directory.iterdir()) if p.is_file()}


def error_line(capsys) -> str:
    """The one line a failed command prints on stderr."""
    lines = capsys.readouterr().err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), lines
    return lines[0]


@pytest.fixture(scope="module")
def played(tmp_path_factory) -> Path:
    """A real tournament's results file (idle and chaser, 2 matches of 30 cycles) and its tables."""
    out = tmp_path_factory.mktemp("played") / "t.sqlite"
    assert main(["tournament", *TEAMS, "--out", str(out), *QUICK]) == 0
    return out


@pytest.fixture
def results(played, tmp_path) -> Path:
    copy = tmp_path / "t.sqlite"
    shutil.copyfile(played, copy)
    return copy


def stored(path: Path, records: list[MatchRecord], cycles: int = 30) -> Path:
    """A tournament results file of chaser and idle holding ``records`` (written directly)."""
    config = config_for(cycles)
    params = {"teams": ["chaser", "idle"], "games": 2, "seed": 0, "cycles": cycles}
    with ResultStore.create(path, "tournament", config_hash(config), config_description(config), params) as store:
        for record in records:
            store.add(record)
    return path


# -- writing never lands on an input ------------------------------------------------------
def test_export_never_writes_onto_the_results_file(results, tmp_path, capsys) -> None:
    before = digest(results)
    symlink, hardlink = tmp_path / "link.csv", tmp_path / "hard.csv"
    symlink.symlink_to(results)
    os.link(results, hardlink)
    for option, target in (("--csv", results), ("--parquet", results), ("--csv", symlink), ("--csv", hardlink),
                           ("--csv", Path(f"{results}-wal"))):
        assert main(["results", "export", str(results), option, str(target)]) == 2
        line = error_line(capsys)
        assert f"{option} {target}: would overwrite" in line and "which this command reads" in line
        assert digest(results) == before
    other = tmp_path / "other.sqlite"                               # another results file: never an output
    shutil.copyfile(results, other)
    assert main(["results", "export", str(results), "--csv", str(other)]) == 2
    assert f"--csv {other}: is an SQLite database, never overwritten" in error_line(capsys)
    assert digest(other) == before
    with ResultStore.open(results) as store:
        assert store.count() == 2


def test_export_on_a_full_disk_keeps_the_previous_file(results, tmp_path, capsys, monkeypatch) -> None:
    target = tmp_path / "m.csv"
    target.write_text("previous export\n")

    def full(self, rows):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(csv.DictWriter, "writerows", full)          # after the header is written
    before = set(os.listdir(tmp_path))
    assert main(["results", "export", str(results), "--csv", str(target)]) == 1
    line = error_line(capsys)
    assert f"{target} (No space left on device)" in line
    assert target.read_text() == "previous export\n" and set(os.listdir(tmp_path)) == before
    fresh = tmp_path / "fresh.csv"
    assert main(["results", "export", str(results), "--csv", str(fresh)]) == 1
    assert "No space left" in error_line(capsys) and not fresh.exists()


# -- reading changes nothing --------------------------------------------------------------
def test_reading_an_empty_or_foreign_file_changes_nothing(tmp_path, capsys) -> None:
    empty = tmp_path / "empty.sqlite"
    empty.touch()
    foreign = tmp_path / "people.db"
    db = sqlite3.connect(foreign)
    db.execute("CREATE TABLE people (name TEXT)")
    db.execute("INSERT INTO people VALUES ('ada')")
    db.commit()
    db.close()
    before = files_in(tmp_path)
    for path, what in ((empty, "an empty file"), (foreign, "an SQLite database with tables people")):
        for command in (["results", "show", str(path)],
                        ["results", "export", str(path), "--csv", str(tmp_path / "m.csv")],
                        ["replay", "--results", str(path), "--row", "0", "--out", str(tmp_path / "m.rrd")]):
            assert main(command) == 2
            assert error_line(capsys) == f"error: {path}: not a soccer-sim results file ({what})"
            assert files_in(tmp_path) == before                      # no 4 KB database, no WAL switch, no output
    # A run refuses another program's database before writing anything into it.
    assert main(["tournament", *TEAMS, "--out", str(foreign), *QUICK]) == 2
    assert "not a soccer-sim results file (an SQLite database with tables people); it is left untouched" in \
        error_line(capsys)
    assert files_in(tmp_path) == before
    assert sqlite3.connect(foreign).execute("PRAGMA journal_mode").fetchone() == ("delete",)


def test_reading_a_results_file_opens_it_read_only(results, capsys) -> None:
    before = files_in(results.parent)
    assert main(["results", "show", str(results)]) == 0
    assert main(["results", "export", str(results), "--csv", str(results.with_suffix(".csv"))]) == 0
    capsys.readouterr()
    assert files_in(results.parent) == {**before, "t.csv": digest(results.with_suffix(".csv"))}
    with ResultStore.open(results) as store:                          # mode=ro: works on read-only media
        with pytest.raises(sqlite3.OperationalError, match="readonly"):
            store._db.execute("CREATE TABLE scratch (a)")


def test_a_log_left_by_kill_9_is_read_without_changing_anything(tmp_path, monkeypatch) -> None:
    writer = ResultStore.create(tmp_path / "r.sqlite", "tournament", "abc", "{}", {})
    with monkeypatch.context() as patch:
        # Rows only in the -wal file, as in a file an older version left behind.
        patch.setattr(ResultStore, "_checkpoint", lambda self, mode: None, raising=False)
        for seed in range(3):
            writer.add(MatchRecord("A", "B", seed, "abc", home_goals=1, away_goals=0))
        crashed, locked = tmp_path / "crashed", tmp_path / "locked"
        for directory in (crashed, locked):                          # the files as kill -9 leaves them
            directory.mkdir()
            for suffix in ("", "-wal"):
                shutil.copyfile(f"{tmp_path / 'r.sqlite'}{suffix}", directory / f"r.sqlite{suffix}")
        writer.close()
    # Where the -shm index cannot be made (read-only media), SQLite cannot open the log: the
    # files are read from a private copy. (Simulated: the tests run as root, who may write anywhere.)
    connect, copies = sqlite3.connect, []

    def no_index(database, *args, **kwargs):
        if "locked" in str(database) and "mode=ro" in str(database):
            raise sqlite3.OperationalError("unable to open database file")
        return connect(database, *args, **kwargs)

    monkeypatch.setattr(store_module.sqlite3, "connect", no_index)
    real_copy = connections.private_copy
    monkeypatch.setattr(connections, "private_copy", lambda *a: copies.append(a) or real_copy(*a))
    for directory, copied in ((crashed, 0), (locked, 1)):
        before = {name: value for name, value in files_in(directory).items() if name != "r.sqlite-shm"}
        with ResultStore.open(directory / "r.sqlite") as store:
            assert store.count() == 3                                # immutable would see none of them
        assert len(copies) == copied
        assert {name: value for name, value in files_in(directory).items() if name != "r.sqlite-shm"} == before


def test_the_sqlite_file_alone_holds_every_stored_row(tmp_path) -> None:
    path = tmp_path / "r.sqlite"
    writer = ResultStore.create(path, "tournament", "abc", "{}", {})
    for seed in range(3):
        writer.add(MatchRecord("A", "B", seed, "abc", home_goals=seed, away_goals=0))
    alone = tmp_path / "copy.sqlite"
    shutil.copyfile(path, alone)                                     # only the .sqlite file, writer still open
    with ResultStore.open(alone) as store:
        assert [r.home_goals for r in store.records()] == [0, 1, 2]
    writer.close()
    assert not Path(f"{path}-wal").exists() or Path(f"{path}-wal").stat().st_size == 0


# -- full disks and unusable destinations -------------------------------------------------
def test_a_full_disk_while_storing_is_one_line_and_the_rerun_resumes(tmp_path, capsys, monkeypatch) -> None:
    out = tmp_path / "t.sqlite"
    add = ResultStore.add
    done = []

    def fill_up(self, record):
        if done:
            raise sqlite3.OperationalError("database or disk is full")
        add(self, record)
        done.append(record)

    monkeypatch.setattr(ResultStore, "add", fill_up)
    assert main(["tournament", *TEAMS, "--out", str(out), *QUICK]) == 1
    line = error_line(capsys)
    assert line.startswith(f"error: {out}: cannot store a match (database or disk is full); 1 of the run's 2 "
                           f"matches are stored in {out}") and "re-run the same command to resume" in line
    monkeypatch.undo()
    assert main(["tournament", *TEAMS, "--out", str(out), *QUICK]) == 0
    assert "2 matches in" in capsys.readouterr().out.replace("\n", " ")
    with ResultStore.open(out) as store:
        assert store.count() == 2


def test_tables_on_a_full_disk_keep_the_previous_files(results, tmp_path, capsys, monkeypatch) -> None:
    import experiments.reporting

    tables = tmp_path / "tables"
    run = ["tournament", *TEAMS, "--out", str(results), "--tables", str(tables), *QUICK]
    assert main(run) == 0                                            # every match stored: nothing is played
    capsys.readouterr()
    before = files_in(tables)
    assert {"league.csv", "pairwise.csv", "tournament.png"} <= set(before)

    def full(path, header, rows):
        Path(path).write_text("rank,te")
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(experiments.reporting, "write_csv", full)
    assert main(run) == 1
    line = error_line(capsys)
    assert f"{tables / 'league.csv'} (No space left on device)" in line
    assert f"the 2 matches are stored in {results}" in line and "results show" in line
    assert files_in(tables) == before                                # no 0-byte or partial table, no temp file
    fresh = tmp_path / "fresh"
    assert main(["results", "show", str(results), "--tables", str(fresh)]) == 1
    assert "No space left on device" in error_line(capsys)
    assert list(fresh.iterdir()) == []


def test_unusable_tables_directories_are_refused_before_any_match(tmp_path, capsys) -> None:
    a_file = tmp_path / "notes.txt"
    a_file.write_text("notes")
    out = tmp_path / "t.sqlite"
    for tables in (a_file, a_file / "sub"):
        assert main(["tournament", *TEAMS, "--out", str(out), "--tables", str(tables), *QUICK]) == 2
        assert f"--tables {tables}: " in error_line(capsys)
        assert not out.exists()                                      # refused before the first match
    stored(out, [])
    assert main(["results", "show", str(out), "--tables", str(a_file)]) == 2
    assert error_line(capsys) == f"error: --tables {a_file}: is a file, not a directory"
    assert a_file.read_text() == "notes"


# -- replay of failed rows, seeds -----------------------------------------------------------
def test_failed_rows_are_not_replayed(tmp_path, capsys) -> None:
    digest_ = config_hash(config_for(30))
    path = stored(tmp_path / "t.sqlite", [
        MatchRecord("chaser", "idle", 0, digest_, home_goals=0, away_goals=0, cycles=30),
        MatchRecord("chaser", "idle", 1, digest_, error="MatchTimeout: match exceeded its time budget of 600 s",
                    forfeit=1),
        MatchRecord("idle", "chaser", 0, digest_, error="TeamError: team 'idle': act() raised RuntimeError: boom",
                    forfeit=0),
        MatchRecord("idle", "chaser", 1, digest_, error="worker died (exit code -9)"),
    ])
    out = tmp_path / "m.rrd"
    expected = {1: "chaser v idle, seed 1, was forfeited by idle: MatchTimeout: match exceeded its time budget",
                2: "idle v chaser, seed 0, was forfeited by idle: TeamError: team 'idle': act() raised",
                3: "idle v chaser, seed 1, was not played to its end (no team blamed): worker died"}
    for row, failure in expected.items():
        assert main(["replay", "--results", str(path), "--row", str(row), "--out", str(out)]) == 2
        line = error_line(capsys)
        assert line.startswith(f"error: --row {row}: {failure}") and "only a match played to its end" in line
        assert not out.exists()


def test_seeds_a_results_file_cannot_store_are_refused(tmp_path, capsys) -> None:
    out = tmp_path / "t.sqlite"
    assert main(["tournament", "--teams", "idle,chaser", "--games", "4", "--seed", str(MAX_SEED), "--out", str(out),
                 *QUICK]) == 2
    assert error_line(capsys).startswith(f"error: --seed must be between 0 and {MAX_SEED - 1} for this run")
    assert not out.exists()
    with pytest.raises(SystemExit) as usage:      # beyond any results file: refused by the option's range
        main(["tournament", "--teams", "idle,chaser", "--games", "2", "--seed", str(2**64), "--out", str(out), *QUICK])
    assert usage.value.code == 2
    assert error_line(capsys).startswith(f"error: argument --seed: must be a non-negative integer up to {MAX_SEED}")
    assert not out.exists()
    check_seeds([MatchSpec("a", "b", MAX_SEED - 1), MatchSpec("b", "a", MAX_SEED)])       # the largest fit
    with pytest.raises(ValueError, match=f"between 0 and {MAX_SEED - 2} "):
        check_seeds([MatchSpec("a", "b", MAX_SEED - 1), MatchSpec("a", "b", MAX_SEED + 1)])


def test_the_runner_names_its_parameters_and_the_command_line_its_options(tmp_path, capsys) -> None:
    from experiments.errors import ExperimentError, ParameterError
    from experiments.runner import run_matches

    out = tmp_path / "t.sqlite"
    calls = {"seed": dict(specs=[MatchSpec("idle", "chaser", MAX_SEED + 1, 30)]),
             "record_every": dict(specs=[MatchSpec("idle", "chaser", 0, 30)], record_dir=tmp_path / "r", record_every=0)}
    for parameter, call in calls.items():
        with pytest.raises(ParameterError) as caught:
            run_matches(call.pop("specs"), out, "tournament", {}, cycles=30, progress=False, **call)
        assert caught.value.parameter == parameter and str(caught.value).startswith(f"{parameter} ")
        assert "--" not in str(caught.value) and isinstance(caught.value, (ValueError, ExperimentError))
        assert not out.exists()
    (tmp_path / "file").write_text("")
    assert main(["tournament", "--teams", "idle,chaser", "--record-dir", str(tmp_path / "file" / "r"),
                 "--out", str(out), *QUICK]) == 2
    assert error_line(capsys).startswith(f"error: --record-dir {tmp_path / 'file' / 'r'}: cannot create it")


# -- the tournament writes what its help says ----------------------------------------------
def test_tournament_writes_the_markdown_tables_its_help_promises(played, capsys) -> None:
    with pytest.raises(SystemExit):
        main(["tournament", "--help"])
    assert "Markdown" in capsys.readouterr().out
    markdown = (played.with_name("t-tables") / "tournament.md").read_text()
    assert markdown.startswith("Tournament: 2 matches, seeds from 0, cycles per match: 30.")
    assert "**league: 2 teams, 2 matches**" in markdown and "| 1 | " in markdown
    assert "| idle |  | " in markdown and "| chaser | " in markdown


def test_a_damaged_row_is_one_error_naming_the_file(tmp_path, capsys):
    import sqlite3

    from experiments.cli import main

    out = tmp_path / "r.sqlite"
    assert main(["tournament", "--teams", "chaser,idle", "--games", "2", "--cycles", "50", "--workers", "1",
                 "--out", str(out), "--tables", str(tmp_path / "t"), "--no-progress"]) == 0
    with sqlite3.connect(out) as db:               # a stored row's statistics no longer JSON
        db.execute("UPDATE matches SET home_stats = '{x' WHERE seed = (SELECT MIN(seed) FROM matches)")
    db.close()
    capsys.readouterr()
    before = out.read_bytes()
    assert main(["results", "show", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and f"{out}: damaged results file" in err
    assert out.read_bytes() == before
