"""Enter a policy trained in the environment in matches and tournaments as a Team, as trained.

:class:`PolicyTeam` builds each player's observation from the team's view exactly as the
environment does (:mod:`soccer_sim.env.spaces`), asks the policy for the players' actions and
turns them into the team's command with the environment's own translation of that action mode.
Everything that shapes what the policy sees and does is an option of the same name as the
environment's, given at construction (or read from the environment with :meth:`PolicyTeam.for_env`):

* ``action_mode``: ``"low_level"`` (5 floats a player) or a discrete mode such as
  ``"high_level"`` (one integer a player, translated by the same entry point of the group
  ``soccer_sim.action_modes`` the environment loads); with ``action_mask_in_observation`` the
  policy gets ``{"observation": ..., "action_mask": ...}`` as in training;
* ``scenario`` and ``max_cycles``: the time feature divides the cycle by the episode's horizon
  (:func:`~soccer_sim.env.spaces.episode_horizon`: 300 on empty-goal), not by the match's length;
* ``observation_slots`` and ``say_values``; the observation mode follows the match's configuration
  (partial observation: :mod:`soccer_sim.env.partial_spaces`, low-level actions only).

The policy is, in the order looked for:

* an object with ``act_batch(observations) -> actions``: called once per cycle with the whole
  team, ``(n, D)`` observations (a dict of ``(n, D)`` and ``(n, A)`` arrays with the mask) to
  ``(n, 5)`` low-level or ``(n,)`` discrete actions;
* with ``batched=True``, a callable taking and returning the same batch;
* an object with ``act(observation) -> action`` or a callable ``policy(observation)``, called
  for each player;
* a dict from player index (0 = goalkeeper) to such a per-player policy.

``name`` is how match results and tables name the team.
"""

from __future__ import annotations

from typing import Any, Callable

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.env.options import load_action_mode, load_scenario_option
from soccer_sim.env.partial_spaces import PartialObservationBuilder
from soccer_sim.env.say_codec import MAX_SAY_VALUES
from soccer_sim.env.spaces import (ACTION_SIZE, ActionDecoder, ObservationBuilder, check_actions, check_choices,
                                   episode_horizon)
from soccer_sim.team import SideInfo, TeamCommand, TeamError

LOW_LEVEL = "low_level"


def _as_callable(policy: Any, where: str) -> Callable[[Any], Any]:
    if hasattr(policy, "act") and callable(policy.act):
        return policy.act
    if callable(policy):
        return policy
    raise TypeError(f"{where} must be callable or have an act(observation) method, got {type(policy).__name__}")


