"""Position labels of formation roles (:mod:`agents.teams.positions`): the built-in systems
and formations of other shapes, labelled from their geometry."""

from __future__ import annotations

import numpy as np
import pytest

import formations
from agents.teams.positions import POSITIONS, position_codes, position_labels
from formations import Formation, FormationSet, Role


def _by_name(system: str) -> dict[str, str]:
    fs = formations.load_builtin(system)
    return {role.name: label for role, label in zip(fs.roles, position_labels(fs))}


def test_the_4_3_3_has_an_anchor_two_central_midfielders_wingers_and_a_centre_forward() -> None:
    labels = _by_name("4-3-3")
    assert labels["goalkeeper"] == "goalkeeper"
    assert labels["left back"] == labels["right back"] == "full-back"
    assert labels["left centre back"] == labels["right centre back"] == "centre-back"
    assert labels["defensive midfielder"] == "holding-midfielder"
    assert labels["left central midfielder"] == labels["right central midfielder"] == "central-midfielder"
    assert labels["left winger"] == labels["right winger"] == "winger"
    assert labels["centre forward"] == "centre-forward"


def test_the_4_4_2_has_a_flat_midfield_wide_midfielders_and_two_centre_forwards() -> None:
    labels = _by_name("4-4-2")
    assert labels["left back"] == labels["right back"] == "full-back"
    assert labels["left centre back"] == labels["right centre back"] == "centre-back"
    assert labels["left central midfielder"] == labels["right central midfielder"] == "central-midfielder"
    assert labels["left midfielder"] == labels["right midfielder"] == "wide-midfielder"
    assert labels["left striker"] == labels["right striker"] == "centre-forward"
    assert "holding-midfielder" not in labels.values()


def _fixed_set(spots: list[tuple[str, tuple[float, float]]]) -> FormationSet:
    """A formation set whose roles stand at fixed spots whatever the ball (kinds given)."""
    roles = [Role(i + 1, f"role {i + 1}", kind) for i, (kind, _) in enumerate(spots)]
    balls = np.array([(-50.0, -30.0), (-50.0, 30.0), (50.0, -30.0), (50.0, 30.0), (0.0, 0.0)])
    positions = np.repeat(np.array([spot for _, spot in spots], float)[None], len(balls), axis=0)
    return FormationSet("fixed", {"normal": Formation(roles, balls, positions)})


def test_labels_follow_the_geometry_of_any_formation() -> None:
    # A 3-5-2 with a back three, wing-backs listed as midfielders and a deep anchor.
    fs = _fixed_set([("goalkeeper", (-50.0, 0.0)), ("defender", (-20.0, -10.0)), ("defender", (-20.0, 0.0)),
                     ("defender", (-20.0, 10.0)), ("midfielder", (-12.0, 0.0)), ("midfielder", (-5.0, -9.0)),
                     ("midfielder", (-5.0, 9.0)), ("midfielder", (-2.0, -26.0)), ("midfielder", (-2.0, 26.0)),
                     ("forward", (10.0, -5.0)), ("forward", (10.0, 5.0))])
    assert position_labels(fs) == ("goalkeeper", "centre-back", "centre-back", "centre-back",
                                   "holding-midfielder", "central-midfielder", "central-midfielder",
                                   "wide-midfielder", "wide-midfielder", "centre-forward", "centre-forward")
    # Move the anchor up level with the others: a flat midfield has no holding midfielder.
    flat = _fixed_set([("goalkeeper", (-50.0, 0.0)), ("midfielder", (-5.0, 0.0)), ("midfielder", (-5.0, -9.0)),
                       ("midfielder", (-4.0, 9.0)), ("forward", (10.0, 20.0)), ("defender", (-20.0, 18.0))])
    assert position_labels(flat) == ("goalkeeper", "central-midfielder", "central-midfielder",
                                     "central-midfielder", "winger", "full-back")


def test_codes_index_the_labels_and_bad_input_is_refused() -> None:
    fs = formations.load_builtin("4-3-3")
    assert [POSITIONS[c] for c in position_codes(fs)] == list(position_labels(fs))
    with pytest.raises(TypeError, match="FormationSet"):
        position_labels("4-3-3")  # type: ignore[arg-type]
    with pytest.raises(ValueError, match="wide_fraction"):
        position_labels(fs, wide_fraction=1.5)
