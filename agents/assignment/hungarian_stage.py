"""One stage of the Hungarian method on a sparse bipartite graph with labels.

The graph matching form of the Hungarian method (Kuhn, Munkres) keeps a
*feasible labelling* ``lx[robot] + ly[target] >= utility`` on every edge and a
matching made of *tight* edges (equality). A stage grows the matching by one
edge: it searches from one exposed robot for an augmenting path, adjusting the
labels as little as needed to make the next edge tight, and flips the path.

Here the search is the equivalent shortest-path form (Dijkstra on the reduced
costs ``lx + ly - utility >= 0``, with a binary heap), so that a stage costs
``O(E log V)`` on a graph with ``E`` edges: linear-ish in the number of robots
when every robot has a bounded number ``k`` of edges, as "Tunable Routing
Solutions for Multi-Robot Navigation via the Assignment Problem: A 3D
Representation of the Matching Graph" (Liu and Shell) points out. Missing
edges are forbidden pairs; when no augmenting path exists the stage reports
it and changes nothing (the sparse graph has no matching covering the robot).
"""

from __future__ import annotations

import heapq

import numpy as np


def hungarian_stage(
    root: int,
    adj_targets: list[np.ndarray],
    adj_utilities: list[np.ndarray],
    lx: np.ndarray,
    ly: np.ndarray,
    target_of: np.ndarray,
    robot_of: np.ndarray,
) -> list[tuple[int, int]] | None:
    """Match the exposed robot ``root`` by one augmenting path; maximises total utility.

    Args:
        root: index of an unmatched robot.
        adj_targets: per robot, the int array of targets it has an edge to.
        adj_utilities: per robot, the utilities of those edges (same order).
        lx, ly: robot and target labels, feasible on every edge; updated in place.
        target_of, robot_of: the matching (``-1`` = exposed); updated in place.

    Returns:
        The new matched edges ``(robot, target)`` of the flipped path, from the
        exposed target back to ``root``; ``None`` (and nothing changed) when no
        exposed target can be reached from ``root``.
    """
    dist: dict[int, float] = {}
    pred: dict[int, int] = {}
    scanned: dict[int, float] = {}
    robot_dist: dict[int, float] = {root: 0.0}
    heap: list[tuple[float, int]] = []

    def relax(robot: int, base: float) -> None:
        targets = adj_targets[robot]
        if targets.size == 0:
            return
        reduced = np.maximum(lx[robot] + ly[targets] - adj_utilities[robot], 0.0) + base
        for target, value in zip(targets.tolist(), reduced.tolist()):
            if target not in scanned and value < dist.get(target, np.inf):
                dist[target] = value
                pred[target] = robot
                heapq.heappush(heap, (value, target))

    relax(root, 0.0)
    free_target = -1
    while heap:
        value, target = heapq.heappop(heap)
        if target in scanned or value > dist[target]:
            continue
        scanned[target] = value
        robot = int(robot_of[target])
        if robot < 0:
            free_target = target
            break
        robot_dist[robot] = value
        relax(robot, value)
    if free_target < 0:
        return None
    reach = scanned[free_target]
    for target, value in scanned.items():
        ly[target] += reach - value
    for robot, value in robot_dist.items():
        lx[robot] -= reach - value
    path = []
    target = free_target
    while True:
        robot = pred[target]
        previous = int(target_of[robot])
        target_of[robot] = target
        robot_of[target] = robot
        path.append((robot, target))
        if robot == root:
            return path
        target = previous
