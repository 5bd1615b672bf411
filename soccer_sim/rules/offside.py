"""Offside (rcssserver's ``OffsideRef``): positions marked when a team plays the ball, and
the free kick when a marked player plays it.

A team-mate of the player on the ball is in an offside position when its centre is
(strictly) in the opponents' half, nearer the opponents' goal line than the ball and nearer
than the second-last opponent. Being level with the ball or with the second-last opponent is
not offside. Positions are judged whenever one team plays the ball: a kick in play on, at a
free kick, at a kick-off or by a goalkeeper releasing a held ball, and a body touch in play
on (a deflection off a team-mate counts as playing it, and a kicker's own touch in the cycle
of its kick re-judges the positions rather than clearing them). Kicks from kick-ins, corners
and goal kicks, and cycles in which both teams play the ball, clear all marks instead; so do
a catch, a dropped ball, any restart and time over. A marked player is penalised when it
plays the ball (kick or body touch); with ``offside_active_distance`` set, also when it ends
a play-on cycle that close to the ball. The free kick is taken on the offside line as it was
when the ball was played, level with the offender.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
from numba import njit

from soccer_sim.rules.judge import Judge
from soccer_sim.rules.play_modes import PlayModes
from soccer_sim.state import AWAY, HOME, EventKind, PlayMode, WorldState

_OFFSIDE_MODES = frozenset({PlayMode.PLAY_ON, PlayMode.FREE_KICK, PlayMode.KICK_OFF, PlayMode.GOALIE_HOLDS})
"""Modes in which a kick can put team-mates offside (not kick-ins, corners, goal kicks)."""


def mark_offside_positions(pos: np.ndarray, n: int | tuple[int, int], team: int, direction: int, ball_x: float,
                           kickers: Sequence[int] | np.ndarray, out: np.ndarray,
                           present: np.ndarray | None = None) -> float | None:
    """Write into ``out`` ((P,) bool) which players of ``team`` are in an offside position.

    ``pos`` is the (P, 2) absolute player positions (home rows first), ``n`` the players per
    side (an int for two even sides, or (home, away)), ``direction`` the kicking team's attack
    direction (+1 towards +x), ``ball_x`` the ball's x when kicked and ``kickers`` the rows
    that kicked (never marked). ``present`` ((P,) bool, optional): players sent off count
    neither as opponents nor as marked players. With fewer than two opponents there is no
    second-last opponent; the opponents' goal line takes its place, so nobody is offside.
    Returns the offside line's x (absolute frame) if any player was marked, else None.
    """
    home, away = (n, n) if isinstance(n, (int, np.integer)) else n
    total = home + away
    own = slice(0, home) if team == 0 else slice(home, total)
    opp = slice(home, total) if team == 0 else slice(0, home)
    opp_x = pos[opp, 0]
    if present is not None:
        opp_x = opp_x[present[opp]]
    # In the kicking team's direction of attack (depth = direction * x).
    line = offside_line(direction * opp_x, direction * ball_x)
    out[:] = False
    marks = out[own]
    np.greater(pos[own, 0] * direction, line, out=marks)
    out[kickers] = False
    if present is not None:
        out &= present
    return direction * line if np.count_nonzero(marks) > 0 else None


@njit(cache=True, nogil=True)
def offside_line(opp_x: np.ndarray, ball_x: float) -> float:  # pragma: no cover - compiled
    """The offside line's x for a team attacking towards +x (the team frame; the referee passes
    depths, ``direction * x``): the halfway line, the ball or the second-last opponent,
    whichever is deepest (duplicates count: two opponents level are last and second-last).
    With fewer than two opponents in ``opp_x`` there is no second-last opponent and the line
    is +inf: nobody is offside. The one definition of the line, for the referee and for every
    team that keeps its players onside."""
    last = second = -math.inf
    for i in range(opp_x.shape[0]):
        x = opp_x[i]
        if x > last:
            last, second = x, last
        elif x > second:
            second = x
    if opp_x.shape[0] < 2:
        return math.inf
    line = 0.0
    if ball_x > line:
        line = ball_x
    if second > line:
        line = second
    return line


class OffsideJudge(Judge):
    """rcssserver's ``OffsideRef``: marks offside positions when one team plays the ball and
    calls offside when a marked player plays it (or, with ``offside_active_distance``, comes
    that close to it). Present only with ``RuleConfig.offside``."""

    name = "offside"

    def __init__(self, modes: PlayModes) -> None:
        self.modes = modes
        reach = modes.config.rules.offside_active_distance
        self._reach2 = None if reach is None else reach ** 2
        self._marks = np.zeros(sum(modes.sizes), dtype=bool)
        self._pending = False
        """Whether any player is marked."""
        self._rows = np.zeros(0, dtype=np.int64)
        """Rows of ``_marks`` that are marked (while ``_pending``)."""
        self._line = 0.0
        """x of the offside line (absolute frame) when the current marks were made."""

    def kick_taken(self, state: WorldState, rows: list[int], mode: PlayMode, x: float, y: float) -> bool:
        return self._played(state, rows, mode, x)

    def ball_touched(self, state: WorldState, rows: list[int], x: float, y: float) -> bool:
        return self._played(state, rows, PlayMode.PLAY_ON, x)

    def ball_caught(self, state: WorldState, row: int, x: float, y: float) -> None:
        self._clear()

    def analyse(self, state: WorldState, x: float, y: float) -> bool:
        """A marked player within ``offside_active_distance`` of the ball is penalised (the
        nearest, if several are); play goes on being analysed (the later judges see the new
        play mode)."""
        if self._pending and self._reach2 is not None:
            rows = self._rows
            diff = state.pos[rows] - state.ball
            d2 = (diff * diff).sum(axis=1)
            nearest = int(d2.argmin())
            if d2[nearest] <= self._reach2:
                self._call(state, int(rows[nearest]))
        return False

    def play_mode_change(self, state: WorldState, mode: PlayMode) -> None:
        if mode == PlayMode.TIME_OVER:
            self._clear()

    def ball_placed(self, state: WorldState, x: float, y: float) -> None:
        self._clear()

    def ball_dropped(self, state: WorldState, x: float, y: float) -> None:
        self._clear()

    def _played(self, state: WorldState, rows: list[int], mode: PlayMode, ball_x: float) -> bool:
        """``rows`` played the ball in ``mode``: a marked one is penalised (True: play stopped);
        else, when they are of one team and the mode allows offside, their team-mates in
        offside positions are marked afresh; otherwise all marks are cleared."""
        if self._pending:
            marks = self._marks
            for row in rows:
                if marks[row]:
                    self._call(state, row)
                    return True
        n = self.modes.n
        team = HOME if rows[0] < n else AWAY
        if (rows[-1] < n) == (team == HOME) and mode in _OFFSIDE_MODES:
            present = None if state.present.all() else state.present
            line = mark_offside_positions(state.pos, self.modes.sizes, team, state.attack_direction(team), ball_x,
                                          rows, self._marks, present)
            self._pending = line is not None
            if line is not None:
                self._rows = np.flatnonzero(self._marks)
                self._line = line
        else:
            self._clear()
        return False

    def _clear(self) -> None:
        if self._pending:
            self._marks[:] = False
            self._pending = False

    def _call(self, state: WorldState, row: int) -> None:
        """OFFSIDE event (at the offender's position) and an indirect free kick for the
        defenders on the offside line, level with the offender."""
        n = self.modes.n
        team = HOME if row < n else AWAY
        f = self.modes.config.field
        x = min(max(float(state.pos[row, 0]), -f.half_length), f.half_length)
        y = min(max(float(state.pos[row, 1]), -f.half_width), f.half_width)
        self.modes.events.add(state.cycle, EventKind.OFFSIDE, team, row - team * n, x, y, 0)
        self.modes.restart(state, PlayMode.FREE_KICK, 1 - team, self._line, y)
