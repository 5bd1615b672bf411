"""Observations and actions of the learning interface, built from a team's view.

Everything here works on a :class:`~soccer_sim.team.TeamView` (the team-relative frame: the
team attacks +x, its own goal is at -x), so the PettingZoo environment and
:class:`~soccer_sim.env.policy_team.PolicyTeam` (a policy entered in matches as a team) see
exactly the same numbers.

Observation of player ``i`` of a team of ``n`` against ``m``: float32, ``observation_size(k, k)``
values for ``k`` *slots* per side (default :data:`OBSERVATION_SLOTS`, 11, whatever the sides'
sizes, so every scenario up to 11 a side shares one observation space and a policy moves
between scenarios unchanged). Positions are divided by the field's half length, player
velocities by the players' top speed, the ball's velocity by its top speed, stamina by its
maximum:

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
``12:12+4k``               4k      team-mate slots by shirt number (self included): x, y, vx, vy
``12+4k:12+8k``            4k      opponent slots by shirt number: x, y, vx, vy
next                       9       play mode, one-hot (:class:`~soccer_sim.state.PlayMode` order)
next                       1       1 when the current set play is ours
next                       2       goals for, goals against
next                       1       time: cycle / the episode's horizon (see :meth:`Scales.of`)
next                       1       half: 0 first, 1 second
next                       k       presence mask of the team-mate slots: 1 on the pitch, 0 sent off or no player
next                       k       presence mask of the opponent slots, the same
=========================  ======  ==========================================================

**Padding**: slots beyond a side's size (a team-mate slot ``j >= n``, an opponent slot
``j >= m``) hold zeros and a 0 in the presence mask, so 3 v 1 and 11 v 11 observations have the
same layout.

**Bounds** (:func:`observation_bounds`), from the configuration: player positions within
``(half_length + margin) / half_length`` (players are kept on the field plus its margin;
1.095 on the regular field), the ball within a cycle's flight more (1.152), velocities
within 2 (a margin over the top speeds: measured over built-in matches, players reach 0.51
and the ball 0.98, random actions less), the relative ball position within the sum, goals within the
match's cycles, every flag, mask, share and stamina in [0, 1]. Observations are clipped to
them, so they always lie in the space.

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
from soccer_sim.perception.views import PlayerViews
from soccer_sim.team import TeamCommand, TeamView

ACTION_SIZE = 5
MODES = len(PlayMode)
_TAIL = MODES + 1 + 2 + 1 + 1
OBSERVATION_SLOTS = 11
"""Player slots per side in an observation by default (the largest side a scenario fields)."""
VELOCITY_BOUND = 2.0
"""Bound of a scaled velocity in the observation: a margin over the top speeds (measured over
built-in matches at the end of a cycle: players up to 0.51, the ball 0.98)."""


def observation_size(n: int, m: int) -> int:
    """Values in one player's observation, for ``n`` team-mate slots (self included) and ``m``
    opponent slots (both :data:`OBSERVATION_SLOTS` by default, see the module docstring)."""
    return 12 + 4 * n + 4 * m + _TAIL + n + m


def observation_slots(n: int, m: int, slots: int | None = None) -> int:
    """Slots per side for sides of ``n`` and ``m`` players: ``slots`` (None: at least
    :data:`OBSERVATION_SLOTS`); ValueError when a side does not fit."""
    if slots is None:
        return max(OBSERVATION_SLOTS, n, m)
    if isinstance(slots, bool) or not isinstance(slots, (int, np.integer)) or slots < max(n, m, 1):
        raise ValueError(f"observation_slots must be an integer of at least the larger side ({max(n, m, 1)}), "
                         f"got {slots!r}")
    return int(slots)


def episode_horizon(max_cycles: int | None, scenario: object | None) -> int | None:
    """The episode's last cycle when it ends before the match would: the smaller of the
    environment's ``max_cycles`` and the scenario's ``cycle_limit`` (either may be None), None
    when neither is set. The time feature's scale (:meth:`Scales.of`): the environment and
    :class:`~soccer_sim.env.policy_team.PolicyTeam` both take it from here, so a policy sees in
    matches the time it was trained with."""
    limits = [c for c in (max_cycles, getattr(scenario, "cycle_limit", None)) if c]
    return min(limits) if limits else None


def observation_bounds(slots: int, config: MatchConfig) -> tuple[np.ndarray, np.ndarray]:
    """(low, high) float32 arrays of the observation with ``slots`` slots per side (see the
    module docstring)."""
    field, physics = config.field, config.physics
    half = field.length / 2.0
    player = (half + field.margin) / half
    ball = (half + field.margin + physics.ball_speed_max) / half
    high = np.ones(observation_size(slots, slots), dtype=np.float64)
    high[0:2], high[2:4], high[6:8], high[8:10], high[10:12] = player, VELOCITY_BOUND, ball, VELOCITY_BOUND, \
        player + ball
    rows = high[12:12 + 8 * slots].reshape(2 * slots, 4)
    rows[:, 0:2], rows[:, 2:4] = player, VELOCITY_BOUND
    low = -high
    low[4:6] = 0.0
    tail = 12 + 8 * slots
    low[tail:] = 0.0
    high[tail + MODES + 1:tail + MODES + 3] = max(config.total_cycles, 1)  # goals: at most one a cycle
    return low.astype(np.float32), high.astype(np.float32)


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
    def of(cls, config: MatchConfig, horizon: int | None = None) -> Scales:
        """The scales of ``config``; the time feature divides the cycle by ``horizon`` (the
        episode's last cycle: a scenario's ``cycle_limit`` or the env's ``max_cycles``) when given,
        else by the match's cycles, so a short episode's time still runs from 0 to 1."""
        physics = config.physics
        return cls(length=config.field.length / 2.0, player_speed=physics.player_speed_max,
                   ball_speed=physics.ball_speed_max, stamina=config.stamina.maximum,
                   dash=physics.dash_power_max * physics.dash_power_rate, kick=physics.kick_speed_max,
                   total_cycles=float(horizon or config.max_cycles or config.total_cycles))


class ObservationBuilder:
    """Writes every player's observation of a team's view into one (n, size) float32 array."""

    def __init__(self, n: int, m: int, goalie: int, config: MatchConfig, slots: int | None = None,
                 horizon: int | None = None) -> None:
        self.n, self.m = n, m
        self.slots = k = observation_slots(n, m, slots)
        self.size = observation_size(k, k)
        self.scales = Scales.of(config, horizon)
        self.low, self.high = observation_bounds(k, config)
        self.out = np.zeros((n, self.size), dtype=np.float32)
        self._goalie = np.zeros(n, dtype=np.float32)
        if 0 <= goalie < n:
            self._goalie[goalie] = 1.0
        self._row = np.zeros(self.size, dtype=np.float32)
        """The values every player of the team shares (all but the own columns)."""
        self._mate_rows = self._row[12:12 + 4 * n].reshape(n, 4)
        self._opp_rows = self._row[12 + 4 * k:12 + 4 * k + 4 * m].reshape(m, 4)
        self._mode = 12 + 8 * k
        self._tail = self._row[self._mode:]
        self._mates_present = slice(self._mode + _TAIL, self._mode + _TAIL + n)
        self._opps_present = slice(self._mode + _TAIL + k, self._mode + _TAIL + k + m)

    def build(self, view, out: np.ndarray | None = None) -> np.ndarray:
        """The (n, size) observations of ``view``, clipped to the bounds: written into ``out``
        when given (rows of a caller's array), else into a new array (safe to keep). Padding
        slots stay zero."""
        s = self.scales
        row, buf = self._row, self.out
        # Everything but the own columns (0:6, 10:12) is the same for every player: one row, copied.
        pos = view.own_pos / s.length
        vel = view.own_vel / s.player_speed
        ball = view.ball / s.length
        row[6:8] = ball
        row[8:10] = view.ball_vel / s.ball_speed
        mates, opps = self._mate_rows, self._opp_rows  # (n, 4) and (m, 4) windows on the row
        mates[:, 0:2] = pos
        mates[:, 2:4] = vel
        opps[:, 0:2] = view.opp_pos / s.length
        opps[:, 2:4] = view.opp_vel / s.player_speed
        tail = self._tail
        tail[:MODES] = 0.0
        tail[int(view.play_mode)] = 1.0
        tail[MODES] = float(view.mode_ours)
        tail[MODES + 1] = view.score[0]
        tail[MODES + 2] = view.score[1]
        tail[MODES + 3] = view.cycle / s.total_cycles
        tail[MODES + 4] = view.half
        row[self._mates_present] = view.present
        row[self._opps_present] = view.opp_present
        buf[:] = row
        buf[:, 0:2] = pos
        buf[:, 2:4] = vel
        buf[:, 4] = view.stamina / s.stamina
        buf[:, 5] = self._goalie
        np.subtract(ball, pos, out=buf[:, 10:12])
        if out is None:
            out = np.empty_like(buf)
        np.maximum(buf, self.low, out=out)
        return np.minimum(out, self.high, out=out)


class ActionDecoder:
    """Turns the players' (n, 5) actions into the team's :class:`TeamCommand`.

    A player executes one body command a cycle (the match's rule, as rcssserver's): an action's
    kick is sent only for a player who perceives the ball within its kickable distance
    (:func:`ball_within_reach`), so that the dash of a player who cannot kick is not lost to a
    kick that could do nothing."""

    def __init__(self, n: int, goalie: int, config: MatchConfig) -> None:
        self.n, self.goalie = n, goalie
        self.scales = Scales.of(config)
        self.kickable = config.physics.kickable_distance
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def decode(self, actions: np.ndarray, view: TeamView | PlayerViews) -> TeamCommand:
        """``actions`` (n, 5), already checked and clipped to [-1, 1]; ``view``: what the
        players perceived this cycle (the team's view, or each player's own)."""
        command = self.command
        command.dash[:] = actions[:, 0:2] * self.scales.dash
        command.kick[:] = actions[:, 2:4] * self.scales.kick
        command.kick[~ball_within_reach(view, self.kickable)] = 0.0
        command.catch = bool(0 <= self.goalie < self.n and actions[self.goalie, 4] > 0.0)
        return command


def ball_within_reach(view: TeamView | PlayerViews, kickable: float) -> np.ndarray:
    """(n,) bool: the players who perceive the ball within ``kickable`` (m): exactly under full
    observation; under partial observation by the distance of this cycle's see (a player who
    does not see the ball this cycle does not kick)."""
    if isinstance(view, PlayerViews):
        return np.nan_to_num(view.ball_distance, nan=np.inf) <= kickable
    gap = view.ball - view.own_pos
    return np.einsum("ij,ij->i", gap, gap) <= kickable * kickable


def check_actions(agents: list[str], actions: list[object], size: int = ACTION_SIZE) -> np.ndarray:
    """The actions of ``agents`` as one float64 (len(agents), size) array clipped to [-1, 1]: one
    array operation when every action is well formed, else :func:`check_action` agent by agent,
    so the ValueError names the first agent at fault. ``size``: values per action (5; more with
    the say action of partial observation)."""
    try:
        rows = np.array(actions, dtype=np.float64)
    except (TypeError, ValueError):
        rows = None
    if rows is None or rows.shape != (len(agents), size) or not np.isfinite(rows).all():
        return np.array([check_action(agent, action, size) for agent, action in zip(agents, actions)])
    return np.clip(rows, -1.0, 1.0, out=rows)


def check_choice(agent: str, action: object, choices: int, action_mode: str) -> int:
    """One agent's discrete action as an int in ``0..choices-1``; ValueError naming the agent
    (and ``action_mode``) otherwise. A float with an integral value (``5.0``, as some libraries'
    random policies give) counts as it."""
    value = np.asarray(action)
    integral = value.dtype.kind in "iu" or (value.dtype.kind == "f" and bool(np.all(np.mod(value, 1) == 0)))
    if value.shape not in ((), (1,)) or not integral:
        raise ValueError(f"action of {agent} must be one integer (action_mode={action_mode!r}), got {action!r}")
    choice = int(value.reshape(-1)[0])
    if not 0 <= choice < choices:
        raise ValueError(f"action of {agent} must be in 0..{choices - 1}, got {choice}")
    return choice


def check_choices(agents: list[str], actions: object, choices: int, action_mode: str) -> np.ndarray:
    """The discrete actions of ``agents`` as one int64 (len(agents),) array: one array operation
    when they are well formed ((n,) or (n, 1) integers in range), else :func:`check_choice` agent
    by agent, so the ValueError names the first agent at fault."""
    n = len(agents)
    rows = np.asarray(actions) if not isinstance(actions, list) else None
    if rows is not None and rows.shape == (n, 1):
        rows = rows[:, 0]
    if rows is not None and rows.shape == (n,) and rows.dtype.kind in "iu" and bool(
            ((rows >= 0) & (rows < choices)).all()):
        return rows.astype(np.int64)
    try:
        listed = list(actions)  # type: ignore[call-overload]
    except TypeError:
        raise ValueError(f"actions must hold one action per agent ({n}), got {actions!r}") from None
    if len(listed) != n:
        raise ValueError(f"actions must hold one action per agent ({n}), got {len(listed)}")
    return np.array([check_choice(agent, action, choices, action_mode) for agent, action in zip(agents, listed)],
                    dtype=np.int64)


def check_action(agent: str, action: object, size: int = ACTION_SIZE) -> np.ndarray:
    """One agent's action as a float64 (size,) array clipped to [-1, 1]; ValueError naming the
    agent for the wrong shape, a non-numeric value or a NaN."""
    try:
        array = np.asarray(action, dtype=np.float64)
    except (TypeError, ValueError):
        raise ValueError(f"action of {agent} must be {size} numbers, got {action!r}") from None
    if array.shape != (size,):
        raise ValueError(f"action of {agent} must have shape ({size},), got {array.shape}")
    if not np.isfinite(array).all():
        raise ValueError(f"action of {agent} is not finite: {array.tolist()}")
    return np.clip(array, -1.0, 1.0)
