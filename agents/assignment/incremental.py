"""Incremental assignment with a tunable reassignment trade-off.

From "Tunable Routing Solutions for Multi-Robot Navigation via the Assignment
Problem: A 3D Representation of the Matching Graph" (Liu and Shell). A team
of interchangeable robots is *deployed*: every robot stands on its target. New
robot-target pairs arrive; instead of re-solving, one stage of the Hungarian
method per new pair (an augmenting path on the existing labels) routes the
team: the new robot takes some target, the robot standing there moves on to
another, and so on until the new target is taken. The matched edges of the
path are the moves.

Formulation (the paper's, maximising utility): the utility of sending robot
``r`` to target ``j`` is minus their distance, ``u_rj = -|p_r - q_j|``, on the
edges of the graph only (missing edges forbid the pair). A deployed robot's
edge to its own target (the "vertical" edge of the paper's 3D picture) is a
virtual edge worth ``u_rr = max_{j != r} u_rj`` (minus the distance to its
nearest neighbouring target), scaled by ``lam``:

* ``lam = 0``: staying costs nothing, so a route costs exactly its travelled
  distance and the stage finds the shortest route (on a complete graph the new
  robot drives straight to the new target; on a sparse graph the route is a
  shortest path, Dijkstra's). Least total travel, few robots disturbed.
* ``lam = 1``: staying is worth no more than hopping to the nearest neighbour,
  so long chains of short hops become free: more robots move, each a short
  way, and the route finishes sooner (robots move at once).

Between the two, the total travelled distance (and the summed nearest-neighbour
distances of the displaced robots) never decreases as ``lam`` grows (the paper's
Fig. 8 shows the mean distance and finishing time falling). Scaling the
diagonal keeps the deployed matching optimal with the labels ``lx_r = lam u_rr``,
``ly = 0``, so no repair is needed before a stage.

Graphs: ``degree=None`` connects every robot to every target; ``degree=k``
connects each robot to its ``k`` nearest targets and each target to its ``k``
nearest robots (besides the robot's own target), the paper's nearest-neighbour
topology. Units are those of the positions; robots move in straight lines at
the same speed, so a route's finishing time is its longest move.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from numbers import Real

import numpy as np

from .errors import AssignmentError
from .hungarian_stage import hungarian_stage
from .validation import as_points, check_point_pair


def check_lambda(lam: object) -> float:
    """``lam`` as a float in [0, 1], or an :class:`AssignmentError` saying what is wrong."""
    if isinstance(lam, bool) or not isinstance(lam, Real):
        raise AssignmentError(f"lam must be a number in [0, 1] (the diagonal scaling), got {lam!r}")
    value = float(lam)
    if not (math.isfinite(value) and 0.0 <= value <= 1.0):
        raise AssignmentError(f"lam must be in [0, 1] (the diagonal scaling), got {value!r}")
    return value


def check_degree(degree: object) -> int | None:
    """``degree`` as a positive int or ``None`` (complete graph)."""
    if degree is None:
        return None
    if isinstance(degree, bool) or not isinstance(degree, (int, np.integer)) or degree < 1:
        raise AssignmentError(f"degree must be a positive integer or None (complete graph), got {degree!r}")
    return int(degree)


def _nearest(points: np.ndarray, queries: np.ndarray, degree: int, skip: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Pairs (query, point) of each query's ``degree`` nearest points other than ``skip[query]``."""
    from scipy.spatial import cKDTree

    count = min(degree + 1, points.shape[0])
    _, idx = cKDTree(points).query(queries, k=count)
    idx = idx.reshape(queries.shape[0], count)
    keep = idx != skip[:, None]
    keep &= np.cumsum(keep, axis=1) <= degree
    rows = np.broadcast_to(np.arange(queries.shape[0])[:, None], idx.shape)
    return rows[keep], idx[keep]


def graph_pairs(robots: np.ndarray, targets: np.ndarray, home: np.ndarray, degree: int | None) -> tuple[np.ndarray, np.ndarray]:
    """Edges ``(robot, target)`` of the routing graph, without any robot's own target.

    ``home[r]`` is the target robot ``r`` stands on (``-1`` for a robot not yet
    deployed). ``degree=None``: all pairs; otherwise each robot's ``degree``
    nearest targets and each target's ``degree`` nearest robots, merged.
    Sorted by robot, then target.
    """
    n, m = robots.shape[0], targets.shape[0]
    if degree is None or (degree >= m and degree >= n):
        rows, cols = np.divmod(np.arange(n * m), m)
    else:
        robot_at = np.full(m, -1, dtype=np.int64)
        deployed = home >= 0
        robot_at[home[deployed]] = np.flatnonzero(deployed)
        r1, c1 = _nearest(targets, robots, degree, home)
        c2, r2 = _nearest(robots, targets, degree, robot_at)
        keys = np.unique(np.concatenate([r1 * m + c1, r2 * m + c2]))
        rows, cols = np.divmod(keys, m)
    keep = cols != home[rows]
    return rows[keep].astype(np.int64), cols[keep].astype(np.int64)


