"""Clearing: kick the ball hard, away from danger, where the opponents get to it last.

Directions are tried in a fan around +x (``± spread_deg``), each with the fastest ball one
kick gives. For each the opponents' and our earliest interceptions on the ball's path are
found (:mod:`agents.skills.lanes`); the score of a direction is

    ``w_ours * [a team-mate gets there first] + w_time * min(their cycle, time_cap) / time_cap
      + w_forward * cos(angle) + w_wing * |sin(angle)| - w_out * [the ball leaves the field]``

so a clearance prefers a team-mate, then a long run before any opponent, upfield and (for
the goalkeeper) towards the wings, and not out of play. The weights are :class:`ClearParams`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from agents.skills.interception import UNREACHABLE
from agents.skills.kicking import kick_for_velocity
from agents.skills.lanes import opponent_cycles, teammate_cycles
from agents.skills.model import MotionModel, check_params, check_player


@dataclass(frozen=True)
class ClearParams:
    """Tunable choices of the clearance (degrees, cycles, weights)."""

    fan: int = 15
    spread_deg: float = 75.0
    """Directions span ± this angle around +x."""
    time_cap: int = 30
    """Opponent cycles beyond this count no more."""
    weight_ours: float = 1.0
    weight_time: float = 1.0
    weight_forward: float = 0.5
    weight_wing: float = 0.0
    """Preference for the wings (the goalkeeper's clearance raises it)."""
    weight_out: float = 0.8

    def __post_init__(self) -> None:
        check_params(self, non_negative=("spread_deg", "weight_ours", "weight_time", "weight_forward", "weight_wing",
                                         "weight_out"), counts=("fan", "time_cap"))


@dataclass(frozen=True)
class ClearPlan:
    direction: np.ndarray
    """(2,) unit vector of the clearance."""
    kick: np.ndarray
    """(2,) kick request."""
    ball_vel: np.ndarray
    """(2,) ball velocity right after the kick."""
    opponent_cycle: int
    teammate_cycle: int
    score: float


def best_clearance(model: MotionModel, view: object, kicker: int, params: ClearParams = ClearParams(),
                   holder: bool = False) -> ClearPlan:
    """The best clearance kick for ``kicker`` (see the module docstring)."""
    kicker = check_player(kicker, model.players_per_team, "kicker")
    angles = np.radians(np.linspace(-params.spread_deg, params.spread_deg, params.fan)) if params.fan > 1 \
        else np.zeros(1)
    dirs = np.column_stack([np.cos(angles), np.sin(angles)])
    ball = np.asarray(view.ball, float)
    kicks, velocities = kick_for_velocity(model, view.own_pos[kicker], ball, view.ball_vel,
                                          dirs * model.ball_speed_max, holder)
    theirs, _ = opponent_cycles(model, view, ball, velocities)
    ours, _ = teammate_cycles(model, view, ball, velocities)
    ours = ours.copy()
    ours[:, kicker] = UNREACHABLE
    our_first = ours.min(axis=1)
    rest = ball + velocities * model.ball_travel[-1]
    out = ~model.in_field(rest) & ~((rest[:, 0] > model.half_length) & (np.abs(rest[:, 1]) < model.goal_half_width))
    score = (params.weight_ours * (our_first < theirs)
             + params.weight_time * np.minimum(theirs, params.time_cap) / params.time_cap
             + params.weight_forward * np.cos(angles) + params.weight_wing * np.abs(np.sin(angles))
             - params.weight_out * out)
    best = int(np.argmax(score))
    return ClearPlan(direction=dirs[best].copy(), kick=kicks[best].copy(), ball_vel=velocities[best].copy(),
                     opponent_cycle=int(theirs[best]), teammate_cycle=int(our_first[best]), score=float(score[best]))
