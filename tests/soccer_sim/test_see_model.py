"""soccer_sim.perception: rcssserver's see for point robots, its schedule and self-localisation.
The server's formulas are recomputed here independently (math module, scalar) and compared."""

from __future__ import annotations

import math

import numpy as np
import pytest

from soccer_sim.config_checks import ConfigError
from soccer_sim.perception import (ANONYMOUS, FULL, TEAM_ONLY, UNSEEN, SeeParams, body_directions,
                                   field_flags, localise, see, see_cycles)

P = SeeParams()


def server_distance(d: float, qstep: float) -> float:
    """rcssserver's reported distance, written out scalar: Quantize(exp(Quantize(log(d+EPS), q)), 0.1)."""
    inner = round(math.log(d + 1e-10) / qstep) * qstep
    return round(math.exp(inner) / 0.1) * 0.1


def ring(center: tuple[float, float], distances: np.ndarray, angles_deg: np.ndarray) -> np.ndarray:
    a = np.radians(angles_deg)
    return np.stack([center[0] + distances * np.cos(a), center[1] + distances * np.sin(a)], axis=1)


def test_reported_distances_are_the_servers_levels_with_its_spread():
    rng = np.random.default_rng(3)
    true = rng.uniform(0.5, 60.0, 4000)
    balls = ring((0.0, 0.0), true, rng.uniform(-40.0, 40.0, true.size))
    got = np.array([see(np.zeros((1, 2)), [0.0], b, np.empty((0, 2)), rng).distance[0, 0] for b in balls[:400]])
    expect = np.array([server_distance(d, 0.1) for d in true[:400]])
    np.testing.assert_allclose(got, expect, atol=1e-9)
    # the whole sample through one vectorised call: observers at the origin, objects around
    s = see(np.zeros((1, 2)), [0.0], balls[0], balls, rng, SeeParams(omnidirectional=True))
    reported = s.distance[0, 1:]
    np.testing.assert_allclose(reported, [server_distance(d, 0.1) for d in true], atol=1e-9)
    # every value is a multiple of 0.1 m, and the log error is ~uniform on +-q/2 (mean 0, sd q/sqrt 12)
    assert np.allclose(reported * 10.0, np.rint(reported * 10.0))
    far = true > 10.0  # the final 0.1 m rounding is negligible here
    log_err = np.log(reported[far] / true[far])
    assert np.max(np.abs(log_err)) <= 0.05 + 0.1 / 10.0
    assert abs(np.mean(log_err)) < 0.005
    assert np.std(log_err) == pytest.approx(0.1 / math.sqrt(12.0), rel=0.1)
    # distinct levels near 20 m: exp(k * 0.1) rounded to 0.1 m
    near20 = reported[(true > 19.0) & (true < 21.0)]
    assert set(np.round(near20, 6)) <= {round(round(math.exp(k * 0.1) / 0.1) * 0.1, 6) for k in (29, 30, 31)}


def test_nobody_sees_outside_its_cone_or_range():
    rng = np.random.default_rng(5)
    observers = rng.uniform([-50, -30], [50, 30], (11, 2))
    bodies = rng.uniform(-180, 180, 11)
    for _ in range(30):
        players = rng.uniform([-55, -35], [55, 35], (22, 2))
        players[:11] = observers
        ball = rng.uniform([-52, -34], [52, 34])
        s = see(observers, bodies, ball, players, rng, self_index=np.arange(11))
        objects = np.vstack([ball, players])
        off = objects[None] - observers[:, None]
        dist = np.hypot(off[..., 0], off[..., 1])
        rel = (np.degrees(np.arctan2(off[..., 1], off[..., 0])) - bodies[:, None] + 180) % 360 - 180
        in_cone = np.abs(rel) < 45.0
        assert not np.any(s.seen & ~in_cone & (dist > 3.0))
        assert not np.any(s.seen & (dist >= P.max_observation_length))
        assert not np.any(s.seen[np.arange(11), np.arange(11) + 1])  # nobody sees itself
        others = ~np.eye(11, 23, 1, dtype=bool)
        assert np.all(s.seen[in_cone & others] | (dist[in_cone & others] >= P.max_observation_length))
        assert np.all(s.seen[(dist <= 3.0) & others])
        # seen outside the cone: anonymous (the ball stays the ball)
        behind = s.seen & ~in_cone
        assert np.all(s.identity[:, 1:][behind[:, 1:]] == ANONYMOUS)
        assert np.all(s.identity[~s.seen] == UNSEEN) and np.all(np.isnan(s.distance[~s.seen]))


