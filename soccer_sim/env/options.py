"""The environment's options checked and resolved once, so the environment itself only plays.

:func:`resolve_options` turns the keyword arguments of :func:`soccer_sim.env.parallel_env`
into an :class:`EnvOptions` (the scenario resolved into a :class:`~soccer_sim.setup.MatchSetup`,
the controlled sides sized from it, the reward weights), raising a ValueError (TypeError for a
config of the wrong type, ScenarioError for a bad scenario) that names the option at fault.
"""

from __future__ import annotations

import os
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.env.rewards import reward_weights
from soccer_sim.env.say_codec import ALPHABET, CHARS_PER_VALUE, MAX_SAY_VALUES
from soccer_sim.registry import resolve_team
from soccer_sim.scenarios import Scenario, load_scenario
from soccer_sim.setup import MatchSetup
from soccer_sim.state import AWAY, HOME
from soccer_sim.team_hooks import observation_modes, plays_partial

SIDES = ("left", "right")
"""Agent name prefixes of HOME (the left side at kick-off) and AWAY."""
CONTROLLED = {"left": (HOME,), "right": (AWAY,), "both": (HOME, AWAY)}
RENDER_MODES = ("rgb_array", "human")
OBSERVATIONS = ("full", "partial")
"""The values of the ``observation`` option."""
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
                    observation_slots: int | None = None, record_dir: str | None = None,
                    observation: str | None = None, say_values: int = 0) -> EnvOptions:
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
    config = observation_config(config, observation, say_values, action_mode)
    resolved = load_scenario_option(scenario)
    setup = MatchSetup.resolve(config, resolved)
    sides = tuple(side for side in CONTROLLED[controlled] if setup.sizes[side] > 0)
    if not sides:
        raise ValueError(f"scenario {setup.scenario.name!r} fields no players on the controlled side "
                         f"(controlled={controlled!r}; sides of {setup.sizes[HOME]} and {setup.sizes[AWAY]} players)")
    if any(setup.sizes[side] > 0 and side not in sides for side in (HOME, AWAY)):
        team, name = resolve_team(opponent)  # an unknown name fails here, naming the registered teams
        if config.observation.partial and not plays_partial(team):
            raise ValueError(f"opponent {name!r} cannot play under partial observation (observation='partial'): "
                             f"its observation_modes are {observation_modes(team)!r}; choose a team that lists "
                             "'partial' (e.g. 'chaser' or 'idle')")
    kwargs = dict(controlled=controlled, opponent=opponent, max_cycles=max_cycles, end_on_goal=end_on_goal,
                  config=config, render_mode=render_mode, reward_shaping=reward_shaping, action_mode=action_mode,
                  scenario=resolved, rewards=rewards, event_texts=event_texts,
                  action_mask_in_observation=action_mask_in_observation, observation_slots=observation_slots,
                  record_dir=record_dir, observation=config.observation.mode, say_values=say_values)
    return EnvOptions(kwargs=kwargs, setup=setup, sides=sides, weights=weights)


def observation_config(config: MatchConfig, observation: str | None, say_values: Any,
                       action_mode: str) -> MatchConfig:
    """``config`` with the observation mode the options ask for (``observation``: None keeps the
    config's own mode; "full" or "partial" sets it), after checking ``say_values`` and that
    partial observation plays with low-level actions; a ValueError naming the option."""
    if observation is not None and observation not in OBSERVATIONS:
        raise ValueError(f"observation must be 'full' or 'partial', got {observation!r}")
    if observation == "full" and config.observation.partial:
        raise ValueError("observation='full' contradicts the config's observation mode 'partial' "
                         "(leave observation out, or set it to 'partial')")
    if observation == "partial" and not config.observation.partial:
        config = replace(config, observation=replace(config.observation, mode="partial"))
    if isinstance(say_values, bool) or not isinstance(say_values, (int, np.integer)) or not \
            0 <= say_values <= MAX_SAY_VALUES:
        raise ValueError(f"say_values must be an integer from 0 to {MAX_SAY_VALUES}, got {say_values!r}")
    if not config.observation.partial:
        if say_values:
            raise ValueError(f"say_values={say_values} needs partial observation (observation='partial'): "
                             "under full observation messages reach nobody")
        return config
    if action_mode != "low_level":
        raise ValueError(f"action_mode {action_mode!r} needs the exact team view; under partial observation "
                         "(observation='partial') only action_mode='low_level' plays")
    audio = config.observation.audio
    if say_values and CHARS_PER_VALUE * say_values > audio.say_msg_size:
        raise ValueError(f"say_values={say_values} needs messages of {CHARS_PER_VALUE * say_values} characters, "
                         f"more than the config's say_msg_size {audio.say_msg_size}")
    if say_values and set(ALPHABET) - set(audio.characters):
        raise ValueError(f"say_values={say_values} needs the say characters {ALPHABET!r}, which the config's "
                         "AudioParams.characters leave out")
    return config


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
