"""A team of players that act at random: every action drawn uniformly from the action box.

In the environment:  actions = {a: random_policy(obs[a]) for a in env.agents}
In a match:          soccer-sim play examples.random_team:RandomTeam static
"""

import numpy as np

from soccer_sim.env import ACTION_SIZE, PolicyTeam


class RandomPolicy:
    """Uniform random actions in [-1, 1] from its own seeded generator."""

    def __init__(self, seed: int = 0) -> None:
        self.rng = np.random.default_rng(seed)

    def act(self, observation: np.ndarray) -> np.ndarray:
        return self.rng.uniform(-1.0, 1.0, ACTION_SIZE).astype(np.float32)


class RandomTeam(PolicyTeam):
    """The random policy for all eleven players, as a Team."""

    def __init__(self) -> None:
        super().__init__(RandomPolicy(), name="random-actions")
