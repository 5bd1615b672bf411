"""The formations' field is the simulator's default field, number for number."""

from __future__ import annotations

from formations.field import STANDARD_FIELD
from soccer_sim.config import FieldConfig


def test_the_standard_field_is_the_simulators_default_field():
    field = FieldConfig()
    assert (STANDARD_FIELD.length, STANDARD_FIELD.width) == (field.length, field.width)
    assert (STANDARD_FIELD.half_length, STANDARD_FIELD.half_width) == (field.half_length, field.half_width)
    assert (STANDARD_FIELD.penalty_area_depth, STANDARD_FIELD.penalty_area_width) == (
        field.penalty_area_length, field.penalty_area_width)
    assert (STANDARD_FIELD.goal_area_depth, STANDARD_FIELD.goal_area_width) == (
        field.goal_area_length, field.goal_area_width)
    assert STANDARD_FIELD.goal_width == field.goal_width
    assert STANDARD_FIELD.centre_circle_radius == field.centre_circle_radius
