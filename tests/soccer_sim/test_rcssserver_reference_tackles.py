"""Tackles and fouls against traces of the real rcssserver 19 (tests/data/rcssserver/tackle.json).

The interface these tests expect from the simulator (one place each, below, so a rename is a
one-line change here):

* ``soccer_sim.tackles.success_probability(forward, lateral, foul=False, config=None) -> float``:
  the probability that a tackle succeeds with the ball's centre at ``forward`` metres ahead of
  the tackler's centre (along where its body faces) and ``lateral`` metres to the side;
  ``foul`` for a foul tackle on an opponent who can kick the ball (rcssserver's
  ``foul_exponent`` instead of ``tackle_exponent``); ``config`` None means the defaults.
  rcssserver: 1 - (|forward| / tackle_dist)^e - (|lateral| / tackle_width)^e, and 0 for a
  ball behind the tackler (tackle_back_dist 0) or where that is negative.
* ``TeamCommand.tackle``: an (n, 2) array per player: the tackle's direction (radians, in the
  team's frame, like the dash and kick vectors) and the foul flag (1.0 as ``(tackle DIR on)``,
  0.0 as ``off``); a NaN direction means no tackle (see :func:`tackle_rows`).
* Events ``EventKind.TACKLE`` (a successful tackle, by the tackler), ``EventKind.FOUL`` (a foul
  called, on the tackler's team) and ``EventKind.YELLOW_CARD``; a called foul gives the other
  team a ``PlayMode.FREE_KICK`` at the tackler's position.

A still tackler faces the ball (soccer_sim.body), so the server's figures for a ball straight
ahead of the body (lateral 0) are the ones a match can reproduce directly; the whole grid
(ball beside the body) is compared through ``success_probability``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from tests.soccer_sim.test_rcssserver_reference import (AWAY_PROBE, FULL, HOME_PROBE, N_TEAM, PROBE, Pitch,
                                                        binomial_share_agrees, config, trace)

from soccer_sim import PlayMode
from soccer_sim.state import AWAY, EventKind


def success_probability(forward: float, lateral: float, foul: bool = False) -> float:
    """The simulator's tackle success probability (interface in the module docstring)."""
    from soccer_sim.tackles import success_probability as implementation

    return float(implementation(forward, lateral, foul=foul))


def tackle_rows(directions: dict[int, float], foul: bool = False) -> np.ndarray:
    """``TeamCommand.tackle`` for one team: tackles by the given players (index -> direction in
    radians, team frame), no tackle for the others."""
    rows = np.full((N_TEAM, 2), np.nan)
    rows[:, 1] = 0.0
    for index, angle in directions.items():
        rows[index] = (angle, 1.0 if foul else 0.0)
    return rows


def event_kind(name: str) -> EventKind:
    kind = getattr(EventKind, name, None)
    assert kind is not None, f"soccer_sim.state.EventKind has no {name}"
    return kind


def events_of(pitch: Pitch, name: str) -> int:
    kind = int(event_kind(name))
    return sum(1 for k in pitch.match.events.kind if k == kind)


# ------------------------------------------------------------------------------ success by place


def grid() -> list[tuple[float, float, int, int]]:
    return [tuple(cell) for cell in trace("tackle")["grid"]]


@pytest.mark.parametrize("x,y,successes,trials", grid())
def test_success_probability_agrees_with_the_server_grid(x: float, y: float, successes: int, trials: int) -> None:
    """Tackles with the ball at (x, y) from the tackler (x ahead of its body), 60 server
    trials per place: the server's successes lie within 3 binomial standard deviations (plus
    one trial) of the implementation's probability; where the server never succeeded (behind,
    beyond tackle_dist, wider than tackle_width) the probability is 0."""
    p = success_probability(x, y)
    assert 0.0 <= p <= 1.0
    if successes == 0:
        assert p == 0.0
    else:
        assert abs(successes - trials * p) <= 3.0 * math.sqrt(trials * p * (1.0 - p)) + 1.0, (p, successes, trials)


def test_success_probability_over_the_whole_grid() -> None:
    """All places together (1140 server trials): observed and expected successes agree within
    3 standard deviations of their sum, so a probability off by a few percent everywhere fails."""
    cells = grid()
    expected = sum(n * success_probability(x, y) for x, y, _, n in cells)
    variance = sum(n * success_probability(x, y) * (1 - success_probability(x, y)) for x, y, _, n in cells)
    observed = sum(s for _, _, s, _ in cells)
    assert abs(observed - expected) <= 3.0 * math.sqrt(variance) + 1.0, (observed, expected)


def tackle_trials(distance: float, trials: int, seed: int) -> int:
    """Still tacklers (home players 1..10 in turn: a tackler is frozen for tackle_cycles) tackle
    towards the ball lying ``distance`` straight ahead of them; returns the successes (the ball
    moved)."""
    pitch = Pitch(config(), seed=seed)
    pitch.home.tackle = tackle_rows({})
    successes = 0
    for trial in range(trials):
        tackler = 1 + trial % (N_TEAM - 1)
        pitch.park()
        pitch.place(tackler, 0.0, 0.0)
        pitch.ball(distance, 0.0)
        pitch.home.tackle = tackle_rows({tackler: 0.0})
        pitch.step()
        successes += bool(np.hypot(*pitch.state.ball_vel) > 1e-9)
        pitch.step()
    return successes


