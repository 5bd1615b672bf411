"""Tackles and fouls against traces of the real rcssserver 19 (tests/data/rcssserver/tackle.json;
what every figure means: its ``meta``; how it was recorded: tests/data/rcssserver/probes/).

The simulator's side, as :mod:`soccer_sim.tackles` and :mod:`soccer_sim.rules.fouls` implement it:

* ``TeamCommand.tackle``: (n,) tackle directions in degrees in the team's frame, NaN for no
  tackle; ``TeamCommand.foul``: (n,) bool, ``(tackle DIR on)``.
* :func:`soccer_sim.tackles.failure_probability`: rcssserver's failure probability for the ball
  at (x, y) in the tackler's body frame; a match draws each tackle's success from it.
* Events ``EventKind.TACKLE`` (every tackle; ``detail`` bit 1: it reached the ball),
  ``EventKind.FOUL`` (a foul called on the tackler), ``YELLOW_CARD`` and ``RED_CARD``; a called
  foul gives the other team a ``PlayMode.FREE_KICK`` where the tackler stood.

Where the body faces is :mod:`soccer_sim.body`'s model: a still tackler faces the ball. So the
server's figures for a ball straight ahead of its body are reproduced by still tacklers; a ball
beside the body by a moving tackler whose motion, turned towards the ball as far as it can turn,
faces the server's body direction (+x); the whole grid of places is compared through
``failure_probability`` with the defaults of ``TackleConfig``.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from tests.soccer_sim.probe_rig import (FULL, HOME_PROBE, N_TEAM, PROBE, Pitch, Probe, binomial_share_agrees,
                                        config, trace)

from soccer_sim import Match, PlayMode, TeamCommand
from soccer_sim.body import DEFAULT_INERTIA_MOMENT
from soccer_sim.config import MatchConfig, PhysicsConfig, TackleConfig
from soccer_sim.state import AWAY, EventKind
from soccer_sim.tackles import failure_probability

TACKLES = TackleConfig()
"""rcssserver 19's tackle parameters (the defaults), as the traces were recorded with."""
VICTIMS = 4
"""The server's probe rotated its fouled ball holders over four players (B1..B4)."""


def success_probability(forward: float, lateral: float, foul: bool = False) -> float:
    """The simulator's probability that a tackle succeeds with the ball's centre ``forward``
    metres ahead of the tackler's body and ``lateral`` to the side (``foul``: a foul tackle on
    an opponent who can kick the ball, with ``foul_exponent``)."""
    exponent = TACKLES.foul_exponent if foul else TACKLES.tackle_exponent
    failure = failure_probability(forward, lateral, TACKLES.tackle_dist, TACKLES.tackle_back_dist,
                                  TACKLES.tackle_width, exponent)
    return max(0.0, 1.0 - failure)


def noiseless() -> MatchConfig:
    """No noise at all, the tackle's included: it scales ``PhysicsConfig.kick_rand``, which is 0
    here as in the clean and referee traces (``server::kick_rand=0``)."""
    return config()


class TackleProbe(Probe):
    """A probe team that also tackles: ``tackle`` (degrees, own frame, NaN: none) and ``foul``."""

    def __init__(self) -> None:
        super().__init__()
        self.tackle = np.full(N_TEAM, np.nan)
        self.foul = np.zeros(N_TEAM, dtype=bool)

    def act(self, view) -> TeamCommand:
        command = super().act(view)
        command.foul = self.foul.copy()
        return command

    def idle(self) -> None:
        super().idle()
        self.foul[:] = False


class TacklePitch(Pitch):
    """:class:`Pitch` with two :class:`TackleProbe` teams."""

    def __init__(self, cfg: MatchConfig, seed: int = 0) -> None:
        self.home, self.away = TackleProbe(), TackleProbe()
        self.match = Match(self.home, self.away, seed=seed, config=cfg)
        self.match.start()
        self.state = self.match.state
        self.park()


def count(pitch: Pitch, kind: EventKind, since: int = 0) -> int:
    """Events of ``kind`` from event number ``since`` on."""
    return sum(1 for k in pitch.match.events.kind[since:] if k == int(kind))


# ------------------------------------------------------------------------------ success by place


def grid() -> list[tuple[float, float, int, int]]:
    return [tuple(cell) for cell in trace("tackle")["grid"]]


def server_cell(x: float, y: float) -> tuple[int, int]:
    """(successes, trials) of the server at (x, y)."""
    return next((s, n) for gx, gy, s, n in grid() if (gx, gy) == (x, y))


