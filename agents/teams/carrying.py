"""Carrying the ball into the box: near the opponents' goal the player on the ball dribbles on
rather than passing back or clearing (team frame: we attack +x).

Measured in built-in matches (on-ball decisions with the ball 17-35 m from the opponents'
goal centre): about half of the passes went back or square (reception point more than 3 m
further from the goal than the ball, or within 3 m of the ball's distance) and only a fifth
towards the goal, and a pressed player with no safe pass cleared the ball long, usually into
the goalkeeper's hands; decisions with the ball within 17 m were rare, so few shots came from
where shots score (helios-base, real server: median shot 11 m from the goal centre, 61 % of
those from under 11 m scored; ours 25 m). A real forward there carries the ball on towards the
goal and shoots from close.

:func:`carry_kick` turns such a pass or clearance into a dribble
(:func:`agents.skills.dribble` with the decision's own dribbling parameters): within
``carry_range`` of the goal centre, a pass whose reception point is not at least
``pass_gain`` metres closer to the goal when the best dribbling direction keeps at least the
decision's ``dribble_clearance``; within ``clear_range`` (further out), a clearance always.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from agents import skills
from agents.skills.model import check_params
from agents.teams.finishing import goal_distance
from soccer_sim.team import TeamView


@dataclass(frozen=True)
class CarryParams:
    """When the player on the ball near the opponents' goal dribbles on (metres)."""

    carry_range: float = 32.0
    """Within this distance of the opponents' goal centre (m) a pass back or a clearance
    becomes a dribble: the final third's width of play around the box, beyond which passing
    back to build up is what real teams do (0: never). In 48 built-in matches 38 m scored a
    little more (goals 3.98 against 3.83) but sent more balls out (corners 1.75 -> 1.48,
    kick-ins 15.7 -> 17.7)."""
    clear_range: float = 42.0
    """Within this distance of the opponents' goal centre (m) a clearance becomes a dribble
    (at least ``carry_range``): from there a long clearance mostly rolls to their goalkeeper.
    In 48 built-in matches (seeds 0..2) 42 m against 32 m: goalkeeper catches 8.8 -> 7.0,
    goal kicks 3.7 -> 2.8 (real server 5.4 and 2.8), goals unchanged (3.8), kick-ins 15.7 ->
    20.3 (dribbles lost over the touchline); the whole opponents' half (52.5 m): catches 5.2,
    kick-ins 21.2, shots 14.6 -> 12.6."""
    pass_gain: float = 3.0
    """A pass stands when its reception point is at least this much closer to the goal centre
    than the ball (m): a pass forward into the box beats carrying it there."""

    def __post_init__(self) -> None:
        check_params(self, non_negative=("carry_range", "clear_range", "pass_gain"))


CARRY = CarryParams()
"""The built-in team's carrying choice."""


def carry_kick(ctx: skills.SkillContext, view: TeamView, kicker: int, decision: skills.BallDecision,
               decision_params: skills.DecisionParams,
               params: CarryParams = CARRY) -> tuple[np.ndarray, np.ndarray] | None:
    """(kick, dash) of ``kicker`` (an outfield player who can kick the ball) carrying it on
    towards the opponents' goal, or None when ``decision`` stands (see the module docstring)."""
    if params.carry_range <= 0.0 or decision.action not in (skills.OnBallAction.PASS, skills.OnBallAction.CLEAR):
        return None
    gx = ctx.model.half_length
    dist = goal_distance(gx, view.ball)
    if dist > (params.carry_range if decision.action == skills.OnBallAction.PASS
               else max(params.carry_range, params.clear_range)):
        return None
    if decision.action == skills.OnBallAction.PASS:
        point = decision.plan.receive_point
        if goal_distance(gx, point) <= dist - params.pass_gain:
            return None
    plan = skills.dribble(ctx, view, kicker, decision_params.dribbling)
    if decision.action == skills.OnBallAction.PASS and plan.clearance < decision_params.dribble_clearance:
        return None
    return plan.kick, plan.dash
