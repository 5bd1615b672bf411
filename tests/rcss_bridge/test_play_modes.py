"""The referee's calls as the project's play modes (rcss_bridge.play_modes)."""

from __future__ import annotations

import pytest

from rcss_bridge.errors import ProtocolError
from rcss_bridge.play_modes import MODE_MAP, RefereeState
from soccer_sim.state import PlayMode


def _after(side: str, *calls: str) -> RefereeState:
    state = RefereeState(side)
    for call in calls:
        state.hear(call)
    return state


@pytest.mark.parametrize("calls, mode, ours", [
    ((), PlayMode.KICK_OFF, True),
    (("kick_in_r",), PlayMode.KICK_IN, False),
    (("offside_r",), PlayMode.FREE_KICK, True),  # the right's offside: the left's free kick
    (("foul_charge_l",), PlayMode.FREE_KICK, False),
    (("goal_r_1",), PlayMode.AFTER_GOAL, True),  # the left kicks off after the right's goal
    (("goalie_catch_ball_l",), PlayMode.GOALIE_HOLDS, True),
    (("goalie_catch_ball_l", "free_kick_l"), PlayMode.GOALIE_HOLDS, True),
    (("goalie_catch_ball_l", "free_kick_l", "play_on"), PlayMode.PLAY_ON, False),
    (("goalie_catch_ball_r", "free_kick_r"), PlayMode.GOALIE_HOLDS, False),
    (("free_kick_l",), PlayMode.FREE_KICK, True),
    (("half_time", "before_kick_off"), PlayMode.KICK_OFF, False),  # the right kicks off the second half
    (("drop_ball",), PlayMode.PLAY_ON, False),
    (("time_over",), PlayMode.TIME_OVER, False),
])
def test_calls_map_to_modes(calls, mode, ours):
    state = _after("l", *calls)
    assert (state.play_mode, state.mode_ours) == (mode, ours)
    mirrored = _after("r", *(c.replace("_l", "_X").replace("_r", "_l").replace("_X", "_r") for c in calls))
    assert mirrored.play_mode == mode


def test_score_half_and_cards():
    state = _after("r", "goal_l_1", "kick_off_r", "play_on", "goal_r_1", "goal_r_2", "yellow_card_l_5", "half_time",
                   "time_up")
    assert state.score == (2, 1) and state.half == 1
    assert state.cards == [("yellow_card", "l", 5)] and state.last_call == "time_up"
    assert state.play_mode == PlayMode.AFTER_GOAL  # time_up is not a mode


def test_every_server_mode_is_mapped():
    from tests.rcss_bridge.recorded import exchange  # noqa: F401 - the data are there too
    names = {"before_kick_off", "time_over", "play_on", "drop_ball", "first_half_over", "pause", "human_judge"}
    sided = {"kick_off", "kick_in", "free_kick", "corner_kick", "goal_kick", "goal", "offside", "penalty_kick",
             "foul_charge", "foul_push", "foul_multiple_attack", "foul_ballout", "back_pass", "free_kick_fault",
             "catch_fault", "indirect_free_kick", "penalty_setup", "penalty_ready", "penalty_taken", "penalty_miss",
             "penalty_score", "illegal_defense"}
    assert names | sided == set(MODE_MAP)


def test_a_side_is_l_or_r():
    with pytest.raises(ProtocolError, match="'l' or 'r'"):
        RefereeState("x")
