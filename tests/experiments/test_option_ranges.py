"""Every numeric option of every command has a range (experiments.limits.OPTION_RANGES), checked
while the arguments are parsed, before any work: one line naming the option and the range."""

from __future__ import annotations

import argparse
import re
from pathlib import Path

import pytest

from experiments.cli import build_parser, main
from experiments.lazy_parser import LazyParser
from experiments.limits import MAX_SEED, OPTION_RANGES, NumberRange, parse_list

DOCS = Path(__file__).resolve().parents[2] / "docs" / "limits.md"

CHECKED_AGAINST_INPUT = {("replay", "--cycle"), ("replay", "--row"), ("formation show", "--ball")}
"""Options whose range is that of their input (a replay's cycles, a results file's rows, the
field), checked against it by their command."""


def numeric_options() -> list[tuple[str, str, object]]:
    """(command, option, argparse type) of every option of every command that parses numbers."""
    found = []

    def walk(parser: argparse.ArgumentParser, path: list[str]) -> None:
        if isinstance(parser, LazyParser):
            parser.populate()
        for action in parser._actions:
            if isinstance(action, argparse._SubParsersAction):
                for name, sub in action.choices.items():
                    walk(sub, path + [name])
            elif action.option_strings and action.type is not None:
                found.append((" ".join(path), action.option_strings[0], action.type))

    walk(build_parser(), [])
    return found


def test_every_numeric_option_takes_its_type_from_the_table() -> None:
    options = numeric_options()
    assert len(options) > 60
    untyped = [(command, option) for command, option, kind in options
               if kind in (int, float) and (command, option) not in CHECKED_AGAINST_INPUT]
    assert untyped == []
    ranged = [(command, option, kind.__name__) for command, option, kind in options
              if getattr(kind, "__module__", "") == "experiments.limits"]
    assert len(ranged) > 60
    assert all(name.replace("_", "-") in OPTION_RANGES for _, _, name in ranged)


def usage_error(argv: list[str], capsys) -> str:
    """The one stderr line of a command refused while parsing (exit status 2)."""
    with pytest.raises(SystemExit) as usage:
        main(argv)
    assert usage.value.code == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    lines = captured.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: argument ")
    return lines[0]


@pytest.mark.parametrize("argv, expected", [
    (["play", "--cycles", "99999999999"], "--cycles: must be a positive integer up to 1000000 (cycles), got 99999999999"),
    (["play", "--match-timeout", "1e308"], "--match-timeout: must be a number in [1, 604800] (seconds), got 1e308"),
    (["play", "--match-timeout", "1e-6"], "--match-timeout: must be a number in [1, 604800] (seconds), got 1e-6"),
    (["play", "--match-timeout", "nan"], "--match-timeout: must be a number in [1, 604800] (seconds), got nan"),
    (["play", "--seed", "-1"], "--seed: must be a non-negative integer up to 9223372036854775807 (seed), got -1"),
    (["tournament", "--games", "1000000000"],
     "--games: must be a positive integer up to 10000 (matches per pairing or team), got 1000000000"),
    (["tournament", "--workers", "5000"], "--workers: must be a positive integer up to 256 (processes), got 5000"),
    (["tournament", "--match-timeout", "1e308"], "--match-timeout: must be a number in [1, 604800]"),
    (["tournament", "--record-every", "0"], "--record-every: must be a positive integer up to 1000000"),
    (["experiment", "case-study", "--cycles", "1e3"], "--cycles: must be a positive integer up to 1000000 (cycles), got 1e3"),
    (["experiment", "penalty-shot", "--robots", "12"], "--robots: must be a positive integer up to 11 (robots), got 12"),
    (["experiment", "penalty-shot", "--limit", "99999999999"], "--limit: must be a positive integer up to 1000000"),
    (["experiment", "assigners", "--league-games", "0"], "--league-games: must be a positive integer up to 10000"),
    (["experiment", "distributed", "--seed", "-1"], "--seed: must be a non-negative integer up to 9223372036854775807"),
    (["experiment", "incremental", "--seed", "-1"], "--seed: must be a non-negative integer up to 9223372036854775807"),
    (["bench", "formation", "--seed", "-1"], "--seed: must be a non-negative integer up to 9223372036854775807"),
    (["bench", "formation", "--queries", "10000000000"], "--queries: must be a positive integer up to 10000000"),
    (["bench", "match", "--top", "-5"], "--top: must be a positive integer up to 10000 (entries), got -5"),
    (["bench", "assignment", "--time-limit", "inf"], "--time-limit: must be a positive number up to 86400 (seconds)"),
    (["bench", "assignment", "--sizes", "10,1000000"],
     "--sizes: each value must be a positive integer up to 100000 (robots), got 1000000"),
    (["bench", "assignment", "--quality-instances", "-1"], "--quality-instances: must be a non-negative integer"),
    (["bench", "env", "--envs", "1000"], "--envs: must be a positive integer up to 256 (environments), got 1000"),
    (["bench", "roles", "--players", "11"], "--players: must be a positive integer up to 10 (outfield players), got 11"),
    (["bench", "soccer", "--workers", "0"], "--workers: must be a positive integer up to 256 (processes), got 0"),
    (["bench", "startup", "--seed", str(MAX_SEED + 1)], "--seed: must be a non-negative integer up to 9223372036854775807"),
])
def test_numbers_out_of_range_are_one_line_naming_the_option_and_range(argv, expected, capsys) -> None:
    assert usage_error(argv, capsys).startswith(f"error: argument {expected}")


