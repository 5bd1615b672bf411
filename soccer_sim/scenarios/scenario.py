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
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

import numpy as np

from soccer_sim.scenarios.parts import (
    CONFIG_GOALIE,
    END_CONDITIONS,
    MAX_PLAYERS,
    SIDE_NAMES,
    START_MODES,
    BallStart,
    Point,
    ScenarioError,
    Side,
    check_side,
    is_int,
    line_up,
    side_goalie,
    side_size,
)
from soccer_sim.state import AWAY, HOME, NO_PLAYER, SET_PLAYS, PlayMode

if TYPE_CHECKING:
    from soccer_sim.config import MatchConfig

__all__ = ["CONFIG_GOALIE", "END_CONDITIONS", "MAX_PLAYERS", "SIDE_NAMES", "START_MODES", "BallStart", "Point",
           "Scenario", "ScenarioError", "Side", "line_up"]
"""The parts are re-exported: this module is where a scenario's names have always been imported from."""


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
            check_side(side, name)
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
        if self.cycle_limit is not None and not (is_int(self.cycle_limit) and self.cycle_limit > 0):
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
        return side_size(self.home, config), side_size(self.away, config)

    def goalies(self, config: MatchConfig) -> tuple[int, int]:
        """Each side's goalkeeper index within the side, ``NO_PLAYER`` (-1) for none."""
        return side_goalie(self.home, config, "home"), side_goalie(self.away, config, "away")

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
            n = side_size(side, config)
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


# ---------------------------------------------------------------------- helpers
def _other(side: str) -> str:
    return "away" if side == "home" else "home"


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
