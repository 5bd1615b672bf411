"""The built-in team's per-match figures: role switches per minute follow the configured cycle
length, distances are averaged over measured cycles only."""

from __future__ import annotations

from dataclasses import replace

import pytest

from agents.teams.reporting import RoleFigures
from soccer_sim import MatchConfig
from soccer_sim.config import PhysicsConfig


def one_minute_of_switches(config: MatchConfig, cycles: int) -> dict[str, float]:
    figures = RoleFigures(config, roles=10)
    for _ in range(cycles):
        figures.add(1, True, 2.0, 5.0, 3)
    return figures.statistics()


def test_switches_per_minute_use_the_configured_cycle_length() -> None:
    assert one_minute_of_switches(MatchConfig(), 600)["role_switches_per_minute"] == pytest.approx(600.0)
    slow = replace(MatchConfig(), physics=replace(PhysicsConfig(), cycle_seconds=0.2))
    # 300 cycles of 0.2 s are one minute: 300 switches in it.
    assert one_minute_of_switches(slow, 300)["role_switches_per_minute"] == pytest.approx(300.0)


def test_only_measured_cycles_count_for_the_distances() -> None:
    figures = RoleFigures(MatchConfig(), roles=4)
    assert figures.statistics()["role_switches_per_minute"] == 0.0
    figures.add(2, True, 1.0, 3.0, 1)
    figures.add(1, False, 100.0, 100.0, 4)  # a set play: switches count, distances do not
    stats = figures.statistics()
    assert stats["target_distance_mean"] == 1.0 and stats["target_distance_max"] == 3.0
    assert stats["role_unfilled_share"] == pytest.approx(1 / 4)
    assert stats["role_switches_per_minute"] == pytest.approx(3 * 600.0)
