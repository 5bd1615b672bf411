"""The PettingZoo interface: :func:`parallel_env` (a ``ParallelEnv``) and :func:`env` (the
same as an AEC environment), so that PettingZoo's test helpers and multi-agent RL libraries
take the module as it is; :class:`PolicyTeam` enters a policy written for the environment in
matches and tournaments, and :func:`load_policy` / :func:`checkpoint_team` a saved checkpoint of
an RL library (:mod:`soccer_sim.env.checkpoints`, the optional extra ``rl``). User guide:
``docs/env.md``.

Options (keyword arguments of both):

``controlled``
    "left", "right" or "both" (default): the sides played by agents.
``scenario``
    a :class:`~soccer_sim.scenarios.Scenario`, a library name (``"3-vs-1-with-keeper"``) or a
    ``.json``/``.toml`` file (default: the regular match); sizes the sides and ends episodes
    on its end conditions.
``opponent``
    the uncontrolled side: a registered team name, a ``package.module:Attribute`` path or a
    Team object (default :data:`DEFAULT_OPPONENT`).
``max_cycles``
    truncate after this many steps (default: none).
``end_on_goal``
    terminate at the first goal (default False).
``config``
    a MatchConfig (default: the regular one).
``action_mode``
    "low_level" (default; ``Box(-1, 1, (5,))``) or "high_level" (``Discrete(13 + k)``).
``rewards``
    None or "sparse" (goals only, the default), "dense", or a dict term -> weight
    (:mod:`soccer_sim.env.rewards`); ``reward_shaping`` w adds w to ``ball_progress``.
``event_texts``
    also put the step's events as text in the infos (default False: numbers only,
    :mod:`soccer_sim.env.infos`).
``action_mask_in_observation``
    observations are dicts ``{"observation", "action_mask"}`` (discrete modes; default False:
    the Box observation, the mask in ``infos[agent]["action_mask"]``).
``observation_slots``
    player slots per side in an observation (default 11: one layout for every scenario,
    :mod:`soccer_sim.env.spaces`).
``observation``
    "full" (the exact world in every agent's team frame, :mod:`soccer_sim.env.spaces`) or
    "partial" (each agent's own noisy, range-limited view of the match's partial observation,
    :mod:`soccer_sim.env.partial_spaces`; low-level actions only; the opponent must play
    partial); default: the config's mode (full).
``say_values``
    0 to 5, partial observation only: the low-level action gains a speak flag and this many
    values, said as one message to the team-mates in range and decoded in their next
    observation (:mod:`soccer_sim.env.say_codec`); default 0.
``render_mode``
    "rgb_array" or "human" (a rerun viewer, or an ``.rrd`` file in ``record_dir`` where no
    display is; :mod:`soccer_sim.env.render`).

:func:`vector_env` steps several matches at once, in this process or on worker processes
(:mod:`soccer_sim.env.vector`). See :mod:`soccer_sim.env.parallel` for episodes and the batched interface
(``reset_arrays``/``step_arrays``), :mod:`soccer_sim.env.global_state` for ``state()``,
:mod:`soccer_sim.env.persistence` for pickling.
"""

from __future__ import annotations

from soccer_sim.env.checkpoint_teams import checkpoint_team
from soccer_sim.env.checkpoints import CheckpointError, load_policy
from soccer_sim.env.infos import EVENT_KIND_NAMES, PLAY_MODE_NAMES
from soccer_sim.env.options import DEFAULT_OPPONENT
from soccer_sim.env.parallel import SoccerParallelEnv
from soccer_sim.env.partial_spaces import partial_observation_size
from soccer_sim.env.policy_team import PolicyTeam
from soccer_sim.env.rewards import DENSE, TERMS
from soccer_sim.env.spaces import ACTION_SIZE, OBSERVATION_SLOTS, observation_size
from soccer_sim.env.vector import vector_env


def parallel_env(**options) -> SoccerParallelEnv:
    """The parallel environment (see the module docstring for the options)."""
    return SoccerParallelEnv(**options)


def env(**options):
    """The AEC form of :func:`parallel_env`: agents act one after another within a cycle, each
    action checked at its own agent's step (:mod:`soccer_sim.env.aec`)."""
    from soccer_sim.env.aec import to_aec

    return to_aec(parallel_env(**options))


__all__ = ["ACTION_SIZE", "CheckpointError", "DEFAULT_OPPONENT", "DENSE", "EVENT_KIND_NAMES", "OBSERVATION_SLOTS",
           "PLAY_MODE_NAMES", "PolicyTeam", "SoccerParallelEnv", "TERMS", "checkpoint_team", "env", "load_policy",
           "observation_size", "parallel_env", "partial_observation_size", "vector_env"]
