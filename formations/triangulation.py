"""Delaunay triangulation of the samples' ball positions, with clear errors.

Qhull fails with long, cryptic messages on degenerate input; the checks here
catch those cases first (too few samples, all on one line, near-duplicates
dropped by Qhull, needle triangles) and name the samples at fault.
"""

from __future__ import annotations

import numpy as np
from scipy.spatial import Delaunay, QhullError

from formations.errors import FormationError

COLLINEAR_TOLERANCE = 1e-6
"""Relative spread (smaller / larger principal standard deviation of the ball
positions) below which the samples are treated as lying on one line."""


def triangulate(balls: np.ndarray, source: str) -> Delaunay:
    """Return the Delaunay triangulation of *balls* ((n, 2) array, metres).

    Raises :class:`FormationError` when no usable triangulation exists.
    """
    n = len(balls)
    if n < 3:
        raise FormationError(source, f"a formation needs at least 3 samples to be triangulated, got {n}")
    if _flatness(balls) <= COLLINEAR_TOLERANCE:
        raise FormationError(
            source, f"the ball positions of all {n} samples lie on one line, so they cannot be triangulated"
        )
    try:
        tri = Delaunay(balls)
    except (QhullError, ValueError) as error:  # pragma: no cover - guarded by the checks above
        first_line = str(error).strip().splitlines()[0] if str(error).strip() else type(error).__name__
        raise FormationError(source, f"triangulation failed: {first_line}") from error
    if len(tri.coplanar):
        sample, _, nearest = (int(v) for v in tri.coplanar[0])
        raise FormationError(
            source,
            f"ball position (nearly) coincides with that of sample {nearest}, so it cannot be triangulated",
            f"sample {sample}",
        )
    if not np.all(np.isfinite(tri.transform)):
        bad = int(np.flatnonzero(~np.isfinite(tri.transform).all(axis=(1, 2)))[0])
        corners = ", ".join(str(int(i)) for i in tri.simplices[bad])
        raise FormationError(source, f"samples {corners} make a degenerate (flat) triangle")
    return tri


def hull_edges(tri: Delaunay) -> np.ndarray:
    """Sample indices (E, 2) of the convex hull's boundary segments."""
    return np.asarray(tri.convex_hull, dtype=np.intp)


def _flatness(points: np.ndarray) -> float:
    """Ratio of the smaller to the larger principal spread of (n, 2) points
    (0 when they lie on one line). Closed form for the 2 x 2 covariance, which
    avoids a LAPACK call (and its thread start-up) for a tiny problem."""
    dx = points[:, 0] - points[:, 0].mean()
    dy = points[:, 1] - points[:, 1].mean()
    sxx, syy, sxy = float(np.sum(dx * dx)), float(np.sum(dy * dy)), float(np.sum(dx * dy))
    mean = 0.5 * (sxx + syy)
    spread = float(np.hypot(0.5 * (sxx - syy), sxy))
    largest, smallest = mean + spread, max(mean - spread, 0.0)
    return 0.0 if largest <= 0.0 else float(np.sqrt(smallest / largest))
