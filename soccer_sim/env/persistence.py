"""Pickling and deep-copying the environment, by replaying its episode.

A match holds a pymunk space (C data, whose own pickling does not keep the numpy windows the
simulator shares between the world state, the teams' views and the solver) and many arrays
that are views of one another, so the environment is not pickled object by object. A match
is a pure function of its teams, configuration, scenario, seed and the agents' actions
(:mod:`soccer_sim.match`), so what is pickled is that: the environment's options, its seed
generator, the episode's match seed and every step's actions as the environment checked
them (one (N, A) array per step). Unpickling builds the environment anew, starts the same
match and replays the actions: the copy is in exactly the state of the original (the same
observations, rewards, infos and ends, bit for bit, from then on).

The cost: the actions in the pickle (1.3 MB for 3,000 steps of 11 agents), and the replay's
time on unpickling: the match's cycles played again, without building the observations
between (after 3,000 steps a copy took 0.26 s with both sides controlled, 0.37 s against the
default opponent, on a shared 2-core machine). ``copy.deepcopy`` goes the same way. A
``render_mode="human"`` copy does not record the replayed part again.
"""

from __future__ import annotations

from typing import Any

import numpy as np


class ReplayPickling:
    """Mixin of :class:`~soccer_sim.env.parallel.SoccerParallelEnv`: ``__getstate__`` and
    ``__setstate__`` (see the module docstring). The environment provides ``_options``,
    ``_seeds``, ``_match_seed``, ``_log``, ``_start(seed, record)`` and ``_advance(actions)``."""

    def __getstate__(self) -> dict[str, Any]:
        live = self._match is not None
        log = np.stack(self._log) if live and self._log else None
        return {"options": self._options.kwargs, "seeds": self._seeds, "match_seed": self._match_seed if live
                else None, "log": log, "steps": self._steps if live else 0,
                "limits": (self.max_cycles, self.end_on_goal)}

    def __setstate__(self, state: dict[str, Any]) -> None:
        self.__init__(**state["options"])
        self._seeds = state["seeds"]
        self.max_cycles, self.end_on_goal = state["limits"]  # as set on the original (PettingZoo's tests do)
        if state["match_seed"] is None:
            return
        self._start(state["match_seed"], record=False)
        log, steps = state["log"], state["steps"]
        for k in range(steps):
            self._advance(log[k], observe=k == steps - 1)
