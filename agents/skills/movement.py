"""Dashing to a point and stopping there, and how fast players should run.

**Arrive without overshoot.** With the player model ``vel += a; pos += vel; vel *= decay``
the displacement of this cycle is ``w = vel + a``. The controller asks for the displacement
``w* = d`` (the whole remaining distance ``d`` when it is within the speed cap) or
``d / |d| * cap``; the acceleration is ``a = w* - vel``. When that exceeds the player's
largest acceleration (``accel_max * effort``) it is shortened along its own direction, which
is also how the match clips it and gives the displacement closest to ``w*``. Once on the
target the next command is ``-vel``, which cancels the coasting velocity (``decay * w*``,
within reach of one dash whenever the cap is at most the top speed), so the player stops on
the point. Side and back dash rates (weaker dashes against the direction of motion) are not
modelled: they only slow the braking a little.

**Not sprinting when one need not.** :func:`speed_caps` gives each player either its top
speed or the speed its stamina recovery sustains for ever (:meth:`MotionModel.
sustainable_speed`): top speed only for players marked urgent (near the action, chasing the
ball) whose stamina is above the level where recovery and effort start to fall for good.

:func:`dash_to_points` moves any players (a checked :class:`~agents.skills.context.Players`)
at given caps; :func:`speed_caps` gives the view's players their caps; :func:`paced_dashes`
does both for the view's players in one compiled pass, as a team does every cycle. The
kernels are in :mod:`agents.skills.player_kernels`.
"""

from __future__ import annotations

import numpy as np

from agents.skills.context import Players, SkillContext, ViewArrays
from agents.skills.model import MotionModel, SkillInputError, float_array
from agents.skills.player_kernels import caps_kernel, dash_kernel, paced_dash_kernel
from soccer_sim.team import TeamView

_F64 = np.dtype(np.float64)
_BOOL = np.dtype(np.bool_)


def dash_to_points(model: MotionModel, players: Players, targets: np.ndarray,
                   speed_cap: np.ndarray | float | None = None, tolerance: float = 0.05,
                   out: np.ndarray | None = None) -> np.ndarray:
    """(n, 2) dash accelerations (m/cycle²) that bring each of the ``players`` (their
    positions, velocities and effort, e.g. ``ctx.arrays(view).ours``) to its ``targets`` row
    ((n, 2), team frame) and stop it there.

    Each player's effort scales its largest acceleration; ``speed_cap`` (scalar or (n,),
    m/cycle, e.g. :func:`speed_caps`; None: the top speed) limits the running speed. A player
    within ``tolerance`` (m) of its target and already at rest gets a zero dash (no stamina
    spent). ``out`` receives the result when given (e.g. ``TeamCommand.dash``).
    """
    if not isinstance(players, Players):
        raise SkillInputError(f"players must be a Players record, got {type(players).__name__}")
    pos, vel, effort = players.pos, players.vel, players.effort
    n = pos.shape[0]
    targets = float_array("targets", targets, (n, 2))
    if type(speed_cap) is np.ndarray and speed_cap.dtype is _F64 and speed_cap.shape == (n,):
        caps = speed_cap  # the kernel only reads it
    else:
        caps = np.empty(n)
        try:
            caps[:] = model.top_speed if speed_cap is None else speed_cap
        except ValueError as exc:
            raise SkillInputError(f"speed_cap must be a number or ({n},) numbers: {exc}") from exc
    out = _out(out, n)
    dash_kernel(pos, vel, targets, effort, caps, model.accel_max, model.speed_max, tolerance, out)
    return out


def speed_caps(ctx: SkillContext, view: TeamView, urgent: np.ndarray | bool = False, near: float | None = None,
               stamina_reserve: float = 0.05) -> np.ndarray:
    """(n,) running-speed caps (m/cycle) for the view's players.

    A player sprints (its top speed, scaled by effort) only when it is urgent (``urgent``,
    bool or (n,) bool; or, when ``near`` is given, within ``near`` metres of the ball: close
    to the action) and its stamina is above ``stamina_low + stamina_reserve * maximum``, the
    level under which recovery and effort begin to fall (StaminaConfig); otherwise it runs at
    its sustainable speed, which its recovery pays for, so stamina never drains.
    """
    model = ctx.model
    arrays = ctx.arrays(view)
    caps = np.empty(model.players_per_team)
    caps_kernel(_hurry(model, arrays, view, urgent, near), arrays.stamina, arrays.ours.effort, model.top_speed,
                model.jog_speed, model.stamina_low + stamina_reserve * model.stamina_max, caps)
    return caps


def paced_dashes(ctx: SkillContext, view: TeamView, targets: np.ndarray, urgent: np.ndarray | bool = False,
                 out: np.ndarray | None = None, near: float | None = None, stamina_reserve: float = 0.05,
                 tolerance: float = 0.05) -> np.ndarray:
    """The view's players' dashes to their ``targets`` ((n, 2)) at the pace :func:`speed_caps`
    gives them: ``dash_to_points(model, ctx.arrays(view).ours, targets, speed_caps(ctx, view,
    urgent, near, stamina_reserve), tolerance, out)``, the same numbers in one compiled pass
    (what a team calls every cycle)."""
    model = ctx.model
    arrays = ctx.arrays(view)
    n = model.players_per_team
    targets = float_array("targets", targets, (n, 2))
    out = _out(out, n)
    paced_dash_kernel(arrays.ours.pos, arrays.ours.vel, targets, arrays.ours.effort, arrays.stamina,
                      _hurry(model, arrays, view, urgent, near), model.top_speed, model.jog_speed,
                      model.stamina_low + stamina_reserve * model.stamina_max, model.accel_max, model.speed_max,
                      tolerance, out)
    return out


def _hurry(model: MotionModel, arrays: ViewArrays, view: TeamView, urgent: np.ndarray | bool,
           near: float | None) -> np.ndarray:
    """(n,) bool: the players who may sprint if their stamina allows (``urgent``, and with
    ``near`` those within ``near`` metres of the ball)."""
    n = model.players_per_team
    hurry = urgent if type(urgent) is np.ndarray and urgent.dtype is _BOOL else np.asarray(urgent, bool)
    if hurry.shape != (n,):
        try:
            hurry = np.broadcast_to(hurry, (n,))
        except ValueError as exc:
            raise SkillInputError(f"urgent must be a bool or ({n},) bools, got shape {hurry.shape}") from exc
    if near is not None:
        gap = arrays.ours.pos - view.ball
        hurry = hurry | (np.einsum("ij,ij->i", gap, gap) <= near * near)
    return hurry


def _out(out: np.ndarray | None, n: int) -> np.ndarray:
    """``out`` checked as a float64 (n, 2) array, or a new one."""
    if out is None:
        return np.empty((n, 2))
    if not (isinstance(out, np.ndarray) and out.dtype == _F64 and out.shape == (n, 2)):
        raise SkillInputError(f"out must be a float64 ({n}, 2) array")
    return out
