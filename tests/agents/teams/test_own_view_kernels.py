"""Small kernels of the decentralised team's cycle against the numpy they stand for."""

from __future__ import annotations

import numpy as np
import pytest

from agents.teams.own_view_kernels import assignment_problems, whole_brain_rows


def test_assignment_problems_gather_each_players_own_beliefs():
    rng = np.random.default_rng(2)
    n, k, roles = 11, 10, 11
    outfield = np.arange(1, 11)
    mate_pos = rng.normal(size=(n, n, 2))
    targets = rng.normal(size=(n, roles, 2))
    match_roles = np.array([rng.permutation(roles)[:k] for _ in range(n)])
    rows = np.array([7, 2, 9])
    players, role_targets = np.full((n, k, 2), np.nan), np.full((n, k, 2), np.nan)
    assignment_problems(rows, outfield, mate_pos, targets, match_roles, players[:3], role_targets[:3])
    np.testing.assert_array_equal(players[:3], mate_pos[rows[:, None], outfield])
    np.testing.assert_array_equal(role_targets[:3], targets[rows[:, None], match_roles[rows]])
    assert np.isnan(players[3:]).all()  # nothing written past the rows


@pytest.mark.parametrize("play_on, set_play", [(True, False), (False, True), (False, False)])
def test_whole_brain_rows_split_the_present_players_and_clear_the_command(play_on, set_play):
    rng = np.random.default_rng(5)
    n = 11
    position = rng.uniform(-20, 20, (n, 2))
    ball = position + rng.normal(scale=2.0, size=(n, 2))  # some believe it near, some not
    present = np.ones(n, dtype=bool)
    present[4] = False
    out, deciding = np.zeros(n, dtype=bool), np.zeros(n, dtype=bool)
    dash, kick = rng.normal(size=(n, 2)), rng.normal(size=(n, 2))
    brains, positioned = whole_brain_rows(play_on, set_play, ball, position, np.zeros(n, dtype=bool), present,
                                          rng.normal(size=(n, n, 2)), np.arange(1, n), 3, False, 0, 2.2, 1.5,
                                          36.0, 20.0, out, deciding, dash, kick)
    np.testing.assert_array_equal(deciding, present & ~out)
    assert brains == out.sum() and positioned == deciding.sum() and not out[4]
    assert not dash.any() and not kick.any()
    if play_on:
        near = np.hypot(*(ball - position).T) < 2.2
        np.testing.assert_array_equal(out[1:], (near & present)[1:])
    elif set_play:
        assert out[3]  # the taker
    else:
        assert not out.any()
