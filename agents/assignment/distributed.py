"""Distributed target assignment under limited communication: the public entry point.

Simulates the two monotonic algorithms of "Monotonic Target Assignment for
Robotic Networks" (Smith and Bullo): ``n`` agents with communication range
``r_comm`` divide ``m`` target positions among themselves while moving to them,
in the square environment ``[0, side]^2``.

>>> from agents.assignment import distributed_assign
>>> result = distributed_assign([[1, 1], [9, 9]], [[8, 8], [2, 1]], side=10, r_comm=3, algorithm="etsp")
>>> result.completed, result.target_of.tolist()
(True, [1, 0])

* ``"etsp"`` (ETSP ASSGMT, full target knowledge): agents walk a common tour of
  the targets and resolve conflicts with neighbours; completion time in
  O(sqrt(n |E|)) for any start, the best possible order for monotonic
  algorithms in sparse environments.
* ``"grid"`` (GRID ASSGMT, full knowledge or a sensing range of at least
  ``sqrt(2/5) r_comm``): cell leaders guide unassigned agents; O(|E|) for any
  start and O(sqrt(|E|)) with high probability for uniformly random agents and
  targets in dense environments.

Agents and targets may differ in number (the paper's Section VIII-B): with
more agents, the extra ones end without a target; with more targets, some
stay free.
"""

from __future__ import annotations

import math
import numbers

import numpy as np

from .distributed_etsp import simulate_etsp
from .distributed_grid import cells_per_side, simulate_grid
from .distributed_model import DistributedResult, NetworkModel
from .errors import AssignmentError
from .validation import as_points

#: Algorithm name -> simulation.
DISTRIBUTED_ALGORITHMS = {"etsp": simulate_etsp, "grid": simulate_grid}

#: Default time between communication rounds, as a fraction of ``r_comm / v_max`` (the
#: paper asks for a round period much smaller than the time to cross the range).
DEFAULT_ROUND_FRACTION = 0.1

#: GRID ASSGMT under local sensing needs a sensing range of at least this times ``r_comm``
#: (an agent anywhere in a cell then senses the whole cell).
MIN_SENSE_RATIO = math.sqrt(2.0 / 5.0)

__all__ = ["DISTRIBUTED_ALGORITHMS", "DistributedResult", "NetworkModel", "cells_per_side", "distributed_assign"]


def _positive(value: object, name: str, allow_none: bool = False) -> float | None:
    """``value`` as a positive finite float, or an :class:`AssignmentError` naming ``name``."""
    if value is None and allow_none:
        return None
    if isinstance(value, bool) or not isinstance(value, numbers.Real):
        raise AssignmentError(f"{name} must be a positive number, got {value!r}")
    number = float(value)
    if not math.isfinite(number) or number <= 0.0:
        raise AssignmentError(f"{name} must be a positive finite number, got {number!r}")
    return number


def _positions(points: object, name: str, side: float) -> np.ndarray:
    """Checked ``(count, 2)`` positions inside ``[0, side]^2``."""
    array = as_points(points, name)
    if array.shape[0] == 0:
        return array.reshape(0, 2)
    if array.shape[1] != 2:
        raise AssignmentError(
            f"{name} must have shape (count, 2) (points in the plane), got {array.shape[1]} coordinates per point"
        )
    outside = ((array < 0.0) | (array > side)).any(axis=1)
    if outside.any():
        i = int(np.flatnonzero(outside)[0])
        raise AssignmentError(
            f"{name}[{i}] = ({array[i, 0]:g}, {array[i, 1]:g}) lies outside the environment [0, {side:g}]^2"
        )
    return array


def _check_distinct(targets: np.ndarray) -> None:
    """Targets must be distinct locations (one agent per location)."""
    if targets.shape[0] < 2:
        return
    order = np.lexsort((targets[:, 1], targets[:, 0]))
    ordered = targets[order]
    same = (ordered[1:] == ordered[:-1]).all(axis=1)
    if same.any():
        k = int(np.flatnonzero(same)[0])
        i, j = sorted((int(order[k]), int(order[k + 1])))
        raise AssignmentError(
            f"targets[{i}] and targets[{j}] are both at ({targets[i, 0]:g}, {targets[i, 1]:g}): "
            "target locations must be distinct"
        )


