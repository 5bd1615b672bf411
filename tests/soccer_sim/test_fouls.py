"""Fouls and cards (rcssserver's FoulRef): the referee's decisions on hand-built tackles, and a
whole match in which a team fouls until one of its players is sent off."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from soccer_sim import AWAY, HOME, EventKind, MatchConfig, PlayMode, TeamCommand
from soccer_sim.config import TackleConfig
from soccer_sim.match import Match
from soccer_sim.rules.fouls import parking_spot
from soccer_sim.scenarios import BallStart, Scenario, Side
from soccer_sim.tackles import TackleOutcome
from tests.soccer_sim.referee_world import N, NO_TOUCH, kinds, make_world, set_play_modes

TACKLER = 5
FOULED = N + 6


def config(**tackles) -> MatchConfig:
    return replace(MatchConfig(), tackles=TackleConfig(**tackles))


def world(tackler=(-1.1, 0.0), fouled=(0.0, 0.0), ball=(0.6, 0.0), **tackles):
    """Home's TACKLER behind away's FOULED, who has the ball at its feet and faces it (at rest)."""
    return make_world(ball=ball, config=config(**tackles), moves={TACKLER: tackler, FOULED: fouled})


def tackle(ref, state, foul: bool, dashed: bool = True, row: int = TACKLER) -> None:
    """``row``'s tackle pushed the ball (as the match would report it to the referee)."""
    mask = np.zeros(2 * N, dtype=bool)
    mask[FOULED] = dashed
    outcome = TackleOutcome(rows=[row], reached=[True], fouls=[foul], pushers=[row], dashed=mask)
    ref.on_commands(state, NO_TOUCH, np.zeros(2, dtype=bool), outcome)


def test_a_seen_foul_tackle_on_a_charged_player_is_a_yellow_card_and_a_free_kick():
    ref, state, events = world(foul_detect_probability=1.0)
    tackle(ref, state, foul=True)
    assert kinds(events) == [EventKind.TACKLE, EventKind.FOUL, EventKind.SET_PLAY, EventKind.YELLOW_CARD]
    assert events.detail[0] == 3  # reached, foul tackle
    assert (events.team[1], events.player[1]) == (HOME, TACKLER)
    assert (events.x[3], events.y[3]) == (events.x[1], events.y[1]) == (-1.1, 0.0)  # the card where the foul was
    assert state.play_mode == PlayMode.FREE_KICK and state.mode_team == AWAY
    assert state.ball.tolist() == [-1.1, 0.0]  # where the tackler stood
    assert state.cards[TACKLER] == 1 and state.present[TACKLER]
    assert state.frozen[FOULED] == 5  # foul_cycles


def test_a_second_yellow_card_sends_the_player_off():
    ref, state, events = world(foul_detect_probability=1.0)
    tackle(ref, state, foul=True)
    state.play_mode, state.mode_team = PlayMode.PLAY_ON, -1
    state.pos[TACKLER], state.ball[:] = (-1.1, 0.0), (0.6, 0.0)
    tackle(ref, state, foul=True)
    assert kinds(events)[-3:] == [EventKind.FOUL, EventKind.SET_PLAY, EventKind.RED_CARD]
    assert events.detail[-1] == 2
    assert not state.present[TACKLER] and state.cards[TACKLER] == 2
    assert tuple(state.pos[TACKLER]) == parking_spot(TACKLER, N, ref.config.field) == (-18.0, -39.0)
    assert state.vel[TACKLER].tolist() == [0.0, 0.0]


def test_a_straight_red_card():
    ref, state, events = world(foul_detect_probability=1.0, red_card_probability=1.0)
    tackle(ref, state, foul=True)
    assert EventKind.RED_CARD in kinds(events) and EventKind.YELLOW_CARD not in kinds(events)
    assert not state.present[TACKLER]


def test_an_ordinary_tackle_that_charges_is_a_foul_without_card():
    ref, state, events = world(foul_detect_probability=1.0)
    tackle(ref, state, foul=False)
    assert kinds(events) == [EventKind.TACKLE, EventKind.FOUL, EventKind.SET_PLAY]
    assert state.frozen[FOULED] == 0  # only a foul tackle stops the fouled player
    # rcssserver's red_card_probability draw after an ordinary foul gives a yellow card
    ref, state, events = world(foul_detect_probability=1.0, red_card_probability=1.0)
    tackle(ref, state, foul=False)
    assert EventKind.YELLOW_CARD in kinds(events) and state.present[TACKLER]