class PolicyTeam:
    """A team playing ``policy`` for every player, as it was trained (see the module docstring)."""

    observation_modes = ("full", "partial")

    def __init__(self, policy: Any, name: str = "policy", observation_slots: int | None = None,
                 say_values: int = 0, *, action_mode: str = LOW_LEVEL, action_mask_in_observation: bool = False,
                 scenario: Any = None, max_cycles: int | None = None, batched: bool = False) -> None:
        self.name = name
        self.observation_slots = observation_slots
        if isinstance(say_values, bool) or not isinstance(say_values, (int, np.integer)) or not \
                0 <= say_values <= MAX_SAY_VALUES:
            raise ValueError(f"say_values must be an integer from 0 to {MAX_SAY_VALUES}, got {say_values!r}")
        self.say_values = int(say_values)
        self.action_mode = action_mode
        self._translator = None if action_mode == LOW_LEVEL else load_action_mode(action_mode)
        if self._translator is not None and self.say_values:
            raise ValueError(f"say_values={self.say_values} needs action_mode='low_level', got {action_mode!r}")
        if action_mask_in_observation and self._translator is None:
            raise ValueError("action_mask_in_observation needs a discrete action mode (action_mode='high_level')")
        self.action_mask_in_observation = bool(action_mask_in_observation)
        if max_cycles is not None and (isinstance(max_cycles, bool) or not isinstance(max_cycles, (int, np.integer))
                                       or max_cycles < 1):
            raise ValueError(f"max_cycles must be a positive integer or None, got {max_cycles!r}")
        self.horizon = episode_horizon(max_cycles, load_scenario_option(scenario))
        """The time feature's scale the environment used (None: the match's length)."""
        self._batch: Callable[[Any], Any] | None = None
        self._policies: dict[int, Callable[[Any], Any]] = {}
        self._shared: Callable[[Any], Any] | None = None
        if hasattr(policy, "act_batch") and callable(policy.act_batch):
            self._batch = policy.act_batch
        elif batched:
            if not callable(policy):
                raise TypeError(f"a batched policy must be callable, got {type(policy).__name__}")
            self._batch = policy
        elif isinstance(policy, dict):
            self._policies = {int(k): _as_callable(p, f"policy for player {k}") for k, p in policy.items()}
        else:
            self._shared = _as_callable(policy, "policy")

    @classmethod
    def for_env(cls, policy: Any, env: Any, name: str = "policy", batched: bool = False) -> PolicyTeam:
        """A team playing ``policy`` as the parallel environment ``env`` (built with the options
        the policy was trained with) presents it: its action mode, mask, scenario horizon,
        observation slots and say values. Play it with ``env.config`` (the observation mode)."""
        return cls(policy, name, env.observation_slots, env.say_values, action_mode=env.action_mode,
                   action_mask_in_observation=_has_mask(env), scenario=env.scenario, max_cycles=env.max_cycles,
                   batched=batched)

    def reset(self, side_info: SideInfo, config: MatchConfig, rng: np.random.Generator) -> None:
        n = side_info.players_per_team
        missing = [i for i in range(n) if self._policies and i not in self._policies]
        if missing:
            raise TeamError(self.name, f"no policy for players {missing}")
        self.n = n
        partial = config.observation.partial
        if self.say_values and not partial:
            raise TeamError(self.name, f"say_values={self.say_values} needs partial observation")
        if partial and self._translator is not None:
            raise TeamError(self.name, f"action_mode {self.action_mode!r} needs the exact team view; under partial "
                                       "observation only action_mode='low_level' plays")
        try:
            if partial:
                self._builder = PartialObservationBuilder(n, side_info.opponents, side_info.goalie_index, config,
                                                          self.observation_slots, self.horizon,
                                                          say_values=self.say_values)
            else:
                self._builder = ObservationBuilder(n, side_info.opponents, side_info.goalie_index, config,
                                                   self.observation_slots, self.horizon)
        except ValueError as exc:
            raise TeamError(self.name, str(exc)) from None
        self._names = [f"player {i}" for i in range(n)]
        if self._translator is not None:
            self._translator.reset(side_info, config)
            self._choices = self._translator.size(self._builder.slots)
            self._masks = np.ones((n, self._choices), dtype=np.int8)
        else:
            self._decoder = ActionDecoder(n, side_info.goalie_index, config)
            self._size = ACTION_SIZE + (1 + self.say_values if self.say_values else 0)
            self._actions = np.zeros((n, self._size))

    def act(self, view) -> TeamCommand:
        observations = self._builder.build(view)
        if self._translator is not None:
            if self.action_mask_in_observation and hasattr(self._translator, "action_mask"):
                self._masks[:] = self._translator.action_mask(view, self._builder.slots)
            if self.n == 0:
                return self._translator.command_for(view, np.zeros(0, dtype=np.int64))
            try:
                choices = check_choices(self._names, self._ask(observations), self._choices, self.action_mode)
            except ValueError as exc:
                raise TeamError(self.name, str(exc)) from None
            return self._translator.command_for(view, choices)
        if self.n == 0:  # a side a scenario leaves empty: nothing to ask (a network may refuse an empty batch)
            return self._decoder.decode(self._actions, view)
        try:
            self._actions[:] = check_actions(self._names, self._rows(self._ask(observations)), self._size)
        except ValueError as exc:
            raise TeamError(self.name, str(exc)) from None
        command = self._decoder.decode(self._actions, view)
        if self.say_values:
            command.say = self._builder.codec.encode(self._actions[:, ACTION_SIZE + 1:],
                                                     self._actions[:, ACTION_SIZE] > 0)
        return command

    def _ask(self, observations: np.ndarray) -> Any:
        """The policy's actions for the team's ``observations`` (one call for a batched policy,
        one per player otherwise), with the masks beside them when the environment gave them so."""
        masked = self._translator is not None and self.action_mask_in_observation
        if self._batch is not None:
            batch = {"observation": observations, "action_mask": self._masks.copy()} if masked else observations
            try:
                return self._batch(batch)
            except Exception as exc:
                raise TeamError(self.name, f"policy raised {type(exc).__name__}: {exc}") from exc
        actions = []
        for i in range(self.n):
            policy = self._shared or self._policies[i]
            seen = {"observation": observations[i], "action_mask": self._masks[i].copy()} if masked else observations[i]
            try:
                actions.append(policy(seen))
            except Exception as exc:
                raise TeamError(self.name, f"policy of player {i} raised {type(exc).__name__}: {exc}") from exc
        return actions

    def _rows(self, actions: Any) -> list[Any]:
        """Low-level ``actions`` as one row per player (a TeamError for another count)."""
        try:
            rows = list(actions)
        except TypeError:
            raise TeamError(self.name, f"the policy must give one action per player ({self.n}), "
                                       f"got {actions!r}") from None
        if len(rows) != self.n:
            raise TeamError(self.name, f"the policy must give one action per player ({self.n}), got {len(rows)}")
        return rows


def _has_mask(env: Any) -> bool:
    """Whether ``env``'s observations carry the action mask (``action_mask_in_observation``)."""
    from gymnasium import spaces

    return isinstance(env.observation_space(env.possible_agents[0]), spaces.Dict)
