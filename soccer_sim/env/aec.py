"""The AEC form of the environment: agents act one after another within a cycle.

PettingZoo's conversion of the parallel environment (``parallel_to_aec``) collects the
agents' actions and plays the cycle at the last agent's step, so a bad action of ``left_0``
would only be reported at ``left_10``'s step. :class:`SoccerAECWrapper` checks each action at
its own agent's step (a ValueError naming the agent, before anything is stored), and is
otherwise PettingZoo's conversion.
"""

from __future__ import annotations

from typing import Any

from pettingzoo.utils.conversions import parallel_to_aec_wrapper
from pettingzoo.utils.wrappers import OrderEnforcingWrapper


class SoccerAECWrapper(parallel_to_aec_wrapper):
    """PettingZoo's parallel-to-AEC conversion, checking every action at its agent's step."""

    def step(self, action: Any) -> None:
        agent = self.agent_selection
        if not (self.terminations[agent] or self.truncations[agent]):
            self.env.check_agent_action(agent, action)
        super().step(action)


def to_aec(parallel_env: Any) -> OrderEnforcingWrapper:
    """``parallel_env`` as an AEC environment (wrapped in PettingZoo's order checks, as
    ``parallel_to_aec`` does)."""
    return OrderEnforcingWrapper(SoccerAECWrapper(parallel_env))
