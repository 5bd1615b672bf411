"""Observations and actions of the learning interface, built from a team's view.

Everything here works on a :class:`~soccer_sim.team.TeamView` (the team-relative frame: the
team attacks +x, its own goal is at -x), so the PettingZoo environment and
:class:`~soccer_sim.env.policy_team.PolicyTeam` (a policy entered in matches as a team) see
exactly the same numbers.

Observation of player ``i`` of a team of ``n`` against ``m`` (float32, ``observation_size(n, m)``
values); positions are divided by the field's half length, player velocities by the players'
top speed, the ball's velocity by its top speed, stamina by its maximum:

=========================  ======  ==========================================================
slice                      size    what
=========================  ======  ==========================================================
``0:2``                    2       own position
``2:4``                    2       own velocity
``4``                      1       own stamina
``5``                      1       1 for the goalkeeper, else 0
``6:8``                    2       ball position
``8:10``                   2       ball velocity
``10:12``                  2       ball position minus own position
``12:12+4n``               4n      every team-mate by shirt number (self included): x, y, vx, vy
``12+4n:12+4n+4m``         4m      every opponent by shirt number: x, y, vx, vy
next                       9       play mode, one-hot (:class:`~soccer_sim.state.PlayMode` order)
next                       1       1 when the current set play is ours
next                       2       goals for, goals against
next                       1       match time: cycle / total cycles
next                       1       half: 0 first, 1 second
next                       n       every team-mate by shirt number: 1 on the pitch, 0 sent off
next                       m       every opponent by shirt number: 1 on the pitch, 0 sent off
=========================  ======  ==========================================================

A player sent off keeps its rows (parked off the pitch) and its actions are ignored.

Action of one player (float32, 5 values in [-1, 1]; values outside are clipped): ``0:2`` the
dash, scaled to the largest acceleration (``dash_power_max * dash_power_rate`` m/cycle²);
``2:4`` the kick, scaled to the largest change of the ball's velocity
(``kick_speed_max`` m/cycle), a kick only where the ball is kickable and all zeros for none;
``4`` the catch: above 0 asks to catch (heeded for the goalkeeper only). The match clips every
request to the physical limits.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.state import PlayMode
from soccer_sim.team import TeamCommand

ACTION_SIZE = 5
MODES = len(PlayMode)
_TAIL = MODES + 1 + 2 + 1 + 1


def observation_size(n: int, m: int) -> int:
    """Values in one player's observation, for ``n`` team-mates (self included) and ``m`` opponents."""
    return 12 + 4 * n + 4 * m + _TAIL + n + m


@dataclass(frozen=True)
class Scales:
    """The divisors of the observation and the multipliers of the action, from a MatchConfig."""

    length: float
    player_speed: float
    ball_speed: float
    stamina: float
    dash: float
    kick: float
    total_cycles: float

    @classmethod
    def of(cls, config: MatchConfig) -> Scales:
        physics = config.physics
        return cls(length=config.field.length / 2.0, player_speed=physics.player_speed_max,
                   ball_speed=physics.ball_speed_max, stamina=config.stamina.maximum,
                   dash=physics.dash_power_max * physics.dash_power_rate, kick=physics.kick_speed_max,
                   total_cycles=float(config.max_cycles or config.total_cycles))


class ObservationBuilder:
    """Writes every player's observation of a team's view into one (n, size) float32 array."""

    def __init__(self, n: int, m: int, goalie: int, config: MatchConfig) -> None:
        self.n, self.m = n, m
        self.size = observation_size(n, m)
        self.scales = Scales.of(config)
        self.out = np.zeros((n, self.size), dtype=np.float32)
        if 0 <= goalie < n:
            self.out[goalie, 5] = 1.0
        self._mates = slice(12, 12 + 4 * n)
        self._opps = slice(12 + 4 * n, 12 + 4 * n + 4 * m)
        self._mode = 12 + 4 * n + 4 * m

    def build(self, view) -> np.ndarray:
        """The (n, size) observations of ``view`` (a new array: safe to keep)."""
        s = self.scales
        out = self.out
        pos = view.own_pos / s.length
        vel = view.own_vel / s.player_speed
        ball = view.ball / s.length
        out[:, 0:2] = pos
        out[:, 2:4] = vel
        out[:, 4] = view.stamina / s.stamina
        out[:, 6:8] = ball
        out[:, 8:10] = view.ball_vel / s.ball_speed
        out[:, 10:12] = ball - pos
        mates = np.concatenate([pos, vel], axis=1).reshape(-1)
        opps = np.concatenate([view.opp_pos / s.length, view.opp_vel / s.player_speed], axis=1).reshape(-1)
        out[:, self._mates] = mates
        out[:, self._opps] = opps
        tail = out[:, self._mode:]
        tail[:, :MODES] = 0.0
        tail[:, int(view.play_mode)] = 1.0
        tail[:, MODES] = float(view.mode_ours)
        tail[:, MODES + 1] = view.score[0]
        tail[:, MODES + 2] = view.score[1]
        tail[:, MODES + 3] = view.cycle / s.total_cycles
        tail[:, MODES + 4] = view.half
        tail[:, _TAIL:_TAIL + self.n] = view.present
        tail[:, _TAIL + self.n:] = view.opp_present
        return out.copy()


class ActionDecoder:
    """Turns the players' (n, 5) actions into the team's :class:`TeamCommand`."""

    def __init__(self, n: int, goalie: int, config: MatchConfig) -> None:
        self.n, self.goalie = n, goalie
        self.scales = Scales.of(config)
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def decode(self, actions: np.ndarray) -> TeamCommand:
        """``actions`` (n, 5), already checked and clipped to [-1, 1]."""
        command = self.command
        command.dash[:] = actions[:, 0:2] * self.scales.dash
        command.kick[:] = actions[:, 2:4] * self.scales.kick
        command.catch = bool(0 <= self.goalie < self.n and actions[self.goalie, 4] > 0.0)
        return command


def check_actions(agents: list[str], actions: list[object]) -> np.ndarray:
    """The actions of ``agents`` as one float64 (len(agents), 5) array clipped to [-1, 1]: one
    array operation when every action is well formed, else :func:`check_action` agent by agent,
    so the ValueError names the first agent at fault."""
    try:
        rows = np.array(actions, dtype=np.float64)
    except (TypeError, ValueError):
        rows = None
    if rows is None or rows.shape != (len(agents), ACTION_SIZE) or not np.isfinite(rows).all():
        return np.array([check_action(agent, action) for agent, action in zip(agents, actions)])
    return np.clip(rows, -1.0, 1.0, out=rows)


def check_action(agent: str, action: object) -> np.ndarray:
    """One agent's action as a float64 (5,) array clipped to [-1, 1]; ValueError naming the
    agent for the wrong shape, a non-numeric value or a NaN."""
    try:
        array = np.asarray(action, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"action of {agent} must be {ACTION_SIZE} numbers, got {action!r}") from None
    if array.shape != (ACTION_SIZE,):
        raise ValueError(f"action of {agent} must have shape ({ACTION_SIZE},), got {array.shape}")
    if not np.isfinite(array).all():
        raise ValueError(f"action of {agent} is not finite: {array.tolist()}")
    return np.clip(array, -1.0, 1.0)
