"""rcssserver game logs: a match written as a .rcg and read back line by line agrees with
the simulator's own record (positions in rcssserver's frame, play modes, score, counters),
and the lines have the shape rcssserver 19 writes."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from soccer_sim import EventKind, MatchConfig, PlayMode, run_match
from soccer_sim.config import RuleConfig
from soccer_sim.rcg import RcgError, RcgRecorder, read_rcg
from soccer_sim.rcg.defaults import SERVER_PARAMS
from soccer_sim.rcg.mapping import play_mode_name
from soccer_sim.rcg.reader import parse_show

SIDES = ("l", "r")

REAL_SHOW = ("(show 200 ((b) 16.6242 -33.1328 -0.1476 -0.0735) ((l 1) 0 0x9 -15 5 0 0 0 0 (v h 120) (fp 0 0) "
             "(s 8000 1 1 130600) (c 0 0 0 0 1 0 0 0 0 0 0 0)) ((r 2) 1 0x1 21.5357 -28.7013 -0.2833 -0.1459 "
             "-147.175 0 (v h 120) (fp 0 0) (s 958.477 0.824166 0.936 121642) (c 2 160 37 0 1 0 0 0 0 0 0 0)))")
"""A show line of rcssserver 19.0.0 (game_log_version 6), two of its players kept."""


class Trajectory:
    """The simulator's own record of every cycle, to compare the game log with."""

    def on_start(self, match) -> None:
        self.cycles, self.pos, self.vel, self.ball, self.score, self.attacks = [], [], [], [], [], []
        self.stamina = []
        self.type_ids = match.type_ids.copy()  # each player's type (the built-in team chooses some)
        self.on_cycle(match)

    def on_cycle(self, match) -> None:
        state = match.state
        self.cycles.append(state.cycle)
        self.pos.append(state.pos.copy())
        self.vel.append(state.vel.copy())
        self.ball.append(np.concatenate((state.ball, state.ball_vel)))
        self.score.append(tuple(int(g) for g in state.score))
        self.attacks.append(state.home_attacks)
        self.stamina.append(state.stamina.copy())

    def on_end(self, match) -> None:
        pass


@pytest.fixture(scope="module")
def logged(tmp_path_factory):
    """A 600-cycle match with halves of 300 cycles (two goals, catches, set plays), logged."""
    path = tmp_path_factory.mktemp("rcg") / "match.rcg"
    trajectory = Trajectory()
    config = MatchConfig(max_cycles=600, rules=RuleConfig(half_cycles=300))
    result = run_match("mmdr", "chaser", seed=4, config=config, recorders=[trajectory, RcgRecorder(path)])
    return path, trajectory, result, read_rcg(path)


def test_positions_are_the_simulators_in_rcssservers_frame(logged) -> None:
    _, trajectory, _, log = logged
    assert [show.cycle for show in log.shows] == trajectory.cycles == list(range(601))
    assert trajectory.cycles[-1] > 300 and set(trajectory.attacks) == {1}  # both halves, the same ends
    for show, pos, vel, ball, s in zip(log.shows, trajectory.pos, trajectory.vel, trajectory.ball, trajectory.attacks):
        turn = np.array([s, -s])                      # y down
        assert np.allclose(show.ball, np.concatenate((ball[:2] * turn, ball[2:] * turn)), atol=6e-5)
        players = sorted(show.players, key=lambda p: (p.side, p.unum))
        assert [(p.side, p.unum) for p in players] == [(side, k) for side in SIDES for k in range(1, 12)]
        assert np.allclose([(p.x, p.y) for p in players], pos * turn, atol=6e-5)
        assert np.allclose([(p.vx, p.vy) for p in players], vel * turn, atol=6e-5)
    # the home goalkeeper keeps the left goal in both halves, as rcssserver's left team does
    assert all(show.player("l", 1).x < -30 for show in log.shows)


