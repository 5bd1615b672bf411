"""Output a script can read: tables and listings printed plain when piped, --json where a
command prints tables, and a reader that goes away (``| head``) is not an error."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from experiments.cli import main

ROOT = Path(__file__).resolve().parents[2]
BOX = set("┏━┳┓┃┡╇┩│└┴┘")


@pytest.fixture(scope="module")
def stored(tmp_path_factory) -> Path:
    """A small tournament's results file."""
    out = tmp_path_factory.mktemp("piped") / "t.sqlite"
    assert main(["tournament", "--teams", "chaser,idle", "--games", "2", "--cycles", "100", "--workers", "1",
                 "--out", str(out), "--tables", str(out.parent / "tables"), "--no-progress"]) == 0
    return out


def test_the_scenario_listing_is_plain_text_when_piped(capsys):
    assert main(["scenarios"]) == 0
    out = capsys.readouterr().out
    assert not BOX & set(out)
    lines = out.splitlines()
    assert lines[1].split("\t")[:3] == ["name", "home v away", "start"]
    rows = {line.split("\t")[0]: line.split("\t") for line in lines[2:] if "\t" in line}
    assert rows["full-match"][1] == "11 (GK) v 11 (GK)" and rows["full-match"][4] == "6000"
    assert any(line.startswith("empty-goal: ") for line in lines)  # descriptions, one a line


def test_the_scenario_listing_as_json(capsys):
    assert main(["scenarios", "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    names = [row[0] for row in document["tables"][0]["rows"]]
    assert "full-match" in names and "kick-off" in names
    assert any(note.startswith("corner: ") for note in document["notes"])


@pytest.mark.parametrize("command", [["tournament", "--teams", "chaser,idle", "--games", "2", "--cycles", "100",
                                      "--workers", "1", "--no-progress"], ["results", "show"]])
def test_tournament_and_results_show_print_json(command, stored, capsys):
    argv = [*command, "--out", str(stored), "--tables", str(stored.parent / "tables")] \
        if command[0] == "tournament" else [*command, str(stored)]
    assert main([*argv, "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    league = document["tables"][0]
    assert league["columns"][:2] == ["#", "team"]
    assert [row[1] for row in league["rows"]] == ["chaser", "idle"]


@pytest.mark.parametrize("command", [["results", "show"], ["tournament", "--teams", "chaser,idle", "--games", "2",
                                                            "--cycles", "100", "--workers", "1", "--no-progress"]])
def test_a_reader_that_goes_away_is_not_an_error(command, stored):
    argv = [*command, str(stored)] if command[0] == "results" else \
        [*command, "--out", str(stored), "--tables", str(stored.parent / "tables")]
    with subprocess.Popen([sys.executable, "-m", "experiments.cli", *argv], cwd=ROOT, stdout=subprocess.PIPE,
                          stderr=subprocess.PIPE) as process:
        process.stdout.readline()
        process.stdout.close()                   # as `| head -1` does
        err = process.stderr.read().decode()
        status = process.wait(timeout=120)
    assert status == 0 and "error" not in err, (status, err)


def test_table_files_are_written_whole_or_not_at_all(tmp_path, monkeypatch):
    from experiments import reporting

    target = tmp_path / "t.csv"
    target.write_text("previous\n")

    def failing_rows():
        yield ["a", 1]
        raise OSError(28, "No space left on device")

    with pytest.raises(OSError):
        reporting.write_csv(target, ["x", "y"], failing_rows())
    assert target.read_text() == "previous\n"           # untouched, no partial file
    assert [p.name for p in tmp_path.iterdir()] == ["t.csv"]
    reporting.write_csv(target, ["x", "y"], [["a", 1]])
    assert target.read_text().splitlines() == ["x,y", "a,1"]
