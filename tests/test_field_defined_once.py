"""The field's dimensions are defined once, in :class:`soccer_sim.config.FieldConfig`
(:mod:`soccer_sim.field_config`), and everything else takes them from there: the simulator's
perception, the teams (agents), the formations (which take the field from their callers, being
pure), the experiments and the bridge to rcssserver. No number of the default field (105, 68,
52.5, 34) is written anywhere else in those packages."""

from __future__ import annotations

import ast
import math
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from soccer_sim.config import STANDARD_FIELD, FieldConfig, MatchConfig

ROOT = Path(__file__).resolve().parents[1]
SCANNED = ("soccer_sim", "agents", "formations", "experiments", "rcss_bridge")
FIELD_NUMBERS = {105.0, 68.0, 52.5, 34.0}
"""The default field's length, width, half length and half width (m)."""
DEFINITION = ROOT / "soccer_sim" / "field_config.py"
GENERATED = {ROOT / "experiments" / "kernel_manifest.py":
             "generated table of kernel indices (python -m experiments.kernel_record --write)"}
"""Files left out of the scan, with why: their numbers are not the field's."""


def field_literals(path: Path, skip_class: str | None = None) -> list[str]:
    """``file:line: value`` for every int or float literal of :data:`FIELD_NUMBERS` in the
    Python file ``path`` (docstrings and comments are not literals), outside the class body
    ``skip_class`` if given."""
    tree = ast.parse(path.read_text(encoding="utf-8"), str(path))
    skipped: set[int] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.ClassDef) and node.name == skip_class:
            skipped |= {id(inner) for inner in ast.walk(node)}
    hits = [node for node in ast.walk(tree) if isinstance(node, ast.Constant) and type(node.value) in (int, float)
            and float(node.value) in FIELD_NUMBERS and id(node) not in skipped]
    return [f"{path}:{node.lineno}: {node.value!r}" for node in sorted(hits, key=lambda n: (n.lineno, n.col_offset))]


def test_no_package_writes_the_fields_numbers_outside_field_config():
    found = []
    for package in SCANNED:
        for path in sorted((ROOT / package).rglob("*.py")):
            if path in GENERATED:
                continue
            found += field_literals(path, "FieldConfig" if path == DEFINITION else None)
    assert not found, "the field's numbers written outside FieldConfig (take them from it):\n" + "\n".join(found)


def test_the_scan_finds_a_field_number_and_only_outside_the_definition(tmp_path):
    path = tmp_path / "module.py"
    path.write_text('"""A 105 x 68 m pitch."""\n# 52.5\nclass FieldConfig:\n    length: float = 105.0\n\n'
                    "GOAL_LINE = -52.5\nWIDTH = 68\nROWS = 34.5\n")
    assert [line.split(": ", 1)[1] for line in field_literals(path, "FieldConfig")] == ["52.5", "68"]
    assert len(field_literals(path)) == 3
    assert DEFINITION.exists() and field_literals(DEFINITION), "FieldConfig's defaults are not where the scan looks"


def test_the_default_match_plays_on_the_standard_field():
    assert MatchConfig().field is STANDARD_FIELD
    assert STANDARD_FIELD == FieldConfig()


def test_the_agents_use_the_simulators_field():
    import agents.roles.base as role_base
    import agents.roles.timing as role_timing
    import agents.teams.positions as positions

    assert positions.STANDARD_FIELD is STANDARD_FIELD
    assert role_timing.STANDARD_FIELD is STANDARD_FIELD
    context = role_base.RoleContext(ball=np.zeros(2), own_goal=np.zeros(2), opp_goal=np.zeros(2),
                                    opponents=np.zeros((0, 2)), field_half_length=1.0, field_half_width=1.0,
                                    cycle=0, attacking=True)
    assert context.penalty_area_length == STANDARD_FIELD.penalty_area_length
    assert context.penalty_area_half_width == STANDARD_FIELD.penalty_area_width / 2.0


def test_perception_and_the_bridge_take_the_pitch_from_the_field():
    from rcss_bridge.landmarks import FLAGS, flag_positions
    from soccer_sim.perception.localise import DEFAULT_FLAGS, field_flags
    from soccer_sim.perception.params import MAX_DIST_IN_PITCH, SeeParams

    assert MAX_DIST_IN_PITCH == math.hypot(STANDARD_FIELD.length, STANDARD_FIELD.width)
    assert SeeParams().max_observation_length == MAX_DIST_IN_PITCH
    assert np.array_equal(DEFAULT_FLAGS, field_flags(STANDARD_FIELD))
    assert sorted(map(tuple, DEFAULT_FLAGS.tolist())) == sorted(FLAGS.values())
    wider = replace(STANDARD_FIELD, width=70.0)
    assert np.abs(field_flags(wider)[:, 1]).max() == wider.half_width + 5.0
    assert flag_positions(wider)[("f", "c", "b")] == (0.0, wider.half_width)


def test_the_formations_take_the_field_from_their_caller(tmp_path):
    import formations
    from formations.design import design_set, sample_balls_left_half
    from formations.files import dumps
    from formations.validation import check_ball_position

    longer = replace(STANDARD_FIELD, length=110.0)
    assert sample_balls_left_half(longer)[:, 0].max() == longer.half_length
    assert dumps(design_set("4-3-3", longer)) != dumps(design_set("4-3-3", STANDARD_FIELD))
    # The file readers check positions against the field they are given.
    path = tmp_path / "wide.json"
    formations.load_builtin("4-3-3").formation("normal").save(path)
    formations.load(path, field=STANDARD_FIELD)
    narrow = replace(STANDARD_FIELD, width=30.0, penalty_area_width=20.0, goal_area_width=16.0, goal_width=8.0)
    with pytest.raises(formations.FormationError, match=r"far outside the 105 x 30 m field"):
        formations.load(path, field=narrow)
    check_ball_position((STANDARD_FIELD.half_length + 9.0, 0.0), "--ball", STANDARD_FIELD)
    with pytest.raises(formations.FormationError, match="far outside"):
        check_ball_position((longer.half_length + 11.0, 0.0), "--ball", STANDARD_FIELD)
