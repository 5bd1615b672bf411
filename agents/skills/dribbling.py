"""Dribbling: small kicks that keep the ball just ahead of a running player.

**Direction.** A fan of directions around the line to the opponents' goal centre (``fan``
directions over ``± spread_deg``) is scored. Along each, probe points at ``probes`` metres
ahead are reached by the dribbler after ``distance / speed`` cycles; an opponent threatens a
probe point when its reachable disc at that cycle (coast point, ``reach(k)``, plus the
kickable distance) comes near it. A direction's **clearance** is the smallest margin (m) over
probe points and opponents; its score is ``min(clearance, clearance_cap) / clearance_cap +
goal_weight * cos(angle to the goal)``. Directions whose farthest probe leaves the field
(less ``field_margin``) are excluded.

**Kick and dash.** The dribbler dashes so that this cycle's displacement is ``speed`` along
the direction (clipped to its acceleration); the kick sends the ball to the point ``lead``
ahead of where the dribbler will be after this cycle, so after the move the ball is again
between the body and the edge of the kickable area (never touching the body, which in
rcssserver contact mode would stop both). Repeating it every cycle keeps the ball in reach.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from agents.skills.context import SkillContext
from agents.skills.kicking import kick_for_velocity
from agents.skills.model import SkillInputError, check_params, check_player, float_array
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

    def __post_init__(self) -> None:
        check_params(self, positive=("clearance_cap",), non_negative=("spread_deg", "goal_weight", "field_margin"),
                     counts=("fan",), fractions=("speed_fraction",))
        probes = np.asarray(self.probes, dtype=float)
        if probes.ndim != 1 or len(probes) == 0 or not (np.isfinite(probes) & (probes > 0)).all():
            raise SkillInputError(f"DribbleParams.probes must be positive distances, got {self.probes!r}")
        if self.speed_fraction <= 0:
            raise SkillInputError("DribbleParams.speed_fraction must be positive")
        if self.lead is not None and not (math.isfinite(self.lead) and self.lead > 0):
            raise SkillInputError(f"DribbleParams.lead must be None or a positive distance, got {self.lead!r}")


@dataclass(frozen=True)
class DribblePlan:
    """One cycle of dribbling: put ``kick`` and ``dash`` into the player's command rows."""

    direction: np.ndarray
    """(2,) unit vector of the dribble."""
    kick: np.ndarray
    """(2,) kick request (zero when the ball is not kickable)."""
    dash: np.ndarray
    """(2,) dash acceleration."""
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
    a (2,) vector, when given), the dash and the kick that keeps the ball ``lead`` ahead."""
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
    vx, vy = view.own_vel[player].tolist()
    pace = params.speed_fraction * model.top_speed * effort
    ax, ay = ux * pace - vx, uy * pace - vy
    size = math.hypot(ax, ay)
    limit = model.accel_max * effort
    if size > limit:
        ax, ay = ax * limit / size, ay * limit / size
    bx, by = view.ball.tolist()
    kick = np.zeros(2)
    if (bx - px) ** 2 + (by - py) ** 2 <= model.kickable_distance ** 2:
        lead = params.lead if params.lead is not None else 0.5 * (model.touch_distance + model.kickable_distance)
        wanted = np.array([px + vx + ax + ux * lead - bx, py + vy + ay + uy * lead - by])
        kick, _ = kick_for_velocity(model, view.own_pos[player], view.ball, view.ball_vel, wanted,
                                    player_vel=view.own_vel[player])
    return DribblePlan(direction=np.array([ux, uy]), kick=kick, dash=np.array([ax, ay]),
                       clearance=float(clearance[best]), score=float(score[best]))
