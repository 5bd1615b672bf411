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

import functools
import itertools
import os
from dataclasses import dataclass

import numpy as np
from numba import njit
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
        padded = np.ones(tuple(side + 2 for side in self.shape), dtype=bool)
        padded[(slice(1, -1),) * self.ndim] = self.blocked
        self.padded_shape = padded.shape
        self.strides = np.array(
            [int(np.prod(padded.shape[axis + 1:])) for axis in range(self.ndim)], dtype=np.int64
        )
        self.moves = _moves(padded, self.strides)
        self.component = _label_regions(padded, self.strides)

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


@functools.lru_cache(maxsize=None)
def _move_table(ndim: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The 8 (2-D) or 26 (3-D) moves: ``(steps, half-unit costs, boxes)``.

    ``steps`` is ``(k, ndim)``: the coordinate change of each move. Bit ``j`` of
    ``boxes[m]`` is set when move ``j`` leads to a cell of move ``m``'s box (the cells a
    move must find free: every non-empty part of its step, the target included).
    """
    steps = [d for d in itertools.product((-1, 0, 1), repeat=ndim) if any(d)]
    costs = [STEP_HALF_COST[sum(map(abs, d))] for d in steps]
    boxes = []
    for step in steps:
        parts = itertools.product(*[(0, d) if d else (0,) for d in step])
        boxes.append(sum(1 << steps.index(part) for part in parts if any(part)))
    table = (np.array(steps, dtype=np.int64), np.array(costs, dtype=np.int64), np.array(boxes, dtype=np.uint32))
    for array in table:
        array.setflags(write=False)
    return table


def _moves(padded: np.ndarray, strides: np.ndarray) -> Moves:
    """Offsets, costs and per-cell legality of the 8 (2-D) or 26 (3-D) moves of ``padded``.

    A move is legal from a cell when every cell of the box between the cell and the
    move's target is free (the border of obstacles keeps every move of a free cell
    inside the array).
    """
    steps, costs, boxes = _move_table(padded.ndim)
    offsets = steps @ strides
    free = (~padded).ravel().view(np.uint8)
    return Moves(offsets, costs.copy(), _allowed_moves(free, int(strides.sum()), offsets, boxes))


@njit(cache=True, nogil=True)
def _allowed_moves(free: np.ndarray, border: int, offsets: np.ndarray,
                   boxes: np.ndarray) -> np.ndarray:  # pragma: no cover - compiled
    """Per cell, bit ``m`` set when the cell is free and so is every neighbour of
    ``boxes[m]`` (neighbours as in ``offsets``). Only cells ``border`` or more from either end
    have neighbours looked up: no free cell lies on the obstacle border. Unsigned indices
    (no wrap-around check) and one pass per neighbour and per move, so that the loops can
    run on vectors.
    """
    n = free.shape[0]
    first = np.uint64(border)
    around = np.zeros(n, dtype=np.uint32)  # bit k: the neighbour offsets[k] away is free
    for k in range(offsets.shape[0]):
        start = np.uint64(border + offsets[k])
        bit = np.uint32(k)
        for c in range(n - 2 * border):
            around[first + np.uint64(c)] |= np.uint32(free[start + np.uint64(c)]) << bit
    allowed = np.zeros(n, dtype=np.uint32)
    for m in range(boxes.shape[0]):
        box = boxes[m]
        bit = np.uint32(m)
        for c in range(n):
            allowed[c] |= np.uint32(((around[c] & box) == box) & (free[c] != 0)) << bit
    return allowed


def _label_regions(padded: np.ndarray, strides: np.ndarray) -> np.ndarray:
    """Labels (1, 2, ...) of the axis-connected free regions of ``padded``, 0 on obstacles."""
    return _flood_labels((~padded).ravel().view(np.uint8), strides).reshape(padded.shape)


@njit(cache=True, nogil=True)
def _flood_labels(free: np.ndarray, strides: np.ndarray) -> np.ndarray:  # pragma: no cover - compiled
    """Label each free cell with its axis-connected region (a flood fill from each unlabelled
    free cell in turn); obstacles get 0. The obstacle border keeps every step inside."""
    labels = np.zeros(free.shape[0], dtype=np.int32)
    stack = np.empty(free.shape[0], dtype=np.int64)
    count = 0
    for seed in range(free.shape[0]):
        if free[seed] == 0 or labels[seed] != 0:
            continue
        count += 1
        labels[seed] = count
        stack[0] = seed
        top = 1
        while top > 0:
            top -= 1
            cell = stack[top]
            for stride in strides:
                for nb in (cell - stride, cell + stride):
                    if free[nb] != 0 and labels[nb] == 0:
                        labels[nb] = count
                        stack[top] = nb
                        top += 1
    return labels


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
