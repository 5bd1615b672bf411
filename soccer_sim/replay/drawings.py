"""What a :class:`~soccer_sim.team_hooks.Drawable` team draws in a replay: its role targets,
an arrow from each outfield player to its role's target, and its formation's triangulation.

:class:`TeamDrawings` buffers one team's drawings cycle by cycle, alongside the recorder's
buffers of the world, and sends a block of cycles to rerun in columns.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from soccer_sim.team import TeamError
from soccer_sim.team_hooks import Drawable, Drawing

TEAM_KEYS = ("home", "away")


def team_drawing(team: Drawable, name: str) -> Drawing:
    """The team's current :class:`Drawing`; a TeamError naming the team if ``drawing()`` fails
    or returns anything else."""
    try:
        drawing = team.drawing()
    except Exception as exc:
        raise TeamError(name, f"drawing() failed with {type(exc).__name__}: {exc}") from exc
    if not isinstance(drawing, Drawing):
        raise TeamError(name, f"drawing() must return a soccer_sim.team_hooks.Drawing, got {type(drawing).__name__}")
    return drawing


class TeamDrawings:
    """One team's drawings over a block of up to ``capacity`` buffered cycles (row ``i`` is the
    recorder's row ``i``), kept in the team's frame and mirrored into the absolute frame when
    sent.

    ``team`` is 0 (home) or 1 (away); ``source`` the Drawable team, ``name`` its name (for
    errors). The outfield players' indices are read once, from the team's first drawing.
    """

    def __init__(self, team: int, source: Drawable, name: str, capacity: int) -> None:
        self.team = team
        self.key = TEAM_KEYS[team]
        self.source = source
        self.name = name
        self.capacity = capacity
        self.outfield = team_drawing(source, name).outfield
        self.targets: np.ndarray | None = None
        """Role targets as the team drew them (team frame), (capacity, roles, 2)."""
        self.assigned: np.ndarray | None = None
        """Each outfield player's role target (team frame), (capacity, k, 2)."""
        self.signs = np.empty(capacity, dtype=np.float32)
        """The team's attack direction (+1/-1: its frame to the absolute frame) per row."""
        self.drawn = np.zeros(capacity, dtype=np.bool_)
        """Whether the team had assigned roles (its assigned targets are drawn) in that row."""
        self._formation: tuple[int, float] | None = None
        self._meshes: dict[tuple[int, float], np.ndarray] = {}
        self._mesh_changes: list[tuple[int, np.ndarray]] = []
        """(cycle, closed triangles (t, 4, 2), absolute frame) whenever the formation changed."""

    def current(self) -> Drawing:
        """The team's drawing now."""
        return team_drawing(self.source, self.name)

    def fits(self, drawing: Drawing) -> bool:
        """Whether the drawing's arrays have the shapes of the rows buffered so far (when they
        do not, the recorder sends what it holds before :meth:`write` starts new buffers)."""
        targets, assigned = drawing.targets, drawing.assigned_targets
        if self.targets is None or self.targets.shape[1:] != targets.shape:
            return False
        return assigned is None or self.assigned is None or self.assigned.shape[1:] == assigned.shape

    def write(self, i: int, drawing: Drawing, sign: float, cycle: int) -> None:
        """Row ``i``: the drawing of cycle ``cycle``, the team attacking towards ``sign``."""
        targets, assigned = drawing.targets, drawing.assigned_targets
        if self.targets is None or self.targets.shape[1:] != targets.shape:
            self.targets = np.empty((self.capacity,) + targets.shape)
        self.targets[i] = targets
        self.signs[i] = sign
        self.drawn[i] = assigned is not None
        if assigned is not None:
            if self.assigned is None or self.assigned.shape[1:] != assigned.shape:
                self.assigned = np.empty((self.capacity,) + assigned.shape)
            self.assigned[i] = assigned
        balls, triangles = drawing.formation_balls, drawing.formation_triangles
        if balls is not None and triangles is not None:
            key = (id(balls), sign)
            if self._formation != key:
                self._formation = key
                self._mesh_changes.append((cycle, self._mesh(key, balls, triangles)))

    def move_row(self, source: int, target: int) -> None:
        """Copy row ``source`` to row ``target`` (the recorder keeps a half-written cycle)."""
        for buffer in (self.targets, self.assigned, self.signs, self.drawn):
            if buffer is not None:
                buffer[target] = buffer[source]

    def send(self, rr: Any, recording: Any, times: list[Any], count: int, rows_of_team: np.ndarray,
             time_columns: Callable[[np.ndarray], list[Any]]) -> None:
        """Send the first ``count`` rows (at ``times``; ``rows_of_team`` (count, n, 2) the team's
        player positions, absolute frame) and the formation meshes that came into use, at their
        cycles (``time_columns`` makes rerun's time columns of cycles)."""
        signs = self.signs[:count, None, None]
        targets = self.targets[:count].astype(np.float32) * signs
        roles = targets.shape[1]
        rr.send_columns(f"world/{self.key}/roles/targets", indexes=times,
                        columns=rr.Points2D.columns(positions=targets.reshape(-1, 2)).partition([roles] * count),
                        recording=recording)
        drawn = self.drawn[:count]
        lengths = np.zeros(count, dtype=np.int64)
        if drawn.any():
            ends = self.assigned[:count][drawn].astype(np.float32) * signs[drawn]
            starts = rows_of_team[drawn][:, self.outfield[:ends.shape[1]]]
            lengths[drawn] = ends.shape[1]
            origins, vectors = starts.reshape(-1, 2), (ends - starts).reshape(-1, 2)
        else:
            origins = vectors = np.zeros((0, 2), np.float32)
        rr.send_columns(f"world/{self.key}/roles/assignment", indexes=times,
                        columns=rr.Arrows2D.columns(origins=origins, vectors=vectors).partition(lengths),
                        recording=recording)
        self._send_meshes(rr, recording, time_columns)

    def _mesh(self, key: tuple[int, float], balls: np.ndarray, triangles: np.ndarray) -> np.ndarray:
        """A formation's Delaunay mesh as closed triangles (t, 4, 2) in the absolute frame
        (``key[1]`` the team's attack direction), made once per formation and direction."""
        mesh = self._meshes.get(key)
        if mesh is None:
            points = np.float32(key[1]) * np.asarray(balls, dtype=np.float32)
            triangles = np.asarray(triangles)
            mesh = self._meshes[key] = points[np.concatenate([triangles, triangles[:, :1]], axis=1)]
        return mesh

    def _send_meshes(self, rr: Any, recording: Any, time_columns: Callable[[np.ndarray], list[Any]]) -> None:
        changes = self._mesh_changes
        if not changes:
            return
        cycles = np.array([cycle for cycle, _ in changes], dtype=np.int64)
        strips = np.concatenate([mesh for _, mesh in changes])
        rr.send_columns(f"world/{self.key}/roles/triangulation", indexes=time_columns(cycles),
                        columns=rr.LineStrips2D.columns(strips=line_strips(strips)).partition(
                            [len(m) for _, m in changes]),
                        recording=recording)
        changes.clear()


def line_strips(strips: np.ndarray) -> Any:
    """(k, length, 2) strips of equal length as rerun's line-strip Arrow array, built in one
    go (rerun's own conversion walks the strips one by one in Python)."""
    import pyarrow as pa
    from rerun.components import LineStrip2DBatch
    from rerun.encodings import Vec2DBatch

    k, length = strips.shape[:2]
    offsets = np.arange(0, (k + 1) * length, length, dtype=np.int32)
    points = Vec2DBatch(np.ascontiguousarray(strips, dtype=np.float32).reshape(-1, 2)).as_arrow_array()
    return pa.ListArray.from_arrays(offsets, points, type=LineStrip2DBatch._ARROW_DATATYPE)
