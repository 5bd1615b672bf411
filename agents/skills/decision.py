"""The on-ball decision, whole: what the player who can kick the ball does with it (team
frame: we attack +x). :func:`decide_on_ball` is the one place where a player decides to shoot,
cross, pass, dribble, clear or put the ball out of danger; the other skills only make the
plans it chooses between.

**The first choice**, in this order (:class:`DecisionParams`):

1. **Shoot** when the best shot's probability-like score clears ``ShotParams.threshold``
   (:mod:`agents.skills.shooting`; out of range means no shot).
2. **Cross** when the ball is wide in the final third and a cross into the box works
   (:mod:`agents.skills.crossing`): a wide player puts the ball where a team-mate takes it
   in front of goal rather than passing back or sideways.
3. **Pass** when the best safe pass (:mod:`agents.skills.passing`) scores at least
   ``pass_good``.
4. **Dribble** when the best dribbling direction keeps ``dribble_clearance`` metres of
   clearance (never the goalkeeper), pressed or not: a way past the man.
5. **Pass** to whoever is safely available (any score) when under pressure, in our own part
   of the field (ball x below ``clear_line``; a fraction of the half length, so -1/3 is our
   third), or for the goalkeeper.
6. **Clear** in our own part of the field or for the goalkeeper.
7. **Dribble** otherwise (the direction with most clearance, even if small): a player free of
   pressure keeps the ball rather than passing it on for want of space (step 3 takes the pass
   that is clearly better).

Under pressure means an opponent's interception of the ball (rolled with its current
velocity) comes within ``pressure_cycles`` cycles. Steps 4, 5 and 7 make the ball carried
rather than passed when no pass is clearly better: in 48 built-in matches (``soccer-sim bench
soccer --compare``) passes fell from 550 to 381 a match (helios-base in the real server: 144),
tackles rose from 30 to 46 (39) and shots from 10.8 to 14.3 (16.6), against the earlier order
(a free player's dribble only with clearance, else any safe pass; no dribble under pressure)
with ``pass_good`` 0.6 lower. Raising ``pass_good`` from 1.8 to 2.2 and 2.6 (the reference
opponents' by as much) took passes on to 341 and 333, goals from 3.73 to 3.85 and 4.17 (6.75),
kick-ins from 13.4 to 12.4 and 11.6 (7.4), goalkeeper catches from 7.3 to 7.5 and 7.9 (5.4).

**In play on** (``in_play=True``: the built-in team's player on the ball, not a set-play
taker) three refinements follow the first choice, the first that applies:

a. **Finish** (:class:`FinishParams`): a dribble or clearance within ``shot_range`` of the
   opponents' goal, with an opponent on the ball or about to win it, becomes a full-power
   shot (:func:`finishing_shot`).
b. **Carry** (:class:`CarryParams`): near the opponents' goal a pass back or square becomes a
   dribble on towards the goal, unless an opponent is on the ball (:func:`carry_kick`).
c. **Keep safe** (:class:`SafetyParams`): a dribble or clearance with an opponent on the ball,
   or pressed deep in our half, goes behind, wide of our post, near our goal (``BLOCK``), and
   towards the nearer touchline elsewhere (``WING``; :func:`safe_kick`).
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
from agents.skills.kicking import kick_for_velocity
from agents.skills.model import MotionModel, SkillInputError, check_params, check_player
from agents.skills.passing import PassParams, PassPlan, best_pass
from agents.skills.saving import SaveParams, parry_kick
from agents.skills.shooting import ShotParams, ShotPlan, best_shot
from soccer_sim.team import TeamView


class OnBallAction(str, Enum):
    """What the player on the ball does."""

    SHOOT = "shoot"
    CROSS = "cross"
    PASS = "pass"
    DRIBBLE = "dribble"
    CLEAR = "clear"
    BLOCK = "block"
    """Put the ball behind, wide of our post, near our goal (a corner rather than a chance)."""
    WING = "wing"
    """Kick the ball hard towards the nearer touchline, a little forwards."""


@dataclass(frozen=True)
class FinishParams:
    """When a pressed player near the opponents' goal shoots (metres, cycles).

    Near the goal the first choice dribbles or clears when no shot clears its threshold. With
    a defender on the ball as well, both kicks add up and the defender's (wide of its post and
    behind: :mod:`agents.skills.saving`) then decides where the ball goes; a dribble is lost and
    a clearance meets the defender's mirror image. A real forward closed down at the edge of
    the box shoots at once: the ball goes in, the goalkeeper must save, or a block sends it
    behind for a corner."""

    shot_range: float = 25.0
    """Within this distance of the opponents' goal centre (m) a pressed or contested ball is
    shot: about the penalty area's depth plus a few metres, where real forwards still shoot and
    about as far as a full-power shot keeps enough pace to beat a goalkeeper's reach (0: never)."""
    pressure_cycles: int = 3
    """An opponent controlling the ball within this many cycles counts as pressing (the
    decision's own pressure horizon, shorter than the open-lane shot's): the dribble would be
    lost before it gets closer."""

    def __post_init__(self) -> None:
        check_params(self, non_negative=("shot_range",), whole=("pressure_cycles",))


