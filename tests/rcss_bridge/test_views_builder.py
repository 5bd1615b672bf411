"""Views built from messages recorded from rcssserver 19, against the trainer's exact positions."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rcss_bridge.messages import SenseBody, read_message
from rcss_bridge.views_builder import ViewsBuilder
from soccer_sim.perception.views import TEAMMATE
from soccer_sim.state import PlayMode
from tests.rcss_bridge.recorded import received, truth

DECAY = [0.4] * 18
"""Every type's player_decay (the dead reckoning between sees only: no type changes matter here)."""


def _replay(team: str, clients: dict[int, str], side: str):
    """Feed the recorded steps of ``clients`` (row -> client) to a builder; yield (recorder step,
    server time, views) after each."""
    builder = ViewsBuilder(team, side, 11, DECAY)
    boxes = {row: received(client) for row, client in clients.items()}
    for counter, step in enumerate(sorted(set().union(*boxes.values()))):
        inboxes = {row: [read_message(t) for t in box.get(step, [])] for row, box in boxes.items()}
        time = max((m.time for box in inboxes.values() for m in box if isinstance(m, SenseBody)), default=-1)
        yield step, time, builder.update(counter, inboxes)


def _angle_error(a: float, b: float) -> float:
    return abs((a - b + 180.0) % 360.0 - 180.0)


def test_own_position_and_body_follow_the_truth():
    checked = 0
    for step, _, views in _replay("BRIDGE", {0: "BRIDGE-1", 1: "BRIDGE-2"}, "l"):
        for row in (0, 1):
            if views.localised[row] and step in truth():
                x, y, body = truth()[step][("BRIDGE", row + 1)]
                assert math.hypot(*(views.position[row] - (x, y))) < 1.0
                assert _angle_error(views.body_direction[row], body) < 2.0
                checked += 1
    assert checked >= 10


def test_the_right_side_sees_itself_in_its_own_frame():
    checked = 0
    for step, _, views in _replay("OTHERS", {0: "OTHERS-1"}, "r"):
        if views.localised[0] and step in truth():
            x, y, body = truth()[step][("OTHERS", 1)]
            assert math.hypot(*(views.position[0] + (x, y))) < 1.0  # team frame: (x, y) -> (-x, -y)
            assert _angle_error(views.body_direction[0], body + 180.0) < 2.0
            checked += 1
    assert checked >= 5


def test_seen_ball_and_players_are_where_the_trainer_saw_them():
    balls = players = 0
    for step, _, views in _replay("BRIDGE", {0: "BRIDGE-1", 1: "BRIDGE-2"}, "l"):
        exact = truth().get(step)
        for row in (0, 1):
            if not views.saw[row] or exact is None:
                continue
            if views.ball_seen[row]:
                error = math.hypot(*(views.ball[row] - exact["ball"]))
                assert error < 1.0 + 0.05 * views.ball_distance[row]
                balls += 1
            for c in range(views.seen_count[row]):
                number, side = int(views.seen_number[row, c]), int(views.seen_side[row, c])
                if number < 0 or side == 0:
                    continue
                team = "BRIDGE" if side == TEAMMATE else "OTHERS"
                x, y, _ = exact[(team, number + 1)]
                assert math.hypot(*(views.seen_position[row, c] - (x, y))) < 1.0 + 0.05 * views.seen_distance[row, c]
                players += 1
            assert np.all(np.diff(views.seen_distance[row, :views.seen_count[row]]) >= 0)  # nearest first
    assert balls >= 5 and players >= 20


def test_play_modes_score_and_who_owns_them():
    seen = {step: (views.play_mode, views.mode_ours, views.score)
            for step, _, views in _replay("BRIDGE", {0: "BRIDGE-1", 1: "BRIDGE-2"}, "l")}
    assert seen[0] == (PlayMode.KICK_OFF, True, (0, 0))  # before_kick_off: the left kicks off
    assert seen[9] == (PlayMode.KICK_OFF, True, (0, 0))  # kick_off_l
    assert seen[41] == (PlayMode.PLAY_ON, False, (0, 0))
    assert seen[42] == (PlayMode.AFTER_GOAL, False, (1, 0))  # goal_l_1: the right kicks off next
    assert seen[93] == (PlayMode.KICK_OFF, False, (1, 0))  # kick_off_r
    other = {step: (views.mode_ours, views.score) for step, _, views in _replay("OTHERS", {0: "OTHERS-1"}, "r")}
    assert other[42] == (True, (0, 1)) and other[93] == (True, (0, 1))


def test_heard_messages_types_and_presence():
    order = []
    for step, _, views in _replay("BRIDGE", {0: "BRIDGE-1", 1: "BRIDGE-2"}, "l"):  # the views are overwritten
        order.append(step)
        if step == 42:
            break
    mates = dict(views.heard_mates[0])
    assert mates and all(text == f"m{index + 1}s41" for index, text in mates.items())
    assert all(text.startswith("m") for text in views.heard_opponents[0])
    assert 0 not in mates  # one's own say is not a team-mate's message
    assert views.player_types[1] == 5  # the coach's change_player_type 2 5
    assert views.player_types[10] == 10  # the server's type for shirt 11 at kick-off
    assert views.present.tolist() == [True, True] + [False] * 9
    assert np.all(np.isnan(views.position[2:])) and views.stamina[0] == pytest.approx(8000.0, abs=1000)
    assert views.cycle == order.index(42)  # the builder's counter, not the server's clock


def test_the_neck_angle_is_sense_bodys_head_angle():
    """A recorded sense_body with its head_angle set (the recordings keep the neck at 0): the
    views report it, directions stay relative to the body, and a row that hears nothing
    keeps the last one told."""
    text = next(t for t in received("BRIDGE-1")[42] if t.startswith("(sense_body"))
    turned = text.replace("(head_angle 0)", "(head_angle -45)")
    assert turned != text
    builder = ViewsBuilder("BRIDGE", "l", 11, DECAY)
    views = builder.update(0, {0: [read_message(turned)], 1: [read_message(text)]})
    assert views.neck_angle[:2].tolist() == [-45.0, 0.0]
    assert builder.necks[:2].tolist() == [-45.0, 0.0]
    views = builder.update(1, {1: [read_message(text)]})
    assert views.neck_angle[0] == -45.0


def test_the_view_width_is_sense_bodys_view_mode():
    text = next(t for t in received("BRIDGE-1")[42] if t.startswith("(sense_body"))
    narrow = text.replace("(view_mode high normal)", "(view_mode high narrow)")
    assert narrow != text
    builder = ViewsBuilder("BRIDGE", "l", 11, DECAY)
    views = builder.update(0, {0: [read_message(narrow)], 1: [read_message(text)]})
    assert views.view_width[:3].tolist() == [0, 1, 1]  # NARROW, NORMAL, and NORMAL for a row not heard
