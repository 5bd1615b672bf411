"""Grid workspaces with obstacles: checked occupancy grids, cells, moves and MovingAI map files.

A workspace is a boolean occupancy array (``True`` = obstacle), 2-D ``(rows,
cols)`` or 3-D ``(x, y, z)``; robots and goals sit on free cells given by
integer indices. Movement follows "It Costs to Get Costs! A Heuristic-Based
Scalable Goal Assignment Algorithm for Multi-Robot Systems": in 2-D a robot
steps to any of its 8 neighbours (cost 1 along an axis, 1.5 diagonally), in
3-D to any of its 26 neighbours (cost 1 along one axis, 1.5 along two, 2 along
three), and never cuts a corner: a move that changes several coordinates is
allowed only if every cell of the box it spans is free (in 2-D: both cells
beside a diagonal step).

Costs are kept as integers in **half units** (2, 3 and 4), so path lengths are
exact and comparisons never suffer from rounding; :data:`HALF` converts back.

Because no corner may be cut, two free cells are connected exactly when they
are connected through axis-aligned steps, so reachability is the 4-connected
(2-D) or 6-connected (3-D) labelling of the free cells.

:func:`load_movingai_map` reads the 2-D ``.map`` format of the MovingAI
pathfinding benchmarks and :func:`load_voxel_map` their 3-D voxel format.
"""

from __future__ import annotations

import itertools
import os
from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from .errors import AssignmentError

#: Path costs are integers in half units: a cost ``c`` means ``c * HALF`` grid units.
HALF = 0.5
#: Half-unit cost of a move changing 1, 2 or 3 coordinates (1, 1.5 and 2 grid units).
STEP_HALF_COST = {1: 2, 2: 3, 3: 4}

#: MovingAI terrain letters treated as free ground; every other letter of the format is an obstacle.
MOVINGAI_FREE = frozenset(".GS")
#: MovingAI terrain letters treated as obstacles (out of bounds, trees, water).
MOVINGAI_BLOCKED = frozenset("@OTW")


@dataclass(frozen=True)
class Moves:
    """The moves of a grid with a one-cell obstacle border (see :class:`Workspace`).

    Attributes:
        offsets: int64 ``(k,)``; flat-index difference of each move in the padded grid.
        costs: int64 ``(k,)``; half-unit cost of each move.
        allowed: uint32 ``(cells,)``; bit ``m`` of ``allowed[c]`` is set when move ``m``
            from padded cell ``c`` is legal (source, target and the spanned box free).
    """

    offsets: np.ndarray
    costs: np.ndarray
    allowed: np.ndarray


class Workspace:
    """A checked occupancy grid, padded with a border of obstacles for the searches.

    Attributes:
        blocked: bool array, the grid as given (``True`` = obstacle), 2-D or 3-D.
        shape: shape of ``blocked``; ``ndim`` its dimension (2 or 3).
        padded_shape: ``shape`` plus 2 along each axis (the obstacle border).
        moves: the :class:`Moves` of the padded grid.
        component: int32 array over the padded grid; label of the free region
            holding each free cell (0 for obstacles).
    """

    def __init__(self, grid: object) -> None:
        self.blocked = as_occupancy(grid)
        self.shape = self.blocked.shape
        self.ndim = self.blocked.ndim
        padded = np.pad(self.blocked, 1, constant_values=True)
        self.padded_shape = padded.shape
        self.strides = np.array(
            [int(np.prod(padded.shape[axis + 1:])) for axis in range(self.ndim)], dtype=np.int64
        )
        self.moves = _moves(padded, self.strides)
        self.component, _ = ndimage.label(~padded)

    def flat(self, cells: np.ndarray) -> np.ndarray:
        """Flat indices in the padded grid of ``(k, ndim)`` checked cell indices."""
        return (cells + 1) @ self.strides

    def cells(self, points: object, name: str) -> np.ndarray:
        """``points`` as an int64 ``(k, ndim)`` array of free cells; raises naming the bad index."""
        return as_cells(points, name, self.blocked)


