"""Every error the simulator raises on purpose sits under SoccerSimError and keeps its built-in base."""

from __future__ import annotations

import pickle

import pytest

import soccer_sim
from soccer_sim import ConfigError, MatchConfig, ScenarioError, SoccerSimError, TeamError, TeamNotFoundError
from soccer_sim.errors import SoccerSimError as RootFromModule
from soccer_sim.physics import PymunkChangedError
from soccer_sim.registry import resolve_team
from soccer_sim.replay.recorder import ReplayError
from soccer_sim.scenarios import Scenario


@pytest.mark.parametrize("error, builtin", [
    (ConfigError, ValueError),
    (ScenarioError, ValueError),
    (PymunkChangedError, RuntimeError),
    (TeamNotFoundError, LookupError),
    (ReplayError, RuntimeError),
    (TeamError, Exception),
])
def test_each_error_is_a_soccer_sim_error_and_keeps_its_builtin_base(error: type, builtin: type) -> None:
    assert issubclass(error, SoccerSimError)
    assert issubclass(error, builtin)


def test_the_root_is_exported_from_the_package() -> None:
    assert soccer_sim.SoccerSimError is RootFromModule
    assert "SoccerSimError" in soccer_sim.__all__


def test_raised_errors_are_caught_by_the_root_and_by_the_old_base() -> None:
    with pytest.raises(SoccerSimError, match="players_per_team"):
        MatchConfig(players_per_team=0)
    with pytest.raises(ValueError, match="players_per_team"):
        MatchConfig(players_per_team=0)
    with pytest.raises(SoccerSimError, match="cycle_limit"):
        Scenario(cycle_limit=0)
    with pytest.raises(LookupError, match="no-such-team"):
        resolve_team("no-such-team")
    with pytest.raises(SoccerSimError, match="no-such-team"):
        resolve_team("no-such-team")


def test_errors_with_fields_still_pickle() -> None:
    for error in (ScenarioError("home.players", "too many"), TeamError("t", "bad", player=2)):
        again = pickle.loads(pickle.dumps(error))
        assert isinstance(again, SoccerSimError) and str(again) == str(error)
