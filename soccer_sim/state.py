"""The world state shared by the match loop and the referee, and the play modes.

Frames: the *absolute* frame has the origin at the centre spot, +x towards the
goal on the right. Player rows 0..h-1 are the home team, h..h+a-1 the away
team (h, a = players of each side; h = a = players per team in a full match,
``WorldState.sizes``). ``home_attacks`` tells which way home plays in the
whole match (+1: towards +x; -1 only when a scenario starts it so: the teams keep their ends
at half time, as in rcssserver 19).
Teams never see this frame: :mod:`soccer_sim.view` mirrors it for them.

Units follow :mod:`soccer_sim.config`: metres, cycles, metres per cycle.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import IntEnum
from operator import attrgetter

import numpy as np
from numpy.typing import ArrayLike

from soccer_sim.errors import SoccerSimError

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
    TACKLE = 13
    """A player tackled; ``detail`` 1 when it reached the ball (the ball was pushed), 0 when it
    missed, plus 2 when it was a foul tackle (``TeamCommand.foul``)."""
    FOUL = 14
    """The referee called a foul on ``player`` of ``team`` (the tackler); the fouled team's
    free kick follows (the next SET_PLAY event)."""
    YELLOW_CARD = 15
    """A yellow card for ``player`` of ``team``; ``detail`` is its number of yellow cards."""
    RED_CARD = 16
    """A red card for ``player`` of ``team`` (a second yellow one, or a straight red one): it is
    sent off for the rest of the match."""
    CATCH_FAULT = 17
    """The ball held by ``team``'s goalkeeper (``player``) left its penalty area; the opponents'
    free kick follows (the next SET_PLAY event; rcssserver's ``catch_fault_X``)."""


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


class StateError(SoccerSimError, ValueError):
    """A hand-built :class:`WorldState` given values it cannot hold."""


def _owned(attribute: str, name: str, doc: str) -> property:
    """A :class:`WorldState` array attribute: reads give the owned array; assigning anything
    but the array itself (what ``state.ball += v`` does after adding in place) raises
    AttributeError, so the array can never be replaced."""

    def refuse(state: WorldState, value: object) -> None:
        if value is not getattr(state, attribute):
            raise AttributeError(f"WorldState.{name} cannot be replaced: write into it (state.{name}[...] = values)")

    return property(attrgetter(attribute), refuse, doc=doc)


class WorldState:
    """The mutable state of a match, absolute frame.

    The state owns its arrays: they are created once, with the state, and everything that
    changes the world writes into them in place. They cannot be replaced (assigning
    ``state.pos = other`` raises AttributeError; ``state.ball += v`` adds in place and is
    fine), so every component can keep a reference to them for the whole match and never
    sees a stale copy.

    All bodies live in one (P + 2, 4) float table, rows ``[x, y, vx, vy]``: the P players
    (home first), the ball, and last the field's fixed frame (always at rest: the anchor of
    the goal posts). ``pos``/``vel``/``ball``/``ball_vel`` and :attr:`bodies` are views into
    it; :attr:`body_table` is all of it, so that a collision solver can exchange the whole
    world in one transfer.

    ``sizes``: (home, away) players. Built by hand (tests, tools), the keyword arguments give
    the starting values, copied into the state's own arrays: ``pos``/``vel`` (P, 2),
    ``ball``/``ball_vel`` (2,), ``stamina``/``effort``/``recovery``/``capacity`` (P,),
    ``score`` (2,). Left out, positions and velocities start at zero, stamina at zero, effort
    and recovery at 1 and capacity unlimited (fresh players; a match restores them from its
    configuration before the kick-off). Without ``sizes``, ``pos`` must be given and the rows
    split into two even sides.
    """

    def __init__(self, sizes: tuple[int, int] | None = None, *, pos: ArrayLike | None = None,
                 vel: ArrayLike | None = None, ball: ArrayLike | None = None,
                 ball_vel: ArrayLike | None = None, stamina: ArrayLike | None = None,
                 effort: ArrayLike | None = None, recovery: ArrayLike | None = None,
                 capacity: ArrayLike | None = None, score: ArrayLike | None = None, cycle: int = 0,
                 half: int = 0, home_attacks: int = 1, play_mode: PlayMode = PlayMode.KICK_OFF,
                 mode_team: int = HOME, mode_start: int = 0, ball_holder: int = NO_PLAYER,
                 last_touch: int = NO_PLAYER) -> None:
        if sizes is None:
            if pos is None:
                raise StateError("WorldState needs its sizes (home, away players) or the players' pos")
            half_rows = np.shape(pos)[0] // 2
            sizes = (half_rows, half_rows)
        self.sizes: tuple[int, int] = (int(sizes[0]), int(sizes[1]))
        """(home, away) players: rows ``0..home-1`` are home's, the rest away's."""
        if min(self.sizes) < 0:
            raise StateError(f"WorldState sizes must be non-negative, got {self.sizes}")
        players = self.sizes[0] + self.sizes[1]
        self._allocate(np.zeros((players + 2, 4), dtype=np.float64), np.zeros(players), np.ones(players),
                       np.ones(players), np.full(players, np.inf), np.zeros(2, dtype=np.int64))
        starts = {"pos": pos, "vel": vel, "ball": ball, "ball_vel": ball_vel, "stamina": stamina,
                  "effort": effort, "recovery": recovery, "capacity": capacity, "score": score}
        for name, value in starts.items():
            if value is not None:
                target = getattr(self, name)
                value = np.asarray(value)
                if value.shape != target.shape:
                    raise StateError(f"WorldState.{name} must have shape {target.shape}, got {value.shape}")
                target[...] = value
        self.cycle = cycle
        self.half = half
        """0 for the first half, 1 for the second."""
        self.home_attacks = home_attacks
        """+1 when home attacks towards +x, -1 towards -x (for the whole match: no change of ends)."""
        self.play_mode = play_mode
        self.mode_team = mode_team
        """Team the current set play belongs to (NO_TEAM in play on)."""
        self.mode_start = mode_start
        """Cycle at which the current play mode began."""
        self.ball_holder = ball_holder
        """Player row (0..P-1) of the goalkeeper holding the ball, or NO_PLAYER."""
        self.last_touch = last_touch
        """Player row that last kicked or touched the ball, or NO_PLAYER."""
        self._frozen = np.zeros(players, dtype=np.int64)
        self._cards = np.zeros(players, dtype=np.int64)
        self._present = np.ones(players, dtype=bool)
        self._dashed_before = np.zeros(players, dtype=bool)

    def _allocate(self, table: np.ndarray, stamina: np.ndarray, effort: np.ndarray, recovery: np.ndarray,
                  capacity: np.ndarray, score: np.ndarray) -> None:
        """Take ownership of the arrays and make the views into the body table."""
        players = table.shape[0] - 2
        self._table = table
        self._bodies = table[: players + 1]
        self._pos = table[:players, 0:2]
        self._vel = table[:players, 2:4]
        self._ball = table[players, 0:2]
        self._ball_vel = table[players, 2:4]
        self._stamina, self._effort, self._recovery, self._capacity = stamina, effort, recovery, capacity
        self._score = score

    # --- the owned arrays (write into them; they cannot be replaced) -----------------------
    pos = _owned("_pos", "pos", "(P, 2) player positions (m).")
    vel = _owned("_vel", "vel", "(P, 2) player velocities (m/cycle).")
    ball = _owned("_ball", "ball", "(2,) ball position (m).")
    ball_vel = _owned("_ball_vel", "ball_vel", "(2,) ball velocity (m/cycle).")
    bodies = _owned("_bodies", "bodies", "(P + 1, 4) rows ``[x, y, vx, vy]``: the players, then the ball.")
    body_table = _owned("_table", "body_table",
                        "(P + 2, 4): :attr:`bodies` and the field's fixed frame (a last row always at rest).")
    stamina = _owned("_stamina", "stamina", "(P,) player stamina.")
    effort = _owned("_effort", "effort", "(P,) effort of each player: the fraction of dash power that becomes "
                    "acceleration (see config.StaminaConfig).")
    recovery = _owned("_recovery", "recovery", "(P,) stamina recovery rate of each player (see config.StaminaConfig).")
    capacity = _owned("_capacity", "capacity",
                      "(P,) stamina each player can still recover in this half (inf: unlimited).")
    score = _owned("_score", "score", "(home, away) goals.")
    frozen = _owned("_frozen", "frozen", "(P,) cycles during which each player cannot act after a tackle or being "
                    "fouled: its commands are ignored while the count is above zero (it falls by one every cycle).")
    cards = _owned("_cards", "cards", "(P,) yellow cards of each player (2 once sent off, as rcssserver counts a red "
                   "card).")
    present = _owned("_present", "present", "(P,) False for a player sent off: parked off the pitch, its commands "
                     "ignored.")
    dashed_before = _owned("_dashed_before", "dashed_before",
                           "(P,) whether each player's dash was taken in the previous cycle (rcssserver's "
                           "``dashed()`` stays true for the cycle after a dash; the foul rule reads it).")

    # --- copies and pickling: the views are rebuilt on the copied table --------------------
    def __getstate__(self) -> dict[str, object]:
        views = {"_bodies", "_pos", "_vel", "_ball", "_ball_vel"}
        return {key: value for key, value in self.__dict__.items() if key not in views}

    def __setstate__(self, data: dict[str, object]) -> None:
        self.__dict__.update(data)
        self._allocate(self._table, self._stamina, self._effort, self._recovery, self._capacity, self._score)

    def __repr__(self) -> str:
        return (f"WorldState(sizes={self.sizes}, cycle={self.cycle}, half={self.half}, "
                f"play_mode={self.play_mode!r}, score={self._score.tolist()})")

    # --- derived facts ---------------------------------------------------------------------
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
