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
(:func:`intercept_many`). The compiled search is :mod:`agents.skills.interception_kernels`.

Players enter as :class:`~agents.skills.context.Players` (checked once when made; a view's are
made by :meth:`SkillContext.arrays <agents.skills.context.SkillContext.arrays>`).

When a player cannot get there within the horizon although the ball is still on the field,
its cycle is estimated beyond the horizon (the ball at rest where the horizon leaves it,
the player at its top speed), so the ordering of slow players stays meaningful. When the
ball leaves the field (or passes the cycle limit given to :func:`intercept_many`) before a
player gets there, that player's cycle is :data:`UNREACHABLE` and its point is the ball's
last position on the field.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from agents.skills.context import Players, SkillContext
from agents.skills.interception_kernels import EVERYONE, NO_LIMITS, UNREACHABLE, first_of, intercept_kernel, race_kernel
from agents.skills.model import SkillInputError, float_array
from soccer_sim.team import TeamView

__all__ = ["UNREACHABLE", "BallRace", "Interception", "ball_race", "intercept", "intercept_many"]


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


def intercept(ctx: SkillContext, ball: np.ndarray, ball_vel: np.ndarray, players: Players,
              catch_side: float = -1.0) -> Interception:
    """Earliest interception of the ball (``ball``, ``ball_vel``: (2,), or (1, 2)) by each of
    ``players`` (team frame; e.g. ``ctx.arrays(view).theirs``, or ``Players(model, pos, vel,
    effort, radius, catch_radius)``): the catch radius replaces the control radius when larger
    and the ball is in the penalty area on side ``catch_side`` (-1: ours, at -x; +1: the
    opponents')."""
    cycles, points = intercept_many(ctx, ball, ball_vel, players, catch_side)
    if cycles.shape[0] != 1:
        raise SkillInputError(f"ball_vel must be one velocity (2,), got {cycles.shape[0]} rows")
    first, first_cycle = first_of(cycles[0])
    return Interception(cycles[0], points[0], first, first_cycle)


