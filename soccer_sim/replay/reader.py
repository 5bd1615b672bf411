"""Read a recorded replay back into numpy arrays, with rerun's own reader."""

from __future__ import annotations

import os
from dataclasses import dataclass, field

import numpy as np

from soccer_sim.replay.recorder import TEAM_KEYS, ReplayError, import_rerun


@dataclass
class Replay:
    """What :func:`read_replay` finds in a ``.rrd`` file (absolute frame, metres).

    ``players[key]`` is (T, n, 2) for ``key`` in ("home", "away") at ``cycles`` (T,);
    ``ball`` (T, 2); ``score`` (T, 2); ``possession`` (T,) home's possession share (empty if
    the recording has none); ``events`` (cycle, text) pairs in order;
    ``static_paths`` the entities logged as static (the field, styles); ``targets[key]`` the
    role targets per cycle (a list of (k, 2) arrays) when the team drew them;
    ``lines[key]`` the player-to-target segments per cycle ((k, 2, 2) arrays);
    ``temporal_paths`` the entities with data on the ``cycle`` timeline; ``has_blueprint``
    whether a default blueprint is stored;
    ``static_values[entity][component]`` what the static entities hold, e.g.
    ``static_values["/world"]["Transform3D:scale"]`` (the viewer's mirror of y).
    """

    cycles: np.ndarray
    players: dict[str, np.ndarray]
    ball: np.ndarray
    score: np.ndarray
    events: list[tuple[int, str]]
    static_paths: set[str]
    targets: dict[str, list[np.ndarray]] = field(default_factory=dict)
    lines: dict[str, list[np.ndarray]] = field(default_factory=dict)
    temporal_paths: set[str] = field(default_factory=set)
    possession: np.ndarray = field(default_factory=lambda: np.zeros(0))
    has_blueprint: bool = False
    static_values: dict[str, dict[str, list]] = field(default_factory=dict)


def _column(batch, suffix: str):
    for name in batch.column_names:
        if name.endswith(suffix):
            return batch.column(name)
    return None


def _components(batch) -> dict[str, list]:
    """A chunk's component columns as Python lists (``"Archetype:field"`` names; rerun's row ids
    and time columns left out)."""
    import pyarrow as pa

    return {name: batch.column(name).to_pylist() for name in batch.column_names
            if ":" in name and not pa.types.is_timestamp(batch.column(name).type)}


def _open(path: str | os.PathLike):
    """The reader of ``path``, or ReplayError if it is missing or not a rerun recording."""
    import_rerun()
    from rerun.chunk import RrdReader

    from formations.input_files import check_input  # the project's one rule for files it reads

    name = os.fspath(path)
    try:
        check_input(name)
    except FileNotFoundError:
        raise ReplayError(f"{name}: no such replay file") from None
    except OSError as exc:
        raise ReplayError(f"{name}: cannot read it ({exc.strerror or exc})") from None
    try:
        reader = RrdReader(name)
        reader.recordings()
    except Exception as exc:
        raise ReplayError(f"{name}: not a rerun recording ({exc})") from exc
    return reader


def read_blueprint(path: str | os.PathLike) -> dict[str, dict[str, list]]:
    """The default blueprint stored in ``path`` as {blueprint entity: {component: values}},
    e.g. a view's ``ViewBlueprint:space_origin`` or the ``EntityBehavior:visible`` of an entity
    it hides; empty when none is stored."""
    reader = _open(path)
    found: dict[str, dict[str, list]] = {}
    for store in reader.blueprints()[:1]:
        for chunk in reader.stream(store=store).to_chunks():
            found.setdefault(chunk.entity_path, {}).update(_components(chunk.to_record_batch()))
    return found


def read_replay(path: str | os.PathLike) -> Replay:
    """Read ``path`` (written by :class:`RerunRecorder`); ReplayError if it is not a replay."""
    reader = _open(path)
    name = os.fspath(path)
    try:
        chunks = reader.stream().to_chunks()
    except Exception as exc:
        raise ReplayError(f"{name}: not a rerun recording ({exc})") from exc
    static: set[str] = set()
    static_values: dict[str, dict[str, list]] = {}
    series: dict[str, list[tuple[np.ndarray, list]]] = {}
    for chunk in chunks:
        entity = chunk.entity_path
        if chunk.is_static:
            static.add(entity)
            static_values.setdefault(entity, {}).update(_components(chunk.to_record_batch()))
            continue
        batch = chunk.to_record_batch()
        if "cycle" not in batch.column_names:
            continue
        cycles = np.asarray(batch.column("cycle").to_numpy(zero_copy_only=False), dtype=np.int64)
        for suffix in (":positions", ":scalars", ":text", ":strips", ":origins", ":vectors"):
            values = _column(batch, suffix)
            if values is not None:
                series.setdefault(entity + suffix, []).append((cycles, values.to_pylist()))
    if "/world/ball:positions" not in series:
        raise ReplayError(f"{name}: no ball positions; not a soccer-sim replay")

    def ordered(key: str) -> tuple[np.ndarray, list]:
        parts = series.get(key, [])
        cycles = np.concatenate([c for c, _ in parts]) if parts else np.zeros(0, np.int64)
        values = [v for _, vs in parts for v in vs]
        order = np.argsort(cycles, kind="stable")
        return cycles[order], [values[i] for i in order]

    cycles, ball = ordered("/world/ball:positions")
    players = {}
    targets = {}
    lines = {}
    for key in TEAM_KEYS:
        c, origins = ordered(f"/world/{key}/roles/assignment:origins")
        if len(c):
            vectors = ordered(f"/world/{key}/roles/assignment:vectors")[1]
            lines[key] = []
            for start, step in zip(origins, vectors):
                start = np.asarray(start, dtype=np.float32).reshape(-1, 2)
                lines[key].append(np.stack([start, start + np.asarray(step, dtype=np.float32).reshape(-1, 2)], axis=1))
        c, rows = ordered(f"/world/{key}/players:positions")
        if len(c):
            players[key] = np.asarray(rows, dtype=np.float32)
        c, rows = ordered(f"/world/{key}/roles/targets:positions")
        if len(c):
            targets[key] = [np.asarray(r, dtype=np.float32).reshape(-1, 2) for r in rows]
    score = np.column_stack([np.asarray(ordered(f"/stats/score/{key}:scalars")[1], dtype=float).reshape(-1)
                             for key in TEAM_KEYS])
    possession = np.asarray(ordered("/stats/possession/home:scalars")[1], dtype=float).reshape(-1)
    event_cycles, texts = ordered("/events:text")
    try:
        has_blueprint = bool(reader.blueprints())
    except Exception:
        has_blueprint = False
    return Replay(cycles=cycles, players=players, ball=np.asarray([b[0] for b in ball], dtype=np.float32),
                  score=score, events=[(int(c), t[0] if isinstance(t, list) else t) for c, t in zip(event_cycles, texts)],
                  static_paths=static, targets=targets, lines=lines,
                  temporal_paths={key.rsplit(':', 1)[0] for key in series}, possession=possession,
                  has_blueprint=has_blueprint,
                  static_values=static_values)
