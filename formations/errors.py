"""The package's errors: :class:`FormationError`, the root, for a malformed formation or file,
and :class:`FormationInputError` (with :class:`UnknownRoleError`) for a bad argument to a query.

Every error the package raises on purpose derives from :class:`FormationError`, which is a
``ValueError``, so ``except ValueError`` keeps catching them all.
"""

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


class FormationInputError(FormationError):
    """A bad argument to a formations function: an unknown situation or built-in set name, a
    ball position that is not two finite numbers. The message is the problem alone (no source),
    so that callers can embed it in their own."""

    def __init__(self, problem: str) -> None:
        self.source = ""
        self.where = None
        self.problem = problem
        ValueError.__init__(self, problem)

    def __reduce__(self):
        """Pickle by the problem, so the error crosses process boundaries intact."""
        return type(self), (self.problem,)

    def within(self, prefix: str) -> "FormationInputError":
        """The same error, prefixed with *prefix* (e.g. ``formation 'attack'``)."""
        return type(self)(f"{prefix}: {self.problem}")


class UnknownRoleError(FormationInputError, KeyError):
    """A role number a formation does not have; also a ``KeyError`` (a lookup by number)."""

    __str__ = BaseException.__str__  # the message, not KeyError's quoted repr of it