def distributed_assign(
    agents: object,
    targets: object,
    side: float,
    r_comm: float,
    *,
    algorithm: str = "grid",
    v_max: float = 1.0,
    round_time: float | None = None,
    r_sense: float | None = None,
    max_time: float | None = None,
    record_trace: bool = False,
) -> DistributedResult:
    """Simulate a distributed assignment of ``agents`` to ``targets`` with limited communication.

    Args:
        agents: ``(n, 2)`` start positions in ``[0, side]^2``; agent ``i``'s id is ``i``.
        targets: ``(m, 2)`` distinct target positions in ``[0, side]^2``.
        side: side length of the square environment.
        r_comm: communication range (same length unit).
        algorithm: ``"grid"`` (GRID ASSGMT) or ``"etsp"`` (ETSP ASSGMT).
        v_max: agent speed (length per time unit).
        round_time: time between communication rounds; default ``0.1 * r_comm / v_max``; an
            agent may move at most ``r_comm`` per round.
        r_sense: target sensing range for GRID ASSGMT under local sensing (at least
            ``sqrt(2/5) * r_comm``); ``None`` means full target knowledge. ETSP ASSGMT
            needs full knowledge.
        max_time: stop the simulation at this time even if incomplete (``result.completed``
            says whether it finished); default: the algorithm's worst-case bound, with a margin.
        record_trace: keep every agent's position at every round in ``result.trace``.

    Returns:
        A :class:`DistributedResult` (held targets, completion time, distances, rounds, ...).

    Raises:
        AssignmentError: unknown algorithm; a non-positive or non-finite ``side``, ``r_comm``,
            ``v_max``, ``round_time``, ``r_sense`` or ``max_time``; a round period in which an
            agent would cross more than ``r_comm``; a sensing range too short for GRID
            ASSGMT or given to ETSP ASSGMT; positions that are not finite, not 2-D or
            outside the environment (named by index); two targets at the same place.
    """
    if algorithm not in DISTRIBUTED_ALGORITHMS:
        valid = ", ".join(repr(name) for name in DISTRIBUTED_ALGORITHMS)
        raise AssignmentError(f"unknown distributed algorithm {algorithm!r}; valid: {valid}")
    side = _positive(side, "side")
    r_comm = _positive(r_comm, "r_comm")
    v_max = _positive(v_max, "v_max")
    round_time = _positive(round_time, "round_time", allow_none=True)
    r_sense = _positive(r_sense, "r_sense", allow_none=True)
    max_time = _positive(max_time, "max_time", allow_none=True)
    if round_time is None:
        round_time = DEFAULT_ROUND_FRACTION * r_comm / v_max
    elif v_max * round_time > r_comm:
        raise AssignmentError(
            f"round_time {round_time:g} lets an agent move {v_max * round_time:g} between rounds, more than "
            f"r_comm = {r_comm:g}; rounds must come at least every r_comm / v_max = {r_comm / v_max:g}"
        )
    if r_sense is not None:
        if algorithm == "etsp":
            raise AssignmentError("ETSP ASSGMT needs full target knowledge: leave r_sense as None")
        if r_sense < MIN_SENSE_RATIO * r_comm:
            raise AssignmentError(
                f"r_sense {r_sense:g} is too short for GRID ASSGMT: it must be at least sqrt(2/5) * r_comm = "
                f"{MIN_SENSE_RATIO * r_comm:g} so that an agent senses every target of its cell"
            )
    agent_array = _positions(agents, "agents", side)
    target_array = _positions(targets, "targets", side)
    _check_distinct(target_array)
    model = NetworkModel(side=side, r_comm=r_comm, v_max=v_max, round_time=round_time, r_sense=r_sense)
    n = agent_array.shape[0]
    if n == 0 or target_array.shape[0] == 0:
        return DistributedResult(
            algorithm=algorithm, target_of=np.full(n, -1, dtype=np.int64), completed=True, completion_time=0.0,
            rounds=0, distances=np.zeros(n), arrival_times=np.full(n, np.nan), positions=agent_array.copy(),
            messages=0, max_message_distance=0.0, model=model,
            trace=agent_array[None].copy() if record_trace else None,
        )
    return DISTRIBUTED_ALGORITHMS[algorithm](agent_array, target_array, model, max_time, record_trace)
