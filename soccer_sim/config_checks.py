"""The configuration's error (:mod:`soccer_sim.config`); the ranges its dataclasses check are
:mod:`soccer_sim.config_ranges`'s."""

from __future__ import annotations

from soccer_sim.errors import SoccerSimError


class ConfigError(SoccerSimError, ValueError):
    """A configuration value is impossible (negative size, goal wider than the field, ...)."""
