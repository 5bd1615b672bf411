"""The goalkeeper's hold traced against rcssserver 19 (tests/data/rcssserver/goalkeeper.json,
recorded by tests/data/rcssserver/probes/record.py keeper): the same catch, moves, running out
of the free kick's time and catch fault, replayed through the referee, give the server's play
modes and the keeper's and ball's positions."""

import json
import math
from pathlib import Path

import pytest

from soccer_sim.config import MatchConfig
from soccer_sim.state import AWAY, HOME, NO_PLAYER, EventKind, PlayMode
from tests.soccer_sim.referee_world import N, catch, make_world, step

TRACE = json.loads((Path(__file__).parents[1] / "data" / "rcssserver" / "goalkeeper.json").read_text())
CFG = MatchConfig()
GK = 0


def keeper_world(keeper, ball):
    return make_world(ball=tuple(ball), moves={GK: tuple(keeper)}, last_touch=N + 9)


def test_defaults_are_the_servers():
    assert TRACE["meta"]["server_parameters"]["keeper"]["goalie_max_moves"] == CFG.rules.goalie_max_moves
    assert TRACE["meta"]["server_parameters"]["keeper"]["drop_ball_time"] == CFG.rules.set_play_timeout


def test_catch_and_moves_as_the_server():
    hold = TRACE["hold"]
    ref, st, ev = keeper_world(hold[0]["keeper"], hold[0]["ball"])
    catch(ref, st, HOME)
    step(ref, st)
    # the catch: goalie_catch_ball_l, then free_kick_l (GOALIE_HOLDS), the keeper stepped to the ball
    assert hold[1]["heard"] == ["goalie_catch_ball_l", "free_kick_l"]
    assert (st.play_mode, st.mode_team, st.ball_holder) == (PlayMode.GOALIE_HOLDS, HOME, GK)
    assert st.pos[GK].tolist() == pytest.approx(hold[1]["keeper"], abs=1e-3)
    assert st.ball.tolist() == pytest.approx(hold[1]["ball"], abs=1e-3)
    step(ref, st)  # the idle cycle
    for i in (2, 3, 4):  # three moves: two made, the third refused with (error too_many_moves)
        x, y = (float(v) for v in hold[i]["order"][len("(move "):-1].split())
        made = ref.move_keeper(st, x, y)
        step(ref, st)
        assert made == (hold[i + 1]["errors"] == [])
        assert st.play_mode == PlayMode.GOALIE_HOLDS
        assert st.pos[GK].tolist() == pytest.approx(hold[i + 1]["keeper"], abs=1e-3)
        assert st.ball.tolist() == pytest.approx(hold[i + 1]["ball"], abs=1e-3)
    assert hold[5]["errors"] == ["(error too_many_moves)"] and ref.goalkeeper.refused_moves == [1, 0]


def test_the_free_kicks_time_runs_out_as_on_the_server():
    rows = {row["i"]: row for row in TRACE["timeout"]}
    ref, st, ev = keeper_world(rows[0]["keeper"], rows[0]["ball"])
    catch(ref, st, HOME)
    state = 0  # the server's state index: each cycle (the catch's first) leads to the next state
    while st.play_mode == PlayMode.GOALIE_HOLDS or state == 0:
        step(ref, st)
        state += 1
    # the server: free_kick_l from state 1 to state 99, the ball dropped in the cycle to state 100
    assert "drop_ball" in rows[100]["heard"] and not rows[99]["heard"]
    assert state == 100
    assert st.play_mode == PlayMode.PLAY_ON and st.ball_holder == NO_PLAYER
    assert st.ball.tolist() == pytest.approx(rows[100]["ball"], abs=1e-3)


def test_a_dash_out_of_the_area_with_the_ball_is_a_catch_fault_as_on_the_server():
    trace = TRACE["leaves_area"]
    ref, st, ev = keeper_world(trace[0]["keeper"], trace[0]["ball"])
    catch(ref, st, HOME)
    step(ref, st)
    assert st.pos[GK].tolist() == pytest.approx(trace[1]["keeper"], abs=1e-3)
    fault = next(i for i, row in enumerate(trace) if "catch_fault_l" in row["heard"])
    for row in trace[2:fault + 1]:  # the server's dashes, the ball carried in front
        assert st.play_mode == PlayMode.GOALIE_HOLDS
        st.pos[GK] = row["keeper"]
        step(ref, st)
        if row is not trace[fault]:
            assert math.dist(st.ball, row["ball"]) < 1e-3
    [(_, team, _, x, y, _)] = ev.of_kind(EventKind.CATCH_FAULT)
    assert team == HOME and (x, y) == pytest.approx(trace[fault]["ball"], abs=1e-3)
    assert (st.play_mode, st.mode_team) == (PlayMode.FREE_KICK, AWAY)  # the server: free_kick_r
    assert any("free_kick_r" in row["heard"] for row in trace[fault:])
