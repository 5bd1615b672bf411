"""The client layer end to end against a fake server on 127.0.0.1 replaying an exchange
recorded from rcssserver 19: connection, parameters, steps, the quoted say, time-outs, bye."""

from __future__ import annotations

import time

import pytest

from rcss_bridge import ClientSettings, PlayerOrder, ServerError, TeamClient, TeamFailure, TeamTooSlow
from rcss_bridge.messages import SenseBody
from soccer_sim.state import PlayMode
from tests.rcss_bridge.fake_server import FakeServer, server_commands
from tests.rcss_bridge.recorded import received, sent


def _settings(server: FakeServer, **changes) -> ClientSettings:
    values = dict(port=server.port, coach_port=server.coach_port, connect=2, connect_timeout=3.0, step_timeout=3.0,
                  decision_budget=1.0)
    values.update(changes)
    return ClientSettings(**values)


def test_the_fake_server_reads_a_datagram_as_rcssserver_did():
    unquoted = "(turn 10)(say ABC)(done)"
    assert unquoted in sent("OTHERS-1")[20]
    said = server_commands(unquoted)[-1]
    assert said == "(say ABC)(done)"  # no (done): the step waits for it in vain
    assert any(t.endswith(f'self "{said[5:-1]}")') for t in received("OTHERS-1")[21])  # heard as "ABC)(done"
    assert server_commands('(turn 10)(say "A(B) C")(done)') == ["(turn 10)", '(say "A(B) C")', "(done)"]


def test_a_recorded_exchange_plays_through_the_client():
    with FakeServer() as server:
        steps = []
        with TeamClient("BRIDGE", _settings(server)) as team:
            team.connect()
            assert team.side == "l" and sorted(team.players) == [0, 1]
            assert len(team.parameters.types) == 18 and team.config.rules.half_cycles == 3000
            played = team.play(lambda step, row: PlayerOrder("(turn 5)", say="AB(C) 1"), steps=len(server.steps),
                               on_step=lambda step: steps.append(
                                   (step.step, step.server_time, step.views.play_mode, step.views.score,
                                    step.missed, tuple(step.coach_messages))))
        time.sleep(0.2)
    assert played == len(server.steps)
    # Shirt 1 got a (think) before shirt 2 had connected: the team's first step is the next
    # one, and that one step went by without shirt 1's (done) (counted in Step.missed).
    assert server.missed == [-1] and steps[0][4] == 1 and all(s[4] == 0 for s in steps[1:])
    assert server.byes == {"BRIDGE-1", "BRIDGE-2", "BRIDGE-coach"}
    for name in ("BRIDGE-1", "BRIDGE-2"):
        datagrams = [d for d in server.datagrams[name] if d not in ("(synch_see)", "(bye)")]
        assert len(datagrams) == played
        assert all(server_commands(d) == ["(turn 5)", '(say "AB(C) 1")', "(done)"] for d in datagrams)
    assert [s[0] for s in steps] == list(range(played))  # our own counter: one a step
    recorded_times = [max(int(t.split()[1]) for t in received("BRIDGE-1")[s] if t.startswith("(sense_body"))
                      for s in server.steps]
    assert [s[1] for s in steps] == recorded_times  # the server's clock, standing still at times
    assert recorded_times.count(0) > 3 and recorded_times.count(34) > 3
    modes = {s[2] for s in steps}
    assert {PlayMode.KICK_OFF, PlayMode.PLAY_ON, PlayMode.AFTER_GOAL} <= modes
    assert steps[-1][3] == (1, 0)
    assert any("(ok change_player_type 2 5)" in s[5] for s in steps)


def test_a_slow_decision_ends_with_the_player_and_the_step():
    with FakeServer() as server:
        team = TeamClient("BRIDGE", _settings(server, decision_budget=0.5))
        team.connect()

        def decide(step, row):
            if step.step == 3 and row == 1:
                time.sleep(2.0)
            return PlayerOrder("(dash 50)")

        with pytest.raises(TeamTooSlow, match=r"player 1 \(shirt 2\), step 3 \(server time 0\)") as info:
            team.play(decide)
        assert isinstance(info.value, TimeoutError) and (info.value.player, info.value.step) == (1, 3)
        time.sleep(0.3)
        assert server.byes == {"BRIDGE-1", "BRIDGE-2", "BRIDGE-coach"}


