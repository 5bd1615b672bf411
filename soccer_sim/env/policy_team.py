"""Enter a policy written for the environment in matches and tournaments as a Team.

:class:`PolicyTeam` builds each player's observation from the team's view exactly as the
environment does (:mod:`soccer_sim.env.spaces`), asks the policy for the players' actions and
turns them into the team's command. The policy is a callable ``policy(observation) -> action``,
an object with ``act(observation) -> action`` (used for every player), or a dict from player
index (0 = goalkeeper) or agent suffix to such a policy, one per player.

It plays under both observation modes: under full observation with the observations of
:mod:`soccer_sim.env.spaces`, under partial observation (``MatchConfig.observation.mode ==
"partial"``) with those of :mod:`soccer_sim.env.partial_spaces`, built from each player's own
view as the environment's ``observation="partial"`` builds them; with ``say_values=k`` the
actions carry the speak flag and the message's values (:mod:`soccer_sim.env.say_codec`), as the
environment's option of that name. The policy must have been trained under the same mode.
"""

from __future__ import annotations

from typing import Any, Callable

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.env.partial_spaces import PartialObservationBuilder
from soccer_sim.env.say_codec import MAX_SAY_VALUES
from soccer_sim.env.spaces import ACTION_SIZE, ActionDecoder, ObservationBuilder, check_actions
from soccer_sim.team import SideInfo, TeamCommand, TeamError


def _as_callable(policy: Any, where: str) -> Callable[[np.ndarray], Any]:
    if hasattr(policy, "act") and callable(policy.act):
        return policy.act
    if callable(policy):
        return policy
    raise TypeError(f"{where} must be callable or have an act(observation) method, got {type(policy).__name__}")


class PolicyTeam:
    """A team playing ``policy`` for every player (see the module docstring); ``name`` is
    how results name it; ``observation_slots``: as the environment's option of that name (the
    policy must see the layout it was trained on; default 11 slots a side); ``say_values``: as the
    environment's option (partial observation only)."""

    observation_modes = ("full", "partial")

    def __init__(self, policy: Any, name: str = "policy", observation_slots: int | None = None,
                 say_values: int = 0) -> None:
        self.name = name
        self.observation_slots = observation_slots
        if isinstance(say_values, bool) or not isinstance(say_values, (int, np.integer)) or not \
                0 <= say_values <= MAX_SAY_VALUES:
            raise ValueError(f"say_values must be an integer from 0 to {MAX_SAY_VALUES}, got {say_values!r}")
        self.say_values = int(say_values)
        if isinstance(policy, dict):
            self._policies = {int(k): _as_callable(p, f"policy for player {k}") for k, p in policy.items()}
            self._shared = None
        else:
            self._policies = {}
            self._shared = _as_callable(policy, "policy")

    def reset(self, side_info: SideInfo, config: MatchConfig, rng: np.random.Generator) -> None:
        n = side_info.players_per_team
        missing = [i for i in range(n) if self._shared is None and i not in self._policies]
        if missing:
            raise TeamError(self.name, f"no policy for players {missing}")
        self.n = n
        partial = config.observation.partial
        if self.say_values and not partial:
            raise TeamError(self.name, f"say_values={self.say_values} needs partial observation")
        try:
            if partial:
                self._builder = PartialObservationBuilder(n, side_info.opponents, side_info.goalie_index, config,
                                                          self.observation_slots, say_values=self.say_values)
            else:
                self._builder = ObservationBuilder(n, side_info.opponents, side_info.goalie_index, config,
                                                   self.observation_slots)
        except ValueError as exc:
            raise TeamError(self.name, str(exc)) from None
        self._decoder = ActionDecoder(n, side_info.goalie_index, config)
        self._size = ACTION_SIZE + (1 + self.say_values if self.say_values else 0)
        self._actions = np.zeros((n, self._size))
        self._names = [f"player {i}" for i in range(n)]

    def act(self, view) -> TeamCommand:
        observations = self._builder.build(view)
        actions = []
        for i in range(self.n):
            policy = self._shared or self._policies[i]
            try:
                actions.append(policy(observations[i]))
            except Exception as exc:
                raise TeamError(self.name, f"policy of player {i} raised {type(exc).__name__}: {exc}") from exc
        try:
            self._actions[:] = check_actions(self._names, actions, self._size)
        except ValueError as exc:
            raise TeamError(self.name, str(exc)) from None
        command = self._decoder.decode(self._actions, view)
        if self.say_values:
            command.say = self._builder.codec.encode(self._actions[:, ACTION_SIZE + 1:],
                                                     self._actions[:, ACTION_SIZE] > 0)
        return command
