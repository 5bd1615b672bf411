"""Clearances that give the ball away: to the opponents' goalkeeper, or out of play."""

from __future__ import annotations

import numpy as np

from agents.skills import ClearParams, MotionModel, SkillContext, best_clearance
from agents.skills.lanes import opponent_cycles
from tests.agents.skills.skill_views import CONFIG, HL, make_view

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
P = 9


def view_with_ball_at(bx: float, by: float):
    """Our player ``P`` on the ball at (bx, by) with two opponents just behind it, their
    goalkeeper in goal and our team-mates far back."""
    own = {i: (-45.0, -30.0 + 6.0 * i) for i in range(11)}
    own[P] = (bx - 0.5, by)
    opp = {0: (HL - 1.0, 0.0), 1: (bx - 2.0, by + 1.5), 2: (bx - 2.0, by - 1.5)}
    return make_view(own=own, opp=opp, ball=(bx, by))


def first_opponent(view, plan) -> tuple[int, int]:
    cycles, who = opponent_cycles(CTX, view, view.ball, plan.ball_vel[None])
    return int(cycles[0]), int(who[0])


def leaves_field_at(view, plan) -> int | None:
    """The cycle at which the clearance's unhindered ball leaves the field other than into the
    goal (None: it stays in)."""
    path = view.ball + MODEL.ball_travel[:, None] * plan.ball_vel
    out = ~MODEL.in_field(path) & ~((path[:, 0] > HL) & (np.abs(path[:, 1]) < MODEL.goal_half_width))
    return int(np.argmax(out)) if out.any() else None


def test_a_clearance_is_not_played_to_the_opponents_goalkeeper() -> None:
    view = make_view(own={**{i: (-45.0, -30.0 + 6.0 * i) for i in range(11)}, P: (10.0, 0.0)},
                     opp={0: (HL - 1.0, 0.0), 1: (8.5, 1.5), 2: (8.5, -1.5)}, ball=(10.5, 0.0))
    old = best_clearance(CTX, view, P, ClearParams(keeper_gets_it=False))
    assert first_opponent(view, old)[1] == MODEL.opponent_goalie_index  # the long roll to the keeper
    new = best_clearance(CTX, view, P)
    assert first_opponent(view, new)[1] != MODEL.opponent_goalie_index


def test_a_clearance_near_their_goal_line_is_not_rolled_out_for_a_goal_kick() -> None:
    view = view_with_ball_at(35.0, 10.0)
    old = best_clearance(CTX, view, P, ClearParams(out_gives_it_away=False))
    assert leaves_field_at(view, old) is not None and first_opponent(view, old)[0] > 100  # nobody stops it
    new = best_clearance(CTX, view, P)
    leaves = leaves_field_at(view, new)
    assert leaves is None or first_opponent(view, new)[0] < leaves