def intercept_many(ctx: SkillContext, ball: np.ndarray, ball_vel: np.ndarray, players: Players,
                   catch_side: float = -1.0, limit: np.ndarray | None = None, reaction: int = 0,
                   first_only: bool = False, only: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Interception of many ball trajectories at once: ``ball_vel`` (P, 2) one row per
    trajectory (e.g. candidate passes or shots) and ``ball`` (P, 2), or (2,) / (1, 2) for one
    start shared by all; ``players`` and ``catch_side`` as for :func:`intercept`.

    ``limit`` (P,) int: the last cycle searched per trajectory (None: the model's horizon);
    beyond it a player counts as :data:`UNREACHABLE`. ``reaction``: cycles before the players
    start to dash for the ball (opponents see a kick only the cycle after it: 1); they coast
    meanwhile. ``first_only``: stop each trajectory at its first interception (only the
    earliest players' cycles are real, the others are UNREACHABLE), for "does anybody get
    there, and when" questions. ``only`` (P,) int: search just that player on each trajectory
    (-1: everybody). Returns (cycles (P, n) int, points (P, n, 2)).
    """
    if not isinstance(players, Players):
        raise SkillInputError(f"players must be a Players record, got {type(players).__name__}")
    model = ctx.model
    if isinstance(reaction, bool) or not (isinstance(reaction, (int, np.integer)) and 0 <= reaction < model.horizon):
        raise SkillInputError(f"reaction must be an integer in [0, {model.horizon}), got {reaction!r}")
    ball, ball_vel = _trajectories(ball, ball_vel)
    count, n = ball_vel.shape[0], players.pos.shape[0]
    limits = NO_LIMITS if limit is None else _indices("limit", limit, count, None)
    chosen = EVERYONE if only is None else _indices("only", only, count, n)
    return intercept_checked(ctx, ball, ball_vel, players, float(catch_side), limits, int(reaction),
                             bool(first_only), chosen)


def intercept_checked(ctx: SkillContext, ball: np.ndarray, ball_vel: np.ndarray, players: Players,
                      catch_side: float, limits: np.ndarray, reaction: int, first_only: bool,
                      only: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """:func:`intercept_many` for a caller whose inputs are already in the kernel's form (a
    skill's own arrays, checked where they were made): ``ball`` (1, 2) or (P, 2) and
    ``ball_vel`` (P, 2) C-contiguous float64, ``limits`` and ``only`` C-contiguous int64 (P,)
    (or :data:`NO_LIMITS` / :data:`EVERYONE`), players indices below their count. Nothing is
    checked (the compiled search does not check bounds)."""
    model = ctx.model
    count, n = ball_vel.shape[0], players.pos.shape[0]
    cycles = np.empty((count, n), dtype=np.int64)
    points = np.empty((count, n, 2))
    intercept_kernel(ball, ball_vel, players.runners, model.tables, limits, only, cycles, points,
                     ctx.intercept_params, catch_side, reaction, first_only)
    return cycles, points


def ball_race(ctx: SkillContext, view: TeamView, eligible: np.ndarray | None = None,
              their_first_only: bool = False) -> BallRace:
    """Interceptions of the view's ball by our players and by the opponents.

    Our players use the view's effort (ones when absent) and our goalkeeper catches in our
    penalty area; the opponents are taken fresh (effort 1), their goalkeeper
    (``model.opponent_goalie_index``) catching in theirs. ``eligible`` ((n,) bool, None: all)
    leaves out our players who must not play the ball, e.g. those in an offside position when
    a team-mate last kicked (:func:`agents.skills.offside_positions`): their cycle is
    UNREACHABLE and they are never ``first``. ``their_first_only``: the opponents' search
    stops at their first interception (``theirs.first``, ``first_cycle`` and that player's
    point are the same; the other opponents' cycles are UNREACHABLE unless they tie), for a
    caller that needs no more and wants it cheaper.
    """
    ball, ball_vel, ours, theirs, _ = ctx.arrays(view)
    n, m = ours.pos.shape[0], theirs.pos.shape[0]
    if eligible is None:
        mask = _ALL_ELIGIBLE
    else:
        mask = eligible if type(eligible) is np.ndarray else np.asarray(eligible)
        if mask.shape != (n,) or mask.dtype != np.bool_:
            raise SkillInputError(f"eligible must be a ({n},) bool array, got {mask.dtype} {mask.shape}")
    model = ctx.model
    our_cycles, our_points = np.empty((1, n), dtype=np.int64), np.empty((1, n, 2))
    their_cycles, their_points = np.empty((1, m), dtype=np.int64), np.empty((1, m, 2))
    firsts = race_kernel(ball, ball_vel, ours.runners, theirs.runners, model.tables, mask, our_cycles, our_points,
                         their_cycles, their_points, ctx.intercept_params, their_first_only)
    return BallRace(Interception(our_cycles[0], our_points[0], firsts.first, firsts.first_cycle),
                    Interception(their_cycles[0], their_points[0], firsts.their_first, firsts.their_first_cycle))


_ALL_ELIGIBLE = np.zeros(0, dtype=np.bool_)  # empty: every player may play the ball
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


def _trajectories(ball: np.ndarray, ball_vel: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """``ball`` as (1, 2) or (P, 2) and ``ball_vel`` as (P, 2), checked ((2,) counts as one row)."""
    ball_vel = _rows("ball_vel", ball_vel)
    ball = _rows("ball", ball)
    if ball.shape[0] not in (1, ball_vel.shape[0]):
        raise SkillInputError(f"ball {ball.shape} must be (2,), (1, 2) or match ball_vel {ball_vel.shape}")
    return ball, ball_vel


def _rows(name: str, value: object) -> np.ndarray:
    """``value`` as C-contiguous float64 (k, 2) rows, a (2,) point as one row."""
    if not isinstance(value, np.ndarray):
        value = float_array(name, value, (-1,) if np.ndim(value) == 1 else (-1, 2))
    if value.shape == (2,):
        value = value.reshape(1, 2)
    return float_array(name, value, (-1, 2))
