"""Formations for more players than a team has, and `formation show --ball` far off the field."""

from __future__ import annotations

import argparse

import numpy as np
import pytest

from formations.files import formation_from_dict
from experiments.commands import formation as formation_command
from tests.formations.formation_samples import eleven_roles
from formations import Formation, FormationError, Role
from soccer_sim.config import STANDARD_FIELD as FIELD


def run(*argv: str) -> int:
    parser = argparse.ArgumentParser(prog="soccer-sim")
    formation_command.register(parser.add_subparsers(dest="command"))
    args = parser.parse_args(list(argv))
    return args.func(args)


def twelve_role_document() -> dict:
    """A formation in our layout that is well formed except for its twelve roles."""
    roles = eleven_roles() + [Role(12, "extra striker", "forward")]
    balls = [(-30.0, 0.0), (30.0, 0.0), (0.0, 20.0), (0.0, -20.0)]
    samples = []
    for bx, by in balls:
        positions = {str(r.number): [round(-45.0 + 7.5 * k + 0.2 * bx, 2), round(-25.0 + 4.0 * k + 0.1 * by, 2)]
                     for k, r in enumerate(roles)}
        samples.append({"ball": [bx, by], "positions": positions})
    return {"format": "soccer-sim-formation", "version": 1, "name": "twelve", "description": "",
            "roles": [{"number": r.number, "name": r.name, "kind": r.kind, "partner": r.partner} for r in roles],
            "samples": samples}


def test_validate_refuses_twelve_roles_naming_the_file_and_count(write_json, capsys) -> None:
    path = write_json("twelve.json", twelve_role_document())
    assert run("formation", "validate", str(path)) == 2  # bad input
    captured = capsys.readouterr()
    assert captured.err == f"error: {path}: 12 roles; a formation places one team, at most 11 players\n"
    assert "OK" not in captured.out


def test_eleven_roles_are_still_fine(write_json, capsys) -> None:
    document = twelve_role_document()
    document["roles"].pop()
    for sample in document["samples"]:
        del sample["positions"]["12"]
    assert run("formation", "validate", str(write_json("eleven.json", document))) == 0
    assert "11 roles" in capsys.readouterr().out


def test_a_formation_built_in_memory_refuses_twelve_roles() -> None:
    roles = eleven_roles() + [Role(12, "extra", "forward")]
    balls = np.array([[-30.0, 0.0], [30.0, 0.0], [0.0, 20.0], [0.0, -20.0]])
    positions = np.random.default_rng(1).uniform(-30, 30, (4, 12, 2))
    with pytest.raises(FormationError, match="mine: 12 roles; a formation places one team, at most 11 players"):
        Formation(roles, balls, positions, source="mine")
    with pytest.raises(FormationError, match="12 roles"):
        formation_from_dict(twelve_role_document(), "doc", FIELD)


@pytest.mark.parametrize("ball", [("1000", "0"), ("0", "-45")])
def test_show_refuses_a_ball_far_off_the_field_naming_the_limits(tmp_path, capsys, ball) -> None:
    out = tmp_path / "x.png"
    assert run("formation", "show", "4-3-3", "--ball", *ball, "--out", str(out)) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith("error: --ball: position (")
    assert "limits |x| <= 62.5, |y| <= 44" in err and not out.exists()