def test_behind_within_visible_distance_keeps_distance_and_direction():
    s = see(np.zeros((1, 2)), [0.0], (-2.0, 0.5), np.array([[0.0, -2.9], [-3.1, 0.0]]), np.random.default_rng(0))
    assert s.seen[0].tolist() == [True, True, False]
    assert not s.in_cone[0, 0] and s.identity[0, 0] == FULL
    assert s.distance[0, 0] == pytest.approx(server_distance(math.hypot(2.0, 0.5), 0.1))
    assert s.direction[0, 0] == round(math.degrees(math.atan2(0.5, -2.0)))
    assert s.direction[0, 1] == -90.0 and s.identity[0, 1] == ANONYMOUS


def test_omnidirectional_sees_everything_in_range_with_identity():
    rng = np.random.default_rng(1)
    players = ring((0.0, 0.0), np.full(36, 10.0), np.arange(0.0, 360.0, 10.0))
    cone = see(np.zeros((1, 2)), [0.0], (0.0, -8.0), players, rng)
    omni = see(np.zeros((1, 2)), [0.0], (0.0, -8.0), players, rng, SeeParams(omnidirectional=True))
    assert cone.seen[0].sum() == 9  # -40..40 degrees only (45 is on the cone's edge: not seen)
    assert omni.seen[0].all() and np.all(omni.identity[0] == FULL)


def test_identity_is_certain_inside_the_far_lengths_and_lost_beyond_the_too_far_ones():
    rng = np.random.default_rng(11)
    dists = np.array([5.0, 19.0, 30.0, 45.0, 50.0, 65.0, 100.0])
    players = ring((0.0, 0.0), dists, np.zeros(dists.size))
    levels = np.stack([see(np.zeros((1, 2)), [0.0], (1.0, 1.0), players, rng).identity[0, 1:]
                       for _ in range(4000)])
    assert np.all(levels[:, :2] == FULL)  # reported (18.2 m) <= unum_far_length (20 m)
    assert np.all(levels[:, 5:] == ANONYMOUS)  # reported >= team_too_far_length (60 m)
    assert np.all(levels[:, 3:5] != FULL)  # beyond unum_too_far_length (40 m): no number
    # in between, the server's linear chances (from the reported distance)
    d30 = server_distance(30.0, 0.1)
    assert np.mean(levels[:, 2] == TEAM_ONLY) == pytest.approx((d30 - 20.0) / 20.0, abs=0.03)
    d50 = server_distance(50.0, 0.1)
    assert np.mean(levels[:, 4] == ANONYMOUS) == pytest.approx((d50 - 40.0) / 20.0, abs=0.03)


def test_directions_are_rounded_to_whole_degrees_relative_to_the_body():
    rng = np.random.default_rng(2)
    angles = rng.uniform(-44.0, 44.0, 500)
    body = 123.4
    players = ring((3.0, -2.0), np.full(500, 15.0), body + angles)
    s = see(np.array([[3.0, -2.0]]), [body], (0.0, 0.0), players, rng)
    np.testing.assert_allclose(s.direction[0, 1:], np.rint(angles), atol=1e-9)
    coarse = see(np.array([[3.0, -2.0]]), [body], (0.0, 0.0), players, rng, SeeParams(direction_step=5.0))
    assert np.all(coarse.direction[0, 1:] % 5.0 == 0.0)
    assert np.max(np.abs(coarse.direction[0, 1:] - angles)) <= 2.5 + 1e-9


def test_body_directions_follow_the_simulators_facing_model():
    dirs = body_directions(np.array([[0.0, 0.0], [0.0, 0.0]]), np.array([[0.0, 0.0], [1.0, 0.0]]), (0.0, 5.0))
    assert dirs == pytest.approx([90.0, 30.0])


