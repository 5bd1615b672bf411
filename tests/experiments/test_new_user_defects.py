"""Small defects a new user met (issue 12), each checked where the user meets it: a misspelt
TeamCommand field, `formation show --out DIR`, a team path that cannot be imported, and long
team names in the printed tables."""

from __future__ import annotations

import numpy as np
import pytest

from experiments.cli import main
from soccer_sim import TeamCommand


def test_a_misspelt_command_field_is_an_error() -> None:
    command = TeamCommand(dash=np.zeros((11, 2)), kick=np.zeros((11, 2)))
    command.catch = True  # a real field
    with pytest.raises(AttributeError, match="kik"):
        command.kik = np.zeros((11, 2))


def test_formation_show_says_the_file_it_wrote(tmp_path, capsys) -> None:
    assert main(["formation", "show", "4-3-3", "--out", str(tmp_path / "picture")]) == 0
    assert f"wrote {tmp_path / 'picture.png'}" in capsys.readouterr().out
    assert (tmp_path / "picture.png").is_file() and not (tmp_path / "picture").exists()
    folder = tmp_path / "figures"
    folder.mkdir()
    assert main(["formation", "show", "4-3-3", "--out", str(folder)]) == 0
    written = capsys.readouterr().out.split("wrote ", 1)[1].split()[0]
    assert written.startswith(str(folder) + "/") and written.endswith(".png")
    assert (folder / written.rsplit("/", 1)[1]).is_file()


def test_an_unimportable_team_path_says_how_to_make_it_importable(tmp_path, capsys) -> None:
    assert main(["tournament", "--teams", "chaser,nowhere_pkg.teams:Mine", "--out", str(tmp_path / "t.sqlite"),
                 "--no-progress"]) == 2
    err = capsys.readouterr().err
    assert "cannot import module 'nowhere_pkg.teams'" in err and "PYTHONPATH" in err and "Traceback" not in err


def test_long_team_names_are_printed_whole(capsys) -> None:
    from rich.console import Console

    from experiments.reporting import Table

    name = "examples.scripted_team:ScriptedTeam"
    table = Table("league", ["#", "team", "games", "mean GD (SE)"], labels=2)
    table.rows.append(["1", name, "4", "+1.00 (0.50)"])
    table.print(Console(width=40, file=None, force_terminal=True))
    printed = capsys.readouterr().out
    cells = "".join(line.split("│")[2].strip() for line in printed.splitlines() if line.count("│") > 2)
    assert name in cells
