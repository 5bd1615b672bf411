"""Helpers shared by the experiments tests, always imported as ``tests.experiments.helpers``."""

from __future__ import annotations

SCRIPTED = "tests.experiments.scripted_teams:"
"""The module path prefix of the scripted test teams (``SCRIPTED + "Forward"``)."""


def outcome(records) -> list[tuple]:
    """What must not depend on workers, backend or resuming: key, score, statistics, failure."""
    return [(r.home, r.away, r.seed, r.config_hash, r.home_goals, r.away_goals, r.cycles, r.home_stats,
             r.away_stats, r.error, r.forfeit) for r in records]
