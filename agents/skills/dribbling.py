"""Dribbling: small kicks that keep the ball just ahead of a running player.

**Direction.** A fan of directions around the line to the opponents' goal centre (``fan``
directions over ``± spread_deg``) is scored. Along each, probe points at ``probes`` metres
ahead are reached by the dribbler after ``distance / speed`` cycles; an opponent threatens a
probe point when its reachable disc at that cycle (coast point, ``reach(k)``, plus the
kickable distance) comes near it. A direction's **clearance** is the smallest margin (m) over
probe points and opponents; its score is ``min(clearance, clearance_cap) / clearance_cap +
goal_weight * cos(angle to the goal)``. Directions whose farthest probe leaves the field
(less ``field_margin``) are excluded.

**Kicks and dashes, one a cycle.** A player executes one body command a cycle (rcssserver's
rule), so the dribbler alternates: it **dashes** (towards ``speed`` along the direction,
clipped to its acceleration) while the ball, rolling on, stays within its kickable area one
cycle ahead, in front of it and off its body; otherwise, when it can kick the ball, it
**kicks** it to the point ``lead`` ahead of where it will be after this cycle (in which it
only coasts) and ``dashes`` more cycles of running, and then runs after it. A ball out of
reach that dashing will not bring back is chased: the dash goes towards where the ball will
be. The ball never touches the body (which in rcssserver's contact mode would stop both).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from agents.skills.context import SkillContext
from agents.skills.kicking import kick_for_velocity
from agents.skills.model import MotionModel, SkillInputError, check_params, check_player, float_array
from agents.skills.player_kernels import FAN_PARAMS, FanOut, fan_kernel
from soccer_sim.kernels import make_record
from soccer_sim.team import TeamView


@dataclass(frozen=True)
class DribbleParams:
    """Tunable choices of the dribbling skill (metres, m/cycle, degrees)."""

    fan: int = 13
    """Number of directions tried."""
    spread_deg: float = 90.0
    """Directions span ± this angle around the line to the goal."""
    probes: tuple[float, ...] = (1.0, 2.5, 4.0)
    """Distances ahead (m) at which the clearance is measured."""
    speed_fraction: float = 0.7
    """Dribbling speed as a fraction of the player's top speed (slower keeps control)."""
    lead: float | None = None
    """Distance from the player's centre to the ball after each kick (m); None: halfway
    between touching the body and the edge of the kickable distance."""
    clearance_cap: float = 5.0
    """Clearance beyond this (m) counts no more."""
    goal_weight: float = 0.6
    """Weight of heading towards the goal against clearance."""
    field_margin: float = 1.0
    """Directions whose farthest probe is not this far inside the lines are excluded (m)."""
    dashes: int = 2
    """Cycles of running a kick plans for before the ball is again ``lead`` ahead (the kick
    cycle itself not counted): kick, dash, dash, kick... at dribbling speed."""
    reach_margin: float = 0.1
    """A dash keeps the ball only if the ball stays this much inside the kickable distance and
    this much off the body one cycle ahead (m)."""

    def __post_init__(self) -> None:
        check_params(self, positive=("clearance_cap",), non_negative=("spread_deg", "goal_weight", "field_margin",
                                                                       "reach_margin"),
                     counts=("fan", "dashes"), fractions=("speed_fraction",))
        probes = np.asarray(self.probes, dtype=float)
        if probes.ndim != 1 or len(probes) == 0 or not (np.isfinite(probes) & (probes > 0)).all():
            raise SkillInputError(f"DribbleParams.probes must be positive distances, got {self.probes!r}")
        if self.speed_fraction <= 0:
            raise SkillInputError("DribbleParams.speed_fraction must be positive")
        if self.lead is not None and not (math.isfinite(self.lead) and self.lead > 0):
            raise SkillInputError(f"DribbleParams.lead must be None or a positive distance, got {self.lead!r}")


