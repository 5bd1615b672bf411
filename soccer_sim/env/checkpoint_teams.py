"""Checkpoint team names: ``checkpoint:KIND:PATH?OPTION=VALUE&...`` names a saved RL checkpoint
entered as a :class:`~soccer_sim.env.PolicyTeam`, so that the command line (``evaluate``,
``tournament``, ``play``) and the results store can name, store and rebuild it like any team.

``KIND`` is a kind of :data:`soccer_sim.env.checkpoints.KINDS` (``sb3``, ``torch``/``torchrl``,
``tianshou``, ``rllib``), ``PATH`` the checkpoint's file or directory (relative to the directory
the command runs in; no commas, which separate teams in a list). The options after ``?``, joined
by ``&``, say how the policy was trained, with the environment's option names, so that it sees
the observations it was trained on (:class:`~soccer_sim.env.PolicyTeam`):

=============================  ==============================================================
``scenario``                   the training scenario (a library name or a file): the time
                               feature's horizon (300 cycles on empty-goal)
``max_cycles``                 the training environment's ``max_cycles``
``action_mode``                ``low_level`` (default) or ``high_level``
``action_mask_in_observation`` ``true`` when the policy was trained on ``{"observation",
                               "action_mask"}`` observations (default ``false``)
``observation_slots``          the training environment's slots (default 11)
``say_values``                 the training environment's say values (default 0)
``name``                       the team's name in tables (default: the checkpoint's file name
                               without its extension)
=============================  ==============================================================

and the loader's own: ``algorithm`` (sb3, default ``PPO``), ``deterministic`` (sb3, default
``true``), ``constructor`` (torch, tianshou: ``package.module:callable`` for a state dict),
``policy`` (rllib: the policy id). For example
``checkpoint:sb3:runs/ppo.zip?scenario=empty-goal&name=ppo-empty-goal``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from soccer_sim.env.checkpoints import KINDS, CheckpointError, load_policy
from soccer_sim.env.policy_team import LOW_LEVEL, PolicyTeam

PREFIX = "checkpoint:"

TEAM_OPTIONS = {"scenario": str, "max_cycles": int, "action_mode": str, "action_mask_in_observation": bool,
                "observation_slots": int, "say_values": int, "name": str}
"""The options that shape the team (the environment's names) and how their values read."""
LOADER_OPTIONS = {"algorithm": str, "deterministic": bool, "constructor": str, "policy": str}
"""The options passed to the loader (:func:`soccer_sim.env.checkpoints.load_policy`)."""
TRUE, FALSE = ("true", "1", "yes"), ("false", "0", "no")


def is_checkpoint_name(name: str) -> bool:
    """Whether ``name`` is a checkpoint team name (starts with ``checkpoint:``)."""
    return name.startswith(PREFIX)


@dataclass(frozen=True)
class CheckpointSpec:
    """A checkpoint team name, read (see the module docstring)."""

    kind: str
    path: str
    team: dict[str, Any] = field(default_factory=dict)
    """The PolicyTeam options given (``name`` included)."""
    loader: dict[str, Any] = field(default_factory=dict)
    """The loader options given."""

    @property
    def name(self) -> str:
        """The team's name in tables: the ``name`` option, else the checkpoint's file stem."""
        return self.team.get("name") or Path(self.path).stem or self.path


def _value(option: str, text: str, kind: type) -> Any:
    if kind is bool:
        if text.lower() in TRUE:
            return True
        if text.lower() in FALSE:
            return False
        raise CheckpointError(f"option {option}={text!r} must be true or false")
    if kind is int:
        try:
            return int(text)
        except ValueError:
            raise CheckpointError(f"option {option}={text!r} must be an integer") from None
    if not text:
        raise CheckpointError(f"option {option}= needs a value")
    return text


def parse_checkpoint_name(name: str) -> CheckpointSpec:
    """The :class:`CheckpointSpec` of a checkpoint team name; a :class:`CheckpointError` saying
    what is wrong with it (kind, path, an option or its value)."""
    if not is_checkpoint_name(name):
        raise CheckpointError(f"{name!r} is not a checkpoint team name ('checkpoint:KIND:PATH')")
    kind, sep, rest = name[len(PREFIX):].partition(":")
    if not sep or kind not in KINDS:
        raise CheckpointError(f"team {name!r}: a checkpoint team is named 'checkpoint:KIND:PATH' with KIND one of "
                              f"{', '.join(KINDS)}")
    path, _, query = rest.partition("?")
    if not path:
        raise CheckpointError(f"team {name!r}: no checkpoint path after 'checkpoint:{kind}:'")
    if "," in path:
        raise CheckpointError(f"team {name!r}: a checkpoint path cannot hold a comma (commas separate teams)")
    team: dict[str, Any] = {}
    loader: dict[str, Any] = {}
    for item in filter(None, query.split("&")):
        option, equals, text = item.partition("=")
        if not equals:
            raise CheckpointError(f"team {name!r}: option {item!r} must look like OPTION=VALUE")
        if option in TEAM_OPTIONS:
            target, kind_of = team, TEAM_OPTIONS[option]
        elif option in LOADER_OPTIONS:
            target, kind_of = loader, LOADER_OPTIONS[option]
        else:
            raise CheckpointError(f"team {name!r}: unknown option {option!r}; the options: "
                                  f"{', '.join([*TEAM_OPTIONS, *LOADER_OPTIONS])}")
        if option in target:
            raise CheckpointError(f"team {name!r}: option {option!r} is given twice")
        try:
            target[option] = _value(option, text, kind_of)
        except CheckpointError as exc:
            raise CheckpointError(f"team {name!r}: {exc}") from None
    return CheckpointSpec(kind, path, team, loader)


def checkpoint_team(name: str) -> PolicyTeam:
    """The :class:`~soccer_sim.env.PolicyTeam` a checkpoint team name describes, its checkpoint
    loaded; a :class:`CheckpointError` (one line) for a bad name, option, file or a library
    that is not installed."""
    spec = parse_checkpoint_name(name)
    options = {k: v for k, v in spec.team.items() if k != "name"}
    discrete = options.get("action_mode", LOW_LEVEL) != LOW_LEVEL
    try:
        policy = load_policy(spec.kind, spec.path, discrete=discrete, **spec.loader)
    except CheckpointError as exc:
        raise CheckpointError(f"team {name!r}: {exc}") from None
    try:
        return PolicyTeam(policy, spec.name, batched=True, **options)
    except ValueError as exc:  # a bad action_mode, scenario, slots, ...
        raise CheckpointError(f"team {name!r}: {' '.join(str(exc).split())}") from None
