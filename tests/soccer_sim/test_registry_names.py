"""Resolving teams by registered name, module path, class or object."""

from __future__ import annotations

import pytest

from soccer_sim import TeamNotFoundError, available_teams, resolve_team
from soccer_sim.trivial_teams import ChaserTeam, IdleTeam


def test_builtin_names_resolve_without_installation() -> None:
    team, name = resolve_team("chaser")
    assert isinstance(team, ChaserTeam) and name == "chaser"
    team, name = resolve_team("idle")
    assert isinstance(team, IdleTeam) and name == "idle"
    assert {"chaser", "idle"} <= set(available_teams())


def test_each_resolution_makes_a_fresh_team() -> None:
    assert resolve_team("chaser")[0] is not resolve_team("chaser")[0]


def test_module_paths_classes_and_objects() -> None:
    team, name = resolve_team("soccer_sim.trivial_teams:ChaserTeam")
    assert isinstance(team, ChaserTeam) and name == "soccer_sim.trivial_teams:ChaserTeam"
    team, name = resolve_team(IdleTeam)
    assert isinstance(team, IdleTeam) and name == "IdleTeam"
    existing = ChaserTeam()
    assert resolve_team(existing) == (existing, "ChaserTeam")
    existing.name = "my chaser"
    assert resolve_team(existing)[1] == "my chaser"


def test_unknown_name_names_the_closest_registered_ones() -> None:
    with pytest.raises(TeamNotFoundError) as info:
        resolve_team("chasr")
    message = str(info.value)
    assert "'chasr'" in message and "chaser" in message and "\n" not in message


def test_unknown_name_message_lists_few_teams_and_points_to_the_list_of_many() -> None:
    from soccer_sim.registry import unknown_team_message

    few = unknown_team_message("chasr", ["idle", "chaser"])
    assert "registered teams: chaser, idle;" in few
    many = [f"team-{i:02d}" for i in range(23)] + ["mmdr", "mmdr-leave", "mmd+msd2"]
    message = unknown_team_message("mmdrr", many)
    assert "did you mean mmdr" in message and "`soccer-sim teams` lists the 26 registered teams" in message
    assert "team-05" not in message and len(message) < 200
    assert "did you mean" not in unknown_team_message("zzz", many)


@pytest.mark.parametrize("path, fragment", [
    ("no_such_module_xyz:Team", "cannot import module 'no_such_module_xyz'"),
    ("soccer_sim.trivial_teams:NoSuchTeam", "has no attribute 'NoSuchTeam'"),
    ("soccer_sim.trivial_teams:", "must look like"),
    ("soccer_sim.trivial_teams:np", "neither a Team nor a class"),
    ("soccer_sim.trivial_teams:TeamCommand", "without arguments failed"),
])
def test_bad_paths_say_what_is_wrong(path: str, fragment: str) -> None:
    with pytest.raises(TeamNotFoundError, match=fragment):
        resolve_team(path)


def test_non_teams_are_rejected() -> None:
    with pytest.raises(TeamNotFoundError, match="cannot use 42"):
        resolve_team(42)
    with pytest.raises(TeamNotFoundError, match="lacks reset"):
        resolve_team(dict)


def test_names_are_read_once_and_a_package_installed_later_is_still_found(monkeypatch) -> None:
    from importlib import metadata

    from soccer_sim import registry

    calls = []
    late = [metadata.EntryPoint("late-team", "soccer_sim.trivial_teams:IdleTeam", registry.ENTRY_POINT_GROUP)]

    def entry_points(group: str):
        calls.append(group)
        return late if len(calls) > 1 else []

    monkeypatch.setattr(registry.metadata, "entry_points", entry_points)
    registry.available_teams(refresh=True)
    registry.available_teams()
    resolve_team("chaser")
    assert len(calls) == 1  # read once
    team, name = resolve_team("late-team")  # unknown: the names are read again
    assert isinstance(team, IdleTeam) and name == "late-team" and len(calls) == 2
    monkeypatch.undo()
    registry.available_teams(refresh=True)  # (the real names again for later tests)
