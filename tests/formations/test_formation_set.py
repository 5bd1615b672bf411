"""FormationSet: picking a formation by situation."""

from __future__ import annotations

import numpy as np
import pytest

import formations
from formations import FormationSet, Situation, parse_situation


def test_situations_pick_their_own_formation():
    team = formations.load_builtin("4-3-3")
    ball = (-10.0, 12.0)
    for situation in Situation:
        own = team.own_formations()[situation]
        assert team.formation(situation) is own
        assert team.formation(situation.value) is own
        np.testing.assert_array_equal(team.positions(ball, situation), own.positions(ball))
        np.testing.assert_array_equal(team.positions(ball, situation.value), own.positions(ball))
    assert not np.allclose(team.positions(ball, "attack"), team.positions(ball, "defend"))


def test_kick_off_aliases_are_set_plays():
    team = formations.load_builtin("4-4-2")
    assert team.formation("our_kickoff") is team.formation(Situation.OUR_SET_PLAY)
    assert team.formation("their_kickoff") is team.formation(Situation.THEIR_SET_PLAY)
    assert team.formation("Their-Kick-Off") is team.formation(Situation.THEIR_SET_PLAY)
    assert parse_situation("OUR_SET_PLAY") is Situation.OUR_SET_PLAY


def test_unknown_situation_is_a_clear_error():
    team = formations.load_builtin("4-4-2")
    with pytest.raises(ValueError, match="unknown situation 'counter'; expected one of normal, attack"):
        team.positions((0.0, 0.0), "counter")


def test_missing_situations_fall_back_to_normal(random_formation):
    team = FormationSet("partial", {Situation.NORMAL: random_formation})
    assert team.situations == (Situation.NORMAL,)
    for situation in Situation:
        assert team.formation(situation) is random_formation
    many = team.positions_many(np.array([[0.0, 0.0], [5.0, 5.0]]), "defend")
    assert many.shape == (2, 11, 2)
