"""rcssserver game logs of a match with tackles, fouls and cards: the tackle counter and the
TACKLE / TACKLE_FAULT flags add up to the match statistics the way rcssserver's logs are
read (counter 8 going up; TACKLE without TACKLE_FAULT in that show is a tackle won), fouls
are rcssserver's foul_charge play modes, cards and the player sent off are the server's
flags, and the sides list 11 players with the missing ones disabled."""

from __future__ import annotations

import time
from dataclasses import replace

import numpy as np
import pytest

from soccer_sim import AWAY, HOME, EventKind, MatchConfig, TeamCommand
from soccer_sim.config import TackleConfig
from soccer_sim.match import Match
from soccer_sim.rcg import RcgRecorder, read_rcg
from soccer_sim.rcg.marks import TACKLE_COUNT
from soccer_sim.scenarios import BallStart, Scenario, Side

TACKLE, TACKLE_FAULT, DISCARD, FOUL_CHARGED, YELLOW, RED = 0x1000, 0x2000, 0x100, 0x20000, 0x40000, 0x80000
CARRIER = 1
STARTED = 1_700_000_000.0


class Carrier:
    """Player 1 walks the ball towards its own +x, pushing it with its body and so keeping it
    within reach (a walker pushes a ball it runs into; a sprinter would pass through it); the
    others stand."""

    def reset(self, side_info, config, rng) -> None:
        self.n = side_info.players_per_team
        self.reach = config.physics.kickable_distance

    def act(self, view) -> TeamCommand:
        dash, kick = np.zeros((self.n, 2)), np.zeros((self.n, 2))
        me, ball = view.own_pos[CARRIER], view.ball
        dash[CARRIER] = (ball - me) * 0.3 + (0.05, 0.0)  # one body command a cycle: the walk pushes the ball
        return TeamCommand(dash=dash, kick=kick)


class Tackler:
    """Player 1 chases the ball and tackles it whenever it is within 2.6 m (beyond the 2 m
    reach too), every other tackle a foul one."""

    def reset(self, side_info, config, rng) -> None:
        self.n = side_info.players_per_team
        self.tries = 0

    def act(self, view) -> TeamCommand:
        dash = np.zeros((self.n, 2))
        me, ball = view.own_pos[CARRIER], view.ball
        dash[CARRIER] = (ball - me) * 0.5
        tackle = np.full(self.n, np.nan)
        foul = np.zeros(self.n, dtype=bool)
        if view.present[CARRIER] and view.frozen[CARRIER] == 0 and np.hypot(*(ball - me)) < 2.6:
            tackle[CARRIER] = 0.0
            foul[CARRIER] = self.tries % 2 == 1
            self.tries += 1
        return TeamCommand(dash=dash, kick=np.zeros((self.n, 2)), tackle=tackle, foul=foul)


@pytest.fixture(scope="module")
def logged(tmp_path_factory):
    """Home (3 players) tackles away's carrier (2 players) until sent off; logged."""
    path = tmp_path_factory.mktemp("rcg") / "tackles.rcg"
    scenario = Scenario(name="tackles", home=Side(players=3, goalie=None, positions=((-30.0, 20.0), (1.5, 0.0),
                                                                                      (-30.0, -20.0))),
                        away=Side(players=2, goalie=None, positions=((30.0, 20.0), (0.0, 0.0))),
                        ball=BallStart(position=(-0.7, 0.0)), start_mode="play_on", cycle_limit=900,
                        half_time=False)
    config = replace(MatchConfig(), tackles=TackleConfig(foul_detect_probability=1.0))
    match = Match(Tackler(), Carrier(), seed=7, config=config, scenario=scenario,  # a yellow, then a red card
                  recorders=[RcgRecorder(path, started=STARTED)])
    result = match.run()
    return path, result, read_rcg(path)


def test_tackle_counter_and_flags_add_up_to_the_statistics(logged) -> None:
    _, result, log = logged
    home = result.statistics[HOME]
    assert home.tackles > 5 and 0 < home.tackles_won < home.tackles and home.fouls > 0
    # counted as rcssserver's logs are read (the rcssserver kit's rcg_stats.py does the same)
    tries, won, previous = {"l": 0, "r": 0}, {"l": 0, "r": 0}, {}
    for show in log.shows:
        for p in show.players:
            key = (p.side, p.unum)
            if key in previous and p.counts[TACKLE_COUNT] > previous[key]:
                tries[p.side] += 1
                won[p.side] += bool(p.state & TACKLE and not p.state & TACKLE_FAULT)
            previous[key] = p.counts[TACKLE_COUNT]
    # as in rcssserver, a tackler sent off for its tackle is shown sent off (DISCARD | RED_CARD):
    # its tackle, won, has no TACKLE flag left to see
    events = result.events
    reds = {cycle for cycle, *_ in events.of_kind(EventKind.RED_CARD)}
    won_and_sent_off = sum(1 for cycle, _, _, _, _, detail in events.of_kind(EventKind.TACKLE)
                           if detail & 1 and cycle in reds)
    assert won_and_sent_off == 1
    assert (tries["l"], won["l"]) == (home.tackles, home.tackles_won - won_and_sent_off)
    assert (tries["r"], won["r"]) == (0, 0)
    last = log.shows[-1]
    assert sum(p.counts[TACKLE_COUNT] for p in last.players if p.side == "l") == home.tackles


