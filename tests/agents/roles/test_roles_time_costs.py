"""Role assigners with players of different speeds (``RoleContext.time_scale``): time costs,
and plain distances exactly as before when the players are equal."""

from __future__ import annotations

import numpy as np
import pytest

from agents.roles import RoleError, assigner_names, make_assigner, offensive_order
from agents.roles.base import RoleContext

_HALF_LENGTH, _HALF_WIDTH = 52.5, 34.0


def _context(scale=None, ball=(0.0, 0.0)) -> RoleContext:
    return RoleContext(ball=np.array(ball, float), own_goal=np.array([-_HALF_LENGTH, 0.0]),
                       opp_goal=np.array([_HALF_LENGTH, 0.0]), opponents=np.zeros((0, 2)),
                       field_half_length=_HALF_LENGTH, field_half_width=_HALF_WIDTH, cycle=0, attacking=False,
                       time_scale=None if scale is None else np.asarray(scale, float))


def _assign(name: str, players, targets, scale=None) -> list[int]:
    assigner = make_assigner(name)
    players, targets = np.asarray(players, float), np.asarray(targets, float)
    assigner.reset(len(players), np.random.default_rng(0))
    return assigner.assign(players, targets, offensive_order(targets), None, _context(scale)).tolist()


# Player 0 is slow (half speed, time factor 2) and 18 m from the far target, player 1 fast and
# 30 m from it. By distance the slow one goes far (makespan 18 v 30); by time the fast one
# does (30 v 36 metres at the reference speed).
PLAYERS = [[12.0, 0.0], [0.0, 1.0]]
TARGETS = [[0.0, 0.0], [30.0, 0.0]]


@pytest.mark.parametrize("name", ["mmdr", "mmd+msd2", "greedy-offense"])
def test_a_faster_far_player_takes_the_far_target(name: str) -> None:
    assert _assign(name, PLAYERS, TARGETS) == [1, 0]
    assert _assign(name, PLAYERS, TARGETS, scale=[2.0, 1.0]) == [0, 1]


def test_bidding_bids_are_times() -> None:
    assigner = make_assigner("bidding")
    assigner.reset(2, np.random.default_rng(0))
    players, targets = np.array(PLAYERS), np.array(TARGETS)
    plain = assigner.bids(players, targets, _context(ball=(40.0, 20.0)))
    timed = assigner.bids(players, targets, _context([2.0, 1.0], ball=(40.0, 20.0)))
    assert np.allclose(timed[0, :2], 2.0 * plain[0, :2]) and np.array_equal(timed[1, :2], plain[1, :2])


@pytest.mark.parametrize("name", assigner_names())
def test_equal_speeds_give_exactly_the_distance_assignment(name: str) -> None:
    rng = np.random.default_rng(5)
    for _ in range(20):
        players = np.column_stack((rng.uniform(-50, 50, 10), rng.uniform(-30, 30, 10)))
        targets = np.column_stack((rng.uniform(-50, 50, 10), rng.uniform(-30, 30, 10)))
        assert _assign(name, players, targets, scale=np.ones(10)) == _assign(name, players, targets)


def test_bad_time_scale_is_a_clear_error() -> None:
    with pytest.raises(RoleError, match="time_scale must be a finite positive float64"):
        _assign("mmdr", PLAYERS, TARGETS, scale=[1.0, -1.0])
