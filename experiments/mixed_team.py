"""Mixed teams for ad hoc teamwork ("drop-in") games: each player runs a different team's code.

A :class:`MixedTeam` wraps one team object per distinct member team. Every cycle each member
team sees the full team view and decides for all eleven players, as if its team-mates played
as it would; player ``i`` then follows the row of its own member team's command (dash, kick,
placement) and the goalkeeper's member team decides the catch. This is the setting of the
drop-in player challenge described in "SCRAM: Scalable Collision-avoiding Role Assignment with
Minimal-makespan for Formational Positioning": nobody knows how its team-mates decide.

A mixed team is named ``mixed(A|B|...)`` with one member team name per player, so the runner can
store it and rebuild it in any worker.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from soccer_sim import SideInfo, TeamCommand, TeamError, resolve_team

_PREFIX, _SUFFIX, _SEPARATOR = "mixed(", ")", "|"


def is_mixed_name(name: str) -> bool:
    return name.startswith(_PREFIX) and name.endswith(_SUFFIX)


def mixed_name(members: list[str] | tuple[str, ...]) -> str:
    """The name of the mixed team whose player ``i`` runs ``members[i]``."""
    for member in members:
        if not member or _SEPARATOR in member or is_mixed_name(member):
            raise ValueError(f"cannot use {member!r} as a member of a mixed team")
    return _PREFIX + _SEPARATOR.join(members) + _SUFFIX


def member_names(name: str) -> list[str]:
    """The member team of every player of a mixed team's name."""
    if not is_mixed_name(name):
        raise ValueError(f"{name!r} is not a mixed team name 'mixed(A|B|...)'")
    return name[len(_PREFIX):-len(_SUFFIX)].split(_SEPARATOR)


def mixed_team(name: str) -> MixedTeam:
    """The MixedTeam of a name made by :func:`mixed_name`."""
    return MixedTeam(member_names(name), name=name)


class MixedTeam:
    """A team whose player ``i`` follows the decision of team ``members[i]`` (see the module)."""

    def __init__(self, members: list[str], name: str | None = None) -> None:
        self.members = list(members)
        self.name = name or mixed_name(self.members)
        self.codes = list(dict.fromkeys(self.members))
        """The distinct member teams, in order of first appearance."""
        self.teams = [resolve_team(code)[0] for code in self.codes]
        index = {code: k for k, code in enumerate(self.codes)}
        self.code_of = np.array([index[m] for m in self.members])
        """Index into :attr:`codes` of every player's member team."""

    def reset(self, side_info: SideInfo, config, rng: np.random.Generator) -> None:
        n = side_info.players_per_team
        if n != len(self.members):
            raise TeamError(self.name, f"has {len(self.members)} member players but the match plays {n} a side")
        # Each member team gets its own stream, drawn from the mixed team's generator.
        for team, code, child in zip(self.teams, self.codes, rng.spawn(len(self.teams))):
            team.reset(dataclasses.replace(side_info, name=code), config, child)
        # The goalkeeper's catch comes from its own member team; with no goalkeeper nobody catches.
        goalie = side_info.goalie_index
        self._goalie_code = int(self.code_of[goalie]) if 0 <= goalie < n else -1
        self._rows = [np.flatnonzero(self.code_of == k) for k in range(len(self.teams))]
        self._command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))
        self._move = np.zeros((n, 2))

    def act(self, view) -> TeamCommand:
        command = self._command
        command.move = None
        for k, team in enumerate(self.teams):
            try:
                decision = team.act(view)
            except Exception as exc:
                raise TeamError(self.name, f"member team {self.codes[k]!r} raised {type(exc).__name__}: {exc}") from exc
            rows = self._rows[k]
            try:
                command.dash[rows] = np.asarray(decision.dash, dtype=float)[rows]
                command.kick[rows] = np.asarray(decision.kick, dtype=float)[rows]
                if decision.move is not None:
                    if command.move is None:
                        self._move[:] = view.own_pos
                        command.move = self._move
                    command.move[rows] = np.asarray(decision.move, dtype=float)[rows]
            except (AttributeError, IndexError, TypeError, ValueError) as exc:
                raise TeamError(self.name, f"member team {self.codes[k]!r} returned a malformed command: "
                                           f"{type(exc).__name__}: {exc}") from exc
            if k == self._goalie_code:
                command.catch = bool(decision.catch)
        return command
