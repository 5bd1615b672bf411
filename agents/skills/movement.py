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

**Not sprinting when one need not.** :func:`paced_dashes` runs each player under the
stamina policy of :mod:`agents.skills.pacing`: a dash-power budget (full power for urgent
players, a pace that the stamina recovery pays for, by how far the target is, for the
others; never spending below a floor over the recovery threshold), the arrive-and-stop dash
at the speed that budget holds, shortened to the budget with the simulator's side and back
dash costs counted. :func:`speed_caps` gives the speed caps the policy allows on a long run,
for callers that dash with :func:`dash_to_points`.

:func:`dash_to_points` moves any players (a checked :class:`~agents.skills.context.Players`)
at given caps. The kernels are in :mod:`agents.skills.player_kernels`.
"""

from __future__ import annotations

import numpy as np

from agents.skills.context import Players, SkillContext, ViewArrays
from agents.skills.model import MotionModel, SkillInputError, float_array
from agents.skills.pacing import PacingParams, pacing_constants
from agents.skills.player_kernels import Bodies, DashOut, caps_kernel, dash_kernel, paced_dash_kernel
from soccer_sim.team import TeamView

_F64 = np.dtype(np.float64)
_BOOL = np.dtype(np.bool_)
DEFAULT_PACING = PacingParams()
"""The stamina policy's default choices."""
_LAST_PACING = ("pacing", "last")


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
               params: PacingParams = DEFAULT_PACING) -> np.ndarray:
    """(n,) running-speed caps (m/cycle) of the view's players on a long run, under the
    stamina policy of :mod:`agents.skills.pacing`.

    A player sprints (its top speed, scaled by effort) when it is urgent (``urgent``, bool or
    (n,) bool; or, when ``near`` is given, within ``near`` metres of the ball: close to the
    action) and its stamina is above the policy's floor; otherwise it runs at the speed its
    power budget holds (``cruise`` times its income when fresh, less when tired); 0 for a
    player who may not dash at all (at the floor with nothing recovered).
    """
    model = ctx.model
    arrays = ctx.arrays(view)
    caps = np.empty(model.players_per_team)
    caps_kernel(_hurry(model, arrays, view, urgent, near), arrays.stamina, _capacity(view, model),
                arrays.ours.effort, model.goalie_index, view.cycle, view.half,
                _constants(ctx, ctx.table(_LAST_PACING, _no_pacing_yet), params, 0.05), caps)
    return caps


def paced_dashes(ctx: SkillContext, view: TeamView, targets: np.ndarray, urgent: np.ndarray | bool = False,
                 out: np.ndarray | None = None, near: float | None = None, attacking: bool | None = None,
                 params: PacingParams = DEFAULT_PACING, tolerance: float = 0.05,
                 budgets: np.ndarray | None = None) -> np.ndarray:
    """The view's players' dashes to their ``targets`` ((n, 2), team frame) under the stamina
    policy of :mod:`agents.skills.pacing` (what a team calls every cycle).

    ``urgent`` (bool or (n,) bool) and ``near`` (m; players this near the ball) mark those
    who sprint; ``attacking`` (True: we have the ball, False: they have it, None: not in
    play) adds the policy's sprinted runs: into the final third when we attack, back
    goal-side when they attack in our half. Each player gets the arrive-and-stop dash of
    :func:`dash_to_points` at the pace its power budget holds, shortened to the budget
    (counting side and back dashes as the simulator does); players not in a hurry within
    their settling distance of the target do not dash. ``budgets`` ((n,) float64), when
    given, receives each player's power budget (stamina per cycle; 0 for those not dashing).
    """
    model = ctx.model
    arrays = ctx.arrays(view)
    n = model.players_per_team
    targets = float_array("targets", targets, (n, 2))
    out = _out(out, n)
    last = ctx.table(_LAST_PACING, _no_pacing_yet)
    constants = _constants(ctx, last, params, tolerance)
    if budgets is None:
        budgets = last[3]
    elif not (isinstance(budgets, np.ndarray) and budgets.dtype == _F64 and budgets.shape == (n,)):
        raise SkillInputError(f"budgets must be a float64 ({n},) array")
    if attacking is None:
        phase = -1
    elif attacking is True or attacking is False or isinstance(attacking, np.bool_):
        phase = 1 if attacking else 0
    else:
        raise SkillInputError(f"attacking must be True, False or None, got {attacking!r}")
    bodies = Bodies(arrays.ours.pos, arrays.ours.vel, arrays.ours.effort, arrays.stamina, _capacity(view, model))
    paced_dash_kernel(bodies, targets, _hurry(model, arrays, view, urgent, near), arrays.ball[0], model.goalie_index,
                      phase, view.cycle, view.half, constants, DashOut(out, budgets))
    return out


def _no_pacing_yet() -> list:
    """The per-match record of the last pacing constants: [params, tolerance, constants,
    scratch budgets]."""
    return [None, None, None, None]


def _constants(ctx: SkillContext, last: list, params: PacingParams, tolerance: float) -> np.ndarray:
    """The pacing kernel's constants for ``params`` (made once per match and choice; the last
    ones are kept by identity in ``last``, as hashing the parameters every cycle would cost
    more than the kernel)."""
    if last[0] is params and last[1] == tolerance:
        return last[2]
    if not isinstance(params, PacingParams):
        raise SkillInputError(f"params must be a PacingParams, got {type(params).__name__}")
    constants = ctx.table(("pacing", params, float(tolerance)), lambda: pacing_constants(ctx.model, params, tolerance))
    last[:] = params, tolerance, constants, np.empty(ctx.model.players_per_team)
    return constants


def _capacity(view: TeamView, model: MotionModel) -> np.ndarray:
    """The view's (n,) stamina left to recover this half (inf when it has none)."""
    capacity = getattr(view, "capacity", None)
    if type(capacity) is np.ndarray and capacity.dtype is _F64 and capacity.shape == (model.players_per_team,):
        return capacity  # the kernel only reads it
    if capacity is None:
        return np.full(model.players_per_team, np.inf)
    return float_array("capacity", capacity, (model.players_per_team,))


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
