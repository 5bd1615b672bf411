"""Role behaviours (:mod:`agents.teams.role_behaviours`): each position moves its formation
target its own way, checked on the built-in formations' real targets and hand-placed
opponents (team frame, we attack +x)."""

from __future__ import annotations

import numpy as np
import pytest

import formations
from agents.teams.positions import position_labels
from agents.teams.role_behaviours import RoleBehaviours, RoleParams
from formations import Situation

HALF_LENGTH, HALF_WIDTH = 52.5, 34.0
FAR_AWAY = np.array([[60.0, 30.0], [60.0, -30.0]])
"""Two opponents far from everybody (their offside line at x = 60 unless the ball is ahead)."""


def _setup(system: str, situation: Situation, ball, opponents=FAR_AWAY):
    fs = formations.load_builtin(system)
    labels = np.array(position_labels(fs))
    before = fs.positions(ball, situation).copy()
    after = before.copy()
    RoleBehaviours(fs, HALF_LENGTH, HALF_WIDTH).adjust(after, situation == Situation.ATTACK, np.asarray(ball, float),
                                                      np.asarray(opponents, float))
    return labels, before, after


def test_centre_backs_mark_the_nearest_forward_goal_side_each_a_different_one() -> None:
    ball = np.array([-25.0, 0.0])
    fs = formations.load_builtin("4-3-3")
    labels = np.array(position_labels(fs))
    targets = fs.positions(ball, Situation.DEFEND)
    cbs = np.flatnonzero(labels == "centre-back")
    # One forward near each centre-back's target, plus a third next to the first.
    forwards = np.array([targets[cbs[0]] + (3.0, 2.0), targets[cbs[1]] + (4.0, -1.0),
                         targets[cbs[0]] + (3.5, 2.5), [40.0, 0.0]])
    _, _, after = _setup("4-3-3", Situation.DEFEND, ball, forwards)
    goal = np.array([-HALF_LENGTH, 0.0])
    for cb, fwd in zip(cbs, forwards[:2]):
        assert np.linalg.norm(after[cb] - fwd) == pytest.approx(RoleParams().mark_distance, abs=1e-6)
        # goal-side: between the forward and the middle of our goal
        assert np.linalg.norm(after[cb] - goal) < np.linalg.norm(fwd - goal) - 1.9
    # Nobody near: the centre-backs keep their formation slots, on the last line.
    _, before, alone = _setup("4-3-3", Situation.DEFEND, ball, FAR_AWAY)
    np.testing.assert_allclose(alone[cbs, 1], before[cbs, 1])
    assert (alone[cbs, 0] <= before[cbs, 0]).all()


@pytest.mark.parametrize("system", ["4-3-3", "4-4-2"])
@pytest.mark.parametrize("situation", [Situation.ATTACK, Situation.DEFEND])
@pytest.mark.parametrize("ball", [(-30.0, 10.0), (0.0, -20.0), (30.0, 25.0)])
def test_centre_backs_hold_the_last_line_and_wingers_are_the_widest(system, situation, ball) -> None:
    labels, _, after = _setup(system, situation, ball)
    outfield = labels != "goalkeeper"
    cb = labels == "centre-back"
    rest = outfield & ~cb
    assert after[cb, 0].max() <= after[rest, 0].min() - RoleParams().back_line_gap + 1e-9
    if situation == Situation.ATTACK and ball[0] < HALF_LENGTH / 3.0:
        wide = np.isin(labels, ["winger", "wide-midfielder"])
        assert np.abs(after[wide, 1]).min() > np.abs(after[outfield & ~wide, 1]).max()


