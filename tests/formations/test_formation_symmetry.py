"""Mirror symmetry: completing from one half, and reporting asymmetries."""

from __future__ import annotations

import numpy as np
import pytest

import formations
from formations import Formation, FormationError, Situation
from formations.symmetry import asymmetries, mirror_complete, mirror_permutation, mirror_positions, query_asymmetry
from tests.formations.formation_samples import eleven_roles, scattered_balls


def half_formation() -> Formation:
    rng = np.random.default_rng(2)
    balls = scattered_balls(rng, 30)
    balls[:, 1] = np.abs(balls[:, 1])
    inner = balls[4:][balls[4:, 1] > 1.0]  # near-axis samples would be near-duplicates of their mirrors
    balls = np.vstack((balls[[0, 2]], inner, [[-20.0, 0.0], [25.0, 0.0]]))  # one corner per side, two axis samples
    positions = rng.uniform(-40.0, 40.0, (len(balls), 11, 2))
    return Formation(eleven_roles(), balls, positions, name="half")


def test_mirror_complete_makes_an_exactly_symmetric_formation():
    half = half_formation()
    full = mirror_complete(half)
    on_axis = int(np.sum(np.abs(half.balls[:, 1]) <= 1e-9))
    assert full.n_samples == 2 * half.n_samples - on_axis
    assert asymmetries(full, tolerance=0.0) == []
    # Off-axis samples are kept unchanged ...
    for ball, positions in zip(half.balls, half.sample_positions):
        if ball[1] > 0:
            row = int(np.flatnonzero((full.balls == ball).all(axis=1))[0])
            np.testing.assert_array_equal(full.sample_positions[row], positions)
    # ... and their mirror images swap partners: the left back takes the right back's mirrored place.
    ball = half.balls[5]
    mirrored = full.positions_many((ball * (1, -1))[None])[0]
    index = {r.number: i for i, r in enumerate(full.roles)}
    assert np.allclose(mirrored[index[3]], half.sample_positions[5][index[2]] * (1, -1))
    assert np.allclose(mirrored[index[7]], half.sample_positions[5][index[7]] * (1, -1))


def test_asymmetries_name_the_sample_and_role():
    full = mirror_complete(half_formation())
    positions = full.sample_positions.copy()
    positions[6, full.index_of(10), 0] += 0.25
    broken = Formation(full.roles, full.balls, positions)
    found = asymmetries(broken)
    assert {(a.sample, a.role) for a in found} >= {(6, 10)}
    assert all(abs(a.error - 0.25) < 1e-9 for a in found)
    assert any(a.describe() == "sample 6, role 10: 0.25 m from the mirror of its partner" for a in found)


def test_a_sample_without_a_mirror_is_reported():
    full = mirror_complete(half_formation())
    balls = full.balls.copy()
    balls[3] += (0.0, 0.7)
    found = asymmetries(Formation(full.roles, balls, full.sample_positions))
    lonely = [a for a in found if a.role is None]
    assert {a.sample for a in lonely} >= {3}
    assert lonely[0].describe().endswith("no sample has the mirrored ball position")


def test_mirror_complete_refuses_samples_on_both_sides():
    half = half_formation()
    balls = half.balls.copy()
    balls[4, 1] = -balls[4, 1]
    mixed = Formation(half.roles, balls, half.sample_positions, name="mixed")
    with pytest.raises(FormationError, match="formation 'mixed': sample 4: .*one side of y = 0"):
        mirror_complete(mixed)


def test_mirror_positions_is_an_involution(random_formation):
    perm = mirror_permutation(random_formation)
    twice = mirror_positions(mirror_positions(random_formation.sample_positions, perm), perm)
    np.testing.assert_array_equal(twice, random_formation.sample_positions)


@pytest.mark.parametrize("name", ["4-3-3", "4-4-2"])
def test_builtins_are_mirror_symmetric_to_1e_9(name):
    rng = np.random.default_rng(4)
    balls = np.column_stack((rng.uniform(-60, 60, 4000), rng.uniform(-42, 42, 4000)))
    team = formations.load_builtin(name)
    for situation in Situation:
        formation = team.formation(situation)
        assert asymmetries(formation, tolerance=1e-9) == []
        # The triangulation itself is symmetric, so every query is.
        assert query_asymmetry(formation, balls) <= 1e-9
        perm = mirror_permutation(formation)
        for ball in balls[:50]:
            direct = formation.positions(ball)
            mirrored = mirror_positions(formation.positions(ball * (1, -1)), perm)
            np.testing.assert_allclose(direct, mirrored, rtol=0, atol=1e-9)
