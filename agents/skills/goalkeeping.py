"""Goalkeeping: where to stand, when to ask for a catch, and what to do with a held ball.

**Guard position.** The goalkeeper stands on the segment from our goal centre to the ball,
``depth`` metres from the goal centre. The depth grows as the ball comes closer (narrowing
the angle a shooter sees): ``depth_far`` when the ball is ``far`` or more from the goal
centre, rising linearly to the goal area's depth when it is ``near`` or closer. The point is
then pulled back along the same segment until it lies inside the goal area, and never beyond
``ball_gap`` short of the ball, so it always stays on the ball-goal line (a ball behind the
goal line, out of play, puts it on the goal line on the ball's side).

**Catch.** Ask for a catch only when the referee would grant it (``RuleConfig``): play on,
nobody holding, goalkeeper and ball both in our penalty area, centres at most
``catch_length`` apart (less a small margin), and the ball not last kicked by a team-mate
(the back-pass rule; the view does not carry the last kicker, so the team tracks it).

**Coming out.** The goalkeeper leaves its guard point for the ball only when it wins the race
to it: it controls the ball (catch radius in our penalty area) at least ``race_margin`` cycles
before the first opponent, at a point inside our penalty area (:func:`comes_out`). Otherwise it
holds its line on the ball-goal segment: a goalkeeper running out to a ball an attacker gets to
first leaves an open goal behind it.

**Distribution.** Holding the ball, the goalkeeper passes to an open team-mate when a pass
scores well enough, else clears towards the wings (:mod:`agents.skills.clearing`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from agents.skills.clearing import ClearParams, ClearPlan, best_clearance
from agents.skills.context import SkillContext
from agents.skills.interception import UNREACHABLE, BallRace
from agents.skills.model import MotionModel, SkillInputError, check_params, check_player, float_array
from agents.skills.passing import PassParams, PassPlan, best_pass
from agents.skills.player_kernels import guard_kernel
from soccer_sim.state import NO_PLAYER, PlayMode
from soccer_sim.team import TeamView


@dataclass(frozen=True)
class GoalieParams:
    """Tunable choices of the goalkeeper (metres)."""

    depth_far: float = 1.0
    """Distance from the goal centre when the ball is far."""
    near: float = 12.0
    """Ball distance from the goal centre at which the goalkeeper is furthest out."""
    far: float = 40.0
    """Ball distance from the goal centre beyond which the goalkeeper is at ``depth_far``."""
    ball_gap: float = 1.0
    """The guard point stays at least this far short of the ball (m)."""
    catch_margin: float = 0.05
    """Ask for a catch only within ``catch_length`` less this (m)."""
    race_margin: int = 1
    """The goalkeeper comes out for the ball only when it gets there at least this many cycles
    before the first opponent (1: strictly first, as :attr:`BallRace.we_win`)."""
    pass_score: float = 1.0
    """A held ball is passed when the best pass scores at least this, else cleared."""
    passing: PassParams = field(default_factory=lambda: PassParams(min_lead=3, min_distance=8.0))
    clearing: ClearParams = field(default_factory=lambda: ClearParams(weight_wing=0.6, weight_forward=0.3))

    def __post_init__(self) -> None:
        check_params(self, positive=("near", "far"), non_negative=("depth_far", "ball_gap", "catch_margin",
                                                                   "pass_score"), whole=("race_margin",))
        if self.near >= self.far:
            raise SkillInputError(f"GoalieParams.near ({self.near}) must be smaller than far ({self.far})")


def guard_position(model: MotionModel, ball: np.ndarray,
                   params: GoalieParams = GoalieParams()) -> tuple[float, float]:
    """(x, y) the goalkeeper's guard point for a ball at ``ball`` ((2,), team frame)."""
    if not (type(ball) is np.ndarray and ball.shape == (2,) and ball.dtype.kind == "f"):
        ball = float_array("ball", ball, (2,))
    bx, by = float(ball[0]), float(ball[1])
    gx = -model.half_length
    dx = bx - gx
    # Python's hypot (correctly rounded) here, the rest compiled: the same point to the bit.
    return guard_kernel(math.hypot(dx, by), dx, by, gx, params.near, params.far, params.depth_far,
                        params.ball_gap, model.goal_area_length, model.goal_area_half_width)


def comes_out(model: MotionModel, race: BallRace, goalie: int | None = None,
              params: GoalieParams = GoalieParams()) -> bool:
    """Whether our goalkeeper (``goalie``, None: ours) goes for the ball of ``race`` (this
    cycle's :func:`agents.skills.ball_race`): it reaches it ``race_margin`` cycles before every
    opponent, inside our penalty area (see the module docstring)."""
    goalie = model.goalie_index if goalie is None else check_player(goalie, model.players_per_team, "goalie")
    if goalie < 0:
        return False
    mine = int(race.ours.cycles[goalie])
    if mine >= UNREACHABLE or int(race.theirs.first_cycle) - mine < params.race_margin:
        return False
    return bool(model.in_penalty_area(race.ours.points[goalie]))


def should_catch(ctx: SkillContext, view: TeamView, goalie: int | None = None, teammate_kicked_last: bool = False,
                 params: GoalieParams = GoalieParams()) -> bool:
    """Whether the goalkeeper (``goalie``, None: ours) should ask for a catch this cycle (see
    the module docstring)."""
    model = ctx.model
    goalie = model.goalie_index if goalie is None else check_player(goalie, model.players_per_team, "goalie")
    if view.play_mode != PlayMode.PLAY_ON or view.ball_holder != NO_PLAYER or teammate_kicked_last:
        return False
    keeper = np.asarray(view.own_pos[goalie], float)
    ball = np.asarray(view.ball, float)
    if not (model.in_penalty_area(keeper) and model.in_penalty_area(ball)):
        return False
    return float(np.hypot(*(ball - keeper))) <= model.catch_length - params.catch_margin


@dataclass(frozen=True)
class Distribution:
    """What a holding goalkeeper does: ``kind`` is ``"pass"`` or ``"clear"``; ``plan`` the
    :class:`PassPlan` or :class:`ClearPlan`."""

    kind: str
    kick: np.ndarray
    plan: PassPlan | ClearPlan


def distribute(ctx: SkillContext, view: TeamView, goalie: int | None = None,
               params: GoalieParams = GoalieParams()) -> Distribution:
    """The kick of a goalkeeper that has the ball (holding it, or merely able to kick it): a
    pass to an open team-mate when one scores at least ``pass_score``, else a clearance
    towards the wings."""
    model = ctx.model
    goalie = model.goalie_index if goalie is None else check_player(goalie, model.players_per_team, "goalie")
    holding = view.ball_holder == goalie
    plan = best_pass(ctx, view, goalie, params.passing, holder=holding)
    if plan is not None and plan.score >= params.pass_score:
        return Distribution("pass", plan.kick, plan)
    clear = best_clearance(ctx, view, goalie, params.clearing, holder=holding)
    return Distribution("clear", clear.kick, clear)
