"""A match recorder that writes an rcssserver game log (``.rcg``, text format version 6).

The file is what rcssserver 19 writes with ``game_log_version 6``: the ``ULG6`` header, the
``(server_param ...)``, ``(player_param ...)`` and 18 ``(player_type ...)`` lines
(:mod:`soccer_sim.rcg.params`), then per cycle ``(playmode CYCLE MODE)`` when the play mode
changes, ``(team CYCLE LEFT RIGHT SCORE_L SCORE_R)`` when the score changes (and at the
start and the end), and one ``(show CYCLE ((b) x y vx vy) ((l 1) TYPE STATE x y vx vy BODY
NECK (v h 120) (fp 0 0) (s STAMINA EFFORT RECOVERY CAPACITY) (c COUNTS...)) ...)`` line, the
state after that cycle (cycle 0: the kick-off position). rcssmonitor, soccerwindow2 and
librcsc's tools replay and analyse it.

What is written how (:mod:`soccer_sim.rcg.mapping` has the frame and the play modes):

- home is the left team, away the right; positions and velocities in rcssserver's frame;
- ``BODY``: soccer-sim's players have no body direction, so the log shows the one
  body-direction model of the simulator, :func:`soccer_sim.body.facing` with the ball
  (at rest: towards the ball; moving: the motion turned towards the ball by at most the
  largest turn at that speed); ``NECK`` 0 (the head looks where the body faces);
- ``TYPE`` 0 (every player is of the default type); ``STATE``: on the field (0x1), goalie
  (0x8), kicked in this cycle (0x2), caught the ball (0x10), the ball bounced off its body
  (0x400);
- stamina, effort, recovery and capacity from the match state (the same units as the
  server's; an unlimited capacity is written -1 as the server's ``stamina_capacity``);
- ``COUNTS`` (kick, dash, turn, catch, move, turn_neck, change_view, say, tackle, pointto,
  attentionto, change_focus): the kicks and catches so far; soccer-sim has no commands for
  the others, so they stay 0.

The recorder writes to ``path`` as the match goes (buffered); it does not make the file
atomic: :func:`experiments.recording.rcg_recording` writes into a temporary file that
replaces the target once the match is over.
"""

from __future__ import annotations

import os
import re
from typing import IO, TYPE_CHECKING

import numpy as np

from soccer_sim.body import DEFAULT_INERTIA_MOMENT
from soccer_sim.errors import SoccerSimError
from soccer_sim.rcg.mapping import (
    BALL_COLLIDE, CATCH, FOCUS_POINT, GOALIE, KICK, STAND, VIEW, play_mode_name, side,
)
from soccer_sim.rcg.bodies import facings
from soccer_sim.rcg.params import player_param_line, player_type_lines, server_param_line
from soccer_sim.state import EventKind, PlayMode

if TYPE_CHECKING:
    from soccer_sim.match import Match

HEADER = "ULG6"
"""The first line of a version 6 game log."""
COUNTERS = 12
"""Numbers in a player's ``(c ...)`` counts (rcssserver 19)."""
_KICK_COUNT, _CATCH_COUNT = 0, 3
_CAUSES = {int(EventKind.OFFSIDE): ("offside", "free_kick"), int(EventKind.BACK_PASS): ("back_pass", "indirect_free_kick")}


class RcgError(SoccerSimError, ValueError):
    """A game log that cannot be written or read; the message names the file."""


def team_name(name: str) -> str:
    """A team name as a game log can hold it: one token without brackets or quotes
    (rcssserver's team names are such tokens); anything else becomes ``_``."""
    cleaned = re.sub(r"[\s()\"]+", "_", name)
    return cleaned or "null"


