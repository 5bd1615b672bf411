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
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from agents.skills.interception import checked_own_players
from agents.skills.model import MotionModel, SkillInputError, float_array, view_effort


def dash_to_points(model: MotionModel, pos: np.ndarray, vel: np.ndarray, targets: np.ndarray,
                   effort: np.ndarray | None = None, speed_cap: np.ndarray | float | None = None,
                   tolerance: float = 0.05, out: np.ndarray | None = None) -> np.ndarray:
    """(n, 2) dash accelerations (m/cycle²) that bring each player at ``pos``/``vel`` to its
    ``targets`` row and stop it there (team frame, all (n, 2)).

    ``effort`` (n,) (None: 1) scales the largest acceleration; ``speed_cap`` (scalar or (n,),
    m/cycle; None: the top speed) limits the running speed. A player within ``tolerance`` (m)
    of its target and already at rest gets a zero dash (no stamina spent). ``out`` receives
    the result when given (e.g. ``TeamCommand.dash``).
    """
    pos = float_array("pos", pos, (-1, 2))
    n = pos.shape[0]
    vel = float_array("vel", vel, (n, 2))
    targets = float_array("targets", targets, (n, 2))
    effort = _ones(n) if effort is None else float_array("effort", effort, (n,))
    caps = np.empty(n)
    try:
        caps[:] = model.top_speed if speed_cap is None else speed_cap
    except ValueError as exc:
        raise SkillInputError(f"speed_cap must be a number or ({n},) numbers: {exc}") from exc
    if out is None:
        out = np.empty((n, 2))
    elif not (isinstance(out, np.ndarray) and out.shape == (n, 2) and out.dtype == np.float64):
        raise SkillInputError(f"out must be a float64 ({n}, 2) array")
    _dash_kernel(pos, vel, targets, effort, caps, model.accel_max, model.speed_max, tolerance, out)
    return out


def speed_caps(model: MotionModel, view: object, urgent: np.ndarray | bool = False, near: float | None = None,
               stamina_reserve: float = 0.05) -> np.ndarray:
    """(n,) running-speed caps (m/cycle) for the view's players.

    A player sprints (its top speed, scaled by effort) only when it is urgent (``urgent``,
    bool or (n,) bool; or, when ``near`` is given, within ``near`` metres of the ball: close
    to the action) and its stamina is above ``stamina_low + stamina_reserve * maximum``, the
    level under which recovery and effort begin to fall (StaminaConfig); otherwise it runs at
    its sustainable speed, which its recovery pays for, so stamina never drains.
    """
    hurry = urgent if isinstance(urgent, np.ndarray) and urgent.dtype == np.bool_ else np.asarray(urgent, bool)
    if near is not None:
        gap = view.own_pos - view.ball
        hurry = hurry | (np.einsum("ij,ij->i", gap, gap) <= near * near)
    n = model.players_per_team
    caps = np.empty(n)
    _caps_kernel(np.broadcast_to(hurry, (n,)), float_array("stamina", view.stamina, (n,)), view_effort(view, n),
                 model.top_speed, model.jog_speed, model.stamina_low + stamina_reserve * model.stamina_max, caps)
    return caps


def paced_dashes(model: MotionModel, view: object, targets: np.ndarray, urgent: np.ndarray,
                 out: np.ndarray, stamina_reserve: float = 0.05, tolerance: float = 0.05) -> np.ndarray:
    """:func:`speed_caps` (``urgent`` a (n,) bool array) and :func:`dash_to_points` for the
    view's own players in one compiled pass, with the same result: the per-cycle form for a
    team (the view's arrays are checked once per match, as by the ball race). ``targets``
    and ``out`` are (n, 2) float64 arrays; returns ``out``."""
    pos, vel, effort = checked_own_players(model, view)
    n = pos.shape[0]
    stamina = float_array("stamina", view.stamina, (n,))
    targets = float_array("targets", targets, (n, 2))
    if not (isinstance(urgent, np.ndarray) and urgent.dtype == np.bool_ and urgent.shape == (n,)):
        raise SkillInputError(f"urgent must be a ({n},) bool array")
    if not (isinstance(out, np.ndarray) and out.shape == (n, 2) and out.dtype == np.float64):
        raise SkillInputError(f"out must be a float64 ({n}, 2) array")
    _paced_dash_kernel(pos, vel, targets, effort, stamina, urgent, model.top_speed, model.jog_speed,
                       model.stamina_low + stamina_reserve * model.stamina_max, model.accel_max, model.speed_max,
                       tolerance, out)
    return out


@njit(cache=True, nogil=True)
def _paced_dash_kernel(pos: np.ndarray, vel: np.ndarray, targets: np.ndarray, effort: np.ndarray,
                       stamina: np.ndarray, urgent: np.ndarray, top_speed: float, jog_speed: float, fresh: float,
                       accel_max: float, speed_max: float, tolerance: float,
                       out: np.ndarray) -> None:  # pragma: no cover - compiled
    """:func:`speed_caps`'s caps (top speed for the urgent and fresh, else the jogging speed,
    times effort) fed to :func:`_dash_kernel`, player by player."""
    caps = np.empty(pos.shape[0])
    _caps_kernel(urgent, stamina, effort, top_speed, jog_speed, fresh, caps)
    _dash_kernel(pos, vel, targets, effort, caps, accel_max, speed_max, tolerance, out)


@njit(cache=True, nogil=True)
def _caps_kernel(urgent: np.ndarray, stamina: np.ndarray, effort: np.ndarray, top_speed: float, jog_speed: float,
                 fresh: float, caps: np.ndarray) -> None:  # pragma: no cover - compiled
    """The running-speed rule of :func:`speed_caps`: the top speed for a player who is urgent
    and has stamina above ``fresh``, else the jogging speed; both times its effort (both
    speeds are proportional to it, see MotionModel.sustainable_speed)."""
    for i in range(caps.shape[0]):
        pace = top_speed if urgent[i] and stamina[i] > fresh else jog_speed
        caps[i] = pace * effort[i]


_ONES: dict[int, np.ndarray] = {}


def _ones(n: int) -> np.ndarray:
    ones = _ONES.get(n)
    if ones is None:
        ones = _ONES[n] = np.ones(n)
    return ones


@njit(cache=True, nogil=True)
def _dash_kernel(pos: np.ndarray, vel: np.ndarray, targets: np.ndarray, effort: np.ndarray, caps: np.ndarray,
                 accel_max: float, speed_max: float, tolerance: float, out: np.ndarray) -> None:  # pragma: no cover
    for i in range(pos.shape[0]):
        dx = targets[i, 0] - pos[i, 0]
        dy = targets[i, 1] - pos[i, 1]
        vx, vy = vel[i, 0], vel[i, 1]
        dist = math.sqrt(dx * dx + dy * dy)
        if dist <= tolerance and vx * vx + vy * vy <= 1e-6:
            out[i, 0] = 0.0
            out[i, 1] = 0.0
            continue
        cap = min(caps[i], speed_max)
        if dist > cap:
            dx *= cap / dist
            dy *= cap / dist
        ax, ay = dx - vx, dy - vy
        size = math.sqrt(ax * ax + ay * ay)
        limit = accel_max * effort[i]
        if size > limit:
            ax *= limit / size
            ay *= limit / size
        out[i, 0] = ax
        out[i, 1] = ay