def test_full_backs_overlap_on_the_ball_side_and_tuck_in_when_defending() -> None:
    ball = (10.0, 25.0)  # left side (+y)
    labels, before, after = _setup("4-3-3", Situation.ATTACK, ball)
    fbs = np.flatnonzero(labels == "full-back")
    left = fbs[before[fbs, 1] > 0][0]
    right = fbs[before[fbs, 1] < 0][0]
    assert after[left, 0] == pytest.approx(before[left, 0] + RoleParams().overlap_push)
    assert after[left, 1] >= RoleParams().overlap_width * HALF_WIDTH - 1e-9
    np.testing.assert_allclose(after[right], before[right])  # far side: stays
    labels, before, after = _setup("4-3-3", Situation.DEFEND, (-20.0, 0.0))
    np.testing.assert_allclose(np.abs(after[fbs, 1]), RoleParams().tuck_in * np.abs(before[fbs, 1]))


def test_the_holding_midfielder_screens_between_ball_and_goal_in_front_of_the_centre_backs() -> None:
    ball = np.array([5.0, -20.0])
    labels, _, after = _setup("4-3-3", Situation.DEFEND, ball)
    hm = int(np.flatnonzero(labels == "holding-midfielder")[0])
    cb_x = after[labels == "centre-back", 0].mean()
    assert after[hm, 0] == pytest.approx(cb_x + RoleParams().screen_gap)
    # on the straight line from the middle of our goal to the ball
    goal = np.array([-HALF_LENGTH, 0.0])
    along = (after[hm] - goal) / np.linalg.norm(after[hm] - goal)
    to_ball = (ball - goal) / np.linalg.norm(ball - goal)
    assert along @ to_ball == pytest.approx(1.0, abs=1e-9)
    # attacking: it stays behind the ball
    labels, before, after = _setup("4-3-3", Situation.ATTACK, (10.0, 0.0))
    assert before[hm, 0] > 10.0 - RoleParams().hold_behind
    assert after[hm, 0] == pytest.approx(10.0 - RoleParams().hold_behind)
    assert after[hm, 0] >= after[labels == "centre-back", 0].max() + RoleParams().back_line_gap


def test_central_midfielders_come_to_passing_distance_when_we_attack() -> None:
    ball = np.array([30.0, -25.0])
    labels, before, after = _setup("4-3-3", Situation.ATTACK, ball)
    cms = labels == "central-midfielder"
    assert (np.linalg.norm(before[cms] - ball, axis=1) > RoleParams().support_distance).any()
    assert (np.linalg.norm(after[cms] - ball, axis=1) <= RoleParams().support_distance + 1e-9).all()


def test_wingers_and_the_centre_forward_run_to_the_offside_line_when_we_attack() -> None:
    opponents = np.array([[30.0, 0.0], [28.0, 5.0], [10.0, 0.0], [50.0, 0.0]])  # second-last at x = 30
    labels, before, after = _setup("4-3-3", Situation.ATTACK, (0.0, 5.0), opponents)
    high = np.isin(labels, ["winger", "centre-forward"])
    assert (before[high, 0] < 29.0 - 1.0).all()
    np.testing.assert_allclose(after[high, 0], 30.0 - RoleParams().behind_line)


def test_the_centre_forward_does_not_drop_deep_to_defend() -> None:
    labels, before, after = _setup("4-4-2", Situation.DEFEND, (-40.0, 10.0))
    cf = labels == "centre-forward"
    assert (before[cf, 0] < RoleParams().forward_floor).all()
    np.testing.assert_allclose(after[cf, 0], RoleParams().forward_floor)


def test_bad_parameters_are_named() -> None:
    with pytest.raises(ValueError, match="tuck_in"):
        RoleParams(tuck_in=1.5)
    with pytest.raises(ValueError, match="mark_radius"):
        RoleParams(mark_radius=-1.0)


def test_centre_backs_stay_at_the_halfway_line_as_rest_defence_when_we_attack_high() -> None:
    labels, before, after = _setup("4-3-3", Situation.ATTACK, (45.0, 10.0))
    cb = labels == "centre-back"
    assert (before[cb, 0] > RoleParams().back_line_limit + 5.0).all()
    np.testing.assert_allclose(after[cb, 0], RoleParams().back_line_limit)
    np.testing.assert_allclose(after[cb, 1], before[cb, 1])