def as_occupancy(grid: object) -> np.ndarray:
    """``grid`` as a C-contiguous boolean array (2-D or 3-D, non-empty); numbers must be 0 or 1."""
    try:
        array = np.asarray(grid)
    except (TypeError, ValueError) as exc:
        raise AssignmentError(f"grid must be a boolean array (True = obstacle): {exc}") from None
    if array.ndim not in (2, 3):
        raise AssignmentError(f"grid must be 2-D or 3-D (True = obstacle), got an array of shape {array.shape}")
    if array.size == 0:
        raise AssignmentError(f"grid must have at least one cell, got shape {array.shape}")
    if array.dtype != np.bool_:
        if array.dtype.kind not in "biuf":
            raise AssignmentError(f"grid must be a boolean array (True = obstacle), got dtype {array.dtype}")
        bad = (array != 0) & (array != 1)
        if bad.any():
            index = tuple(int(v) for v in np.argwhere(bad)[0])
            raise AssignmentError(f"grid{list(index)} is {array[index]!r}: grid cells must be True/False or 0/1")
        array = array != 0
    return np.ascontiguousarray(array)


def as_cells(points: object, name: str, blocked: np.ndarray) -> np.ndarray:
    """``points`` as int64 ``(k, ndim)`` cell indices of free cells of ``blocked``.

    Raises :class:`AssignmentError` naming the first offending row for
    non-integer values, cells outside the grid and cells on obstacles.
    """
    ndim = blocked.ndim
    try:
        array = np.asarray(points)
    except (TypeError, ValueError) as exc:
        raise AssignmentError(f"{name} must be integer cell indices of shape (count, {ndim}): {exc}") from None
    if array.size == 0:
        return np.zeros((0, ndim), dtype=np.int64)
    if array.ndim != 2 or array.shape[1] != ndim:
        raise AssignmentError(
            f"{name} must have shape (count, {ndim}) for a {ndim}-D grid, got an array of shape {array.shape}"
        )
    if array.dtype.kind not in "iu":
        if array.dtype.kind != "f":
            raise AssignmentError(f"{name} must be integer cell indices, got dtype {array.dtype}")
        fractional = ~np.isfinite(array) | (array != np.round(array))
        if fractional.any():
            i = int(np.argwhere(fractional)[0][0])
            raise AssignmentError(f"{name}[{i}] = {array[i].tolist()} is not a cell: indices must be integers")
    if array.dtype.kind == "u" and array.max() > 2**62 or array.dtype.kind == "f" and np.abs(array).max() > 2**62:
        i = int(np.argwhere(np.abs(array.astype(np.float64)) > 2**62)[0][0])
        raise AssignmentError(f"{name}[{i}] = {array[i].tolist()} is outside the grid")
    cells = array.astype(np.int64)
    outside = ((cells < 0) | (cells >= np.array(blocked.shape))).any(axis=1)
    if outside.any():
        i = int(np.argmax(outside))
        size = " x ".join(str(s) for s in blocked.shape)
        raise AssignmentError(f"{name}[{i}] = {cells[i].tolist()} is outside the {size} grid")
    on_obstacle = blocked[tuple(cells.T)]
    if on_obstacle.any():
        i = int(np.argmax(on_obstacle))
        raise AssignmentError(f"{name}[{i}] = {cells[i].tolist()} is on an obstacle")
    return np.ascontiguousarray(cells)


