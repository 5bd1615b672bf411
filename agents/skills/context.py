"""The per-match state the skills share: :class:`SkillContext`.

A team makes one context in ``Team.reset`` (:meth:`SkillContext.for_match`) and passes it to
every skill that reads a view. It holds

* the :class:`~agents.skills.model.MotionModel` (constants and tables of the configuration);
* tables made once per match: the control radii of both sides, the interception search's
  constants (:class:`InterceptConstants`), and the small tables a skill derives from its
  parameters (:meth:`SkillContext.table`);
* the view's arrays, checked: a match hands a team the same view arrays every cycle,
  overwritten in place, so :meth:`SkillContext.arrays` checks them when it first sees them
  and hands the checked :class:`ViewArrays` back for as long as the view holds the same
  array objects (checking them costs more than the ball race itself).

Players given as raw arrays enter through :class:`Players`, which checks them once.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable
from typing import NamedTuple, TypeVar

import numpy as np

from agents.skills.interception_kernels import INTERCEPT_PARAMS, Runners
from agents.skills.model import MotionModel, SkillInputError, float_array, view_effort
from soccer_sim.kernels import make_record
from soccer_sim.config import MatchConfig
from soccer_sim.team import SideInfo, TeamView

_T = TypeVar("_T")


class Players:
    """One team's players as the interception search takes them, checked once here:
    ``pos`` and ``vel`` (n, 2), ``effort`` (n,) (None: 1), ``radius`` (n,) each player's control
    distance (None: the kickable distance) and ``catch_radius`` (n,) the one inside the penalty
    area where it catches (None: ``radius``), all C-contiguous float64 (the compiled search
    relies on it, as it does not check bounds)."""

    __slots__ = ("pos", "vel", "effort", "radius", "catch_radius", "_runners")

    def __init__(self, model: MotionModel, pos: np.ndarray, vel: np.ndarray, effort: np.ndarray | None = None,
                 radius: np.ndarray | None = None, catch_radius: np.ndarray | None = None) -> None:
        self.pos = float_array("pos", pos, (-1, 2))
        n = self.pos.shape[0]
        self.vel = float_array("vel", vel, (n, 2))
        self.effort = np.ones(n) if effort is None else float_array("effort", effort, (n,))
        self.radius = np.full(n, model.kickable_distance) if radius is None else float_array("radius", radius, (n,))
        self.catch_radius = self.radius if catch_radius is None else float_array("catch_radius", catch_radius, (n,))

    @property
    def count(self) -> int:
        """Number of players."""
        return self.pos.shape[0]

    @property
    def runners(self) -> Runners:
        """These players' arrays as the compiled searches take them (the same arrays; made once)."""
        try:
            return self._runners
        except AttributeError:
            self._runners = Runners(self.pos, self.vel, self.effort, self.radius, self.catch_radius)
            return self._runners

    def rows(self, start: int, stop: int) -> Players:
        """Players ``start`` to ``stop - 1`` alone (views of these arrays, no copy)."""
        part = object.__new__(Players)
        part.pos, part.vel, part.effort = self.pos[start:stop], self.vel[start:stop], self.effort[start:stop]
        part.radius, part.catch_radius = self.radius[start:stop], self.catch_radius[start:stop]
        return part

    def with_radii(self, radius: np.ndarray, catch_radius: np.ndarray) -> Players:
        """The same players with other control radii ((n,) each), checked."""
        n = self.pos.shape[0]
        other = object.__new__(Players)
        other.pos, other.vel, other.effort = self.pos, self.vel, self.effort
        other.radius = float_array("radius", radius, (n,))
        other.catch_radius = float_array("catch_radius", catch_radius, (n,))
        return other


class ViewArrays(NamedTuple):
    """A view's arrays checked for the skills: the ball (1, 2) and its velocity (1, 2) as
    one-row trajectories, our players (the view's effort, our control radii), the opponents
    (effort 1, their control radii) and our players' stamina (n,)."""

    ball: np.ndarray
    ball_vel: np.ndarray
    ours: Players
    theirs: Players
    stamina: np.ndarray


class InterceptConstants(NamedTuple):
    """The interception search's constants of one match (metres, m/cycle, m/cycle²), passed
    to the compiled search as an :data:`~agents.skills.interception_kernels.INTERCEPT_PARAMS`
    record (:attr:`SkillContext.intercept_params`)."""

    x_max: float
    """|x| beyond which the ball has left the field: half length plus the ball's radius (the
    ball is in play until it is wholly over a line, so a ball on a line can be reached)."""
    y_max: float
    """|y| beyond which the ball has left the field."""
    top_speed: float
    """Steady running speed at full effort, for estimates beyond the horizon."""
    area_x: float
    """|x| of the penalty areas' front lines."""
    area_y: float
    """Half width of the penalty areas."""
    accel_max: float
    speed_max: float
    decay: float
    """Player decay per cycle."""
    body: float
    """Centre distance at which the ball touches a player's body."""


