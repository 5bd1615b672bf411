"""The environment's options checked and resolved once, so the environment itself only plays.

:func:`resolve_options` turns the keyword arguments of :func:`soccer_sim.env.parallel_env`
into an :class:`EnvOptions` (the scenario resolved into a :class:`~soccer_sim.setup.MatchSetup`,
the controlled sides sized from it, the reward weights), raising a ValueError (TypeError for a
config of the wrong type, ScenarioError for a bad scenario) that names the option at fault.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.env.rewards import reward_weights
from soccer_sim.registry import resolve_team
from soccer_sim.scenarios import Scenario, load_scenario
from soccer_sim.setup import MatchSetup
from soccer_sim.state import AWAY, HOME

SIDES = ("left", "right")
"""Agent name prefixes of HOME (the left side at kick-off) and AWAY."""
CONTROLLED = {"left": (HOME,), "right": (AWAY,), "both": (HOME, AWAY)}
RENDER_MODES = ("rgb_array", "human")
DEFAULT_OPPONENT = "static"
"""The built-in team that won the default tournament (README): the default opponent."""


@dataclass(frozen=True)
class EnvOptions:
    """Everything an environment is built from (see :func:`soccer_sim.env.parallel_env`)."""

    kwargs: dict[str, Any]
    """The keyword arguments, the scenario resolved to a Scenario (what pickling rebuilds from)."""
    setup: MatchSetup
    sides: tuple[int, ...]
    """The controlled sides that field players, HOME first."""
    weights: dict[str, float]


def check_seed(seed: Any) -> None:
    """A seed must be None or a non-negative integer, as for ``run_match`` (no silent truncation)."""
    if seed is not None and (isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0):
        raise ValueError(f"seed must be a non-negative integer or None, got {seed!r}")


def load_scenario_option(scenario: Any) -> Scenario | None:
    """``scenario`` as a Scenario (or None): a Scenario, a library name or a .json/.toml file."""
    if isinstance(scenario, os.PathLike) or (isinstance(scenario, str) and scenario.lower().endswith((".json",
                                                                                                      ".toml"))):
        return load_scenario(scenario)
    if isinstance(scenario, str):
        from soccer_sim.scenarios import get_scenario

        return get_scenario(scenario)
    return scenario


def resolve_options(controlled: str = "both", opponent: Any = DEFAULT_OPPONENT, max_cycles: int | None = None,
                    end_on_goal: bool = False, config: MatchConfig | None = None, render_mode: str | None = None,
                    reward_shaping: float = 0.0, action_mode: str = "low_level", scenario: Any = None,
                    rewards: Any = None, event_texts: bool = False, action_mask_in_observation: bool = False,
                    observation_slots: int | None = None, record_dir: str | None = None) -> EnvOptions:
    """Check every option (see :func:`soccer_sim.env.parallel_env`) and resolve the scenario."""
    if controlled not in CONTROLLED:
        raise ValueError(f"controlled must be 'left', 'right' or 'both', got {controlled!r}")
    if render_mode not in (None, *RENDER_MODES):
        raise ValueError(f"render_mode must be None, 'rgb_array' or 'human', got {render_mode!r}")
    if max_cycles is not None and (isinstance(max_cycles, bool) or not isinstance(max_cycles, (int, np.integer))
                                   or max_cycles < 1):
        raise ValueError(f"max_cycles must be a positive integer or None, got {max_cycles!r}")
    if render_mode == "human" and record_dir is not None:
        _make_record_dir(record_dir)
    weights = reward_weights(rewards, reward_shaping)
    if action_mask_in_observation and action_mode == "low_level":
        raise ValueError("action_mask_in_observation needs a discrete action mode (action_mode='high_level')")
    config = config or MatchConfig()
    if not isinstance(config, MatchConfig):
        raise TypeError(f"config must be a MatchConfig, got {type(config).__name__}")
    resolved = load_scenario_option(scenario)
    setup = MatchSetup.resolve(config, resolved)
    sides = tuple(side for side in CONTROLLED[controlled] if setup.sizes[side] > 0)
    if not sides:
        raise ValueError(f"scenario {setup.scenario.name!r} fields no players on the controlled side "
                         f"(controlled={controlled!r}; sides of {setup.sizes[HOME]} and {setup.sizes[AWAY]} players)")
    if any(setup.sizes[side] > 0 and side not in sides for side in (HOME, AWAY)):
        resolve_team(opponent)  # an unknown name fails here, naming the registered teams
    kwargs = dict(controlled=controlled, opponent=opponent, max_cycles=max_cycles, end_on_goal=end_on_goal,
                  config=config, render_mode=render_mode, reward_shaping=reward_shaping, action_mode=action_mode,
                  scenario=resolved, rewards=rewards, event_texts=event_texts,
                  action_mask_in_observation=action_mask_in_observation, observation_slots=observation_slots,
                  record_dir=record_dir)
    return EnvOptions(kwargs=kwargs, setup=setup, sides=sides, weights=weights)


def load_action_mode(name: str) -> Any:
    """A new translator of the action mode ``name`` (an entry point of the group
    ``soccer_sim.action_modes``): an object with ``size(n)``, ``reset(side_info, config)``,
    ``command_for(view, actions)`` and optionally ``action_mask(view, slots)``."""
    from importlib import metadata

    found = {ep.name: ep for ep in metadata.entry_points(group="soccer_sim.action_modes")}
    if name not in found:
        known = ", ".join(["low_level", *sorted(found)])
        raise ValueError(f"unknown action_mode {name!r}; known: {known}")
    return found[name].load()()


def _make_record_dir(record_dir: Any) -> None:
    """Create ``record_dir`` (where ``render_mode="human"`` records without a display) now, so a
    folder that cannot be made is refused at construction, naming it, not at the first reset."""
    try:
        os.makedirs(record_dir, exist_ok=True)
    except (OSError, TypeError) as exc:
        raise ValueError(f"record_dir {record_dir!r}: cannot make the folder ({exc})") from None
