"""Physics limits with numbers: speed, acceleration, stamina, kick range and power, ball decay,
no tunnelling, teammate contacts, ball touches, goal posts, the field margin."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
from tests.soccer_sim.core_helpers import quiet_config
from tests.soccer_sim.probe_rig import kick_once

from soccer_sim.config import StaminaConfig
from soccer_sim.kinematics import CycleNoise, Kinematics
from soccer_sim.physics import Physics, SubstepPlanner
from soccer_sim.state import WorldState

N = 11
CONFIG = quiet_config()
PHYS = CONFIG.physics
FAR = np.array([[-40.0 + 3.0 * (i % 10), -30.0 + 5.0 * (i // 10)] for i in range(2 * N)])
"""Players spread far from the centre and from each other."""


def zero_noise() -> np.ndarray:
    """Movement noise draws of every player and the ball whose length draw is 0: no noise."""
    return np.zeros((2 * N + 1, 2))


def no_kick_noise() -> np.ndarray:
    """Kick noise draws of every player whose length draw is 0: no noise."""
    return np.zeros((2 * N, 2))


BALL_AWAY = (0.0, 25.0)
"""Where the ball waits when a test is about the players."""


def world(config=CONFIG) -> tuple[WorldState, Physics]:
    """Players far apart, the ball away from them, and a collision solver working on them."""
    state = WorldState((config.players_per_team, config.players_per_team))
    state.pos[:] = FAR
    state.ball[:] = BALL_AWAY
    return state, Physics(config, state)


# --- dash ----------------------------------------------------------------------------------
class Players:
    """Per-player arrays of the dash and stamina model, fresh unless changed."""

    def __init__(self, config=CONFIG) -> None:
        self.kin = Kinematics(config, 2 * config.players_per_team)
        n2 = 2 * config.players_per_team
        self.vel = np.zeros((n2, 2))
        self.ball_vel = np.zeros(2)
        self.stamina, self.effort, self.recovery, self.capacity = (np.empty(n2) for _ in range(4))
        self.kin.restore(self.stamina, self.effort, self.recovery, self.capacity)

    def dash(self, dash: np.ndarray, noise: np.ndarray | None = None) -> float:
        return self.kin.dash(self.vel, self.ball_vel, self.stamina, self.effort, self.recovery, self.capacity,
                             dash, zero_noise() if noise is None else noise)

    def sprint(self, cycles: int, direction=(1.0, 0.0)) -> list[float]:
        """Every player dashes at full power for ``cycles`` cycles (decay included); returns
        player 0's speed during each cycle's move."""
        speeds = []
        for _ in range(cycles):
            self.dash(np.tile(direction, (2 * N, 1)) * 10.0)
            speeds.append(float(np.hypot(*self.vel[0])))
            self.vel *= PHYS.player_decay
        return speeds


def test_acceleration_is_clipped_to_full_power_times_the_power_rate() -> None:
    players = Players()
    dash = np.zeros((2 * N, 2))
    dash[0] = (30.0, 40.0)  # asks for 50 m/cycle²
    dash[1] = (0.3, 0.4)  # within the limit
    players.dash(dash)
    assert PHYS.player_accel_max == pytest.approx(100 * 0.006)  # rcssserver: maxpower x dash_power_rate
    assert np.allclose(players.vel[0], (0.36, 0.48))  # 0.6 m/cycle² along the request
    assert np.allclose(players.vel[1], (0.3, 0.4))
    assert np.allclose(players.vel[2:], 0.0)
    # Power is paid in stamina: 100 for the full dash, 0.5 / 0.006 for the small one; then the
    # cycle's recovery (45) tops both up.
    stam = CONFIG.stamina
    assert players.stamina[0] == pytest.approx(stam.maximum - 100.0 + stam.recovery_per_cycle)
    assert players.stamina[1] == pytest.approx(stam.maximum - 0.5 / 0.006 + stam.recovery_per_cycle)
    assert players.stamina[2] == stam.maximum
    assert dash[0] == pytest.approx((0.36, 0.48))  # the command is overwritten with what was applied


def test_top_speed_takes_several_cycles_from_rest() -> None:
    speeds = Players().sprint(8)
    assert speeds[0] == pytest.approx(0.6)  # rcssserver: 0.6 of ~1.0 m/cycle in the first cycle
    # v_k = 0.6 (1 + 0.4 + ... + 0.4^(k-1)): 0.84, 0.936, 0.974, ... -> 1.0 m/cycle
    assert speeds[:4] == pytest.approx([1 - 0.4 ** k for k in range(1, 5)])
    assert speeds[2] < 0.95 <= speeds[3]  # 95 % of top speed in the fourth cycle
    assert speeds[-1] == pytest.approx(1.0, abs=1e-3) and max(speeds) <= PHYS.player_speed_max


def test_speed_limit_holds_before_the_noise_as_in_rcssserver() -> None:
    """rcssserver clips a body's speed, then adds its movement noise: the noise may carry a
    player up to ``player_rand`` beyond the limit, never further."""
    rand = 0.5
    config = replace(CONFIG, physics=replace(PHYS, player_rand=rand, dash_power_rate=0.02))
    players = Players(config)
    rng = np.random.default_rng(0)
    beyond = 0
    for _ in range(50):
        players.dash(rng.normal(size=(2 * N, 2)) * 5, rng.random((2 * N + 1, 2)))
        speeds = np.hypot(players.vel[:, 0], players.vel[:, 1])
        assert speeds.max() <= PHYS.player_speed_max * (1 + rand) + 1e-12
        beyond += int((speeds > PHYS.player_speed_max + 1e-9).sum())
    assert beyond > 0
    quiet = Players()
    for _ in range(20):
        quiet.dash(rng.normal(size=(2 * N, 2)) * 5)
        assert np.hypot(quiet.vel[:, 0], quiet.vel[:, 1]).max() <= PHYS.player_speed_max + 1e-12


@pytest.mark.parametrize("angle, rate", [(0.0, 1.0), (90.0, 0.4), (180.0, 0.7), (135.0, 0.55), (45.0, 0.7)])
def test_dashing_against_the_direction_of_motion_is_weaker(angle: float, rate: float) -> None:
    players = Players()
    players.vel[0] = (1.0, 0.0)  # running along +x, well above dash_heading_speed
    players.vel[1] = (0.0, 0.0)  # at rest: no heading, every direction is full strength
    a = math.radians(angle)
    dash = np.zeros((2 * N, 2))
    dash[0] = dash[1] = (10.0 * math.cos(a), 10.0 * math.sin(a))
    players.dash(dash)
    assert np.hypot(*dash[0]) == pytest.approx(0.6 * rate)  # rcssserver's side/back dash rates
    assert np.hypot(*dash[1]) == pytest.approx(0.6)
    # Slow motion blends towards full strength: at half the heading speed, half the penalty.
    slow = Players()
    slow.vel[0] = (PHYS.dash_heading_speed / 2, 0.0)
    dash = np.zeros((2 * N, 2))
    dash[0] = (-10.0, 0.0)
    slow.dash(dash)
    assert -dash[0, 0] == pytest.approx(0.6 * (1 - 0.5 * (1 - PHYS.back_dash_rate)))


def test_a_sprinter_whose_stamina_is_spent_slows_to_the_rcssserver_figure() -> None:
    stam = CONFIG.stamina
    players = Players()
    speeds = players.sprint(1500)
    # Spent: each cycle recovers recover_min x 45 = 22.5 and the dash may use 50 more, at the
    # lowest effort: (22.5 + 50) x 0.006 x 0.6 = 0.261 m/cycle², a speed of 0.261 / (1 - 0.4).
    model = (stam.recover_min * stam.recovery_per_cycle + stam.extra_stamina) * PHYS.dash_power_rate \
        * stam.effort_min / (1 - PHYS.player_decay)
    assert model == pytest.approx(0.435)
    assert speeds[-1] == pytest.approx(model, rel=0.10)
    assert players.effort[0] == stam.effort_min and players.recovery[0] == stam.recover_min
    assert speeds[100] > 0.95  # fresh players run at top speed for a good while first
    assert sum(speeds) < 0.6 * 1500 * 1.0  # far less ground than 1500 cycles at top speed


def test_effort_recovers_above_its_threshold_and_recovery_never_does() -> None:
    stam = CONFIG.stamina
    players = Players()
    players.sprint(600)
    tired_effort, tired_recovery = players.effort[0], players.recovery[0]
    for _ in range(400):  # rest
        players.dash(np.zeros((2 * N, 2)))
    assert players.stamina[0] >= stam.effort_inc_thr * stam.maximum
    assert players.effort[0] > tired_effort
    assert players.recovery[0] == tired_recovery  # restored only at half time


def test_once_the_capacity_is_spent_stamina_no_longer_recovers() -> None:
    config = replace(CONFIG, stamina=replace(StaminaConfig(), capacity=2000.0))
    players = Players(config)
    speeds = players.sprint(1500)
    assert players.capacity[0] == 0.0
    assert players.stamina[0] == 0.0
    # Only the extra stamina is left: 50 x 0.006 x 0.6 / 0.6 = 0.3 m/cycle.
    assert speeds[-1] == pytest.approx(50 * 0.006 * 0.6 / 0.6, rel=0.05)
    unlimited = Players(replace(CONFIG, stamina=replace(StaminaConfig(), capacity=None)))
    assert unlimited.sprint(1500)[-1] > speeds[-1] * 1.2


# --- kicks ---------------------------------------------------------------------------------
def test_kickable_distance_is_the_touch_distance_plus_the_margin() -> None:
    reach = PHYS.player_radius + PHYS.ball_radius + PHYS.kickable_margin
    assert reach == pytest.approx(1.085)
    assert kick_once((reach - 1e-6, 0.0), (1.0, 0.0))[0] == 1
    assert kick_once((reach + 1e-6, 0.0), (1.0, 0.0))[0] == 0


def test_kick_power_and_ball_speed_are_clipped() -> None:
    touch = PHYS.player_radius + PHYS.ball_radius
    _, velocity = kick_once((touch, 0.0), (100.0, 0.0))
    assert velocity == pytest.approx((PHYS.kick_speed_max, 0.0))
    # A holding goalkeeper kicks with full effect whatever the geometry.
    _, held = kick_once((0.0, 0.0), (-100.0, 0.0), holder=0)
    assert held == pytest.approx((-PHYS.kick_speed_max, 0.0))


def test_zero_kick_vector_is_no_kick_and_mask_forbids() -> None:
    assert kick_once((0.5, 0.0), (0.0, 0.0))[0] == 0
    kin = Kinematics(CONFIG, 2 * N)
    pos = FAR.copy()
    pos[0] = (0.0, 0.0)
    kick = np.ones((2 * N, 2))
    mask = np.ones(2 * N, dtype=bool)
    mask[0] = False
    count, _ = kin.kick_candidates(pos, np.array([0.5, 0.0]), kick, mask, -1, np.zeros(2 * N, dtype=np.int64))
    assert count == 0


# --- ball decay and the collision solver -----------------------------------------------------
def test_ball_decays_by_the_ball_decay_each_cycle() -> None:
    state, physics = world()
    kin = Kinematics(CONFIG, 2 * N)
    state.ball_vel[:] = (2.0, 0.0)
    x = state.ball[0]
    for cycle in range(10):
        physics.step(1)
        kin.decay(state.vel, state.ball_vel)
        x += 2.0 * PHYS.ball_decay ** cycle
        assert state.ball_vel[0] == pytest.approx(2.0 * PHYS.ball_decay ** (cycle + 1))
        assert state.ball[0] == pytest.approx(x)
    # The players decay differently: 0.4 per cycle.
    state.vel[0] = (1.0, 0.0)
    kin.decay(state.vel, state.ball_vel)
    assert state.vel[0, 0] == pytest.approx(PHYS.player_decay)


RIGID = replace(CONFIG, physics=replace(PHYS, body_ball_contact="rigid"))
SWEPT = replace(CONFIG, physics=replace(PHYS, body_ball_contact="swept"))


def planned(state: WorldState, ball_free: bool = True, config=CONFIG) -> int:
    return SubstepPlanner(config).count(state.bodies, ball_free)


@pytest.mark.parametrize("player_speed", [0.0, 1.05])
def test_swept_contacts_let_no_ball_pass_through_a_player(player_speed: float) -> None:
    state, physics = world(SWEPT)
    state.pos[0] = (0.0, 0.0)
    state.vel[0] = (-player_speed, 0.0)  # running at the ball makes it worse
    state.ball[:] = (-2.0, 0.0)
    state.ball_vel[:] = (PHYS.ball_speed_max, 0.0)
    assert planned(state, config=SWEPT) == 1  # the contact sweep is exact: no sub-steps needed for it
    touchers = physics.step(1)
    assert touchers.tolist() == [0]
    # Both are put back where they met, and their velocities multiplied by -0.1.
    contact = PHYS.player_radius + PHYS.ball_radius
    assert state.pos[0, 0] - state.ball[0] == pytest.approx(contact)
    t = (2.0 - contact) / (PHYS.ball_speed_max + player_speed)  # the moment they met
    assert state.ball[0] == pytest.approx(-2.0 + PHYS.ball_speed_max * t)
    assert state.ball_vel.tolist() == pytest.approx([-0.1 * PHYS.ball_speed_max, 0.0])
    assert state.vel[0].tolist() == pytest.approx([0.1 * player_speed, 0.0])


@pytest.mark.parametrize("player_speed", [0.0, 1.05])
def test_rigid_contacts_need_substeps_against_tunnelling(player_speed: float) -> None:
    state, physics = world(RIGID)
    state.pos[0] = (0.0, 0.0)
    state.vel[0] = (-player_speed, 0.0)
    state.ball[:] = (-1.2, 0.0)
    state.ball_vel[:] = (PHYS.ball_speed_max, 0.0)
    substeps = planned(state, config=RIGID)
    assert substeps == math.ceil((PHYS.ball_speed_max + player_speed) / PHYS.max_substep_distance)
    touchers = physics.step(substeps)
    assert state.ball[0] < state.pos[0, 0]  # still on the near side
    assert state.ball_vel[0] < 0.0  # bounced back
    assert touchers.tolist() == [0]


def test_without_substeps_a_rigid_ball_would_tunnel() -> None:
    """The control experiment: one step lets the ball jump through, so sub-steps matter."""
    state, physics = world(RIGID)
    state.pos[0] = (0.0, 0.0)
    state.ball[:] = (-1.2, 0.0)
    state.ball_vel[:] = (PHYS.ball_speed_max, 0.0)
    physics.step(1)
    assert state.ball[0] > 1.0


def test_a_running_body_stops_at_the_ball_with_swept_contacts() -> None:
    state, physics = world(SWEPT)
    state.pos[0], state.vel[0] = (-1.0, 0.0), (1.0, 0.0)
    state.ball[:] = (0.0, 0.0)
    assert physics.step(1).tolist() == [0]
    assert state.ball.tolist() == [0.0, 0.0] and state.ball_vel.tolist() == [0.0, 0.0]
    assert state.pos[0, 0] == pytest.approx(-(PHYS.player_radius + PHYS.ball_radius))
    assert state.vel[0, 0] == pytest.approx(-0.1)
    # With rigid contacts the same run drives the ball ahead at the player's speed.
    state, physics = world(RIGID)
    state.pos[0], state.vel[0] = (-1.0, 0.0), (1.0, 0.0)
    state.ball[:] = (0.0, 0.0)
    physics.step(planned(state, config=RIGID))
    assert state.ball_vel[0] > 0.9


def test_this_cycles_kicker_lets_the_ball_pass_with_swept_contacts() -> None:
    state, physics = world(SWEPT)
    state.pos[0] = (0.0, 0.0)
    state.ball[:] = (-0.5, 0.0)
    state.ball_vel[:] = (2.0, 0.0)  # kicked through the kicker's own body
    assert physics.step(1, np.array([0])).size == 0
    assert state.ball[0] == pytest.approx(1.5)


@pytest.mark.parametrize("speed", [0.4, 0.7, 1.05])
def test_players_running_head_on_do_not_pass_through_each_other(speed: float) -> None:
    state, physics = world()
    state.pos[0], state.vel[0] = (-0.8 * speed, 0.0), (speed, 0.0)
    state.pos[N], state.vel[N] = (0.8 * speed, 0.0), (-speed, 0.0)
    substeps = planned(state)
    assert substeps == math.ceil(2 * speed / (2 * PHYS.max_substep_distance) - 1e-9)
    physics.step(substeps)
    assert state.pos[0, 0] < state.pos[N, 0]
    if speed > PHYS.max_substep_distance:  # the control: one step would let them swap sides
        state2, physics2 = world()
        state2.body_table[:] = 0.0
        state2.pos[:] = FAR
        state2.ball[:] = BALL_AWAY
        state2.pos[0], state2.vel[0] = (-0.8 * speed, 0.0), (speed, 0.0)
        state2.pos[N], state2.vel[N] = (0.8 * speed, 0.0), (-speed, 0.0)
        physics2.step(1)
        assert state2.pos[0, 0] > state2.pos[N, 0]


def test_substeps_follow_closing_speeds_of_bodies_that_can_meet() -> None:
    step = PHYS.max_substep_distance
    state, _ = world()
    assert planned(state) == 1
    # A lone sprinter, and two players running side by side, need no sub-steps.
    state.vel[0] = (1.05, 0.0)
    state.pos[1], state.vel[1] = state.pos[0] + (0.0, 0.7), (1.05, 0.0)
    assert planned(state) == 1
    # Head-on towards a teammate within reach.
    state.pos[2], state.vel[2] = state.pos[0] + (2.0, 0.0), (-1.05, 0.0)
    assert planned(state) == math.ceil(2.1 / (2 * step))
    # A fast ball near a player: with rigid contacts the closing speed counts...
    state.ball[:] = state.pos[5] + (2.0, 0.0)
    state.ball_vel[:] = (-3.0, 0.0)
    assert planned(state, config=RIGID) == math.ceil(3.0 / step)
    assert planned(state) == math.ceil(2.1 / (2 * step))  # (rcssserver's contacts: only the end counts)
    assert planned(state, config=SWEPT) == math.ceil(2.1 / (2 * step))  # (swept contacts are exact)
    # ...not while a goalkeeper holds it...
    assert planned(state, ball_free=False, config=RIGID) == math.ceil(2.1 / (2 * step))
    # ...and not in free flight.
    state.ball[:] = (0.0, 20.0)
    assert planned(state, config=RIGID) == math.ceil(2.1 / (2 * step))
    # Near a thin goal post the ball may move at most the ball-post contact distance.
    state.vel[:] = 0.0
    state.ball[:] = (CONFIG.field.half_length - 2.0, CONFIG.field.goal_width / 2)
    state.ball_vel[:] = (3.0, 0.0)
    contact = CONFIG.field.goal_post_radius + PHYS.ball_radius
    assert planned(state) == math.ceil(3.0 / contact)


@pytest.mark.parametrize("offset", [0.01, 0.05, 0.1])
def test_ball_bounces_off_a_goal_post(offset: float) -> None:
    state, physics = world()
    post_y = CONFIG.field.goal_width / 2 + CONFIG.field.goal_post_radius
    state.ball[:] = (CONFIG.field.half_length - 3.0, post_y + offset)
    state.ball_vel[:] = (2.9, 0.0)
    for _ in range(2):
        physics.step(planned(state))
    # Deflected (by more than 30 degrees, outwards) rather than passing through.
    vx, vy = state.ball_vel.tolist()
    assert math.atan2(vy, vx) > math.radians(30)


def test_teammate_contacts_are_counted_once_per_contact_and_per_team() -> None:
    state, physics = world()
    state.pos[0] = (0.0, 0.0)
    state.pos[1] = (1.0, 0.0)  # home teammates 1 m apart
    state.pos[N] = (10.0, 0.0)
    state.pos[N + 1] = (11.0, 0.0)  # an away pair...
    state.pos[2] = (20.0, 0.0)
    state.pos[N + 2] = (21.0, 0.0)  # ...and a home-away pair
    for a, b in ((0, 1), (N, N + 1), (2, N + 2)):
        state.vel[a] = (0.3, 0.0)
        state.vel[b] = (-0.3, 0.0)
    physics.step(4)
    assert physics.teammate_contacts.tolist() == [1, 1]
    for _ in range(5):  # staying in contact is still one contact
        state.vel[0], state.vel[1] = (0.1, 0.0), (-0.1, 0.0)
        physics.step(1)
    assert physics.teammate_contacts.tolist() == [1, 1]
    state.pos[1] = (3.0, 0.0)  # apart...
    physics.step(1)
    state.pos[1] = (0.6, 0.0)  # ...and together again: a second contact
    physics.step(1)
    assert physics.teammate_contacts.tolist() == [2, 1]


def test_players_stay_within_the_field_and_its_margin() -> None:
    state, physics = world()
    state.pos[3] = (CONFIG.field.half_length + CONFIG.field.margin - 0.1, 0.0)
    state.vel[3] = (1.0, 0.0)
    state.pos[4] = (0.0, -CONFIG.field.half_width - CONFIG.field.margin + 0.1)
    state.vel[4] = (0.0, -1.0)
    physics.step(4)
    assert state.pos[3, 0] == pytest.approx(CONFIG.field.half_length + CONFIG.field.margin)
    assert state.pos[4, 1] == pytest.approx(-CONFIG.field.half_width - CONFIG.field.margin)


def test_held_ball_does_not_collide() -> None:
    state, physics = world()
    state.pos[0] = (0.0, 0.0)
    state.ball[:] = (0.0, 0.0)
    physics.set_ball_collides(False)
    assert physics.step(1).size == 0
    assert state.ball.tolist() == [0.0, 0.0]
    physics.set_ball_collides(True)
    assert physics.step(1).tolist() == [0]


def test_cycle_noise_is_uniform_and_drawn_in_one_fixed_block() -> None:
    noise = CycleNoise(np.random.default_rng(3), 2 * N)
    noise.draw()
    first = noise.values.copy()
    assert first.shape == (2 * (2 * N) + 1, 2)  # movement of every player and the ball, every player's kick
    assert np.shares_memory(noise.motion, noise.values) and noise.motion.shape == (2 * N + 1, 2)
    assert noise.kick.shape == (2 * N, 2) and np.array_equal(noise.ball, first[2 * N])
    assert ((first >= 0) & (first < 1)).all()
    again = CycleNoise(np.random.default_rng(3), 2 * N)
    again.draw()
    assert np.array_equal(first, again.values)


def test_a_swept_kick_plays_the_ball_around_the_kicker_but_not_through_others() -> None:
    state, physics = world(SWEPT)
    state.pos[0] = (0.0, 0.0)  # the kicker, ball just in front of it...
    state.pos[1] = (-1.4, 0.0)  # ...and a teammate behind it
    state.ball[:] = (0.5, 0.0)
    state.ball_vel[:] = (-2.0, 0.0)  # kicked back through the kicker
    touchers = physics.step(planned(state), kickers=np.array([0]))
    assert touchers.tolist() == [1]  # the kicker let it through; the teammate stopped it
    assert state.ball[0] > -1.4
    # After the kick cycle the kicker collides with the ball again.
    state.ball[:] = (0.5, 0.0)
    state.ball_vel[:] = (-1.0, 0.0)
    assert physics.step(4).tolist() == [0]


# --- the bulk body transfer's dependence on pymunk internals ----------------------------------
def test_bulk_transfer_round_trips_every_field_of_every_body() -> None:
    state, physics = world()
    rng = np.random.default_rng(5)
    state.bodies[:] = rng.uniform(-50.0, 50.0, state.bodies.shape)  # players and ball
    expected = state.bodies.copy()
    bodies = physics.space.bodies  # in the order they were added: the players, then the ball
    physics._bulk.write()
    got = np.array([[*b.position, *b.velocity] for b in bodies])
    assert np.array_equal(got, expected)
    for body in bodies:
        body.position = (body.position.x + 1.0, body.position.y)
        body.velocity = (body.velocity.x, body.velocity.y - 2.0)
    physics._bulk.read()
    assert np.array_equal(state.bodies[:, 0], expected[:, 0] + 1.0)
    assert np.array_equal(state.bodies[:, 3], expected[:, 3] - 2.0)
    assert np.array_equal(state.bodies[:, [1, 2]], expected[:, [1, 2]])
    assert state.body_table[-1].tolist() == [0.0, 0.0, 0.0, 0.0]  # the static body stays at rest


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


@pytest.mark.parametrize("cap_sum, expected", [(True, 2.7), (False, 3.0)])
def test_the_kicks_of_one_cycle_are_summed_and_capped(cap_sum: bool, expected: float) -> None:
    config = replace(CONFIG, physics=replace(PHYS, cap_summed_kicks=cap_sum))
    kin = Kinematics(config, 2 * config.players_per_team)
    touch = PHYS.player_radius + PHYS.ball_radius
    pos = FAR.copy()
    pos[0], pos[N] = (-touch, 0.0), (0.0, -touch)  # two players touching the ball, both kick it along +x
    ball, ball_vel = np.zeros(2), np.zeros(2)
    kick = np.zeros((2 * N, 2))
    kick[0] = kick[N] = (PHYS.kick_speed_max, 0.0)
    rows = np.zeros(2 * N, dtype=np.int64)
    count, _ = kin.kick_candidates(pos, ball, kick, np.ones(2 * N, dtype=bool), -1, rows)
    assert count == 2
    kin.kick(rows[:count], pos, np.zeros((2 * N, 2)), ball, ball_vel, kick, kin.ball_distance, -1, no_kick_noise())
    # rcssserver adds both kicks into one acceleration capped at 2.7; per-kick caps let the two
    # reach the ball speed limit (3.0).
    assert np.hypot(*ball_vel) == pytest.approx(expected)


def test_opposite_kicks_cancel_but_leave_the_ball_noise_of_both() -> None:
    """Two players kicking the ball at each other: the changes cancel, yet each kick's own
    noise (rcssserver draws it per kick, from the kick's power) still moves the ball, so two
    stubborn players cannot hold it still between them for ever."""
    config = replace(CONFIG, physics=replace(PHYS, kick_rand=0.1))
    kin = Kinematics(config, 2 * config.players_per_team)
    touch = PHYS.player_radius + PHYS.ball_radius
    pos = FAR.copy()
    pos[0], pos[N] = (-touch, 0.0), (touch, 0.0)
    kick = np.zeros((2 * N, 2))
    kick[0], kick[N] = (1.0, 0.0), (-1.0, 0.0)
    rows = np.zeros(2 * N, dtype=np.int64)
    count, _ = kin.kick_candidates(pos, np.zeros(2), kick, np.ones(2 * N, dtype=bool), -1, rows)
    ball_vel = np.zeros(2)
    noise = no_kick_noise()
    noise[0] = noise[N] = (1.0, 0.5)  # both at the top of their length range, direction +x
    kin.kick(rows[:count], pos, np.zeros((2 * N, 2)), np.zeros(2), ball_vel, kick, kin.ball_distance, -1, noise)
    # Each: kick_rand x power / max_power x (pos_rate 0.5 + speed_rate 0.5) = 0.1 x 1 / 2.7.
    assert ball_vel == pytest.approx((2 * 0.1 / 2.7, 0.0))