@pytest.mark.parametrize("x,y,successes,trials", grid())
def test_success_probability_agrees_with_the_server_grid(x: float, y: float, successes: int, trials: int) -> None:
    """Tackles with the ball at (x, y) from the tackler (x ahead of its body), 60 server trials
    per place (200 at 1.8 m ahead): the server's successes lie within 3 binomial standard
    deviations (plus one trial) of the simulator's probability; where the server never
    succeeded (behind, beyond tackle_dist, wider than tackle_width) the probability is 0."""
    p = success_probability(x, y)
    assert 0.0 <= p <= 1.0
    if successes == 0:
        assert p == 0.0
    else:
        assert abs(successes - trials * p) <= 3.0 * math.sqrt(trials * p * (1.0 - p)) + 1.0, (p, successes, trials)


def test_success_probability_over_the_whole_grid() -> None:
    """All places together (1160 server trials): observed and expected successes agree within
    3 standard deviations of their sum, so a probability off by a few percent everywhere fails."""
    cells = grid()
    expected = sum(n * success_probability(x, y) for x, y, _, n in cells)
    variance = sum(n * success_probability(x, y) * (1 - success_probability(x, y)) for x, y, _, n in cells)
    observed = sum(s for _, _, s, _ in cells)
    assert abs(observed - expected) <= 3.0 * math.sqrt(variance) + 1.0, (observed, expected)


def tackle_trials(distance: float, trials: int, seed: int) -> int:
    """Still tacklers (home players 1..10 in turn: a tackler is frozen for tackle_cycles) tackle
    towards the ball lying ``distance`` straight ahead of them, noise off; returns the successes
    (the ball moved), checked against the TACKLE events' ``reached`` flags."""
    pitch = TacklePitch(noiseless(), seed=seed)
    successes = 0
    for trial in range(trials):
        tackler = 1 + trial % (N_TEAM - 1)
        pitch.park()
        pitch.place(tackler, 0.0, 0.0)
        pitch.ball(distance, 0.0)
        pitch.home.tackle[tackler] = 0.0
        since = len(pitch.match.events.kind)
        pitch.step()
        moved = bool(np.hypot(*pitch.state.ball_vel) > 1e-9)
        tackles = [d for k, d in zip(pitch.match.events.kind[since:], pitch.match.events.detail[since:])
                   if k == int(EventKind.TACKLE)]
        assert tackles == [int(moved)]
        successes += moved
        pitch.step()
    return successes


@pytest.mark.parametrize("distance", [1.5, 1.75, 1.8, 1.9])
def test_tackle_reach_in_a_match_agrees_with_the_server(distance: float) -> None:
    """A tackle reaches 2.0 m in front (a kick 1.085 m): the success share of 200 tackles in a
    match is within 2.5 standard errors of the server's trials at that distance."""
    successes, trials = server_cell(distance, 0.0)
    ours = tackle_trials(distance, 200, seed=11)
    assert binomial_share_agrees(ours, 200, successes, trials), (ours, successes, trials)


# ----------------------------------------------------------------------------------- ball speed


def tackle_speed_cases() -> list[str]:
    return sorted(trace("tackle")["tackle_speed"])


@pytest.mark.parametrize("name", tackle_speed_cases())
def test_tackle_ball_speed_within_1_percent(name: str) -> None:
    """A successful tackle of a still ball at ``ball_rel`` from a tackler whose body faces +x,
    at DIR to the body, noise off: 2.7 m/cycle straight ahead, less to the side and for a ball
    beside the body, nothing backwards (max_back_tackle_power 0). The ball's displacement in
    the tackle's cycle within 1 % of the tackle's full 2.7 m/cycle. A ball straight ahead: a
    still tackler (it faces the ball). A ball beside the body: the tackler moves at 1 m/cycle,
    turned away from the ball by the largest turn it can make at that speed, so that its body,
    turned towards the ball, faces +x."""
    data = trace("tackle")["tackle_speed"][name]
    forward, lateral = data["ball_rel"]
    pitch = TacklePitch(noiseless())
    vx = vy = 0.0
    if lateral:
        speed = 1.0
        turn = math.copysign(math.pi / (1.0 + DEFAULT_INERTIA_MOMENT * speed), lateral)
        vx, vy = speed * math.cos(-turn), speed * math.sin(-turn)
    pitch.place(HOME_PROBE, 0.0, 0.0, vx, vy)
    pitch.ball(forward, lateral)
    pitch.home.tackle[PROBE] = data["dir"]
    pitch.step()
    np.testing.assert_allclose(pitch.state.ball - (forward, lateral), data["first_cycle"], atol=0.027)