@dataclass(frozen=True)
class DribblePlan:
    """One cycle of dribbling: put ``kick`` and ``dash`` into the player's command rows (one of
    them is zero: one body command a cycle)."""

    direction: np.ndarray
    """(2,) unit vector of the dribble."""
    kick: np.ndarray
    """(2,) kick request (zero on a cycle the dribbler runs)."""
    dash: np.ndarray
    """(2,) dash acceleration (zero on a cycle the dribbler kicks)."""
    clearance: float
    """Opponents' margin along the direction (m; large when nobody is near)."""
    score: float


def dribble_directions(ctx: SkillContext, view: TeamView, player: int,
                       params: DribbleParams = DribbleParams()) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(directions (fan, 2), clearance (fan,), score (fan,)) for ``player`` dribbling from
    where it stands; excluded directions score -inf."""
    model = ctx.model
    player = check_player(player, model.players_per_team)
    arrays = ctx.arrays(view)
    p = arrays.ours.pos[player]
    goal_x = model.half_length
    base = math.atan2(-p[1], goal_x - p[0])
    offsets, probes = ctx.table(("dribble fan", params.fan, params.spread_deg, params.probes),
                                lambda: _fan(params))
    effort = float(arrays.ours.effort[player])
    speed = max(params.speed_fraction * model.top_speed * effort, 1e-6)
    cycles = np.minimum(np.ceil(probes / speed).astype(np.int64), model.horizon)
    fan = len(offsets)
    dirs, clearance, score = np.empty((fan, 2)), np.empty(fan), np.empty(fan)
    constants = ctx.table(("dribble fan params", params), lambda: make_record(
        FAN_PARAMS, kickable=model.kickable_distance, cap=params.clearance_cap, goal_weight=params.goal_weight,
        x_max=model.half_length - params.field_margin, y_max=model.half_width - params.field_margin))
    fan_kernel(p, base, offsets, probes, cycles, arrays.theirs.pos, arrays.theirs.vel, model.tables, constants,
               FanOut(dirs, clearance, score))
    return dirs, clearance, score


def _fan(params: DribbleParams) -> tuple[np.ndarray, np.ndarray]:
    """(angle offsets (rad), probe distances) of ``params``."""
    offsets = np.radians(np.linspace(-params.spread_deg, params.spread_deg, params.fan)) if params.fan > 1 \
        else np.zeros(1)
    return offsets, np.asarray(params.probes, dtype=np.float64)


def dribble(ctx: SkillContext, view: TeamView, player: int, params: DribbleParams = DribbleParams(),
            direction: np.ndarray | None = None) -> DribblePlan:
    """One cycle of dribbling for ``player``: the best direction of the fan (or ``direction``,
    a (2,) vector, when given), and this cycle's dash or kick (module docstring)."""
    model = ctx.model
    player = check_player(player, model.players_per_team)
    dirs, clearance, score = dribble_directions(ctx, view, player, params)
    px, py = view.own_pos[player].tolist()
    if direction is not None:
        wx, wy = float_array("direction", direction, (2,)).tolist()
        best = int(np.argmax(dirs @ np.array([wx, wy])))
        size = max(math.hypot(wx, wy), 1e-12)
        ux, uy = wx / size, wy / size
    else:
        best = int(score.argmax())
        if score[best] == -np.inf:  # cornered against a line: head for the centre of the field
            size = max(math.hypot(px, py), 1e-9)
            best = int(np.argmax(dirs @ np.array([-px / size, -py / size])))
        ux, uy = dirs[best].tolist()
    effort = float(ctx.arrays(view).ours.effort[player])
    pace = params.speed_fraction * model.top_speed * effort
    limit = model.accel_max * effort
    position, velocity = np.array([px, py]), view.own_vel[player].astype(float)
    ball, ball_vel = view.ball.astype(float), view.ball_vel.astype(float)
    heading = np.array([ux, uy])
    dash = _run(velocity, heading * pace, limit)
    kick = np.zeros(2)
    if not _keeps_ball(model, position + _moved(model, velocity, dash), ball + ball_vel, heading, params):
        gap = ball - position
        if gap @ gap <= model.kickable_distance ** 2:
            kick = _kick_ahead(model, view, player, heading, pace, limit, params)
            dash = np.zeros(2)
        else:  # chase: run towards where the ball will be
            dash = _run(velocity, _toward(ball + ball_vel - position, pace), limit)
    return DribblePlan(direction=heading, kick=kick, dash=dash, clearance=float(clearance[best]),
                       score=float(score[best]))


