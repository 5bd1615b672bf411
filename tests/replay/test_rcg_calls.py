"""rcssserver game logs: the referee's calls and the players' actions as the server shows
them (calls as play modes of their own, state flags, counters), the recorder driven cycle by
cycle through every case."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim import EventKind, Match, MatchConfig, PlayMode
from soccer_sim.rcg import RcgRecorder, read_rcg
from soccer_sim.rcg.mapping import play_mode_name
from soccer_sim.state import AWAY, HOME, NO_PLAYER, NO_TEAM

NONE = np.zeros(0, dtype=np.int64)


class Driver:
    """A started match whose state and events a test sets by hand, one cycle at a time."""

    def __init__(self, path) -> None:
        self.match = Match("idle", "idle", config=MatchConfig(max_cycles=50))
        self.match.start()
        self.recorder = RcgRecorder(path)
        self.recorder.on_start(self.match)

    def event(self, kind: EventKind, team: int = NO_TEAM, player: int = NO_PLAYER, detail: int = 0) -> None:
        self.match.events.add(self.match.state.cycle, kind, team, player, 0.0, 0.0, detail)

    def mode(self, mode: PlayMode, team: int = NO_TEAM) -> None:
        state = self.match.state
        state.play_mode, state.mode_team = mode, team
        if mode != PlayMode.PLAY_ON:
            self.event(EventKind.SET_PLAY, team, detail=int(mode))

    def cycle(self, kickers=NONE, touchers=NONE) -> None:
        match = self.match
        match.kickers, match.touchers = np.asarray(kickers, dtype=np.int64), np.asarray(touchers, dtype=np.int64)
        match.state.cycle += 1
        self.recorder.on_cycle(match)


def test_calls_become_rcssservers_play_mode_sequences(tmp_path) -> None:
    d = Driver(tmp_path / "calls.rcg")
    d.mode(PlayMode.PLAY_ON); d.cycle()                                     # 1
    d.event(EventKind.OFFSIDE, HOME, 9); d.mode(PlayMode.FREE_KICK, AWAY); d.cycle()  # 2: home offside
    d.mode(PlayMode.PLAY_ON); d.cycle()                                     # 3
    d.event(EventKind.BACK_PASS, AWAY, 0); d.mode(PlayMode.FREE_KICK, HOME); d.cycle()  # 4: away keeper
    d.mode(PlayMode.PLAY_ON); d.cycle()                                     # 5
    d.mode(PlayMode.FREE_KICK, AWAY); d.cycle()                             # 6: home keeper held too long
    d.mode(PlayMode.PLAY_ON); d.cycle()                                     # 7
    d.event(EventKind.DROP_BALL); d.cycle()                                 # 8: dropped, play on
    d.match.state.score[HOME] = 1; d.mode(PlayMode.AFTER_GOAL, AWAY); d.cycle()  # 9: home scored
    d.event(EventKind.HALF_TIME); d.mode(PlayMode.KICK_OFF, AWAY); d.cycle()     # 10
    d.mode(PlayMode.TIME_OVER); d.cycle()                                   # 11
    d.recorder.on_end(d.match)
    log = read_rcg(tmp_path / "calls.rcg")
    assert log.play_modes == [
        (0, "kick_off_l"), (1, "play_on"), (2, "offside_l"), (2, "free_kick_r"), (3, "play_on"),
        (4, "back_pass_r"), (4, "indirect_free_kick_l"), (5, "play_on"), (6, "indirect_free_kick_r"),
        (7, "play_on"), (8, "drop_ball"), (8, "play_on"), (9, "goal_l"), (10, "before_kick_off"),
        (10, "kick_off_r"), (11, "time_over")]
    assert log.teams == [(0, "idle", "idle", 0, 0), (9, "idle", "idle", 1, 0), (11, "idle", "idle", 1, 0)]
    assert [show.cycle for show in log.shows] == list(range(12))


def test_kicks_catches_and_touches_set_flags_and_counters(tmp_path) -> None:
    d = Driver(tmp_path / "flags.rcg")
    n = d.match.state.sizes[0]
    d.mode(PlayMode.PLAY_ON)
    d.cycle(kickers=[3], touchers=[n + 4])                                  # 1: home #4 kicks, away #5 is hit
    d.cycle(kickers=[3])                                                    # 2: kicks again
    d.event(EventKind.CATCH, AWAY, 0); d.mode(PlayMode.GOALIE_HOLDS, AWAY); d.cycle()  # 3: away keeper
    d.mode(PlayMode.PLAY_ON); d.cycle()                                     # 4
    d.recorder.on_end(d.match)
    log = read_rcg(tmp_path / "flags.rcg")
    shows = log.shows
    assert shows[1].player("l", 4).state == 0x1 | 0x2 and shows[1].player("r", 5).state == 0x1 | 0x400
    assert shows[1].player("l", 1).state == 0x1 | 0x8 and shows[1].player("l", 2).state == 0x1
    assert shows[3].player("r", 1).state == 0x1 | 0x8 | 0x10 and shows[4].player("r", 1).state == 0x1 | 0x8
    assert shows[4].player("l", 4).state == 0x1                             # flags last one cycle
    assert shows[4].player("l", 4).counts == (2,) + (0,) * 11               # counters add up
    assert shows[4].player("r", 1).counts[3] == 1
    assert (3, "free_kick_r") in log.play_modes                             # rcssserver's restart after a catch


def test_mode_names() -> None:
    assert play_mode_name(PlayMode.KICK_IN, AWAY) == "kick_in_r"
    assert play_mode_name(PlayMode.CORNER_KICK, HOME) == "corner_kick_l"
    assert play_mode_name(PlayMode.GOAL_KICK, AWAY) == "goal_kick_r"
    assert play_mode_name(PlayMode.AFTER_GOAL, HOME) == "goal_r"            # home kicks off: away scored
    assert play_mode_name(PlayMode.FREE_KICK, HOME, "free_kick") == "free_kick_l"
    with pytest.raises(ValueError):
        play_mode_name(99, HOME)


def test_fouls_become_foul_charges_then_the_free_kick_the_server_gives(tmp_path) -> None:
    d = Driver(tmp_path / "fouls.rcg")
    state = d.match.state
    d.mode(PlayMode.PLAY_ON); d.cycle()                                     # 1
    state.ball[:] = (10.0, 5.0)                                             # away's free kick in midfield
    d.event(EventKind.FOUL, HOME, 5); d.mode(PlayMode.FREE_KICK, AWAY); d.cycle()     # 2
    d.mode(PlayMode.PLAY_ON); d.cycle()                                     # 3
    state.ball[:] = (-52.5 + 16.5, 20.16)                                   # on the corner of home's penalty area
    d.event(EventKind.FOUL, HOME, 5); d.mode(PlayMode.FREE_KICK, AWAY); d.cycle()     # 4
    d.mode(PlayMode.PLAY_ON); d.cycle()                                     # 5
    state.ball[:] = (52.5 - 16.5 - 0.2, 0.0)                                # just outside away's penalty area
    d.event(EventKind.FOUL, AWAY, 2); d.mode(PlayMode.FREE_KICK, HOME); d.cycle()     # 6
    d.mode(PlayMode.FREE_KICK, HOME); d.cycle()                             # 7: a keeper's free kick again
    d.recorder.on_end(d.match)
    assert read_rcg(tmp_path / "fouls.rcg").play_modes == [
        (0, "kick_off_l"), (1, "play_on"), (2, "foul_charge_l"), (2, "free_kick_r"), (3, "play_on"),
        (4, "foul_charge_l"), (4, "indirect_free_kick_r"), (5, "play_on"),
        (6, "foul_charge_r"), (6, "free_kick_l"), (7, "indirect_free_kick_l")]


def test_tackle_flags_and_counter(tmp_path) -> None:
    d = Driver(tmp_path / "tackles.rcg")
    state = d.match.state
    n = state.sizes[0]
    d.mode(PlayMode.PLAY_ON)
    state.pos[3], state.vel[3], state.ball[:] = (0.0, 0.0), (0.0, 0.0), (1.0, 0.0)   # home #4, ball in reach
    state.pos[n + 6] = (3.0, 0.0)                                            # away #7, the ball 2 m away
    state.vel[n + 6] = 0.0
    d.cycle()                                                               # 1: the state the tackles see
    d.event(EventKind.TACKLE, HOME, 3, detail=0)                            # in reach, the draw failed
    d.event(EventKind.TACKLE, AWAY, 6, detail=0)                            # out of reach (x = 2 m)
    state.frozen[3] = state.frozen[n + 6] = 9                               # after the cycle's count-down
    d.cycle()                                                               # 2
    for cycle in range(3, 14):
        state.frozen[3] = state.frozen[n + 6] = max(0, 11 - cycle)
        state.frozen[n + 1] = max(0, 9 - cycle) if cycle >= 5 else 0        # away #2 fouled in cycle 5
        if cycle == 11:
            d.event(EventKind.TACKLE, AWAY, 1, detail=3)                    # a foul tackle that pushed: not frozen
            d.event(EventKind.YELLOW_CARD, AWAY, 1, detail=1)
            state.cards[n + 1] = 1
        d.cycle()
    d.recorder.on_end(d.match)
    shows = read_rcg(tmp_path / "tackles.rcg").shows
    home4 = [show.player("l", 4).state for show in shows]
    away7 = [show.player("r", 7).state for show in shows]
    away2 = [show.player("r", 2).state for show in shows]
    assert home4 == [0x1, 0x1] + [0x3001] * 10 + [0x1, 0x1]                 # up for tackle_cycles shows
    assert away7 == [0x1, 0x1] + [0x2001] * 10 + [0x1, 0x1]
    assert away2 == [0x1] * 5 + [0x20001] * 5 + [0x1, 0x41001, 0x40001, 0x40001]  # foul_cycles; a push: one show
    assert shows[-1].player("l", 4).counts[8] == 1 and shows[-1].player("r", 2).counts[8] == 1
    assert shows[-1].player("r", 7).counts == (0,) * 8 + (1,) + (0,) * 3
