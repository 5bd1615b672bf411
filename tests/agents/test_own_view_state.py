"""The own-view positioning's compiled record (:mod:`agents.teams.own_view_state`): it shares
the positioning's and the world models' arrays, so what the compiled steps write is what the
team reads, and a new world model or vote book gets a new record."""

from __future__ import annotations

import numpy as np
import pytest
from numba import njit

from agents.teams.own_view_state import FIELDS, PositioningState, state_of
from soccer_sim import MatchConfig
from soccer_sim.match import Match
from soccer_sim.perception.config import ObservationConfig

PARTIAL = MatchConfig(observation=ObservationConfig("partial"), max_cycles=60)


@njit
def _fields(state):
    """Some of a record's arrays, read in compiled code."""
    return state.targets, state.goals, state.followed, state.proposals, state.ball, state.mate_pos, state.votes


def _played_team():
    match = Match("mmdr", "static", seed=3, config=PARTIAL)
    match.run()
    return match.teams[0].players


def test_the_record_shares_the_positionings_and_the_world_models_arrays() -> None:
    play = _played_team()
    positioning, beliefs = play.positioning, play.beliefs
    state = positioning._state
    assert isinstance(state, PositioningState)
    own = (positioning.targets, positioning.goals, positioning.followed, positioning.proposals, beliefs.ball,
           beliefs.mate_pos, play.votes.votes)
    for read, array in zip(_fields(state), own):
        assert read.shape == array.shape and np.shares_memory(read, array)
    beliefs.ball[0, 0] = 12.5  # a change on either side shows on the other
    assert _fields(state)[4][0, 0] == 12.5


def test_a_new_world_model_or_vote_book_gets_a_new_record() -> None:
    play = _played_team()
    positioning = play.positioning
    state = positioning._state
    assert positioning._state_for(play.beliefs, play.votes) is state
    other = positioning._state_for(play.beliefs, None)
    assert other is not state and _fields(other)[6].shape[2] == 0  # no votes: an empty vote book


def test_a_record_of_missing_or_unknown_fields_is_refused_by_name() -> None:
    values = {name: 0 for name in FIELDS if name != "goals"}
    with pytest.raises(ValueError, match=r"missing \['goals'\], unknown \['goal'\]"):
        state_of({**values, "goal": 0})
