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
  largest turn at that speed); ``NECK`` the player's neck angle (degrees, relative to the
  body: ``TeamCommand.turn_neck`` under partial observation; 0 under full observation);
- ``TYPE`` 0 (every player is of the default type); ``STATE``: on the field (0x1), goalie
  (0x8), kicked in this cycle (0x2), caught the ball (0x10), the ball bounced off its body
  (0x400), and the tackle, foul-charge and card flags (:mod:`soccer_sim.rcg.marks`);
- every side lists 11 players, as rcssserver's show lines do: a shirt number the scenario
  does not field is a disabled player (state 0) and a player sent off shows the server's
  DISCARD and RED_CARD flags (0x80100); both stand where the server parks absent players
  (:func:`soccer_sim.rcg.mapping.parking_spot`), still, facing 0;
- stamina, effort, recovery and capacity from the match state (the same units as the
  server's; an unlimited capacity is written -1 as the server's ``stamina_capacity``);
- ``COUNTS`` (kick, dash, turn, catch, move, turn_neck, change_view, say, tackle, pointto,
  attentionto, change_focus): the kicks, catches and tackles so far; soccer-sim has no
  commands for the others, so they stay 0;
- a foul is rcssserver's ``foul_charge_X`` of the fouling side, followed at once by the
  fouled side's ``free_kick_Y`` (``indirect_free_kick_Y`` when the ball lies in the fouling
  side's penalty area, as the server decides), where the server waits 30 cycles between them;
