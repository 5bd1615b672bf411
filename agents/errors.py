"""The root of the agents package's errors.

Every error :mod:`agents` raises on purpose (bad skill input, an assignment problem, a role
assigner's bad argument) derives from :class:`AgentsError`; each also keeps its built-in base
(``ValueError`` for bad input), so ``except ValueError`` keeps working.
"""

from __future__ import annotations


class AgentsError(Exception):
    """Something a built-in team, skill, role assigner or assignment solver refuses."""
