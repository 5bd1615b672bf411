"""Our JSON layout round-trips; helios-base files import."""

from __future__ import annotations

import copy
import json

import numpy as np
import pytest

import formations
from formations import FormationError, FormationSet, Situation
from formations.files import dumps

from tests.formations.formation_samples import small_document
from soccer_sim.config import STANDARD_FIELD as FIELD


def test_formation_round_trip_is_exact(tmp_path, random_formation):
    path = tmp_path / "random.json"
    random_formation.save(path)
    loaded = formations.load(path, field=FIELD)
    assert loaded.roles == random_formation.roles
    assert loaded.name == random_formation.name
    assert np.array_equal(loaded.balls, random_formation.balls)
    assert np.array_equal(loaded.sample_positions, random_formation.sample_positions)
    assert dumps(loaded) == dumps(random_formation)


def test_formation_set_round_trip(tmp_path):
    original = formations.load_builtin("4-4-2")
    path = tmp_path / "set.json"
    formations.save(original, path)
    loaded = formations.load_set(path, field=FIELD)
    assert loaded.name == "4-4-2" and loaded.situations == original.situations
    for situation in Situation:
        a, b = original.formation(situation), loaded.formation(situation)
        assert np.array_equal(a.sample_positions, b.sample_positions)
        assert np.array_equal(a.positions((12.5, -3.0)), b.positions((12.5, -3.0)))


def test_formations_pickle_compactly():
    import pickle

    team = formations.load_builtin("4-3-3")
    data = pickle.dumps(team)
    assert len(data) < 200_000  # the definition, not the lookup tables
    again = pickle.loads(data)
    for situation in Situation:
        np.testing.assert_array_equal(again.positions((7.0, -3.0), situation), team.positions((7.0, -3.0), situation))


def test_layout_is_readable_one_sample_per_line(random_formation):
    text = dumps(random_formation)
    lines = text.splitlines()
    sample_lines = [line for line in lines if line.strip().startswith('{"ball"')]
    assert len(sample_lines) == random_formation.n_samples
    assert json.loads(text)["format"] == "soccer-sim-formation"


def test_small_document_loads(write_json):
    formation = formations.load(write_json("small.json", small_document()), field=FIELD)
    assert formation.role_numbers == (1, 2, 3)
    assert formation.role(2).partner == 3
    np.testing.assert_allclose(formation.positions((30.0, 0.0))[1], (0.0, -15.0))


def test_load_and_load_set_refuse_the_other_kind(tmp_path, write_json):
    single = write_json("single.json", small_document())
    with pytest.raises(FormationError, match="single.json.*not a formation set"):
        formations.load_set(single, field=FIELD)
    set_path = tmp_path / "set.json"
    formations.save(formations.load_builtin("4-3-3"), set_path)
    with pytest.raises(FormationError, match="set.json.*formation set"):
        formations.load(set_path, field=FIELD)
    assert isinstance(formations.read_any(set_path, field=FIELD), FormationSet)


# ----------------------------------------------------------------- helios
HELIOS_ROLES = [
    {"number": 1, "name": "Keeper", "type": "G", "side": "C", "pair": 0},
    {"number": 2, "name": "BackLeft", "type": "DF", "side": "L", "pair": -1},
    {"number": 3, "name": "BackRight", "type": "DF", "side": "R", "pair": 2},
    {"number": 4, "name": "Stopper", "type": "DF", "side": "C", "pair": 0},
    {"number": 5, "name": "MidLeft", "type": "MF", "side": "L", "pair": -1},
    {"number": 6, "name": "MidRight", "type": "MF", "side": "R", "pair": 5},
    {"number": 7, "name": "Pivot", "type": "MF", "side": "C", "pair": 0},
    {"number": 8, "name": "Playmaker", "type": "MF", "side": "C", "pair": 0},
    {"number": 9, "name": "WingLeft", "type": "FW", "side": "L", "pair": -1},
    {"number": 10, "name": "WingRight", "type": "FW", "side": "R", "pair": 9},
    {"number": 11, "name": "Target", "type": "FW", "side": "C", "pair": 0},
]


def helios_sample(index: int, bx: float, by: float) -> dict:
    """A sample in the server frame (y to the right): the team shifts with the ball."""
    base = {
        1: (-50, 0),
        2: (-30, -15),
        3: (-30, 15),
        4: (-35, 0),
        5: (-10, -20),
        6: (-10, 20),
        7: (-15, 0),
        8: (-5, 0),
        9: (10, -25),
        10: (10, 25),
        11: (15, 0),
    }
    sample = {"index": index, "ball": {"x": bx, "y": by}}
    for number, (x, y) in base.items():
        gain = 0.0 if number == 1 else 0.5
        sample[str(number)] = {"x": x + gain * bx, "y": y + 0.3 * by}
    return sample