@dataclass(frozen=True)
class ScaledProblem:
    """The diagonally scaled utilities of one insertion, as a sparse graph.

    ``rows``/``cols``/``utilities`` list the edges, including each deployed
    robot's scaled virtual edge to its own target. Utilities are minus
    distances (units of the positions), so they are ``<= 0``.
    """

    n_robots: int
    n_targets: int
    rows: np.ndarray
    cols: np.ndarray
    utilities: np.ndarray

    def dense(self) -> np.ndarray:
        """The ``(robots, targets)`` utility matrix, ``-inf`` for a missing edge."""
        matrix = np.full((self.n_robots, self.n_targets), -np.inf)
        matrix[self.rows, self.cols] = self.utilities
        return matrix


def scaled_problem(robots: np.ndarray, targets: np.ndarray, home: np.ndarray, lam: float, degree: int | None) -> ScaledProblem:
    """The paper's diagonally scaled utility graph for robots at ``robots`` (deployed ones on ``home``).

    The virtual edge of a deployed robot is worth ``lam`` times the utility of
    its best real edge (``0`` if it has none).
    """
    rows, cols = graph_pairs(robots, targets, home, degree)
    utilities = -np.linalg.norm(robots[rows] - targets[cols], axis=1)
    best = np.full(robots.shape[0], -np.inf)
    np.maximum.at(best, rows, utilities)
    deployed = np.flatnonzero(home >= 0)
    diagonal = lam * np.where(np.isfinite(best[deployed]), best[deployed], 0.0)
    all_rows = np.concatenate([rows, deployed])
    order = np.argsort(all_rows, kind="stable")
    return ScaledProblem(
        robots.shape[0], targets.shape[0], all_rows[order],
        np.concatenate([cols, home[deployed]])[order], np.concatenate([utilities, diagonal])[order],
    )


@dataclass(frozen=True)
class Reassignment:
    """What one insertion changed: the robots that move, from where to which target.

    Attributes:
        robots: the moving robots, route by route, each route starting at a new
            robot and following the robot displaced from each target taken.
        from_targets: the target each moving robot stood on (``-1``: a new robot).
        to_targets: its new target.
        distances: the length of each move (units of the positions).
        scaled_utility: total scaled utility of the new matching (the stage's
            objective; equal to a full re-solve's optimum).
    """

    robots: np.ndarray
    from_targets: np.ndarray
    to_targets: np.ndarray
    distances: np.ndarray
    scaled_utility: float

    @property
    def moved(self) -> int:
        """Number of robots that move (new robots included)."""
        return int(self.robots.size)

    @property
    def reassigned(self) -> int:
        """Number of deployed robots sent to another target."""
        return int((self.from_targets >= 0).sum())

    @property
    def total(self) -> float:
        """Summed length of the moves."""
        return float(self.distances.sum())

    @property
    def mean(self) -> float:
        """Mean length of a move (0 if nobody moves)."""
        return float(self.distances.mean()) if self.distances.size else 0.0

    @property
    def finishing_time(self) -> float:
        """Longest move: the time to finish when all robots move at once at unit speed."""
        return float(self.distances.max()) if self.distances.size else 0.0


def _adjacency(problem: ScaledProblem) -> tuple[list[np.ndarray], list[np.ndarray]]:
    bounds = np.searchsorted(problem.rows, np.arange(problem.n_robots + 1))
    targets = [problem.cols[a:b] for a, b in zip(bounds[:-1], bounds[1:])]
    utilities = [problem.utilities[a:b] for a, b in zip(bounds[:-1], bounds[1:])]
    return targets, utilities


