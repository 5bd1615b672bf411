"""Ball lanes: can a kicked ball get along its path before an opponent gets to it?

Our own players are told of the kick by the team in the cycle it is made, so they start at
once; opponents see the kicked ball only in the next cycle's view, so they start one cycle
late (``reaction``).

A lane is a ball trajectory that starts at the ball with the velocity a kick gives it. For
each lane the opponents' earliest interception cycle (:mod:`agents.skills.interception`,
the ball rolled forward with its decay) is compared with the cycle at which the ball
reaches its destination, or with the cycle at which the intended team-mate controls it.
Passing and shooting both build on these two calls; which lanes a kick can use at all, and
when the ball gets to their ends, is :func:`agents.skills.ball_kernels.lane_arrivals`.
"""

from __future__ import annotations

import numpy as np

from agents.skills.context import SkillContext
from agents.skills.interception import UNREACHABLE, intercept_many
from agents.skills.model import check_player
from soccer_sim.team import TeamView


def opponent_cycles(ctx: SkillContext, view: TeamView, ball: np.ndarray, velocities: np.ndarray,
                    limit: np.ndarray | None = None, extra_radius: float = 0.0,
                    reaction: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """Earliest cycle any opponent controls the ball on each lane, and who.

    ``velocities`` (P, 2): the ball's velocity right after the kick, one row per lane;
    ``limit`` (P,) int: last cycle searched per lane (None: the horizon); ``extra_radius``
    (m) widens every opponent's control distance (a safety margin for noise); ``reaction``
    (cycles) is how late the opponents start to chase: they see our kick only in the next
    cycle's view, so 1. Opponents are taken at full effort; their goalkeeper
    (``model.opponent_goalie_index``) catches in its penalty area.
    Returns (cycles (P,) int, :data:`UNREACHABLE` when nobody gets there; opponent (P,) int,
    -1 when nobody).
    """
    velocities = np.ascontiguousarray(velocities, dtype=np.float64).reshape(-1, 2)
    theirs = ctx.arrays(view).theirs.with_radii(*ctx.opponent_radii(extra_radius))
    cycles, _ = intercept_many(ctx, np.asarray(ball, np.float64), velocities, theirs, 1.0, limit, reaction,
                               first_only=True)
    if cycles.shape[1] == 0:
        return np.full(len(velocities), UNREACHABLE, dtype=np.int64), np.full(len(velocities), -1, dtype=np.int64)
    who = np.argmin(cycles, axis=1)
    first = cycles[np.arange(len(velocities)), who]
    who = np.where(first >= UNREACHABLE, -1, who)
    return first, who


def teammate_cycles(ctx: SkillContext, view: TeamView, ball: np.ndarray, velocities: np.ndarray,
                    limit: np.ndarray | None = None,
                    receivers: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Each of our players' interception cycle and point on each lane: ((P, n) int, (P, n, 2)).

    ``receivers`` (P,) int: search only that team-mate on each lane (the others get
    UNREACHABLE), which is much cheaper. The kicker's own column is meaningless (it is at the
    ball at cycle 0).
    """
    velocities = np.ascontiguousarray(velocities, dtype=np.float64).reshape(-1, 2)
    return intercept_many(ctx, np.asarray(ball, np.float64), velocities, ctx.arrays(view).ours, -1.0, limit,
                          only=receivers)


def lane_open(ctx: SkillContext, view: TeamView, ball: np.ndarray, velocity: np.ndarray, receiver: int,
              min_lead: int = 1, extra_radius: float = 0.0) -> bool:
    """True when our ``receiver`` controls the ball kicked to ``velocity`` (2,) at least
    ``min_lead`` cycles before any opponent can (and can control it at all)."""
    receiver = check_player(receiver, ctx.model.players_per_team, "receiver")
    velocity = np.asarray(velocity, np.float64).reshape(1, 2)
    ours, _ = teammate_cycles(ctx, view, ball, velocity, None, np.array([receiver]))
    theirs, _ = opponent_cycles(ctx, view, ball, velocity, None, extra_radius)
    mine = int(ours[0, receiver])
    return mine < UNREACHABLE and int(theirs[0]) - mine >= min_lead
