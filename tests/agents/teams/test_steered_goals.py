"""A steering assigner's one-step goals become goals as far as the role targets, in the step's
direction, so that the team's pacing (by distance to the goal) does not read a short field
step as "arrived"; and the built-in bidding team's players run to their places."""

from __future__ import annotations

import numpy as np

from agents.teams.role_kernels import steered_goals


def test_a_short_step_is_stretched_to_the_role_targets_distance_in_its_direction() -> None:
    players = np.array([[0.0, 0.0], [10.0, 5.0], [3.0, 3.0]])
    steps = np.array([[1.0, 0.0], [10.0, 4.0], [3.0, 3.0]])      # a step right, a step down, no step
    anchors = np.array([[0.0, 20.0], [10.0, 5.5], [9.0, 9.0]])     # 20 m away, 0.5 m away, far
    goals = steered_goals(players, steps, anchors)
    np.testing.assert_allclose(goals[0], [20.0, 0.0])             # the step's direction, 20 m out
    np.testing.assert_allclose(goals[1], [10.0, 4.0])             # a step longer than the way: kept
    np.testing.assert_allclose(goals[2], [3.0, 3.0])              # no step: stays


def test_the_bidding_teams_players_keep_near_their_role_targets() -> None:
    from soccer_sim import MatchConfig, run_match

    result = run_match("bidding", "mmdr", seed=1, config=MatchConfig(max_cycles=600))
    figures = result.statistics[0].reported
    # With one-step goals the pacing left bidding's players about 10 m from their targets on
    # average (the other assigners: about 5 m).
    assert figures["target_distance_mean"] < 8.0
