"""The other layouts real helios-base / agent2d formation files use.

librcsc's editor saves a static formation as ``Formation Static 0`` with an
empty samples block; helios-base has shipped its ``formations-dt`` files as
comma-separated rows and, today, as JSON whose fixed line-ups (method
``Static``, role type ``Unknown``) hold one sample. Files here are written by
the tests (see agent2d_samples.py), in the server's frame.
"""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

import formations
from tests.formations.agent2d_samples import (
    LINEUP,
    LINEUP_KINDS,
    ROLES,
    csv_dt_text,
    csv_static_text,
    dt_v2_text,
    lineup_positions,
    mirrored_samples,
    static_json_document,
    static_v0_text,
    write_directory,
)
from experiments.cli import main as cli
from formations import FormationError, Situation
from formations.helios_dir import import_helios_directory
from formations.symmetry import asymmetries
from soccer_sim.config import STANDARD_FIELD as FIELD

BALLS = [(0.0, 0.0), (52.5, 34.0), (-30.0, 12.5), (41.0, -20.0), (-52.5, -34.0)]
"""Ball positions (ours) at which a static formation must give its line-up."""


def _write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


def _assert_holds_lineup(formation):
    expected = lineup_positions() * (1.0, -1.0)  # server y (to the right) -> ours (to the left)
    for ball in BALLS:
        np.testing.assert_allclose(formation.positions(ball), expected, rtol=0, atol=1e-9)


# ----------------------------------------------------------------- Formation Static 0 + empty samples block
@pytest.mark.parametrize("end", [False, True], ids=["no End", "End"])
def test_static_file_with_an_empty_samples_block_holds_its_lineup(tmp_path, end):
    formation = formations.load(_write(tmp_path, "before-kick-off.conf", static_v0_text(end=end)), field=FIELD)
    _assert_holds_lineup(formation)
    assert [r.name for r in formation.roles] == [name for _, name, _, _ in LINEUP]
    assert [r.kind for r in formation.roles] == LINEUP_KINDS
    assert all(r.partner is None for r in formation.roles)


def test_static_file_with_comments_and_plain_header_and_empty_samples_block(tmp_path):
    text = static_v0_text().replace("Formation Static 0\n", "Formation Static\n# line-up before kick-off\n")
    text = text.replace("Begin Samples 2 0\n", "\n// saved by the editor\nBegin Samples 2 0\n")
    _assert_holds_lineup(formations.load(_write(tmp_path, "static.conf", text), field=FIELD))


@pytest.mark.parametrize(
    "old, new, message",
    [
        ("Begin Samples 2 0", "Begin Samples 2 3", r"static.conf: line 13: a static formation holds no samples, but this block announces 3"),
        ("End Samples\n", "----- 0 -----\n", r"static.conf: line 14: expected 'End Samples' after the empty samples block of line 13"),
        ("End Samples\n", "", r"static.conf: line 13: the file ends where 'End Samples' \(the empty samples block begins on line 13\)"),
        ("Begin Samples 2 0", "Begin Samples 3 0", r"static.conf: line 13: sample layout version 3 is not supported"),
        ("Begin Samples 2 0", "Begin Samples 2 none", r"static.conf: line 13: 'none' is not an integer \(number of samples\)"),
        ("\n7 OffensiveHalf -14 -11.5\n", "\n", r"static.conf: line 12: players \[7\] have no position"),
        ("End Samples\n", "End Samples\n5 SideBack 0 0\n", r"static.conf: line 15: unexpected line after the samples"),
    ],
    ids=["samples announced", "no End Samples", "file ends", "sample version", "bad count", "missing player", "after the block"],
)
def test_broken_static_file_with_samples_block_names_file_and_line(tmp_path, old, new, message):
    text = static_v0_text()
    assert old in text
    with pytest.raises(FormationError, match=message):
        formations.load(_write(tmp_path, "static.conf", text.replace(old, new, 1)), field=FIELD)


# ----------------------------------------------------------------- helios-base's JSON, method Static
def test_json_static_formation_with_unknown_types_holds_its_lineup(tmp_path):
    path = _write(tmp_path, "before-kick-off.conf", json.dumps(static_json_document(), indent=2))
    formation = formations.load(path, field=FIELD)
    _assert_holds_lineup(formation)
    assert [r.kind for r in formation.roles] == LINEUP_KINDS  # from the names: every type is Unknown
    assert all(r.partner is None for r in formation.roles)
    assert formations.load_helios(path, field=FIELD).roles == formation.roles
    # Unknown types stay refused where the kind matters: a Delaunay formation.
    document = static_json_document()
    document["method"] = "DelaunayTriangulation"
    with pytest.raises(FormationError, match=r"role 1: 'type' must be one of G, DF, MF, FW, got 'Unknown'"):
        formations.load(_write(tmp_path, "dt.json", json.dumps(document)), field=FIELD)


