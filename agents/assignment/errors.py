"""The one exception type of the assignment library."""

from __future__ import annotations

from agents.errors import AgentsError


class AssignmentError(AgentsError, ValueError):
    """An assignment problem that cannot be solved as given.

    Raised for malformed input (NaN, infinite or overflowing coordinates, NaN
    or negative costs, wrong array dimensions, mismatched point dimensions,
    unknown method names, a missing or invalid ``rng``) and for cost matrices
    whose forbidden pairs (``inf``) leave no complete assignment.
    It subclasses :class:`~agents.errors.AgentsError` and :class:`ValueError`, so
    callers may catch any of the three.
    """
