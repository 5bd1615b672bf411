"""Input checks: turn user arrays into clean float64 arrays or explain what is wrong.

The checks are written for the hot path (the simulator calls the library every
cycle): a handful of attribute reads and one vectorised finiteness test per
array; the detailed diagnosis only runs once something is known to be wrong.
"""

from __future__ import annotations

import numpy as np

from .errors import AssignmentError

#: Largest coordinate magnitude accepted: squared distances between points this far
#: apart stay finite in float64 (about 1.8e308).
MAX_COORDINATE = 1e150


def _as_float_matrix(value: object, name: str, if_not_numeric: str, if_not_2d: str) -> np.ndarray:
    """``value`` as a 2-D float64 array (any empty input becomes shape ``(0, 0)``); the two
    texts say what ``name`` must be when it is not numeric / not two-dimensional."""
    try:
        raw = np.asarray(value)
        if np.iscomplexobj(raw):
            raise AssignmentError(f"{name} {if_not_numeric}: complex numbers are not coordinates or costs "
                                  "(give the real and imaginary parts as two columns)")
        array = np.asarray(raw, dtype=np.float64)
    except (TypeError, ValueError) as exc:
        if isinstance(exc, AssignmentError):
            raise
        raise AssignmentError(f"{name} {if_not_numeric}: {exc}") from None
    if array.ndim != 2:
        if array.size == 0:
            return array.reshape(0, 0)
        raise AssignmentError(f"{name} {if_not_2d}, got an array of shape {array.shape}")
    return array


def as_points(points: object, name: str) -> np.ndarray:
    """Return ``points`` as a C-contiguous float64 array of shape ``(count, d)``.

    An empty input (``[]`` or shape ``(0,)``) becomes shape ``(0, 0)``; its
    dimension is taken from the other point set by :func:`check_point_pair`.
    """
    array = _as_float_matrix(
        points, name, "must be an array of numbers of shape (count, d)", "must have shape (count, d)"
    )
    if not np.isfinite(array).all():
        bad = np.argwhere(~np.isfinite(array))[0]
        raise AssignmentError(
            f"{name}[{bad[0]}, {bad[1]}] is {float(array[bad[0], bad[1]])}: coordinates must be finite"
        )
    if array.size and np.abs(array).max() > MAX_COORDINATE:
        i, j = np.unravel_index(np.argmax(np.abs(array)), array.shape)
        raise AssignmentError(
            f"{name}[{i}, {j}] is {float(array[i, j]):g}: coordinates must be at most {MAX_COORDINATE:g} "
            "in magnitude (squared distances must stay finite)"
        )
    return np.ascontiguousarray(array)


def check_point_pair(robots: np.ndarray, targets: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Check that both point sets live in the same space; fix up empty sets."""
    if robots.shape[1] == targets.shape[1]:
        if robots.shape[1] == 0 and robots.shape[0] and targets.shape[0]:
            raise AssignmentError("points must have at least one coordinate (d >= 1)")
        return robots, targets
    if robots.shape[0] == 0:
        return robots.reshape(0, targets.shape[1]), targets
    if targets.shape[0] == 0:
        return robots, targets.reshape(0, robots.shape[1])
    raise AssignmentError(
        f"robots are {robots.shape[1]}-dimensional but targets are {targets.shape[1]}-dimensional"
    )


def as_costs(costs: object) -> np.ndarray:
    """Return ``costs`` as a C-contiguous float64 ``(n, m)`` matrix.

    ``+inf`` marks a forbidden pair and is kept; NaN and ``-inf`` are rejected,
    as are negative costs (distances and travel costs cannot be negative, and
    the lexicographic methods order pairs by cost), complex numbers, and finite
    costs so large that the total of an assignment (``min(n, m)`` pairs) would
    overflow to ``inf``: at most the largest float64 divided by ``min(n, m)``.
    """
    matrix = _as_float_matrix(
        costs, "costs", "must be a numeric matrix of shape (robots, targets)", "must be a 2-D matrix (robots, targets)"
    )
    if matrix.size and not (matrix >= 0).all():
        bad_mask = ~(matrix >= 0)
        i, j = np.argwhere(bad_mask)[0]
        value = matrix[i, j]
        what = "NaN" if np.isnan(value) else f"negative ({float(value)})"
        raise AssignmentError(f"costs[{i}, {j}] is {what}: costs must be >= 0, or +inf for a forbidden pair")
    pairs = min(matrix.shape)
    if pairs:
        limit = np.finfo(np.float64).max / pairs
        _refuse_above(matrix, limit, f"with {pairs} pair(s) to assign, finite costs must be at most {limit:.4g} "
                                     "so that the total of an assignment stays finite")
    return np.ascontiguousarray(matrix)


def check_squares(costs: np.ndarray, method: str) -> None:
    """Raise if a finite cost's square, or the total of the squares of an assignment, overflows
    to ``inf`` (methods that square costs)."""
    limit = np.sqrt(np.finfo(np.float64).max / max(1, min(costs.shape)))
    _refuse_above(costs, limit, f"method {method!r} squares the costs, so finite costs must be at most {limit:.4g}")


def _refuse_above(costs: np.ndarray, limit: float, why: str) -> None:
    """AssignmentError naming the first finite cost above ``limit``, and ``why`` it may not be."""
    too_large = np.isfinite(costs) & (costs > limit)
    if too_large.any():
        i, j = np.argwhere(too_large)[0]
        raise AssignmentError(f"costs[{i}, {j}] is {float(costs[i, j]):g}: {why}")