def test_players_state_type_stamina_and_body(logged) -> None:
    _, trajectory, _, log = logged
    rows = {(side, unum): row for row, (side, unum) in
            enumerate([("l", u) for u in range(1, 12)] + [("r", u) for u in range(1, 12)])}
    assert trajectory.type_ids.any() and not trajectory.type_ids[11:].any()  # mmdr chooses types, chaser not
    for show in log.shows:
        for p in show.players:
            assert p.state & 0x1 and p.type == trajectory.type_ids[rows[(p.side, p.unum)]]
            assert bool(p.state & 0x8) == (p.unum == 1)  # goalie flag on the keepers only
    last = log.shows[-1]
    players = sorted(last.players, key=lambda p: (p.side, p.unum))
    assert np.allclose([p.stamina for p in players], trajectory.stamina[-1], rtol=1e-5)
    # at the kick-off everyone stands still, so each body faces the ball (rcssserver's angles: degrees, y down)
    first = log.shows[0]
    bx, by = first.ball[:2]
    for p in first.players:
        if math.hypot(bx - p.x, by - p.y) > 0:
            towards = math.degrees(math.atan2(by - p.y, bx - p.x))
            assert (p.body - towards + 180.0) % 360.0 - 180.0 == pytest.approx(0.0, abs=2e-3)


def test_play_modes_follow_the_referee(logged) -> None:
    _, _, result, log = logged
    modes = log.play_modes
    assert modes[0] == (0, "kick_off_l") and modes[-1] == (600, "time_over")
    assert all(a[1] != b[1] for a, b in zip(modes, modes[1:]))   # written on changes (and calls) only
    named = set(modes)
    set_plays = [(cycle, team, PlayMode(detail)) for cycle, team, _, _, _, detail
                 in result.events.of_kind(EventKind.SET_PLAY)]
    assert len(set_plays) > 5 and set_plays[0] == (0, 0, PlayMode.KICK_OFF)    # the opening kick-off: show 0
    for cycle, team, mode in set_plays[1:]:    # the show after the referee's call carries the new mode
        assert (cycle + 1, play_mode_name(mode, team)) in named
    half_time = modes.index((300, "before_kick_off"))       # as rcssserver at half time
    assert modes[half_time + 1] == (300, "kick_off_r")           # then away kicks off the second half


def test_score_lines_and_goals(logged) -> None:
    _, trajectory, result, log = logged
    goals = result.events.of_kind(EventKind.GOAL)
    assert len(goals) >= 2 and len(goals) == sum(result.score)  # (the recorded match has goals to check)
    assert log.teams[0] == (0, "mmdr", "chaser", 0, 0)
    assert log.teams[-1] == (600, "mmdr", "chaser", *result.score)
    for cycle, team, *_ in goals:
        assert (cycle + 1, f"goal_{SIDES[team]}") in log.play_modes
        line = next(t for t in log.teams if t[0] == cycle + 1)
        assert line[3:] == trajectory.score[cycle + 1]


def test_kick_and_catch_counters_add_up_to_the_statistics(logged) -> None:
    _, _, result, log = logged
    last = log.shows[-1]
    for team, side in enumerate(SIDES):
        kicks = sum(p.counts[0] for p in last.players if p.side == side)
        assert kicks == result.statistics[team].kicks
        catches = sum(p.counts[3] for p in last.players if p.side == side)
        assert catches == sum(1 for e in result.events.of_kind(EventKind.CATCH) if e[1] == team)
    flagged = sum(bool(p.state & 0x2) for show in log.shows for p in show.players)
    assert flagged == sum(p.counts[0] for p in last.players)    # the kick flag is up in the kick's cycle only


