"""soccer_sim: a 2D RoboCup-style soccer simulator for point robots.

The world (field, pymunk physics, referee), the match setup (:class:`MatchSetup`), the
deterministic match loop, the Team interface and the team registry. Play a match with::

    from soccer_sim import run_match
    result = run_match("chaser", "idle", seed=1)
    result.score  # (home goals, away goals)
"""

import kernel_cache  # noqa: F401 - first of all: numba's cache stamps for the kernels below (see kernel_cache)

from soccer_sim.config import (ConfigError, FieldConfig, MatchConfig, PhysicsConfig, RuleConfig, StaminaConfig,
                               TackleConfig)
from soccer_sim.errors import SoccerSimError
from soccer_sim.match import Match, MatchResult, run_match
from soccer_sim.recorder import Recorder
from soccer_sim.registry import TeamNotFoundError, available_teams, resolve_team
from soccer_sim.scenarios import Scenario, ScenarioError
from soccer_sim.setup import MatchSetup
from soccer_sim.state import AWAY, HOME, EventKind, EventLog, PlayMode, WorldState
from soccer_sim.statistics import TeamStatistics
from soccer_sim.team import SideInfo, Team, TeamCommand, TeamError, TeamView

__all__ = [
    "AWAY", "HOME", "ConfigError", "EventKind", "EventLog", "FieldConfig", "Match", "MatchConfig",
    "MatchResult", "MatchSetup", "PhysicsConfig", "PlayMode", "Recorder", "RuleConfig", "Scenario",
    "ScenarioError", "SideInfo", "SoccerSimError", "StaminaConfig", "TackleConfig", "Team", "TeamCommand", "TeamError",
    "TeamNotFoundError", "TeamStatistics", "TeamView", "WorldState", "available_teams", "resolve_team",
    "run_match",
]
