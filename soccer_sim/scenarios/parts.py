"""The parts of a scenario: its sides and its ball, the names and limits scenarios use, and
:class:`ScenarioError`, which every scenario check raises.

:mod:`soccer_sim.scenarios.scenario` puts the parts together into a
:class:`~soccer_sim.scenarios.scenario.Scenario`. Frame and units as there: absolute frame at
the start (home attacks +x), metres and m/cycle.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from soccer_sim.errors import SoccerSimError
from soccer_sim.state import AWAY, HOME, NO_PLAYER, PlayMode

if TYPE_CHECKING:
    from soccer_sim.config import MatchConfig

MAX_PLAYERS = 11
"""Largest side a scenario may field."""
CONFIG_GOALIE = "config"
"""``Side.goalie`` value meaning: the configuration's ``rules.goalie_index`` (if the side is
large enough for it; a side of 0 players has no goalkeeper)."""
END_CONDITIONS = ("goal", "scored", "out", "lost")
"""End conditions besides the cycle limit, in the order they are judged within one cycle:
a goal (either side), a goal for the attacking side (``Scenario.attacker``; own goals of the
defenders included), the ball out over a line (not a goal), the ball lost to the defending
side (one of its players kicks, touches or catches it, or it is awarded a set play)."""
START_MODES = {
    "kick_off": PlayMode.KICK_OFF, "play_on": PlayMode.PLAY_ON, "kick_in": PlayMode.KICK_IN,
    "corner_kick": PlayMode.CORNER_KICK, "goal_kick": PlayMode.GOAL_KICK, "free_kick": PlayMode.FREE_KICK,
}
"""Play modes a scenario may start in, by name."""
SIDE_NAMES = {"home": HOME, "away": AWAY}
_SAME_POINT = 1e-6
"""Two start positions closer than this (m) are the same point."""


class ScenarioError(SoccerSimError, ValueError):
    """A scenario that cannot be played; ``field`` names the offending field
    (``"home.positions[2]"``, ``"end_on"``, ...) and the message says why."""

    def __init__(self, field_name: str, message: str) -> None:
        qualified = field_name if field_name[:1].isupper() else f"Scenario.{field_name}"
        super().__init__(f"{qualified}: {message}")
        self.field = field_name
        self.message = message

    def __reduce__(self):
        """Pickle by the constructor's arguments (so the error crosses process boundaries)."""
        return type(self), (self.field, self.message)


Point = tuple[float, float]


@dataclass(frozen=True)
class Side:
    """One side's players at the start (absolute frame, see the module docstring)."""

    players: int | None = None
    """Players of the side, 0 to 11; None: as many as ``positions`` lists, else
    ``config.players_per_team``."""
    goalie: int | None | str = CONFIG_GOALIE
    """Index of the goalkeeper within the side, None for no goalkeeper, or ``"config"``: the
    configuration's ``rules.goalie_index`` (none for a side of 0 players)."""
    positions: tuple[Point, ...] | None = None
    """Start position of each player (m); None: the regular line-up in the side's own half
    (goalkeeper on its goal line, the others in three lines), as at a kick-off."""
    velocities: tuple[Point, ...] | None = None
    """Start velocity of each player (m/cycle); None: at rest."""
    relative_to_ball: bool = False
    """``positions`` are offsets from the ball's start position (drawn or fixed), so the
    players move with a randomised ball."""
    jitter: float = 0.0
    """Each non-goalkeeper's start position is moved by a uniform draw in
    ``[-jitter, jitter]`` per axis (m), then kept on the field."""

    def __post_init__(self) -> None:
        _freeze(self, "positions", self.positions, "Side.positions")
        _freeze(self, "velocities", self.velocities, "Side.velocities")
        if self.goalie is False:
            object.__setattr__(self, "goalie", None)


@dataclass(frozen=True)
class BallStart:
    """The ball at the start (absolute frame)."""

    position: Point = (0.0, 0.0)
    """Start position (m); ignored when ``area`` is given."""
    velocity: Point = (0.0, 0.0)
    """Start velocity (m/cycle)."""
    area: tuple[Point, Point] | None = None
    """((x_min, y_min), (x_max, y_max)): the start position is drawn uniformly in this
    rectangle (m)."""

    def __post_init__(self) -> None:
        object.__setattr__(self, "position", as_point(self.position, "ball.position"))
        object.__setattr__(self, "velocity", as_point(self.velocity, "ball.velocity"))
        if self.area is not None:
            if not isinstance(self.area, (list, tuple)) or len(self.area) != 2:
                raise ScenarioError("ball.area", f"must be two corners ((x_min, y_min), (x_max, y_max)), got {self.area!r}")
            low, high = as_point(self.area[0], "ball.area[0]"), as_point(self.area[1], "ball.area[1]")
            if low[0] > high[0] or low[1] > high[1]:
                raise ScenarioError("ball.area", f"the first corner {low} must be below and left of the second {high}")
            object.__setattr__(self, "area", (low, high))


