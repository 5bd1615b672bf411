"""Two trivial teams for tests and benchmarks: ``idle`` stands still, ``chaser`` runs at the ball.

Both reuse one command object and no per-player Python (the chaser's rule is one compiled
loop), so they add almost nothing to a cycle's cost: the benchmark of a full match measures
the simulator, not the teams.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from soccer_sim.config import MatchConfig
from soccer_sim.team import SideInfo, TeamCommand, TeamView


class IdleTeam:
    """Every player stands still and never kicks."""

    def reset(self, side_info: SideInfo, config: MatchConfig, rng: np.random.Generator) -> None:
        n = side_info.players_per_team
        self._command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view: TeamView) -> TeamCommand:
        return self._command


class ChaserTeam:
    """Every player (the goalkeeper too) runs flat out at the ball and, when it can, kicks it
    as hard as possible straight at the centre of the opponents' goal."""

    _DASH_GAIN = 100.0
    """Requested acceleration per metre of distance to the ball: large, so the match's clipping
    makes every player dash at full strength until it reaches the ball."""

    def reset(self, side_info: SideInfo, config: MatchConfig, rng: np.random.Generator) -> None:
        n = side_info.players_per_team
        self._goal_x = config.field.half_length
        self._kick_speed = config.physics.kick_speed_max
        self._command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view: TeamView) -> TeamCommand:
        command = self._command
        _chase(view.own_pos, view.ball, view.ball_vel, self._goal_x, self._kick_speed, self._DASH_GAIN,
               command.dash, command.kick)
        return command


@njit(cache=True, nogil=True)
def _chase(own_pos: np.ndarray, ball: np.ndarray, ball_vel: np.ndarray, goal_x: float, kick_speed: float,
           gain: float, dash: np.ndarray, kick: np.ndarray) -> None:  # pragma: no cover - compiled
    """Dash at the ball; kick so that the ball leaves at ``kick_speed`` towards (goal_x, 0)."""
    bx, by = ball[0], ball[1]
    dx, dy = goal_x - bx, -by
    scale = kick_speed / max(math.sqrt(dx * dx + dy * dy), 1e-9)
    kx, ky = dx * scale - ball_vel[0], dy * scale - ball_vel[1]
    for i in range(own_pos.shape[0]):
        dash[i, 0] = (bx - own_pos[i, 0]) * gain
        dash[i, 1] = (by - own_pos[i, 1]) * gain
        kick[i, 0] = kx
        kick[i, 1] = ky
