"""Argument types shared by every command, study and benchmark that parses numbers.

Each is an ``argparse`` type: it turns the text of an option into a value or raises
``argparse.ArgumentTypeError`` saying what is wrong, which argparse reports as one line naming
the option. Kept out of :mod:`experiments.commands` so studies and benchmarks take them from
here rather than from a command module.
"""

from __future__ import annotations

import argparse


def positive_int(text: str) -> int:
    """A positive integer (a count of matches, cycles, workers, repetitions)."""
    value = int(text)  # not a number: argparse's own "invalid positive_int value" line
    if value <= 0:
        raise argparse.ArgumentTypeError(f"must be a positive integer, got {text}")
    return value


def positive_float(text: str) -> float:
    """A positive finite number (e.g. seconds)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a positive number, got {text}") from None
    if not value > 0 or value == float("inf"):
        raise argparse.ArgumentTypeError(f"must be a positive number, got {text}")
    return value


def seed_value(text: str) -> int:
    """A non-negative integer seed."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"must be a non-negative integer, got {text}") from None
    if value < 0:
        raise argparse.ArgumentTypeError(f"must be a non-negative integer, got {text}")
    return value