def helios_document() -> dict:
    balls = [(0, 0), (-40, -25), (-40, 25), (40, -25), (40, 25), (20, 0)]
    return {
        "version": "test",
        "method": "DelaunayTriangulation",
        "role": copy.deepcopy(HELIOS_ROLES),
        "data": [helios_sample(i, x, y) for i, (x, y) in enumerate(balls)],
    }


def test_helios_layout_imports_with_y_mirrored_to_our_frame(write_json):
    formation = formations.load(write_json("helios.json", helios_document()), field=FIELD)
    assert formation.name == "helios"
    assert [r.kind for r in formation.roles][:2] == ["goalkeeper", "defender"]
    assert formation.role(2).partner == 3 and formation.role(3).partner == 2
    assert formation.role(9).partner == 10 and formation.role(4).partner is None
    # Server y = -25 is to the player's left, which is +y in our frame.
    assert (-40.0, 25.0) in [tuple(b) for b in formation.balls.tolist()]
    left_back = formation.positions((0.0, 0.0))[formation.index_of(2)]
    np.testing.assert_allclose(left_back, (-30.0, 15.0))
    # At server ball (40, -25) the server wing-left stands at (30, -32.5): ours (30, 32.5).
    np.testing.assert_allclose(formation.positions((40.0, 25.0))[formation.index_of(9)], (30.0, 32.5))


def test_helios_import_then_save_round_trips(tmp_path, write_json):
    imported = formations.load(write_json("helios.json", helios_document()), field=FIELD)
    out = tmp_path / "ours.json"
    imported.save(out)
    again = formations.load(out, field=FIELD)
    assert again.roles == imported.roles
    assert np.array_equal(again.sample_positions, imported.sample_positions)


def helios_text_mutual_pairs() -> str:
    """A helios-base file written the way its tools write one: a timestamp
    version string, ``"key" : value`` spacing, roles whose ``pair`` fields name
    each other (rather than -1), ``side`` letters, ``-0.00`` and balls 2 m
    beyond the field lines (where helios places its corner samples)."""
    roles = [
        (1, "Goalie", "G", "C", 0),
        (2, "CenterBack", "DF", "L", 3),
        (3, "CenterBack", "DF", "R", 2),
        (4, "SideBack", "DF", "L", 5),
        (5, "SideBack", "DF", "R", 4),
        (6, "DefensiveHalf", "MF", "C", 0),
        (7, "OffensiveHalf", "MF", "L", 8),
        (8, "OffensiveHalf", "MF", "R", 7),
        (9, "SideForward", "FW", "L", 10),
        (10, "SideForward", "FW", "R", 9),
        (11, "CenterForward", "FW", "C", 0),
    ]
    role_lines = ",\n".join(
        f'    {{ "number" : {n}, "name" : "{name}", "type" : "{kind}", "side" : "{side}", "pair" : {pair} }}'
        for n, name, kind, side, pair in roles
    )
    samples = []
    for index, (bx, by) in enumerate([(0.0, 0.0), (54.5, -36.0), (54.5, 36.0), (-54.5, 0.0), (-20.0, -25.0)]):
        entries = [f'"index" : {index}', f'"ball" : {{ "x" : {bx:.2f}, "y" : {by:.2f} }}']
        for n in range(1, 12):
            x = -50.0 if n == 1 else -40.0 + 7.0 * n + 0.4 * bx
            y = -0.0 if n == 1 else (n % 3 - 1) * 12.0 + 0.3 * by
            entries.append(f'"{n}" : {{ "x" : {x:.2f}, "y" : {y:.2f} }}')
        samples.append("    {\n      " + ",\n      ".join(entries) + "\n    }")
    return (
        '{\n  "version" : "20240527-202716",\n  "method" : "DelaunayTriangulation",\n'
        f'  "role" : [\n{role_lines}\n  ],\n  "data" : [\n' + ",\n".join(samples) + "\n  ]\n}\n"
    )


def test_helios_file_with_mutual_pairs_as_its_tools_write_it(write_json):
    formation = formations.load(write_json("normal-formation.conf", helios_text_mutual_pairs()), field=FIELD)
    assert formation.name == "normal-formation" and formation.n_samples == 5
    assert [formation.role(n).partner for n in range(1, 12)] == [None, 3, 2, 5, 4, None, 8, 7, 10, 9, None]
    assert formation.role(6).kind == "midfielder" and formation.role(11).kind == "forward"
    # helios y grows to the right: its corner sample (54.5, -36) is our (54.5, 36).
    row = [tuple(b) for b in formation.balls.tolist()].index((54.5, 36.0))
    np.testing.assert_allclose(formation.sample_positions[row, formation.index_of(4)], (-40.0 + 28.0 + 21.8, -0.0 + 10.8))