def test_sees_arrive_alternately_after_one_and_two_cycles():
    cycles = np.arange(300)
    gaps = np.diff(np.nonzero(see_cycles(cycles))[0])
    assert set(gaps[::2]) == {1} and set(gaps[1::2]) == {2}
    assert see_cycles(cycles).sum() == 200  # 2 sees per 3 cycles = one per 150 ms
    shifted = see_cycles(cycles, offset_ms=np.full(300, 50))  # sees at 50, 200, 350 ms
    assert np.nonzero(shifted)[0][:4].tolist() == [0, 2, 3, 5]
    assert see_cycles(cycles, SeeParams(send_step=100)).all()


def test_a_seed_gives_the_same_sightings_and_another_seed_other_identities():
    rng = np.random.default_rng(0)
    observers = rng.uniform(-40, 40, (11, 2))
    players = rng.uniform(-50, 50, (22, 2))
    bodies = rng.uniform(-180, 180, 11)
    a = see(observers, bodies, (0.0, 0.0), players, np.random.default_rng(42))
    b = see(observers, bodies, (0.0, 0.0), players, np.random.default_rng(42))
    c = see(observers, bodies, (0.0, 0.0), players, np.random.default_rng(43))
    for field in ("seen", "identity"):
        assert np.array_equal(getattr(a, field), getattr(b, field))
    np.testing.assert_array_equal(a.distance, b.distance)
    many = [see(observers, bodies, (0.0, 0.0), players, np.random.default_rng(s)).identity for s in range(20)]
    assert any(not np.array_equal(many[0], m) for m in many[1:]) and np.array_equal(a.seen, c.seen)


def test_self_localisation_error_follows_the_flag_quantisation():
    rng = np.random.default_rng(9)
    pos = rng.uniform([-50, -32], [50, 32], (300, 2))
    vel = rng.uniform(-1.0, 1.0, (300, 2))
    body = rng.uniform(-180, 180, 300)
    est = localise(pos, vel, body)
    assert est.localised.all() and np.all(est.flags_seen >= 1)
    err = np.hypot(*(est.position - pos).T)
    # each flag's estimate errs by at most 0.05 m + 0.5 % along and d sin(0.5 deg) across the sight line
    flags = field_flags()
    far = np.max(np.hypot(*(flags[None] - pos[:, None]).transpose(2, 0, 1)), axis=1)
    assert np.all(err <= 0.05 + far * (math.exp(0.005) - 1.0 + math.sin(math.radians(0.5))) + 1e-9)
    assert 0.0 < np.median(err) < 0.5
    speed = np.hypot(*est.velocity.T)
    np.testing.assert_allclose(speed, np.rint(np.hypot(*vel.T) / 0.01) * 0.01, atol=1e-12)
    exact = localise(pos, vel, body, SeeParams(exact_self=True))
    np.testing.assert_array_equal(exact.position, pos)
    np.testing.assert_array_equal(exact.velocity, vel)
    # a player looking out of the field from beyond its corner sees no flag
    lost = localise(np.array([[70.0, 50.0]]), np.zeros((1, 2)), [45.0])
    assert not lost.localised[0] and np.isnan(lost.position).all()


def test_the_field_has_the_servers_55_flags():
    flags = field_flags()
    assert flags.shape == (55, 2) and len({tuple(f) for f in flags.round(6)}) == 55
    assert [0.0, 0.0] in flags.tolist() and [-57.5, 0.0] in flags.tolist() and [50.0, 39.0] in flags.tolist()


@pytest.mark.parametrize("field, value", [("visible_angle", 0.0), ("visible_distance", -1.0),
                                          ("quantize_step", float("nan")), ("unum_too_far_length", 10.0),
                                          ("team_too_far_length", 30.0), ("send_step", 150.5),
                                          ("omnidirectional", 1), ("visible_angle", 400.0)])
def test_bad_parameters_name_the_field(field, value):
    with pytest.raises(ConfigError, match=f"SeeParams.{field}"):
        SeeParams(**{field: value})


def test_bad_shapes_are_a_clear_error():
    rng = np.random.default_rng(0)
    with pytest.raises(ValueError, match="body_dirs"):
        see(np.zeros((2, 2)), [0.0], (0, 0), np.zeros((3, 2)), rng)
    with pytest.raises(ValueError, match="observers"):
        see(np.zeros(3), [0.0], (0, 0), np.zeros((3, 2)), rng)
    with pytest.raises(ValueError, match="self_index"):
        see(np.zeros((1, 2)), [0.0], (0, 0), np.zeros((3, 2)), rng, self_index=[3])


