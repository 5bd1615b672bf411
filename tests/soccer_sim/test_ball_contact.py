"""Body-ball contact as rcssserver resolves it (``body_ball_contact = "rcssserver"``): overlaps
left at the end of the cycle are separated and both velocities multiplied by -0.1, so fast
balls pass through a body and slow players push the ball. The rules themselves, with chosen
situations; the real server's traces of the probe situations are compared in
``test_rcssserver_reference.py``."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from tests.soccer_sim.probe_rig import (Rig, ball_launched_at_a_standing_player, dash_power, kick_full, probe_config,
                                        run_at_a_still_ball)

from soccer_sim.config import BODY_BALL_CONTACTS, ConfigError, PhysicsConfig
from soccer_sim.state import PlayMode

DATA = Path(__file__).resolve().parents[1] / "data" / "rcssserver"
CONTACT = 0.3 + 0.085
"""Player-ball contact distance of the default bodies (m)."""


def test_swept_contacts_stop_every_ball_unlike_rcssserver() -> None:
    """The control: the swept contact (not rcssserver's) never lets a ball through, where
    rcssserver's lets most balls at 2.7 m/cycle through (test_rcssserver_reference.py compares
    the default contact with the server's traces)."""
    assert ball_launched_at_a_standing_player(2.7, contact="swept") == {"through": 0, "stop": 0, "back": 20}
    assert ball_launched_at_a_standing_player(2.7)["through"] >= 10


def test_a_walker_pushes_the_ball_ahead_where_the_swept_contact_stops_it() -> None:
    """rcssserver's walker (dash 30) pushes the ball about 2.6 m in 40 cycles (compared phase by
    phase in test_rcssserver_reference.py); the swept contact stops the walker instead."""
    server = [walk["ball_x"][-1] for walk in json.loads((DATA / "contact.json").read_text())["walk"]]
    results = run_at_a_still_ball(30, 40, start=-3.0, step=0.015)
    assert not any(passed for _, passed in results)
    assert all(abs(x - float(np.mean(server))) < 0.15 for x, _ in results)  # rcssserver: 2.60 .. 2.69 m
    swept = run_at_a_still_ball(30, 40, start=-3.0, step=0.015, contact="swept")
    assert all(abs(x) < 0.01 for x, _ in swept)


def test_a_path_passing_0_3_m_from_the_ball_leaves_it_untouched() -> None:
    rig = Rig(probe_config(noise=False))
    rig.state.pos[0] = (-5.0, 0.0)
    rig.state.ball[:] = (0.0, 0.3)
    touched = [rig.cycle(dash=dash_power(100)) for _ in range(25)]
    assert not any(touched)
    assert rig.state.ball.tolist() == [0.0, 0.3]


def test_an_overlap_is_split_between_both_bodies_and_both_velocities_reverse() -> None:
    rig = Rig(probe_config(noise=False))
    state = rig.state
    state.pos[0], state.vel[0] = (0.0, 0.0), (0.0, 0.0)
    state.ball[:], state.ball_vel[:] = (-0.5, 0.0), (0.3, 0.0)  # ends at -0.2: 0.185 inside the body
    assert rig.physics.step(1).tolist() == [0]
    # Each moves half the overlap from their midpoint (-0.1): ball to -0.2925, player to +0.0925.
    assert state.ball[0] == pytest.approx(-0.1 - CONTACT / 2)
    assert state.pos[0, 0] == pytest.approx(-0.1 + CONTACT / 2)
    assert state.pos[0, 0] - state.ball[0] > CONTACT  # no longer overlapping
    assert state.ball_vel.tolist() == pytest.approx([-0.03, 0.0])
    assert state.vel[0].tolist() == [0.0, 0.0]


def test_a_ball_between_two_players_goes_to_the_mean_of_its_separations() -> None:
    rig = Rig(probe_config(noise=False))
    state = rig.state
    state.pos[0], state.pos[1] = (-0.3, 0.0), (0.3, 0.0)
    state.vel[0], state.vel[1] = (0.0, 0.05), (0.0, 0.05)  # side by side: they do not meet each other
    state.ball[:] = (0.0, 0.1)
    touchers = rig.physics.step(1)
    assert sorted(touchers) == [0, 1]
    assert state.ball[0] == pytest.approx(0.0, abs=1e-12)  # symmetric: pushed out sideways, not along x
    assert state.ball[1] > 0.1
    for row in (0, 1):
        assert math.dist(state.pos[row], state.ball) >= CONTACT - 0.05
    assert state.vel[:2, 1].tolist() == pytest.approx([-0.005, -0.005])  # x -0.1, once each


def test_outside_play_on_the_ball_stays_and_the_player_is_moved_off_it() -> None:
    rig = Rig(probe_config(noise=False))
    state = rig.state
    state.play_mode = PlayMode.FREE_KICK
    state.pos[0], state.vel[0] = (-0.5, 0.0), (0.4, 0.0)
    state.ball[:] = (0.0, 0.0)
    assert rig.physics.step(1).tolist() == [0]
    assert state.ball.tolist() == [0.0, 0.0]
    assert state.pos[0, 0] == pytest.approx(-CONTACT)
    assert state.vel[0, 0] == pytest.approx(-0.04)


def test_a_weak_kick_into_the_kickers_own_body_meets_it() -> None:
    """rcssserver has no exception for the kicker: a ball that ends the kick's cycle inside
    the kicker's body touches it (the swept contact lets this cycle's kickers through)."""
    for contact, touches in (("rcssserver", [0]), ("swept", [])):
        rig = Rig(probe_config(noise=False, contact=contact))
        rig.state.pos[0] = (0.0, 0.0)
        rig.state.ball[:] = (0.5, 0.0)
        kick = kick_full((-1.0, 0.0)) * (0.4 / 2.7)  # 0.4 m/cycle back: ends 0.1 m in front of the centre
        assert rig.cycle(kick=kick) == touches, contact


def test_a_held_ball_meets_nobody() -> None:
    rig = Rig(probe_config(noise=False))
    rig.state.pos[0] = (0.0, 0.0)
    rig.state.ball[:] = (0.0, 0.0)
    rig.physics.set_ball_collides(False)
    assert rig.physics.step(1).size == 0 and rig.state.ball.tolist() == [0.0, 0.0]
    rig.physics.set_ball_collides(True)
    assert rig.physics.step(1).tolist() == [0]
    assert math.dist(rig.state.pos[0], rig.state.ball) > CONTACT  # separated along +x
    assert np.isfinite(rig.state.bodies).all()


def test_the_contact_models_are_named_and_a_bad_one_is_refused() -> None:
    assert PhysicsConfig().body_ball_contact == "rcssserver"
    assert BODY_BALL_CONTACTS == ("rcssserver", "swept", "rigid")
    with pytest.raises(ConfigError, match="body_ball_contact must be one of rcssserver, swept, rigid, got 'soft'"):
        PhysicsConfig(body_ball_contact="soft").validate()
