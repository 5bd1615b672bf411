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


class ParameterError(ExperimentError, ValueError):
    """A parameter of a library call that cannot be used. ``parameter`` is its Python name
    (``record_every``) and ``problem`` what is wrong with it, worded to follow the name
    (``"must be at least 1, got 0"``), so a command line can put its own option name in front."""

    def __init__(self, parameter: str, problem: str) -> None:
        super().__init__(f"{parameter} {problem}")
        self.parameter = parameter
        self.problem = problem

    def __reduce__(self):
        return type(self), (self.parameter, self.problem)
