"""Optional things a team may offer besides ``reset`` and ``act``.

A team that implements one of these protocols gets more out of the tools around a match:

* :class:`ReportsStatistics`: ``statistics()`` returns per-match figures (name -> number)
  that match statistics, the results store and the tables carry as the team's own figures.
* :class:`ChoosesPlayerTypes`: ``choose_player_types(types, side_info)`` picks a
  heterogeneous player type per player at reset (:mod:`soccer_sim.player_types`); a team
  without it plays every player as the default type 0.
* :class:`Drawable`: ``drawing()`` returns a :class:`Drawing` that a replay draws over the
  pitch (role targets, where each player is going, the current formation's triangulation).
* :class:`ReportsRoles`: ``role_labels()`` names each player's current role (e.g.
  ``"defender"``), so that ``bench soccer`` can split the distance run by role. Only that
  benchmark calls it (once per cycle); a normal match never does.

* ``observation_modes``: a tuple attribute naming the observation modes the team plays under
  (``("full",)`` when absent). A team that lists ``"partial"`` accepts, under
  ``MatchConfig.observation.mode == "partial"``, a
  :class:`~soccer_sim.perception.views.PlayerViews` (each player's own noisy view and the
  messages it heard) in ``act`` instead of the exact ``TeamView``
  (:func:`check_observation_mode`).

Both are checked structurally (``isinstance(team, Drawable)``), so a team needs no base class.
Import them from here: ``from soccer_sim.team_hooks import Drawable, Drawing, ReportsStatistics``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Protocol, Sequence, runtime_checkable

import numpy as np


@runtime_checkable
class ReportsStatistics(Protocol):
    """A team that reports its own per-match figures."""

    def statistics(self) -> dict[str, float]:
        """Figures of the match so far, by name (called once, when the match ends)."""
        ...


@dataclass(frozen=True)
class Drawing:
    """What a replay may draw for one team at one cycle, in the team's own frame (metres; the
    team attacks towards +x).

    ``targets`` (n, 2): each role's target. ``goals`` (n, 2): where each player is going.
    ``outfield``: the outfield players' indices. ``role_of_player``: outfield player ->
    outfield role (None before the first assignment). ``assigned_targets`` (k, 2): one row per
    outfield player, its role's target (None before the first assignment).
    ``formation_balls`` (m, 2) and ``formation_triangles`` (t, 3): the current formation's
    sample ball positions and its Delaunay triangles (indices into ``formation_balls``); None
    when the team has no formation to show.
    """

    targets: np.ndarray
    goals: np.ndarray
    outfield: np.ndarray
    role_of_player: np.ndarray | None = None
    assigned_targets: np.ndarray | None = None
    formation_balls: np.ndarray | None = None
    formation_triangles: np.ndarray | None = None

    def __post_init__(self) -> None:
        """Hold every field as a numpy array of the documented shape (arrays of the right kind
        pass through without a copy, so a formation's arrays keep their identity); a ValueError
        naming the field otherwise."""
        for name, columns, kind in _FIELDS:
            value = getattr(self, name)
            if value is None:
                if name in _REQUIRED:
                    raise ValueError(f"Drawing.{name} is required")
                continue
            array = value if isinstance(value, np.ndarray) and value.dtype.kind in kind else np.asarray(
                value, dtype=np.float64 if kind == "f" else np.intp)
            if array.ndim != (1 if columns is None else 2) or (columns is not None and array.shape[1] != columns):
                shape = "(n,)" if columns is None else f"(n, {columns})"
                raise ValueError(f"Drawing.{name} must have shape {shape}, got {array.shape}")
            object.__setattr__(self, name, array)


_FIELDS = (("targets", 2, "f"), ("goals", 2, "f"), ("outfield", None, "iu"), ("role_of_player", None, "iu"),
           ("assigned_targets", 2, "f"), ("formation_balls", 2, "f"), ("formation_triangles", 3, "iu"))
"""Each field of :class:`Drawing`: name, columns (None: one-dimensional) and the numpy kinds
accepted as they are (others are converted to float64, or to intp for index fields)."""
_REQUIRED = ("targets", "goals", "outfield")


@runtime_checkable
class Drawable(Protocol):
    """A team that can show a replay what it is thinking."""

    def drawing(self) -> Drawing:
        """The team's current drawing (called once per recorded cycle)."""
        ...


@runtime_checkable
class ChoosesPlayerTypes(Protocol):
    """A team that picks rcssserver's heterogeneous player types for its players."""

    def choose_player_types(self, types: tuple[Any, ...], side_info: Any) -> Sequence[int]:
        """One type id per player of the team (row order), from ``types`` (the match's
        :class:`~soccer_sim.player_types.PlayerType` tuple, type 0 the default); at most
        ``pt_max`` players of one non-default type. Called once, before ``reset``."""
        ...


@runtime_checkable
class BelievesBall(Protocol):
    """A team that can say where each of its players believes the ball is (its world model
    under partial observation). The rcssserver bridge aims kicks, catches and the neck with
    it on the steps without a see."""

    def believed_ball(self) -> np.ndarray:
        """(n, 2) where each player (row order) believes the ball is now, in the team's frame
        (m), after the team's ``act`` of the cycle; NaN rows for players without any ball
        information yet."""
        ...


@runtime_checkable
class ReportsRoles(Protocol):
    """A team that can name the role each of its players is playing now."""

    def role_labels(self) -> Sequence[str]:
        """One label per player of the team (row order), e.g. ``"goalkeeper"``,
        ``"defender"`` or a finer name such as ``"centre-back"``; any strings will do (readers
        group figures by the label as given). Called after the team's ``act`` of a cycle."""
        ...


def observation_modes(team: object) -> tuple[str, ...]:
    """The observation modes ``team`` plays under: its ``observation_modes`` attribute, else
    ``("full",)``."""
    modes = getattr(team, "observation_modes", ("full",))
    return tuple(modes) if isinstance(modes, (tuple, list, frozenset, set)) else ("full",)


def plays_partial(team: object) -> bool:
    """Whether ``team`` plays under partial observation (``"partial"`` in its ``observation_modes``)."""
    return "partial" in observation_modes(team)


def check_observation_mode(team: object, name: str, mode: str) -> None:
    """A :class:`~soccer_sim.team.TeamError` naming the team unless it plays under observation
    ``mode``: a team written for the exact ``TeamView`` would otherwise fail on its first ``act``
    with an unrelated attribute error (and one written for per-player views under full)."""
    if mode in observation_modes(team):
        return
    from soccer_sim.team import TeamError

    if mode == "partial":
        raise TeamError(name, "cannot play under partial observation: its act() takes the exact TeamView. "
                              "A team that takes each player's PlayerViews declares "
                              "observation_modes = ('full', 'partial') (docs/simulator.md, section 14)")
    raise TeamError(name, f"cannot play under {mode} observation: it declares observation_modes = "
                          f"{observation_modes(team)!r}")
