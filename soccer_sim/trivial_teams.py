"""Two trivial teams for tests and benchmarks: ``idle`` stands still, ``chaser`` runs at the ball.

Both reuse one command object and no per-player Python (the chaser's rule is one compiled
loop, :func:`soccer_sim.kernels.chase_ball`), so they add almost nothing to a cycle's cost: the
benchmark of a full match measures the simulator, not the teams.
"""

from __future__ import annotations

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.kernels import chase_ball
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
        chase_ball(view.own_pos, view.ball, view.ball_vel, self._goal_x, self._kick_speed, self._DASH_GAIN,
                   command.dash, command.kick)
        return command

