"""The one-call pass search (agents.skills.pass_search) chooses what the passing skill's steps,
taken one by one through the same kernels, choose: the same pass bit for bit on random views."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import MotionModel, SkillContext, best_pass, offside_positions
from agents.skills.ball_kernels import PassLanes, deciding_cycles, lane_arrivals, pass_scores, pass_targets
from agents.skills.interception import UNREACHABLE, intercept_checked
from agents.skills.interception_kernels import EVERYONE
from agents.skills.kicking import kick_for_velocity
from agents.skills.passing import PassParams, pass_search_inputs
from tests.agents.skills.skill_views import CONFIG, N, make_view

MODEL = MotionModel.even_sides(CONFIG)


def stepwise_pass(ctx: SkillContext, view, passer: int, params: PassParams, holder: bool):
    """The passing skill's steps one by one, as NumPy calls between the kernels: (receiver,
    target, receive point, kick, ball velocity, arrival, receive cycle, opponent cycle, score)
    or None."""
    model = ctx.model
    ok = ~offside_positions(model, view.own_pos, view.opp_pos, view.ball)
    ok[passer] = False
    if not params.allow_goalie and model.goalie_index >= 0:
        ok[model.goalie_index] = False
    receivers = np.flatnonzero(ok)
    if receivers.size == 0:
        return None
    ball = np.asarray(view.ball, np.float64)
    size = receivers.size * len(params.leads) * len(params.arrival_speeds)
    targets, wanted, owners = np.empty((size, 2)), np.empty((size, 2)), np.empty(size, dtype=np.int64)
    constants = pass_search_inputs(ctx, params).params
    count = pass_targets(view.own_pos, receivers, np.asarray(params.leads, float).reshape(-1, 2),
                         np.asarray(params.arrival_speeds, float), ball, constants, targets, owners, wanted)
    if count == 0:
        return None
    targets, owners, wanted = targets[:count], owners[:count], wanted[:count]
    kicks, velocities = kick_for_velocity(model, view.own_pos[passer], ball, view.ball_vel, wanted, holder,
                                          view.own_vel[passer])
    arrival, limit = np.empty(count, dtype=np.int64), np.empty(count, dtype=np.int64)
    usable = lane_arrivals(targets, wanted, velocities, ball, model.ball_decay, model.horizon, params.extra_cycles,
                           arrival, limit)
    if usable.size == 0:
        return None
    vel_u, own_u, lim_u, arrival_u = velocities[usable], owners[usable], limit[usable], arrival[usable]
    arrays = ctx.arrays(view)
    ours, our_points = intercept_checked(ctx, arrays.ball, vel_u, arrays.ours, -1.0, lim_u, 0, False, own_u)
    rows = np.arange(usable.size)
    receive, received_at = ours[rows, own_u], our_points[rows, own_u]
    opponents = arrays.theirs.with_radii(*ctx.opponent_radii(params.opponent_margin))
    theirs = intercept_checked(ctx, arrays.ball, vel_u, opponents, 1.0,
                               deciding_cycles(receive, arrival_u, lim_u, params.min_lead), 1, True,
                               EVERYONE)[0].min(axis=1, initial=UNREACHABLE)
    score, points = np.empty(usable.size), np.empty((usable.size, 2))
    lanes = PassLanes(targets[usable], own_u, arrival_u, receive, np.ascontiguousarray(received_at), theirs)
    best = pass_scores(lanes, view.own_pos, view.own_vel, arrays.ours.effort, view.opp_pos, ball, model.reach,
                       constants, score, points)
    if best < 0:
        return None
    j = int(usable[best])
    return (int(owners[j]), tuple(targets[j]), tuple(points[best]), tuple(kicks[j]), tuple(velocities[j]),
            int(arrival[j]), int(receive[best]), int(theirs[best]), float(score[best]))


@pytest.mark.parametrize("params", [PassParams(), PassParams(allow_goalie=True, min_lead=4, opponent_margin=0.5,
                                                                leads=((0.0, 0.0), (4.0, 2.0)))])
def test_the_one_call_search_chooses_what_the_steps_choose(params: PassParams) -> None:
    rng = np.random.default_rng(11)
    found = none = 0
    for _ in range(150):
        own, opp = rng.uniform((-50, -32), (50, 32), (N, 2)), rng.uniform((-50, -32), (50, 32), (N, 2))
        passer = int(rng.integers(1, N))
        ball = own[passer] + rng.uniform(-0.5, 0.5, 2)
        view = make_view(own=own, opp=opp, ball=ball, ball_vel=rng.uniform(-0.5, 0.5, 2),
                         own_vel=rng.uniform(-0.3, 0.3, (N, 2)), opp_vel=rng.uniform(-0.3, 0.3, (N, 2)),
                         effort=rng.uniform(0.7, 1.0, N))
        holder = bool(rng.random() < 0.2)
        expected = stepwise_pass(SkillContext(MODEL), view, passer, params, holder)
        plan = best_pass(SkillContext(MODEL), view, passer, params, holder)
        if expected is None:
            assert plan is None
            none += 1
            continue
        found += 1
        got = (plan.receiver, tuple(plan.target), tuple(plan.receive_point), tuple(plan.kick), tuple(plan.ball_vel),
               plan.arrival_cycle, plan.receive_cycle, plan.opponent_cycle, plan.score)
        assert got == expected  # bit for bit
    assert found > 30 and none > 5  # both outcomes are exercised
