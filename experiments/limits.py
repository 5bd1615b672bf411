"""The allowed range of every number the command line takes: one table, :data:`OPTION_RANGES`.

Every numeric option of every ``soccer-sim`` command, study and benchmark parses its text with
:func:`ranged` (one number) or :func:`ranged_list` (comma-separated numbers), naming its entry
here, so a value out of range is refused while the arguments are parsed, before any work, with
one line naming the option and the range (``error: argument --cycles: must be a positive
integer up to 1000000 (cycles), got 99999999999``). docs/limits.md lists the same table.

Why the bounds are where they are: each upper bound keeps a run finite in time and memory on an
ordinary machine (a match of ``--cycles 1000000`` lasts about 28 hours of game time and some
minutes of computing; ``--games 10000`` per pairing is ten times the case study's) and inside
what the values are used for (a results file stores seeds up to 2**63 - 1; a timer takes at
most a week). Lower bounds say what the value means (at least one match, at least two robots).

Kept free of numpy and the simulator: parsers are built on every ``--help``.
"""

from __future__ import annotations

import argparse
import math
from collections.abc import Callable
from dataclasses import dataclass

from experiments.errors import StudyArgumentError

MAX_SEED = 2**63 - 1
"""The largest seed: what a results file (SQLite's signed 64-bit INTEGER) stores."""

MAX_CYCLES = 1_000_000
"""The most cycles of one match (about 28 hours of game time at 0.1 s a cycle)."""


class OutOfRange(StudyArgumentError):
    """A number outside its option's range (or not a number); the message names the option."""


@dataclass(frozen=True)
class NumberRange:
    """The values one option accepts: ``low`` to ``high`` inclusive (``low`` excluded when
    ``low_open``), whole numbers only when ``integer``; ``unit`` says what is counted or
    measured (shown in messages and docs/limits.md)."""

    low: float
    high: float
    unit: str
    integer: bool = True
    low_open: bool = False

    def describe(self) -> str:
        """The range in words: ``a positive integer up to 1000000 (cycles)``."""
        unit = f" ({self.unit})" if self.unit else ""
        if self.integer:
            if self.low == 1:
                return f"a positive integer up to {self.high}{unit}"
            if self.low == 0:
                return f"a non-negative integer up to {self.high}{unit}"
            return f"an integer from {self.low} to {self.high}{unit}"
        if self.low == 0 and self.low_open:
            return f"a positive number up to {self.high:g}{unit}"
        opening = "(" if self.low_open else "["
        return f"a number in {opening}{self.low:g}, {self.high:g}]{unit}"

    def parse(self, text: str) -> int | float:
        """``text`` as a number within the range, else ValueError saying what is allowed."""
        problem = f"must be {self.describe()}, got {text.strip() or repr(text)}"
        try:
            value: int | float = int(text) if self.integer else float(text)
        except (TypeError, ValueError):
            raise ValueError(problem) from None
        if not self.contains(value):
            raise ValueError(problem)
        return value

    def contains(self, value: float) -> bool:
        """Whether ``value`` (a number) lies in the range."""
        if not math.isfinite(value) or value > self.high:
            return False
        return value > self.low if self.low_open else value >= self.low


def _counts(high: int, unit: str, low: int = 1) -> NumberRange:
    return NumberRange(low, high, unit)


