"""The trials of the penalty-shot experiment (:mod:`experiments.studies.penalty_shot`): the
fixed sequence of ball markers, where the attackers start, each trial as a scenario, the
uncoordinated team (robots blind to each other), and a chain of trials played in order, each
starting where the previous goal left the attackers.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    import numpy as np

    from soccer_sim.config import FieldConfig


CONDITIONS = ("one", "uncoordinated", "coordinated")
SETTINGS = ("empty goal", "goalkeeper")
MARKER_INSET = 3.0
"""Markers lie at least this far (m) inside the lines."""
ROBOT_SPACING = 4.0
"""Metres between the attackers on their goal line at the first trial."""
KEEPER_START = (51.5, 0.0)
"""Where the goalkeeper starts every trial (on the line of the goal the attackers attack)."""


@dataclass(frozen=True)
class Trial:
    """One trial: a marker, a condition, a setting and how long the attackers took."""

    setting: str
    condition: str
    trial: int
    marker_x: float
    marker_y: float
    cycles: int
    seconds: float
    scored: bool


def markers(count: int, seed: int, field: FieldConfig | None = None) -> np.ndarray:
    """(count, 2) the fixed marker sequence on ``field`` (default: the simulator's
    :data:`~soccer_sim.config.STANDARD_FIELD`; absolute frame, the attackers attack +x):
    alternately in the attackers' own half and in the opponents' half, uniform within
    ``MARKER_INSET`` of the lines, none in or next to the goal area they attack."""
    import numpy as np

    from soccer_sim.config import STANDARD_FIELD

    field = field or STANDARD_FIELD
    half_length, half_width = field.half_length, field.half_width
    goal_area_length, goal_area_half_width = field.goal_area_length, field.goal_area_width / 2.0

    rng = np.random.default_rng([seed, 0x5E7])
    out = np.empty((count, 2))
    x_max, y_max = half_length - MARKER_INSET, half_width - MARKER_INSET
    for i in range(count):
        while True:
            x = rng.uniform(-x_max, 0.0) if i % 2 == 0 else rng.uniform(0.0, x_max)
            y = rng.uniform(-y_max, y_max)
            near_goal = x > half_length - goal_area_length - 1.0 and abs(y) < goal_area_half_width + 1.0
            if not near_goal:
                break
        out[i] = (x, y)
    return out


def first_positions(robots: int, half_length: float | None = None) -> np.ndarray:
    """(robots, 2) the attackers on their own goal line at the first trial, ``ROBOT_SPACING`` apart
    (``half_length`` m: half the field's length, default the simulator's
    :data:`~soccer_sim.config.STANDARD_FIELD`'s)."""
    import numpy as np

    from soccer_sim.config import STANDARD_FIELD

    half_length = STANDARD_FIELD.half_length if half_length is None else half_length

    y = (np.arange(robots) - (robots - 1) / 2.0) * ROBOT_SPACING
    return np.column_stack([np.full(robots, -half_length + 0.5), y])


def settle(positions: np.ndarray, half_length: float, half_width: float, gap: float,
           fixed: Sequence[tuple[float, float]] = ()) -> np.ndarray:
    """``positions`` moved onto the field (a scorer may stand behind the goal line), half a metre
    inside the lines, and apart by at least ``gap`` (m), so that they are a valid start for the
    next trial: each overlapping pair is pushed apart symmetrically until none is left. An
    attacker closer than ``gap`` to one of the ``fixed`` players (the goalkeeper's start on its
    line) is moved sideways off it."""
    import numpy as np

    pos = positions.astype(float).copy()
    x_max, y_max = half_length - 0.5, half_width - 0.5
    for _ in range(100):
        np.clip(pos[:, 0], -x_max, x_max, out=pos[:, 0])
        np.clip(pos[:, 1], -y_max, y_max, out=pos[:, 1])
        moved = False
        for i in range(len(pos)):
            for j in range(i + 1, len(pos)):
                d = pos[j] - pos[i]
                dist = float(np.hypot(*d))
                if dist < gap:
                    # Apart along their line, or across the field when they coincide.
                    direction = d / dist if dist > 1e-9 else np.array([0.0, 1.0])
                    shift = direction * (gap - dist + 1e-6) / 2.0
                    pos[i] -= shift
                    pos[j] += shift
                    moved = True
        for q in fixed:
            for i in range(len(pos)):
                d = pos[i] - q
                if float(np.hypot(*d)) < gap:
                    # Sideways: a scorer on the goal line cannot go further back.
                    side = 1.0 if d[1] >= 0 else -1.0
                    pos[i, 1] = q[1] + side * (math.sqrt(max(gap * gap - d[0] * d[0], 0.0)) + 1e-6)
                    moved = True
        if not moved:
            return pos
    raise ValueError(f"cannot place {len(pos)} attackers {gap} m apart on the field")


def trial_scenario(marker: np.ndarray, attackers: np.ndarray, keeper: bool, limit: int):
    """One trial: the attackers (home, no goalkeeper) at rest at ``attackers``, the ball still
    on ``marker``, an empty goal or a goalkeeper on its line; ends at the goal or ``limit``."""
    from soccer_sim.scenarios import BallStart, Scenario, Side

    away = Side(positions=[KEEPER_START], goalie=0) if keeper else Side(players=0)
    return Scenario(name="penalty-shot", description="attackers score from a marker",
                    home=Side(positions=[tuple(p) for p in attackers.tolist()], goalie=None), away=away,
                    ball=BallStart(position=tuple(marker.tolist())), start_mode="play_on", end_on=("scored",),
                    cycle_limit=limit, offside=False, set_plays=False, half_time=False)


class Uncoordinated:
    """``robots`` players, each running its own one-player copy of a team, blind to the others
    (they are neither team-mates nor opponents to it): the "no coordination" condition.

    ``factory`` makes a fresh team object; each copy gets its own random stream."""

    def __init__(self, factory: Callable[[], object], robots: int, name: str = "uncoordinated") -> None:
        self.factory = factory
        self.robots = robots
        self.name = name

    def reset(self, side_info, config, rng: np.random.Generator) -> None:
        from soccer_sim import SideInfo, TeamCommand, TeamError, TeamView
        import numpy as np

        n = side_info.players_per_team
        if n != self.robots:
            raise TeamError(self.name, f"plays {self.robots} robots, not {n}")
        m = side_info.opponents
        self.copies = [self.factory() for _ in range(n)]
        self.views = []
        for k, (team, child) in enumerate(zip(self.copies, rng.spawn(n))):
            team.reset(SideInfo(side_info.team, f"{self.name}[{k}]", side_info.opponent_name, 1, -1, m,
                                side_info.opponent_goalie_index), config, child)
            self.views.append(TeamView(own_pos=np.zeros((1, 2)), own_vel=np.zeros((1, 2)), opp_pos=np.zeros((m, 2)),
                                       opp_vel=np.zeros((m, 2)), ball=np.zeros(2), ball_vel=np.zeros(2),
                                       stamina=np.zeros(1), effort=np.ones(1), capacity=np.full(1, np.inf)))
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view):
        command = self.command
        command.catch = False
        command.move = None
        for k, (team, own) in enumerate(zip(self.copies, self.views)):
            own.own_pos[0] = view.own_pos[k]
            own.own_vel[0] = view.own_vel[k]
            own.opp_pos[:] = view.opp_pos
            own.opp_vel[:] = view.opp_vel
            own.ball[:] = view.ball
            own.ball_vel[:] = view.ball_vel
            own.stamina[0] = view.stamina[k]
            own.effort[0] = view.effort[k]
            own.capacity[0] = view.capacity[k]
            own.play_mode, own.mode_ours, own.score = view.play_mode, view.mode_ours, view.score
            own.cycle, own.half, own.ball_holder = view.cycle, view.half, -1
            decision = team.act(own)
            command.dash[k] = decision.dash[0]
            command.kick[k] = decision.kick[0]
        return command


