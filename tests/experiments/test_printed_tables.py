"""Tables printed on a terminal keep their label columns whole, however narrow the terminal
(a long team path is never cut or folded)."""

from __future__ import annotations


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