def test_tackle_flags_stay_up_while_the_tackler_is_frozen(logged) -> None:
    _, result, log = logged
    events = result.events
    # an event of cycle c shows in the show line of cycle c + 1 (the state after that cycle)
    tackles = [(cycle + 1, detail) for cycle, team, player, _, _, detail in events.of_kind(EventKind.TACKLE)]
    shows = {show.cycle: show for show in log.shows}
    missed = set()
    for cycle, detail in tackles:
        state = shows[cycle].player("l", CARRIER + 1).state
        if not state & 0x1:                               # sent off for this tackle
            assert state == DISCARD | RED
        elif detail & 1:
            assert state & (TACKLE | TACKLE_FAULT) == TACKLE
        else:
            assert state & TACKLE_FAULT
            missed.add(state & (TACKLE | TACKLE_FAULT))
        if detail != 3:                                   # frozen: the flags stay up tackle_cycles shows
            up = [shows[c].player("l", CARRIER + 1).state & (TACKLE | TACKLE_FAULT) for c in range(cycle, cycle + 10)
                  if c in shows and shows[c].player("l", CARRIER + 1).present]
            assert len(set(up)) == 1
    assert missed == {TACKLE_FAULT, TACKLE | TACKLE_FAULT}   # out of reach, and in reach with the draw failed
    fouled = [p.state & FOUL_CHARGED for show in log.shows for p in show.players if p.side == "r"]
    assert any(fouled)


def test_fouls_are_foul_charges_then_the_free_kick(logged) -> None:
    _, result, log = logged
    fouls = result.events.of_kind(EventKind.FOUL)
    charges = [(cycle, mode) for cycle, mode in log.play_modes if mode.startswith("foul_charge")]
    assert [(cycle + 1, "foul_charge_l") for cycle, *_ in fouls] == charges
    for cycle, _ in charges:
        after = log.play_modes[log.play_modes.index((cycle, "foul_charge_l")) + 1]
        assert after[0] == cycle and after[1] in ("free_kick_r", "indirect_free_kick_r")
    assert result.statistics[HOME].fouls == len(charges) and result.statistics[AWAY].fouls == 0


def test_cards_and_the_player_sent_off(logged) -> None:
    _, result, log = logged
    events = result.events
    (yellow, *_), = events.of_kind(EventKind.YELLOW_CARD)
    (red, *_), = events.of_kind(EventKind.RED_CARD)
    yellow, red = yellow + 1, red + 1                     # the shows after the cards' cycles
    unum = CARRIER + 1
    for show in log.shows:
        p = show.player("l", unum)
        if show.cycle < yellow:
            assert p.state & (YELLOW | RED) == 0 and p.present
        elif show.cycle < red:
            assert p.state & (YELLOW | RED) == YELLOW and p.present
        else:                                             # sent off: DISCARD | RED_CARD, parked, still
            assert p.state == DISCARD | RED and not p.present
            assert (p.x, p.y, p.vx, p.vy) == (-3.0 * unum, -37.0, 0.0, 0.0)
    final = log.shows[-1].player("l", unum)
    assert final.counts[TACKLE_COUNT] == result.statistics[HOME].tackles   # its counters stay
    # 3 and 2 players fielded: the other shirt numbers are disabled players
    assert [p.unum for p in log.shows[-1].players if p.present] == [1, 3, 1, 2]
    assert len(log.shows[-1].players) == 22


def test_the_log_ends_with_the_result_message(logged) -> None:
    path, result, log = logged
    lines = path.read_text().splitlines()
    stamp = time.strftime("%Y%m%d%H%M", time.localtime(STARTED))
    home, away = result.score
    assert lines[-2] == f'(msg {result.cycles} 1 "(result {stamp} Tackler_{home}-vs-Carrier_{away})")'
    assert log.messages == [(result.cycles, 1, f"(result {stamp} Tackler_{home}-vs-Carrier_{away})")]
    assert lines[-1] == f"(team {result.cycles} Tackler Carrier {home} {away})"
