"""FormationTeam names each player's current role (the ReportsRoles hook of bench soccer)."""

from __future__ import annotations

import numpy as np

from agents.teams import FormationTeam
from agents.teams.positions import position_labels
from soccer_sim import MatchConfig, SideInfo
from soccer_sim.team_hooks import ReportsRoles


def _ready(team: FormationTeam) -> FormationTeam:
    team.reset(SideInfo(0, "us", "them", 11, 0, 11, 0), MatchConfig(), np.random.default_rng(0))
    return team


def test_labels_follow_the_role_each_player_is_assigned() -> None:
    team = _ready(FormationTeam("greedy"))
    assert isinstance(team, ReportsRoles)
    kinds = list(position_labels(team.formation_set))
    labels = team.role_labels()
    assert len(labels) == 11 and labels[0] == "goalkeeper"
    assert labels == kinds  # before the first assignment every player holds its own role
    swap = np.arange(10)
    defender = next(r for r in range(10) if kinds[r + 1] == "centre-back")
    forward = next(r for r in range(10) if kinds[r + 1] == "centre-forward")
    swap[[defender, forward]] = swap[[forward, defender]]
    team.pipeline.followed[0] = swap
    labels = team.role_labels()
    assert labels[defender + 1] == "centre-forward" and labels[forward + 1] == "centre-back"
    assert sorted(labels) == sorted(kinds)  # still one label per formation role


def test_a_goalkeeper_elsewhere_in_the_rows_keeps_its_label() -> None:
    team = FormationTeam("mmdr")
    team.reset(SideInfo(0, "us", "them", 11, 4, 11, 0), MatchConfig(), np.random.default_rng(0))
    labels = team.role_labels()
    assert labels[4] == "goalkeeper" and labels.count("goalkeeper") == 1
