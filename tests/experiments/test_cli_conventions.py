"""The conventions every `soccer-sim` command follows: one error line on stderr; exit status 2
for bad input, 1 for a failed run, 130 after Ctrl-C; tables that a script can read when stdout
is not a terminal; ``--json``; and no files written by default where a user does not expect
them."""

from __future__ import annotations

import argparse
import json

import pytest

from experiments.cli import main
from experiments.commands.errors import TRACEBACK_VARIABLE, CommandParser
from experiments.reporting import Table

BOX = set("│┃━─┏┓┗┛╭╮╰╯┡┩")
"""Characters rich draws a table with."""


def one_error_line(err: str) -> str:
    """The single line on stderr (asserting there is exactly one, starting with 'error: ')."""
    assert err.count("\n") == 1 and err.startswith("error: "), err
    assert "Traceback" not in err
    return err.strip()


@pytest.fixture
def in_tmp(tmp_path, monkeypatch):
    """Run in an empty directory, so that stray output files show up."""
    monkeypatch.chdir(tmp_path)
    return tmp_path


# ----------------------------------------------------------------------- exit status 2 for bad input
def test_formation_bad_input_exits_2_like_every_command(tmp_path, capsys):
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "soccer-sim-formation", "roles": []}')
    assert main(["formation", "validate", str(bad)]) == 2
    assert str(bad) in one_error_line(capsys.readouterr().err)
    assert main(["formation", "show", str(bad), "--out", str(tmp_path / "x.png")]) == 2
    one_error_line(capsys.readouterr().err)
    assert main(["formation", "import", "helios", str(bad), str(tmp_path / "out.json")]) == 2
    one_error_line(capsys.readouterr().err)
    assert not (tmp_path / "x.png").exists() and not (tmp_path / "out.json").exists()


def test_a_failed_symmetry_check_exits_1(tmp_path, capsys):
    from formations.builtin import builtin_path

    document = json.loads(builtin_path("4-3-3").read_text())
    x, y = document["formations"]["normal"]["samples"][1]["positions"]["2"]
    document["formations"]["normal"]["samples"][1]["positions"]["2"] = [x, y + 3.0]  # off its partner's mirror
    path = tmp_path / "asym.json"
    path.write_text(json.dumps(document))
    assert main(["formation", "validate", str(path)]) == 0
    capsys.readouterr()
    assert main(["formation", "validate", str(path), "--require-symmetry"]) == 1
    assert "not mirror-symmetric" in one_error_line(capsys.readouterr().err)


# ----------------------------------------------------------------------- errors on stderr, one line
@pytest.mark.parametrize("argv, words", [
    (["experiment", "assigners", "--part", "claims", "--assigners", "nobody", "--workers", "1"], "unknown team 'nobody'"),
    (["experiment", "assigners", "--part", "league", "--league", "", "--workers", "1"], "--league"),
    (["bench", "lazy-assignment", "--sizes", "ten"], "--sizes"),
    (["bench", "formation", "--set", "5-5-0"], "5-5-0"),
    (["bench", "assignment", "--repeats", "0"], "--repeats"),
    (["experiment", "distributed", "--grid-sizes", "50," + "x" * 100], "--grid-sizes"),
])
def test_errors_are_one_line_on_stderr_and_nothing_on_stdout(argv, words, capsys, in_tmp):
    assert exit_status(argv) == 2
    captured = capsys.readouterr()
    assert words in one_error_line(captured.err)
    assert captured.out == ""


def test_case_study_names_the_empty_opponents_not_the_baseline(capsys, in_tmp):
    assert main(["experiment", "case-study", "--teams", "static", "--opponents", "", "--no-progress"]) == 2
    line = one_error_line(capsys.readouterr().err)
    assert "--opponents" in line and "--baseline" not in line
    assert list(in_tmp.iterdir()) == []


def test_a_study_that_finds_nothing_fails_in_one_line(capsys):
    # degree 1 never joins the corners of 6 robots: no route at all, a failed run (not a traceback)
    assert main(["experiment", "incremental", "--n", "6", "--degree", "1", "--trials", "2", "--lambdas", "0"]) == 1
    assert "joins the corners" in one_error_line(capsys.readouterr().err)


def test_a_study_with_an_empty_figure_panel_warns_nothing(tmp_path, capsys):
    import warnings

    argv = ["experiment", "distributed", "--grid-sizes", "", "--etsp-sizes", "4", "--worst-sizes", "",
            "--sweep-areas", "", "--trials", "1", "--out", str(tmp_path)]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert main(argv) == 0
    assert [str(w.message) for w in caught if not issubclass(w.category, DeprecationWarning)] == []
    assert (tmp_path / "distributed_scaling.png").stat().st_size > 1000


