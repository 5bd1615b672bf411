"""Interception: who reaches a rolling ball first, when and where.

The ball is rolled forward with its decay (:class:`~agents.skills.model.MotionModel`) for up
to ``horizon`` cycles, stopping where it leaves the field. A player reaches the ball at cycle
``k`` when the ball's position after ``k`` cycles lies within its control radius (the
kickable distance, or the catch length for a goalkeeper inside its penalty area) of the disc
the player can reach in ``k`` cycles: centred where it would coast to from its current
velocity, of radius ``reach(k) * effort``; and, since the speed limit caps what a player
already running fast can add, no further from where it stands than it can run in ``k``
cycles flat out along its current direction of motion (its speed clipped each cycle). A
ball also stops against a body (rcssserver's contact rule), so a player whose disc comes
within the touch distance (player + ball radius) of the ball's path *during* cycle ``k`` (the
segment between its positions after ``k - 1`` and ``k`` cycles; a fast ball moves up to 3 m
in a cycle) reaches it at cycle ``k`` too, at the nearest point of that segment. Cycle 0
means the ball is under control now.

The search is one compiled loop over trajectories, cycles and players with an early exit
(and, when the search ends at a cycle limit anyway, players who cannot get near the ball's
whole path in time are skipped), so all players of a team against one ball cost a few
microseconds, and the same kernel checks many pass or shot trajectories at once
(:func:`intercept_many`).

When a player cannot get there within the horizon although the ball is still on the field,
its cycle is estimated beyond the horizon (the ball at rest where the horizon leaves it,
the player at its top speed), so the ordering of slow players stays meaningful. When the
ball leaves the field (or passes the cycle limit given to :func:`intercept_many`) before a
player gets there, that player's cycle is :data:`UNREACHABLE` and its point is the ball's
last position on the field.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from agents.skills.model import MotionModel, SkillInputError, float_array, view_effort

UNREACHABLE = 1_000_000
"""Interception cycle of a player who cannot get to the ball before it leaves the field or the
cycle limit (larger than any real cycle, so ``argmin`` over cycles works unchanged)."""


class Interception(NamedTuple):
    """Per player of one team: the earliest cycle it controls the ball and where.

    ``cycles`` (n,) int: cycles from now (0: controllable now; :data:`UNREACHABLE`: never);
    ``points`` (n, 2) the ball's predicted position at that cycle; ``first`` the player who
    gets there first (-1 if nobody can) and ``first_cycle`` its cycle (UNREACHABLE if none).
    """

    cycles: np.ndarray
    points: np.ndarray
    first: int
    first_cycle: int


class BallRace(NamedTuple):
    """Both teams' interceptions of the same ball (see :func:`ball_race`)."""

    ours: Interception
    theirs: Interception

    @property
    def we_win(self) -> bool:
        """True when one of our players gets there strictly first (ties go to the opponents)."""
        return self.ours.first_cycle < self.theirs.first_cycle

    @property
    def lead(self) -> int:
        """Their first cycle minus ours: positive when we are ahead, in cycles."""
        return int(self.theirs.first_cycle) - int(self.ours.first_cycle)


def control_radii(model: MotionModel, goalie: int | None = None, players: int | None = None
                  ) -> tuple[np.ndarray, np.ndarray]:
    """(radius, catch radius) per player of a team of ``players`` (None: ours): the kickable
    distance for everyone, and for ``goalie`` (None or -1: no goalkeeper) the larger of it and
    the catch length (used inside its own penalty area)."""
    n = model.players_per_team if players is None else players
    radius = np.full(n, model.kickable_distance)
    catch = radius.copy()
    if goalie is not None and goalie >= 0:
        catch[goalie] = max(model.kickable_distance, model.catch_length)
    return radius, catch


