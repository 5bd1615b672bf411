"""The named scenarios shipped with the package (``soccer_sim/scenarios/data/*.toml``).

``soccer-sim scenarios`` lists them; ``soccer-sim play --scenario NAME`` and
``run_match(..., scenario=NAME)`` play one. Each file's name is its scenario's name.
"""

from __future__ import annotations

from functools import lru_cache
from importlib import resources

from soccer_sim.scenarios.files import scenario_from_dict, tomllib
from soccer_sim.scenarios.scenario import Scenario, ScenarioError


@lru_cache(maxsize=1)
def library() -> dict[str, Scenario]:
    """Every shipped scenario by name, in name order (the regular ``full-match`` first)."""
    found: dict[str, Scenario] = {}
    for entry in sorted(resources.files("soccer_sim.scenarios").joinpath("data").iterdir(), key=lambda e: e.name):
        if not entry.name.endswith(".toml"):
            continue
        scenario = scenario_from_dict(tomllib.loads(entry.read_text()), entry.name)
        if scenario.name != entry.name[:-len(".toml")]:
            raise ScenarioError("name", f"{entry.name} holds scenario {scenario.name!r}; a library file is named "
                                        "after its scenario")
        found[scenario.name] = scenario
    regular = {name: s for name, s in found.items() if s.is_regular}
    return {**regular, **{name: s for name, s in found.items() if name not in regular}}


def scenario_names() -> list[str]:
    """Names of the shipped scenarios."""
    return list(library())


def get_scenario(name: str) -> Scenario:
    """The shipped scenario called ``name``; ScenarioError listing the names for an unknown one."""
    found = library().get(name)
    if found is None:
        raise ScenarioError("name", f"no scenario called {name!r}; the library has {', '.join(library())}")
    return found