def test_the_tackler_is_frozen_for_tackle_cycles_as_by_the_server() -> None:
    """(tackle 0), then a full dash every cycle: the server's tackler, whether it won the ball
    (0.5 m ahead) or missed it (3 m), stays put for tackle_cycles (10) cycles and then runs; ours
    is at the same x after each of the 13 cycles (to the server's 4 printed decimals)."""
    freeze = trace("tackle")["freeze"]
    for case, ball_x in (("won", 0.5), ("missed", 3.0)):
        pitch = TacklePitch(noiseless())
        pitch.place(HOME_PROBE, 0.0, 0.0)
        pitch.ball(ball_x, 0.0)
        pitch.home.tackle[PROBE] = 0.0
        xs = []
        for _ in freeze[case]:
            pitch.step()
            xs.append(float(pitch.state.pos[HOME_PROBE, 0]))
            pitch.home.dash[PROBE] = (FULL, 0.0)
        np.testing.assert_allclose(xs, freeze[case], atol=5e-5, err_msg=case)
        assert (np.hypot(*pitch.state.ball - (ball_x, 0.0)) > 1.0) == (case == "won")


# ---------------------------------------------------------------------------------------- fouls


def foul_trials(trials: int, victim_dashes: bool, seed: int) -> dict[str, int]:
    """Foul tackles (foul flag on) as the server's probe made them: home players 1..10 in turn
    (those still on the pitch) at (-1, 0) tackle towards +x the ball (0.5, 0) held by an away
    player at (0, 0) (away players 1..4 in turn), which dashes towards +x in the tackle's cycle
    if ``victim_dashes``; two idle cycles follow (the server's probe: a setup cycle and one more).
    Counts of trials with a foul called, a successful tackle, a yellow card, a red card, a free
    kick to the away team at the tackler's place, and a foul called on a tackler already called
    once ("called_again"); "sent_off": home players off the pitch at the end."""
    pitch = TacklePitch(noiseless(), seed=seed)
    counts = dict.fromkeys(("foul_called", "tackled", "yellow_card", "red_card", "free_kick_at_tackler",
                            "called_again"), 0)
    called_before: set[int] = set()
    n = 0
    for _ in range(trials):
        on_pitch = [p for p in range(1, N_TEAM) if pitch.state.present[p]]
        tackler, victim = on_pitch[n % len(on_pitch)], 1 + n % VICTIMS
        n += 1
        while pitch.state.frozen[tackler] or pitch.state.frozen[N_TEAM + victim]:
            pitch.step()  # the last tacklers left after red cards: wait out a missed tackle's freeze
        pitch.park()
        pitch.place(tackler, -1.0, 0.0)
        pitch.place(N_TEAM + victim, 0.0, 0.0)
        pitch.ball(0.5, 0.0)
        pitch.home.tackle[tackler] = 0.0
        pitch.home.foul[tackler] = True
        if victim_dashes:
            pitch.away.dash[victim] = (-FULL, 0.0)  # the away frame is turned by 180°: towards +x
        since = len(pitch.match.events.kind)
        pitch.step()
        events = pitch.match.events
        tackle = [d for k, d in zip(events.kind[since:], events.detail[since:]) if k == int(EventKind.TACKLE)]
        assert len(tackle) == 1 and tackle[0] & 2  # a foul tackle: the victim could kick the ball
        called = count(pitch, EventKind.FOUL, since) > 0
        counts["foul_called"] += called
        counts["tackled"] += bool(tackle[0] & 1)
        counts["yellow_card"] += count(pitch, EventKind.YELLOW_CARD, since) > 0
        counts["red_card"] += count(pitch, EventKind.RED_CARD, since) > 0
        if called:
            counts["called_again"] += tackler in called_before
            called_before.add(tackler)
            counts["free_kick_at_tackler"] += bool(
                pitch.state.play_mode == PlayMode.FREE_KICK and pitch.state.mode_team == AWAY
                and np.hypot(*(pitch.state.ball - (-1.0, 0.0))) < 1e-9)
        pitch.step()
        pitch.step()
    counts["sent_off"] = int((~pitch.state.present[:N_TEAM]).sum())
    return counts


