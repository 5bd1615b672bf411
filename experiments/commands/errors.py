"""How ``soccer-sim`` commands end: one error line on stderr and a conventional exit status.

The convention every command follows:

* an error is one line on stderr, ``error: WHAT IS WRONG`` (naming the option, file or team);
* exit status 0 for success, 2 for bad input (an option, a file that cannot be read or is
  malformed, a team that cannot be found), 1 for a run that started and failed (a check that
  did not pass, a team that broke during a match), 130 after Ctrl-C.

:class:`CommandParser` makes argparse's own errors follow it (one line instead of its
usage + error pair) and :func:`call` runs a command's ``func(args)`` under it: Ctrl-C, a
closed pipe and an unexpected exception each end in one line and the right status.
"""

from __future__ import annotations

import argparse
import os
import sys
from collections.abc import Callable
from typing import NoReturn

BAD_INPUT = 2
FAILED = 1
INTERRUPTED = 130

TRACEBACK_VARIABLE = "SOCCER_SIM_TRACEBACK"
"""Set to 1 to let an unexpected exception raise with its traceback (for debugging and tests)."""


def one_line(message: str) -> str:
    """``message`` on one line: line breaks (e.g. from a file's text quoted in it) become spaces."""
    return " ".join(part.strip() for part in str(message).splitlines() if part.strip())


def fail(message: str, status: int = BAD_INPUT) -> int:
    """Print ``error: message`` as one line on stderr and return ``status``."""
    print(f"error: {one_line(message)}", file=sys.stderr)
    return status


class CommandParser(argparse.ArgumentParser):
    """An ArgumentParser whose usage errors are one line on stderr (exit status 2): the problem
    and where to read the options, instead of argparse's usage block followed by the error.

    Sub-parsers made with ``add_subparsers`` are of the same class, so building the top-level
    parser with it covers every command."""

    def error(self, message: str) -> NoReturn:
        sys.stderr.write(f"error: {one_line(message)} (see: {self.prog} --help)\n")
        sys.exit(BAD_INPUT)

    def parse_known_args(self, args=None, namespace=None):
        parsed, extras = super().parse_known_args(args, namespace)
        # Python 3.11's argparse can hand a single-valued positional an empty list when "--" is
        # repeated (``formation import helios -- -- --map``): refuse it as a missing value.
        for action in self._actions:
            if not action.option_strings and action.nargs is None and isinstance(getattr(parsed, action.dest, None), list):
                self.error(f"argument {action.metavar or action.dest}: expected one value")
        return parsed, extras


def call(func: Callable[[argparse.Namespace], int | None], args: argparse.Namespace) -> int:
    """Run ``func(args)`` and return its exit status, ending every way out by the convention:

    * Ctrl-C: ``interrupted`` on stderr, 130;
    * the reader of stdout went away (``soccer-sim ... | head``): 0, without a second error
      when Python flushes stdout at exit;
    * a write that started and failed (a full disk, stdout included: it is flushed here): one
      line naming the file, status 1;
    * an exception the command did not expect: one line naming it, status 1 (with
      ``SOCCER_SIM_TRACEBACK=1`` in the environment it is raised, traceback and all).
    """
    from experiments.results.files import write_failure

    try:
        status = int(func(args) or 0)
        sys.stdout.flush()                   # a full disk under stdout shows here, not at exit
        return status
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return INTERRUPTED
    except BrokenPipeError:
        _silence_stdout()
        return 0
    except OSError as exc:
        failed = write_failure(exc)          # a full disk: the same one line and status everywhere
        if failed is None:
            return _unexpected(exc)
        if exc.filename is not None:         # written through a temporary file: nothing is left
            return fail(failed, FAILED)
        _silence_stdout()
        return fail(f"{failed}; the output is incomplete", FAILED)
    except Exception as exc:  # noqa: BLE001 - the last line of defence: one line, never a bare traceback
        return _unexpected(exc)


def _unexpected(exc: Exception) -> int:
    """One line naming an exception no command expected, status 1 (raised again, traceback and
    all, with ``SOCCER_SIM_TRACEBACK=1``)."""
    if os.environ.get(TRACEBACK_VARIABLE, "") not in ("", "0"):
        raise exc
    return fail(f"unexpected {type(exc).__name__}: {exc} (run with {TRACEBACK_VARIABLE}=1 for the traceback)",
                FAILED)


def guarded(func: Callable[[argparse.Namespace], int | None]) -> Callable[[argparse.Namespace], int]:
    """``func`` wrapped by :func:`call` (for ``set_defaults(func=...)``)."""

    def run(args: argparse.Namespace) -> int:
        return call(func, args)

    run.__wrapped__ = func  # type: ignore[attr-defined]
    run.__doc__ = func.__doc__
    return run


def _silence_stdout() -> None:
    """Point stdout at /dev/null so the interpreter's final flush finds no broken pipe."""
    try:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):  # stdout is not a real file (e.g. captured in tests)
        pass
