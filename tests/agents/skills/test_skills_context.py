"""The skills' per-match context: both sides taken from the team's SideInfo, tables made once,
the view's arrays checked once and followed in place."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import MotionModel, Players, SkillContext, SkillInputError, ball_race
from soccer_sim.team import SideInfo, TeamView
from tests.agents.skills.skill_views import CONFIG, make_view

CATCH = max(CONFIG.rules.catch_length, CONFIG.physics.kickable_distance)
KICKABLE = CONFIG.physics.kickable_distance


def uneven_view(own: int, opp: int, dtype=np.float64) -> TeamView:
    rng = np.random.default_rng(3)
    return TeamView(own_pos=rng.uniform(-30, 30, (own, 2)).astype(dtype), own_vel=np.zeros((own, 2), dtype),
                    opp_pos=rng.uniform(-30, 30, (opp, 2)).astype(dtype), opp_vel=np.zeros((opp, 2), dtype),
                    ball=np.array([1.0, 2.0], dtype), ball_vel=np.array([0.5, 0.0], dtype),
                    stamina=np.full(own, CONFIG.stamina.maximum), effort=np.full(own, 0.8))


def test_the_context_takes_both_sides_from_the_side_info() -> None:
    ctx = SkillContext.for_match(CONFIG, SideInfo(0, "a", "b", 5, 2, opponents=3, opponent_goalie_index=-1))
    model = ctx.model
    assert (model.players_per_team, model.goalie_index, model.opponents, model.opponent_goalie_index) == (5, 2, 3, -1)
    radius, catch = ctx.team_radii()
    assert radius.tolist() == [KICKABLE] * 5 and catch[2] == CATCH and np.delete(catch, 2).tolist() == [KICKABLE] * 4
    their_radius, their_catch = ctx.opponent_radii(0.2)
    assert their_radius.tolist() == their_catch.tolist() == [KICKABLE + 0.2] * 3  # no goalkeeper of theirs
    assert ctx.opponent_radii(0.2)[0] is their_radius  # made once per margin
    race = ball_race(ctx, uneven_view(5, 3))
    assert race.ours.cycles.shape == (5,) and race.theirs.cycles.shape == (3,)


def test_even_sides_share_the_radii_of_both_teams() -> None:
    ctx = SkillContext(MotionModel.even_sides(CONFIG))
    assert ctx.opponent_radii() is ctx.team_radii()


def test_the_view_is_checked_once_and_followed_in_place() -> None:
    ctx = SkillContext(MotionModel.even_sides(CONFIG))
    view = make_view(own={5: (3.0, 1.0)}, ball=(0.0, 0.0), effort=np.full(11, 0.7))
    arrays = ctx.arrays(view)
    assert arrays.ours.pos is view.own_pos and arrays.ours.effort is view.effort
    assert arrays.ball.shape == (1, 2) and np.shares_memory(arrays.ball, view.ball)
    assert arrays.theirs.effort.tolist() == [1.0] * 11  # opponents are taken fresh
    view.own_pos[5] = (7.0, 7.0)
    assert ctx.arrays(view) is arrays and arrays.ours.pos[5].tolist() == [7.0, 7.0]
    view.own_pos = view.own_pos.copy()  # new array objects: checked again
    assert ctx.arrays(view) is not arrays


def test_arrays_that_need_converting_are_checked_every_time() -> None:
    ctx = SkillContext.for_match(CONFIG, SideInfo(0, "a", "b", 4, 0, opponents=4, opponent_goalie_index=0))
    view = uneven_view(4, 4, np.float32)
    first = ctx.arrays(view)
    assert first.ours.pos.dtype == np.float64 and first.ours.pos is not view.own_pos
    view.own_pos[0] = (9.0, 9.0)
    assert ctx.arrays(view).ours.pos[0].tolist() == [9.0, 9.0]  # never a stale copy


def test_tables_are_made_once_per_key() -> None:
    ctx = SkillContext(MotionModel.even_sides(CONFIG))
    made = []
    first = ctx.table(("aims", 3), lambda: made.append(1) or np.arange(3))
    assert ctx.table(("aims", 3), lambda: made.append(1) or np.arange(3)) is first and made == [1]
    ctx.table(("aims", 4), lambda: made.append(1) or np.arange(4))
    assert made == [1, 1]


def test_players_are_checked_when_made() -> None:
    players = Players(MotionModel.even_sides(CONFIG), [[0.0, 1.0]], [[0.0, 0.0]])
    assert players.count == 1 and players.effort.tolist() == [1.0] and players.radius.tolist() == [KICKABLE]
    assert players.catch_radius is players.radius
    wider = players.with_radii(np.array([2.0]), np.array([3.0]))
    assert wider.pos is players.pos and wider.catch_radius.tolist() == [3.0]
    with pytest.raises(SkillInputError, match="catch_radius"):
        players.with_radii(np.array([2.0]), np.ones(2))