def test_foul_tackles_are_called_as_often_as_by_the_server() -> None:
    """100 server trials of foul tackles on a ball holder standing still: some fail
    (foul_exponent 10 at 1.5 m: the server's failures within 3 binomial standard deviations plus
    one trial of the simulator's probability), the others are called with
    foul_detect_probability 0.5. Ours over 200 trials: called and failed shares within 2.5
    standard errors of the server's."""
    server = trace("tackle")["fouls"]["standing"]
    p = success_probability(1.5, 0.0, foul=True)  # foul_exponent: 1 - 0.75^10
    n = server["trials"]
    assert abs(n - server["tackle_failed"] - n * p) <= 3.0 * math.sqrt(n * p * (1.0 - p)) + 1.0, (p, server)
    ours = foul_trials(200, victim_dashes=False, seed=13)
    assert binomial_share_agrees(ours["foul_called"], 200, server["foul_called"], server["trials"]), (ours, server)
    failed = 200 - ours["tackled"]
    assert binomial_share_agrees(failed, 200, server["tackle_failed"], server["trials"]), (ours, server)
    assert ours["foul_called"] <= ours["tackled"]  # only a tackle that reached the ball is judged


def test_a_called_foul_gives_the_other_team_a_free_kick_at_the_tacklers_place_and_no_card() -> None:
    """The server: foul_charge_l, then free_kick_r with the ball where the tackler stood; a ball
    holder that did not dash earns the tackler no card."""
    server = trace("tackle")
    assert [m for _, m in server["followup"]["messages"]][-2:] == ["foul_charge_l", "free_kick_r"]
    assert server["followup"]["ball_after_call"][:2] == server["followup"]["tackler_at"]
    assert server["fouls"]["standing"]["yellow_card"] == server["fouls"]["standing"]["red_card"] == 0
    ours = foul_trials(40, victim_dashes=False, seed=17)
    assert ours["foul_called"] > 0
    assert ours["free_kick_at_tackler"] == ours["foul_called"]
    assert ours["yellow_card"] == ours["red_card"] == 0


def test_a_called_foul_on_a_dashing_ball_holder_brings_a_card_the_second_one_red() -> None:
    """The server (20 trials, its 11 tacklers in turn, red_card_probability 0): every foul
    called on a ball holder that dashed in the tackle's cycle came with a yellow card, and a
    tackler's second one was also a red card (so fewer red cards than calls). Ours, 30 trials
    with 10 tacklers in turn (so that some are called twice): calls as often as the server's
    within 2.5 standard errors, every call carded, a red card exactly for the tacklers called a
    second time (shown as the red card alone; the server announces both), who leave play."""
    server = trace("tackle")["fouls"]["dashing"]
    assert server["yellow_card"] == server["foul_called"] > server["red_card"]
    ours = foul_trials(30, victim_dashes=True, seed=19)
    assert binomial_share_agrees(ours["foul_called"], 30, server["foul_called"], server["trials"]), (ours, server)
    assert ours["called_again"] > 0
    assert ours["red_card"] == ours["called_again"] == ours["sent_off"]
    assert ours["yellow_card"] + ours["red_card"] == ours["foul_called"]
    assert ours["free_kick_at_tackler"] == ours["foul_called"]


# -------------------------------------------------------------- the foul rule, situation by situation
# tests/data/rcssserver/foul_rule.json: tackles with and without the foul flag on a ball holder,
# from behind, the side and the front, the holder standing, dashing, or having dashed the cycle
# before (what each case means: the file's meta).

HOLDER_DASH_POWER = {"dash_first": 100.0, "dash_after": 100.0, "dashed_before": 20.0}
"""The server's probe: the holder's dash power per action (rcssserver power units)."""
TURNED_AWAY_SPEED = 0.4
"""A still player here faces the ball (soccer_sim.body); the server's holder with its body
turned away from the ball (body 180) is a holder moving away from the ball at this speed
(m/cycle), which faces more than 90 degrees off the ball."""


def foul_rule_cases() -> dict[str, dict]:
    return trace("foul_rule")["cases"]


