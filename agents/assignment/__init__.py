"""Role assignment: which robot goes to which target.

A pure numpy/scipy library (no soccer): give robot and target positions, or a
robot x target cost matrix, and a method name; get back the target of every
robot and the distance it travels.

>>> from agents.assignment import assign
>>> result = assign([[0, 0], [10, 0]], [[9, 1], [1, 1]], method="mmdr")
>>> result.target_of.tolist()
[1, 0]

Methods (see :data:`METHODS`): SCRAM's ``"mmdr"`` (lexicographic bottleneck:
collision-free and dynamically consistent) and ``"mmd+msd2"`` (smallest
makespan, then least sum of squared distances: collision-free), from
"SCRAM: Scalable Collision-avoiding Role Assignment with Minimal-makespan for
Formational Positioning"; and the baselines ``"msd"``, ``"msd2"``,
``"bottleneck"``, ``"greedy"``, ``"random"``.

:func:`distributed_assign` simulates agents with a limited communication range
that divide targets among themselves while moving (ETSP ASSGMT and GRID ASSGMT
from "Monotonic Target Assignment for Robotic Networks").

:class:`IncrementalAssignment` inserts new robot-target pairs into a deployed
team one Hungarian stage per pair, with a tunable trade-off between travel and
the number of robots reassigned ("Tunable Routing Solutions for Multi-Robot
Navigation via the Assignment Problem: A 3D Representation of the Matching Graph").
"""

from .api import MMDR_ALGORITHMS, METHOD_ALIASES, METHODS, assign, assign_costs
from .distributed import DISTRIBUTED_ALGORITHMS, DistributedResult, distributed_assign
from .errors import AssignmentError
from .incremental import IncrementalAssignment, Reassignment
from .lazy import GRID_METHODS, GridAssignmentResult, assign_on_grid
from .result import AssignmentResult

__all__ = [
    "METHODS",
    "METHOD_ALIASES",
    "MMDR_ALGORITHMS",
    "AssignmentError",
    "AssignmentResult",
    "assign",
    "assign_costs",
    "DISTRIBUTED_ALGORITHMS",
    "DistributedResult",
    "distributed_assign",
    "IncrementalAssignment",
    "Reassignment",
    "GRID_METHODS",
    "GridAssignmentResult",
    "assign_on_grid",
]