class IncrementalAssignment:
    """A deployed team that absorbs new robot-target pairs one Hungarian stage at a time.

    ``IncrementalAssignment(robots, targets, lam=0.5, degree=None)`` first sends
    the ``n`` robots to the ``n`` targets with the least total distance (the
    Hungarian method, one stage per robot, on the degree-``k`` graph); the team
    is then deployed. :meth:`add` and :meth:`add_pairs` insert new pairs and
    return the :class:`Reassignment`; the team is deployed again afterwards.
    Robots and targets keep their indices; new ones are numbered on.

    Raises:
        AssignmentError: bad positions, ``lam`` outside [0, 1], a bad degree,
            unequal numbers of robots and targets, or a sparse graph on which
            no complete assignment (or route for a new pair) exists.
    """

    def __init__(self, robots: object, targets: object, lam: float = 0.5, degree: int | None = None) -> None:
        self._lam = check_lambda(lam)
        self._degree = check_degree(degree)
        r, t = check_point_pair(as_points(robots, "robots"), as_points(targets, "targets"))
        if r.shape[0] != t.shape[0]:
            raise AssignmentError(
                f"an incremental team needs as many robots as targets, got {r.shape[0]} robots and {t.shape[0]} targets"
            )
        self._targets = t
        n = r.shape[0]
        rows, cols = graph_pairs(r, t, np.full(n, -1, dtype=np.int64), self._degree)
        problem = ScaledProblem(n, n, rows, cols, -np.linalg.norm(r[rows] - t[cols], axis=1))
        adj_targets, adj_utilities = _adjacency(problem)
        lx = np.array([u.max() if u.size else 0.0 for u in adj_utilities])
        ly = np.zeros(n)
        target_of = np.full(n, -1, dtype=np.int64)
        robot_of = np.full(n, -1, dtype=np.int64)
        for robot in range(n):
            if hungarian_stage(robot, adj_targets, adj_utilities, lx, ly, target_of, robot_of) is None:
                raise AssignmentError(
                    f"no complete assignment on the degree-{self._degree} graph: robot {robot} cannot be given a "
                    "target without leaving another robot without one (raise degree)"
                )
        self._home = target_of
        self._travelled = np.linalg.norm(r - t[target_of], axis=1) if n else np.zeros(0)
        self._history: list[Reassignment] = []

    @property
    def lam(self) -> float:
        """The diagonal scaling in [0, 1]."""
        return self._lam

    @property
    def degree(self) -> int | None:
        """Edges per robot and per target (``None``: complete graph)."""
        return self._degree

    @property
    def target_of(self) -> np.ndarray:
        """The target each robot stands on, shape ``(n,)``."""
        return self._home.copy()

    @property
    def targets(self) -> np.ndarray:
        """Target positions, shape ``(n, d)``."""
        return self._targets.copy()

    @property
    def positions(self) -> np.ndarray:
        """Robot positions (each on its target), shape ``(n, d)``."""
        return self._targets[self._home]

    @property
    def travelled(self) -> np.ndarray:
        """Distance each robot has travelled so far (initial deployment included)."""
        return self._travelled.copy()

    @property
    def total_travel(self) -> float:
        """Summed distance travelled by the team so far."""
        return float(self._travelled.sum())

    @property
    def reassignments(self) -> int:
        """Deployed robots sent to another target by all insertions so far."""
        return sum(step.reassigned for step in self._history)

    @property
    def history(self) -> list[Reassignment]:
        """The :class:`Reassignment` of every insertion, oldest first."""
        return list(self._history)

    def scaled_problem(self, robots: object, targets: object) -> ScaledProblem:
        """The scaled utility graph that inserting these new robots and targets would solve."""
        new_r, new_t = self._check_new(robots, targets)
        positions = np.vstack([self.positions, new_r])
        all_targets = np.vstack([self._targets, new_t])
        home = np.concatenate([self._home, np.full(new_r.shape[0], -1, dtype=np.int64)])
        return scaled_problem(positions, all_targets, home, self._lam, self._degree)

    def shortest_route(self, robot: object, target: object) -> float:
        """Length of Dijkstra's shortest route from a new robot to a new target on the routing graph.

        The graph's nodes are the deployed robots (each on its target), the new
        robot's start and the new target; its arcs are the real edges of
        :meth:`scaled_problem` weighted by distance. The paper compares its
        ``lam = 0`` routes with this; here they have the same length.
        """
        from scipy.sparse import csr_matrix
        from scipy.sparse.csgraph import dijkstra

        problem = self.scaled_problem([robot], [target])
        n = problem.n_targets - 1  # deployed robots; node n is the new target, node n + 1 the new robot's start
        real = problem.cols != np.concatenate([self._home, [-1]])[problem.rows]
        start = np.where(problem.rows == n, n + 1, self._home[np.minimum(problem.rows, n - 1)])
        graph = csr_matrix((-problem.utilities[real], (start[real], problem.cols[real])), shape=(n + 2, n + 2))
        return float(dijkstra(graph, indices=n + 1)[n])

    def add(self, robot: object, target: object) -> Reassignment:
        """Insert one new robot (position ``robot``) and one new target; one Hungarian stage."""
        return self.add_pairs([robot], [target])

    def add_pairs(self, robots: object, targets: object) -> Reassignment:
        """Insert several new robots and as many targets at once; one stage per new robot.

        Solving them together is globally optimal, which inserting them one
        after the other (letting the team settle in between) need not be.
        """
        new_r, new_t = self._check_new(robots, targets)
        n, k = self._home.shape[0], new_r.shape[0]
        positions = np.vstack([self.positions, new_r])
        problem = scaled_problem(positions, np.vstack([self._targets, new_t]),
                                 np.concatenate([self._home, np.full(k, -1, dtype=np.int64)]),
                                 self._lam, self._degree)
        adj_targets, adj_utilities = _adjacency(problem)
        # Labels: the deployed matching is optimal with lx = its scaled diagonal and ly = 0 (the
        # diagonal is each row's largest utility); a new robot starts at its largest utility and a
        # new target at the smallest label that keeps every edge into it feasible.
        lx = np.zeros(n + k)
        for robot in range(n + k):
            cols, utilities = adj_targets[robot], adj_utilities[robot]
            if robot < n:
                lx[robot] = utilities[cols == self._home[robot]][0]
            elif cols.size:
                lx[robot] = utilities.max()
            else:
                raise AssignmentError(f"new robot {robot} has no edge to any target")
        ly = np.zeros(n + k)
        for robot in range(n + k):
            new = adj_targets[robot] >= n
            np.maximum.at(ly, adj_targets[robot][new], adj_utilities[robot][new] - lx[robot])
        target_of = np.concatenate([self._home, np.full(k, -1, dtype=np.int64)])
        robot_of = np.full(n + k, -1, dtype=np.int64)
        robot_of[self._home] = np.arange(n)
        for robot in range(n, n + k):
            if hungarian_stage(robot, adj_targets, adj_utilities, lx, ly, target_of, robot_of) is None:
                raise AssignmentError(
                    f"no route for new robot {robot}: on the degree-{self._degree} graph no chain of robots "
                    "reaches a free new target (raise degree)"
                )
        return self._settle(positions, np.vstack([self._targets, new_t]), target_of, n, float(lx.sum() + ly.sum()))

    def _check_new(self, robots: object, targets: object) -> tuple[np.ndarray, np.ndarray]:
        new_r = as_points(robots, "new robots")
        new_t = as_points(targets, "new targets")
        if new_r.shape[0] != new_t.shape[0] or new_r.shape[0] == 0:
            raise AssignmentError(
                f"add as many new robots as new targets (at least one), got {new_r.shape[0]} and {new_t.shape[0]}"
            )
        if self._targets.shape[0] == 0:  # an empty team takes the dimension of its first pairs
            self._targets = self._targets.reshape(0, new_t.shape[1])
        d = self._targets.shape[1]
        for name, array in (("new robots", new_r), ("new targets", new_t)):
            if array.shape[1] != d:
                raise AssignmentError(f"{name} are {array.shape[1]}-dimensional but the team's targets are {d}-dimensional")
        return new_r, new_t

    def _settle(self, positions: np.ndarray, targets: np.ndarray, target_of: np.ndarray, n: int,
                utility: float) -> Reassignment:
        """Record the moves of the new matching (route by route) and make it the deployment."""
        total = target_of.shape[0]
        old_robot_at = np.full(total, -1, dtype=np.int64)
        old_robot_at[self._home] = np.arange(n)
        old_home = np.concatenate([self._home, np.full(total - n, -1, dtype=np.int64)])
        moved = target_of != old_home
        order: list[int] = []
        seen = np.zeros(total, dtype=bool)
        for start in list(range(n, total)) + np.flatnonzero(moved).tolist():
            robot = start
            while robot >= 0 and moved[robot] and not seen[robot]:
                seen[robot] = True
                order.append(robot)
                robot = int(old_robot_at[target_of[robot]])
        robots = np.array(order, dtype=np.int64)
        to = target_of[robots]
        distances = np.linalg.norm(positions[robots] - targets[to], axis=1)
        step = Reassignment(robots, old_home[robots], to, distances, utility)
        self._travelled = np.concatenate([self._travelled, np.zeros(total - n)])
        self._travelled[robots] += distances
        self._home = target_of
        self._targets = targets
        self._history.append(step)
        return step