def _attackers(condition: str, team: str, robots: int):
    from soccer_sim import resolve_team

    if condition == "uncoordinated":
        return Uncoordinated(lambda: resolve_team(team)[0], robots), robots
    return resolve_team(team)[0], (1 if condition == "one" else robots)


def run_chain(setting: str, condition: str, team: str, keeper_team: str, robots: int, marker_list: np.ndarray,
              limit: int, seed: int, watch: Callable[[object, int], object] | None = None) -> list[Trial]:
    """Play one condition's trials in order, each starting where the previous goal left the
    attackers. ``watch(team, side)`` wraps each team object played (0: the attackers, 1: the
    keeper), e.g. so the runner can blame the side whose code fails."""
    from soccer_sim import MatchConfig, resolve_team, run_match

    watch = watch or (lambda team_object, side: team_object)
    config = MatchConfig()
    f, phys = config.field, config.physics
    keeper = setting == "goalkeeper"
    attackers, count = _attackers(condition, team, robots)
    attackers = watch(attackers, 0)
    keeper_side = watch(resolve_team(keeper_team)[0], 1) if keeper else "idle"
    positions = first_positions(count, f.half_length)
    trials = []
    for i, marker in enumerate(marker_list):
        start = settle(positions, f.half_length, f.half_width, 2.0 * phys.player_radius + 0.05,
                       fixed=[KEEPER_START] if keeper else [])
        result = run_match(attackers, keeper_side, seed=seed + i, config=config,
                           scenario=trial_scenario(marker, start, keeper, limit))
        scored = result.end_reason == "scored"
        trials.append(Trial(setting, condition, i, float(marker[0]), float(marker[1]), result.cycles,
                            result.cycles * phys.cycle_seconds, scored))
        positions = result.state.pos[:count].copy()
    return trials
