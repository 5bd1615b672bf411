"""The mechanism figures: fixed (and held) roles against the minimal makespan."""

from __future__ import annotations

import numpy as np
import pytest

import soccer_sim
from agents.teams import FormationTeam
from agents.teams.mechanism import SAMPLE_EVERY, makespans
from agents.teams.reporting import RoleFigures
from soccer_sim import MatchConfig

RNG = np.random.default_rng(3)
FORMATION = np.column_stack((RNG.uniform(-40, 40, 10), RNG.uniform(-30, 30, 10)))
IDENTITY = np.arange(10)


def test_a_pure_shift_of_the_targets_keeps_fixed_roles_optimal() -> None:
    players = FORMATION.copy()  # everybody on its own target...
    targets = FORMATION + np.array([9.0, -4.0])  # ...then the whole block moves
    fixed, held, minimal = makespans(players, targets, IDENTITY)
    assert fixed == held == minimal == pytest.approx(np.hypot(9.0, 4.0))


def test_swapped_players_open_a_gap_the_held_roles_close() -> None:
    players = FORMATION.copy()
    players[[0, 1]] = FORMATION[[1, 0]]  # players 0 and 1 stand on each other's targets
    swap = IDENTITY.copy()
    swap[[0, 1]] = [1, 0]  # and hold each other's roles
    fixed, held, minimal = makespans(players, FORMATION, swap)
    assert minimal == 0.0 and held == 0.0
    assert fixed == pytest.approx(np.hypot(*(FORMATION[0] - FORMATION[1])))


def test_role_figures_report_shares_and_gaps() -> None:
    figures = RoleFigures(MatchConfig(), 10)
    figures.add_sample(5.0, 5.0, 5.0)
    figures.add_sample(8.0, 5.0, 5.0)
    figures.add_sample(7.0, 6.0, 5.0)
    stats = figures.statistics()
    assert stats["fixed_roles_optimal_share"] == pytest.approx(1 / 3)
    assert stats["makespan_gap"] == pytest.approx(5.0 / 3)
    assert stats["held_roles_optimal_share"] == pytest.approx(2 / 3)
    assert stats["held_makespan_gap"] == pytest.approx(1 / 3)


def test_a_static_team_samples_every_nth_play_on_cycle() -> None:
    team = FormationTeam("static")
    soccer_sim.run_match(team, "idle", seed=1, config=MatchConfig(max_cycles=200))
    figures = team.pipeline.figures
    assert 0 < figures.samples <= 200 // SAMPLE_EVERY
    assert figures.samples >= figures.cycles // SAMPLE_EVERY - 1
    # static holds the shirt-number roles: fixed and held roles are the same assignment.
    assert figures.fixed_optimal == figures.held_optimal and figures.gap_sum == pytest.approx(figures.held_gap_sum)