@pytest.mark.parametrize("distance", [1.5, 1.75, 1.9])
def test_tackle_reach_in_a_match_agrees_with_the_server(distance: float) -> None:
    """A tackle reaches 2.0 m in front (a kick 1.085 m): the success share of 200 tackles in a
    match is within 2.5 standard errors of the server's 60 trials at that distance."""
    server = next(cell for cell in grid() if cell[0] == distance and cell[1] == 0.0)
    ours = tackle_trials(distance, 200, seed=11)
    assert binomial_share_agrees(ours, 200, server[2], server[3]), (ours, server)


# ----------------------------------------------------------------------------------- ball speed


@pytest.mark.parametrize("name", ["tackle_speed_0.5_0.0_dir0", "tackle_speed_0.5_0.0_dir45",
                                  "tackle_speed_1.0_0.0_dir-45", "tackle_speed_0.5_0.0_dir90",
                                  "tackle_speed_0.5_0.0_dir180"])
def test_tackle_ball_speed_within_1_percent(name: str) -> None:
    """A successful tackle of a still ball straight ahead, at DIR to the body: 2.7 m/cycle at 0°,
    less to the side (max_back_tackle_power 0: nothing backwards). Noise off."""
    data = trace("tackle")["tackle_speed"][name]
    forward = data["ball_rel"][0]
    pitch = Pitch(config())
    pitch.place(HOME_PROBE, 0.0, 0.0)
    pitch.ball(forward, 0.0)
    pitch.home.tackle = tackle_rows({PROBE: math.radians(data["dir"])})
    pitch.step()
    np.testing.assert_allclose(pitch.state.ball - (forward, 0.0), data["first_cycle"], atol=0.027)


# ---------------------------------------------------------------------------------------- fouls


def foul_trials(trials: int, victim_dashes: bool, seed: int) -> dict[str, int]:
    """Foul tackles (foul flag on) by home players 1..10 in turn at (-1, 0) on the away probe
    at (0, 0) holding the ball at (0.5, 0), the referee on; the away probe dashes towards +x in
    the tackle's cycle if ``victim_dashes``. Counts of fouls called, successful tackles and
    yellow cards."""
    pitch = Pitch(config(), seed=seed)
    counts = {"foul_called": 0, "tackled": 0, "yellow_card": 0, "free_kick_at_tackler": 0}
    for trial in range(trials):
        tackler = 1 + trial % (N_TEAM - 1)
        pitch.park()
        pitch.place(tackler, -1.0, 0.0)
        pitch.place(AWAY_PROBE, 0.0, 0.0)
        pitch.ball(0.5, 0.0)
        pitch.home.tackle = tackle_rows({tackler: 0.0}, foul=True)
        if victim_dashes:
            pitch.away.dash[PROBE] = (-FULL, 0.0)  # the away frame is turned by 180°: towards +x
        before = {name: events_of(pitch, name) for name in ("FOUL", "TACKLE", "YELLOW_CARD")}
        pitch.step()
        called = events_of(pitch, "FOUL") > before["FOUL"]
        counts["foul_called"] += called
        counts["tackled"] += events_of(pitch, "TACKLE") > before["TACKLE"]
        counts["yellow_card"] += events_of(pitch, "YELLOW_CARD") > before["YELLOW_CARD"]
        if called:
            for _ in range(40):  # rcssserver pauses (foul_charge) before the free kick
                if pitch.state.play_mode == PlayMode.FREE_KICK:
                    break
                pitch.step()
            counts["free_kick_at_tackler"] += bool(
                pitch.state.play_mode == PlayMode.FREE_KICK and pitch.state.mode_team == AWAY
                and np.hypot(*(pitch.state.ball - (-1.0, 0.0))) < 0.1)
    return counts


def test_foul_tackles_are_called_as_often_as_by_the_server() -> None:
    """100 server trials: the foul tackle fails 7 times (foul_exponent 10 at 1.5 m), succeeds
    unseen 55 times and is called 38 times (foul_detect_probability 0.5 of successful foul
    tackles). Ours over 200 trials: called and failed shares within 2.5 standard errors."""
    server = trace("tackle")["fouls"]["standing"]
    ours = foul_trials(200, victim_dashes=False, seed=13)
    assert binomial_share_agrees(ours["foul_called"], 200, server["foul_called"], server["trials"]), (ours, server)
    failed = 200 - ours["foul_called"] - ours["tackled"]
    assert binomial_share_agrees(failed, 200, server["tackle_failed"], server["trials"]), (ours, server)


def test_a_called_foul_gives_the_other_team_a_free_kick_at_the_tacklers_place_and_no_card() -> None:
    """The server: foul_charge_l, then free_kick_r with the ball where the tackler stood; a ball
    holder that did not dash earns the tackler no card."""
    ours = foul_trials(40, victim_dashes=False, seed=17)
    assert ours["foul_called"] > 0
    assert ours["free_kick_at_tackler"] == ours["foul_called"]
    assert ours["yellow_card"] == 0
    assert trace("tackle")["fouls"]["standing"]["yellow_card"] == 0


def test_a_called_foul_on_a_dashing_ball_holder_brings_a_yellow_card() -> None:
    """The server: every foul called on a ball holder that dashed in the tackle's cycle came with
    a yellow card (8 of 8). Ours: 10 trials (each tackler once, so no second yellow)."""
    server = trace("tackle")["fouls"]["dashing"]
    assert server["yellow_card"] == server["foul_called"] > 0
    ours = foul_trials(N_TEAM - 1, victim_dashes=True, seed=19)
    assert ours["foul_called"] > 0
    assert ours["yellow_card"] == ours["foul_called"]