@dataclass(frozen=True)
class CarryParams:
    """When the player on the ball near the opponents' goal dribbles on (metres).

    Measured in built-in matches (on-ball decisions with the ball 17-35 m from the opponents'
    goal centre): about half of the passes went back or square (reception point more than 3 m
    further from the goal than the ball, or within 3 m of the ball's distance) and only a fifth
    towards the goal, and a pressed player with no safe pass cleared the ball long, usually
    into the goalkeeper's hands; decisions with the ball within 17 m were rare, so few shots
    came from where shots score (helios-base, real server: median shot 11 m from the goal
    centre, 61 % of those from under 11 m scored; ours 25 m). A real forward there carries the
    ball on towards the goal and shoots from close."""

    carry_range: float = 32.0
    """Within this distance of the opponents' goal centre (m) a pass back or square becomes a
    dribble: the final third's width of play around the box, beyond which passing
    back to build up is what real teams do (0: never). In 48 built-in matches 38 m scored a
    little more (goals 3.98 against 3.83) but sent more balls out (corners 1.75 -> 1.48,
    kick-ins 15.7 -> 17.7)."""
    pass_gain: float = 3.0
    """A pass stands when its reception point is at least this much closer to the goal centre
    than the ball (m): a pass forward into the box beats carrying it there."""

    def __post_init__(self) -> None:
        check_params(self, non_negative=("carry_range", "pass_gain"))


@dataclass(frozen=True)
class SafetyParams:
    """Where a contested or pressed ball is put out of danger instead of dribbled or cleared."""

    block: SaveParams = field(default_factory=lambda: SaveParams(behind_depth=20.0))
    """The block: within ``block.behind_depth`` (20 m: the penalty area and a few metres
    beyond) of our goal line, wide of the post and over our goal line (a corner rather than a
    chance). With the area's 16.5 m alone, 1.5 corners a match between built-in teams; with
    20 m, 1.75. Also an outfield player's block of a shot at our goal."""
    deep_pressure: int = 4
    """Cycles until an opponent controls the ball within which a player of ours within the
    block's depth counts as pressed (and so puts the ball behind or wide instead of dribbling
    or clearing across our goal): a defender closed down near its goal line plays safe, as
    real ones do."""

    wing_margin: float = 3.0
    """The wing kick is as hard as keeps the ball at least this far inside the touchline and the
    opponents' goal line when it stops, even with an opponent's kick of the same strength
    towards the same touchline in the same cycle (each takes half the room; m; the full kick
    when that allows it): a ball knocked away from a contest stays in play rather than going
    out for their throw."""
    wing_min_speed: float = 0.5
    """... but never slower than this (m/cycle): near the touchline the ball must still get
    away from the opponent."""

    def __post_init__(self) -> None:
        check_params(self, whole=("deep_pressure",), non_negative=("wing_margin", "wing_min_speed"))
        if not isinstance(self.block, SaveParams):
            raise SkillInputError("SafetyParams.block must be a SaveParams")


