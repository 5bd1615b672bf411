"""The configuration's error and the checks its dataclasses share (:mod:`soccer_sim.config`)."""

from __future__ import annotations

import math
import numbers

from soccer_sim.errors import SoccerSimError


class ConfigError(SoccerSimError, ValueError):
    """A configuration value is impossible (negative size, goal wider than the field, ...)."""


def _is_integer(value: object) -> bool:
    """True for Python and numpy integers (not bools)."""
    return isinstance(value, numbers.Integral) and not isinstance(value, bool)


def _is_real(value: object) -> bool:
    """True for Python and numpy real numbers (not bools)."""
    return isinstance(value, numbers.Real) and not isinstance(value, bool)


def _require_positive(owner: object, *names: str) -> None:
    for name in names:
        value = getattr(owner, name)
        if not (_is_real(value) and math.isfinite(value) and value > 0):
            raise ConfigError(f"{type(owner).__name__}.{name} must be a positive finite number, got {value!r}")


def _require_fraction(owner: object, *names: str) -> None:
    for name in names:
        value = getattr(owner, name)
        if not (_is_real(value) and 0.0 <= value <= 1.0):
            raise ConfigError(f"{type(owner).__name__}.{name} must be within [0, 1], got {value!r}")
