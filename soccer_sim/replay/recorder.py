"""A match recorder that writes a rerun replay (``.rrd``) or streams to a rerun viewer.

:class:`RerunRecorder` observes the match loop (``on_start``/``on_cycle``/``on_end``). Every
cycle it copies what it needs into growing numpy buffers; every ``flush_every`` cycles and at
the end it sends them to rerun in columns (``rerun.send_columns``: one call per entity for a
whole block of cycles), so recording costs little next to the match.

What a replay holds (absolute frame, metres; entity paths):

- ``/world``: a static transform that mirrors y (:data:`VIEW_SCALE`), so that the viewer's
  2-D view, which draws +y downwards, shows +y upwards like the pictures; the data below stay
  in the absolute frame.
- ``/world/field/grass`` (a green image under everything), ``/world/field/lines``,
  ``/world/field/goals``: the pitch and its markings, static.
- ``/world/home/players``, ``/world/away/players``: positions every cycle, team colours,
  shirt numbers as labels (static).
- ``/world/ball`` and ``/world/ball/trail`` (the last :attr:`trail` positions).
- ``/world/home/roles/targets``, ``.../roles/assignment`` (an arrow from each player to its role's target) and
  ``.../roles/triangulation`` (the formation's Delaunay mesh, logged when it changes; hidden
  when the replay opens unless ``formation_meshes=True``), for a team with the ``drawing()``
  hook (:class:`~soccer_sim.team_hooks.Drawable`, e.g. :mod:`agents.teams`); each a layer the
  viewer toggles.
- ``/events``: a text log of goals, shots, passes, set plays, offside, ...
- ``/stats/score/{home,away}``, ``/stats/possession/home`` (home's possession share so far, as
  :mod:`soccer_sim.analysis.possession` defines it and the match statistics report it),
  ``/stats/stamina/{home,away}`` (team mean).

Timelines: ``cycle`` (a sequence) and ``match_time`` (a duration, ``cycle_seconds`` per cycle).
The default blueprint (:func:`soccer_sim.replay.blueprint.default_blueprint`) is stored with the
recording.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING, Any

import numpy as np

from soccer_sim.analysis.events import describe_event
from soccer_sim.analysis.possession import Possession
from soccer_sim.errors import SoccerSimError
from soccer_sim.replay.blueprint import default_blueprint
from soccer_sim.replay.drawings import TEAM_KEYS, TeamDrawings, line_strips
from soccer_sim.replay.field import GRASS_COLOUR, LINE_COLOUR, field_lines, goal_frames
from soccer_sim.state import HOME, EventKind
from soccer_sim.team_hooks import Drawable

if TYPE_CHECKING:
    from soccer_sim.match import Match

TEAM_COLOURS = ((220, 50, 47), (38, 139, 210))
"""Home red, away blue (RGB)."""
BALL_COLOUR = (250, 250, 250)
GRASS_DRAW_ORDER = -100.0
"""Below everything else (rerun draws images at -10, lines at 20 and points at 30 by default)."""
PLAYER_DRAW_RADIUS = 0.8
"""Players are drawn at least this large (metres) to be seen on a whole-field view."""
VIEW_SCALE = (1.0, -1.0, 1.0)
"""The scale of ``/world``: the viewer's 2-D view draws +y downwards and takes no view
coordinates, so mirroring y there puts +y up with labels upright, as in the pictures."""


class ReplayError(SoccerSimError, RuntimeError):
    """rerun-sdk is missing, or a replay cannot be written or read; the message says what to do."""


def has_display() -> bool:
    """Whether a viewer window can open here (a display on Linux; always on macOS and Windows)."""
    import sys

    return bool(os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")
                or sys.platform in ("darwin", "win32"))


def import_rerun() -> Any:
    """The rerun module, or a ReplayError saying how to install it."""
    try:
        import rerun
    except ImportError as exc:  # pragma: no cover - rerun-sdk is a dependency
        raise ReplayError("replays need rerun-sdk: pip install rerun-sdk") from exc
    return rerun


class RerunRecorder:
    """Record a match for the rerun viewer: into the file ``path`` (no window opens), or
    streamed to a viewer it spawns (``spawn=True``), or into a caller's ``recording`` stream.

    ``trail``: cycles of ball trail drawn behind the ball. ``flush_every``: cycles buffered
    before they are sent (smaller streams more smoothly to a live viewer). ``drawings``:
    whether to record the teams' role targets, assignment lines and triangulation.
    ``formation_meshes``: whether the triangulations are shown when the replay opens (they are
    recorded either way; the viewer's visibility toggle shows or hides them).
    """

    def __init__(self, path: str | os.PathLike | None = None, *, spawn: bool = False, recording: Any = None,
                 trail: int = 10, flush_every: int = 1000, drawings: bool = True,
                 formation_meshes: bool = False) -> None:
        if path is None and not spawn and recording is None:
            raise ValueError("RerunRecorder needs a path, spawn=True or a recording stream")
        if trail < 1 or flush_every < 1:
            raise ValueError(f"trail and flush_every must be at least 1, got {trail} and {flush_every}")
        self.path = None if path is None else os.fspath(path)
        self.spawn = spawn
        self.trail = int(trail)
        self.flush_every = int(flush_every)
        self.drawings = drawings
        self.formation_meshes = formation_meshes
        self.recording = recording
        self._rr = import_rerun()

    # ------------------------------------------------------------------ match loop
    def on_start(self, match: Match) -> None:
        rr = self._rr
        names = match.team_names
        if self.recording is None:
            self.recording = rr.RecordingStream("soccer-sim", recording_id=f"{names[0]}-v-{names[1]}-seed-{match.seed}")
        blueprint = default_blueprint(match.config.field, formation_meshes=self.formation_meshes)
        try:
            if self.path is not None:
                # kept in memory and written at the end (:meth:`on_end`): rerun's own file writer
                # can block for ever when the disk fills under it, a write of ours fails at once
                self._memory = self.recording.memory_recording()
                self.recording.send_blueprint(blueprint, make_active=True, make_default=True)
            if self.spawn:
                self.recording.spawn(default_blueprint=blueprint)
        except Exception as exc:  # rerun reports unwritable paths and missing viewers as plain errors
            raise ReplayError(f"cannot start the replay ({self.path or 'viewer'}): {exc}") from exc
        self._seconds = float(match.config.physics.cycle_seconds)
        self._sizes = tuple(match.state.sizes)
        self._log_static(match)
        self._allocate(sum(self._sizes))
        self._trail_seed = np.repeat(match.state.ball[None, :].astype(np.float32), self.trail, axis=0)
        self._possession = Possession(self._sizes[0])
        self._drawers = [TeamDrawings(team, obj, match.team_names[team], self.flush_every)
                         for team, obj in enumerate(match.teams)
                         if self.drawings and self._sizes[team] and isinstance(obj, Drawable)]
        self._sent_events = 0
        self._buffer(match, played=False)

    def on_cycle(self, match: Match) -> None:
        self._buffer(match)
        if self._count >= self.flush_every:
            self._flush(match)

    def on_end(self, match: Match) -> None:
        self._flush(match)
        rec = self.recording
        rec.flush()
        if self.path is not None:
            data = self._memory.drain_as_bytes()
            rec.disconnect()
            with open(self.path, "wb") as handle:  # (an OSError names the file: a full disk fails here)
                handle.write(data)

    # ------------------------------------------------------------------ buffering
    def _allocate(self, players: int) -> None:
        """Buffers for ``flush_every`` cycles, written row by row and sent as whole columns."""
        cap = self.flush_every
        self._count = 0
        self._cycles = np.empty(cap, dtype=np.int64)
        # Rows are written as the match holds them (float64: a plain copy) and converted to
        # float32 once per block when sent.
        self._pos = np.empty((cap, players, 2))
        self._ball = np.empty((cap, 2))
        self._score = np.empty((cap, 2))
        self._stamina = np.empty((cap, players))
        self._share = np.empty(cap)
        """Home's possession share after each cycle."""

    def _buffer(self, match: Match, played: bool = True) -> None:
        """Copy this cycle into the buffers (``played``: a cycle of the match, not the state it
        started from, which counts for no possession)."""
        state = match.state
        i = self._count
        self._cycles[i] = state.cycle
        self._pos[i] = state.pos
        self._ball[i] = state.ball
        self._score[i] = state.score
        self._stamina[i] = state.stamina
        if played:
            self._possession.add(state.last_touch)
        self._share[i] = self._possession.share(HOME)
        for drawer in self._drawers:
            drawing = drawer.current()
            if not drawer.fits(drawing) and self._count:
                self._flush(match, keep_current=True)  # a change of shape: send what was buffered first
            sign = state.home_attacks if drawer.team == 0 else -state.home_attacks
            drawer.write(self._count, drawing, sign, int(state.cycle))
        self._count += 1

    # ------------------------------------------------------------------ sending
    def _times(self, cycles: np.ndarray) -> list[Any]:
        rr = self._rr
        return [rr.TimeColumn("cycle", sequence=cycles),
                rr.TimeColumn("match_time", duration=cycles * self._seconds)]

    def _flush(self, match: Match, keep_current: bool = False) -> None:
        """Send the buffered cycles; ``keep_current``: the cycle being buffered (its world
        already written, its drawings not) stays, moved to the first row."""
        count = self._count
        if not count:
            return
        rr, rec = self._rr, self.recording
        cycles = self._cycles[:count].copy()
        times = self._times(cycles)
        # Copies: rerun may read the arrays after this returns, when the buffers hold new cycles.
        pos = self._pos[:count].astype(np.float32)
        home = self._sizes[0]
        for team, key in enumerate(TEAM_KEYS):
            size = self._sizes[team]
            if size == 0:
                continue
            rows = pos[:, :home] if team == 0 else pos[:, home:]
            rr.send_columns(f"world/{key}/players", indexes=times,
                            columns=rr.Points2D.columns(positions=rows.reshape(-1, 2)).partition([size] * count),
                            recording=rec)
        for drawer in self._drawers:
            drawer.send(rr, rec, times, count, pos[:, :home] if drawer.team == 0 else pos[:, home:], self._times)
        ball = self._ball[:count].astype(np.float32)
        rr.send_columns("world/ball", indexes=times, columns=rr.Points2D.columns(positions=ball), recording=rec)
        history = np.concatenate([self._trail_seed, ball])
        strips = np.stack([history[k:k + count] for k in range(self.trail + 1)], axis=1)
        rr.send_columns("world/ball/trail", indexes=times,
                        columns=rr.LineStrips2D.columns(strips=line_strips(strips)), recording=rec)
        self._trail_seed = history[-self.trail:]
        score = self._score[:count].copy()
        stamina = self._stamina[:count]
        for team, key in enumerate(TEAM_KEYS):
            rr.send_columns(f"stats/score/{key}", indexes=times, columns=rr.Scalars.columns(scalars=score[:, team]),
                            recording=rec)
            if self._sizes[team]:
                mean = (stamina[:, :home] if team == 0 else stamina[:, home:]).mean(axis=1, dtype=np.float64)
                rr.send_columns(f"stats/stamina/{key}", indexes=times, columns=rr.Scalars.columns(scalars=mean),
                                recording=rec)
        share = self._share[:count].copy()
        rr.send_columns("stats/possession/home", indexes=times, columns=rr.Scalars.columns(scalars=share),
                        recording=rec)
        self._send_events(match)
        self._count = 0
        if keep_current:  # the row being written moves to the front
            for buffer in (self._cycles, self._pos, self._ball, self._score, self._stamina, self._share):
                buffer[0] = buffer[count]
            for drawer in self._drawers:
                drawer.move_row(count, 0)

    def _send_events(self, match: Match) -> None:
        events = match.events.as_arrays()
        new = slice(self._sent_events, len(events["cycle"]))
        self._sent_events = len(events["cycle"])
        cycles = events["cycle"][new]
        if not len(cycles):
            return
        rr = self._rr
        texts = [describe_event(match.team_names, int(k), int(t), int(p), float(x), float(y), int(d))
                 for k, t, p, x, y, d in zip(events["kind"][new], events["team"][new], events["player"][new],
                                             events["x"][new], events["y"][new], events["detail"][new])]
        levels = ["WARN" if int(k) == EventKind.GOAL else "INFO" for k in events["kind"][new]]
        rr.send_columns("events", indexes=self._times(np.asarray(cycles, dtype=np.int64)),
                        columns=rr.TextLog.columns(text=texts, level=levels), recording=self.recording)

    # ------------------------------------------------------------------ static and rare data
    def _log_static(self, match: Match) -> None:
        rr, rec = self._rr, self.recording
        field = match.config.field
        rec.log("world", rr.Transform3D(scale=VIEW_SCALE), static=True)
        self._log_grass(field)
        rec.log("world/field/lines", rr.LineStrips2D(field_lines(field), colors=[LINE_COLOUR], radii=0.12),
                static=True)
        rec.log("world/field/goals", rr.LineStrips2D(goal_frames(field), colors=[LINE_COLOUR], radii=0.2),
                static=True)
        radius = float(match.config.physics.player_radius)
        for team, key in enumerate(TEAM_KEYS):
            size = self._sizes[team]
            if size:
                rec.log(f"world/{key}/players", rr.Points2D.from_fields(
                    colors=[TEAM_COLOURS[team]] * size, radii=[max(radius, PLAYER_DRAW_RADIUS)] * size,
                    labels=[str(i + 1) for i in range(size)], show_labels=True), static=True)
                rec.log(f"world/{key}/roles/targets", rr.Points2D.from_fields(
                    colors=[TEAM_COLOURS[team]], radii=[0.3]), static=True)
                rec.log(f"world/{key}/roles/assignment", rr.Arrows2D.from_fields(
                    colors=[TEAM_COLOURS[team]], radii=[0.06]), static=True)
                rec.log(f"world/{key}/roles/triangulation", rr.LineStrips2D.from_fields(
                    colors=[TEAM_COLOURS[team] + (70,)], radii=[0.04]), static=True)
        rec.log("world/ball", rr.Points2D.from_fields(colors=[BALL_COLOUR], radii=[0.4]), static=True)
        rec.log("world/ball/trail", rr.LineStrips2D.from_fields(colors=[BALL_COLOUR + (120,)], radii=[0.1]),
                static=True)
        names = match.team_names
        rec.log("match", rr.TextDocument(f"{names[0]} (home, red) v {names[1]} (away, blue), seed {match.seed}"),
                static=True)

    def _log_grass(self, field: Any) -> None:
        """The pitch and its margin as a green 2x2-pixel image stretched over them, under the
        lines: white markings and ball then read on the viewer's light and dark themes alike."""
        rr, rec = self._rr, self.recording
        half = np.array([field.length / 2.0 + field.margin, field.width / 2.0 + field.margin])
        pixels = np.broadcast_to(np.array(GRASS_COLOUR, dtype=np.uint8), (2, 2, 3)).copy()
        rec.log("world/field/grass", rr.Transform3D(translation=[*-half, 0.0], scale=[*half, 1.0]), static=True)
        rec.log("world/field/grass", rr.Image(pixels, color_model="RGB", draw_order=GRASS_DRAW_ORDER), static=True)
