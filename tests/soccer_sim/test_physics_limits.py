"""Physics limits with numbers: speed, acceleration, stamina, kick range and power, ball decay,
no tunnelling, teammate contacts, ball touches, goal posts, the field margin."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from core_helpers import quiet_config

from soccer_sim.config import StaminaConfig
from soccer_sim.kinematics import CycleNoise, Kinematics
from soccer_sim.physics import BodyBlock, Physics, SubstepPlanner

N = 11
CONFIG = quiet_config()
PHYS = CONFIG.physics
FAR = np.array([[-40.0 + 3.0 * (i % 10), -30.0 + 5.0 * (i // 10)] for i in range(2 * N)])
"""Players spread far from the centre and from each other."""


def zero_noise() -> np.ndarray:
    """Raw noise of 0.5 maps to 0 in [-1, 1)."""
    return np.full((2 * N, 2), 0.5)


def world(config=CONFIG) -> tuple[BodyBlock, Physics]:
    block = BodyBlock(config.players_per_team)
    block.pos[:] = FAR
    return block, Physics(config, block)


# --- dash ----------------------------------------------------------------------------------
def test_acceleration_is_clipped_to_the_limit() -> None:
    kin = Kinematics(CONFIG)
    vel = np.zeros((2 * N, 2))
    stamina = np.full(2 * N, CONFIG.stamina.maximum)
    dash = np.zeros((2 * N, 2))
    dash[0] = (30.0, 40.0)  # asks for 50 m/cycle²
    dash[1] = (0.3, 0.4)  # within the limit
    kin.dash(vel, stamina, dash, zero_noise())
    assert np.allclose(vel[0], (0.6, 0.8))  # 1.0 m/cycle² along the request
    assert np.allclose(vel[1], (0.3, 0.4))
    assert np.allclose(vel[2:], 0.0)


def test_speed_is_clipped_to_the_limit_after_repeated_dashes() -> None:
    kin = Kinematics(CONFIG)
    vel = np.zeros((2 * N, 2))
    stamina = np.full(2 * N, CONFIG.stamina.maximum)
    for _ in range(30):
        dash = np.tile([1.0, 0.0], (2 * N, 1))
        top = kin.dash(vel, stamina, dash, zero_noise())
        assert top <= PHYS.player_speed_max + 1e-12
        vel *= PHYS.player_decay
    # Steady state: v = decay * v + 1.0 would reach 1 / 0.6 = 1.67 m/cycle without the limit.
    assert top == pytest.approx(PHYS.player_speed_max)


def test_speed_limit_holds_with_noise() -> None:
    config = replace(CONFIG, physics=replace(PHYS, player_noise=0.5))
    kin = Kinematics(config)
    rng = np.random.default_rng(0)
    vel = np.zeros((2 * N, 2))
    stamina = np.full(2 * N, CONFIG.stamina.maximum)
    for _ in range(50):
        kin.dash(vel, stamina, rng.normal(size=(2 * N, 2)) * 5, rng.random((2 * N, 2)))
        assert np.hypot(vel[:, 0], vel[:, 1]).max() <= PHYS.player_speed_max + 1e-12


def test_stamina_drains_recovers_and_low_stamina_weakens_acceleration() -> None:
    stam = CONFIG.stamina
    kin = Kinematics(CONFIG)
    vel = np.zeros((2 * N, 2))
    stamina = np.full(2 * N, stam.maximum)
    stamina[1] = 0.0
    stamina[2] = stam.tired_fraction * stam.maximum / 2  # half way down the ramp
    dash = np.zeros((2 * N, 2))
    dash[:3] = (10.0, 0.0)
    kin.dash(vel, stamina, dash, zero_noise())
    assert vel[0, 0] == pytest.approx(1.0)
    assert vel[1, 0] == pytest.approx(stam.min_effort)
    assert vel[2, 0] == pytest.approx((1 + stam.min_effort) / 2)
    # A full dash costs 100 and the cycle recovers 45; standing players stay full.
    assert stamina[0] == pytest.approx(stam.maximum - 100.0 + stam.recovery_per_cycle)
    assert stamina[5] == stam.maximum
    assert stamina[1] == pytest.approx(0.0 + stam.recovery_per_cycle)  # 30 paid, clipped at 0, recovered


def test_no_tired_ramp_means_full_effort_at_zero_stamina() -> None:
    config = replace(CONFIG, stamina=replace(StaminaConfig(), tired_fraction=0.0))
    kin = Kinematics(config)
    vel = np.zeros((2 * N, 2))
    stamina = np.zeros(2 * N)
    dash = np.tile([5.0, 0.0], (2 * N, 1))
    kin.dash(vel, stamina, dash, zero_noise())
    assert np.allclose(vel[:, 0], 1.0)


# --- kicks ---------------------------------------------------------------------------------
def kick_once(ball_offset, kick_vector, holder=-1):
    """Player 0 at the origin, the ball at ``ball_offset``; returns (kicked?, new ball velocity)."""
    kin = Kinematics(CONFIG)
    pos = FAR.copy()
    pos[0] = (0.0, 0.0)
    ball = np.array(ball_offset, dtype=float)
    ball_vel = np.zeros(2)
    kick = np.zeros((2 * N, 2))
    kick[0] = kick_vector
    rows = np.zeros(2 * N, dtype=np.int64)
    count, nearest = kin.kick_candidates(pos, ball, kick, np.ones(2 * N, dtype=bool), holder, rows)
    assert nearest == pytest.approx(math.hypot(*ball_offset))
    if count:
        kin.kick(rows[:count], pos, ball, ball_vel, kick, kin.ball_distance, holder, np.full(2, 0.5))
    return count, ball_vel


def test_kickable_distance_is_the_touch_distance_plus_the_margin() -> None:
    reach = PHYS.player_radius + PHYS.ball_radius + PHYS.kickable_margin
    assert reach == pytest.approx(1.085)
    assert kick_once((reach - 1e-6, 0.0), (1.0, 0.0))[0] == 1
    assert kick_once((reach + 1e-6, 0.0), (1.0, 0.0))[0] == 0


def test_kick_effectiveness_falls_with_distance_and_angle() -> None:
    touch = PHYS.player_radius + PHYS.ball_radius
    _, close = kick_once((touch, 0.0), (2.0, 0.0))
    assert close == pytest.approx((2.0, 0.0))  # ball touching, kicked straight ahead: full power
    _, far = kick_once((PHYS.kickable_distance, 0.0), (2.0, 0.0))
    assert far == pytest.approx((2.0 * (1 - PHYS.kick_distance_penalty), 0.0))
    _, back = kick_once((touch, 0.0), (-2.0, 0.0))  # straight back through the player
    assert back == pytest.approx((-2.0 * (1 - PHYS.kick_angle_penalty), 0.0))
    _, side = kick_once((touch, 0.0), (0.0, 2.0))  # 90 degrees
    assert side == pytest.approx((0.0, 2.0 * (1 - PHYS.kick_angle_penalty / 2)))


def test_kick_power_and_ball_speed_are_clipped() -> None:
    touch = PHYS.player_radius + PHYS.ball_radius
    _, velocity = kick_once((touch, 0.0), (100.0, 0.0))
    assert velocity == pytest.approx((PHYS.kick_speed_max, 0.0))
    # A holding goalkeeper kicks with full effect whatever the geometry.
    _, held = kick_once((0.0, 0.0), (-100.0, 0.0), holder=0)
    assert held == pytest.approx((-PHYS.kick_speed_max, 0.0))


def test_zero_kick_vector_is_no_kick_and_mask_forbids() -> None:
    assert kick_once((0.5, 0.0), (0.0, 0.0))[0] == 0
    kin = Kinematics(CONFIG)
    pos = FAR.copy()
    pos[0] = (0.0, 0.0)
    kick = np.ones((2 * N, 2))
    mask = np.ones(2 * N, dtype=bool)
    mask[0] = False
    count, _ = kin.kick_candidates(pos, np.array([0.5, 0.0]), kick, mask, -1, np.zeros(2 * N, dtype=np.int64))
    assert count == 0


# --- ball decay and the collision solver -----------------------------------------------------
def test_ball_decays_by_the_ball_decay_each_cycle() -> None:
    block, physics = world()
    kin = Kinematics(CONFIG)
    block.ball_vel[:] = (2.0, 0.0)
    x = 0.0
    for cycle in range(10):
        physics.step(1)
        kin.decay(block.vel, block.ball_vel, np.full(2, 0.5))
        x += 2.0 * PHYS.ball_decay ** cycle
        assert block.ball_vel[0] == pytest.approx(2.0 * PHYS.ball_decay ** (cycle + 1))
        assert block.ball[0] == pytest.approx(x)
    # The players decay differently: 0.4 per cycle.
    block.vel[0] = (1.0, 0.0)
    kin.decay(block.vel, block.ball_vel, np.full(2, 0.5))
    assert block.vel[0, 0] == pytest.approx(PHYS.player_decay)


def planned(block: BodyBlock, ball_free: bool = True) -> int:
    return SubstepPlanner(CONFIG).count(block.dynamic, ball_free)


@pytest.mark.parametrize("player_speed", [0.0, 1.05])
def test_full_speed_ball_does_not_pass_through_a_player(player_speed: float) -> None:
    block, physics = world()
    block.pos[0] = (0.0, 0.0)
    block.vel[0] = (-player_speed, 0.0)  # running at the ball makes it worse
    block.ball[:] = (-1.2, 0.0)
    block.ball_vel[:] = (PHYS.ball_speed_max, 0.0)
    substeps = planned(block)
    assert substeps == math.ceil((PHYS.ball_speed_max + player_speed) / PHYS.max_substep_distance)
    touchers = physics.step(substeps)
    assert block.ball[0] < block.pos[0, 0]  # still on the near side
    assert block.ball_vel[0] < 0.0  # bounced back
    assert touchers.tolist() == [0]


def test_without_substeps_the_same_ball_would_tunnel() -> None:
    """The control experiment: one step lets the ball jump through, so sub-steps matter."""
    block, physics = world()
    block.pos[0] = (0.0, 0.0)
    block.ball[:] = (-1.2, 0.0)
    block.ball_vel[:] = (PHYS.ball_speed_max, 0.0)
    physics.step(1)
    assert block.ball[0] > 1.0


@pytest.mark.parametrize("speed", [0.4, 0.7, 1.05])
def test_players_running_head_on_do_not_pass_through_each_other(speed: float) -> None:
    block, physics = world()
    block.pos[0], block.vel[0] = (-0.8 * speed, 0.0), (speed, 0.0)
    block.pos[N], block.vel[N] = (0.8 * speed, 0.0), (-speed, 0.0)
    substeps = planned(block)
    assert substeps == math.ceil(2 * speed / (2 * PHYS.max_substep_distance) - 1e-9)
    physics.step(substeps)
    assert block.pos[0, 0] < block.pos[N, 0]
    if speed > PHYS.max_substep_distance:  # the control: one step would let them swap sides
        block2, physics2 = world()
        block2.data[:] = 0.0
        block2.pos[:] = FAR
        block2.pos[0], block2.vel[0] = (-0.8 * speed, 0.0), (speed, 0.0)
        block2.pos[N], block2.vel[N] = (0.8 * speed, 0.0), (-speed, 0.0)
        physics2.step(1)
        assert block2.pos[0, 0] > block2.pos[N, 0]


def test_substeps_follow_closing_speeds_of_bodies_that_can_meet() -> None:
    step = PHYS.max_substep_distance
    block, _ = world()
    assert planned(block) == 1
    # A lone sprinter, and two players running side by side, need no sub-steps.
    block.vel[0] = (1.05, 0.0)
    block.pos[1], block.vel[1] = block.pos[0] + (0.0, 0.7), (1.05, 0.0)
    assert planned(block) == 1
    # Head-on towards a teammate within reach.
    block.pos[2], block.vel[2] = block.pos[0] + (2.0, 0.0), (-1.05, 0.0)
    assert planned(block) == math.ceil(2.1 / (2 * step))
    # A fast ball near a player: the closing speed counts...
    block.ball[:] = block.pos[5] + (2.0, 0.0)
    block.ball_vel[:] = (-3.0, 0.0)
    assert planned(block) == math.ceil(3.0 / step)
    # ...not while a goalkeeper holds it...
    assert planned(block, ball_free=False) == math.ceil(2.1 / (2 * step))
    # ...and not in free flight.
    block.ball[:] = (0.0, 20.0)
    assert planned(block) == math.ceil(2.1 / (2 * step))
    # Near a thin goal post the ball may move at most the ball-post contact distance.
    block.vel[:] = 0.0
    block.ball[:] = (CONFIG.field.half_length - 2.0, CONFIG.field.goal_width / 2)
    block.ball_vel[:] = (3.0, 0.0)
    contact = CONFIG.field.goal_post_radius + PHYS.ball_radius
    assert planned(block) == math.ceil(3.0 / contact)


@pytest.mark.parametrize("offset", [0.01, 0.05, 0.1])
def test_ball_bounces_off_a_goal_post(offset: float) -> None:
    block, physics = world()
    post_y = CONFIG.field.goal_width / 2 + CONFIG.field.goal_post_radius
    block.ball[:] = (CONFIG.field.half_length - 3.0, post_y + offset)
    block.ball_vel[:] = (2.9, 0.0)
    for _ in range(2):
        physics.step(planned(block))
    # Deflected (by more than 30 degrees, outwards) rather than passing through.
    vx, vy = block.ball_vel.tolist()
    assert math.atan2(vy, vx) > math.radians(30)


def test_teammate_contacts_are_counted_once_per_contact_and_per_team() -> None:
    block, physics = world()
    block.pos[0] = (0.0, 0.0)
    block.pos[1] = (1.0, 0.0)  # home teammates 1 m apart
    block.pos[N] = (10.0, 0.0)
    block.pos[N + 1] = (11.0, 0.0)  # an away pair...
    block.pos[2] = (20.0, 0.0)
    block.pos[N + 2] = (21.0, 0.0)  # ...and a home-away pair
    for a, b in ((0, 1), (N, N + 1), (2, N + 2)):
        block.vel[a] = (0.3, 0.0)
        block.vel[b] = (-0.3, 0.0)
    physics.step(4)
    assert physics.teammate_contacts.tolist() == [1, 1]
    for _ in range(5):  # staying in contact is still one contact
        block.vel[0], block.vel[1] = (0.1, 0.0), (-0.1, 0.0)
        physics.step(1)
    assert physics.teammate_contacts.tolist() == [1, 1]
    block.pos[1] = (3.0, 0.0)  # apart...
    physics.step(1)
    block.pos[1] = (0.6, 0.0)  # ...and together again: a second contact
    physics.step(1)
    assert physics.teammate_contacts.tolist() == [2, 1]


def test_players_stay_within_the_field_and_its_margin() -> None:
    block, physics = world()
    block.pos[3] = (CONFIG.field.half_length + CONFIG.field.margin - 0.1, 0.0)
    block.vel[3] = (1.0, 0.0)
    block.pos[4] = (0.0, -CONFIG.field.half_width - CONFIG.field.margin + 0.1)
    block.vel[4] = (0.0, -1.0)
    physics.step(4)
    assert block.pos[3, 0] == pytest.approx(CONFIG.field.half_length + CONFIG.field.margin)
    assert block.pos[4, 1] == pytest.approx(-CONFIG.field.half_width - CONFIG.field.margin)


def test_held_ball_does_not_collide() -> None:
    block, physics = world()
    block.pos[0] = (0.0, 0.0)
    block.ball[:] = (0.0, 0.0)
    physics.set_ball_collides(False)
    assert physics.step(1).size == 0
    assert block.ball.tolist() == [0.0, 0.0]
    physics.set_ball_collides(True)
    assert physics.step(1).tolist() == [0]


def test_cycle_noise_is_uniform_and_drawn_in_one_fixed_block() -> None:
    noise = CycleNoise(np.random.default_rng(3), 2 * N)
    noise.draw()
    first = noise.values.copy()
    assert first.shape == (2 * N + 2, 2)
    assert ((first >= 0) & (first < 1)).all()
    again = CycleNoise(np.random.default_rng(3), 2 * N)
    again.draw()
    assert np.array_equal(first, again.values)


def test_a_kick_plays_the_ball_around_the_kicker_but_not_through_others() -> None:
    block, physics = world()
    block.pos[0] = (0.0, 0.0)  # the kicker, ball just in front of it...
    block.pos[1] = (-1.4, 0.0)  # ...and a teammate behind it
    block.ball[:] = (0.5, 0.0)
    block.ball_vel[:] = (-2.0, 0.0)  # kicked back through the kicker
    touchers = physics.step(planned(block), kickers=np.array([0]))
    assert touchers.tolist() == [1]  # the kicker let it through; the teammate stopped it
    assert block.ball[0] > -1.4
    # After the kick cycle the kicker collides with the ball again.
    block.ball[:] = (0.5, 0.0)
    block.ball_vel[:] = (-1.0, 0.0)
    assert physics.step(4).tolist() == [0]


# --- the bulk body transfer's dependence on pymunk internals ----------------------------------
def test_bulk_transfer_round_trips_every_field_of_every_body() -> None:
    block, physics = world()
    rng = np.random.default_rng(5)
    block.dynamic[:] = rng.uniform(-50.0, 50.0, block.dynamic.shape)  # players and ball
    expected = block.dynamic.copy()
    bodies = physics.space.bodies  # in the order they were added: the players, then the ball
    physics._bulk.write()
    got = np.array([[*b.position, *b.velocity] for b in bodies])
    assert np.array_equal(got, expected)
    for body in bodies:
        body.position = (body.position.x + 1.0, body.position.y)
        body.velocity = (body.velocity.x, body.velocity.y - 2.0)
    physics._bulk.read()
    assert np.array_equal(block.dynamic[:, 0], expected[:, 0] + 1.0)
    assert np.array_equal(block.dynamic[:, 3], expected[:, 3] - 2.0)
    assert np.array_equal(block.dynamic[:, [1, 2]], expected[:, [1, 2]])
    assert block.data[-1].tolist() == [0.0, 0.0, 0.0, 0.0]  # the static body stays at rest


def test_a_changed_pymunk_fails_loudly_naming_the_supported_versions(monkeypatch) -> None:
    import pymunk.batch

    from soccer_sim.physics import PymunkChangedError

    class WithoutInternals:  # a Buffer whose private arrays were renamed
        def set_float_buf(self, buffer) -> None:
            pass

    monkeypatch.setattr(pymunk.batch, "Buffer", WithoutInternals)
    with pytest.raises(PymunkChangedError, match=r"pymunk 7 internals.*pymunk>=7.1,<8") as info:
        world()
    assert "AttributeError" in str(info.value)
    monkeypatch.undo()

    def reads_nothing_back(space, fields, buffer) -> None:  # a batch read laid out differently
        buffer.set_float_buf(np.zeros((2 * N + 1) * 4))

    monkeypatch.setattr(pymunk.batch, "get_space_bodies", reads_nothing_back)
    with pytest.raises(PymunkChangedError, match="unexpected amount of body data"):
        world()