def _run(velocity: np.ndarray, wanted: np.ndarray, limit: float) -> np.ndarray:
    """The dash acceleration towards the velocity ``wanted``, at most ``limit`` long."""
    accel = wanted - velocity
    size = math.hypot(*accel)
    return accel * (limit / size) if size > limit else accel


def _toward(offset: np.ndarray, pace: float) -> np.ndarray:
    """A velocity of ``pace`` along ``offset`` (zero for a zero offset)."""
    size = math.hypot(*offset)
    return offset * (pace / size) if size > 1e-9 else np.zeros(2)


def _moved(model: MotionModel, velocity: np.ndarray, accel: np.ndarray) -> np.ndarray:
    """How far a player moving at ``velocity`` moves this cycle with ``accel`` (speed clipped to
    ``player_speed_max``, as the simulator moves it)."""
    moved = velocity + accel
    speed = math.hypot(*moved)
    return moved * (model.speed_max / speed) if speed > model.speed_max else moved


def _keeps_ball(model: MotionModel, player_next: np.ndarray, ball_next: np.ndarray, heading: np.ndarray,
                params: DribbleParams) -> bool:
    """Whether the ball at ``ball_next`` is within the kickable area of a player at
    ``player_next`` (by ``reach_margin``), off its body and in front of it along ``heading``."""
    gap = ball_next - player_next
    distance = math.hypot(*gap)
    return (model.touch_distance + params.reach_margin < distance < model.kickable_distance - params.reach_margin
            and float(gap @ heading) > 0.0)


def _kick_ahead(model: MotionModel, view: TeamView, player: int, heading: np.ndarray, pace: float, limit: float,
                params: DribbleParams) -> np.ndarray:
    """The kick that puts the ball ``lead`` ahead of where the dribbler will be after this
    cycle (in which it kicks and coasts) and ``m`` cycles of running at ``pace``: the most
    cycles up to ``params.dashes`` for which the ball stays within reach and off the body on
    every cycle between (else the one whose ball strays least)."""
    position, velocity = view.own_pos[player].astype(float), view.own_vel[player].astype(float)
    ball = view.ball.astype(float)
    lead = params.lead if params.lead is not None else 0.5 * (model.touch_distance + model.kickable_distance)
    path = [position + velocity]  # the kick cycle: no dash, the player coasts
    moving = velocity * model.player_decay
    for _ in range(params.dashes):
        moved = _moved(model, moving, _run(moving, heading * pace, limit))
        path.append(path[-1] + moved)
        moving = moved * model.player_decay
    near, far = model.touch_distance + params.reach_margin, model.kickable_distance - params.reach_margin
    best, best_stray = None, np.inf
    for m in range(params.dashes, 0, -1):
        ball_vel = (path[m] + heading * lead - ball) / model.ball_travel[m + 1]
        stray = 0.0
        for k in range(1, m + 1):  # the cycles between the kick and the ball's arrival
            gap = math.hypot(*(ball + ball_vel * model.ball_travel[k] - path[k - 1]))
            stray = max(stray, gap - far, near - gap)
        if stray <= 0.0:
            best = ball_vel
            break
        if stray < best_stray:
            best, best_stray = ball_vel, stray
    kick, _ = kick_for_velocity(model, view.own_pos[player], view.ball, view.ball_vel, best,
                                player_vel=view.own_vel[player])
    return kick