def line_up(n: int, goalie: int, half_length: float, half_width: float) -> np.ndarray:
    """(n, 2) the regular opening line-up of one side attacking +x (team frame): the
    goalkeeper (index ``goalie``, -1 for none) a metre in front of its goal line's centre,
    the others spread over the own half in three lines at 70, 45 and 20 % of the half's depth."""
    own = np.zeros((n, 2))
    outfield = [i for i in range(n) if i != goalie]
    if goalie != NO_PLAYER:
        own[goalie] = (-half_length + 1.0, 0.0)
    depths = (0.7, 0.45, 0.2)
    for line, depth in enumerate(depths):
        members = outfield[line::len(depths)]
        for k, i in enumerate(members):
            own[i] = (-half_length * depth, half_width * (2.0 * (k + 1) / (len(members) + 1) - 1.0) * 0.8)
    return own


# ---------------------------------------------------------------------- helpers
def is_int(value: object) -> bool:
    return isinstance(value, (int, np.integer)) and not isinstance(value, bool)


def as_point(value: object, name: str) -> Point:
    """``value`` as a finite (x, y) pair of floats, else a ScenarioError naming ``name``."""
    try:
        x, y = value  # type: ignore[misc]
        point = (float(x), float(y))
    except (TypeError, ValueError):
        raise ScenarioError(name, f"must be a pair of numbers (x, y), got {value!r}") from None
    if isinstance(x, bool) or isinstance(y, bool) or not (math.isfinite(point[0]) and math.isfinite(point[1])):
        raise ScenarioError(name, f"must be a pair of finite numbers, got {value!r}")
    return point


def _freeze(side: Side, name: str, points: object, label: str) -> None:
    """Store a list of points as a tuple of float pairs (checked); ScenarioError naming
    ``label`` otherwise."""
    if points is None:
        return
    if isinstance(points, np.ndarray):
        points = points.tolist()
    if not isinstance(points, (list, tuple)):
        raise ScenarioError(label, f"must be a list of (x, y) pairs, got {points!r}")
    object.__setattr__(side, name, tuple(as_point(p, f"{label}[{i}]") for i, p in enumerate(points)))


def check_side(side: Side, name: str) -> None:
    """The checks of one side that need no configuration."""
    for attr in ("positions", "velocities"):
        _freeze(side, attr, getattr(side, attr), f"{name}.{attr}")
    if side.players is not None:
        if not is_int(side.players) or not 0 <= side.players <= MAX_PLAYERS:
            raise ScenarioError(f"{name}.players", f"must be an integer from 0 to {MAX_PLAYERS}, got {side.players!r}")
    listed = len(side.positions) if side.positions is not None else None
    if listed is not None and listed > MAX_PLAYERS:
        raise ScenarioError(f"{name}.positions", f"lists {listed} players; a side has at most {MAX_PLAYERS}")
    if side.players is not None and listed is not None and listed != side.players:
        raise ScenarioError(f"{name}.positions", f"lists {listed} positions for {side.players} players")
    count = side.players if side.players is not None else listed
    if side.velocities is not None and count is not None and len(side.velocities) != count:
        raise ScenarioError(f"{name}.velocities", f"lists {len(side.velocities)} velocities for {count} players")
    goalie = side.goalie
    if goalie is not None and goalie != CONFIG_GOALIE:
        if not is_int(goalie) or goalie < 0:
            raise ScenarioError(f"{name}.goalie", f"must be a player index, None (no goalkeeper) or 'config', "
                                                  f"got {goalie!r}")
        if count is not None and goalie >= count:
            raise ScenarioError(f"{name}.goalie", f"index {goalie} is beyond the side's {count} players")
    if isinstance(side.jitter, bool) or not isinstance(side.jitter, (int, float)) or not math.isfinite(side.jitter) \
            or side.jitter < 0:
        raise ScenarioError(f"{name}.jitter", f"must be a number >= 0 (m), got {side.jitter!r}")
    if not isinstance(side.relative_to_ball, bool):
        raise ScenarioError(f"{name}.relative_to_ball", f"must be true or false, got {side.relative_to_ball!r}")
    if side.positions is not None:  # offsets from the ball too: equal offsets are the same point
        pts = side.positions
        for i in range(len(pts)):
            for j in range(i + 1, len(pts)):
                if math.dist(pts[i], pts[j]) < _SAME_POINT:
                    raise ScenarioError(f"{name}.positions[{j}]", f"{pts[j]} is the same point as "
                                                                  f"{name}.positions[{i}]")


def side_size(side: Side, config: MatchConfig) -> int:
    if side.players is not None:
        return int(side.players)
    if side.positions is not None:
        return len(side.positions)
    return int(config.players_per_team)


def side_goalie(side: Side, config: MatchConfig, name: str) -> int:
    n = side_size(side, config)
    goalie = side.goalie
    if goalie is None:
        return NO_PLAYER
    if goalie == CONFIG_GOALIE:
        index = config.rules.goalie_index
        return index if index < n else NO_PLAYER
    if goalie >= n:
        raise ScenarioError(f"{name}.goalie", f"index {goalie} is beyond the side's {n} players")
    return int(goalie)