- at the end the server's result message, ``(msg CYCLE 1 "(result STAMP LEFT_SL-vs-RIGHT_SR)")``
  (``STAMP``: the match's start as local ``%Y%m%d%H%M``), then the final ``(team ...)`` line.

The recorder writes to ``path`` as the match goes (buffered); it does not make the file
atomic: :func:`experiments.recording.rcg_recording` writes into a temporary file that
replaces the target once the match is over.
"""

from __future__ import annotations

import os
import re
import time
from typing import IO, TYPE_CHECKING

import numpy as np

from soccer_sim.errors import SoccerSimError
from soccer_sim.rcg.mapping import (
    BALL_COLLIDE, CATCH, DISCARD, FOCUS_POINT, GOALIE, KICK, MAX_PLAYER, RED_CARD, SIDES, STAND, VIEW,
    parking_spot, play_mode_name, side,
)
from soccer_sim.rcg.bodies import facings
from soccer_sim.rcg.marks import TACKLE_COUNT, Marks
from soccer_sim.rcg.params import (
    SERVER_PARAMETERS, number, player_param_line, player_type_lines, server_param_line,
)
from soccer_sim.state import EventKind, PlayMode

if TYPE_CHECKING:
    from soccer_sim.match import Match

HEADER = "ULG6"
"""The first line of a version 6 game log."""
COUNTERS = 12
"""Numbers in a player's ``(c ...)`` counts (rcssserver 19)."""
_KICK_COUNT, _CATCH_COUNT = 0, 3
MSG_BOARD = 1
"""The board number of rcssserver's ``(msg ...)`` lines that carry the result."""
DISABLED_VIEW = "(v h 90)"
"""The view a player that never connected shows (rcssserver's default ``visible_angle``)."""
_CAUSES = {int(EventKind.OFFSIDE): ("offside", "free_kick"), int(EventKind.BACK_PASS): ("back_pass", "indirect_free_kick"),
           int(EventKind.CATCH_FAULT): ("catch_fault", "free_kick")}


class RcgError(SoccerSimError, ValueError):
    """A game log that cannot be written or read; the message names the file."""


def team_name(name: str) -> str:
    """A team name as a game log can hold it: one token without brackets or quotes
    (rcssserver's team names are such tokens); anything else becomes ``_``."""
    cleaned = re.sub(r"[\s()\"]+", "_", name)
    return cleaned or "null"


class RcgRecorder:
    """Write the match into the game log ``path`` (see the module docstring).

    Bodies face as the body-direction model says (:mod:`soccer_sim.body`, with the match's
    ``PhysicsConfig.inertia_moment``). ``started``: the match's start (seconds since the epoch) for the result message; the
    time :meth:`on_start` is called when None."""

    def __init__(self, path: str | os.PathLike, *, started: float | None = None) -> None:
        self.path = os.fspath(path)
        self.inertia_moment = 0.0
        """The players' ``inertia_moment`` (set from the match's configuration at the start)."""
        self.started = started
        self._file: IO[str] | None = None

    # ------------------------------------------------------------------ match loop
    def on_start(self, match: Match) -> None:
        state = match.state
        try:
            self._file = open(self.path, "w", encoding="utf-8", newline="\n")
        except OSError as exc:
            raise RcgError(f"{self.path}: cannot write the game log ({exc.strerror})") from None
        self._started = time.time() if self.started is None else self.started
        rows = state.pos.shape[0]
        home = state.sizes[0]
        type_ids = getattr(match, "type_ids", np.zeros(rows, dtype=np.intp))
        self._labels = ["((%s %d) %d " % (*self._slot(r, home), type_ids[r]) for r in range(rows)]
        self._half_width = match.config.field.half_width
        self._parked = np.array([parking_spot(*self._slot(r, home), self._half_width) for r in range(rows)])
        self.inertia_moment = match.config.physics.inertia_moment
        self._marks = Marks(rows, match.config.tackles, self.inertia_moment)
        self._base = np.full(rows, STAND, dtype=np.int64)
        for team, goalie in enumerate(match.goalies):
            if goalie >= 0:
                self._base[state.first_row(team) + goalie] |= GOALIE
        self._counts = np.zeros((rows, COUNTERS), dtype=np.int64)
        self._count_texts = [self._count_text(r) for r in range(rows)]
        self._facing = np.zeros((rows, 2))
        self._table = np.empty((rows, 12), dtype=object)
        self._format = self._show_format(match)
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
        for line in player_type_lines(match.config, getattr(match, "player_types", None)):
            write(line + "\n")
        self._write_cycle(match, self._base, ())
        self._marks.remember(state)

    def on_cycle(self, match: Match) -> None:
        events = match.events
        end = len(events)
        flags = self._base.copy()
        calls: list[str] = []
        tackles: list[tuple[int, int]] = []
        state = match.state
        for i in range(self._mark, end):
            kind = events.kind[i]
            if kind == EventKind.TACKLE:
                row = state.first_row(events.team[i]) + events.player[i]
                tackles.append((row, int(events.detail[i])))
                self._counts[row, TACKLE_COUNT] += 1
                self._count_texts[row] = self._count_text(row)
            elif kind == EventKind.FOUL:             # foul_charge_X, then the fouled side's free kick
                calls.append(f"foul_charge_{side(events.team[i])}")
                self._free_kick = "indirect_free_kick" if self._in_own_penalty_area(match, events.team[i]) \
                    else "free_kick"
            elif kind == EventKind.YELLOW_CARD:
                self._marks.cards = True
            elif kind == EventKind.CATCH:
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
        self._marks.mark(state, flags, tackles)
        self._write_cycle(match, flags, calls)
        self._marks.remember(state)

    def on_end(self, match: Match) -> None:
        if self._file is None:
            return
        state = match.state
        score = (int(state.score[0]), int(state.score[1]))
        stamp = time.strftime("%Y%m%d%H%M", time.localtime(self._started))
        result = "-vs-".join(f"{name}_{goals}" for name, goals in zip(self._names, score))
        self._file.write(f'(msg {state.cycle} {MSG_BOARD} "(result {stamp} {result})")\n')
        if self._team_cycle != state.cycle:           # the final score, as rcssserver ends its logs
            self._write_team(state.cycle, score)
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

    @staticmethod
    def _slot(row: int, home: int) -> tuple[str, int]:
        """(side letter, shirt number) of a player row."""
        return (SIDES[0], row + 1) if row < home else (SIDES[1], row - home + 1)

    def _in_own_penalty_area(self, match: Match, team: int) -> bool:
        """Whether the ball lies (partly) in ``team``'s own penalty area (rcssserver's
        ``Referee::inPenaltyArea``, which widens the area by the ball's size)."""
        state, f = match.state, match.config.field
        ball_size = match.config.physics.ball_radius
        x = -state.attack_direction(team) * float(state.ball[0])
        return (x >= f.half_length - f.penalty_area_length - ball_size and x <= f.half_length + ball_size
                and abs(float(state.ball[1])) <= f.penalty_area_width / 2.0 + ball_size)

    def _show_format(self, match: Match) -> str:
        """The %-format of a show line after its cycle and ball: per player row its label,
        then the state word, x, y, vx, vy, body, neck, stamina, effort, recovery, capacity, counts;
        the disabled players of shirt numbers the scenario does not field as fixed text."""
        entry = f" %s%s %g %g %g %g %g %g {VIEW} {FOCUS_POINT} (s %g %g %g %g) %s"
        config = match.config
        stamina = " ".join(number(SERVER_PARAMETERS[name](config))
                           for name in ("stamina_max", "effort_init")) + " 1 " \
            + number(SERVER_PARAMETERS["stamina_capacity"](config))
        counts = "(c " + " ".join(["0"] * COUNTERS) + "))"
        parts = []
        rows = iter(self._labels)
        for team, size in enumerate(match.state.sizes):
            letter = side(team)
            for unum in range(1, max(MAX_PLAYER, size) + 1):
                if unum <= size:
                    parts.append(entry.replace("%s%s", next(rows).replace("%", "%%") + "%s", 1))
                else:
                    x, y = parking_spot(letter, unum, self._half_width)
                    parts.append(f" (({letter} {unum}) 0 0 {number(x)} {number(y)} 0 0 0 0 {DISABLED_VIEW} "
                                 f"{FOCUS_POINT} (s {stamina}) {counts}")
        return "".join(parts) + ")\n"

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
        observer = match.observer  # (a neck is relative to the body: the same in every frame)
        table[:, 6] = 0.0 if observer is None else np.round(observer.necks, 3) + 0.0
        table[:, 7] = state.stamina
        table[:, 8] = state.effort
        table[:, 9] = state.recovery
        table[:, 10] = np.where(np.isinf(state.capacity), -1.0, state.capacity)  # rcssserver: negative = unlimited
        table[:, 11] = self._count_texts
        present = state.present
        if not present.all():                         # sent off: rcssserver's disabled player
            for row in np.flatnonzero(~present).tolist():
                table[row, 0] = hex(DISCARD | RED_CARD) if state.cards[row] >= 2 else "0"
                table[row, 1:3] = self._parked[row]
                table[row, 3:7] = 0
        b = (np.round(np.concatenate((ball * turn, state.ball_vel * turn)), 4) + 0.0).tolist()
        head = f"(show {state.cycle} ((b) {b[0]:g} {b[1]:g} {b[2]:g} {b[3]:g})"
        return head + self._format % tuple(table.ravel().tolist())
