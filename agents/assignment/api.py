"""The front door: :func:`assign` (points) and :func:`assign_costs` (cost matrices).

Both reduce the problem to "rows <= cols" (transposing when robots outnumber
targets, so that every target gets a robot and the extra robots get ``-1``),
call one solver, and wrap the answer in an :class:`AssignmentResult`.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from .baselines import greedy_assignment, min_sum_assignment, random_assignment
from .errors import AssignmentError
from .geometry import dense_distances, pair_squared_distances
from .graphs import dense_to_graph
from .lexicographic_reference import bitvector_assignment, brute_force_assignment, subset_dp_assignment
from .matching import maximum_matching
from .result import AssignmentResult
from .validation import MAX_COORDINATE, as_costs, as_points, check_point_pair, check_squares
from .scram import bottleneck_assignment, mmd_msd2_assignment, mmd_msd2_points, mmd_msd2_rows, mmdr_assignment, \
    mmdr_points, mmdr_rows

#: Method names accepted by :func:`assign` and :func:`assign_costs`.
METHODS: tuple[str, ...] = ("mmdr", "mmd+msd2", "msd", "msd2", "bottleneck", "greedy", "random")
#: Other spellings of method names.
METHOD_ALIASES: dict[str, str] = {"mmd-msd2": "mmd+msd2"}
#: Algorithms for ``method="mmdr"``; all give assignments with the same sorted distances.
MMDR_ALGORITHMS: tuple[str, ...] = ("fast", "bitvector", "dp", "brute")
#: Geometric problems with at least this many robot-target pairs use the k-d tree path
#: (for mmdr "fast", mmd+msd2 and bottleneck); smaller ones build the dense matrix.
SPARSE_MIN_PAIRS = 150 * 150

_MMDR_SOLVERS: dict[str, Callable[[np.ndarray], np.ndarray]] = {
    "fast": mmdr_assignment,
    "bitvector": bitvector_assignment,
    "dp": subset_dp_assignment,
    "brute": brute_force_assignment,
}


def _method_key(method: str, algorithm: str | None) -> str:
    """Canonical method name, or ``"mmdr/<algorithm>"``; raises on unknown names."""
    key = METHOD_ALIASES.get(method, method)
    if key not in METHODS:
        raise AssignmentError(
            f"unknown assignment method {method!r}; valid methods: {', '.join(METHODS)} "
            f"(alias: {', '.join(METHOD_ALIASES)})"
        )
    if key == "mmdr":
        algorithm = "fast" if algorithm is None else algorithm
        if algorithm not in _MMDR_SOLVERS:
            raise AssignmentError(
                f"unknown mmdr algorithm {algorithm!r}; valid algorithms: {', '.join(MMDR_ALGORITHMS)}"
            )
        return "mmdr/" + algorithm
    if algorithm is not None:
        raise AssignmentError(f"algorithm= only applies to method 'mmdr', not {method!r}")
    return key


def _generator(rng: object) -> np.random.Generator:
    """The random generator of method ``"random"`` from its ``rng=`` argument."""
    if rng is None:
        raise AssignmentError("method 'random' needs rng= (a numpy Generator or an integer seed)")
    try:
        return np.random.default_rng(rng)
    except (TypeError, ValueError) as exc:
        raise AssignmentError(f"rng must be a numpy Generator or a non-negative integer seed, got {rng!r}: {exc}") from None


def _solve_dense(
    key: str, lengths: np.ndarray, squared: np.ndarray | None, generator: np.random.Generator | None
) -> np.ndarray:
    """Target index of every row of a dense problem with ``rows <= cols``.

    ``squared`` (the squared lengths) is needed by ``msd2`` and ``mmd+msd2`` only,
    ``generator`` by ``random`` only.
    """
    if key == "mmd+msd2":
        return mmd_msd2_assignment(lengths, squared)
    if key == "mmdr/fast":
        return mmdr_assignment(lengths)
    if key == "msd":
        return min_sum_assignment(lengths)
    if key == "msd2":
        return min_sum_assignment(squared)
    if key == "bottleneck":
        return bottleneck_assignment(lengths)[1]
    if key == "greedy":
        return greedy_assignment(lengths)
    if key == "random":
        return random_assignment(lengths, generator)
    return _MMDR_SOLVERS[key[5:]](lengths)


def _check_feasible(lengths: np.ndarray, side: str) -> None:
    """Raise unless the finite entries of ``lengths`` (rows <= cols) admit a complete assignment.

    ``side`` names what the rows are ("robots", or "targets" for a transposed problem).
    """
    indptr, indices, pair_lengths = dense_to_graph(lengths)
    n_rows, n_cols = lengths.shape
    col_of_row = np.full(n_rows, -1, dtype=np.int64)
    row_of_col = np.full(n_cols, -1, dtype=np.int64)
    size = maximum_matching(indptr, indices, pair_lengths, np.inf, col_of_row, row_of_col)
    if size < n_rows:
        raise AssignmentError(
            f"no feasible complete assignment: the allowed (finite-cost) pairs let at most "
            f"{size} of the {n_rows} {side} be matched"
        )


def _result(
    col_of_row: np.ndarray, length_of_row: np.ndarray, transposed: bool, n: int, m: int, method: str
) -> AssignmentResult:
    if not transposed:
        return AssignmentResult(col_of_row, length_of_row, method)
    target_of = np.full(n, -1, dtype=np.int64)
    target_of[col_of_row] = np.arange(m)
    distances = np.full(n, np.nan)
    distances[col_of_row] = length_of_row
    return AssignmentResult(target_of, distances, method)


def _empty(n: int, method: str) -> AssignmentResult:
    return AssignmentResult(np.full(n, -1, dtype=np.int64), np.full(n, np.nan), method)


def assign(
    robots: object,
    targets: object,
    method: str = "mmdr",
    *,
    algorithm: str | None = None,
    rng: object = None,
) -> AssignmentResult:
    """Send robots to targets, travelling in straight lines (Euclidean distance).

    Args:
        robots: ``(n, d)`` robot positions (any unit, any d >= 1; 2 or 3 typically).
        targets: ``(m, d)`` target positions in the same frame and unit.
        method: one of :data:`METHODS` (``"mmd-msd2"`` is an alias of ``"mmd+msd2"``).
        algorithm: for ``"mmdr"`` only, one of :data:`MMDR_ALGORITHMS` (default ``"fast"``).
        rng: for ``"random"`` only, a ``numpy.random.Generator`` or an integer seed.

    When ``n <= m`` every robot gets a target; when ``n > m`` every target gets
    a robot and the other robots get ``-1``. Ties are broken deterministically.

    Raises:
        AssignmentError: (a ``ValueError``) for complex, non-finite coordinates or
            coordinates above ``MAX_COORDINATE`` (1e150) in magnitude, arrays
            that are not 2-D, different dimensions d, unknown method or
            algorithm names, ``"random"`` without a valid ``rng``.
    """
    key = _method_key(method, algorithm)
    name = key[:4] if key.startswith("mmdr") else key
    generator = _generator(rng) if key == "random" else None
    # Fast path for clean, non-empty float64 arrays (the simulator's case); anything else goes
    # through validation, which explains what is wrong.
    if (
        type(robots) is np.ndarray
        and type(targets) is np.ndarray
        and robots.dtype == np.float64
        and targets.dtype == np.float64
        and robots.ndim == 2
        and targets.ndim == 2
        and robots.flags.c_contiguous
        and targets.flags.c_contiguous
        and robots.shape[1] == targets.shape[1]
        and robots.size
        and targets.size
        and np.abs(robots).max() <= MAX_COORDINATE  # also False for NaN
        and np.abs(targets).max() <= MAX_COORDINATE
    ):
        r, t = robots, targets
    else:
        r, t = check_point_pair(as_points(robots, "robots"), as_points(targets, "targets"))
    n, m = r.shape[0], t.shape[0]
    if n == 0 or m == 0:
        return _empty(n, name)
    transposed = n > m
    rows, cols = (t, r) if transposed else (r, t)
    n_rows = rows.shape[0]
    if n_rows * cols.shape[0] >= SPARSE_MIN_PAIRS and key in ("mmdr/fast", "mmd+msd2", "bottleneck"):
        from . import sparse

        solver = {"mmdr/fast": sparse.sparse_mmdr, "mmd+msd2": sparse.sparse_mmd_msd2}.get(
            key, sparse.sparse_bottleneck
        )
        col_of_row, length_of_row = solver(np.ascontiguousarray(rows), np.ascontiguousarray(cols))
        return _result(col_of_row, length_of_row, transposed, n, m, name)
    if generator is not None:  # random: needs no distance matrix
        col_of_row = generator.permutation(cols.shape[0])[:n_rows]
        length_of_row = np.sqrt(pair_squared_distances(rows, cols, np.arange(n_rows), col_of_row))
        return _result(col_of_row, length_of_row, transposed, n, m, name)
    lengths, squared = dense_distances(rows, cols)
    col_of_row = _solve_dense(key, lengths, squared, None)
    return _result(col_of_row, lengths[np.arange(n_rows), col_of_row], transposed, n, m, name)


def dense_target_of(robots: np.ndarray, targets: np.ndarray, method: str,
                    scale: np.ndarray | None = None) -> np.ndarray:
    """``assign(robots, targets, method).target_of`` for a caller whose inputs are already
    clean, without the checks and the result object: for per-cycle callers such as the
    soccer role assigners, where those cost as much as solving a 10 x 10 problem.

    ``robots`` (n, d) and ``targets`` (m, d) must be finite float64 arrays with
    ``0 < n <= m`` and fewer than :data:`SPARSE_MIN_PAIRS` pairs; ``method`` one of
    :data:`METHODS` but ``"random"`` (``"mmdr"`` uses the fast algorithm). ``scale`` (n,)
    finite and positive, or None: robot i's distances are multiplied by ``scale[i]`` (travel
    times of robots of different speeds, in metres at a reference speed); None leaves them
    plain, bit for bit. Nothing is checked: give anything else to :func:`assign` or
    :func:`assign_costs`.
    """
    if method == "mmdr":
        return mmdr_points(robots, targets, _NO_SCALE if scale is None else scale)
    if method == "mmd+msd2":
        return mmd_msd2_points(robots, targets, _NO_SCALE if scale is None else scale)
    lengths, squared = dense_distances(robots, targets)
    if scale is not None:
        lengths = lengths * scale[:, None]
        squared = lengths * lengths
    return _solve_dense(_DENSE_KEYS[method], lengths, squared, None)


def dense_targets_of_rows(robots: np.ndarray, targets: np.ndarray, method: str,
                          scale: np.ndarray | None = None) -> np.ndarray:
    """:func:`dense_target_of` of many independent problems of one size: ``robots`` (problems,
    n, d) and ``targets`` (problems, m, d), C-contiguous, each pair as :func:`dense_target_of`
    takes it; returns (problems, n) target indices, row ``r`` bit for bit
    ``dense_target_of(robots[r], targets[r], method, scale)``. MMDR and MMD+MSD² solve all
    problems in one compiled call (e.g. every player of a team assigning roles on its own view)."""
    plain = _NO_SCALE if scale is None else scale
    if method == "mmdr":
        out = np.empty(robots.shape[:2], dtype=np.int64)
        mmdr_rows(robots, targets, plain, out)
        return out
    if method == "mmd+msd2":
        return mmd_msd2_rows(robots, targets, plain)
    out = np.empty(robots.shape[:2], dtype=np.int64)
    for r in range(robots.shape[0]):
        out[r] = dense_target_of(robots[r], targets[r], method, scale)
    return out


_NO_SCALE = np.empty(0)
"""An empty scale: plain distances."""
_DENSE_KEYS = {method: ("mmdr/fast" if method == "mmdr" else method) for method in METHODS if method != "random"}


def assign_costs(
    costs: object,
    method: str = "mmdr",
    *,
    algorithm: str | None = None,
    rng: object = None,
) -> AssignmentResult:
    """Assign robots (rows) to targets (columns) of a travel-cost matrix.

    ``costs[i, j] >= 0`` is the cost (distance, time...) of sending robot ``i``
    to target ``j``; ``+inf`` forbids the pair. "Squared distance" objectives
    (msd2, mmd+msd2) square the costs. ``result.distances`` holds the costs of
    the chosen pairs. Arguments and rectangular behaviour as in :func:`assign`.

    Raises:
        AssignmentError: for NaN or negative costs, a matrix that is not 2-D,
            unknown method or algorithm names, ``"random"`` without a valid
            ``rng``, finite costs whose total over an assignment would overflow
            (above the largest float64 divided by ``min(n, m)``), finite costs
            whose squares or their total overflow (msd2, mmd+msd2), complex
            costs, or
            forbidden pairs that leave no complete assignment (the message
            says how many robots could be served).
    """
    key = _method_key(method, algorithm)
    name = key[:4] if key.startswith("mmdr") else key
    generator = _generator(rng) if key == "random" else None
    matrix = as_costs(costs)
    n, m = matrix.shape
    if n == 0 or m == 0:
        return _empty(n, name)
    transposed = n > m
    lengths = np.ascontiguousarray(matrix.T) if transposed else matrix
    if not np.isfinite(lengths).all():
        _check_feasible(lengths, "targets" if transposed else "robots")
    squared = None
    if key in ("msd2", "mmd+msd2"):
        check_squares(matrix, key)
        squared = lengths * lengths
    col_of_row = _solve_dense(key, lengths, squared, generator)
    return _result(col_of_row, lengths[np.arange(lengths.shape[0]), col_of_row], transposed, n, m, name)
