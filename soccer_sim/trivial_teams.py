"""Two trivial teams for tests and benchmarks: ``idle`` stands still, ``chaser`` runs at the ball.

Both work on whole arrays (no per-player Python) and reuse one command object, so they add
almost nothing to a cycle's cost; the benchmark of a full match measures the simulator.
"""

from __future__ import annotations

import math

import numpy as np

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
        self._kick_row = np.zeros(2)

    def act(self, view: TeamView) -> TeamCommand:
        command = self._command
        dash = np.subtract(view.ball, view.own_pos, out=command.dash)
        dash *= self._DASH_GAIN
        # Kick: turn the ball's velocity into kick_speed towards the goal centre.
        bx, by = view.ball.tolist()
        vx, vy = view.ball_vel.tolist()
        dx, dy = self._goal_x - bx, -by
        scale = self._kick_speed / max(math.hypot(dx, dy), 1e-9)
        row = self._kick_row
        row[0] = dx * scale - vx
        row[1] = dy * scale - vy
        command.kick[...] = row
        return command
