"""The single exception type of the package."""

from __future__ import annotations


class FormationError(ValueError):
    """A formation (or a formation file) is malformed.

    The message always starts with the *source* (a file path, or a name for a
    formation built in memory) and, where one is at fault, *where* the problem
    is: a sample index (samples are numbered from 0 in file order), a role
    number, or a formation of a set.
    """

    def __init__(self, source: str, problem: str, where: str | None = None) -> None:
        self.source = source
        self.where = where
        self.problem = problem
        location = f"{source}: {where}" if where else source
        super().__init__(f"{location}: {problem}")

    def __reduce__(self):
        """Pickle by the constructor's arguments, so the error crosses process boundaries intact."""
        return type(self), (self.source, self.problem, self.where)

    def within(self, prefix: str) -> "FormationError":
        """The same error, located inside *prefix* (e.g. ``formation 'attack'``)."""
        where = f"{prefix}, {self.where}" if self.where else prefix
        return FormationError(self.source, self.problem, where)
