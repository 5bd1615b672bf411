"""What a match starts from and when it ends: the :class:`Scenario` description.

A scenario says how many players each side fields (0 to 11, a goalkeeper optional), where
they and the ball start and how fast they move, the play mode play starts in, when the match
ends (a goal, the ball going out, the ball lost to the defending side, a cycle limit), and
whether the referee calls offside and awards set plays. The default ``Scenario()`` is the
regular match: ``config.players_per_team`` a side, the goalkeeper at
``config.rules.goalie_index``, the opening kick-off, two halves; a match played with it is
bit for bit the match played without a scenario.

Frame and units: positions are in the absolute frame at the start (origin at the centre
spot, home attacks +x, so the away goal line is at ``x = +half_length``), metres; velocities
in m/cycle. Randomised elements (a ball drawn in an area, players jittered, players placed
relative to the ball) are drawn from the match seed, so a scenario match stays a pure
function of (teams, config, scenario, seed).

Checks: the constructor refuses what is wrong whatever the field (sizes, indices, names,
duplicate points, end conditions that can never fire); :meth:`Scenario.check` adds what
depends on the match configuration (players and ball on the field, overlapping bodies,
speeds within the limits). Both raise :class:`ScenarioError` naming the field.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np

from soccer_sim.errors import SoccerSimError
from soccer_sim.state import AWAY, HOME, NO_PLAYER, SET_PLAYS, PlayMode

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
        object.__setattr__(self, "position", _point(self.position, "ball.position"))
        object.__setattr__(self, "velocity", _point(self.velocity, "ball.velocity"))
        if self.area is not None:
            if not isinstance(self.area, (list, tuple)) or len(self.area) != 2:
                raise ScenarioError("ball.area", f"must be two corners ((x_min, y_min), (x_max, y_max)), got {self.area!r}")
            low, high = _point(self.area[0], "ball.area[0]"), _point(self.area[1], "ball.area[1]")
            if low[0] > high[0] or low[1] > high[1]:
                raise ScenarioError("ball.area", f"the first corner {low} must be below and left of the second {high}")
            object.__setattr__(self, "area", (low, high))


@dataclass(frozen=True)
class Scenario:
    """A match's sides, start state, end conditions and rules (see the module docstring).

    ``Scenario()`` is the regular full match.
    """

    name: str = "full-match"
    description: str = "11 against 11 from the kick-off, two halves (the regular match)"
    home: Side = field(default_factory=Side)
    away: Side = field(default_factory=Side)
    ball: BallStart = field(default_factory=BallStart)
    start_mode: str = "kick_off"
    """Play mode play starts in (:data:`START_MODES`): a set play is taken where the ball
    starts (a kick-off on the centre spot, the players reflected into their own halves)."""
    start_team: str = "home"
    """Side the starting set play belongs to (``"home"`` or ``"away"``)."""
    end_on: tuple[str, ...] = ()
    """End conditions (:data:`END_CONDITIONS`); the match ends after the cycle in which one
    is met."""
    cycle_limit: int | None = None
    """End after this many cycles (None: the configuration's length)."""
    attacker: str = "home"
    """The side that has the ball's initiative; ``"lost"`` means lost by it to the other side."""
    offside: bool | None = None
    """Call offside (None: as ``config.rules.offside``)."""
    set_plays: bool = True
    """Award set plays; without them every restart (kick-in, corner, goal kick, free kick, the
    kick-off after a goal) becomes a dropped ball where it would be taken, and play goes on."""
    half_time: bool = True
    """Change ends at ``config.rules.half_cycles``; False: one period."""

    def __post_init__(self) -> None:
        for name in ("name", "description"):
            if not isinstance(getattr(self, name), str):
                raise ScenarioError(name, f"must be a string, got {getattr(self, name)!r}")
        for name, side in (("home", self.home), ("away", self.away)):
            if not isinstance(side, Side):
                raise ScenarioError(name, f"must be a Side, got {type(side).__name__}")
            _check_side(side, name)
        if not isinstance(self.ball, BallStart):
            raise ScenarioError("ball", f"must be a BallStart, got {type(self.ball).__name__}")
        for name in ("start_mode", "start_team", "attacker"):
            if not isinstance(getattr(self, name), str):
                raise ScenarioError(name, f"must be a string, got {getattr(self, name)!r}")
        if self.start_mode not in START_MODES:
            raise ScenarioError("start_mode", f"unknown play mode {self.start_mode!r}; expected one of "
                                              f"{', '.join(START_MODES)}")
        for name in ("start_team", "attacker"):
            if getattr(self, name) not in SIDE_NAMES:
                raise ScenarioError(name, f"must be 'home' or 'away', got {getattr(self, name)!r}")
        if isinstance(self.end_on, str):
            object.__setattr__(self, "end_on", (self.end_on,))
        if not isinstance(self.end_on, (tuple, list, frozenset, set)):
            raise ScenarioError("end_on", f"must be a list of end conditions, got {self.end_on!r}")
        ends = tuple(self.end_on)
        for end in ends:
            if end not in END_CONDITIONS:
                raise ScenarioError("end_on", f"unknown end condition {end!r}; expected some of "
                                              f"{', '.join(END_CONDITIONS)} (and cycle_limit)")
        if len(set(ends)) != len(ends):
            raise ScenarioError("end_on", f"lists an end condition twice: {list(ends)}")
        object.__setattr__(self, "end_on", tuple(e for e in END_CONDITIONS if e in ends))
        if self.cycle_limit is not None and not (_is_int(self.cycle_limit) and self.cycle_limit > 0):
            raise ScenarioError("cycle_limit", f"must be None or a positive integer, got {self.cycle_limit!r}")
        if self.offside is not None and not isinstance(self.offside, bool):
            raise ScenarioError("offside", f"must be true, false or None, got {self.offside!r}")
        for name in ("set_plays", "half_time"):
            if not isinstance(getattr(self, name), bool):
                raise ScenarioError(name, f"must be true or false, got {getattr(self, name)!r}")
        if not self.set_plays and START_MODES[self.start_mode] in SET_PLAYS:
            raise ScenarioError("start_mode", f"{self.start_mode!r} is a set play, but set_plays is false; "
                                              "start with 'play_on' or allow set plays")
        self._check_end_conditions()

    # ------------------------------------------------------------------ derived values
    @property
    def is_regular(self) -> bool:
        """True for the regular full match (the default scenario, whatever its name)."""
        return _without_names(self) == _without_names(Scenario())

    def sizes(self, config: MatchConfig) -> tuple[int, int]:
        """(home, away) players in a match with ``config``."""
        return _side_size(self.home, config), _side_size(self.away, config)

    def goalies(self, config: MatchConfig) -> tuple[int, int]:
        """Each side's goalkeeper index within the side, ``NO_PLAYER`` (-1) for none."""
        return _side_goalie(self.home, config, "home"), _side_goalie(self.away, config, "away")

    @property
    def start_play_mode(self) -> PlayMode:
        return START_MODES[self.start_mode]

    @property
    def start_side(self) -> int:
        return SIDE_NAMES[self.start_team]

    @property
    def attacking_side(self) -> int:
        return SIDE_NAMES[self.attacker]

    @property
    def randomised(self) -> bool:
        """Whether the start state draws random numbers (a ball area or a jitter)."""
        return self.ball.area is not None or self.home.jitter > 0 or self.away.jitter > 0

    # ------------------------------------------------------------------ checks
    def _check_end_conditions(self) -> None:
        """Refuse an end condition that can never be met when no cycle limit bounds the match."""
        if self.cycle_limit is not None:
            return
        counts = [s.players if s.players is not None else (len(s.positions) if s.positions is not None else None)
                  for s in (self.home, self.away)]
        defender = counts[1 - self.attacking_side]
        if "lost" in self.end_on and defender == 0:
            raise ScenarioError("end_on", f"'lost' can never happen: the defending side ({_other(self.attacker)}) "
                                          "has no players; give a cycle_limit or drop it")
        nobody = counts[0] == 0 and counts[1] == 0
        ball_still = self.ball.velocity == (0.0, 0.0)
        for end in ("goal", "scored", "out"):
            if end in self.end_on and nobody and ball_still:
                raise ScenarioError("end_on", f"{end!r} can never happen: no players and a ball at rest; give a "
                                              "cycle_limit or a ball velocity")

    def check(self, config: MatchConfig) -> None:
        """Refuse what does not fit ``config``: a side larger than the other limits allow, a
        goalkeeper index beyond its side, players or ball off the field, two overlapping
        players, speeds above the limits. ScenarioError naming the field."""
        f, phys = config.field, config.physics
        self.goalies(config)
        for name, side in (("home", self.home), ("away", self.away)):
            n = _side_size(side, config)
            if side.positions is None and side.relative_to_ball:
                raise ScenarioError(f"{name}.relative_to_ball", "needs positions (offsets from the ball)")
            if side.velocities is not None and len(side.velocities) != n:
                raise ScenarioError(f"{name}.velocities", f"lists {len(side.velocities)} velocities for {n} players")
            for i, (vx, vy) in enumerate(side.velocities or ()):
                if math.hypot(vx, vy) > phys.player_speed_max + 1e-9:
                    raise ScenarioError(f"{name}.velocities[{i}]", f"({vx}, {vy}) is faster than the player speed "
                                                                   f"limit {phys.player_speed_max} m/cycle")
            if side.positions is not None and not side.relative_to_ball:
                for i, (x, y) in enumerate(side.positions):
                    if abs(x) > f.half_length or abs(y) > f.half_width:
                        raise ScenarioError(f"{name}.positions[{i}]", f"({x}, {y}) is outside the field (|x| <= "
                                                                      f"{f.half_length}, |y| <= {f.half_width})")
        area = self.ball.area
        corners = area if area is not None else (self.ball.position,)
        for i, (x, y) in enumerate(corners):
            where = "ball.position" if area is None else f"ball.area[{i}]"
            if abs(x) > f.half_length or abs(y) > f.half_width:
                raise ScenarioError(where, f"({x}, {y}) is outside the field (|x| <= {f.half_length}, "
                                           f"|y| <= {f.half_width})")
        vx, vy = self.ball.velocity
        if math.hypot(vx, vy) > phys.ball_speed_max + 1e-9:
            raise ScenarioError("ball.velocity", f"({vx}, {vy}) is faster than the ball speed limit "
                                                 f"{phys.ball_speed_max} m/cycle")
        diameter = 2.0 * phys.player_radius
        if not self.randomised:
            _check_apart(self.start_state(config)[0], self.sizes(config), diameter)
        else:
            self._check_apart_before_draws(config, diameter)

    def _check_apart_before_draws(self, config: MatchConfig, diameter: float) -> None:
        """A randomised start: the players must not overlap before the draws move them (no
        jitter; with a drawn ball, the players placed relative to it are compared among
        themselves by their offsets, and the others among themselves)."""
        from dataclasses import replace

        steady = replace(self, home=replace(self.home, jitter=0.0), away=replace(self.away, jitter=0.0))
        sizes = self.sizes(config)
        if self.ball.area is None:
            _check_apart(steady.start_state(config)[0], sizes, diameter)
            return
        fixed_ball = replace(steady, ball=BallStart(position=self.ball.area[0], velocity=self.ball.velocity))
        pos = fixed_ball.start_state(config)[0]
        relative = np.zeros(len(pos), dtype=bool)
        for team, side in enumerate((self.home, self.away)):
            if side.relative_to_ball and sizes[team]:
                rows = slice(0, sizes[0]) if team == 0 else slice(sizes[0], sizes[0] + sizes[1])
                pos[rows] = np.array(side.positions, dtype=float).reshape(-1, 2)  # the offsets, unclipped
                relative[rows] = True
        for group in (relative, ~relative):
            _check_apart(pos, sizes, diameter, rows=np.flatnonzero(group))

    # ------------------------------------------------------------------ the start state
    def start_state(self, config: MatchConfig, rng: np.random.Generator | None = None
                    ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """The start state for ``config``: (positions (P, 2), velocities (P, 2), ball (2,),
        ball velocity (2,)), absolute frame, home rows first. ``rng`` draws the randomised
        elements (needed when :attr:`randomised`). Drawn positions are kept on the field."""
        f = config.field
        if self.randomised and rng is None:
            raise ValueError(f"scenario {self.name!r} draws its start state: give a random generator")
        if self.ball.area is not None:
            (x0, y0), (x1, y1) = self.ball.area
            ball = np.array([rng.uniform(x0, x1), rng.uniform(y0, y1)])
        else:
            ball = np.array(self.ball.position, dtype=float)
        sizes = self.sizes(config)
        goalies = self.goalies(config)
        blocks, speeds = [], []
        for team, side in ((HOME, self.home), (AWAY, self.away)):
            n = sizes[team]
            if side.positions is None:
                block = line_up(n, goalies[team], f.half_length, f.half_width)
                if team == AWAY:
                    block = -block
            else:
                block = np.array(side.positions, dtype=float).reshape(n, 2)
                if side.relative_to_ball:
                    block = block + ball
            if side.jitter > 0 and n:
                shift = rng.uniform(-side.jitter, side.jitter, (n, 2))
                if goalies[team] != NO_PLAYER:
                    shift[goalies[team]] = 0.0
                block = block + shift
            if side.jitter > 0 or side.relative_to_ball:
                np.clip(block[:, 0], -f.half_length, f.half_length, out=block[:, 0])
                np.clip(block[:, 1], -f.half_width, f.half_width, out=block[:, 1])
            blocks.append(block)
            speeds.append(np.zeros((n, 2)) if side.velocities is None
                          else np.array(side.velocities, dtype=float).reshape(n, 2))
        return (np.concatenate(blocks).reshape(-1, 2), np.concatenate(speeds).reshape(-1, 2), ball,
                np.array(self.ball.velocity, dtype=float))


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
def _is_int(value: object) -> bool:
    return isinstance(value, (int, np.integer)) and not isinstance(value, bool)


def _other(side: str) -> str:
    return "away" if side == "home" else "home"


def _point(value: object, name: str) -> Point:
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
    object.__setattr__(side, name, tuple(_point(p, f"{label}[{i}]") for i, p in enumerate(points)))


def _check_side(side: Side, name: str) -> None:
    """The checks of one side that need no configuration."""
    for attr in ("positions", "velocities"):
        _freeze(side, attr, getattr(side, attr), f"{name}.{attr}")
    if side.players is not None:
        if not _is_int(side.players) or not 0 <= side.players <= MAX_PLAYERS:
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
        if not _is_int(goalie) or goalie < 0:
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


def _side_size(side: Side, config: MatchConfig) -> int:
    if side.players is not None:
        return int(side.players)
    if side.positions is not None:
        return len(side.positions)
    return int(config.players_per_team)


def _side_goalie(side: Side, config: MatchConfig, name: str) -> int:
    n = _side_size(side, config)
    goalie = side.goalie
    if goalie is None:
        return NO_PLAYER
    if goalie == CONFIG_GOALIE:
        index = config.rules.goalie_index
        return index if index < n else NO_PLAYER
    if goalie >= n:
        raise ScenarioError(f"{name}.goalie", f"index {goalie} is beyond the side's {n} players")
    return int(goalie)


def _check_apart(pos: np.ndarray, sizes: tuple[int, int], diameter: float,
                 rows: np.ndarray | None = None) -> None:
    """Two players' bodies must not overlap at the start (among ``rows`` of ``pos``, default
    all)."""
    names = [("home", i) for i in range(sizes[0])] + [("away", i) for i in range(sizes[1])]
    if rows is not None:
        pos, names = pos[rows], [names[r] for r in rows]
    for a in range(len(pos)):
        d = np.hypot(*(pos[a + 1:] - pos[a]).T)
        close = np.flatnonzero(d < diameter - 1e-9)
        if close.size:
            b = a + 1 + int(close[0])
            (sa, ia), (sb, ib) = names[a], names[b]
            raise ScenarioError(f"{sb}.positions[{ib}]",
                                f"{tuple(pos[b].tolist())} overlaps {sa} player {ia} at {tuple(pos[a].tolist())} "
                                f"(centres closer than a body's diameter, {diameter} m)")


def _without_names(scenario: Scenario) -> tuple:
    return tuple(getattr(scenario, f) for f in scenario.__dataclass_fields__ if f not in ("name", "description"))
