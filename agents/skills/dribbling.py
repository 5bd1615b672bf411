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
from numba import njit

from agents.skills.kicking import kick_for_velocity, kickable
from agents.skills.model import MotionModel, SkillInputError, check_params, check_player, view_effort


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


def dribble_directions(model: MotionModel, view: object, player: int,
                       params: DribbleParams = DribbleParams()) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(directions (fan, 2), clearance (fan,), score (fan,)) for ``player`` dribbling from
    where it stands; excluded directions score -inf."""
    p = np.asarray(view.own_pos[player], float)
    goal = model.goal_centre(ours=False)
    base = np.arctan2(goal[1] - p[1], goal[0] - p[0])
    offsets = np.radians(np.linspace(-params.spread_deg, params.spread_deg, params.fan)) if params.fan > 1 \
        else np.zeros(1)
    angles = base + offsets
    dirs = np.column_stack([np.cos(angles), np.sin(angles)])
    effort = float(view_effort(view, model.players_per_team)[player])
    speed = max(params.speed_fraction * model.top_speed * effort, 1e-6)
    probes = np.asarray(params.probes, float)
    cycles = np.minimum(np.ceil(probes / speed).astype(np.int64), model.horizon)
    clearance = np.empty(len(dirs))
    _clearance_kernel(p, dirs, probes, cycles, view.opp_pos, view.opp_vel, model.reach, model.player_coast,
                      model.kickable_distance, clearance)
    points = p + dirs * probes[-1]
    score = np.minimum(clearance, params.clearance_cap) / params.clearance_cap + params.goal_weight * np.cos(offsets)
    inside = model.in_field(points, params.field_margin)
    score = np.where(inside, score, -np.inf)
    return dirs, clearance, score


def dribble(model: MotionModel, view: object, player: int, params: DribbleParams = DribbleParams(),
            direction: np.ndarray | None = None) -> DribblePlan:
    """One cycle of dribbling for ``player``: the best direction of the fan (or ``direction``,
    a (2,) vector, when given), the dash and the kick that keeps the ball ``lead`` ahead."""
    n = model.players_per_team
    player = check_player(player, n)
    dirs, clearance, score = dribble_directions(model, view, player, params)
    if direction is None:
        if np.isfinite(score).any():
            best = int(np.argmax(score))
        else:  # cornered against a line: head for the centre of the field
            p = view.own_pos[player]
            best = int(np.argmax(dirs @ (-p / max(float(np.hypot(*p)), 1e-9))))
        unit = dirs[best]
        chosen_clearance, chosen_score = float(clearance[best]), float(score[best])
    else:
        unit = np.asarray(direction, float)
        unit = unit / max(float(np.hypot(*unit)), 1e-12)
        best = int(np.argmax(dirs @ unit))
        chosen_clearance, chosen_score = float(clearance[best]), float(score[best])
    effort = float(view_effort(view, n)[player])
    pos = np.asarray(view.own_pos[player], float)
    vel = np.asarray(view.own_vel[player], float)
    step = unit * params.speed_fraction * model.top_speed * effort
    dash = step - vel
    size = float(np.hypot(*dash))
    limit = model.accel_max * effort
    if size > limit:
        dash *= limit / size
    kick = np.zeros(2)
    if kickable(model, pos, view.ball):
        lead = params.lead if params.lead is not None else 0.5 * (model.touch_distance + model.kickable_distance)
        after = pos + vel + dash
        wanted = after + unit * lead - np.asarray(view.ball, float)
        kick, _ = kick_for_velocity(model, pos, view.ball, view.ball_vel, wanted)
    return DribblePlan(direction=unit.copy(), kick=np.asarray(kick, float), dash=dash, clearance=chosen_clearance,
                       score=chosen_score)


@njit(cache=True, nogil=True)
def _clearance_kernel(start: np.ndarray, dirs: np.ndarray, probes: np.ndarray, cycles: np.ndarray, opp_pos: np.ndarray,
                      opp_vel: np.ndarray, reach: np.ndarray, coast: np.ndarray, kickable: float,
                      out: np.ndarray) -> None:  # pragma: no cover - compiled
    """Per direction: the smallest margin (m) between a probe point and the disc an opponent
    can cover by the time the dribbler gets there (inf without opponents)."""
    for d in range(dirs.shape[0]):
        best = np.inf
        for j in range(probes.shape[0]):
            qx = start[0] + dirs[d, 0] * probes[j]
            qy = start[1] + dirs[d, 1] * probes[j]
            k = cycles[j]
            for o in range(opp_pos.shape[0]):
                cx = opp_pos[o, 0] + coast[k] * opp_vel[o, 0]
                cy = opp_pos[o, 1] + coast[k] * opp_vel[o, 1]
                margin = math.sqrt((qx - cx) ** 2 + (qy - cy) ** 2) - reach[k] - kickable
                if margin < best:
                    best = margin
        out[d] = best