def test_ctrl_c_exits_130_with_one_line(monkeypatch, capsys):
    import agents.roles.timing
    import formations

    def interrupted(*args, **kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr(agents.roles.timing, "time_assigners", interrupted)
    assert main(["bench", "roles", "--situations", "1", "--number", "1"]) == 130
    assert capsys.readouterr().err == "interrupted\n"
    monkeypatch.setattr(formations, "read_any", interrupted)
    assert main(["formation", "validate", "no-such-file.json"]) == 130
    assert capsys.readouterr().err == "interrupted\n"


def test_an_unexpected_exception_is_one_line_and_exit_1(monkeypatch, capsys):
    import agents.roles.timing

    def broken(*args, **kwargs):
        raise RuntimeError("the timer broke\nsecond line")

    monkeypatch.setattr(agents.roles.timing, "time_assigners", broken)
    monkeypatch.delenv(TRACEBACK_VARIABLE, raising=False)
    assert main(["bench", "roles", "--situations", "1", "--number", "1"]) == 1
    line = one_error_line(capsys.readouterr().err)
    assert "RuntimeError: the timer broke second line" in line and TRACEBACK_VARIABLE in line
    monkeypatch.setenv(TRACEBACK_VARIABLE, "1")
    with pytest.raises(RuntimeError, match="the timer broke"):
        main(["bench", "roles", "--situations", "1", "--number", "1"])


def test_command_parser_reports_a_usage_error_in_one_line(capsys):
    parser = CommandParser(prog="soccer-sim")
    sub = parser.add_subparsers(dest="command", required=True)
    bench = sub.add_parser("bench")
    bench.add_argument("--matches", type=int)
    errors = []
    for argv in (["bench", "--matches", "x"], ["bench", "--nope"], ["nothing"], [], ["bench", "a\nb"]):
        with pytest.raises(SystemExit) as exit_info:
            parser.parse_args(argv)
        assert exit_info.value.code == 2
        errors.append(capsys.readouterr().err)
        assert errors[-1].count("\n") == 1 and errors[-1].startswith("error: "), (argv, errors[-1])
    assert "invalid int value: 'x'" in errors[0] and "(see: soccer-sim bench --help)" in errors[0]
    assert "unrecognized arguments: --nope" in errors[1]


def test_the_cli_parser_reports_usage_errors_in_one_line(capsys):
    with pytest.raises(SystemExit) as exit_info:
        main(["bench", "match", "--matches", "zero"])
    assert exit_info.value.code == 2
    one_error_line(capsys.readouterr().err)


# ----------------------------------------------------------------------- output files only when asked
def test_lazy_assignment_writes_nothing_without_out(capsys, in_tmp):
    tiny = ["--sizes", "10", "--robots", "3", "--densities", "0.1", "--sizes-3d", "", "--repeats", "1"]
    assert main(["bench", "lazy-assignment", *tiny]) == 0
    out = capsys.readouterr().out
    assert "10x10" in out and "--out DIR" in out
    assert list(in_tmp.iterdir()) == []
    assert main(["bench", "lazy-assignment", *tiny, "--out", "mine"]) == 0
    assert sorted(p.name for p in (in_tmp / "mine").iterdir()) == ["speedup.png", "table.csv", "trials.csv"]


@pytest.mark.parametrize("argv", [
    ["experiment", "incremental", "--n", "12", "--trials", "1", "--lambdas", "0,1"],
    ["experiment", "distributed", "--grid-sizes", "", "--etsp-sizes", "4", "--worst-sizes", "", "--sweep-areas", "",
     "--trials", "1"],
])
def test_a_study_writes_nothing_without_out(argv, capsys, in_tmp):
    assert main(argv) == 0
    assert "--out DIR" in capsys.readouterr().out
    assert list(in_tmp.iterdir()) == []


# ----------------------------------------------------------------------- tables a script can read
def test_a_table_printed_to_a_pipe_is_tab_separated_one_row_per_line(capsys):
    long_label = "examples.scripted_team:ScriptedTeam with a label far longer than eighty columns " * 2
    table = Table("a title " * 20, ["team", "games", "mean GD (SE)"], caption="a caption")
    table.rows += [[long_label, "4", "+1.00 (0.50)"], ["b\tc", "2", "-"]]
    table.print()
    printed = capsys.readouterr().out
    assert not BOX & set(printed)
    lines = printed.splitlines()
    assert lines[0] == "# " + "a title " * 20
    assert lines[1:4] == ["team\tgames\tmean GD (SE)", f"{long_label}\t4\t+1.00 (0.50)", "b c\t2\t-"]
    assert lines[4] == "# a caption"


def test_bench_tables_are_plain_when_piped(capsys):
    assert main(["bench", "roles", "--situations", "1", "--number", "2"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert not BOX & set("".join(lines))
    assert lines[0].startswith("# role assigners") and lines[1] == "assigner\tassign\tsteer\tassign+steer"
    rows = [line.split("\t") for line in lines[2:] if line]
    assert len(rows) >= 3 and all(len(row) == 4 for row in rows)
    assert all(float(row[1]) > 0 for row in rows)


def test_json_on_a_benchmark_and_a_study(capsys):
    assert main(["bench", "roles", "--situations", "1", "--number", "2", "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    (table,) = document["tables"]
    assert table["columns"] == ["assigner", "assign", "steer", "assign+steer"]
    assert all(isinstance(row[1], float) and row[1] > 0 for row in table["rows"])
    assert main(["experiment", "incremental", "--n", "12", "--trials", "1", "--lambdas", "0,1", "--json"]) == 0
    document = json.loads(capsys.readouterr().out)
    assert [row[0] for row in document["tables"][0]["rows"]] == [0, 1]
    assert any(note.startswith("2 routes in") for note in document["notes"])


def exit_status(argv: list[str]) -> int:
    """``main(argv)``'s status, or the status argparse exits with for a usage error (a value
    out of its option's range is refused while parsing)."""
    try:
        return main(argv)
    except SystemExit as usage:
        return usage.code


def test_json_of_a_failed_command_is_not_printed(capsys):
    assert exit_status(["bench", "lazy-assignment", "--sizes", "ten", "--json"]) == 2
    captured = capsys.readouterr()
    assert captured.out == "" and "--sizes" in one_error_line(captured.err)


def test_formation_validate_and_show_json(tmp_path, capsys):
    assert main(["formation", "validate", "4-3-3", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["set"] == "4-3-3" and report["ok"] is True
    assert len(report["formations"]) == 5 and all(f["roles"] == 11 for f in report["formations"])
    assert main(["formation", "show", "4-3-3", "--ball", "10", "5", "--out", str(tmp_path / "p.png"), "--json"]) == 0
    shown = json.loads(capsys.readouterr().out)
    assert shown["picture"] == str(tmp_path / "p.png") and shown["ball"] == [10.0, 5.0]
    assert len(shown["positions"]) == 11 and all({"number", "role", "x", "y"} <= set(p) for p in shown["positions"])


def test_formation_show_positions_are_a_plain_table_when_piped(tmp_path, capsys):
    assert main(["formation", "show", "4-4-2", "--out", str(tmp_path / "p.png")]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0] == f"wrote {tmp_path / 'p.png'}" and lines[2] == "number\trole\tx (m)\ty (m)"
    assert not BOX & set("".join(lines))
    assert len([line for line in lines[3:] if line.count("\t") == 3]) == 11


def test_every_bench_and_experiment_takes_json():
    from experiments.cli import build_parser
    from experiments.commands.bench import BENCHMARKS
    from experiments.commands.experiment import STUDIES

    parser = build_parser()
    for command, names in (("bench", BENCHMARKS), ("experiment", STUDIES)):
        for name in names:
            args = parser.parse_args([command, name, "--json"])
            assert args.json is True and isinstance(args, argparse.Namespace)


def test_a_positional_left_empty_by_repeated_double_dashes_is_a_usage_error(capsys):
    # Python 3.11's argparse hands FILE an empty list here; the command must not receive it.
    with pytest.raises(SystemExit) as exit_info:
        main(["formation", "import", "helios", "--", "--", "--map"])
    assert exit_info.value.code == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("error: argument FILE: expected one value")


def test_version_prints_the_installed_version(capsys):
    from importlib import metadata

    with pytest.raises(SystemExit) as exit_info:
        main(["--version"])
    assert exit_info.value.code == 0
    assert capsys.readouterr().out.strip() == f"soccer-sim {metadata.version('soccer-sim')}"


def test_git_ignores_what_runs_leave_behind():
    import shutil
    import subprocess
    from pathlib import Path

    root = Path(__file__).resolve().parents[2]
    if shutil.which("git") is None or not (root / ".git").exists():
        pytest.skip("not a git checkout")
    left_behind = ["results.sqlite", "results.sqlite-wal", "results.sqlite-shm", "results-tables/league.csv",
                   "case-study.sqlite-wal"]
    ignored = subprocess.run(["git", "-C", str(root), "check-ignore", "--no-index", *left_behind],
                             capture_output=True, text=True).stdout.split()
    assert sorted(ignored) == sorted(left_behind)