def test_json_static_formation_takes_given_types_and_places_unknown_names_by_depth(tmp_path):
    document = static_json_document(role_type="MF", ball=(10.0, -5.0))  # a static sample's ball is irrelevant
    document["role"][0]["type"] = "G"
    document["role"][1]["type"] = document["role"][10]["type"] = "Unknown"
    document["role"][1]["name"] = document["role"][10]["name"] = "Sample"
    formation = formations.load(_write(tmp_path, "s.json", json.dumps(document)), field=FIELD)
    _assert_holds_lineup(formation)
    # Given types win over names (a "SideBack" typed MF is a midfielder); "Sample" goes by depth:
    # x -31 is a defender, x -9.5 a midfielder.
    assert [r.kind for r in formation.roles] == ["goalkeeper", "defender"] + ["midfielder"] * 9


@pytest.mark.parametrize(
    "mutate, message",
    [
        (lambda d: d["data"].append(dict(d["data"][0], index=1)), r"a static formation holds exactly one sample \(its line-up\), found 2"),
        (lambda d: d["data"].clear(), r"a static formation holds exactly one sample \(its line-up\), found 0"),
        (lambda d: d["role"][3].update(type="Defender"), r"role 4: 'type' must be one of G, DF, MF, FW or Unknown, got 'Defender'"),
        (lambda d: d["data"][0]["6"].update(x=-90.0), r"sample 0, role 6: position \(-90, -0.5\) is far outside"),
        (lambda d: d["data"][0].pop("9"), r"sample 0: missing the position of role 9"),
    ],
    ids=["two samples", "no sample", "bad type", "far outside", "missing player"],
)
def test_broken_json_static_formation_is_reported(tmp_path, mutate, message):
    document = static_json_document()
    mutate(document)
    path = _write(tmp_path, "static.json", json.dumps(document))
    with pytest.raises(FormationError, match=message) as caught:
        formations.load(path, field=FIELD)
    assert str(caught.value).startswith(str(path) + ":")


# ----------------------------------------------------------------- helios-base's comma-separated layout
def test_csv_delaunay_formation_reproduces_every_sample(tmp_path):
    formation = formations.load(_write(tmp_path, "normal-formation.conf", csv_dt_text()), field=FIELD)
    samples = mirrored_samples()
    assert formation.n_samples == len(samples)
    for ball, positions in samples:
        np.testing.assert_allclose(formation.positions((ball[0], -ball[1])), positions * (1.0, -1.0), rtol=0, atol=1e-9)
    assert [r.name for r in formation.roles] == [name for _, name, _ in ROLES]
    assert [r.kind for r in formation.roles] == ["goalkeeper"] + ["defender"] * 4 + ["midfielder"] * 3 + ["forward"] * 3
    assert [r.partner for r in formation.roles] == [None, 3, 2, 5, 4, None, 8, 7, 10, 9, None]
    assert asymmetries(formation, tolerance=1e-6) == []
    # The same formation as agent2d's text layout of the same samples.
    text = formations.load(_write(tmp_path, "text.conf", dt_v2_text()), field=FIELD)
    assert text.roles == formation.roles and np.array_equal(text.sample_positions, formation.sample_positions)


def test_csv_role_types_give_kinds_and_unknown_falls_back_to_names(tmp_path):
    types = ["G", "MF", "MF", "DF", "DF", "DF", "MF", "MF", "FW", "FW", "Unknown"]
    formation = formations.load(_write(tmp_path, "f.conf", csv_dt_text(types=types)), field=FIELD)
    kinds = [r.kind for r in formation.roles]
    assert kinds == ["goalkeeper", "midfielder", "midfielder", "defender", "defender", "defender"] + ["midfielder"] * 2 + ["forward"] * 3


def test_csv_static_formation_holds_its_lineup(tmp_path):
    formation = formations.load(_write(tmp_path, "before-kick-off.conf", csv_static_text()), field=FIELD)
    _assert_holds_lineup(formation)
    assert [r.kind for r in formation.roles] == LINEUP_KINDS


def _replace_line(text: str, number: int, new: str) -> str:
    lines = text.split("\n")
    lines[number - 1] = new
    return "\n".join(lines)