@pytest.mark.parametrize("name", sorted(OPTION_RANGES))
def test_each_range_takes_its_bounds_and_refuses_beyond_them(name) -> None:
    limits = OPTION_RANGES[name]
    high = limits.parse(str(limits.high))
    assert high == limits.high
    with pytest.raises(ValueError, match=re.escape(f"must be {limits.describe()}, got ")):
        limits.parse(str(limits.high + 1 if limits.integer else limits.high * 2))
    if limits.low_open:
        with pytest.raises(ValueError):
            limits.parse(str(limits.low))
    else:
        assert limits.parse(str(limits.low)) == limits.low
        with pytest.raises(ValueError):
            limits.parse(str(limits.low - 1))
    for junk in ("nan", "inf", "-inf", "x", "", "1e999"):
        with pytest.raises(ValueError):
            limits.parse(junk)


def test_a_list_names_the_value_out_of_range() -> None:
    assert parse_list("2, 10,,", "grid-sizes") == [2, 10]
    assert parse_list("", "grid-sizes") == []
    with pytest.raises(ValueError, match="^--etsp-sizes: each value must be an integer from 2 to 100000 .*got 1$"):
        parse_list("5,1", "etsp-sizes", "--etsp-sizes")


def test_the_run_line_names_the_worker_processes_really_used(tmp_path, capsys) -> None:
    """--workers 50 for two matches runs two processes, and the run line says two."""
    out = tmp_path / "t.sqlite"
    assert main(["tournament", "--teams", "idle,chaser", "--games", "2", "--cycles", "5", "--workers", "50",
                 "--out", str(out), "--no-progress"]) == 0
    printed = capsys.readouterr().out
    assert "on 2 worker(s)" in printed and "on 50 worker(s)" not in printed


def test_docs_list_every_range() -> None:
    """docs/limits.md has a row for every entry of the table, with its bounds and unit."""
    text = DOCS.read_text()
    for name, limits in OPTION_RANGES.items():
        row = f"| `{name}` |"
        assert row in text, name
        line = next(line for line in text.splitlines() if line.startswith(row))
        assert _bound(limits, limits.low) in line and _bound(limits, limits.high) in line and limits.unit in line, line


def _bound(limits: NumberRange, value: float) -> str:
    return f"{value:,}" if limits.integer else f"{value:,g}"


def test_penalty_shot_robots_are_at_most_a_side():
    from soccer_sim.scenarios import MAX_PLAYERS

    assert OPTION_RANGES["robots"].high == MAX_PLAYERS