@pytest.mark.parametrize("place", [
    {"fouled": (0.0, 0.9)},     # beside the tackle's line, beyond the two bodies' radii
    {"fouled": (-2.0, 0.0), "tackler": (-1.4, 0.0)},  # behind the tackler
])
def test_no_charge_no_foul_from_an_ordinary_tackle(place):
    ref, state, events = world(foul_detect_probability=1.0, **place)
    tackle(ref, state, foul=False)
    assert kinds(events) == [EventKind.TACKLE] and state.play_mode == PlayMode.PLAY_ON


def test_a_seen_foul_tackle_without_charge_is_a_foul_without_card():
    ref, state, events = world(foul_detect_probability=1.0)
    tackle(ref, state, foul=True, dashed=False)  # the fouled player did not dash
    assert kinds(events) == [EventKind.TACKLE, EventKind.FOUL, EventKind.SET_PLAY]
    assert state.frozen[FOULED] == 5


def test_an_unseen_foul_tackle_plays_on_but_stops_the_fouled_player():
    ref, state, events = world(foul_detect_probability=0.0)
    tackle(ref, state, foul=True)
    assert kinds(events) == [EventKind.TACKLE] and state.play_mode == PlayMode.PLAY_ON
    assert state.frozen[FOULED] == 5


def test_detection_follows_foul_detect_probability():
    ref, state, events = world(foul_detect_probability=0.5)
    fouls = 0
    for _ in range(400):
        state.play_mode, state.mode_team = PlayMode.PLAY_ON, -1
        state.pos[TACKLER], state.ball[:], state.cards[:] = (-1.1, 0.0), (0.6, 0.0), 0
        before = len(events)
        tackle(ref, state, foul=False, dashed=False)  # no charge: a foul tackle's detection only
        fouls += EventKind.FOUL in kinds(events)[before:]
    assert fouls == 0  # an ordinary tackle without charge is never a foul
    for _ in range(400):
        state.play_mode, state.mode_team = PlayMode.PLAY_ON, -1
        state.pos[TACKLER], state.ball[:] = (-1.1, 0.0), (0.6, 0.0)
        before = len(events)
        tackle(ref, state, foul=True, dashed=False)
        fouls += EventKind.FOUL in kinds(events)[before:]
    assert abs(fouls / 400 - 0.5) < 4 * 0.025


def test_the_free_kick_leaves_the_fouled_teams_penalty_area():
    # home fouls inside the penalty area away defends (x > 0 in the first half)
    ref, state, _ = world(tackler=(47.0, 5.0), fouled=(48.1, 5.0), ball=(48.7, 5.0), foul_detect_probability=1.0)
    tackle(ref, state, foul=False)
    assert state.mode_team == AWAY and state.ball.tolist() == [52.5 - 16.5, 40.32 / 2]
    # away fouls in its own goal area (x > 0): the free kick for home is moved to the goal area's line
    ref, state, _ = make_world(ball=(49.0, 2.0), config=config(foul_detect_probability=1.0),
                               moves={FOULED: (50.5, 2.0), 4: (49.6, 2.0)})
    mask = np.zeros(2 * N, dtype=bool)
    mask[4] = True
    ref.on_commands(state, NO_TOUCH, np.zeros(2, dtype=bool),
                    TackleOutcome(rows=[FOULED], reached=[True], fouls=[False], pushers=[FOULED], dashed=mask))
    assert set_play_modes(ref.events)[-1] == PlayMode.FREE_KICK and state.mode_team == HOME
    assert state.ball.tolist() == [52.5 - 5.5, 2.0]  # out of the goal area, onto its line


# ---------------------------------------------------------------------------------- a match
DRIBBLER = 1


