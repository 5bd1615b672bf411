"""Scenarios: uneven sides, chosen start states and end conditions, and a library of them.

A :class:`Scenario` describes a match's sides (0 to 11 players each, a goalkeeper
optional), start state (players and ball, positions and velocities, some of it drawn from the
match seed), starting play mode, end conditions (a goal, the ball out, the ball lost to the
defending side, a cycle limit) and whether offside and set plays apply. ``Scenario()`` is the
regular match. Pass one to :func:`soccer_sim.run_match` or :class:`soccer_sim.Match`::

    from soccer_sim import run_match
    from soccer_sim.scenarios import get_scenario, load_scenario

    result = run_match("mmdr", "static", seed=3, scenario="3-vs-1-with-keeper")
    result.end_reason          # "goal", "out", "lost" or "cycle_limit"

Modules: :mod:`~soccer_sim.scenarios.parts` (a scenario's sides and ball, its names and
limits, :class:`ScenarioError`), :mod:`~soccer_sim.scenarios.scenario` (the :class:`Scenario`,
its checks against a configuration and its start state), :mod:`~soccer_sim.scenarios.files`
(JSON or TOML files) and :mod:`~soccer_sim.scenarios.library` (the shipped scenarios). A match
resolves its scenario and configuration once into a :class:`soccer_sim.setup.MatchSetup`.
"""

from soccer_sim.scenarios.files import load_scenario, save_scenario, scenario_from_dict, scenario_to_dict
from soccer_sim.scenarios.library import get_scenario, library, scenario_names
from soccer_sim.scenarios.scenario import (
    CONFIG_GOALIE,
    END_CONDITIONS,
    MAX_PLAYERS,
    START_MODES,
    BallStart,
    Scenario,
    ScenarioError,
    Side,
)

__all__ = [
    "CONFIG_GOALIE", "END_CONDITIONS", "MAX_PLAYERS", "START_MODES", "BallStart", "Scenario", "ScenarioError",
    "Side", "get_scenario", "library", "load_scenario", "save_scenario", "scenario_from_dict", "scenario_names",
    "scenario_to_dict",
]