def test_header_parameters_and_player_types(logged) -> None:
    path, _, _, log = logged
    assert path.read_text().split("\n", 1)[0] == "ULG6"
    assert list(log.server_params) == [name for name, _ in SERVER_PARAMS]
    assert log.server_params["half_time"] == "30"           # seconds: 300 cycles of 100 ms
    assert log.server_params["goal_width"] == "14.02" and log.server_params["player_size"] == "0.3"
    assert log.player_params["player_types"] == "18"
    assert [t["id"] for t in log.player_types] == [str(k) for k in range(18)]
    assert log.player_types[0]["player_decay"] == "0.4" and log.player_types[0]["kickable_margin"] == "0.7"
    drawn = log.player_types[1:]  # the match's drawn types (soccer_sim.player_types)
    assert all(0.3 <= float(t["player_decay"]) <= 0.5 and 0.6 <= float(t["kickable_margin"]) <= 0.8 for t in drawn)
    assert len({t["player_decay"] for t in drawn}) == 17


def test_show_lines_have_rcssservers_shape(logged) -> None:
    path, *_ = logged

    def shape(text: str) -> list[str]:
        words = re.sub(r"0x[0-9a-f]+|-?\d+(\.\d+)?(e[-+]?\d+)?", "N", text).replace("((r ", "((l ")
        return re.findall(r"\(\(l N\)[^()]*(?:\([^()]*\)[^()]*)*\)", words)

    ours = next(line for line in path.read_text().splitlines() if line.startswith("(show 200 "))
    real = shape(REAL_SHOW)[0]
    assert len(shape(ours)) == 22 and all(player == real for player in shape(ours))
    real_player = parse_show(REAL_SHOW).player("r", 2)    # the reader reads rcssserver's own lines too
    assert real_player.counts[:3] == (2, 160, 37) and real_player.capacity == 121642


def test_reader_refuses_what_is_not_a_game_log(tmp_path) -> None:
    other = tmp_path / "other.rcg"
    other.write_text("ULG5\n")
    with pytest.raises(RcgError, match="other.rcg: not a version 6 game log"):
        read_rcg(other)
    broken = tmp_path / "broken.rcg"
    broken.write_text("ULG6\n(playmode 0 kick_off_l)\n(show 1 ((b) 0 0 0 0) ((l 1) junk))\n")
    with pytest.raises(RcgError, match=r"broken.rcg, line 3: .*unreadable player text"):
        read_rcg(broken)
    with pytest.raises(RcgError, match="cannot read"):
        read_rcg(tmp_path / "missing.rcg")
    assert isinstance(RcgError("x"), ValueError)


def test_a_scenario_with_fewer_players_and_no_keeper(tmp_path) -> None:
    from soccer_sim.scenarios import get_scenario

    path = tmp_path / "s.rcg"
    result = run_match("chaser", "idle", seed=0, scenario=get_scenario("empty-goal"), recorders=[RcgRecorder(path)])
    log = read_rcg(path)
    for show in (log.shows[0], log.shows[-1]):
        # rcssserver lists 11 players a side: the one fielded (no keeper), the others disabled
        assert [(p.side, p.unum) for p in show.players] == [(side, k) for side in SIDES for k in range(1, 12)]
        assert [p.present for p in show.players] == [True] + [False] * 21
        assert show.player("l", 1).state == 0x1
        for p in show.players[1:]:                        # state 0, parked as the server parks them
            assert (p.state, p.x, p.y, p.vx, p.vy, p.body) == (0, 3.0 * p.unum * (1 if p.side == "r" else -1), -37.0,
                                                                0.0, 0.0, 0.0)
            assert (p.stamina, p.effort, p.recovery, p.capacity, p.counts) == (8000, 1, 1, 130600, (0,) * 12)
    line = next(line for line in path.read_text().splitlines() if line.startswith("(show 0 "))
    assert " ((l 2) 0 0 -6 -37 0 0 0 0 (v h 90) (fp 0 0) (s 8000 1 1 130600) (c 0 0 0 0 0 0 0 0 0 0 0 0)) " in line
    assert log.teams[-1] == (result.cycles, "chaser", "idle", *result.score) and result.score == (1, 0)
    assert len(log.teams) == len(set(log.teams))           # the final score is written once