OPTION_RANGES: dict[str, NumberRange] = {
    # -- every command that plays matches (play, tournament, experiment *, bench *)
    "seed": _counts(MAX_SEED, "seed", low=0),
    "cycles": _counts(MAX_CYCLES, "cycles"),
    "games": _counts(10_000, "matches per pairing or team"),
    "league-games": _counts(10_000, "matches per pairing"),
    "workers": _counts(256, "processes"),
    "match-timeout": NumberRange(1.0, 604_800.0, "seconds", integer=False),
    "record-every": _counts(1_000_000, "matches"),
    "matches": _counts(10_000, "matches"),
    # -- evaluate
    "episodes": _counts(100_000, "episodes"),
    # -- experiment penalty-shot
    "trials": _counts(100_000, "trials"),
    "robots": _counts(11, "robots"),
    "limit": _counts(MAX_CYCLES, "cycles per trial"),
    # -- experiment distributed
    "grid-sizes": _counts(100_000, "agents", low=2),
    "etsp-sizes": _counts(100_000, "agents", low=2),
    "worst-sizes": _counts(100_000, "agents", low=2),
    "grid-trials": _counts(100_000, "instances per size"),
    "sweep-n": _counts(100_000, "agents"),
    "sweep-areas": NumberRange(1e-6, 1e6, "r_comm² per agent", integer=False),
    "r-comm": NumberRange(0.0, 1e6, "metres", integer=False, low_open=True),
    "round-fraction": NumberRange(0.0, 1.0, "of r_comm / v_max", integer=False, low_open=True),
    # -- experiment incremental
    "n": _counts(100_000, "robots", low=2),
    "degree": _counts(100_000, "neighbours"),
    "lambdas": NumberRange(0.0, 1.0, "diagonal scaling", integer=False),
    "side": NumberRange(0.0, 1e6, "metres", integer=False, low_open=True),
    # -- bench assignment and lazy-assignment
    "sizes": _counts(100_000, "robots"),
    "repeats": _counts(1_000, "repetitions"),
    "quality-instances": _counts(10_000_000, "instances", low=0),
    "time-limit": NumberRange(0.0, 86_400.0, "seconds", integer=False, low_open=True),
    "grid-sides": _counts(10_000, "cells a side", low=2),
    "grid-robots": _counts(100_000, "robots"),
    "cube-sides": _counts(500, "cells a side", low=2),
    "densities": NumberRange(0.0, 0.99, "obstacle share", integer=False),
    # -- the other benchmarks
    "queries": _counts(10_000_000, "balls per call"),
    "single": _counts(10_000_000, "calls"),
    "batch": _counts(1_000_000, "calls per batch"),
    "top": _counts(10_000, "entries"),
    "envs": _counts(256, "environments"),
    "processes": _counts(256, "processes"),
    "views": _counts(100_000, "situations"),
    "situations": _counts(100_000, "situations"),
    "number": _counts(10_000_000, "calls"),
    "players": _counts(10, "outfield players"),
}
"""The range of each numeric option, by the option's name without its dashes. An option that
means something else in another command has its own entry: ``grid-sides`` is ``bench
lazy-assignment --sizes``, ``cube-sides`` its ``--sizes-3d``, ``grid-robots`` its ``--robots``.
Three options are checked against their input instead, as their range is the input's:
``replay --cycle`` (the replay's cycles), ``replay --row`` (the results file's rows) and
``formation show --ball`` (the field)."""


def ranged(name: str) -> Callable[[str], int | float]:
    """The argparse ``type`` of an option whose range is ``OPTION_RANGES[name]``: the parsed
    number, or argparse's one-line error naming the option and the range."""
    limits = OPTION_RANGES[name]

    def parse(text: str) -> int | float:
        try:
            return limits.parse(text)
        except ValueError as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    parse.__name__ = name.replace("-", "_")
    return parse


def ranged_list(name: str, option: str | None = None) -> Callable[[str], list]:
    """The argparse ``type`` of a comma-separated list whose every value lies in
    ``OPTION_RANGES[name]`` (empty parts are skipped: ``''`` is the empty list)."""

    def parse(text: str) -> list:
        try:
            return parse_list(text, name, option)
        except OutOfRange as exc:
            raise argparse.ArgumentTypeError(str(exc)) from None

    parse.__name__ = name.replace("-", "_")
    return parse


def parse_list(text: str, name: str, option: str | None = None) -> list:
    """Comma-separated numbers, each within ``OPTION_RANGES[name]``; OutOfRange naming the
    value (and ``option``, when given) otherwise."""
    limits = OPTION_RANGES[name]
    values = []
    for part in (p.strip() for p in text.split(",")):
        if not part:
            continue
        try:
            values.append(limits.parse(part))
        except ValueError as exc:
            where = f"{option}: " if option else ""
            raise OutOfRange(f"{where}each value {exc}") from None
    return values