def foul_rule_trials(case: dict, trials: int, seed: int) -> dict[str, int]:
    """The server's situation ``case`` played ``trials`` times: home players 1..10 in turn
    (those still on the pitch) tackle the ball at (0.5, 0) held by an away player at (0, 0)
    (away players 1..4 in turn), towards the case's push direction, with the foul flag as the
    case says; the holder dashes towards +x as the case says (in the tackle's cycle, or in the
    cycle before and not in the tackle's). Counts of trials with a foul called, a tackle that
    reached the ball, a yellow card and a red card."""
    pitch = TacklePitch(noiseless(), seed=seed)
    counts = dict.fromkeys(("foul_called", "tackled", "yellow_card", "red_card"), 0)
    holder_vx = -TURNED_AWAY_SPEED if case["holder_body"] == 180.0 else 0.0
    dash = HOLDER_DASH_POWER.get(case["holder"], 0.0) * PhysicsConfig().dash_power_rate
    for n in range(trials):
        on_pitch = [p for p in range(1, N_TEAM) if pitch.state.present[p]]
        tackler, victim = on_pitch[n % len(on_pitch)], N_TEAM + 1 + n % VICTIMS
        while pitch.state.frozen[tackler] or pitch.state.frozen[victim]:
            pitch.step()
        pitch.park()
        pitch.place(tackler, *case["tackler"])
        pitch.place(victim, 0.0, 0.0, holder_vx, 0.0)
        pitch.ball(0.5, 0.0)
        since = len(pitch.match.events.kind)
        if case["holder"] == "dashed_before":
            pitch.away.dash[victim - N_TEAM] = (-dash, 0.0)  # the away frame is turned by 180°: towards +x
            pitch.step()
            pitch.place(victim, *pitch.state.pos[victim], holder_vx, 0.0)
        elif case["holder"] in ("dash_first", "dash_after"):
            pitch.away.dash[victim - N_TEAM] = (-dash, 0.0)
        pitch.home.tackle[tackler] = case["push_dir"]
        pitch.home.foul[tackler] = case["flag"] == "on"
        pitch.step()
        events = pitch.match.events
        tackle = [d for k, d in zip(events.kind[since:], events.detail[since:]) if k == int(EventKind.TACKLE)]
        assert len(tackle) == 1
        counts["tackled"] += bool(tackle[0] & 1)
        counts["foul_called"] += count(pitch, EventKind.FOUL, since) > 0
        counts["yellow_card"] += count(pitch, EventKind.YELLOW_CARD, since) > 0
        counts["red_card"] += count(pitch, EventKind.RED_CARD, since) > 0
        pitch.step()
    return counts


@pytest.mark.parametrize("label", [label for label in foul_rule_cases() if label != "off_behind_dash_after"])
def test_the_foul_rule_calls_a_tackle_on_a_ball_holder_as_the_server_does(label: str) -> None:
    """Each server situation, 160 trials here (30 where the server showed cards: a tackler's
    second card sends it off): where the server never called a foul (a tackle without the foul
    flag on a holder that did not dash, that faces away from the ball, or that is not between
    the tackler and the ball) none is called here; elsewhere (a foul tackle on any holder; a
    tackle without the flag that charges a holder who dashed in this cycle or the one before,
    from behind or the side) the called share agrees with the server's within 2.5 standard
    errors; tackles reach the ball as often (3 standard errors), and cards come only where the
    server showed them."""
    server = foul_rule_cases()[label]
    trials = 30 if server["yellow_card"] else 160
    ours = foul_rule_trials(server, trials, seed=23)
    if server["foul_called"] == 0:
        assert ours["foul_called"] == 0, (ours, server)
    else:
        assert binomial_share_agrees(ours["foul_called"], trials, server["foul_called"], server["trials"]), (ours, server)
    assert binomial_share_agrees(ours["tackled"], trials, server["tackled"], server["trials"], sigmas=3.0), (ours, server)
    assert (ours["yellow_card"] > 0) == (server["yellow_card"] > 0), (ours, server)
    if server["yellow_card"] == 0:
        assert ours["red_card"] == 0


def test_a_dash_counts_for_the_foul_rule_in_its_cycle_and_the_next() -> None:
    """rcssserver's ``dashed()`` holds from a dash until the end of the next cycle: a holder
    charged from behind is called about as often when it dashed the cycle before as when it
    dashes in the tackle's cycle (the server: 48 of 120 and 49 of 100), and never when it stood
    (0 of 40). The server counts a dash of the tackle's own cycle only when it was received
    before the tackle (0 of 40 when received after it); a cycle's commands here have no order,
    so every dash of the tackle's cycle counts, as the server's dash received first."""
    cases = foul_rule_cases()
    assert cases["off_behind_stand"]["foul_called"] == cases["off_behind_dash_after"]["foul_called"] == 0
    first, before = cases["off_behind_dash_first"], cases["off_behind_dashed_before"]
    assert binomial_share_agrees(first["foul_called"], first["trials"], before["foul_called"], before["trials"])
    after = foul_rule_trials(cases["off_behind_dash_after"], 160, seed=29)
    assert binomial_share_agrees(after["foul_called"], 160, first["foul_called"], first["trials"]), (after, first)
