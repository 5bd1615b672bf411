"""The environment's rewards: a sum of named terms, each with its weight.

``rewards`` (an option of the environment) maps term names to weights; the default is
``{"goal": 1.0}`` (sparse: goals only), and ``rewards="dense"`` is :data:`DENSE`, a set of
weights that lets a random policy see a reward at once. Per step, for an agent of team T
(units: metres and cycles; "nearest" is T's player on the pitch nearest to the ball when the
step begins):

=================  =================================================================================
term               reward per step
=================  =================================================================================
``goal``           ``w * (goals of T - goals against T)`` in the step, to every agent of T
``ball_approach``  ``w * (d0 - d1)`` to T's nearest player only: d0, d1 its distance to the ball (m)
                   before and after the step (positive while it closes in)
``possession``     ``w`` to every agent of T when, after the step, a player of T touched the ball last
``ball_progress``  ``w * dx`` to every agent of T: dx the ball's move (m) along T's attacking direction
                   (negative when it goes back; the opponents' loss)
``kick_to_goal``   ``w * s`` to an agent whose kick in the step is a shot (``s`` SHOT events of it: a
                   kick whose unhindered path crosses the opponents' goal line between the posts)
=================  =================================================================================

The old option ``reward_shaping=w`` is ``ball_progress`` with weight w added to the terms.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from soccer_sim.state import EventKind

TERMS = ("goal", "ball_approach", "possession", "ball_progress", "kick_to_goal")
"""Names of the reward terms (see the module docstring)."""
SPARSE = {"goal": 1.0}
"""The default: goals only."""
DENSE = {"goal": 1.0, "ball_approach": 0.01, "possession": 0.001, "ball_progress": 0.01, "kick_to_goal": 0.1}
"""``rewards="dense"``: every term, weighted so that a goal still outweighs the shaping of the
cycles before it (closing in 10 m on the ball earns 0.1, a shot 0.1, a goal 1)."""
_SHOT = int(EventKind.SHOT)


def reward_weights(rewards: Any, reward_shaping: float = 0.0) -> dict[str, float]:
    """The weights of ``rewards`` (None, ``"sparse"``, ``"dense"`` or a mapping term -> weight),
    plus ``reward_shaping`` on ``ball_progress``; ValueError naming an unknown term or a weight
    that is not a finite number."""
    if rewards is None or rewards == "sparse":
        weights = dict(SPARSE)
    elif rewards == "dense":
        weights = dict(DENSE)
    elif isinstance(rewards, Mapping):
        weights = {}
        for name, weight in rewards.items():
            if name not in TERMS:
                raise ValueError(f"unknown reward term {name!r}; the terms are {', '.join(TERMS)}")
            if isinstance(weight, bool) or not isinstance(weight, (int, float, np.integer, np.floating)) \
                    or not np.isfinite(weight):
                raise ValueError(f"the weight of reward term {name!r} must be a finite number, got {weight!r}")
            weights[name] = float(weight)
    else:
        raise ValueError(f"rewards must be None, 'sparse', 'dense' or a dict term -> weight, got {rewards!r}")
    if not (isinstance(reward_shaping, (int, float, np.integer, np.floating)) and np.isfinite(reward_shaping)
            and reward_shaping >= 0):
        raise ValueError(f"reward_shaping must be a non-negative number, got {reward_shaping!r}")
    if reward_shaping:
        weights["ball_progress"] = weights.get("ball_progress", 0.0) + float(reward_shaping)
    return {name: w for name, w in weights.items() if w != 0.0}


class Rewards:
    """Computes every controlled agent's reward of a step into one (N,) float32 array.

    ``sides``: the controlled sides (HOME 0, AWAY 1) in agent order; ``rows``: each side's
    player rows in the world state (a slice); ``offsets``: where each side's agents start in
    the reward array.
    """

    def __init__(self, weights: dict[str, float], sides: tuple[int, ...], rows: dict[int, slice],
                 offsets: dict[int, int], total: int) -> None:
        self.weights = weights
        self.sides, self.rows, self.offsets = sides, rows, offsets
        self.out = np.zeros(total, dtype=np.float32)
        self._nearest = {side: -1 for side in sides}
        self._distance = {side: 0.0 for side in sides}

    def before(self, state: Any) -> None:
        """Note what the step's terms compare against (called before the match steps)."""
        self._score = state.score.copy()
        self._ball_x = float(state.ball[0])
        if "ball_approach" in self.weights:
            for side in self.sides:
                rows = self.rows[side]
                gaps = np.hypot(*(state.pos[rows] - state.ball).T)
                gaps[~state.present[rows]] = np.inf
                nearest = int(np.argmin(gaps)) if gaps.size else -1
                self._nearest[side] = nearest if nearest >= 0 and np.isfinite(gaps[nearest]) else -1
                self._distance[side] = float(gaps[nearest]) if self._nearest[side] >= 0 else 0.0

    def after(self, state: Any, events: Any, start: int) -> np.ndarray:
        """The (N,) rewards of the step just played (events from index ``start`` are the step's)."""
        w, out = self.weights, self.out
        out[:] = 0.0
        goals = state.score - self._score
        home_touched = state.last_touch >= 0 and state.last_touch < state.sizes[0]
        away_touched = state.last_touch >= state.sizes[0]
        for side in self.sides:
            agents = slice(self.offsets[side], self.offsets[side] + self.rows[side].stop - self.rows[side].start)
            team = 0.0
            if "goal" in w:
                team += w["goal"] * float(goals[side] - goals[1 - side])
            if "possession" in w and (home_touched if side == 0 else away_touched):
                team += w["possession"]
            if "ball_progress" in w:
                direction = state.attack_direction(side)
                team += w["ball_progress"] * (float(state.ball[0]) - self._ball_x) * direction
            out[agents] = team
            nearest = self._nearest[side]
            if "ball_approach" in w and nearest >= 0:
                row = self.rows[side].start + nearest
                gap = float(np.hypot(*(state.pos[row] - state.ball)))
                out[agents.start + nearest] += w["ball_approach"] * (self._distance[side] - gap)
        if "kick_to_goal" in w and len(events) > start:
            for k in range(start, len(events)):
                if events.kind[k] == _SHOT and events.team[k] in self.offsets and events.player[k] >= 0:
                    out[self.offsets[events.team[k]] + events.player[k]] += w["kick_to_goal"]
        return out
