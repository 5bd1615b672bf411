"""A player's own goal point (:func:`agents.teams.own_view_after.own_goals`): the goalkeeper
comes out only for a ball it wins inside our penalty area, as the whole team's rule
(:func:`agents.skills.comes_out`) has it; otherwise the outfield player it believes nearest goes."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import MotionModel
from agents.teams.own_view_after import own_goals
from soccer_sim import MatchConfig

MODEL = MotionModel.even_sides(MatchConfig())
HALF = MODEL.half_length
AREA_X = MODEL.half_length - MODEL.penalty_area_length
AREA_Y = MODEL.penalty_area_half_width


def goal_of_the_first_outfielder(keeper_point: tuple[float, float]) -> tuple[np.ndarray, bool]:
    """Player 1's goal and hurry when it believes goalkeeper 0 reaches the ball first (cycle 2,
    opponents at 20) at ``keeper_point``, itself next (cycle 5, at (-40, 0)); its role's target
    is (-30, 10)."""
    n, k = 3, 2
    rank = np.array([-1, 0, 1])
    followed = np.tile(np.arange(k), (n, 1))
    out_roles = np.tile(np.array([1, 2]), (n, 1))
    targets = np.zeros((n, 3, 2))
    targets[:, 1] = (-30.0, 10.0)
    cycles = np.tile(np.array([2, 5, 9]), (n, 1)).astype(np.int64)
    points = np.zeros((n, n, 2))
    points[:, 0] = keeper_point
    points[:, 1] = (-40.0, 0.0)
    goals, urgent = np.zeros((n, 2)), np.zeros(n, dtype=bool)
    own_goals(np.array([1]), rank, followed, targets, out_roles, np.array([1, 2]), 0, True, cycles, points,
              np.zeros(n, dtype=np.int64), np.full(n, 20, dtype=np.int64), np.zeros((n, 2)), np.full((n, 4, 2), 40.0),
              1.0, 1, 3, AREA_X, AREA_Y, HALF, goals, urgent)
    return goals[1], bool(urgent[1])


@pytest.mark.parametrize("point, keeper_goes", [((-HALF + 1.0, 0.0), True), ((-AREA_X - 0.5, AREA_Y - 0.5), True),
                                                 ((-HALF - 0.05, 0.0), False), ((-AREA_X + 1.0, 0.0), False),
                                                 ((-HALF + 1.0, AREA_Y + 0.5), False)])
def test_the_goalkeeper_comes_out_only_inside_the_area(point, keeper_goes) -> None:
    goal, urgent = goal_of_the_first_outfielder(point)
    if keeper_goes:  # the outfield player keeps to its role
        assert not urgent and np.array_equal(goal, (-30.0, 10.0))
    else:  # it goes for the ball instead of the goalkeeper
        assert urgent and np.array_equal(goal, (-40.0, 0.0))