def team_radii(model: MotionModel, extra: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """:func:`control_radii` (goalkeeper at the model's index) widened by ``extra``, made once
    per model and margin (never written)."""
    cache = model.__dict__.setdefault("_team_radii", {})
    found = cache.get(extra)
    if found is None:
        radius, catch = control_radii(model, model.goalie_index)
        found = cache[extra] = (radius + extra, catch + extra)
    return found


def opponent_radii(model: MotionModel, extra: float = 0.0) -> tuple[np.ndarray, np.ndarray]:
    """:func:`team_radii` for the opponents (their size and goalkeeper, ``model.opponents`` and
    ``model.opponent_goalie_index``); the same arrays as ours when the sides are alike."""
    if model.opponents == model.players_per_team and model.opponent_goalie_index == model.goalie_index:
        return team_radii(model, extra)
    cache = model.__dict__.setdefault("_opponent_radii", {})
    found = cache.get(extra)
    if found is None:
        radius, catch = control_radii(model, model.opponent_goalie_index, model.opponents)
        found = cache[extra] = (radius + extra, catch + extra)
    return found


def intercept(model: MotionModel, ball: np.ndarray, ball_vel: np.ndarray, pos: np.ndarray, vel: np.ndarray,
              effort: np.ndarray | None = None, radius: np.ndarray | None = None,
              catch_radius: np.ndarray | None = None, catch_side: float = -1.0) -> Interception:
    """Earliest interception of the ball (``ball``, ``ball_vel``: (2,)) by each of the players
    at ``pos``/``vel`` ((n, 2), team frame).

    ``effort`` (n,) scales each player's acceleration (None: 1). ``radius`` (n,) is each
    player's control distance (None: the kickable distance); ``catch_radius`` (n,) replaces it
    when larger and the ball is in the penalty area on side ``catch_side`` (-1: ours, at -x;
    +1: the opponents').
    """
    ball, ball_vel = _trajectories(ball, ball_vel, single=True)
    pos, vel, effort, radius, catch_radius = _players(model, pos, vel, effort, radius, catch_radius)
    return _intercept_checked(model, ball, ball_vel, pos, vel, effort, radius, catch_radius,
                              _kernel_params(model, catch_side))


def _intercept_checked(model: MotionModel, ball: np.ndarray, ball_vel: np.ndarray, pos: np.ndarray, vel: np.ndarray,
                       effort: np.ndarray, radius: np.ndarray, catch_radius: np.ndarray,
                       params: np.ndarray) -> Interception:
    """:func:`intercept` on arrays already checked (ball and ball_vel as (1, 2) rows)."""
    n = pos.shape[0]
    cycles = np.empty((1, n), dtype=np.int64)
    points = np.empty((1, n, 2))
    _intercept_kernel(ball, ball_vel, pos, vel, effort, radius, catch_radius, model.reach, model.ball_travel,
                      model.player_coast, params, _NO_LIMITS, cycles, points, _ALL)
    first, first_cycle = _first_of(cycles[0])
    return Interception(cycles[0], points[0], first, first_cycle)


def intercept_many(model: MotionModel, ball: np.ndarray, ball_vel: np.ndarray, pos: np.ndarray, vel: np.ndarray,
                   effort: np.ndarray | None = None, radius: np.ndarray | None = None,
                   catch_radius: np.ndarray | None = None, catch_side: float = -1.0,
                   limit: np.ndarray | None = None, reaction: int = 0, first_only: bool = False,
                   only: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Interception of many ball trajectories at once: ``ball_vel`` (P, 2) one row per
    trajectory (e.g. candidate passes or shots) and ``ball`` (P, 2), or (2,) for one start
    shared by all; players as for :func:`intercept`.

    ``limit`` (P,) int: the last cycle searched per trajectory (None: the model's horizon);
    beyond it a player counts as :data:`UNREACHABLE`. ``reaction``: cycles before the players
    start to dash for the ball (opponents see a kick only the cycle after it: 1); they coast
    meanwhile. ``first_only``: stop each trajectory at its first interception (only the
    earliest players' cycles are real, the others are UNREACHABLE), for "does anybody get
    there, and when" questions. ``only`` (P,) int: search just that player on each trajectory
    (-1: everybody). Returns (cycles (P, n) int, points (P, n, 2)).
    """
    ball, ball_vel = _trajectories(ball, ball_vel, single=False)
    players = _players(model, pos, vel, effort, radius, catch_radius)
    count, n = ball_vel.shape[0], players[0].shape[0]
    limits = _NO_LIMITS if limit is None else _indices("limit", limit, count, None)
    chosen = _ALL if only is None else _indices("only", only, count, n)
    return intercept_many_checked(model, ball, ball_vel, players, catch_side, limits, reaction, first_only, chosen)


def intercept_many_checked(model: MotionModel, ball: np.ndarray, ball_vel: np.ndarray, players: tuple,
                           catch_side: float, limits: np.ndarray, reaction: int, first_only: bool,
                           chosen: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """:func:`intercept_many` on arrays already checked: ``ball`` (1 or P, 2), ``ball_vel``
    (P, 2), ``players`` = (pos, vel, effort, radius, catch radius) as C-contiguous float64
    arrays (e.g. :func:`race_players`), ``limits`` and ``chosen`` (P,) int64 or empty."""
    pos, vel, effort, radius, catch_radius = players
    count, n = ball_vel.shape[0], pos.shape[0]
    cycles = np.empty((count, n), dtype=np.int64)
    points = np.empty((count, n, 2))
    _intercept_kernel(ball, ball_vel, pos, vel, effort, radius, catch_radius, model.reach, model.ball_travel,
                      model.player_coast, _kernel_params(model, catch_side, reaction, first_only), limits, cycles,
                      points, chosen)
    return cycles, points


def ball_race(model: MotionModel, view: object, eligible: np.ndarray | None = None,
              their_first_only: bool = False) -> BallRace:
    """Interceptions of the view's ball by our players and by the opponents.

    Our players use the view's effort (ones when absent) and our goalkeeper catches in our
    penalty area; the opponents are taken fresh (effort 1), their goalkeeper
    (``model.opponent_goalie_index``, by default the same index as ours) catching in theirs.
    ``eligible`` ((n,) bool, None: all) leaves out our players who must not play the ball,
    e.g. those in an offside position when a team-mate last kicked
    (:func:`agents.skills.offside_positions`): their cycle is UNREACHABLE and they are never
    ``first``. ``their_first_only``: the opponents' search stops at their first interception
    (``theirs.first``, ``first_cycle`` and that player's point are the same; the other
    opponents' cycles are UNREACHABLE unless they tie), for a caller that needs no more and
    wants it cheaper.
    """
    ball, ball_vel, own, opp = _race_inputs(model, view)
    n, m = own[0].shape[0], opp[0].shape[0]
    if eligible is None:
        mask = _ALL_ELIGIBLE
    else:
        mask = eligible if type(eligible) is np.ndarray else np.asarray(eligible)
        if mask.shape != (n,) or mask.dtype != np.bool_:
            raise SkillInputError(f"eligible must be a ({n},) bool array, got {mask.dtype} {mask.shape}")
    tables = model.__dict__.get("_race_tables")
    if tables is None:  # the model's tables and both sides' kernel parameters, gathered once
        tables = model.__dict__["_race_tables"] = (
            model.reach, model.ball_travel, model.player_coast, _kernel_params(model, -1.0),
            (_kernel_params(model, 1.0), _kernel_params(model, 1.0, 0, True)))
    reach, travel, coast, our_params, their_params = tables
    our_cycles, our_points = np.empty((1, n), dtype=np.int64), np.empty((1, n, 2))
    their_cycles, their_points = np.empty((1, m), dtype=np.int64), np.empty((1, m, 2))
    first, first_cycle, their_first, their_first_cycle = _race_kernel(
        ball, ball_vel, *own, *opp, reach, travel, coast, our_params, their_params[1 if their_first_only else 0],
        mask, our_cycles, our_points, their_cycles, their_points)
    return BallRace(Interception(our_cycles[0], our_points[0], first, first_cycle),
                    Interception(their_cycles[0], their_points[0], their_first, their_first_cycle))


_ALL_ELIGIBLE = np.zeros(0, dtype=np.bool_)  # empty: every player may play the ball


@njit(cache=True, nogil=True)
def _race_kernel(ball: np.ndarray, ball_vel: np.ndarray, pos: np.ndarray, vel: np.ndarray, effort: np.ndarray,
                 radius: np.ndarray, catch_radius: np.ndarray, opp_pos: np.ndarray, opp_vel: np.ndarray,
                 opp_effort: np.ndarray, opp_radius: np.ndarray, opp_catch_radius: np.ndarray, reach: np.ndarray,
                 ball_travel: np.ndarray, coast: np.ndarray, our_params: np.ndarray, their_params: np.ndarray,
                 eligible: np.ndarray, our_cycles: np.ndarray, our_points: np.ndarray, their_cycles: np.ndarray,
                 their_points: np.ndarray) -> tuple[int, int, int, int]:  # pragma: no cover - compiled
    """Both teams' :func:`_intercept_kernel` of one ball in one call; our players not
    ``eligible`` (when it is not empty) made UNREACHABLE. Returns (our first player, its
    cycle, their first player, its cycle), -1 and UNREACHABLE when nobody gets there."""
    _intercept_kernel(ball, ball_vel, pos, vel, effort, radius, catch_radius, reach, ball_travel, coast, our_params,
                      _NO_LIMITS, our_cycles, our_points, _ALL)
    if eligible.shape[0] > 0:
        for i in range(our_cycles.shape[1]):
            if not eligible[i]:
                our_cycles[0, i] = UNREACHABLE
    _intercept_kernel(ball, ball_vel, opp_pos, opp_vel, opp_effort, opp_radius, opp_catch_radius, reach, ball_travel,
                      coast, their_params, _NO_LIMITS, their_cycles, their_points, _ALL)
    first, first_cycle = _first_of(our_cycles[0])
    their_first, their_first_cycle = _first_of(their_cycles[0])
    return first, first_cycle, their_first, their_first_cycle


@njit(cache=True, nogil=True)
def _first_of(cycles: np.ndarray) -> tuple[int, int]:  # pragma: no cover - compiled
    """The player with the smallest cycle (the lowest index among equals) and that cycle;
    (-1, its cycle or UNREACHABLE) when nobody gets there."""
    first, first_cycle = -1, UNREACHABLE
    for i in range(cycles.shape[0]):
        if first < 0 or cycles[i] < first_cycle:
            first, first_cycle = i, cycles[i]
    if first_cycle >= UNREACHABLE:
        first = -1
    return first, first_cycle


def _race_inputs(model: MotionModel, view: object) -> tuple[np.ndarray, np.ndarray, tuple, tuple]:
    """:func:`ball_race`'s checked arrays: (ball (1, 2), ball_vel (1, 2), our players, theirs).

    A match hands a team the same view arrays every cycle, overwritten in place, so when the
    checked arrays are those very arrays (or views of them) they are kept on the model and
    reused while the view holds the same array objects: checking them costs more than the
    race itself.
    """
    effort = getattr(view, "effort", None)
    current = (view.ball, view.ball_vel, view.own_pos, view.own_vel, view.opp_pos, view.opp_vel, effort)
    cached = model.__dict__.get("_race_inputs")
    if cached is not None:
        held, inputs = cached
        if (held[0] is current[0] and held[1] is current[1] and held[2] is current[2] and held[3] is current[3]
                and held[4] is current[4] and held[5] is current[5] and held[6] is current[6]):
            return inputs
    ball_row, ball_vel_row = float_array("ball", view.ball, (2,)), float_array("ball_vel", view.ball_vel, (2,))
    ball, ball_vel = ball_row.reshape(1, 2), ball_vel_row.reshape(1, 2)
    radius, catch = team_radii(model)
    own = _players(model, view.own_pos, view.own_vel, view_effort(view, model.players_per_team), radius, catch,
                   radii_checked=True)
    radius, catch = opponent_radii(model)
    opp = _players(model, view.opp_pos, view.opp_vel, None, radius, catch, radii_checked=True)
    inputs = (ball, ball_vel, own, opp)
    checked = (ball_row, ball_vel_row, own[0], own[1], opp[0], opp[1], own[2] if effort is not None else None)
    if all(a is b for a, b in zip(checked, current)):
        model.__dict__["_race_inputs"] = (current, inputs)
    return inputs


def race_players(model: MotionModel, view: object) -> tuple[np.ndarray, np.ndarray, tuple, tuple]:
    """The view's ball (1, 2), ball velocity (1, 2), our players and the opponents, each as
    (pos, vel, effort, radius, catch radius) in the form :func:`ball_race` uses (our effort
    from the view, theirs 1; the model's control radii), checked as C-contiguous float64
    arrays: free after the first call of a match (the checked arrays are kept while the view
    holds the same array objects)."""
    return _race_inputs(model, view)


def checked_own_players(model: MotionModel, view: object) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """The view's own positions (n, 2), velocities (n, 2) and effort (n,) (ones when the view
    has none), checked as C-contiguous float64 arrays (see :func:`race_players`)."""
    own = _race_inputs(model, view)[2]
    return own[0], own[1], own[2]


_NO_LIMITS = np.full(0, -1, dtype=np.int64)  # empty: the kernel searches to the horizon
_ALL = np.zeros(0, dtype=np.int64)
_I64 = np.dtype(np.int64)


def _indices(name: str, value: object, count: int, below: int | None) -> np.ndarray:
    """``value`` as a C-contiguous int64 (count,) array (a scalar is repeated), each below
    ``below`` when given, else a SkillInputError naming it."""
    array = value if type(value) is np.ndarray else np.asarray(value)
    if array.shape == ():
        array = np.full(count, array)
    if array.shape != (count,) or array.dtype.kind not in "iu":
        raise SkillInputError(f"{name} must be an integer or ({count},) integers, got {array.dtype} {array.shape}")
    if array.dtype != _I64 or not array.flags.c_contiguous:
        array = np.ascontiguousarray(array, dtype=np.int64)
    if below is not None and count and array.max() >= below:
        raise SkillInputError(f"{name} holds player index {int(array.max())}, not below {below}")
    return array


def _trajectories(ball: object, ball_vel: object, single: bool) -> tuple[np.ndarray, np.ndarray]:
    if single:
        return (float_array("ball", ball, (2,)).reshape(1, 2), float_array("ball_vel", ball_vel, (2,)).reshape(1, 2))
    ball_vel = float_array("ball_vel", ball_vel, (-1, 2))
    if isinstance(ball, np.ndarray) and ball.shape == (2,):
        ball = float_array("ball", ball, (2,)).reshape(1, 2)
    ball = float_array("ball", ball, (-1, 2))
    if ball.shape[0] not in (1, ball_vel.shape[0]):
        raise SkillInputError(f"ball {ball.shape} must be (2,), (1, 2) or match ball_vel {ball_vel.shape}")
    return ball, ball_vel


def _players(model: MotionModel, pos: object, vel: object, effort: object, radius: object,
             catch_radius: object, radii_checked: bool = False) -> tuple[np.ndarray, ...]:
    """The players' arrays, checked; ``radii_checked``: the radii are the model's own
    (:func:`team_radii`), already right, and are passed through as they are."""
    pos = float_array("pos", pos, (-1, 2))
    n = pos.shape[0]
    vel = float_array("vel", vel, (n, 2))
    defaults = _defaults(model, n)
    effort = defaults[0] if effort is None else float_array("effort", effort, (n,))
    if radii_checked and n == radius.shape[0]:
        return pos, vel, effort, radius, catch_radius
    radius = defaults[1] if radius is None else float_array("radius", radius, (n,))
    catch_radius = radius if catch_radius is None else float_array("catch_radius", catch_radius, (n,))
    return pos, vel, effort, radius, catch_radius


def _defaults(model: MotionModel, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(ones, kickable distances) of length n, made once per model (never written)."""
    cache = model.__dict__.setdefault("_intercept_defaults", {})
    found = cache.get(n)
    if found is None:
        ones, kick = np.ones(n), np.full(n, model.kickable_distance)
        found = cache[n] = (ones, kick)
    return found


def _kernel_params(model: MotionModel, catch_side: float, reaction: int = 0, first_only: bool = False) -> np.ndarray:
    cached = model.__dict__.get("_intercept_params")
    if cached is None:
        cached = {}
        model.__dict__["_intercept_params"] = cached
    key = (catch_side, reaction, bool(first_only))
    params = cached.get(key)
    if params is None:
        if not (isinstance(reaction, (int, np.integer)) and 0 <= reaction < model.horizon):
            raise SkillInputError(f"reaction must be an integer in [0, {model.horizon}), got {reaction!r}")
        # The ball is in play until it is wholly over a line (the referee's rule), so a ball
        # lying on a line can still be reached.
        params = np.array([model.half_length + model.ball_radius, model.half_width + model.ball_radius,
                           model.top_speed, catch_side,
                           model.half_length - model.penalty_area_length, model.penalty_area_half_width,
                           model.accel_max, model.speed_max, model.player_decay, float(reaction),
                           1.0 if first_only else 0.0, model.touch_distance])
        cached[key] = params
    return params


@njit(cache=True, nogil=True)
def _intercept_kernel(ball: np.ndarray, ball_vel: np.ndarray, pos: np.ndarray, vel: np.ndarray, effort: np.ndarray,
                      radius: np.ndarray, catch_radius: np.ndarray, reach: np.ndarray, ball_travel: np.ndarray,
                      coast: np.ndarray, params: np.ndarray, limits: np.ndarray, cycles_out: np.ndarray,
                      points_out: np.ndarray, only: np.ndarray) -> None:  # pragma: no cover - compiled
    """See the module docstring. ``params``: half length, half width, top speed, catch side,
    |x| of the penalty area's front line, its half width, largest acceleration, speed limit,
    player decay, reaction delay (cycles), first-only flag (stop a trajectory at its first
    interception; the later players get UNREACHABLE), body contact distance. ``limits[p] < 0`` (or ``limits``
    empty): the horizon.
    ``only[p] >= 0``: search that player alone on trajectory p (the others get UNREACHABLE)."""
    half_length, half_width, top_speed, side = params[0], params[1], params[2], params[3]
    area_x, area_y, accel_max, speed_max, decay = params[4], params[5], params[6], params[7], params[8]
    delay = int(params[9])
    first_only = params[10] > 0.5
    body = params[11]
    horizon = reach.shape[0] - 1
    n = pos.shape[0]
    run = np.empty(n)  # furthest straight-line run so far, per player
    speed = np.empty(n)
    for p in range(ball_vel.shape[0]):
        b = 0 if ball.shape[0] == 1 else p
        bx0, by0, vx, vy = ball[b, 0], ball[b, 1], ball_vel[p, 0], ball_vel[p, 1]
        bound = limits[p] if limits.shape[0] > 0 else -1
        last = horizon if bound < 0 else min(bound, horizon)
        alone = only[p] if only.shape[0] > 0 else -1
        # Players who cannot get near the ball's whole path within `last` cycles are skipped
        # (-2) when the search ends at `last` anyway (first-only, or a limit within the horizon).
        prune = first_only or (0 <= bound <= horizon)
        wx, wy = ball_travel[last] * vx, ball_travel[last] * vy
        whole = wx * wx + wy * wy
        remaining = 0
        for i in range(n):
            run[i] = 0.0
            speed[i] = math.sqrt(vel[i, 0] ** 2 + vel[i, 1] ** 2)
            if alone < 0 or i == alone:
                cycles_out[p, i] = -1
                remaining += 1
                if prune:
                    qx, qy = pos[i, 0] - bx0, pos[i, 1] - by0
                    t = min(max((qx * wx + qy * wy) / whole, 0.0), 1.0) if whole > 0.0 else 0.0
                    gap = math.sqrt((qx - t * wx) ** 2 + (qy - t * wy) ** 2)
                    grow = reach[last - delay] * effort[i] if last > delay else 0.0
                    if gap > coast[last] * speed[i] + grow + max(radius[i], catch_radius[i]):
                        cycles_out[p, i] = -2
                        remaining -= 1
            else:
                cycles_out[p, i] = UNREACHABLE
                points_out[p, i, 0] = bx0
                points_out[p, i, 1] = by0
        lo, hi = (0, n) if alone < 0 else (alone, alone + 1)
        found = False
        left_field = False
        bx, by = bx0, by0
        k_end = 0
        for k in range(last + 1):
            tx = bx0 + ball_travel[k] * vx
            ty = by0 + ball_travel[k] * vy
            if abs(tx) > half_length or abs(ty) > half_width:
                left_field = True
                break
            px, py = bx, by  # where the ball was a cycle ago
            bx, by = tx, ty
            k_end = k
            in_area = side * tx >= area_x and abs(ty) <= area_y
            sx, sy = tx - px, ty - py
            seg = sx * sx + sy * sy
            seg_len = math.sqrt(seg)
            for i in range(lo, hi):
                if cycles_out[p, i] != -1:
                    continue
                if k > 0:
                    boost = accel_max * effort[i] if k > delay else 0.0
                    speed[i] = min(speed[i] + boost, speed_max)
                    run[i] += speed[i]
                    speed[i] *= decay
                cx = pos[i, 0] + coast[k] * vel[i, 0]
                cy = pos[i, 1] + coast[k] * vel[i, 1]
                r = radius[i]
                if in_area and catch_radius[i] > r:
                    r = catch_radius[i]
                dx, dy = tx - cx, ty - cy
                ex, ey = tx - pos[i, 0], ty - pos[i, 1]
                grow = reach[k - delay] * effort[i] if k > delay else 0.0
                hit = dx * dx + dy * dy <= (grow + r) ** 2 and ex * ex + ey * ey <= (run[i] + r) ** 2
                qx, qy = tx, ty
                if not hit and seg > 0.0 and dx * dx + dy * dy <= (grow + body + seg_len) ** 2:
                    # The ball may run into the body somewhere along this cycle's path.
                    t = min(max(((cx - px) * sx + (cy - py) * sy) / seg, 0.0), 1.0)
                    qx, qy = px + t * sx, py + t * sy
                    hit = (qx - cx) ** 2 + (qy - cy) ** 2 <= (grow + body) ** 2 and \
                        (qx - pos[i, 0]) ** 2 + (qy - pos[i, 1]) ** 2 <= (run[i] + body) ** 2
                if hit:
                    cycles_out[p, i] = k
                    points_out[p, i, 0] = qx
                    points_out[p, i, 1] = qy
                    remaining -= 1
                    found = True
            if remaining == 0 or (found and first_only):
                break
        if found and first_only:
            for i in range(n):
                if cycles_out[p, i] < 0:
                    cycles_out[p, i] = UNREACHABLE
                    points_out[p, i, 0] = bx
                    points_out[p, i, 1] = by
            continue
        beyond = not left_field and k_end == horizon and (bound < 0 or bound > horizon)
        for i in range(n):
            if cycles_out[p, i] >= 0:
                continue
            points_out[p, i, 0] = bx
            points_out[p, i, 1] = by
            if beyond:
                cx = pos[i, 0] + coast[horizon] * vel[i, 0]
                cy = pos[i, 1] + coast[horizon] * vel[i, 1]
                gap = math.sqrt((bx - cx) ** 2 + (by - cy) ** 2) - radius[i] - reach[horizon - delay] * effort[i]
                pace = max(top_speed * effort[i], 1e-9)
                cycles_out[p, i] = horizon + max(1, int(math.ceil(gap / pace)))
            else:
                cycles_out[p, i] = UNREACHABLE
