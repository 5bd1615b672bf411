"""The value every assignment method returns."""

from __future__ import annotations

import numpy as np


class AssignmentResult:
    """Which target each robot goes to, and how far it travels.

    Attributes:
        target_of: int array ``(n,)``; index of the target of each robot, ``-1``
            for a robot left without a target (only when robots outnumber targets).
        distances: float array ``(n,)``; distance (or cost, for
            :func:`~agents.assignment.assign_costs`) travelled by each robot, in
            the units of the input; ``nan`` for a robot without a target.
        method: canonical name of the method that produced the result.

    The summary figures are computed on access over the assigned robots only:
    ``makespan`` (largest distance), ``total`` (sum of distances) and
    ``total_squared`` (sum of squared distances); all are ``0.0`` when nobody
    is assigned.
    """

    __slots__ = ("target_of", "distances", "method")

    def __init__(self, target_of: np.ndarray, distances: np.ndarray, method: str) -> None:
        self.target_of = target_of
        self.distances = distances
        self.method = method

    def _assigned(self) -> np.ndarray:
        return self.distances[self.target_of >= 0]

    @property
    def makespan(self) -> float:
        """Largest distance travelled by an assigned robot (0 if none)."""
        d = self._assigned()
        return float(d.max()) if d.size else 0.0

    @property
    def total(self) -> float:
        """Sum of the distances travelled by the assigned robots."""
        return float(self._assigned().sum())

    @property
    def total_squared(self) -> float:
        """Sum of the squared distances travelled by the assigned robots."""
        d = self._assigned()
        return float(np.dot(d, d))

    def __len__(self) -> int:
        return int(self.target_of.shape[0])

    def __repr__(self) -> str:
        return (
            f"AssignmentResult(method={self.method!r}, target_of={self.target_of.tolist()}, "
            f"makespan={self.makespan:.6g}, total={self.total:.6g})"
        )

