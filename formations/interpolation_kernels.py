"""The compiled single queries of :class:`formations.interpolation.TriangleInterpolator`: the
triangle containing a point (a grid of candidate triangles), the nearest hull edge (a grid of
candidate edges), and the interpolated value, for one point or each of many, each in one call.
The interpolated value takes an interpolator's tables as one named tuple (:class:`QueryTables`),
read by field name."""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit, types
from numba.extending import intrinsic

INSIDE_TOLERANCE = 1e-12
"""Barycentric coordinates down to minus this count as inside a triangle."""


class QueryTables(NamedTuple):
    """An interpolator's tables for :func:`value_kernel` (made once with the interpolator)."""

    grid: np.ndarray
    """(3,) the lookup grid's origin x, y (m) and inverse cell size (1/m)."""
    nx: int
    """Grid cells along x."""
    ny: int
    """Grid cells along y."""
    cell_offsets: np.ndarray
    """(cells + 1,) each cell's first entry in ``cell_triangles``."""
    cell_triangles: np.ndarray
    """The candidate triangles of each cell, one cell after the other."""
    bary: np.ndarray
    """(triangles, 6) each triangle's inverse transform (four entries) and reference corner."""
    affine: np.ndarray
    """(triangles, values, 3) each triangle's affine map of (x, y, 1) to the values."""
    edge_offsets: np.ndarray
    """(cells + 1,) each cell's first entry in ``cell_edges``."""
    cell_edges: np.ndarray
    """The candidate hull edges of each cell, one cell after the other."""
    starts: np.ndarray
    """(edges, 2) each hull edge's start (m)."""
    deltas: np.ndarray
    """(edges, 2) each hull edge's end minus its start (m)."""
    inv_length2: np.ndarray
    """(edges,) one over each hull edge's squared length."""
    edge_values: np.ndarray
    """(edges, values) the values at each hull edge's start."""
    edge_value_deltas: np.ndarray
    """(edges, values) the values at each hull edge's end minus those at its start."""


@intrinsic
def fma(typingctx, a, b, c):  # pragma: no cover - compiled
    """a * b + c with one rounding (the processor's fused multiply-add)."""
    signature = types.float64(types.float64, types.float64, types.float64)

    def codegen(context, builder, sig, args):
        return builder.fma(*args)

    return signature, codegen


@njit(cache=True, nogil=True)
def grid_cell(x: float, y: float, grid: np.ndarray, nx: int, ny: int) -> int:  # pragma: no cover - compiled
    """The lookup grid's cell holding (x, y), or -1 beyond the grid (``grid``: origin x, y and
    the inverse cell size)."""
    fx = (x - grid[0]) * grid[2]
    fy = (y - grid[1]) * grid[2]
    if 0.0 <= fx < nx and 0.0 <= fy < ny:
        return int(fy) * nx + int(fx)
    return -1


@njit(cache=True, nogil=True)
def find_triangle_kernel(x: float, y: float, grid: np.ndarray, nx: int, ny: int, cell_offsets: np.ndarray,
                          cell_triangles: np.ndarray, bary: np.ndarray) -> tuple[int, int]:  # pragma: no cover
    """(grid cell, triangle) of (x, y): the first of the cell's triangles whose barycentric
    coordinates (``bary`` rows: the inverse transform's four entries and the reference
    corner) are all at least ``-INSIDE_TOLERANCE``; triangle -1 when none is (outside the
    hull), cell -1 beyond the grid."""
    cell = grid_cell(x, y, grid, nx, ny)
    if cell < 0:
        return cell, -1  # the grid reaches beyond the hull, so this point is outside
    for k in range(cell_offsets[cell], cell_offsets[cell + 1]):
        t = cell_triangles[k]
        dx = x - bary[t, 4]
        dy = y - bary[t, 5]
        b0 = bary[t, 0] * dx + bary[t, 1] * dy
        if b0 < -INSIDE_TOLERANCE:
            continue
        b1 = bary[t, 2] * dx + bary[t, 3] * dy
        if b1 < -INSIDE_TOLERANCE or b0 + b1 > 1.0 + INSIDE_TOLERANCE:
            continue
        return cell, t
    return cell, -1


@njit(cache=True, nogil=True)
def nearest_edge_kernel(x: float, y: float, cell: int, edge_offsets: np.ndarray, cell_edges: np.ndarray,
                         starts: np.ndarray, deltas: np.ndarray,
                         inv_length2: np.ndarray) -> tuple[int, float]:  # pragma: no cover - compiled
    """The hull edge nearest to (x, y) among the grid cell's candidates (every edge when
    ``cell`` is -1) and the position s in [0, 1] of the nearest point along it (the first
    edge among equally near ones)."""
    first, last = (edge_offsets[cell], edge_offsets[cell + 1]) if cell >= 0 else (0, starts.shape[0])
    best = math.inf
    best_edge = 0
    best_s = 0.0
    for k in range(first, last):
        e = cell_edges[k] if cell >= 0 else k
        ax, ay, dx, dy = starts[e, 0], starts[e, 1], deltas[e, 0], deltas[e, 1]
        s = ((x - ax) * dx + (y - ay) * dy) * inv_length2[e]
        if s < 0.0:
            s = 0.0
        elif s > 1.0:
            s = 1.0
        ex = ax + s * dx - x
        ey = ay + s * dy - y
        dist2 = ex * ex + ey * ey
        if dist2 < best:
            best = dist2
            best_edge = e
            best_s = s
    return best_edge, best_s


@njit(cache=True, nogil=True)
def value_kernel(x: float, y: float, tables: QueryTables, out: np.ndarray) -> None:  # pragma: no cover - compiled
    """:meth:`TriangleInterpolator.value` at (x, y) into ``out``: inside the hull the
    triangle's affine map ``A @ (x, y, 1)``, evaluated as ``fma(A0, x, A1 * y) + A2`` (the
    order and roundings of the BLAS matrix-vector kernel this query used before it was
    compiled, on x86-64, so matches did not change); else the values interpolated along the
    nearest hull edge."""
    cell, t = find_triangle_kernel(x, y, tables.grid, tables.nx, tables.ny, tables.cell_offsets,
                                   tables.cell_triangles, tables.bary)
    if t >= 0:
        affine = tables.affine
        for i in range(out.shape[0]):
            out[i] = fma(affine[t, i, 0], x, affine[t, i, 1] * y) + affine[t, i, 2]
        return
    edge, s = nearest_edge_kernel(x, y, cell, tables.edge_offsets, tables.cell_edges, tables.starts, tables.deltas,
                                  tables.inv_length2)
    edge_values, edge_value_deltas = tables.edge_values, tables.edge_value_deltas
    for i in range(out.shape[0]):
        out[i] = edge_values[edge, i] + s * edge_value_deltas[edge, i]
