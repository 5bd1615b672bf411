"""The robotic-network model shared by the distributed assignment simulations.

From "Monotonic Target Assignment for Robotic Networks" (Smith and Bullo):
agents are points in the square environment ``[0, side]^2`` with kinematics
``dp/dt = u``, ``|u| <= v_max``; they communicate in synchronous rounds, one
every ``round_time`` time units, with every agent within ``r_comm`` (all
messages of a round are exchanged instantaneously at the round's instant), and
move between rounds. This module holds the motion law (straight to a goal at
full speed, stopping on it) and the result type; the algorithms live in
:mod:`.distributed_etsp` and :mod:`.distributed_grid`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
from numba import njit


@dataclass(frozen=True)
class NetworkModel:
    """Physical parameters of the network (all in the units of the positions and of time).

    Attributes:
        side: side length of the square environment ``[0, side]^2``.
        r_comm: communication range: two agents exchange messages in a round iff they are at
            most this far apart.
        v_max: speed of every agent (distance per time unit).
        round_time: time between two communication rounds; ``v_max * round_time`` is at most
            ``r_comm`` (the paper assumes it much smaller).
        r_sense: target sensing range, or ``None`` for full target knowledge.
    """

    side: float
    r_comm: float
    v_max: float
    round_time: float
    r_sense: float | None = None

    @property
    def step(self) -> float:
        """Distance an agent covers between two rounds."""
        return self.v_max * self.round_time


@dataclass
class DistributedResult:
    """Outcome of one simulated run of a distributed assignment algorithm.

    Attributes:
        algorithm: ``"etsp"`` or ``"grid"``.
        target_of: int ``(n,)``: the target each agent holds at the end, ``-1`` if none.
        completed: whether every target (every agent, if agents are fewer) ended up held by
            exactly one agent standing on it before ``max_time``.
        completion_time: time at which the last final holder reached its target (the
            paper's completion time; ``nan`` if not completed).
        rounds: communication rounds simulated.
        distances: float ``(n,)``: path length travelled by each agent.
        arrival_times: float ``(n,)``: when each agent last reached the target it holds at
            the end (``nan`` for agents without one).
        positions: float ``(n, 2)``: final positions.
        messages: messages delivered in total.
        max_message_distance: the largest distance between the sender and a receiver of any
            delivered message (never above ``r_comm``: reported so it can be checked).
        model: the network parameters of the run.
        trace: positions at every round instant ``(rounds + 1, n, 2)`` when requested, else ``None``.
    """

    algorithm: str
    target_of: np.ndarray
    completed: bool
    completion_time: float
    rounds: int
    distances: np.ndarray
    arrival_times: np.ndarray
    positions: np.ndarray
    messages: int
    max_message_distance: float
    model: NetworkModel
    trace: np.ndarray | None = field(default=None, repr=False)

    @property
    def total_distance(self) -> float:
        """Sum of the path lengths of all agents."""
        return float(self.distances.sum())

    @property
    def max_distance(self) -> float:
        """Longest path travelled by one agent (0 with no agents)."""
        return float(self.distances.max()) if self.distances.size else 0.0

    @property
    def mean_distance(self) -> float:
        """Mean path length per agent (0 with no agents)."""
        return float(self.distances.mean()) if self.distances.size else 0.0


def finished_run(
    algorithm: str,
    model: NetworkModel,
    target_of: np.ndarray,
    completed: bool,
    rounds: int,
    travelled: np.ndarray,
    arrived_at: np.ndarray,
    positions: np.ndarray,
    messages: int,
    max_message_distance: float,
    trace: list[np.ndarray] | None,
) -> DistributedResult:
    """Assemble the result of a run: ``target_of`` holds the target each agent stands on at the
    end (-1 if none), ``arrived_at`` the last arrival instant of every agent; the completion
    time is the last arrival among the final holders (the paper's definition)."""
    holding = target_of >= 0
    arrival_times = np.where(holding, arrived_at, np.nan)
    completion_time = float(arrived_at[holding].max(initial=0.0)) if completed else float("nan")
    return DistributedResult(
        algorithm=algorithm,
        target_of=target_of,
        completed=completed,
        completion_time=completion_time,
        rounds=rounds,
        distances=travelled,
        arrival_times=arrival_times,
        positions=positions,
        messages=messages,
        max_message_distance=max_message_distance,
        model=model,
        trace=np.stack(trace) if trace is not None else None,
    )


@njit(cache=True, nogil=True)
def move_toward(
    positions: np.ndarray,
    goals: np.ndarray,
    moving: np.ndarray,
    step: float,
    travelled: np.ndarray,
    arrived_at: np.ndarray,
    now: float,
    v_max: float,
) -> None:
    """Move every agent with ``moving[i]`` up to ``step`` straight towards ``goals[i]``.

    An agent that can reach its goal within the step stops exactly on it (its position
    becomes the goal's bit pattern, so "on the target" is an exact test) and
    ``arrived_at[i]`` becomes the exact arrival instant ``now + distance / v_max``.
    ``travelled`` accumulates path lengths. Agents already on their goal do not move.
    """
    for i in range(positions.shape[0]):
        if not moving[i]:
            continue
        dx = goals[i, 0] - positions[i, 0]
        dy = goals[i, 1] - positions[i, 1]
        if dx == 0.0 and dy == 0.0:
            continue
        dist = np.sqrt(dx * dx + dy * dy)
        if dist <= step:
            positions[i, 0] = goals[i, 0]
            positions[i, 1] = goals[i, 1]
            travelled[i] += dist
            arrived_at[i] = now + dist / v_max
        else:
            scale = step / dist
            positions[i, 0] += dx * scale
            positions[i, 1] += dy * scale
            travelled[i] += step
