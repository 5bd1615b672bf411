"""The environment's render modes: ``rgb_array``, a top view of the field as an RGB image
(numpy only, no window), and ``human``, the match streamed to a rerun viewer where a window
can open, else recorded into a ``.rrd`` file (:func:`human_recorder`)."""

from __future__ import annotations

import numpy as np

from soccer_sim.config import FieldConfig
from soccer_sim.replay.field import field_lines, goal_frames
from soccer_sim.state import WorldState

PIXELS_PER_METRE = 5
GRASS = np.array([60, 130, 60], dtype=np.uint8)
LINE = np.array([235, 235, 235], dtype=np.uint8)
TEAM = (np.array([220, 50, 47], dtype=np.uint8), np.array([38, 139, 210], dtype=np.uint8))
BALL = np.array([255, 255, 255], dtype=np.uint8)


def _pixels(points: np.ndarray, field: FieldConfig, shape: tuple[int, int]) -> np.ndarray:
    """(k, 2) metres -> (k, 2) integer (row, column); +y is up in the image."""
    h, w = shape
    col = (points[:, 0] + field.length / 2 + field.margin) * PIXELS_PER_METRE
    row = (field.width / 2 + field.margin - points[:, 1]) * PIXELS_PER_METRE
    return np.column_stack([np.clip(row, 0, h - 1), np.clip(col, 0, w - 1)]).astype(np.int64)


def _disc(image: np.ndarray, centres: np.ndarray, radius: int, colour: np.ndarray) -> None:
    offsets = np.array([(dr, dc) for dr in range(-radius, radius + 1) for dc in range(-radius, radius + 1)
                        if dr * dr + dc * dc <= radius * radius])
    h, w = image.shape[:2]
    cells = (centres[:, None, :] + offsets[None, :, :]).reshape(-1, 2)
    cells = cells[(cells[:, 0] >= 0) & (cells[:, 0] < h) & (cells[:, 1] >= 0) & (cells[:, 1] < w)]
    image[cells[:, 0], cells[:, 1]] = colour


def _background(field: FieldConfig) -> np.ndarray:
    h = int(round((field.width + 2 * field.margin) * PIXELS_PER_METRE))
    w = int(round((field.length + 2 * field.margin) * PIXELS_PER_METRE))
    image = np.empty((h, w, 3), dtype=np.uint8)
    image[:] = GRASS
    for line in field_lines(field) + goal_frames(field):
        # Dense samples along each polyline segment paint it.
        for a, b in zip(line[:-1], line[1:]):
            steps = max(2, int(np.hypot(*(b - a)) * PIXELS_PER_METRE * 2))
            points = a + np.linspace(0.0, 1.0, steps)[:, None] * (b - a)
            cells = _pixels(points, field, (h, w))
            image[cells[:, 0], cells[:, 1]] = LINE
    return image


_BACKGROUNDS: dict[FieldConfig, np.ndarray] = {}


def render_rgb(state: WorldState, field: FieldConfig) -> np.ndarray:
    """An (H, W, 3) uint8 image of ``state``: home red, away blue, the ball white."""
    background = _BACKGROUNDS.get(field)
    if background is None:
        background = _BACKGROUNDS[field] = _background(field)
    image = background.copy()
    home = state.sizes[0]
    shape = image.shape[:2]
    for team, rows in ((0, state.pos[:home]), (1, state.pos[home:])):
        if len(rows):
            _disc(image, _pixels(rows, field, shape), 4, TEAM[team])
    _disc(image, _pixels(state.ball[None, :], field, shape), 2, BALL)
    return image


def human_recorder(record_dir: str | None, episode: int, seed: int) -> object:
    """The recorder of ``render_mode="human"`` for one episode: a rerun viewer it spawns when a
    display is there; else (a server, a container) a warning naming the ``.rrd`` file the
    episode is recorded into instead (``record_dir``, default the temporary directory), to be
    watched with ``soccer-sim replay FILE`` or ``rerun FILE`` on a machine with a display."""
    import os
    import tempfile
    import warnings

    from soccer_sim.replay import RerunRecorder
    from soccer_sim.replay.recorder import has_display

    if has_display():
        return RerunRecorder(spawn=True, flush_every=10)
    folder = record_dir or tempfile.gettempdir()
    path = os.path.join(folder, f"soccer-sim-env-{os.getpid()}-{id(object()):x}-episode-{episode}-seed-{seed}.rrd")
    warnings.warn(f"render_mode='human': no display here, so the episode is recorded into {path} instead; "
                  "watch it with `soccer-sim replay FILE` or `rerun FILE` where a display is, or use "
                  "render_mode='rgb_array'", stacklevel=3)
    return RerunRecorder(path, flush_every=1000)
