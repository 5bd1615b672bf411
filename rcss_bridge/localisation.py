"""Where a player of the real server is and which way it looks, from one ``see``.

rcssserver tells a player neither. A ``see`` gives each flag's distance and direction
relative to the **face** (body plus neck); the body direction follows from the face and
``sense_body``'s ``head_angle``.

* **Face.** A line ``(l X) dist D`` is reported at ``D = s - 90°`` (``s > 0``) or ``s + 90°``
  (``s < 0``), ``s`` the angle from the face to the line's normal (``calcLineDir``), so
  ``face = normal - s``; the normal points outward from inside the pitch and the other way
  from beyond the line (:data:`~rcss_bridge.landmarks.LINE_NORMALS`), so each line offers two
  faces 180° apart. Two flags ``i, j`` give the face as the angle of ``f_j - f_i`` in the
  absolute frame minus its angle as seen (``d_j e(a_j) - d_i e(a_i)``); the estimate is the
  circular mean over all pairs weighted by the seen baseline's length. A line's face, the one
  of its two nearest the flags' estimate (within :data:`LINE_AGREEMENT`), is taken when there
  is one (the line's direction is the finer one); the flags' estimate otherwise; a single line
  without two flags: the face from inside the pitch.
* **Position.** The simulator's self-localisation formula
  (:func:`soccer_sim.perception.localise.position_from_flags`): the mean over the flags seen of
  ``f - d (cos(face + a), sin(face + a))``.

Everything here is in the server's absolute frame (metres, degrees from +x towards +y);
:mod:`rcss_bridge.views_builder` turns it into the team's frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from soccer_sim.perception.localise import position_from_flags

from rcss_bridge.landmarks import FLAGS, LINE_NORMALS
from rcss_bridge.messages import See

LINE_AGREEMENT = 10.0
"""A line's face is taken when it is within this many degrees of the flags' estimate."""


@dataclass(frozen=True)
class Fix:
    """One see's self-localisation (server frame)."""

    position: np.ndarray
    """(2,) m; NaN when no named flag was seen."""
    face: float
    """The face's direction (degrees; NaN when neither two flags nor a line were seen)."""
    flags: int
    """Named flags the position averages."""


def wrap(angle: float) -> float:
    """``angle`` (degrees) folded into [-180, 180)."""
    return (angle + 180.0) % 360.0 - 180.0


def localise(see: See, landmarks: dict[tuple[str, ...], tuple[float, float]] = FLAGS) -> Fix:
    """The player's position and face from the flags and lines of ``see`` (module docstring)."""
    known = [obj for obj in see.landmarks if obj.name in landmarks and math.isfinite(obj.distance)]
    points = np.array([landmarks[obj.name] for obj in known], dtype=np.float64).reshape(-1, 2)
    distances = np.array([obj.distance for obj in known], dtype=np.float64)
    directions = np.array([obj.direction for obj in known], dtype=np.float64)
    from_flags = face_from_flags(points, distances, directions)
    face = from_flags
    candidates = [c for line in see.lines if line.name in LINE_NORMALS for c in line_faces(
        LINE_NORMALS[line.name], line.direction)]
    if candidates:
        if math.isfinite(from_flags):
            nearest = min(candidates, key=lambda c: abs(wrap(c - from_flags)))
            if abs(wrap(nearest - from_flags)) <= LINE_AGREEMENT:
                face = nearest
        else:
            face = candidates[0]
    if not math.isfinite(face) or len(known) == 0:
        return Fix(np.full(2, np.nan), face, 0)
    return Fix(position_from_flags(points, distances, directions, face), face, len(known))


def line_faces(normal: float, reported: float) -> tuple[float, float]:
    """The two faces (degrees) a line with outward ``normal`` seen at ``reported`` degrees
    allows: from inside the pitch first, from beyond the line second. A line reported at 0°
    is parallel to the line of sight, which the server never sends; it gives its two readings
    too (``s = +-90°``)."""
    sight_to_normal = reported + 90.0 if reported < 0 else reported - 90.0
    inside = wrap(normal - sight_to_normal)
    return inside, wrap(inside + 180.0)


def face_from_flags(points: np.ndarray, distances: np.ndarray, directions: np.ndarray) -> float:
    """The face (degrees) from every pair of flags (module docstring); NaN for fewer than two."""
    k = len(points)
    if k < 2:
        return float("nan")
    rad = np.radians(directions)
    seen = np.stack([distances * np.cos(rad), distances * np.sin(rad)], axis=1)
    i, j = np.triu_indices(k, 1)
    world = points[j] - points[i]
    local = seen[j] - seen[i]
    weight = np.hypot(local[:, 0], local[:, 1])
    angle = np.arctan2(world[:, 1], world[:, 0]) - np.arctan2(local[:, 1], local[:, 0])
    c, s = float(np.sum(weight * np.cos(angle))), float(np.sum(weight * np.sin(angle)))
    if c == 0.0 and s == 0.0:
        return float("nan")
    return wrap(math.degrees(math.atan2(s, c)))


def warm_up() -> None:
    """Compile (or load from numba's cache) the self-localisation kernel now: a step's first
    call must not spend the server's 1.25 s (``TeamClient.connect`` calls this first)."""
    position_from_flags(np.zeros((1, 2)), np.ones(1), np.zeros(1), 0.0)
