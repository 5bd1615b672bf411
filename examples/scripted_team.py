"""A scripted team written only against the environment's observations and actions (see
``soccer_sim.env.spaces`` for the layout): the nearest outfield player runs to the ball and
kicks it towards the goal, the others keep a shape that follows the ball, the goalkeeper
guards the goal mouth and catches.

In the environment:  python examples/scripted_vs_random.py
In a tournament:     soccer-sim tournament --teams static,examples.scripted_team:ScriptedTeam --games 4
"""

import numpy as np

from soccer_sim.config import STANDARD_FIELD
from soccer_sim.env import PolicyTeam

# Home spots (x, y) of players 1-10 as fractions of the half length / half width: a 4-4-2.
SPOTS = np.array([(-0.6, -0.6), (-0.6, -0.2), (-0.6, 0.2), (-0.6, 0.6), (-0.2, -0.6), (-0.2, -0.2), (-0.2, 0.2),
                  (-0.2, 0.6), (0.2, -0.2), (0.2, 0.2)])
HALF_WIDTH_SHARE = STANDARD_FIELD.half_width / STANDARD_FIELD.half_length  # positions are / half length


def _towards(vector: np.ndarray, gain: float = 12.0) -> np.ndarray:
    """A dash along ``vector`` (observation units), full power when far, gentler when close."""
    size = float(np.hypot(*vector))
    if size < 1e-9:
        return np.zeros(2)
    return vector / size * min(1.0, size * gain)


def scripted_policy(observation: np.ndarray) -> np.ndarray:
    """One player's action from its own observation."""
    n = (len(observation) - 26) // 10  # 12 + 14 values, and 4 + 1 per player of two sides of n
    me, ball = observation[0:2], observation[6:8]
    mates = observation[12:12 + 4 * n].reshape(n, 4)[:, :2]
    index = int(np.argmin(np.hypot(*(mates - me).T)))
    action = np.zeros(5, dtype=np.float32)
    goal = np.array([1.0, 0.0])
    if observation[5] > 0.5:  # the goalkeeper
        spot = np.array([-0.97, np.clip(ball[1] * 0.3, -0.1, 0.1)])
        action[0:2] = _towards(spot - me)
        if np.hypot(*(ball - me)) < 2.0 / STANDARD_FIELD.half_length:
            action[4] = 1.0
            action[2:4] = _towards(goal - ball, gain=1e9)
        return action
    outfield = np.arange(n) != 0
    distance = np.where(outfield, np.hypot(*(mates - ball).T), np.inf)
    if index == int(np.argmin(distance)):
        action[0:2] = _towards(ball - me)
        action[2:4] = _towards(goal - ball, gain=1e9)
    else:
        spot = SPOTS[(index - 1) % len(SPOTS)] * np.array([1.0, HALF_WIDTH_SHARE])
        target = np.array([spot[0] * 0.6 + ball[0] * 0.5, spot[1] * 0.8 + ball[1] * 0.2])
        action[0:2] = _towards(target - me) * 0.7
    return action


class ScriptedTeam(PolicyTeam):
    """The scripted policy for every player, as a Team for matches and tournaments."""

    def __init__(self) -> None:
        super().__init__(scripted_policy, name="scripted")