class SkillContext:
    """Everything the skills share during one match (see the module docstring)."""

    def __init__(self, model: MotionModel) -> None:
        if not isinstance(model, MotionModel):
            raise SkillInputError(f"SkillContext needs a MotionModel, got {type(model).__name__}")
        self.model = model
        self.intercept_constants = InterceptConstants(
            x_max=model.half_length + model.ball_radius, y_max=model.half_width + model.ball_radius,
            top_speed=model.top_speed, area_x=model.half_length - model.penalty_area_length,
            area_y=model.penalty_area_half_width, accel_max=model.accel_max, speed_max=model.speed_max,
            decay=model.player_decay, body=model.touch_distance)
        """The interception search's constants."""
        self.intercept_params = make_record(INTERCEPT_PARAMS, **self.intercept_constants._asdict())
        """The same constants as the compiled search reads them (an
        :data:`~agents.skills.interception_kernels.INTERCEPT_PARAMS` record; never to be written)."""
        self._our_radii: dict[float, tuple[np.ndarray, np.ndarray]] = {}
        self._their_radii: dict[float, tuple[np.ndarray, np.ndarray]] = {}
        self._tables: dict[Hashable, object] = {}
        self._held: tuple | None = None
        self._arrays: ViewArrays | None = None

    @classmethod
    def for_match(cls, config: MatchConfig, side: SideInfo, horizon: int = 60) -> SkillContext:
        """The context of a team playing as ``side`` under ``config`` (for ``Team.reset``)."""
        return cls(MotionModel.for_side(config, side, horizon))

    # --- tables ----------------------------------------------------------------------------
    def team_radii(self, extra: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
        """(radius, catch radius) (n,) of our players: the kickable distance, and for our
        goalkeeper the larger of it and the catch length; both widened by ``extra`` (m).
        Made once per margin; never to be written."""
        found = self._our_radii.get(extra)
        if found is None:
            model = self.model
            radius, catch = control_radii(model, model.goalie_index, model.players_per_team)
            found = self._our_radii[extra] = (radius + extra, catch + extra)
        return found

    def opponent_radii(self, extra: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
        """:meth:`team_radii` for the opponents (their size and goalkeeper); the same arrays
        as ours when the sides are alike."""
        model = self.model
        if model.opponents == model.players_per_team and model.opponent_goalie_index == model.goalie_index:
            return self.team_radii(extra)
        found = self._their_radii.get(extra)
        if found is None:
            radius, catch = control_radii(model, model.opponent_goalie_index, model.opponents)
            found = self._their_radii[extra] = (radius + extra, catch + extra)
        return found

    def table(self, key: Hashable, make: Callable[[], _T]) -> _T:
        """The table stored under ``key`` this match, made by ``make()`` the first time (a
        skill's tables that depend on its parameters only, e.g. the shot's aim points)."""
        found = self._tables.get(key)
        if found is None:
            found = self._tables[key] = make()
        return found  # type: ignore[return-value]

    # --- the view --------------------------------------------------------------------------
    def arrays(self, view: TeamView) -> ViewArrays:
        """The view's arrays checked (see :class:`ViewArrays`); free while the view holds the
        array objects checked last (a match overwrites them in place)."""
        held = self._held
        if held is not None and (held[0] is view.ball and held[1] is view.ball_vel and held[2] is view.own_pos
                                 and held[3] is view.own_vel and held[4] is view.opp_pos
                                 and held[5] is view.opp_vel and held[6] is getattr(view, "effort", None)
                                 and held[7] is view.stamina):
            return self._arrays  # type: ignore[return-value]
        return self._check(view)

    def _check(self, view: TeamView) -> ViewArrays:
        model = self.model
        effort = getattr(view, "effort", None)
        current = (view.ball, view.ball_vel, view.own_pos, view.own_vel, view.opp_pos, view.opp_vel, effort,
                   view.stamina)
        ball_row, ball_vel_row = float_array("ball", view.ball, (2,)), float_array("ball_vel", view.ball_vel, (2,))
        radius, catch = self.team_radii()
        ours = Players(model, view.own_pos, view.own_vel, view_effort(view, model.players_per_team), radius, catch)
        radius, catch = self.opponent_radii()
        theirs = Players(model, view.opp_pos, view.opp_vel, None, radius, catch)
        stamina = float_array("stamina", view.stamina, (model.players_per_team,))
        arrays = ViewArrays(ball_row.reshape(1, 2), ball_vel_row.reshape(1, 2), ours, theirs, stamina)
        checked = (ball_row, ball_vel_row, ours.pos, ours.vel, theirs.pos, theirs.vel,
                   ours.effort if effort is not None else None, stamina)
        if all(a is b for a, b in zip(checked, current)):  # no copy was needed: keep them
            self._held, self._arrays = current, arrays
        return arrays


def control_radii(model: MotionModel, goalie: int, players: int) -> tuple[np.ndarray, np.ndarray]:
    """(radius, catch radius) per player of a team of ``players``: the kickable distance for
    everyone, and for ``goalie`` (-1: no goalkeeper) the larger of it and the catch length
    (used inside its own penalty area)."""
    radius = np.full(players, model.kickable_distance)
    catch = radius.copy()
    if goalie >= 0:
        catch[goalie] = max(model.kickable_distance, model.catch_length)
    return radius, catch
