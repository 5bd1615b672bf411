"""A team written against the environment's high-level (discrete, masked) actions, entered in
matches as a :class:`~soccer_sim.env.PolicyTeam` exactly as a learned policy of that action mode
would be: one ``act_batch`` call a cycle on the whole team's observations and masks.

The player nearest the ball intercepts it; with the ball it shoots from within 25 m of the goal,
else dribbles; the others go to their formation targets (action numbers:
``agents.high_level_actions``).

In a tournament:  soccer-sim tournament --teams static,examples.high_level_team:team --games 4
Evaluated:        soccer-sim evaluate examples.high_level_team:team --scenario empty-goal --episodes 20
"""

import numpy as np

from soccer_sim.config import STANDARD_FIELD
from soccer_sim.env import PolicyTeam

GO_TO_TARGET, INTERCEPT, SHOOT, DRIBBLE = 8, 9, 10, 11
SHOOTING_RANGE = 25.0 / (STANDARD_FIELD.length / 2)
"""How near the opponents' goal a player shoots, in observation units (positions / half length)."""


class HighLevelPolicy:
    """The policy of the module docstring, for the whole team at once."""

    def act_batch(self, observations: dict) -> np.ndarray:
        """``observations``: ``{"observation": (n, D), "action_mask": (n, A)}``; returns (n,) actions."""
        rows, masks = observations["observation"], observations["action_mask"]
        own, to_ball = rows[:, 0:2], rows[:, 10:12]
        actions = np.full(len(rows), GO_TO_TARGET, dtype=np.int64)
        distance = np.hypot(to_ball[:, 0], to_ball[:, 1])
        actions[int(np.argmin(distance))] = INTERCEPT
        near_goal = np.hypot(own[:, 0] - 1.0, own[:, 1]) < SHOOTING_RANGE
        actions[(masks[:, DRIBBLE] == 1)] = DRIBBLE
        actions[(masks[:, SHOOT] == 1) & near_goal] = SHOOT
        return actions


def team() -> PolicyTeam:
    """The team, named ``high-level`` in results and tables."""
    return PolicyTeam(HighLevelPolicy(), name="high-level", action_mode="high_level", action_mask_in_observation=True)
