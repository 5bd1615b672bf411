"""The PettingZoo interface: :func:`parallel_env` (a ``ParallelEnv``) and :func:`env` (the
same as an AEC environment, through PettingZoo's conversion), so that PettingZoo's test
helpers and multi-agent RL libraries take the module as it is; :class:`PolicyTeam` enters a
policy written for the environment in matches and tournaments.

Options (keyword arguments of both): ``controlled`` ("left", "right" or "both"),
``opponent`` (a registered team name or Team object for an uncontrolled side; default
:data:`DEFAULT_OPPONENT`), ``max_cycles`` (truncation), ``end_on_goal``, ``config`` (a
MatchConfig), ``render_mode`` ("rgb_array" or "human"), ``reward_shaping``. See
:mod:`soccer_sim.env.parallel` and, for observations and actions, :mod:`soccer_sim.env.spaces`.
"""

from __future__ import annotations

from soccer_sim.env.parallel import DEFAULT_OPPONENT, SoccerParallelEnv
from soccer_sim.env.policy_team import PolicyTeam
from soccer_sim.env.spaces import ACTION_SIZE, observation_size


def parallel_env(**kwargs) -> SoccerParallelEnv:
    """The parallel environment (see the module docstring for the options)."""
    return SoccerParallelEnv(**kwargs)


def env(**kwargs):
    """The AEC form of :func:`parallel_env`: agents act one after another within a cycle."""
    from pettingzoo.utils.conversions import parallel_to_aec

    return parallel_to_aec(parallel_env(**kwargs))


__all__ = ["ACTION_SIZE", "DEFAULT_OPPONENT", "PolicyTeam", "SoccerParallelEnv", "env", "observation_size",
           "parallel_env"]