def test_a_decision_that_raises_ends_with_the_player_and_the_step():
    with FakeServer() as server:
        team = TeamClient("BRIDGE", _settings(server))
        team.connect()

        def decide(step, row):
            if step.step == 2 and row == 0:
                raise ValueError("no idea")
            return PlayerOrder()

        with pytest.raises(TeamFailure, match=r"player 0 \(shirt 1\), step 2 .*ValueError: no idea") as info:
            team.play(decide)
        assert isinstance(info.value.__cause__, ValueError)
        time.sleep(0.3)
        assert {"BRIDGE-1", "BRIDGE-2"} <= server.byes


def test_a_bad_say_is_the_teams_error_before_anything_is_sent():
    with FakeServer() as server:
        team = TeamClient("BRIDGE", _settings(server))
        team.connect()
        with pytest.raises(TeamFailure, match='player 0 .*say|player 0 .*character'):
            team.play(lambda step, row: PlayerOrder(say='a"b'))


def test_a_silent_server_is_an_error_not_a_hang():
    with FakeServer(silent_after=2) as server:
        team = TeamClient("BRIDGE", _settings(server, step_timeout=1.0))
        team.connect()
        started = time.monotonic()
        with pytest.raises(ServerError, match=r"no \(think\) for shirt\(s\) 1, 2 at step 2"):
            team.play(lambda step, row: PlayerOrder())
        assert time.monotonic() - started < 3.0


def test_a_refused_player_and_a_missing_server_are_clear():
    with FakeServer(players=("BRIDGE-1",), refuse_after=1) as server:
        with pytest.raises(ServerError, match="refused .*no_more_team_or_player_or_goalie"):
            TeamClient("BRIDGE", _settings(server)).connect()
    nobody = FakeServer()
    port = nobody.port
    nobody.listen.close()
    nobody.coach_listen.close()
    with pytest.raises(ServerError, match="no reply to .*within 0.3 s"):
        TeamClient("BRIDGE", ClientSettings(port=port, connect_timeout=0.3)).connect()


def test_the_step_messages_are_records():
    with FakeServer() as server:
        with TeamClient("BRIDGE", _settings(server)) as team:
            team.connect()
            step = team.next_step()
            assert set(step.inboxes) == {0, 1}
            assert any(isinstance(m, SenseBody) for m in step.inboxes[0])
            team.send_step({})


def test_a_team_command_goes_out_as_one_body_command_a_neck_turn_and_the_say():
    """The client's send path for a TeamCommand (rcss_bridge.commands): each connected player's
    datagram holds at most one body command, then turn_neck and the say, then (done); the
    coach gives the chosen player types; a malformed command ends with the player and the step."""
    import numpy as np

    from soccer_sim.team import TeamCommand

    with FakeServer() as server:
        with TeamClient("BRIDGE", _settings(server)) as team:
            team.connect()
            team.choose_player_types([0, 5] + [0] * 9)
            for _ in range(3):
                step = team.next_step()
                dash, kick = np.zeros((11, 2)), np.zeros((11, 2))
                dash[1] = kick[1] = (0.3, 0.0)  # a kick and a dash: the kick alone goes
                team.send_command(step, TeamCommand(dash=dash, kick=kick, say=["AB"] + [None] * 10))
            step = team.next_step()
            with pytest.raises(TeamFailure, match=r"player 1 \(shirt 2\), step 3 .*command.kick is not finite"):
                kick[1] = (np.nan, 0.0)
                team.send_command(step, TeamCommand(dash=dash, kick=kick))
        time.sleep(0.2)
    coach = [d for d in server.datagrams["BRIDGE-coach"] if d != "(bye)"]
    assert coach[:2] == ["(change_player_type 1 0)", "(change_player_type 2 5)"] and len(coach) == 11
    for name, said in (("BRIDGE-1", ['(say "AB")']), ("BRIDGE-2", [])):
        datagrams = [d for d in server.datagrams[name] if d not in ("(synch_see)", "(bye)")]
        assert len(datagrams) == 3
        for datagram in datagrams:
            commands = server_commands(datagram)
            body = [c for c in commands if not c.startswith(("(turn_neck", "(say", "(done"))]
            assert len(body) <= 1 and commands[-1] == "(done)" and commands[-1 - len(said):-1] == said
            if name == "BRIDGE-2" and body:
                assert body[0].startswith("(kick ")
