"""The world state shared by the match loop and the referee, and the play modes.

Frames: the *absolute* frame has the origin at the centre spot, +x towards the
goal on the right. Player rows 0..h-1 are the home team, h..h+a-1 the away
team (h, a = players of each side; h = a = players per team in a full match,
``WorldState.sizes``). ``home_attacks`` tells which way home plays in the
current half (+1: towards +x, the first half; -1 after the half-time swap).
Teams never see this frame: :mod:`soccer_sim.view` mirrors it for them.

Units follow :mod:`soccer_sim.config`: metres, cycles, metres per cycle.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import IntEnum

import numpy as np

HOME, AWAY = 0, 1
"""Team indices: home is listed first everywhere (score, statistics, player rows)."""
NO_TEAM = -1
NO_PLAYER = -1


class PlayMode(IntEnum):
    """What the referee currently allows. Set plays belong to ``WorldState.mode_team``."""

    PLAY_ON = 0
    KICK_OFF = 1
    """Ball on the centre spot; only the kicking team may touch it; both teams stay in their own half."""
    KICK_IN = 2
    """Ball left over a touchline; taken where it left."""
    CORNER_KICK = 3
    GOAL_KICK = 4
    FREE_KICK = 5
    """Indirect free kick (after offside, or a goalkeeper holding the ball too long)."""
    GOALIE_HOLDS = 6
    """The mode team's goalkeeper holds the ball and must kick it away in time."""
    TIME_OVER = 7
    AFTER_GOAL = 8
    """The pause between a goal and the kick-off (``RuleConfig.goal_pause_cycles``): nobody may
    kick; ``mode_team`` is the team that will kick off; teams may place their players with
    ``TeamCommand.move`` (into their own half)."""


SET_PLAYS = frozenset({PlayMode.KICK_OFF, PlayMode.KICK_IN, PlayMode.CORNER_KICK, PlayMode.GOAL_KICK, PlayMode.FREE_KICK})
"""Modes in which the ball lies still until the mode team kicks it and opponents keep their distance."""


class EventKind(IntEnum):
    """Kinds of things that happen in a match, as recorded in :class:`EventLog`."""

    KICK = 0
    PASS = 1
    """A pass received: the ball went from one player to a teammate with no opponent touch between."""
    SHOT = 2
    """A kick whose path, if unhindered, would cross the opponents' goal line between the posts."""
    GOAL = 3
    CATCH = 4
    OUT = 5
    """The ball left the field; the following SET_PLAY event says how play restarts."""
    SET_PLAY = 6
    """A play mode began; ``detail`` holds the PlayMode value."""
    OFFSIDE = 7
    DROP_BALL = 8
    """A set play timed out and the ball was dropped (play on, ball still)."""
    HALF_TIME = 9
    TIME_OVER = 10
    TOUCH = 11
    """The ball bounced off a player's body (not a kick)."""
    BACK_PASS = 12
    """A goalkeeper tried to catch a ball kicked to it by a team-mate; the opponents get an
    indirect free kick (the following SET_PLAY event)."""