def _moves(padded: np.ndarray, strides: np.ndarray) -> Moves:
    """Offsets, costs and per-cell legality of the 8 (2-D) or 26 (3-D) moves of ``padded``.

    Legality is computed with whole-array shifts: a move is legal from a cell
    when every cell of the box between the cell and the move's target is free
    (the border of obstacles keeps every move of a free cell inside the array).
    """
    ndim = padded.ndim
    free = ~padded
    flat_free = free.ravel()
    size = flat_free.size
    steps = [d for d in itertools.product((-1, 0, 1), repeat=ndim) if any(d)]
    offsets = np.array([int(np.dot(d, strides)) for d in steps], dtype=np.int64)
    costs = np.array([STEP_HALF_COST[int(np.count_nonzero(d))] for d in steps], dtype=np.int64)
    allowed = np.zeros(size, dtype=np.uint32)
    # Inner cells only: the border is an obstacle and no free cell lies on it.
    lo = int(strides.sum())
    hi = size - lo
    for bit, step in enumerate(steps):
        ok = flat_free[lo:hi].copy()
        axes = [a for a in range(ndim) if step[a]]
        for subset in itertools.product((0, 1), repeat=len(axes)):
            if not any(subset):
                continue
            delta = sum(step[a] * strides[a] for a, use in zip(axes, subset) if use)
            ok &= flat_free[lo + delta:hi + delta]
        allowed[lo:hi] |= ok.astype(np.uint32) << np.uint32(bit)
    return Moves(offsets, costs, allowed)


def _map_error(path: str, line: int, message: str) -> AssignmentError:
    return AssignmentError(f"{path}, line {line}: {message}")


def _read_lines(name: str, kind: str) -> list[str]:
    """The lines of a map file. Read as Latin-1 so that a stray non-ASCII byte is reported
    by the parser with its line (as an unknown letter or a malformed field), not as a decoding error."""
    try:
        with open(name, encoding="latin-1") as handle:
            return handle.read().splitlines()
    except OSError as exc:
        raise AssignmentError(f"{name}: cannot read the {kind} file: {exc.strerror or exc}") from None


def load_movingai_map(path: str | os.PathLike) -> np.ndarray:
    """Read a 2-D MovingAI ``.map`` file into a boolean grid (``True`` = obstacle).

    The format: a header of ``type octile``, ``height H``, ``width W`` and
    ``map``, then ``H`` rows of ``W`` terrain letters. ``.``, ``G`` and ``S``
    are free; ``@``, ``O``, ``T`` and ``W`` are obstacles. The returned array
    has shape ``(H, W)``: cell ``(r, c)`` is letter ``c`` of map row ``r``.

    Raises:
        AssignmentError: naming the file and line of a missing or malformed
            header field, a row of the wrong length, an unknown letter, or a
            missing or extra row; or the file when it cannot be read.
    """
    name = os.fspath(path)
    lines = _read_lines(name, "map")
    header: dict[str, str] = {}
    header_line: dict[str, int] = {}
    expected = ("type", "height", "width", "map")
    number = 0
    for key in expected:
        while number < len(lines) and not lines[number].strip():
            number += 1
        if number == len(lines):
            raise _map_error(name, number + 1, f"the file ends before the header line {key!r}")
        words = lines[number].split()
        number += 1
        header_line[key] = number
        if words[0].lower() != key:
            raise _map_error(name, number, f"expected header line {key!r}, got {lines[number - 1].strip()!r}")
        if key == "map":
            if len(words) != 1:
                raise _map_error(name, number, "the 'map' line must hold only the word 'map'")
        elif len(words) != 2:
            raise _map_error(name, number, f"header line {key!r} must be '{key} VALUE'")
        else:
            header[key] = words[1]
        if key in ("height", "width"):
            value = header[key]
            if not value.isdigit() or int(value) < 1:
                raise _map_error(name, number, f"{key} must be a positive integer, got {value!r}")
    if header["type"].lower() != "octile":
        raise _map_error(name, header_line["type"], f"only 'type octile' maps are supported, got {header['type']!r}")
    height, width = int(header["height"]), int(header["width"])
    rows = lines[number:]
    while rows and not rows[-1].strip():
        rows.pop()
    if len(rows) < height:
        raise _map_error(name, number + len(rows),
                         f"the map ends after {len(rows)} of the {height} rows its header announces (height {height})")
    if len(rows) > height:
        raise _map_error(name, number + height + 1,
                         f"a row beyond the {height} rows its header announces (height {height})")
    grid = np.zeros((height, width), dtype=bool)
    known = MOVINGAI_FREE | MOVINGAI_BLOCKED
    for r, row in enumerate(rows):
        line = number + r + 1
        if len(row) != width:
            raise _map_error(name, line, f"row {r} has {len(row)} cells but the header says width {width}")
        unknown = set(row) - known
        if unknown:
            letter = min(unknown, key=row.index)
            raise _map_error(name, line, f"unknown terrain {letter!r} at column {row.index(letter)} "
                                         f"(known: {''.join(sorted(known))})")
        grid[r] = [c not in MOVINGAI_FREE for c in row]
    return grid