@dataclass(frozen=True)
class DecisionParams:
    """Thresholds of the on-ball decision (see the module docstring) and each skill's own."""

    pass_good: float = 2.6
    """A pass scoring at least this is preferred to dribbling: a pass clearly better than
    carrying the ball (well forward, into space, with a lead; a square pass into space scores
    about 1.2-1.5, and three quarters of the passes free players make at a bar of 1.2 score
    under 2.1)."""
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
    finishing: FinishParams = field(default_factory=FinishParams)
    """In play on: when a pressed player near the opponents' goal shoots (refinement a)."""
    carrying: CarryParams = field(default_factory=CarryParams)
    """In play on: when the player on the ball near the opponents' goal dribbles on (refinement b)."""
    safety: SafetyParams = field(default_factory=SafetyParams)
    """In play on: where a contested or pressed ball is put out of danger (refinement c)."""

    def __post_init__(self) -> None:
        check_params(self, non_negative=("dribble_clearance",), finite=("pass_good", "clear_line"),
                     whole=("pressure_cycles",))
        for name, kind in (("shot", ShotParams), ("passing", PassParams), ("dribbling", DribbleParams),
                           ("clearing", ClearParams), ("crossing", CrossParams), ("finishing", FinishParams),
                           ("carrying", CarryParams), ("safety", SafetyParams)):
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
    plan: ShotPlan | CrossPlan | PassPlan | DribblePlan | ClearPlan | None
    """None for ``BLOCK`` and ``WING`` (a kick in a fixed direction, no plan)."""
    pressure: int
    """Cycles until the fastest opponent controls the ball."""


def decide_on_ball(ctx: SkillContext, view: TeamView, player: int,
                   params: DecisionParams = DecisionParams(), pressure: int | None = None, *,
                   in_play: bool = False, contested: bool = False) -> BallDecision:
    """What ``player`` (who can kick the ball) does with it this cycle: the first choice and,
    ``in_play``, its refinements (module docstring).

    ``pressure``: the cycles until the fastest opponent controls the ball, when the caller
    already knows it (``ball_race(ctx, view).theirs.first_cycle`` of this very view); None:
    worked out here. ``contested``: an opponent can kick the ball this cycle too (in play on)."""
    model = ctx.model
    player = check_player(player, model.players_per_team)
    if pressure is None:
        arrays = ctx.arrays(view)
        pressure = intercept(ctx, arrays.ball, arrays.ball_vel, arrays.theirs, 1.0).first_cycle
    choice = _first_choice(ctx, view, player, params, pressure)
    if not in_play:
        return choice
    return (finishing_shot(ctx, view, player, choice, contested, params)
            or (None if contested else carry_kick(ctx, view, player, choice, params))
            or safe_kick(ctx, view, player, choice, contested, params.safety)
            or choice)


def _first_choice(ctx: SkillContext, view: TeamView, player: int, params: DecisionParams,
                  pressure: int) -> BallDecision:
    """Steps 1-7 of the module docstring."""
    model = ctx.model
    holder = view.ball_holder == player
    goalie = player == model.goalie_index
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
    # A dribble is only ever chosen by an outfield player: not worked out for the goalkeeper
    # (it is the dearest plan after the pass).
    dribble_plan = None if goalie else dribble(ctx, view, player, params.dribbling)
    if dribble_plan is not None and dribble_plan.clearance >= params.dribble_clearance:
        return BallDecision(OnBallAction.DRIBBLE, dribble_plan.kick, dribble_plan.dash, dribble_plan, pressure)
    deep = float(view.ball[0]) < params.clear_line * model.half_length
    if pass_plan is not None and (dribble_plan is None or deep or under_pressure):
        return BallDecision(OnBallAction.PASS, pass_plan.kick, None, pass_plan, pressure)
    if dribble_plan is None or deep:
        clear = best_clearance(ctx, view, player, params.clearing, holder)
        return BallDecision(OnBallAction.CLEAR, clear.kick, None, clear, pressure)
    return BallDecision(OnBallAction.DRIBBLE, dribble_plan.kick, dribble_plan.dash, dribble_plan, pressure)


def goal_distance(half_length: float, point: np.ndarray) -> float:
    """Distance (m) from ``point`` (team frame) to the opponents' goal centre (half_length, 0)."""
    return float(np.hypot(half_length - float(point[0]), float(point[1])))