class RcgRecorder:
    """Write the match into the game log ``path`` (see the module docstring).

    ``inertia_moment``: the players' ``inertia_moment`` for the body-direction model."""

    def __init__(self, path: str | os.PathLike, *, inertia_moment: float = DEFAULT_INERTIA_MOMENT) -> None:
        self.path = os.fspath(path)
        self.inertia_moment = float(inertia_moment)
        self._file: IO[str] | None = None

    # ------------------------------------------------------------------ match loop
    def on_start(self, match: Match) -> None:
        state = match.state
        try:
            self._file = open(self.path, "w", encoding="utf-8", newline="\n")
        except OSError as exc:
            raise RcgError(f"{self.path}: cannot write the game log ({exc.strerror})") from None
        rows = state.pos.shape[0]
        home = state.sizes[0]
        self._labels = [f"(({side(0)} {r + 1}) 0 " if r < home else f"(({side(1)} {r - home + 1}) 0 "
                        for r in range(rows)]
        self._base = np.full(rows, STAND, dtype=np.int64)
        for team, goalie in enumerate(match.goalies):
            if goalie >= 0:
                self._base[state.first_row(team) + goalie] |= GOALIE
        self._counts = np.zeros((rows, COUNTERS), dtype=np.int64)
        self._count_texts = [self._count_text(r) for r in range(rows)]
        self._facing = np.zeros((rows, 2))
        self._table = np.empty((rows, 11), dtype=object)
        self._format = self._show_format()
        self._names = tuple(team_name(name) for name in match.team_names)
        self._mark = len(match.events)
        self._mode = ""
        self._free_kick = "indirect_free_kick"
        self._score = (-1, -1)
        self._team_cycle = -1
        write = self._file.write
        write(HEADER + "\n")
        write(server_param_line(match.config) + "\n")
        write(player_param_line() + "\n")
        for line in player_type_lines(match.config):
            write(line + "\n")
        self._write_cycle(match, self._base, ())

    def on_cycle(self, match: Match) -> None:
        events = match.events
        end = len(events)
        flags = self._base.copy()
        calls: list[str] = []
        for i in range(self._mark, end):
            kind = events.kind[i]
            if kind == EventKind.CATCH:
                row = match.state.first_row(events.team[i]) + events.player[i]
                flags[row] |= CATCH
                self._counts[row, _CATCH_COUNT] += 1
                self._count_texts[row] = self._count_text(row)
            elif kind in _CAUSES:                 # a call shown as a play mode of its own
                call, self._free_kick = _CAUSES[kind]
                calls.append(f"{call}_{side(events.team[i])}")
            elif kind == EventKind.DROP_BALL:
                calls.append("drop_ball")
            elif kind == EventKind.HALF_TIME:      # rcssserver: before_kick_off, then the kick-off
                calls.append("before_kick_off")
            elif kind == EventKind.SET_PLAY and events.detail[i] == PlayMode.FREE_KICK and not calls:
                self._free_kick = "indirect_free_kick"
        self._mark = end
        kickers = match.kickers
        if len(kickers):
            flags[kickers] |= KICK
            self._counts[kickers, _KICK_COUNT] += 1
            for row in kickers.tolist():
                self._count_texts[row] = self._count_text(row)
        touchers = match.touchers
        if len(touchers):
            flags[touchers] |= BALL_COLLIDE
        self._write_cycle(match, flags, calls)

    def on_end(self, match: Match) -> None:
        if self._file is None:
            return
        state = match.state
        if self._team_cycle != state.cycle:           # the final score, as rcssserver ends its logs
            self._write_team(state.cycle, (int(state.score[0]), int(state.score[1])))
        self.close()

    def close(self) -> None:
        """Close the file (also when the match failed part-way)."""
        if self._file is not None:
            self._file.close()
            self._file = None

    # ------------------------------------------------------------------ lines
    def _write_cycle(self, match: Match, flags: np.ndarray, calls: list[str] | tuple[()]) -> None:
        state = match.state
        cycle = state.cycle
        write = self._file.write
        mode = play_mode_name(state.play_mode, state.mode_team, self._free_kick)
        for call in calls:
            write(f"(playmode {cycle} {call})\n")
        if calls or mode != self._mode:
            write(f"(playmode {cycle} {mode})\n")
            self._mode = mode
        score = (int(state.score[0]), int(state.score[1]))
        if score != self._score:
            self._write_team(cycle, score)
        write(self._show(match, flags))

    def _write_team(self, cycle: int, score: tuple[int, int]) -> None:
        self._file.write(f"(team {cycle} {self._names[0]} {self._names[1]} {score[0]} {score[1]})\n")
        self._score, self._team_cycle = score, cycle

    def _count_text(self, row: int) -> str:
        """The ``(c ...)`` part of a player's entry, closing the entry."""
        return "(c " + " ".join(map(str, self._counts[row].tolist())) + "))"

    def _show_format(self) -> str:
        """The %-format of a show line after its cycle and ball: per player its label, then
        the state word, x, y, vx, vy, body, stamina, effort, recovery, capacity, counts."""
        entry = f" %s%s %g %g %g %g %g 0 {VIEW} {FOCUS_POINT} (s %g %g %g %g) %s"
        return "".join(entry.replace("%s%s", label.replace("%", "%%") + "%s", 1) for label in self._labels) + ")\n"

    def _show(self, match: Match, flags: np.ndarray) -> str:
        """The ``(show ...)`` line of the current state (numbers as rcssserver prints them:
        positions to 0.0001, directions to 0.001 degrees, six significant digits)."""
        state = match.state
        s = float(state.home_attacks)
        turn = np.array([s, -s])                      # soccer-sim frame -> rcssserver's
        ball = state.ball
        facings(state.pos, state.vel, ball, self.inertia_moment, self._facing)
        turned = self._facing * turn
        table = self._table
        table[:, 0] = [hex(flag) if flag else "0" for flag in flags.tolist()]
        table[:, 1:3] = np.round(state.pos * turn, 4) + 0.0           # + 0.0: no "-0"
        table[:, 3:5] = np.round(state.vel * turn, 4) + 0.0
        table[:, 5] = np.round(np.degrees(np.arctan2(turned[:, 1], turned[:, 0])), 3) + 0.0
        table[:, 6] = state.stamina
        table[:, 7] = state.effort
        table[:, 8] = state.recovery
        table[:, 9] = np.where(np.isinf(state.capacity), -1.0, state.capacity)  # rcssserver: negative = unlimited
        table[:, 10] = self._count_texts
        b = (np.round(np.concatenate((ball * turn, state.ball_vel * turn)), 4) + 0.0).tolist()
        head = f"(show {state.cycle} ((b) {b[0]:g} {b[1]:g} {b[2]:g} {b[3]:g})"
        return head + self._format % tuple(table.ravel().tolist())