def load_voxel_map(path: str | os.PathLike) -> np.ndarray:
    """Read a 3-D MovingAI voxel map (``.3dmap``) into a boolean ``(x, y, z)`` grid.

    The format: a first line ``voxel X Y Z`` giving the size, then one line
    ``x y z`` per occupied voxel (0-based).

    Raises:
        AssignmentError: naming the file and line of a malformed size line, a
            voxel line that is not three integers, or a voxel outside the size.
    """
    name = os.fspath(path)
    lines = _read_lines(name, "voxel map")
    if not lines:
        raise _map_error(name, 1, "empty file; expected 'voxel X Y Z'")
    words = lines[0].split()
    if len(words) != 4 or words[0].lower() != "voxel" or not all(w.isdigit() and int(w) > 0 for w in words[1:]):
        raise _map_error(name, 1, f"expected 'voxel X Y Z' with positive integer sizes, got {lines[0].strip()!r}")
    size = tuple(int(w) for w in words[1:])
    grid = np.zeros(size, dtype=bool)
    for number, text in enumerate(lines[1:], start=2):
        fields = text.split()
        if not fields:
            continue
        if len(fields) != 3 or not all(f.lstrip("-").isdigit() for f in fields):
            raise _map_error(name, number, f"expected a voxel 'x y z' of three integers, got {text.strip()!r}")
        voxel = tuple(int(f) for f in fields)
        if not all(0 <= v < s for v, s in zip(voxel, size)):
            raise _map_error(name, number, f"voxel {list(voxel)} is outside the {' x '.join(map(str, size))} map")
        grid[voxel] = True
    return grid


def random_instance(
    shape: tuple[int, ...], density: float, robots: int, goals: int, rng: np.random.Generator
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A random workspace as in the experiments of "It Costs to Get Costs!": obstacles, robots, goals.

    Each cell is an obstacle with probability ``density``; robots and goals
    are drawn without repetition from the free cells of the largest free
    region (so every robot can reach every goal). Returns ``(grid, robot
    cells, goal cells)``.

    Raises:
        AssignmentError: the largest free region has fewer cells than
            ``robots + goals``, or ``density`` is not in [0, 1).
    """
    if not 0.0 <= density < 1.0:
        raise AssignmentError(f"obstacle density must be in [0, 1), got {density}")
    grid = rng.random(shape) < density
    labels, count = ndimage.label(~grid)
    if count == 0:
        raise AssignmentError(f"a {shape} grid at density {density} came out without free cells")
    largest = int(np.argmax(np.bincount(labels.ravel())[1:])) + 1
    free = np.argwhere(labels == largest)
    if len(free) < robots + goals:
        raise AssignmentError(
            f"the largest free region has {len(free)} cells, fewer than {robots} robots + {goals} goals"
        )
    pick = rng.choice(len(free), robots + goals, replace=False)
    return grid, free[pick[:robots]].astype(np.int64), free[pick[robots:]].astype(np.int64)
