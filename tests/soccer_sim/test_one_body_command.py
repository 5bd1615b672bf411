"""One body command per player and cycle, as rcssserver (``M_command_done`` in ``player.cpp``):
of the commands a team sends for a player in one cycle the match executes the one of highest
priority, tackle > catch > kick > move > dash, drops the others and counts them."""

from __future__ import annotations

import math

import numpy as np

from soccer_sim import MatchConfig, PlayMode, TeamCommand, run_match
from soccer_sim.kernels import one_body_command

NaN = math.nan


def rule(commands, tackle=None, catch=(False, False), goalie_rows=(0, 2), moving=None, home=2):
    """Apply the rule to 4 players (2 a side); returns (commands, catch, moving, ignored)."""
    commands = np.array(commands, dtype=np.float64)
    p = commands.shape[0]
    tackle = np.full(p, NaN) if tackle is None else np.array(tackle, dtype=np.float64)
    catch = np.array(catch, dtype=bool)
    moving = np.zeros(p, dtype=bool) if moving is None else np.array(moving, dtype=bool)
    ignored = np.zeros(2, dtype=np.int64)
    one_body_command(commands, tackle, catch, np.array(goalie_rows, dtype=np.int64), moving, home, ignored)
    return commands, catch, moving, ignored


def test_a_kick_and_a_dash_sent_together_the_kick_is_taken_the_dash_dropped_and_counted() -> None:
    commands, _, _, ignored = rule([[0, 0, 0, 0], [1.0, 0.5, 2.0, 0.0], [0.3, 0, 0, 0], [0, 0, 0, 0]])
    assert commands[1].tolist() == [0.0, 0.0, 2.0, 0.0]     # the kick stays, the dash goes
    assert commands[2].tolist() == [0.3, 0.0, 0.0, 0.0]     # a dash alone is executed
    assert ignored.tolist() == [1, 0]


def test_the_priority_is_tackle_catch_kick_move_dash() -> None:
    # row 0 (home goalkeeper) tackles, asks to catch, kicks and dashes: only the tackle remains
    commands, catch, _, ignored = rule([[1, 0, 1, 0], [0, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]],
                                       tackle=[0.5, NaN, NaN, NaN], catch=(True, False))
    assert not commands[0].any() and not catch[0] and ignored.tolist() == [3, 0]
    # the away goalkeeper (row 2) catches: its kick and dash are dropped, the catch stays
    commands, catch, _, ignored = rule([[0, 0, 0, 0], [0, 0, 0, 0], [1, 0, 1, 0], [0, 0, 0, 0]],
                                       catch=(False, True))
    assert not commands[2].any() and catch[1] and ignored.tolist() == [0, 2]
    # a kick beats a kick-off move, a move beats a dash
    commands, _, moving, ignored = rule([[0, 0, 1, 0], [1, 0, 0, 0], [0, 0, 0, 0], [0, 0, 0, 0]],
                                        moving=[True, True, False, False])
    assert moving.tolist() == [False, True, False, False]
    assert commands[0].tolist() == [0, 0, 1, 0] and not commands[1].any() and ignored.tolist() == [2, 0]


def test_a_catch_request_of_a_field_player_drops_nothing() -> None:
    commands, catch, _, ignored = rule([[0, 0, 0, 0], [1, 0, 1, 0], [0, 0, 0, 0], [0, 0, 0, 0]],
                                       catch=(True, False))
    assert commands[1].tolist() == [0, 0, 1, 0] and catch[0] and ignored.tolist() == [1, 0]


class KickAndDash:
    """Player 1 stands on the ball and, every cycle of play on, kicks it gently forwards while
    asking to dash too."""

    def reset(self, side_info, config, rng) -> None:
        n = side_info.players_per_team
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view) -> TeamCommand:
        command = self.command
        command.kick[:] = 0.0
        command.dash[:] = 0.0
        command.move = None
        if view.play_mode == PlayMode.KICK_OFF:
            command.move = view.own_pos.copy()
            command.move[1] = view.ball + np.array([-0.5, 0.0])
        near = np.hypot(*(view.own_pos[1] - view.ball)) < 1.0
        if near:
            command.kick[1] = (0.3, 0.0)
        command.dash[1] = (100.0, 0.0)
        return command


class Still:
    def reset(self, side_info, config, rng) -> None:
        n = side_info.players_per_team
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view) -> TeamCommand:
        return self.command


class KickerWatch:
    """A recorder counting the cycles in which player 1 kicked and its speed did not grow
    (no dash executed: the velocity only decays)."""

    def on_start(self, match) -> None:
        self.speed = 0.0
        self.kicked_and_still = self.kicks = 0

    def on_cycle(self, match) -> None:
        speed = float(np.hypot(*match.state.vel[1]))
        if 1 in match.kickers.tolist():
            self.kicks += 1
            self.kicked_and_still += speed <= self.speed + 1e-9
        self.speed = speed

    def on_end(self, match) -> None:
        pass


def test_in_a_match_a_kicker_does_not_run_in_its_kick_cycle_and_the_statistics_count_it() -> None:
    watch = KickerWatch()
    result = run_match(KickAndDash(), Still(), seed=3, config=MatchConfig(max_cycles=60), recorders=[watch])
    assert watch.kicks >= 5 and watch.kicked_and_still == watch.kicks
    home, away = result.statistics
    assert home.ignored_commands >= watch.kicks and away.ignored_commands == 0