def finishing_shot(ctx: SkillContext, view: TeamView, player: int, choice: BallDecision, contested: bool,
                   params: DecisionParams = DecisionParams()) -> BallDecision | None:
    """Refinement a: ``player`` shoots at full power (the best aim of :func:`best_shot`, whatever
    its score) because it is pressed near the opponents' goal, or None when ``choice`` stands:
    the choice is to dribble or clear (a shot or a pass stands), and the ball is within
    ``finishing.shot_range`` of the goal centre with an opponent on it (``contested``) or
    controlling it within ``finishing.pressure_cycles`` (``choice.pressure``)."""
    finish = params.finishing
    if finish.shot_range <= 0.0 or choice.action not in (OnBallAction.DRIBBLE, OnBallAction.CLEAR):
        return None
    if not contested and choice.pressure > finish.pressure_cycles:
        return None
    if goal_distance(ctx.model.half_length, view.ball) > finish.shot_range:
        return None
    plan = best_shot(ctx, view, player, params.shot, pressure=int(choice.pressure))
    return None if plan is None else BallDecision(OnBallAction.SHOOT, plan.kick, None, plan, choice.pressure)


def carry_kick(ctx: SkillContext, view: TeamView, player: int, choice: BallDecision,
               params: DecisionParams = DecisionParams()) -> BallDecision | None:
    """Refinement b: ``player`` (outfield) carries the ball on towards the opponents' goal, or
    None when ``choice`` stands: within ``carrying.carry_range`` of the goal centre a pass whose
    reception point is not at least ``carrying.pass_gain`` metres closer to the goal, when the
    best dribbling direction keeps at least ``dribble_clearance``. (A clearance needs no such
    refinement: outside our own part of the field the first choice never clears.)"""
    carry = params.carrying
    if carry.carry_range <= 0.0 or choice.action != OnBallAction.PASS:
        return None
    gx = ctx.model.half_length
    dist = goal_distance(gx, view.ball)
    if dist > carry.carry_range:
        return None
    if goal_distance(gx, choice.plan.receive_point) <= dist - carry.pass_gain:
        return None
    plan = dribble(ctx, view, player, params.dribbling)
    if plan.clearance < params.dribble_clearance:
        return None
    return BallDecision(OnBallAction.DRIBBLE, plan.kick, plan.dash, plan, choice.pressure)


def safe_kick(ctx: SkillContext, view: TeamView, player: int, choice: BallDecision, contested: bool,
              params: SafetyParams = SafetyParams()) -> BallDecision | None:
    """Refinement c: a dribble or clearance that an opponent contests (against its mirror
    image the two kicks cancel), or that is pressed within ``params.deep_pressure`` cycles
    within the block's depth of our goal line, goes behind wide of our post there (``BLOCK``)
    and towards the nearer touchline elsewhere (``WING``; both teams doing so add up); None
    when ``choice`` stands."""
    model = ctx.model
    if choice.action not in (OnBallAction.DRIBBLE, OnBallAction.CLEAR):
        return None
    deep = float(view.ball[0]) < params.block.behind_depth - model.half_length
    pressed = choice.pressure <= params.deep_pressure and deep
    if not (contested or pressed):
        return None
    if deep:
        return BallDecision(OnBallAction.BLOCK, parry_kick(ctx, view, player, params.block), None, None,
                            choice.pressure)
    return BallDecision(OnBallAction.WING, wing_kick(model, view, player, params), None, None, choice.pressure)


def wing_kick(model: MotionModel, view: TeamView, player: int, params: SafetyParams = SafetyParams()) -> np.ndarray:
    """The kick sending the ball towards the nearer touchline, a little forwards, as hard as
    keeps it ``params.wing_margin`` inside the touchline and the opponents' goal line when it
    stops, with half the room (an opponent's kick in the same cycle may add as much; the ball
    travels ``speed / (1 - ball_decay)`` m), at least ``params.wing_min_speed``."""
    bx, by = float(view.ball[0]), float(view.ball[1])
    side = 1.0 if by >= 0.0 else -1.0
    direction = np.array([0.3, side]) / np.hypot(0.3, 1.0)
    room_y = (model.half_width - params.wing_margin - abs(by)) / abs(direction[1])
    room_x = (model.half_length - params.wing_margin - bx) / direction[0]
    speed = max(min(model.kick_speed_max, 0.5 * min(room_x, room_y) * (1.0 - model.ball_decay)),
                params.wing_min_speed)
    kick, _ = kick_for_velocity(model, view.own_pos[player], view.ball, view.ball_vel,
                                direction * min(speed, model.kick_speed_max), player_vel=view.own_vel[player])
    return kick
