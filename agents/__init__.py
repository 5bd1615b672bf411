"""Decisions: role assignment, the roles, skills and teams of the built-in players, their messages."""

import kernel_cache  # noqa: F401 - first of all: numba's cache stamps for the kernels below (see kernel_cache)
