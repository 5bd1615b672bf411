"""The root of the experiments package's errors.

Every error :mod:`experiments` raises on purpose (bad run input, a stopped run, a results
file it cannot use, a study's bad argument) derives from :class:`ExperimentError`. The
command line turns these into one-line messages; library callers can catch the root.
"""

from __future__ import annotations


class ExperimentError(Exception):
    """Something the experiment runner, results store, a study or a benchmark refuses or could
    not finish."""


class StudyArgumentError(ExperimentError, ValueError):
    """A value a study or benchmark cannot use (a size out of range, a list that does not
    parse); the message names the parameter (the command line's option of the same name)."""