@pytest.mark.parametrize("angle, omni", [(90.0, False), (150.0, False), (180.0, False), (200.0, False),
                                         (90.0, True)])
def test_the_square_shortcut_changes_no_sighting_and_no_localisation(monkeypatch, angle, omni):
    """Objects and flags surely out of view are skipped before their distance is taken
    (``_surely_unseen``); copies of the kernels compiled without that shortcut see and localise
    the same, bit for bit, on random scenes with objects on the cone's edges and at exactly
    ``visible_distance``."""
    from numba import njit

    from soccer_sim.perception import kernels
    from soccer_sim.perception.localise import DEFAULT_FLAGS

    prm = kernels.see_record(SeeParams(visible_angle=angle, omnidirectional=omni))
    monkeypatch.setattr(kernels, "_surely_unseen", njit(lambda dx, dy, bx, by, close2, cos2: False))
    monkeypatch.setattr(kernels, "_see_one", njit(kernels._see_one.py_func))
    monkeypatch.setattr(kernels, "_localise_one", njit(kernels._localise_one.py_func))
    plain_see, plain_localise = njit(kernels.see_into.py_func), njit(kernels.localise_into.py_func)
    # (numba reads the globals when it compiles: compile the copies now, while they are patched)
    plain_see(np.zeros((1, 2)), np.zeros(1), np.ones((2, 2)), np.zeros(1, dtype=np.int64), np.ones(2, dtype=bool),
              np.zeros((2, 1, 2)), prm,
              kernels.SightingRows(*(np.empty((1, 2), dtype=t) for t in (bool, float, float, np.int8, bool))))
    plain_localise(np.zeros((1, 2)), np.zeros(1), DEFAULT_FLAGS, prm, np.empty((1, 2)), np.empty(1, dtype=np.int64))
    monkeypatch.undo()
    rng = np.random.default_rng(21)
    close, half = prm[0]["visible_distance"], prm[0]["half_angle"]
    skipped = 0
    for scene in range(40):
        obs = rng.uniform([-50, -30], [50, 30], (11, 2))
        body = rng.uniform(-180, 180, 11)
        objects = rng.uniform([-55, -35], [55, 35], (23, 2))
        for k in range(10):  # on the cone's edges and about the visible distance, for observer 0
            a = math.radians(body[0] + (half if k % 2 else -half)) if k < 4 else rng.uniform(-math.pi, math.pi)
            r = close * (1.0, 0.9999, 1.0001)[k % 3] if k >= 4 else rng.uniform(1.0, 40.0)
            objects[1 + k] = obs[0] + r * np.array([math.cos(a), math.sin(a)])
        args = (obs, body, objects, np.arange(11), np.ones(23, dtype=bool), rng.random((2, 11, 23)), prm)
        outs = [kernels.SightingRows(*(np.empty((11, 23), dtype=t) for t in (bool, float, float, np.int8, bool)))
                for _ in range(2)]
        kernels.see_into(*args, outs[0])
        plain_see(*args, outs[1])
        for mine, theirs in zip(*outs):
            np.testing.assert_array_equal(mine, theirs)
        flags = np.vstack([DEFAULT_FLAGS, obs[0] + close * np.array([[1.0, 0.0], [0.0, -1.0]])])
        estimates = [(np.empty((11, 2)), np.empty(11, dtype=np.int64)) for _ in range(2)]
        kernels.localise_into(obs, body, flags, prm, *estimates[0])
        plain_localise(obs, body, flags, prm, *estimates[1])
        np.testing.assert_array_equal(estimates[0][0], estimates[1][0])
        np.testing.assert_array_equal(estimates[0][1], estimates[1][1])
        b = math.radians(body[0])
        cos_half = math.cos(math.radians(half))
        bounds = kernels._unseen_bounds(cos_half, close, prm)
        skipped += sum(kernels._surely_unseen(*(o - obs[0]), math.cos(b), math.sin(b), *bounds) for o in objects)
    assert (skipped > 0) == (cos_half > 0.0 and not omni)  # the shortcut ran where it may
