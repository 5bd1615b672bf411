"""The `soccer-sim formation` command and the formation benchmark."""

from __future__ import annotations

import argparse
import json
import re

import pytest

import formations
from experiments.benchmarks import formation as formation_bench
from experiments.commands import formation as formation_command
from tests.formations.formation_samples import small_document
from test_formation_errors import BAD_DOCUMENTS, HELIOS_BAD
from test_formation_files import helios_document
from soccer_sim.config import STANDARD_FIELD as FIELD


def run(*argv: str) -> int:
    parser = argparse.ArgumentParser(prog="soccer-sim")
    formation_command.register(parser.add_subparsers(dest="command"))
    args = parser.parse_args(list(argv))
    return args.func(args)


def test_validate_reports_a_good_file(write_json, capsys):
    assert run("formation", "validate", str(write_json("ok.json", small_document()))) == 0
    out = capsys.readouterr().out
    assert "3 roles, 4 samples" in out and "OK" in out


def test_validate_a_builtin_set_by_name(capsys):
    assert run("formation", "validate", "4-3-3", "--require-symmetry") == 0
    out = capsys.readouterr().out
    assert out.count("mirror-symmetric") == 5


def test_validate_bad_file_prints_one_line_and_exits_2(write_json, capsys):
    document = small_document()
    document["samples"][2]["positions"]["2"] = ["x", 0]
    path = write_json("bad.json", document)
    assert run("formation", "validate", str(path)) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0
    assert err.startswith("error: ") and str(path) in err and "sample 2, role 2" in err


@pytest.mark.parametrize("label, mutate, message", BAD_DOCUMENTS + HELIOS_BAD, ids=[c[0] for c in BAD_DOCUMENTS + HELIOS_BAD])
def test_every_bad_input_is_one_line_and_exit_2(write_json, capsys, label, mutate, message):
    document = helios_document() if (label, mutate, message) in HELIOS_BAD else small_document()
    mutate(document)
    path = write_json("bad.json", document)
    assert run("formation", "validate", str(path)) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith(f"error: {path}: ")
    assert re.search(message, err), err


def test_show_rejects_a_non_finite_ball(tmp_path, capsys):
    assert run("formation", "show", "4-3-3", "--ball", "nan", "0", "--out", str(tmp_path / "x.png")) == 2
    err = capsys.readouterr().err
    assert err.strip() == "error: --ball must be two finite numbers (metres), got nan 0"
    assert not (tmp_path / "x.png").exists()


def test_validate_missing_file_exits_2(tmp_path, capsys):
    assert run("formation", "validate", str(tmp_path / "nope.json")) == 2
    assert "nope.json" in capsys.readouterr().err


def test_require_symmetry_fails_on_an_asymmetric_formation(write_json, capsys):
    document = small_document()
    assert run("formation", "validate", str(write_json("sym.json", document)), "--require-symmetry") == 0
    document["samples"][2]["positions"]["3"] = [-19.0, 25.0]
    assert run("formation", "validate", str(write_json("asym.json", document)), "--require-symmetry") == 1
    captured = capsys.readouterr()
    assert "not mirror-symmetric" in captured.err
    assert "sample 2, role 3: 1 m from the mirror of its partner" in captured.out


def test_show_writes_a_picture(tmp_path, capsys):
    out = tmp_path / "picture.png"
    assert run("formation", "show", "4-4-2", "--ball", "60", "-10", "--situation", "attack", "--out", str(out)) == 0
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n" and out.stat().st_size > 20_000
    assert "left striker" in capsys.readouterr().out


def test_show_bad_situation_and_unwritable_output(tmp_path, capsys):
    assert run("formation", "show", "4-4-2", "--situation", "counter", "--out", str(tmp_path / "x.png")) == 2
    assert "unknown situation" in capsys.readouterr().err
    target = tmp_path / "missing-dir" / "x.png"
    assert run("formation", "show", "4-4-2", "--out", str(target)) == 2
    assert "missing-dir" in capsys.readouterr().err


def test_import_helios(tmp_path, write_json, capsys):
    source = write_json("team.json", helios_document())
    out = tmp_path / "ours.json"
    assert run("formation", "import", "helios", str(source), str(out)) == 0
    assert json.loads(out.read_text())["format"] == "soccer-sim-formation"
    assert formations.load(out, field=FIELD).n_samples == 6
    not_helios = write_json("ours.json", small_document())
    assert run("formation", "import", "helios", str(not_helios), str(tmp_path / "x.json")) == 2
    assert "not a helios-base formation" in capsys.readouterr().err


def test_benchmark_runs_and_reports(capsys):
    parser = argparse.ArgumentParser()
    formation_bench.add_arguments(parser)
    args = parser.parse_args(
        ["--queries", "2000", "--single", "400", "--batch", "100", "--repeats", "1", "--set", "4-3-3"]
    )
    assert formation_bench.run(args) == 0
    out = capsys.readouterr().out
    assert "their_set_play" in out and "slowest single-query median" in out
    assert formation_bench.run(parser.parse_args(["--set", "5-5-0"])) == 2


@pytest.mark.parametrize("name", formations.builtin_names())
def test_builtin_files_validate_as_plain_files(name, capsys):
    from formations.builtin import builtin_path

    assert run("formation", "validate", str(builtin_path(name))) == 0
