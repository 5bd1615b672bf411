"""The referee's rules in whole matches (physics included), played by small scripted teams.

The teams work in their own frame (attacking +x); the assertions read the absolute-frame
events and states the match produces.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from soccer_sim import AWAY, HOME, EventKind, MatchConfig, PlayMode, RuleConfig, TeamCommand, run_match

STRIKER = 9
RUNNER = 10


def config(cycles: int, **rules) -> MatchConfig:
    return replace(MatchConfig(), rules=replace(RuleConfig(), **rules), max_cycles=cycles)


class Idle:
    """Stands still; the goalkeeper optionally tries to catch every cycle and never lets go."""

    def __init__(self, catch: bool = False) -> None:
        self.catch = catch

    def reset(self, side_info, config, rng) -> None:
        n = side_info.players_per_team
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)), catch=self.catch)

    def act(self, view) -> TeamCommand:
        return self.command


class Keeper:
    """Only the goalkeeper moves: it shadows the ball along a line 1.5 m in front of its goal
    and asks to catch whenever the ball is within reach. It never lets go of a caught ball."""

    def reset(self, side_info, config, rng) -> None:
        n = side_info.players_per_team
        self.goalie = side_info.goalie_index
        self.line_x = -config.field.half_length + 1.5
        self.reach = config.rules.catch_length
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view) -> TeamCommand:
        me = view.own_pos[self.goalie]
        spot = np.array([self.line_x, np.clip(view.ball[1], -6.0, 6.0)])
        self.command.dash[self.goalie] = (spot - me) * 100.0
        self.command.catch = math.dist(me, view.ball) < self.reach
        return self.command


class Striker:
    """Player STRIKER dribbles the ball towards ``target`` (own frame) and, once within
    ``shoot_from`` metres of it, kicks it there as hard as it can. Optionally player RUNNER
    first runs to ``runner_spot`` and the striker passes to it after ``pass_after`` cycles."""

    def __init__(self, target, shoot_from: float = 30.0, runner_spot=None, pass_after: int = 10**9) -> None:
        self.target = np.asarray(target, dtype=float)
        self.shoot_from = shoot_from
        self.runner_spot = None if runner_spot is None else np.asarray(runner_spot, dtype=float)
        self.pass_after = pass_after

    def reset(self, side_info, config, rng) -> None:
        self.n = side_info.players_per_team
        self.kick_max = config.physics.kick_speed_max
        self.reach = config.physics.kickable_distance
        self.passed = False

    def act(self, view) -> TeamCommand:
        n = self.n
        dash, kick = np.zeros((n, 2)), np.zeros((n, 2))
        move = None
        if view.play_mode == PlayMode.KICK_OFF:
            move = view.own_pos.copy()
            move[STRIKER] = (-0.6, 0.0)
        to_ball = view.ball - view.own_pos[STRIKER]
        dash[STRIKER] = to_ball * 100.0
        if self.runner_spot is not None:
            if not self.passed or view.play_mode != PlayMode.PLAY_ON:
                dash[RUNNER] = (self.runner_spot - view.own_pos[RUNNER]) * 100.0
            else:
                dash[RUNNER] = (view.ball - view.own_pos[RUNNER]) * 100.0
        if view.cycle >= self.pass_after and self.runner_spot is not None:
            aim = view.own_pos[RUNNER]
            speed = self.kick_max
            self.passed = True
        else:
            aim = self.target
            far = math.dist(view.ball, aim) > self.shoot_from
            speed = 0.6 if far else self.kick_max
        direction = aim - view.ball
        length = float(np.linalg.norm(direction))
        if length > 1e-6 and math.dist(view.ball, view.own_pos[STRIKER]) <= self.reach:
            kick[STRIKER] = direction / length * speed - view.ball_vel  # one body command: kick ...
            dash[STRIKER] = 0.0                                          # ... or run to the ball
        return TeamCommand(dash=dash, kick=kick, move=move)


class ModeLog:
    """Recorder: the play mode, its team and the ball at the end of every cycle."""

    def on_start(self, match) -> None:
        self.rows = []

    def on_cycle(self, match) -> None:
        st = match.state
        self.rows.append((st.cycle - 1, st.play_mode, st.mode_team, float(st.ball[0]), float(st.ball[1])))

    def on_end(self, match) -> None:
        pass

    def first(self, mode: PlayMode):
        return next(row for row in self.rows if row[1] == mode)


def events_of(result, kind):
    return result.events.of_kind(kind)


def test_striker_scores_and_the_conceding_team_kicks_off():
    log = ModeLog()
    result = run_match(Striker(target=(60.0, 4.0)), Idle(), seed=1, config=config(400), recorders=[log])
    assert result.score[0] >= 1 and result.score[1] == 0
    cycle, team, player, x, y, own_goal = events_of(result, EventKind.GOAL)[0]
    assert (team, player, own_goal) == (HOME, STRIKER, 0)
    assert x > 52.5 and abs(y) < 7.01
    assert any(e[1] == HOME and e[2] == STRIKER and e[0] < cycle for e in events_of(result, EventKind.SHOT))
    # A pause, then the idle away team never takes its kick-off: the ball is dropped after the timeout.
    rules = MatchConfig().rules
    after = [(c, k, t, d) for c, k, t, d in zip(result.events.cycle, result.events.kind, result.events.team,
                                                result.events.detail) if c >= cycle]
    assert after[1] == (cycle, EventKind.SET_PLAY, AWAY, PlayMode.AFTER_GOAL)
    kick_off_cycle = cycle + rules.goal_pause_cycles
    assert after[2] == (kick_off_cycle, EventKind.SET_PLAY, AWAY, PlayMode.KICK_OFF)
    drop = events_of(result, EventKind.DROP_BALL)[0]
    assert drop[0] == kick_off_cycle + rules.set_play_timeout
    pause = [row for row in log.rows if row[0] == cycle][0]
    assert pause[1:] == (PlayMode.AFTER_GOAL, AWAY, 0.0, 0.0)
    kick_off = [row for row in log.rows if row[0] == kick_off_cycle][0]
    assert kick_off[1:] == (PlayMode.KICK_OFF, AWAY, 0.0, 0.0)
    state = result.state
    assert state.play_mode == PlayMode.TIME_OVER and result.cycles == 400


def test_kicking_the_ball_over_the_touchline_gives_the_opponents_a_kick_in():
    log = ModeLog()
    result = run_match(Striker(target=(20.0, 60.0), shoot_from=80.0), Idle(), seed=2, config=config(200), recorders=[log])
    [out, *_] = events_of(result, EventKind.OUT)
    cycle, team, player, x, y, line = out
    assert (team, line) == (HOME, 0)  # the striker, or a team-mate the ball bounced off
    _, mode, mode_team, bx, by = [row for row in log.rows if row[0] == cycle][0]
    assert (mode, mode_team) == (PlayMode.KICK_IN, AWAY)
    assert by == 34.0 and bx == pytest.approx(x)


def test_kicking_wide_over_the_goal_line_gives_a_goal_kick_and_the_ends_stay_at_half_time():
    log = ModeLog()
    result = run_match(Striker(target=(60.0, 20.0)), Idle(), seed=3, config=config(600, half_cycles=300), recorders=[log])
    kicks = [row for row in log.rows if row[1] == PlayMode.GOAL_KICK]
    assert kicks, "the ball never went out over the goal line"
    first_half = [row for row in kicks if row[0] < 300]
    second_half = [row for row in kicks if row[0] >= 300]
    # Away defends +x in both halves (rcssserver changes no ends): goal kicks at its goal-area corner.
    assert first_half and all(row[2] == AWAY and (row[3], row[4]) == (47.0, 9.16) for row in first_half)
    assert second_half and all(row[2] == AWAY and (row[3], row[4]) == (47.0, 9.16) for row in second_half)
    [half_time] = events_of(result, EventKind.HALF_TIME)
    assert half_time[0] == 299
    assert log.rows[299][1:3] == (PlayMode.KICK_OFF, AWAY)


def test_goalkeeper_catches_a_shot_and_holding_it_past_the_free_kicks_time_drops_the_ball():
    hold = 30
    log = ModeLog()
    result = run_match(Striker(target=(60.0, 0.0)), Keeper(), seed=4,
                       config=config(700, set_play_timeout=hold), recorders=[log])
    catches = events_of(result, EventKind.CATCH)
    assert catches and catches[0][1:3] == (AWAY, 0)
    caught_at = catches[0][0]
    # rcssserver: the catch's cycle is the first of the keeper's free kick (drop_ball_time counts it)
    assert all(row[1] == PlayMode.GOALIE_HOLDS for row in log.rows[caught_at:caught_at + hold - 1])
    drop = events_of(result, EventKind.DROP_BALL)[0]
    assert drop[0] == caught_at + hold - 1 and log.rows[drop[0]][1] == PlayMode.PLAY_ON
    # dropped on the away penalty area's front corner (x = 36) on the ball's side
    assert (drop[3], abs(drop[4])) == (pytest.approx(36.0), pytest.approx(20.16))
    assert EventKind.GOAL not in set(result.events.kind[: result.events.cycle.index(caught_at) + 1])


@pytest.mark.parametrize("offside", [True, False])
def test_pass_to_a_player_beyond_the_defence_is_offside_only_with_the_rule_on(offside):
    team = Striker(target=(30.0, -10.0), shoot_from=0.0, runner_spot=(45.0, 15.0), pass_after=100)
    result = run_match(team, Idle(), seed=5, config=config(200, offside=offside))
    calls = events_of(result, EventKind.OFFSIDE)
    if offside:
        assert calls and calls[0][1:3] == (HOME, RUNNER)
        assert calls[0][3] > 36.75  # beyond the second-last defender
    else:
        assert calls == []
        assert any(e[1] == HOME and e[2] == STRIKER and e[5] == RUNNER for e in events_of(result, EventKind.PASS))


class MovingKeeper(Keeper):
    """The Keeper, which once it holds the ball asks every cycle to move (own frame) to a spot
    inside its penalty area, a different one each cycle, and keeps dashing."""

    def act(self, view) -> TeamCommand:
        command = super().act(view)
        holds = view.play_mode == PlayMode.GOALIE_HOLDS and view.ball_holder == self.goalie
        if holds:  # (no catch request now: a catch is the higher body command)
            command.catch = False
            spot = (-45.0 + (view.cycle % 3), -3.0 + 2.0 * (view.cycle % 4))
            command.move = np.tile(spot, (len(view.own_pos), 1))
        else:
            command.move = None
        return command


class KeeperSpots:
    """Recorder: the away goalkeeper's position (absolute) while it holds the ball the first
    time, and the moves refused then."""

    def on_start(self, match) -> None:
        self.rows = []
        self.refused = 0
        self.done = False

    def on_cycle(self, match) -> None:
        st = match.state
        if st.play_mode == PlayMode.GOALIE_HOLDS and not self.done:
            self.rows.append(st.pos[st.first_row(AWAY)].tolist())
            self.refused = match.referee.goalkeeper.refused_moves[AWAY]
        elif self.rows:
            self.done = True

    def on_end(self, match) -> None:
        pass


def test_a_holding_goalkeeper_moves_twice_then_its_moves_are_refused_and_it_cannot_dash_then():
    spots = KeeperSpots()
    result = run_match(Striker(target=(60.0, 0.0)), MovingKeeper(), seed=4, config=config(700), recorders=[spots])
    assert events_of(result, EventKind.CATCH)
    # the first two cycles of the hold move the keeper (the away team's own frame is mirrored);
    # then every move is refused, and as the move still is its body command, its dash is dropped
    assert spots.rows[1] != spots.rows[0] and spots.rows[2] != spots.rows[1]
    assert all(row == spots.rows[2] for row in spots.rows[2:])
    assert spots.refused == len(spots.rows) - 3
