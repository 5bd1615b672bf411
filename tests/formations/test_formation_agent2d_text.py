"""agent2d's text formation layouts and formations-dt directories."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

import formations
from tests.formations.agent2d_samples import (
    ROLES,
    STATIC_POSITIONS,
    dt_v1_text,
    dt_v2_text,
    mirrored_samples,
    static_text,
    write_directory,
)
from experiments.cli import main as cli
from formations import FormationError, Situation
from formations.helios_dir import import_helios_directory
from formations.symmetry import asymmetries
from soccer_sim.config import STANDARD_FIELD as FIELD


def _write(tmp_path, name, text):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


@pytest.mark.parametrize("maker", [dt_v2_text, dt_v1_text], ids=["version 2", "version 1"])
def test_every_sample_is_reproduced_at_its_ball_position(tmp_path, maker):
    formation = formations.load(_write(tmp_path, "normal-formation.conf", maker()), field=FIELD)
    samples = mirrored_samples()
    assert formation.name == "normal-formation" and formation.n_samples == len(samples) == 11
    for ball, positions in samples:
        ours = positions * (1.0, -1.0)  # server y (to the right) -> ours (to the left)
        np.testing.assert_allclose(formation.positions((ball[0], -ball[1])), ours, rtol=0, atol=1e-9)
    # Between samples the positions are a blend, not any one sample's.
    between = formation.positions((20.0, 10.0))
    assert all(np.abs(between - p * (1.0, -1.0)).max() > 0.5 for _, p in samples)


def test_roles_kinds_and_mirror_pairs(tmp_path):
    formation = formations.load(_write(tmp_path, "f.conf", dt_v2_text()), field=FIELD)
    assert [r.name for r in formation.roles] == [name for _, name, _ in ROLES]
    assert [r.kind for r in formation.roles] == ["goalkeeper"] + ["defender"] * 4 + ["midfielder"] * 3 + ["forward"] * 3
    assert [r.partner for r in formation.roles] == [None, 3, 2, 5, 4, None, 8, 7, 10, 9, None]
    assert asymmetries(formation, tolerance=1e-6) == []
    # Server (54.5, -36) is the corner to the attacker's left: ours (54.5, 36); the left side back
    # (server y < 0) stays on our left (y > 0).
    left_back = formation.positions((54.5, 36.0))[formation.index_of(4)]
    assert left_back[1] > 0


def test_version_3_takes_kinds_from_the_type_column(tmp_path):
    text = dt_v2_text(version=3)
    types = {1: "G", 2: "DF", 3: "DF", 4: "MF", 5: "MF", 6: "DF", 7: "MF", 8: "MF", 9: "FW", 10: "FW", 11: "FW"}
    for n, name, pair in ROLES:
        text = text.replace(f"\n{n} {name} {pair}\n", f"\n{n} {types[n]} {name} {pair} - -\n", 1)
    formation = formations.load(_write(tmp_path, "v3.conf", text), field=FIELD)
    assert formation.role(4).kind == "midfielder" and formation.role(6).kind == "defender"


def test_static_formation_holds_its_positions_for_every_ball(tmp_path):
    formation = formations.load(_write(tmp_path, "before-kick-off.conf", static_text()), field=FIELD)
    expected = np.array(STATIC_POSITIONS, dtype=float) * (1.0, -1.0)
    for ball in [(0.0, 0.0), (52.5, 34.0), (-30.0, 12.5), (80.0, -50.0)]:
        np.testing.assert_allclose(formation.positions(ball), expected, atol=1e-9)
    kinds = [r.kind for r in formation.roles]
    # "Goalie" by name; agent2d's "Sample" roles by depth (x -30 and -20: defenders, -10 and 0: midfielders).
    assert kinds == ["goalkeeper"] + ["defender"] * 5 + ["midfielder"] * 5
    assert all(r.partner is None for r in formation.roles)


def test_constraints_block_and_comments_are_skipped(tmp_path):
    text = dt_v2_text().replace("End Samples\n", "End Samples\n// editor constraints\nBegin Constraints 1\n0 3\nEnd Constraints\n")
    assert formations.load(_write(tmp_path, "c.conf", text), field=FIELD).n_samples == 11


def _line_of(text: str, needle: str, occurrence: int = 1) -> int:
    lines = text.splitlines()
    hits = [i + 1 for i, line in enumerate(lines) if line == needle]
    return hits[occurrence - 1]


BROKEN = [
    # label, edit of the version-2 text, message pattern (the line is checked separately)
    ("missing player", lambda t: t.replace("----- 3 -----\nBall 30.37 -15.92\n1 -50 0\n", "----- 3 -----\nBall 30.37 -15.92\n"),
     r"sample 3 \(line \d+\) has no position for player\(s\) \[1\]"),
    ("role number out of range", lambda t: t.replace("\n11 CenterForward 0\n", "\n12 CenterForward 0\n"),
     r"role number 12 is out of range"),
    ("player number out of range", lambda t: t.replace("----- 3 -----\nBall 30.37 -15.92\n1 -50 0", "----- 3 -----\nBall 30.37 -15.92\n13 -50 0"),
     r"player number 13 is out of range"),
    ("malformed number", lambda t: t.replace("Ball 42.76 0\n", "Ball 42.7.6 0\n"), r"'42\.7\.6' is not a number \(ball x of sample \d+\)"),
    ("nan", lambda t: t.replace("Ball 42.76 0\n", "Ball nan 0\n"), r"'nan' is not a number"),
    ("unknown header", lambda t: t.replace("Formation DelaunayTriangulation 2", "Formacion DT 2"), r"unknown layout header 'Formacion DT 2'"),
    ("other method", lambda t: t.replace("Formation DelaunayTriangulation 2", "Formation KNN 2"), r"formation method 'KNN' is not supported"),
    ("bad version", lambda t: t.replace("Formation DelaunayTriangulation 2", "Formation DelaunayTriangulation 7"), r"layout version 7 is not supported"),
    ("bad symmetry", lambda t: t.replace("\n3 CenterBack 2\n", "\n3 CenterBack 14\n"), r"symmetry number 14 of role 3 must be"),
    ("contradicting pair", lambda t: t.replace("\n2 CenterBack -1\n", "\n2 CenterBack 0\n"),
     r"role 3: pairs with role 2, but role 2 has symmetry number 0"),
    ("two mirrors of one role", lambda t: t.replace("\n3 CenterBack 2\n", "\n3 CenterBack 4\n"),
     r"role 5: role 4 is paired with both 3 and 5"),
    ("fewer samples", lambda t: t.replace("Begin Samples 2 11", "Begin Samples 2 12"), r"only 11 samples precede 'End Samples', but line \d+ announces 12"),
    ("more samples", lambda t: t.replace("Begin Samples 2 11", "Begin Samples 2 10"), r"more samples than the 10 announced"),
    ("duplicate player", lambda t: t.replace("----- 0 -----\nBall 0 0\n1 -50 0\n2 ", "----- 0 -----\nBall 0 0\n1 -50 0\n1 "),
     r"player 1 is given twice in sample 0"),
    ("too close balls", lambda t: t.replace("Ball 42.76 0\n", "Ball 0.1 0.1\n"), r"sample \d+: ball position .* from that of sample 0"),
    ("no end roles", lambda t: t.replace("End Roles\n", ""), r"'End Roles' is missing before 'Begin Samples'"),
]


@pytest.mark.parametrize("label, edit, message", BROKEN, ids=[case[0] for case in BROKEN])
def test_broken_file_names_file_and_line(tmp_path, label, edit, message):
    good = dt_v2_text()
    text = edit(good)
    assert text != good, "the edit must change the file"
    path = _write(tmp_path, "broken.conf", text)
    with pytest.raises(FormationError, match=message) as caught:
        formations.load(path, field=FIELD)
    assert re.match(re.escape(str(path)) + r": line \d+", str(caught.value)), str(caught.value)


def test_error_lines_point_at_the_culprit(tmp_path):
    text = dt_v2_text().replace("Ball 42.76 0\n", "Ball 42.7.6 0\n")
    with pytest.raises(FormationError) as caught:
        formations.load(_write(tmp_path, "b.conf", text), field=FIELD)
    assert caught.value.where == f"line {_line_of(text, 'Ball 42.7.6 0')}"
    text = dt_v2_text().replace("\n11 CenterForward 0\n", "\n12 CenterForward 0\n")
    with pytest.raises(FormationError) as caught:
        formations.load(_write(tmp_path, "r.conf", text), field=FIELD)
    assert caught.value.where == f"line {_line_of(text, '12 CenterForward 0')}"


@pytest.mark.parametrize(
    "text, message",
    [
        (static_text().replace("\n10 Sample", "\n# 10 Sample"), r"players \[10\] have no position"),
        (static_text().replace("\n3 Sample \t -30.0", "\n3 Sample \t -3O.0"), r"'-3O\.0' is not a number \(x of player 3\)"),
        (static_text().replace("\n3 Sample \t -30.0", "\n3 Sample \t -90.0"), r"line 6, role 3: position \(-90, 10\) is far outside"),
        (dt_v1_text().replace(" -50 0 ", " -50 ", 1), r"sample 0 has 23 numbers, expected 24"),
    ],
    ids=["static missing player", "static malformed number", "static far outside", "v1 missing player"],
)
def test_broken_static_and_version_1_files(tmp_path, text, message):
    with pytest.raises(FormationError, match=message):
        formations.load(_write(tmp_path, "x.conf", text), field=FIELD)


def _directory(tmp_path):
    defense = [(ball, positions - (5.0, 0.0) * (np.arange(11)[:, None] > 0)) for ball, positions in mirrored_samples()]
    return write_directory(
        tmp_path / "formations-dt",
        {
            "normal-formation.conf": dt_v2_text(),
            "defense-formation.conf": dt_v2_text(defense),
            "offense-formation.conf": dt_v1_text(),
            "before-kick-off.conf": static_text(),
            "kickin-our-formation.conf": dt_v2_text(),
            "notes.txt": "not a formation",
        },
    )


def test_directory_becomes_a_set_and_reports_what_it_left_out(tmp_path):
    result = import_helios_directory(_directory(tmp_path), field=FIELD)
    team = result.formation_set
    assert team.name == "formations-dt"
    assert set(team.situations) == {Situation.NORMAL, Situation.ATTACK, Situation.DEFEND}
    assert {p.name for p in result.left_out} == {"before-kick-off.conf", "kickin-our-formation.conf"}
    assert "before kick-offs" in result.left_out[tmp_path / "formations-dt" / "before-kick-off.conf"]
    ball, positions = mirrored_samples()[3]
    ours = (ball[0], -ball[1])
    np.testing.assert_allclose(team.positions(ours, "defend")[1:], (positions * (1, -1) - (5.0, 0.0))[1:], atol=1e-9)
    np.testing.assert_allclose(team.positions(ours, "attack"), positions * (1, -1), atol=1e-9)
    # No set-play files: the set plays use the normal formation.
    assert team.formation("our_set_play") is team.formation("normal")


def test_mapping_places_the_static_file_with_the_normal_roles(tmp_path):
    result = import_helios_directory(_directory(tmp_path), field=FIELD, name="mine", mapping={"before-kick-off.conf": "our_kickoff"})
    team = result.formation_set
    assert team.name == "mine" and team.formation("our_set_play").roles == team.roles
    assert team.formation("our_set_play").role(3).name == "CenterBack"
    assert any("before-kick-off.conf" in note for note in result.notes)
    np.testing.assert_allclose(team.positions((10.0, 10.0), "our_set_play")[2], (-30.0, 10.0), atol=1e-9)


def test_directory_without_normal_formation_or_with_a_broken_file(tmp_path):
    root = write_directory(tmp_path / "empty", {"offense-formation.conf": dt_v2_text()})
    with pytest.raises(FormationError, match=r"no normal formation .*found: offense-formation.conf"):
        import_helios_directory(root, field=FIELD)
    root = write_directory(tmp_path / "broken", {"normal-formation.conf": dt_v2_text().replace("Ball 0 0", "Ball 0 zero")})
    with pytest.raises(FormationError, match=r"normal-formation.conf: line 18: 'zero' is not a number"):
        import_helios_directory(root, field=FIELD)


def test_cli_imports_a_file_and_a_directory(tmp_path, capsys):
    source = _write(tmp_path, "normal-formation.conf", dt_v2_text())
    out = tmp_path / "normal.json"
    assert cli(["formation", "import", "helios", str(source), str(out)]) == 0
    assert "11 roles, 11 samples" in capsys.readouterr().out
    assert formations.load(out, field=FIELD).roles == formations.load(source, field=FIELD).roles
    directory = _directory(tmp_path)
    out = tmp_path / "set.json"
    assert cli(["formation", "import", "helios", str(directory), str(out), "--map", "before-kick-off=their_set_play"]) == 0
    printed = capsys.readouterr().out
    assert "their_set_play  <- before-kick-off.conf" in printed and "not placed (1 file)" in printed
    assert "kickin-our-formation.conf: our kick-ins only" in printed and "notes.txt" not in printed
    assert json.loads(out.read_text())["format"] == "soccer-sim-formation-set"
    assert formations.load_set(out, field=FIELD).situations == (Situation.NORMAL, Situation.ATTACK, Situation.DEFEND, Situation.THEIR_SET_PLAY)


def test_cli_reports_broken_files_and_bad_mapping(tmp_path, capsys):
    bad = _write(tmp_path, "bad.conf", dt_v2_text().replace("\n11 CenterForward 0\n", "\n12 CenterForward 0\n"))
    assert cli(["formation", "import", "helios", str(bad), str(tmp_path / "o.json")]) == 2
    assert re.search(r"bad.conf: line 14: role number 12 is out of range", capsys.readouterr().err)
    assert cli(["formation", "import", "helios", str(_directory(tmp_path)), str(tmp_path / "o.json"), "--map", "x"]) == 2
    assert "--map takes FILE=SITUATION" in capsys.readouterr().err
    assert cli(["formation", "import", "helios", str(_directory(tmp_path)), str(tmp_path / "o.json"), "--map", "normal-formation=corner"]) == 2
    assert "unknown situation 'corner'" in capsys.readouterr().err
    assert cli(["formation", "validate", str(bad)]) == 2


def test_show_writes_the_file_it_names(tmp_path, capsys):
    assert cli(["formation", "show", "4-3-3", "--out", str(tmp_path / "picture")]) == 0
    assert f"wrote {tmp_path / 'picture.png'}" in capsys.readouterr().out
    assert (tmp_path / "picture.png").exists() and not (tmp_path / "picture").exists()
    folder = tmp_path / "pictures"
    folder.mkdir()
    assert cli(["formation", "show", "4-3-3", "--situation", "attack", "--out", str(folder)]) == 0
    assert f"wrote {folder / '4-3-3-attack.png'}" in capsys.readouterr().out
    assert (folder / "4-3-3-attack.png").read_bytes()[:4] == b"\x89PNG"


def test_round_trip_directory_to_set_to_a_team_playing_with_it(tmp_path, capsys):
    import runpy
    from pathlib import Path

    import soccer_sim

    out = tmp_path / "my-team.json"
    assert cli(["formation", "import", "helios", str(_directory(tmp_path)), str(out)]) == 0
    capsys.readouterr()
    examples = Path(__file__).resolve().parents[2] / "examples"
    team_class = runpy.run_path(str(examples / "formation_team.py"))["FormationTeam"]
    for team in (team_class(str(out)), team_class(formations.load_set(out, field=FIELD))):
        assert team.formation_set.formation("defend").n_samples == 11
        result = soccer_sim.run_match(team, "idle", seed=1, config=soccer_sim.MatchConfig(max_cycles=200))
        assert result.cycles == 200
        # Players hold the imported shape: in play the team spreads over both wings.
        view_y = result.state.pos[:11, 1]
        assert view_y.max() - view_y.min() > 20.0
