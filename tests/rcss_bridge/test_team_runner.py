"""One of the project's teams through the client layer (:mod:`rcss_bridge.team_runner`)
against the fake server replaying the exchange recorded from rcssserver 19: the team is told
its side and the server's types, its types go through the coach, it is asked only once its
players know where they are, its ball belief aims the kicks on the steps without a see, and
a team that raises or overruns ends the match with the step named."""

from __future__ import annotations

import math
import time

import numpy as np
import pytest

from rcss_bridge import ClientSettings, ServerError, TeamClient, TeamFailure, TeamTooSlow
from rcss_bridge.team_runner import play_team
from soccer_sim.team import SideInfo, TeamCommand
from tests.rcss_bridge.fake_server import FakeServer, server_commands

KICKER = 1
"""The row of the recorded BRIDGE-2, who is asked to kick every step."""


class KickingTeam:
    """A team for the tests: player 2 kicks 1 m/cycle towards +x every step; it believes the
    ball lies 0.8 m from player 2 at 90 degrees to the team's +x (``believes``), or has no
    belief (None: the bridge then has only what the step's see shows)."""

    observation_modes = ("partial",)

    def __init__(self, believes: bool = True, fail_at: int | None = None, slow_at: int | None = None) -> None:
        self.believes = believes
        self.fail_at, self.slow_at = fail_at, slow_at
        self.info: SideInfo | None = None
        self.config = None
        self.cycles: list[int] = []
        self.saw: list[bool] = []
        self._position = np.zeros((11, 2))

    def choose_player_types(self, types, side_info):
        return [0, 3] + [0] * 9

    def reset(self, side_info, config, rng):
        self.info, self.config = side_info, config

    def act(self, views):
        self.cycles.append(views.cycle)
        self.saw.append(bool(views.saw[KICKER]))
        if views.cycle == self.fail_at:
            raise ValueError("no idea")
        if views.cycle == self.slow_at:
            time.sleep(2.0)
        self._position = views.position.copy()
        kick = np.zeros((11, 2))
        kick[KICKER] = (1.0, 0.0)
        return TeamCommand(dash=np.zeros((11, 2)), kick=kick)

    def believed_ball(self):
        ball = np.full((11, 2), np.nan)
        ball[KICKER] = self._position[KICKER] + (0.0, 0.8)
        return ball


class NoBeliefTeam(KickingTeam):
    """The same team without ``believed_ball`` (the bridge then knows only what it saw)."""

    believed_ball = None  # type: ignore[assignment]


def _settings(server: FakeServer, **changes) -> ClientSettings:
    values = dict(port=server.port, coach_port=server.coach_port, connect=2, connect_timeout=3.0, step_timeout=1.0,
                  decision_budget=1.0)
    values.update(changes)
    return ClientSettings(**values)


def _kicks(server: FakeServer) -> list[tuple[float, float]]:
    out = []
    for datagram in server.datagrams["BRIDGE-2"]:
        for command in server_commands(datagram):
            if command.startswith("(kick "):
                power, direction = command[6:-1].split()
                out.append((float(power), float(direction)))
    return out


def _play(team, **changes):
    with FakeServer() as server:
        client = TeamClient("BRIDGE", _settings(server, **changes))
        with pytest.raises(ServerError, match="no \\(think\\)"):  # the recording ends before time over
            play_team(team, "kickers", "others", client, seed=3)
        time.sleep(0.2)
    return server


def test_the_team_is_told_its_side_and_types_and_decides_once_located():
    team = KickingTeam()
    server = _play(team)
    assert team.info.team == 0 and team.info.name == "kickers" and team.info.opponent_name == "others"
    assert len(team.info.player_types) == 18 and team.info.own_types == (0, 3) + (0,) * 9
    assert team.config.observation.partial and team.config.rules.half_cycles == 3000
    coach = [d for d in server.datagrams["BRIDGE-coach"] if d.startswith("(change_player_type")]
    assert coach[:2] == ["(change_player_type 1 0)", "(change_player_type 2 3)"]
    assert team.cycles == sorted(team.cycles) and len(team.cycles) >= 10
    # not asked before every connected player had seen where it is (the first step)
    assert team.cycles[0] >= 1


def test_the_ball_belief_aims_the_kicks_between_sees():
    """On the steps without a see, the step's views hold no ball: without a belief the kick is
    sent as if the ball lay where both engines' rates agree; with the team's belief (ball
    beside the player) its power makes up for the server's lower rate there."""
    believing, blind = KickingTeam(), NoBeliefTeam()
    with_belief, without = _kicks(_play(believing)), _kicks(_play(blind))
    assert not all(believing.saw) and len(with_belief) == len(believing.cycles)
    unseen = [i for i, saw in enumerate(blind.saw) if not saw]
    assert unseen
    kick_power_rate = 0.027
    plain = 1.0 / kick_power_rate  # the request over the type's rate: both rates taken as equal
    assert all(math.isclose(without[i][0], round(plain, 2), abs_tol=0.01) for i in unseen)
    stronger = [i for i in range(len(with_belief)) if with_belief[i][0] > plain + 1.0]
    assert stronger and set(unseen) & set(stronger)


def test_a_team_that_raises_is_named_with_the_step():
    with FakeServer() as server:
        client = TeamClient("BRIDGE", _settings(server))
        with pytest.raises(TeamFailure, match=r"team 'kickers', every player .*, step 4 .*act\(\) raised "
                                              r"ValueError: no idea") as info:
            play_team(KickingTeam(fail_at=4), "kickers", "others", client, seed=0)
        assert info.value.step == 4
        time.sleep(0.3)
        assert {"BRIDGE-1", "BRIDGE-2", "BRIDGE-coach"} <= server.byes


def test_a_team_that_overruns_the_step_is_named_and_nothing_hangs():
    with FakeServer() as server:
        client = TeamClient("BRIDGE", _settings(server, decision_budget=0.5))
        started = time.monotonic()
        with pytest.raises(TeamTooSlow, match=r"step 3 .*act\(\) took longer than 0.5 s"):
            play_team(KickingTeam(slow_at=3), "kickers", "others", client, seed=0)
        assert time.monotonic() - started < 5.0
