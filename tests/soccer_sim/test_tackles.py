"""Tackles as rcssserver makes them: reach and success probability, the push, the freeze.

The comparisons with the real server's traces are in test_rcssserver_reference_tackles.py."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from soccer_sim import HOME, EventKind, MatchConfig, TeamCommand
from soccer_sim.config import ConfigError, TackleConfig
from soccer_sim.match import Match
from soccer_sim.scenarios import BallStart, Scenario, Side
from soccer_sim.state import WorldState
from soccer_sim.tackles import Tackles, failure_probability
from soccer_sim.team import TeamError, TeamView
from tests.soccer_sim.core_helpers import quiet_config

ALL = np.ones(2, dtype=bool)


def tackle_once(ball, vel=(0.0, 0.0), direction=0.0, config: MatchConfig | None = None, rng=None,
                ball_vel=(0.0, 0.0)):
    """Player row 0 at the centre spot (velocity ``vel``) tackles towards ``direction``
    (radians, absolute) with the ball at ``ball``; returns (outcome, state)."""
    config = config or MatchConfig()
    state = WorldState((1, 1), pos=[(0.0, 0.0), (30.0, 0.0)], vel=[vel, (0.0, 0.0)], ball=ball,
                       ball_vel=ball_vel)
    tackles = Tackles(config, state, (-1, -1), rng or np.random.default_rng(1))
    commands = np.zeros((2, 4))
    outcome = tackles.resolve(state, np.array([direction, np.nan]), np.zeros(2, dtype=bool), True, commands,
                              np.zeros(2, dtype=bool), ALL)
    tackles.push(state, outcome, kicked=False)
    return outcome, state


def test_failure_probability_is_rcssservers_formula():
    assert failure_probability(1.0, 0.0, 2.0, 0.0, 1.25, 6.0) == pytest.approx(0.5 ** 6)
    assert failure_probability(1.0, -0.5, 2.0, 0.0, 1.25, 6.0) == pytest.approx(0.5 ** 6 + 0.4 ** 6)
    assert failure_probability(1.7, 0.0, 2.0, 0.0, 1.25, 10.0) == pytest.approx(0.85 ** 10)
    assert failure_probability(2.0, 0.0, 2.0, 0.0, 1.25, 6.0) == 1.0
    assert failure_probability(-0.3, 0.0, 2.0, 0.0, 1.25, 6.0) == 1.0  # behind: tackle_back_dist 0
    assert failure_probability(-0.3, 0.0, 2.0, 0.5, 1.25, 6.0) == pytest.approx(0.6 ** 6)


@pytest.mark.parametrize("ball, vel, expected", [
    ((1.8, 0.0), (0.0, 0.0), 1.0 - 0.9 ** 6),  # at rest the player faces the ball: x = 1.8, y = 0
    # a sprinter (1 m/cycle along +x) turns at most 180/(1 + 5) = 30 deg towards a ball at 90 deg:
    # the ball lies 60 deg off its body, x = 1.2 cos 60, y = 1.2 sin 60
    ((0.0, 1.2), (1.0, 0.0), 1.0 - (0.6 / 2.0) ** 6 - (1.2 * math.sin(math.pi / 3) / 1.25) ** 6),
])
def test_success_rate_follows_the_formula(ball, vel, expected):
    rng = np.random.default_rng(7)
    trials = 3000
    won = sum(tackle_once(ball, vel, rng=rng)[0].reached[0] for _ in range(trials))
    sigma = math.sqrt(expected * (1 - expected) / trials)
    assert abs(won / trials - expected) < 4 * sigma


def test_a_ball_out_of_reach_is_never_won():
    for ball, vel in (((2.01, 0.0), (0.0, 0.0)), ((-0.5, 0.0), (1.0, 0.0))):  # too far; behind a sprinter
        outcome, state = tackle_once(ball, vel)
        assert outcome.reached == [False] and outcome.pushers == []
        assert state.ball_vel.tolist() == [0.0, 0.0]
        assert state.frozen[0] == 10  # a failed tackle freezes too


def noiseless() -> MatchConfig:
    """Without kick noise, which the tackle noise scales (``PhysicsConfig.kick_rand``)."""
    return replace(MatchConfig(), physics=replace(MatchConfig().physics, kick_rand=0.0))


@pytest.mark.parametrize("direction, speed", [
    (0.0, 2.7),                 # straight ahead of the body: max_tackle_power * tackle_power_rate
    (math.pi / 2, 1.35),        # 90 deg off the body: half the power
    (-math.pi / 2, 1.35),
    (math.pi, 0.0),             # straight back: max_back_tackle_power 0
])
def test_push_falls_with_the_direction_off_the_body(direction, speed):
    outcome, state = tackle_once((0.5, 0.0), direction=direction, config=noiseless())
    assert outcome.reached == [True]
    assert math.hypot(*state.ball_vel) == pytest.approx(speed, abs=1e-12)
    if speed:
        assert math.atan2(state.ball_vel[1], state.ball_vel[0]) == pytest.approx(direction)


def test_push_falls_with_the_ball_off_the_body():
    # The sprinter's body points 30 deg left of +x; the ball lies 60 deg off it.
    body = math.pi / 6
    rng = np.random.default_rng(3)
    for _ in range(20):  # until the tackle is won (it is, with probability 0.67)
        outcome, state = tackle_once((0.0, 1.2), (1.0, 0.0), direction=body, config=noiseless(), rng=rng)
        if outcome.reached[0]:
            break
    assert math.hypot(*state.ball_vel) == pytest.approx(2.7 * (1.0 - 0.5 * 60.0 / 180.0))
    assert math.atan2(state.ball_vel[1], state.ball_vel[0]) == pytest.approx(body)


def test_noise_is_bounded_by_kick_rand_and_the_push_by_ball_accel_max():
    rng = np.random.default_rng(5)
    speeds = []
    for _ in range(300):
        outcome, state = tackle_once((0.5, 0.0), rng=rng, ball_vel=(0.0, 0.0))
        speeds.append(math.hypot(*state.ball_vel))
    # pos_rate = 0.5 + 0.5 * (1 - 0.25^6), speed_rate = 0.5 (ball at rest)
    largest = 0.1 * 2.0 * (0.5 + 0.5 * (1.0 - 0.25 ** 6) + 0.5)
    assert max(speeds) <= 2.7 + 1e-12
    assert min(speeds) >= 2.7 - largest - 1e-12
    assert min(speeds) < 2.7 - 0.5 * largest  # the noise is there


def test_a_tackle_where_the_player_may_not_kick_does_not_move_the_ball():
    config = MatchConfig()
    state = WorldState((1, 1), pos=[(0.0, 0.0), (30.0, 0.0)], ball=(0.5, 0.0))
    tackles = Tackles(config, state, (-1, -1), np.random.default_rng(1))
    outcome = tackles.resolve(state, np.array([0.0, np.nan]), np.zeros(2, dtype=bool), True, np.zeros((2, 4)),
                              np.zeros(2, dtype=bool), np.zeros(2, dtype=bool))
    tackles.push(state, outcome, kicked=False)
    assert outcome.reached == [True] and outcome.pushers == []
    assert state.ball_vel.tolist() == [0.0, 0.0]


class Tackler:
    """Player 0 tackles towards +x (own frame) at cycle ``at`` and asks to dash along +y every
    cycle; remembers what its view said about it being frozen."""

    def __init__(self, at: int = 0) -> None:
        self.at = at
        self.frozen: list[int] = []

    def reset(self, side_info, config, rng) -> None:
        self.n = side_info.players_per_team

    def act(self, view) -> TeamCommand:
        self.frozen.append(int(view.frozen[0]))
        tackle = np.full(self.n, np.nan)
        if view.cycle == self.at:
            tackle[0] = 0.0
        dash = np.zeros((self.n, 2))
        dash[0] = (0.0, 0.3)
        return TeamCommand(dash=dash, kick=np.zeros((self.n, 2)), tackle=tackle)


class Still:
    def reset(self, side_info, config, rng) -> None:
        self.n = side_info.players_per_team

    def act(self, view) -> TeamCommand:
        return TeamCommand(dash=np.zeros((self.n, 2)), kick=np.zeros((self.n, 2)))


def one_against_one(ball_x: float, cycles: int = 14) -> Scenario:
    """Home's one player at the centre spot at rest, the ball still ``ball_x`` ahead of it, the
    away player far off; play on."""
    return Scenario(name="tackle", home=Side(players=1, goalie=None, positions=((0.0, 0.0),)),
                    away=Side(players=1, goalie=None, positions=((30.0, 20.0),)),
                    ball=BallStart(position=(ball_x, 0.0)), start_mode="play_on", cycle_limit=cycles,
                    half_time=False)


@pytest.mark.parametrize("ball_x, won", [(0.5, 1), (3.0, 0)])
def test_the_tackler_is_frozen_for_tackle_cycles(ball_x, won):
    team = Tackler(at=0)
    match = Match(team, Still(), seed=2, config=quiet_config(), scenario=one_against_one(ball_x))
    match.start()
    vy, ball_speed = [], []
    for _ in range(12):
        match.step()
        vy.append(float(match.state.vel[0, 1]))
        ball_speed.append(math.hypot(*match.state.ball_vel))
    tackles = match.events.of_kind(EventKind.TACKLE)
    assert [(c, t, p, d) for c, t, p, _, _, d in tackles] == [(0, HOME, 0, won)]
    # rcssserver's tackle_cycles 10: no dash in the tackle's cycle and the 9 after it
    assert vy[:10] == [0.0] * 10 and vy[10] > 0.0
    assert team.frozen[:11] == [0, 9, 8, 7, 6, 5, 4, 3, 2, 1, 0]
    if won:
        assert 2.2 < ball_speed[0] <= 2.7 * 0.94  # pushed at up to 2.7 m/cycle, then one decay
        assert match.state.last_touch == 0


def test_a_team_that_never_tackles_draws_nothing_and_is_never_frozen():
    match = Match(Still(), Still(), seed=2, config=quiet_config(), scenario=one_against_one(0.5))
    match.start()
    state = match.tackles.rng.bit_generator.state
    for _ in range(5):
        match.step()
    assert match.tackles.rng.bit_generator.state == state
    assert not match.tackles.busy and not match.state.frozen.any()


def test_bad_tackle_commands_are_team_errors():
    for tackle, foul, message in (([0.0, 1.0], None, "shape"), ([np.inf], None, "infinite"),
                                  (["a"], None, "numeric"), ([0.0], [0.5], "command.foul")):
        class Bad(Still):
            def act(self, view, tackle=tackle, foul=foul):
                return TeamCommand(dash=np.zeros((1, 2)), kick=np.zeros((1, 2)), tackle=tackle, foul=foul)

        match = Match(Bad(), Still(), config=quiet_config(), scenario=one_against_one(0.5))
        match.start()
        with pytest.raises(TeamError, match=message):
            match.step()


def test_tackle_config_is_checked():
    with pytest.raises(ConfigError, match="TackleConfig.tackle_dist"):
        TackleConfig(tackle_dist=0.0).validate()
    with pytest.raises(ConfigError, match="TackleConfig.foul_detect_probability"):
        MatchConfig(tackles=TackleConfig(foul_detect_probability=1.5))
    with pytest.raises(ConfigError, match="TackleConfig.tackle_cycles"):
        TackleConfig(tackle_cycles=-1).validate()
    with pytest.raises(TypeError, match="kick_rand"):  # one kick_rand, PhysicsConfig's
        TackleConfig(kick_rand=0.0)


def test_tackles_switched_off_are_ignored():
    config = replace(quiet_config(), tackles=TackleConfig(enabled=False))
    match = Match(Tackler(at=0), Still(), seed=2, config=config, scenario=one_against_one(0.5))
    match.start()
    match.step()
    assert match.events.of_kind(EventKind.TACKLE) == []
    assert match.state.ball_vel.tolist() == [0.0, 0.0] and match.state.vel[0, 1] > 0.0


def test_the_view_shows_presence_and_freezes_read_only():
    match = Match(Tackler(at=0), Still(), seed=2, config=quiet_config(), scenario=one_against_one(0.5))
    match.start()
    match.step()
    view = match.frames[HOME].update_view(match.state, 1)
    assert view.frozen.tolist() == [9] and view.present.tolist() == [True] and view.opp_present.tolist() == [True]
    for flags in (view.frozen, view.present, view.opp_present):
        with pytest.raises(ValueError, match="read-only"):
            flags[0] = 0
    match.state.present[1] = False
    assert match.frames[HOME].update_view(match.state, 1).opp_present.tolist() == [False]


def test_a_view_built_by_hand_has_everybody_present_and_nobody_frozen():
    view = TeamView(own_pos=np.zeros((3, 2)), own_vel=np.zeros((3, 2)), opp_pos=np.zeros((2, 2)),
                    opp_vel=np.zeros((2, 2)), ball=np.zeros(2), ball_vel=np.zeros(2), stamina=np.ones(3))
    assert view.present.tolist() == [True] * 3 and view.opp_present.tolist() == [True] * 2
    assert view.frozen.tolist() == [0, 0, 0]


@pytest.mark.parametrize("opponent, foul_kept, frozen", [((1.0, 0.0), True, 0), ((30.0, 0.0), False, 10)])
def test_a_foul_tackle_needs_an_opponent_on_the_ball_and_then_does_not_freeze(opponent, foul_kept, frozen):
    state = WorldState((1, 1), pos=[(0.0, 0.0), opponent], ball=(0.5, 0.0))
    tackles = Tackles(MatchConfig(), state, (-1, -1), np.random.default_rng(1))
    outcome = tackles.resolve(state, np.array([0.0, np.nan]), np.array([True, False]), True, np.zeros((2, 4)),
                              np.zeros(2, dtype=bool), ALL)
    assert outcome.reached == [True] and outcome.fouls == [foul_kept]
    assert state.frozen[0] == frozen


def test_the_states_tackle_arrays_cannot_be_replaced():
    state = WorldState((2, 1))
    assert state.present.tolist() == [True] * 3 and state.frozen.tolist() == [0] * 3 and state.cards.tolist() == [0] * 3
    for name in ("present", "frozen", "cards"):
        with pytest.raises(AttributeError, match=f"WorldState.{name} cannot be replaced"):
            setattr(state, name, getattr(state, name).copy())