@dataclass
class EventLog:
    """Append-only record of match events, stored column-wise (one Python list per field).

    ``team`` is HOME/AWAY or NO_TEAM; ``player`` is the index within the team (0-based,
    shirt number minus one) or NO_PLAYER; (x, y) is where it happened, absolute frame;
    ``detail`` is kind-specific (the PlayMode for SET_PLAY, the receiver for PASS, ...).
    """

    cycle: list[int] = field(default_factory=list)
    kind: list[int] = field(default_factory=list)
    team: list[int] = field(default_factory=list)
    player: list[int] = field(default_factory=list)
    x: list[float] = field(default_factory=list)
    y: list[float] = field(default_factory=list)
    detail: list[int] = field(default_factory=list)

    def add(self, cycle: int, kind: EventKind, team: int = NO_TEAM, player: int = NO_PLAYER,
            x: float = float("nan"), y: float = float("nan"), detail: int = 0) -> None:
        self.cycle.append(int(cycle))
        self.kind.append(int(kind))
        self.team.append(int(team))
        self.player.append(int(player))
        self.x.append(float(x))
        self.y.append(float(y))
        self.detail.append(int(detail))

    def __len__(self) -> int:
        return len(self.cycle)

    def as_arrays(self) -> dict[str, np.ndarray]:
        """The log as a dict of equal-length numpy arrays (for statistics and comparisons)."""
        return {
            "cycle": np.asarray(self.cycle, dtype=np.int64),
            "kind": np.asarray(self.kind, dtype=np.int64),
            "team": np.asarray(self.team, dtype=np.int64),
            "player": np.asarray(self.player, dtype=np.int64),
            "x": np.asarray(self.x, dtype=np.float64),
            "y": np.asarray(self.y, dtype=np.float64),
            "detail": np.asarray(self.detail, dtype=np.int64),
        }

    def of_kind(self, kind: EventKind) -> list[tuple[int, int, int, float, float, int]]:
        """All events of one kind as (cycle, team, player, x, y, detail) tuples."""
        k = int(kind)
        return [
            (self.cycle[i], self.team[i], self.player[i], self.x[i], self.y[i], self.detail[i])
            for i in range(len(self.cycle)) if self.kind[i] == k
        ]


@dataclass
class WorldState:
    """The mutable state of a match, absolute frame. Arrays are updated in place by the loop."""

    pos: np.ndarray
    """(2n, 2) player positions (m)."""
    vel: np.ndarray
    """(2n, 2) player velocities (m/cycle)."""
    stamina: np.ndarray
    """(2n,) player stamina."""
    ball: np.ndarray
    """(2,) ball position (m)."""
    ball_vel: np.ndarray
    """(2,) ball velocity (m/cycle)."""
    score: np.ndarray = field(default_factory=lambda: np.zeros(2, dtype=np.int64))
    """(home, away) goals."""
    cycle: int = 0
    half: int = 0
    """0 for the first half, 1 for the second."""
    home_attacks: int = 1
    """+1 when home attacks towards +x (first half), -1 after the half-time swap."""
    play_mode: PlayMode = PlayMode.KICK_OFF
    mode_team: int = HOME
    """Team the current set play belongs to (NO_TEAM in play on)."""
    mode_start: int = 0
    """Cycle at which the current play mode began."""
    ball_holder: int = NO_PLAYER
    """Player row (0..2n-1) of the goalkeeper holding the ball, or NO_PLAYER."""
    last_touch: int = NO_PLAYER
    """Player row that last kicked or touched the ball, or NO_PLAYER."""
    effort: np.ndarray | None = None
    """(2n,) effort of each player: the fraction of dash power that becomes acceleration
    (see config.StaminaConfig); None in hand-built states that do not need it."""
    recovery: np.ndarray | None = None
    """(2n,) stamina recovery rate of each player (see config.StaminaConfig)."""
    capacity: np.ndarray | None = None
    """(2n,) stamina each player can still recover in this half (inf: unlimited)."""
    sizes: tuple[int, int] | None = None
    """(home, away) players: rows ``0..home-1`` are home's, the rest away's. None (a state built
    by hand) means two even sides, half the rows each."""

    def __post_init__(self) -> None:
        if self.sizes is None:
            half = self.pos.shape[0] // 2
            self.sizes = (half, half)
        else:
            self.sizes = (int(self.sizes[0]), int(self.sizes[1]))

    @property
    def players_per_team(self) -> int:
        """Players per side when both sides are the same size; a ValueError for uneven sides
        (use :attr:`sizes`)."""
        home, away = self.sizes
        if home != away:
            raise ValueError(f"the sides are uneven ({home} home, {away} away players): use WorldState.sizes")
        return home

    def attack_direction(self, team: int) -> int:
        """+1 if ``team`` attacks towards +x in the current half, else -1."""
        return self.home_attacks if team == HOME else -self.home_attacks

    def team_of(self, row: int) -> int:
        """Team (HOME/AWAY) of player row ``row``."""
        return HOME if row < self.sizes[0] else AWAY

    def first_row(self, team: int) -> int:
        """Row of ``team``'s first player (its player ``i`` is row ``first_row(team) + i``)."""
        return 0 if team == HOME else self.sizes[0]
