"""The on-ball decision: shoot, pass, dribble or clear, for the player who can kick the ball.

The order and thresholds (:class:`DecisionParams`):

1. **Shoot** when the best shot's probability-like score clears ``ShotParams.threshold``
   (:mod:`agents.skills.shooting`; out of range means no shot).
2. **Cross** when the ball is wide in the final third and a cross into the box works
   (:mod:`agents.skills.crossing`): a wide player puts the ball where a team-mate takes it
   in front of goal rather than passing back or sideways.
3. **Pass** when the best safe pass (:mod:`agents.skills.passing`) scores at least
   ``pass_good``.
4. **Dribble** when no opponent can reach the ball within ``pressure_cycles`` and the best
   dribbling direction keeps ``dribble_clearance`` metres of clearance (never the
   goalkeeper).
5. **Pass** to whoever is safely available (any score).
6. **Clear** when under pressure, for the goalkeeper, or in our own part of the field (ball
   x below ``clear_line``; a fraction of the half length, so -1/3 is our third).
7. **Dribble** otherwise (the direction with most clearance, even if small).

Under pressure means an opponent's interception of the ball (rolled with its current
velocity) comes within ``pressure_cycles`` cycles.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum

import numpy as np

from agents.skills.clearing import ClearParams, ClearPlan, best_clearance
from agents.skills.context import SkillContext
from agents.skills.crossing import CrossParams, CrossPlan, best_cross, in_crossing_zone
from agents.skills.dribbling import DribbleParams, DribblePlan, dribble
from agents.skills.interception import intercept
from agents.skills.model import SkillInputError, check_params, check_player
from agents.skills.passing import PassParams, PassPlan, best_pass
from agents.skills.shooting import ShotParams, ShotPlan, best_shot
from soccer_sim.team import TeamView


class OnBallAction(str, Enum):
    """What the player on the ball does."""

    SHOOT = "shoot"
    CROSS = "cross"
    PASS = "pass"
    DRIBBLE = "dribble"
    CLEAR = "clear"


@dataclass(frozen=True)
class DecisionParams:
    """Thresholds of the on-ball decision (see the module docstring) and each skill's own."""

    pass_good: float = 1.2
    """A pass scoring at least this is preferred to dribbling."""
    pressure_cycles: int = 3
    """Under pressure when an opponent can control the ball within this many cycles."""
    dribble_clearance: float = 1.0
    """Dribble (rather than pass or clear) only with at least this clearance (m)."""
    clear_line: float = -1.0 / 3.0
    """Clear rather than dribble when the ball's x is below this fraction of the half length."""
    shot: ShotParams = field(default_factory=ShotParams)
    passing: PassParams = field(default_factory=PassParams)
    dribbling: DribbleParams = field(default_factory=DribbleParams)
    clearing: ClearParams = field(default_factory=ClearParams)
    crossing: CrossParams | None = field(default_factory=CrossParams)
    """Where and how crosses are tried (None: never cross)."""

    def __post_init__(self) -> None:
        check_params(self, non_negative=("dribble_clearance",), finite=("pass_good", "clear_line"),
                     whole=("pressure_cycles",))
        for name, kind in (("shot", ShotParams), ("passing", PassParams), ("dribbling", DribbleParams),
                           ("clearing", ClearParams), ("crossing", CrossParams)):
            if name == "crossing" and self.crossing is None:
                continue
            if not isinstance(getattr(self, name), kind):
                raise SkillInputError(f"DecisionParams.{name} must be a {kind.__name__}")


@dataclass(frozen=True)
class BallDecision:
    """The chosen action: ``kick`` goes into the player's ``TeamCommand.kick`` row; ``dash`` is
    the player's dash for a dribble (None otherwise: the team decides where it runs);
    ``plan`` is the skill's own result (ShotPlan, CrossPlan, PassPlan, DribblePlan or ClearPlan)."""

    action: OnBallAction
    kick: np.ndarray
    dash: np.ndarray | None
    plan: ShotPlan | CrossPlan | PassPlan | DribblePlan | ClearPlan
    pressure: int
    """Cycles until the fastest opponent controls the ball."""


def decide_on_ball(ctx: SkillContext, view: TeamView, player: int,
                   params: DecisionParams = DecisionParams(), pressure: int | None = None) -> BallDecision:
    """Choose what ``player`` (who can kick the ball) does with it this cycle.

    ``pressure``: the cycles until the fastest opponent controls the ball, when the caller
    already knows it (``ball_race(ctx, view).theirs.first_cycle`` of this very view); None:
    worked out here."""
    model = ctx.model
    player = check_player(player, model.players_per_team)
    holder = view.ball_holder == player
    goalie = player == model.goalie_index
    if pressure is None:
        arrays = ctx.arrays(view)
        pressure = intercept(ctx, arrays.ball, arrays.ball_vel, arrays.theirs, 1.0).first_cycle
    under_pressure = pressure <= params.pressure_cycles

    shot = best_shot(ctx, view, player, params.shot, holder, pressure)
    if shot is not None and shot.take:
        return BallDecision(OnBallAction.SHOOT, shot.kick, None, shot, pressure)
    if params.crossing is not None and not goalie and in_crossing_zone(model, view.ball, params.crossing):
        cross = best_cross(ctx, view, player, params.crossing, holder)
        if cross is not None:
            return BallDecision(OnBallAction.CROSS, cross.kick, None, cross, pressure)
    pass_plan = best_pass(ctx, view, player, params.passing, holder)
    if pass_plan is not None and pass_plan.score >= params.pass_good:
        return BallDecision(OnBallAction.PASS, pass_plan.kick, None, pass_plan, pressure)
    # A dribble is only ever chosen free of pressure and by an outfield player: not worked
    # out otherwise (it is the dearest plan after the pass).
    dribble_plan = None if under_pressure or goalie else dribble(ctx, view, player, params.dribbling)
    if dribble_plan is not None and dribble_plan.clearance >= params.dribble_clearance:
        return BallDecision(OnBallAction.DRIBBLE, dribble_plan.kick, dribble_plan.dash, dribble_plan, pressure)
    if pass_plan is not None:
        return BallDecision(OnBallAction.PASS, pass_plan.kick, None, pass_plan, pressure)
    if dribble_plan is None or float(view.ball[0]) < params.clear_line * model.half_length:
        clear = best_clearance(ctx, view, player, params.clearing, holder)
        return BallDecision(OnBallAction.CLEAR, clear.kick, None, clear, pressure)
    return BallDecision(OnBallAction.DRIBBLE, dribble_plan.kick, dribble_plan.dash, dribble_plan, pressure)