@pytest.mark.parametrize(
    "edit, message",
    [
        (lambda t: t.replace("Size,11", "Size,12"), r"f.conf: line 22: the file ends where sample 11 \(of the 12 announced on line 10\)"),
        (lambda t: t.replace("Size,11", "Size,10"), r"f.conf: line 22: unexpected line after the samples: '10,"),
        (lambda t: _replace_line(t, 15, t.split("\n")[14].replace(",-4.13,", ",-4.1x,", 1)), r"f.conf: line 15: '-4.1x' is not a number \(x of player 2 in sample 3\)"),
        (lambda t: _replace_line(t, 13, t.split("\n")[12].rsplit(",", 2)[0]), r"f.conf: line 13: sample 1 has 23 values, expected 25"),
        (lambda t: _replace_line(t, 14, "5" + t.split("\n")[13][1:]), r"f.conf: line 14: sample index 5, expected 2"),
        (lambda t: t.replace("RoleType,G,", "RoleType,GK,"), r"f.conf: line 5: role type 'GK' of role 1 is not one of G, DF, MF, FW or Unknown"),
        (lambda t: t.replace("SymmetryNumber,0,-1,2,", "SymmetryNumber,0,-1,12,"), r"f.conf: line 6: symmetry number 12 of role 3 must be"),
        (lambda t: t.replace("SymmetryNumber,0,-1,2,", "SymmetryNumber,0,-1,4,"), r"f.conf: line 6, role 5: role 4 is paired with both 3 and 5"),
        (lambda t: t.replace("RoleNumber,1,2,", "RoleNumber,2,1,"), r"f.conf: line 3: RoleNumber must list 1..11 in order"),
        (lambda t: t.replace("Marker,0,0,0,0,0,0,0,0,0,0,0\nSetplay", "Setplay"), r"f.conf: line 7: expected the Marker row"),
        (lambda t: t.replace("RoleName,Goalie,", "RoleName,"), r"f.conf: line 4: the RoleName row holds 11 value\(s\), found 10"),
        (lambda t: t.replace("Method,DelaunayTriangulation", "Method,KNN"), r"f.conf: line 2: formation method 'KNN' is not supported"),
        (lambda t: t.replace("\nSampleData\n", "\nSamples\n"), r"f.conf: line 9: expected 'SampleData', found 'Samples'"),
    ],
    ids=[
        "too few samples", "too many samples", "bad number", "short row", "bad index", "bad type", "pair range",
        "pair contradiction", "role numbers", "missing row", "short names", "method", "data tag",
    ],
)
def test_broken_csv_file_names_file_and_line(tmp_path, edit, message):
    text = csv_dt_text()
    edited = edit(text)
    assert edited != text
    with pytest.raises(FormationError, match=message):
        formations.load(_write(tmp_path, "f.conf", edited), field=FIELD)


def test_broken_csv_static_file_names_file_and_line(tmp_path):
    text = csv_static_text().replace("Position,-48.5,0,", "Position,-48.5,0,-91,")
    with pytest.raises(FormationError, match=r"f.conf: line 5: the Position row holds 22 value\(s\), found 23"):
        formations.load(_write(tmp_path, "f.conf", text), field=FIELD)
    text = csv_static_text().replace("Position,-48.5,0,-31,", "Position,-48.5,0,-91,")
    with pytest.raises(FormationError, match=r"f.conf: line 5, role 2: position \(-91, 7.5\) is far outside"):
        formations.load(_write(tmp_path, "f.conf", text), field=FIELD)


# ----------------------------------------------------------------- a directory of these layouts
def _mixed_directory(tmp_path):
    return write_directory(
        tmp_path / "formations-dt",
        {
            "normal-formation.conf": csv_dt_text(),
            "before-kick-off.conf": json.dumps(static_json_document(), indent=2),
            "goal-kick-our.conf": static_v0_text(),
            "kickin-our-formation.conf": csv_static_text(),
            "goalie-formation.conf": dt_v2_text(),
        },
    )


def test_directory_of_csv_json_static_and_text_static_files(tmp_path):
    root = _mixed_directory(tmp_path)
    result = import_helios_directory(root, field=FIELD)
    assert set(result.formation_set.situations) == {Situation.NORMAL}
    assert "never load it" in result.left_out[root / "goalie-formation.conf"]
    mapped = import_helios_directory(
        root, field=FIELD, mapping={"before-kick-off": "our_set_play", "goal-kick-our": "their_set_play", "kickin-our-formation": "defend"}
    )
    team = mapped.formation_set
    for situation in ("our_set_play", "their_set_play", "defend"):
        # Each static member holds the line-up wherever the ball is, with the normal formation's roles.
        assert team.formation(situation).roles == team.roles
        for ball in BALLS:
            np.testing.assert_allclose(team.positions(ball, situation), lineup_positions() * (1.0, -1.0), atol=1e-9)


def test_cli_imports_the_static_file_librcsc_writes(tmp_path, capsys):
    source = _write(tmp_path, "before-kick-off.conf", static_v0_text(end=True))
    out = tmp_path / "kickoff.json"
    assert cli(["formation", "import", "helios", str(source), str(out)]) == 0
    assert re.search(r"wrote .*kickoff.json: 11 roles, 4 samples", capsys.readouterr().out)
    _assert_holds_lineup(formations.load(out, field=FIELD))
    bad = _write(tmp_path, "bad.conf", static_v0_text().replace("Begin Samples 2 0", "Begin Samples 2 1"))
    assert cli(["formation", "import", "helios", str(bad), str(tmp_path / "o.json")]) == 2  # bad input
    assert re.search(r"bad.conf: line 13: a static formation holds no samples", capsys.readouterr().err)
    assert not (tmp_path / "o.json").exists()
