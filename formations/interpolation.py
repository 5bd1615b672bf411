"""Piecewise-linear interpolation over a Delaunay triangulation, fast.

Given sample points p_i (the ball positions) with value vectors v_i (the
flattened player positions), the value at a query point q is:

* inside the convex hull of the samples: the barycentric combination of the
  three samples of the triangle containing q (exact at every sample, linear in
  each triangle, continuous across triangle edges);
* outside the hull: the value at q's projection onto the hull boundary, i.e.
  the linear interpolation between the two samples of the nearest hull edge.
  The projection onto a convex set is continuous, so values stay continuous on
  and beyond the hull (a nearest-sample rule would make targets jump).

Speed: teams query once per cycle per formation, so a single query must cost a
few microseconds. ``scipy.spatial.Delaunay.find_simplex`` has a large fixed
overhead per call, so single queries instead use

* a uniform grid over the hull's bounding box whose cells list the triangles
  that may overlap them (the one containing the cell centre first), tested
  on the precomputed inverse barycentric transforms, and the hull edges that
  may be nearest (for points outside the hull); and
* one precomputed affine map per triangle, values = A_t @ (x, y, 1), since
  barycentric interpolation is affine inside a triangle;

all in one compiled call (:func:`formations.interpolation_kernels.value_kernel`).

Many queries at once use ``find_simplex`` (which amortises its overhead) and
gathers of the three corner values.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.spatial import Delaunay

from formations.errors import FormationInputError
from formations.interpolation_kernels import (QueryTables, find_triangle_kernel, grid_cell, nearest_edge_kernel,
                                              value_kernel)

GRID_CELLS_ALONG_LONG_SIDE = 64
"""Resolution of the triangle lookup grid (cells along the longer side of the
hull's bounding box). Finer grids list fewer candidate triangles per cell."""

OUTSIDE_GRID_MARGIN = 0.25
"""The lookup grid reaches this fraction of the hull's larger extent beyond
the hull's bounding box, so that balls somewhat outside the samples (out of
play) are projected onto the hull as fast as balls inside are located."""


class TriangleInterpolator:
    """Barycentric interpolation of (n, m) sample values over a triangulation."""

    def __init__(self, tri: Delaunay, values: np.ndarray) -> None:
        self.tri = tri
        self.values = np.ascontiguousarray(values, dtype=np.float64)
        simplices = np.asarray(tri.simplices, dtype=np.intp)
        transform = np.asarray(tri.transform, dtype=np.float64)
        self._simplices = simplices
        self._transform = transform
        self._affine = _affine_maps(simplices, transform, self.values)
        self._affine_transposed = np.ascontiguousarray(self._affine.transpose(0, 2, 1))
        self._build_grid(tri.points)
        self._build_hull(tri)
        self._build_flat_tables()

    # ------------------------------------------------------------------ setup
    def _build_grid(self, points: np.ndarray) -> None:
        """Lay a uniform grid over the hull's bounding box plus a margin.

        Each cell lists the triangles whose bounding box overlaps it (the one
        containing the cell centre first) and the hull edges that can be the
        nearest edge of some point in the cell.
        """
        lo = points.min(axis=0)
        hi = points.max(axis=0)
        extent = float(max(hi - lo))
        cell = extent / GRID_CELLS_ALONG_LONG_SIDE
        margin = OUTSIDE_GRID_MARGIN * extent
        lo = lo - margin
        hi = hi + margin
        nx = max(1, int(math.ceil((hi[0] - lo[0]) / cell)))
        ny = max(1, int(math.ceil((hi[1] - lo[1]) / cell)))
        self._grid_origin = (float(lo[0]), float(lo[1]))
        self._grid_origin_array = lo
        self._grid_inv_cell = 1.0 / cell
        self._grid_shape = (nx, ny)
        cells: list[list[int]] = [[] for _ in range(nx * ny)]
        corners = points[self._simplices]  # (T, 3, 2)
        tlo = np.floor((corners.min(axis=1) - lo) / cell).astype(int)
        thi = np.floor((corners.max(axis=1) - lo) / cell).astype(int)
        tlo = np.clip(tlo, 0, [nx - 1, ny - 1])
        thi = np.clip(thi, 0, [nx - 1, ny - 1])
        for t, ((x0, y0), (x1, y1)) in enumerate(zip(tlo.tolist(), thi.tolist())):
            for iy in range(y0, y1 + 1):
                row = iy * nx
                for ix in range(x0, x1 + 1):
                    cells[row + ix].append(t)
        # Put the triangle that contains the cell centre first: most queries stop there.
        ix, iy = np.meshgrid(np.arange(nx), np.arange(ny))
        centres = np.column_stack(((ix.ravel() + 0.5) * cell + lo[0], (iy.ravel() + 0.5) * cell + lo[1]))
        central = self.tri.find_simplex(centres)
        for k, t in enumerate(central.tolist()):
            if t >= 0 and cells[k] and cells[k][0] != t:
                cells[k].remove(t)
                cells[k].insert(0, t)
        self._cells = [tuple(c) for c in cells]
        self._cell_centres = centres
        self._cell_half_diagonal = cell * math.sqrt(0.5)

    def _build_hull(self, tri: Delaunay) -> None:
        edges = np.asarray(tri.convex_hull, dtype=np.intp)
        start = tri.points[edges[:, 0]]
        delta = tri.points[edges[:, 1]] - start
        length2 = np.einsum("ij,ij->i", delta, delta)
        self._hull_edges = edges
        self._hull_start = start
        self._hull_delta = delta
        self._hull_inv_length2 = 1.0 / length2
        self._edge_start_values = self.values[edges[:, 0]]
        self._edge_delta_values = self.values[edges[:, 1]] - self._edge_start_values
        # Candidate nearest edges per grid cell. Distance to an edge is
        # 1-Lipschitz, so the nearest edge of any point of a cell is within
        # 2 * half-diagonal of the nearest edge of the cell's centre.
        centres = self._cell_centres
        _, dist2 = _nearest_on_segments(centres[:, 0:1], centres[:, 1:2], start, delta, self._hull_inv_length2)
        dist = np.sqrt(dist2)
        bound = dist.min(axis=1, keepdims=True) + 2.0 * self._cell_half_diagonal + 1e-9
        count = np.count_nonzero(dist <= bound, axis=1)
        # The candidates are the nearest `count` edges of each cell's centre.
        order = np.argsort(dist, axis=1, kind="stable")
        self._cell_edges = [tuple(row[:c]) for row, c in zip(order.tolist(), count.tolist())]
        width = int(count.max())
        self._cell_edge_count = count.astype(np.intp)
        table = order[:, :width].copy()
        unused = np.arange(width)[None, :] >= count[:, None]
        table[unused] = np.broadcast_to(order[:, :1], table.shape)[unused]
        self._cell_edge_table = table
        # The triangle that owns each hull edge: Delaunay.neighbors is -1
        # opposite a boundary edge.
        owner = {}
        for t, (simplex, neighbours) in enumerate(zip(tri.simplices.tolist(), tri.neighbors.tolist())):
            for k in range(3):
                if neighbours[k] == -1:
                    owner[frozenset(simplex[:k] + simplex[k + 1 :])] = t
        self._edge_triangle = np.array([owner[frozenset(e)] for e in edges.tolist()], dtype=np.intp)

    def _build_flat_tables(self) -> None:
        """The grid's triangle and edge lists as flat arrays (offsets per cell), for the
        compiled single query :func:`value_kernel`."""
        def flat(lists: list[tuple[int, ...]]) -> tuple[np.ndarray, np.ndarray]:
            offsets = np.zeros(len(lists) + 1, dtype=np.int64)
            offsets[1:] = np.cumsum([len(items) for items in lists])
            items = np.fromiter((i for row in lists for i in row), dtype=np.int64, count=int(offsets[-1]))
            return offsets, items

        self._cell_offsets, self._cell_triangles = flat(self._cells)
        self._edge_offsets, self._cell_edge_items = flat(self._cell_edges)
        self._bary_table = np.ascontiguousarray(self._transform.reshape(len(self._transform), 6))
        self._grid_table = np.array([self._grid_origin[0], self._grid_origin[1], self._grid_inv_cell])
        self._edge_starts = np.ascontiguousarray(self._hull_start, dtype=np.float64)
        self._edge_deltas = np.ascontiguousarray(self._hull_delta, dtype=np.float64)
        self._edge_inv_length2 = np.ascontiguousarray(self._hull_inv_length2, dtype=np.float64)
        self._edge_values = np.ascontiguousarray(self._edge_start_values)
        self._edge_value_deltas = np.ascontiguousarray(self._edge_delta_values)
        nx, ny = self._grid_shape
        self._tables = QueryTables(
            grid=self._grid_table, nx=nx, ny=ny, cell_offsets=self._cell_offsets, cell_triangles=self._cell_triangles,
            bary=self._bary_table, affine=self._affine, edge_offsets=self._edge_offsets,
            cell_edges=self._cell_edge_items, starts=self._edge_starts, deltas=self._edge_deltas,
            inv_length2=self._edge_inv_length2, edge_values=self._edge_values,
            edge_value_deltas=self._edge_value_deltas)
        """The compiled query's tables."""

    # ---------------------------------------------------------------- queries
    def find_triangle(self, x: float, y: float) -> int:
        """Index of a triangle containing (x, y), or -1 outside the hull."""
        nx, ny = self._grid_shape
        return find_triangle_kernel(x, y, self._grid_table, nx, ny, self._cell_offsets, self._cell_triangles,
                                    self._bary_table)[1]

    def nearest_hull_point(self, x: float, y: float) -> tuple[int, float]:
        """Nearest hull edge to (x, y) and the position s in [0, 1] along it."""
        nx, ny = self._grid_shape
        cell = grid_cell(x, y, self._grid_table, nx, ny)
        return nearest_edge_kernel(x, y, cell, self._edge_offsets, self._cell_edge_items, self._edge_starts,
                                   self._edge_deltas, self._edge_inv_length2)

    def value(self, x: float, y: float) -> np.ndarray:
        """Interpolated (m,) value at one point (a new array): one compiled call doing what
        :meth:`find_triangle` and :meth:`nearest_hull_point` do, then the triangle's affine map
        or the hull edge's interpolation."""
        if not (math.isfinite(x) and math.isfinite(y)):
            raise FormationInputError(f"query point must be finite, got ({x}, {y})")
        out = np.empty(self.values.shape[1])
        value_kernel(x, y, self._tables, out)
        return out

    @property
    def tables(self) -> QueryTables:
        """:func:`~formations.interpolation_kernels.value_kernel`'s tables."""
        return self._tables

    def values_many(self, points: np.ndarray) -> np.ndarray:
        """Interpolated values (k, m) at points (k, 2).

        Points outside the hull are replaced by their projection onto it and
        evaluated in the triangle owning the nearest hull edge; then the
        points are grouped by triangle and each group is one small matrix
        product with that triangle's affine map.
        """
        points = np.ascontiguousarray(points, dtype=np.float64)
        if points.ndim != 2 or points.shape[1] != 2:
            raise FormationInputError(f"query points must have shape (k, 2), got {points.shape}")
        if not np.isfinite(points).all():
            bad = int(np.flatnonzero(~np.isfinite(points).all(axis=1))[0])
            raise FormationInputError(f"query point {bad} is not finite: {points[bad].tolist()}")
        k = len(points)
        triangle = self.tri.find_simplex(points)
        homogeneous = np.empty((k, 3), dtype=np.float64)
        homogeneous[:, :2] = points
        homogeneous[:, 2] = 1.0
        outside = np.flatnonzero(triangle < 0)
        if len(outside):
            edge, s = self._project_many(points[outside])
            homogeneous[outside, :2] = self._hull_start[edge] + s[:, None] * self._hull_delta[edge]
            triangle[outside] = self._edge_triangle[edge]
        return self._evaluate_grouped(triangle, homogeneous)

    def _evaluate_grouped(self, triangle: np.ndarray, homogeneous: np.ndarray) -> np.ndarray:
        """A_t @ (x, y, 1) for every point, one matrix product per triangle."""
        order = np.argsort(triangle, kind="stable")
        ends = np.cumsum(np.bincount(triangle, minlength=len(self._affine))).tolist()
        sorted_points = homogeneous[order]
        sorted_values = np.empty((len(triangle), self.values.shape[1]), dtype=np.float64)
        start = 0
        for t, end in enumerate(ends):
            if end > start:
                np.matmul(sorted_points[start:end], self._affine_transposed[t], out=sorted_values[start:end])
                start = end
        values = np.empty_like(sorted_values)
        values[order] = sorted_values
        return values

    def _project_many(self, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Nearest hull edge index (k,) and position along it (k,) for each point.

        Inside the lookup grid only the cell's candidate edges are tried, in
        rounds: round j handles the points whose cell has more than j
        candidates (most cells have two or three).
        """
        k = len(points)
        nx, ny = self._grid_shape
        cell_xy = np.floor((points - self._grid_origin_array) * self._grid_inv_cell).astype(np.intp)
        in_grid = (cell_xy[:, 0] >= 0) & (cell_xy[:, 0] < nx) & (cell_xy[:, 1] >= 0) & (cell_xy[:, 1] < ny)
        cell = np.where(in_grid, cell_xy[:, 1] * nx + cell_xy[:, 0], 0)
        count = np.where(in_grid, self._cell_edge_count[cell], len(self._hull_start))
        best_edge = np.zeros(k, dtype=np.intp)
        best_s = np.zeros(k, dtype=np.float64)
        best_d2 = np.full(k, np.inf)
        table_width = self._cell_edge_table.shape[1]
        for j in range(int(count.max(initial=0))):
            rows = np.flatnonzero(count > j)
            # Round j tries a cell's j-th candidate; points beyond the grid try hull edge j.
            edge = np.where(in_grid[rows], self._cell_edge_table[cell[rows], min(j, table_width - 1)], j)
            s, d2 = _nearest_on_segments(
                points[rows, 0],
                points[rows, 1],
                self._hull_start[edge],
                self._hull_delta[edge],
                self._hull_inv_length2[edge],
            )
            better = d2 < best_d2[rows]
            rows = rows[better]
            best_d2[rows] = d2[better]
            best_edge[rows] = edge[better]
            best_s[rows] = s[better]
        return best_edge, best_s

    def hull_projection(self, x: float, y: float) -> tuple[float, float]:
        """The point of the hull (boundary or interior) nearest to (x, y)."""
        if self.find_triangle(x, y) >= 0:
            return x, y
        edge, s = self.nearest_hull_point(x, y)
        (ax, ay), (dx, dy) = self._hull_start[edge].tolist(), self._hull_delta[edge].tolist()
        return ax + s * dx, ay + s * dy


def _affine_maps(simplices: np.ndarray, transform: np.ndarray, values: np.ndarray) -> np.ndarray:
    """Per triangle, the (m, 3) matrix A with value(q) = A @ (qx, qy, 1) inside it.

    With barycentric coordinates (b0, b1) = T^-1 (q - r) of the corners 0 and 1
    (r being corner 2), value = v2 + [v0 - v2, v1 - v2] T^-1 (q - r).
    """
    v0 = values[simplices[:, 0]]
    v1 = values[simplices[:, 1]]
    v2 = values[simplices[:, 2]]
    differences = np.stack((v0 - v2, v1 - v2), axis=2)  # (T, m, 2)
    linear = differences @ transform[:, :2, :]  # (T, m, 2)
    offset = v2 - np.einsum("tmj,tj->tm", linear, transform[:, 2, :])
    return np.ascontiguousarray(np.concatenate((linear, offset[:, :, None]), axis=2))


def _nearest_on_segments(
    px: np.ndarray, py: np.ndarray, start: np.ndarray, delta: np.ndarray, inv_length2: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Position s in [0, 1] along, and squared distance to, the nearest point
    of segments (start, start + delta), broadcasting the query coordinates
    *px*, *py* against the segment arrays (``start[..., 0]`` etc.)."""
    rx = px - start[..., 0]
    ry = py - start[..., 1]
    dx = delta[..., 0]
    dy = delta[..., 1]
    s = (rx * dx + ry * dy) * inv_length2
    np.clip(s, 0.0, 1.0, out=s)
    ex = rx - s * dx
    ey = ry - s * dy
    return s, ex * ex + ey * ey
