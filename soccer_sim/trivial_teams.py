"""Two trivial teams for tests and benchmarks: ``idle`` stands still, ``chaser`` runs at the ball.
Both play under full and partial observation (``observation_modes``).

Both reuse one command object and no per-player Python (the chaser's rule is one compiled
loop, :func:`soccer_sim.kernels.chase_ball`), so they add almost nothing to a cycle's cost: the
benchmark of a full match measures the simulator, not the teams.
"""

from __future__ import annotations

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.kernels import chase_ball
from soccer_sim.perception.views import PlayerViews
from soccer_sim.team import SideInfo, TeamCommand, TeamView


class IdleTeam:
    """Every player stands still and never kicks."""

    observation_modes = ("full", "partial")

    def reset(self, side_info: SideInfo, config: MatchConfig, rng: np.random.Generator) -> None:
        n = side_info.players_per_team
        self._command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view: TeamView) -> TeamCommand:
        return self._command


class ChaserTeam:
    """Every player (the goalkeeper too) runs flat out at the ball and, when it can, kicks it
    as hard as possible straight at the centre of the opponents' goal (a player that kicks does
    not dash in that cycle: one body command per player and cycle). Under partial observation
    each player runs at where it last saw the ball (the centre spot before it has seen it)."""

    observation_modes = ("full", "partial")

    _DASH_GAIN = 100.0
    """Requested acceleration per metre of distance to the ball: large, so the match's clipping
    makes every player dash at full strength until it reaches the ball."""

    def reset(self, side_info: SideInfo, config: MatchConfig, rng: np.random.Generator) -> None:
        n = side_info.players_per_team
        self._goal_x = config.field.half_length
        self._kick_speed = config.physics.kick_speed_max
        self._kickable = config.physics.kickable_distance
        self._command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))
        self._last_ball = np.zeros((n, 2))  # partial observation: where each player last saw the ball

    def act(self, view: TeamView | PlayerViews) -> TeamCommand:
        command = self._command
        if isinstance(view, PlayerViews):
            return self._act_on_own_views(view)
        chase_ball(view.own_pos, view.ball, view.ball_vel, self._goal_x, self._kick_speed, self._DASH_GAIN,
                   self._kickable, command.dash, command.kick)
        return command


    def _act_on_own_views(self, views: PlayerViews) -> TeamCommand:
        """Each player from its own view: dash at where it last saw the ball, kick at goal."""
        command = self._command
        seen = views.ball_seen
        self._last_ball[seen] = views.ball[seen]
        ball = self._last_ball
        command.dash[:] = (ball - views.position) * self._DASH_GAIN
        to_goal = np.array([self._goal_x, 0.0]) - ball
        length = np.maximum(np.hypot(to_goal[:, 0], to_goal[:, 1]), 1e-9)
        command.kick[:] = to_goal * (self._kick_speed / length)[:, None]
        near = np.hypot(*(ball - views.position).T) <= self._kickable  # kick, or else dash
        command.dash[near] = 0.0
        command.kick[~near] = 0.0
        return command