class Dribbler:
    """Player 1 runs the ball forward (own frame +x) with small kicks, a touch and then a run (one
    body command a cycle); player 0 stands still."""

    def reset(self, side_info, config, rng) -> None:
        self.n = side_info.players_per_team
        self.reach = config.physics.kickable_distance

    def act(self, view) -> TeamCommand:
        dash, kick = np.zeros((self.n, 2)), np.zeros((self.n, 2))
        me, ball = view.own_pos[DRIBBLER], view.ball
        # one body command a cycle: it walks into the ball, pushing it on with its body (a
        # walker pushes a ball it runs into: a dashing player with the ball in reach), and every
        # tenth cycle with the ball in reach touches it forward instead
        if view.cycle % 10 == 0 and np.hypot(*(ball - me)) < self.reach:
            kick[DRIBBLER] = (me + (1.0, 0.0) - ball) * 0.3 + (0.25, 0.0)
        else:
            dash[DRIBBLER] = (ball - me) * 0.3 + (0.05, 0.0)
        return TeamCommand(dash=dash, kick=kick)


class Fouler:
    """Player 1 chases the ball and foul-tackles it towards +x whenever it can; remembers the
    presence flags its views showed."""

    def __init__(self) -> None:
        self.present: list[tuple[bool, ...]] = []

    def reset(self, side_info, config, rng) -> None:
        self.n = side_info.players_per_team

    def act(self, view) -> TeamCommand:
        self.present.append(tuple(view.present.tolist()))
        dash = np.zeros((self.n, 2))
        me, ball = view.own_pos[DRIBBLER], view.ball
        dash[DRIBBLER] = (ball - me) * 0.5
        tackle = np.full(self.n, np.nan)
        if np.hypot(*(ball - me)) < 1.9 and view.frozen[DRIBBLER] == 0:
            tackle[DRIBBLER] = 0.0
        return TeamCommand(dash=dash, kick=np.zeros((self.n, 2)), tackle=tackle, foul=np.ones(self.n, dtype=bool))


def test_a_team_that_fouls_until_sent_off_plays_on_with_fewer():
    # away dribbles towards -x (its own +x); home's fouler starts behind it
    scenario = Scenario(name="fouls", home=Side(players=2, goalie=None, positions=((-30.0, 20.0), (1.5, 0.0))),
                        away=Side(players=2, goalie=None, positions=((30.0, 20.0), (0.0, 0.0))),
                        ball=BallStart(position=(-0.7, 0.0)), start_mode="play_on", cycle_limit=1500,
                        half_time=False)
    home, away = Fouler(), Dribbler()
    cfg = replace(MatchConfig(), tackles=TackleConfig(foul_detect_probability=1.0))
    match = Match(home, away, seed=4, config=cfg, scenario=scenario)
    result = match.run()
    events = result.events
    reds = events.of_kind(EventKind.RED_CARD)
    assert [(team, player) for _, team, player, *_ in reds] == [(HOME, DRIBBLER)]
    red_cycle = reds[0][0]
    yellows = events.of_kind(EventKind.YELLOW_CARD)
    assert [(team, player) for _, team, player, *_ in yellows] == [(HOME, DRIBBLER)] and yellows[0][0] < red_cycle
    # every foul gave the away team a free kick
    fouls = events.of_kind(EventKind.FOUL)
    assert len(fouls) >= 2
    free_kicks = [(c, t) for c, t, _, _, _, d in events.of_kind(EventKind.SET_PLAY) if d == PlayMode.FREE_KICK]
    assert [c for c, _ in free_kicks] == [c for c, *_ in fouls] and {t for _, t in free_kicks} == {AWAY}
    # after the red card: parked, flagged absent, its commands ignored, no more tackles by it
    state = result.state
    assert state.present.tolist() == [True, False, True, True]
    assert tuple(state.pos[DRIBBLER]) == parking_spot(DRIBBLER, 2, cfg.field)
    assert state.vel[DRIBBLER].tolist() == [0.0, 0.0]
    assert home.present[red_cycle + 1:] and set(home.present[red_cycle + 1:]) == {(True, False)}
    assert set(home.present[:red_cycle + 1]) == {(True, True)}
    assert all(c <= red_cycle for c, t, p, *_ in events.of_kind(EventKind.TACKLE) if t == HOME)
    # the away team plays on against one: it keeps kicking the ball after the red card
    assert any(c > red_cycle for c, t, *_ in events.of_kind(EventKind.KICK) if t == AWAY)
    home_stats, away_stats = result.statistics
    assert (home_stats.yellow_cards, home_stats.red_cards, home_stats.fouls) == (1, 1, len(fouls))
    assert home_stats.tackles >= len(fouls)  # the free kicks after them: asserted from the events above
    assert home_stats.tackles_won >= len(fouls)
