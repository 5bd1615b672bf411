"""A team's formations for each game situation.

Teams ask every cycle for the positions of the current situation, so picking
a formation is one dictionary lookup, whether the situation is given as a
:class:`Situation` member or as a plain string (``"attack"``,
``"our_kickoff"``, ...).
"""

from __future__ import annotations

import enum
import os
from collections.abc import Mapping

import numpy as np
from numpy.typing import ArrayLike

from formations.errors import FormationError, FormationInputError
from formations.formation import Formation
from formations.writing import formation_set_to_dict, write_document


class Situation(str, enum.Enum):
    """The game situations a :class:`FormationSet` distinguishes."""

    NORMAL = "normal"
    """Open play, neither side clearly in possession."""
    ATTACK = "attack"
    """Open play with our team in possession."""
    DEFEND = "defend"
    """Open play with the opponents in possession."""
    OUR_SET_PLAY = "our_set_play"
    """Our kick-off, free kick, kick-in, corner or goal kick (ball placed)."""
    THEIR_SET_PLAY = "their_set_play"
    """The opponents' kick-off or set play: keep clear of the ball."""

    def __str__(self) -> str:
        return self.value


SITUATION_ALIASES: dict[str, Situation] = {
    "our_kickoff": Situation.OUR_SET_PLAY,
    "our_kick_off": Situation.OUR_SET_PLAY,
    "their_kickoff": Situation.THEIR_SET_PLAY,
    "their_kick_off": Situation.THEIR_SET_PLAY,
}
"""Other accepted names for situations (kick-offs are set plays)."""


def parse_situation(name: str | Situation) -> Situation:
    """The :class:`Situation` called *name* (a value or an alias); FormationInputError (a ValueError) if none."""
    if isinstance(name, Situation):
        return name
    key = str(name).strip().lower().replace("-", "_")
    if key in SITUATION_ALIASES:
        return SITUATION_ALIASES[key]
    try:
        return Situation(key)
    except ValueError:
        valid = [s.value for s in Situation] + list(SITUATION_ALIASES)
        raise FormationInputError(f"unknown situation {name!r}; expected one of {', '.join(valid)}") from None


class FormationSet:
    """One formation per :class:`Situation`, sharing the same roles.

    ``formations`` must contain :attr:`Situation.NORMAL`; a situation without
    its own formation uses the normal one. All formations must have the same
    roles (numbers, names, kinds, partners) in the same order, so that row i
    of every position array is always the same player.
    """

    def __init__(
        self,
        name: str,
        formations: Mapping[Situation | str, Formation],
        *,
        description: str = "",
        source: str | None = None,
    ) -> None:
        self.name = name
        self.description = description
        self.source = source or (f"formation set {name!r}" if name else "<formation set>")
        own: dict[Situation, Formation] = {}
        for key, formation in formations.items():
            try:
                situation = parse_situation(key)
            except ValueError as error:
                raise FormationError(self.source, str(error)) from None
            if situation in own:
                raise FormationError(self.source, f"situation {situation.value!r} is given twice")
            own[situation] = formation
        if Situation.NORMAL not in own:
            raise FormationError(self.source, "a formation set needs a 'normal' formation")
        roles = own[Situation.NORMAL].roles
        for situation, formation in own.items():
            if formation.roles != roles:
                raise FormationError(
                    self.source,
                    "roles differ from those of the 'normal' formation (numbers, names, kinds and partners "
                    "must match, in the same order)",
                    f"formation {situation.value!r}",
                )
        self.roles = roles
        self._own = own
        # Lookup table keyed by every situation member, its plain-string value
        # and every alias (enum members hash by name, so both are needed).
        table: dict[str, Formation] = {}
        for situation in Situation:
            table[situation] = table[situation.value] = own.get(situation, own[Situation.NORMAL])
        for alias, situation in SITUATION_ALIASES.items():
            table[alias] = table[situation]
        self._table = table

    @property
    def situations(self) -> tuple[Situation, ...]:
        """The situations that have their own formation (others use normal)."""
        return tuple(s for s in Situation if s in self._own)

    def own_formations(self) -> dict[Situation, Formation]:
        """Situation -> formation, for the situations that have their own."""
        return dict(self._own)

    def formation(self, situation: Situation | str = Situation.NORMAL) -> Formation:
        """The formation used in *situation* (a :class:`Situation` or its name)."""
        try:
            return self._table[situation]
        except KeyError:
            return self._table[parse_situation(situation)]

    def positions(self, ball_xy: ArrayLike, situation: Situation | str = Situation.NORMAL) -> np.ndarray:
        """(roles, 2) target positions in *situation* for one ball position."""
        try:
            formation = self._table[situation]
        except KeyError:
            formation = self._table[parse_situation(situation)]
        return formation.positions(ball_xy)

    def positions_many(self, balls: ArrayLike, situation: Situation | str = Situation.NORMAL) -> np.ndarray:
        """(k, roles, 2) target positions in *situation* for (k, 2) ball positions."""
        return self.formation(situation).positions_many(balls)

    def save(self, path: str | os.PathLike[str]) -> None:
        """Write this set to *path* in the package's JSON layout."""
        write_document(formation_set_to_dict(self), path)

    def __repr__(self) -> str:
        own = ", ".join(s.value for s in self.situations)
        return f"FormationSet(name={self.name!r}, situations=[{own}])"
