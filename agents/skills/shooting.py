"""Shooting: whether to shoot, and where across the goal mouth to aim.

Aim points are sampled along the opponents' goal line between the posts (kept
``post_margin`` inside them). For each, the shooter's kick is the fastest one can give
towards it (:func:`kick_for_velocity`, ball speed up to ``ball_speed_max``). The ball is
rolled to the goal line (:class:`MotionModel` decay) and the opponents' earliest
interception on that path is found (:mod:`agents.skills.lanes`; the goalkeeper catches
within the catch length inside its penalty area); the ball path stops at the goal line, so
an opponent who cannot get there before the ball crosses it cannot stop the shot.

Each aim gets a probability-like score, the product of

* **unblocked**: a logistic function of the lead (cycles by which the ball beats the
  fastest opponent to the line), 0.5 at a lead of ``lead_half`` cycles, averaged over the
  aim's error window (below; the factor is interpolated between neighbouring aims), so an
  aim next to one the goalkeeper reaches counts as riskier than one further from it;
* **on target**: the share of the aim's error window that lies between the posts. The kick
  noise and the ball noise of the flight (:meth:`MotionModel.kick_spread`, rcssserver's
  formulas: they grow with the ball's distance from the kicker, its speed and the length of
  the flight) spread the ball across the goal line; the window is the uniform spread with
  the same standard deviation, ``± sqrt(3)`` of it.

The best aim is the one with the highest score; :func:`best_shot` returns None when the ball
is beyond ``max_range`` of the goal centre or cannot reach the goal line, and
:attr:`ShotPlan.take` says whether its score clears ``threshold``.

**Shots with an open lane.** A goalkeeper without a body orientation covers its goal from
beyond 15 m, so a score against it rarely clears the threshold from the edge of the box; real
players shoot there anyway when no defender stands in the way, and the goalkeeper must then
save. Within ``lane_range`` of the goal centre the shot is also taken when the best aim among
those the outfield opponents (all but their goalkeeper) cannot reach before the ball crosses
the line, with a lead of at least ``lane_lead`` cycles, has a score of at least
``lane_score``, and an opponent can close the shooter down within ``lane_pressure`` cycles
(a shooter left alone carries the ball closer, where the goalkeeper cannot cover the goal);
that aim is then the one shot at. ``lane_range = 0`` turns this off.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from agents.skills.ball_kernels import SHOT_PARAMS, ShotAims, lane_arrivals, shot_scores
from agents.skills.context import Players, SkillContext
from agents.skills.interception import UNREACHABLE, intercept_many
from agents.skills.kicking import kick_for_velocity
from agents.skills.lanes import opponent_cycles
from agents.skills.model import MotionModel, check_params, check_player
from soccer_sim.body import ball_angle_to_body
from soccer_sim.kernels import make_record
from soccer_sim.team import TeamView


_WINDOW = np.linspace(-1.0, 1.0, 9)
"""Where across an aim's error window (in units of its half-width) the unblocked factor is sampled."""


@dataclass(frozen=True)
class ShotParams:
    """Tunable choices of the shooting skill (metres, cycles)."""

    max_range: float = 30.0
    """No shot from further than this from the goal centre (m)."""
    aims: int = 13
    """Number of aim points sampled across the goal mouth."""
    post_margin: float = 0.4
    """Aim points stay this far inside the posts (m, beyond the ball's and post's radii)."""
    lead_half: float = 1.0
    """Lead (cycles) at which the unblocked factor is one half."""
    lead_scale: float = 1.0
    """Cycles over which the unblocked factor goes from one half to about 0.73."""
    opponent_margin: float = 0.1
    """Extra control distance given to opponents (m), for noise."""
    threshold: float = 0.5
    """Shoot when the best aim's score is at least this."""
    lane_range: float = 0.0
    """Within this distance of the goal centre (m) also shoot through an open lane (see the
    module docstring); 0: never (the skill alone waits for a likely goal)."""
    lane_lead: int = 1
    """Cycles by which the ball must beat every outfield opponent to the goal line for its
    lane to count as open."""
    lane_pressure: int = 1000
    """Shoot through an open lane only when an opponent can control the ball within this many
    cycles (the default: whatever the pressure)."""
    lane_score: float = 0.0
    """The open-lane aim must still score at least this against the goalkeeper (0: any shot on
    target through an open lane is taken)."""

    def __post_init__(self) -> None:
        check_params(self, positive=("max_range", "lead_scale"),
                     non_negative=("post_margin", "opponent_margin", "lane_range"),
                     counts=("aims",), fractions=("threshold", "lane_score"), finite=("lead_half",),
                     whole=("lane_lead", "lane_pressure"))


@dataclass(frozen=True)
class ShotPlan:
    """The best shot from where the ball is."""

    aim: np.ndarray
    """(2,) point on the goal line aimed at (m)."""
    kick: np.ndarray
    """(2,) kick request for the shooter (m/cycle)."""
    ball_vel: np.ndarray
    """(2,) ball velocity right after the kick."""
    cross_cycle: int
    """Cycles until the ball crosses the goal line."""
    opponent_cycle: int
    """Earliest opponent interception (UNREACHABLE: none before the line)."""
    score: float
    """Probability-like score in [0, 1]."""
    take: bool
    """Whether to shoot: the score clears the threshold, or the lane is open (see the module
    docstring)."""
    open_lane: bool = False
    """The shot is taken because its lane is open to the outfield opponents, not for its score."""


def aim_points(model: MotionModel, params: ShotParams = ShotParams()) -> np.ndarray:
    """(aims, 2) points on the opponents' goal line, evenly spread between the posts."""
    inner = model.goal_half_width - model.goal_post_radius - model.ball_radius - params.post_margin
    inner = max(inner, 0.0)
    ys = np.linspace(-inner, inner, params.aims) if params.aims > 1 else np.zeros(1)
    return np.column_stack([np.full(ys.shape, model.half_length), ys])


def best_shot(ctx: SkillContext, view: TeamView, shooter: int, params: ShotParams = ShotParams(),
              holder: bool = False, pressure: int = 0) -> ShotPlan | None:
    """The best shot for ``shooter`` (who must be able to kick), or None when out of range or
    when no aim can reach the goal line. ``holder``: a goalkeeper holding the ball;
    ``pressure``: cycles until the first opponent controls the ball (for the open-lane shot;
    0 when unknown: closed down)."""
    model = ctx.model
    shooter = check_player(shooter, model.players_per_team, "shooter")
    ball = np.asarray(view.ball, float)
    goal = model.goal_centre(ours=False)
    if float(np.hypot(*(goal - ball))) > params.max_range or ball[0] >= model.half_length:
        return None
    aims = ctx.table(("shot aims", params.aims, params.post_margin), lambda: aim_points(model, params))
    delta = aims - ball
    wanted = delta * (model.ball_speed_max / np.hypot(delta[:, 0], delta[:, 1]))[:, None]
    kicks, velocities = kick_for_velocity(model, view.own_pos[shooter], ball, view.ball_vel, wanted, holder,
                                          view.own_vel[shooter])
    count = len(aims)
    cross_cycle, limit = np.empty(count, dtype=np.int64), np.empty(count, dtype=np.int64)
    usable = lane_arrivals(aims, wanted, velocities, ball, model.ball_decay, model.horizon, 0, cross_cycle, limit)
    if usable.size == 0:
        return None
    aims, kicks, velocities, cross_cycle = aims[usable], kicks[usable], velocities[usable], cross_cycle[usable]
    theirs, _ = opponent_cycles(ctx, view, ball, velocities, cross_cycle, params.opponent_margin)
    lead = np.where(theirs >= UNREACHABLE, model.horizon, theirs - cross_cycle).astype(float)
    to_ball = ball - view.own_pos[shooter]
    if holder:
        gap = angle = 0.0
    else:
        gap = float(np.hypot(to_ball[0], to_ball[1])) - model.touch_distance
        angle = ball_angle_to_body(float(view.own_vel[shooter, 0]), float(view.own_vel[shooter, 1]),
                                   float(to_ball[0]), float(to_ball[1]), model.inertia_moment)
    distance_rate, angle_rate, speed_rate = model.noise_rates(gap, angle, float(np.hypot(*view.ball_vel)))
    score = np.empty(len(aims))
    constants = ctx.table(("shot scores", params), lambda: make_record(
        SHOT_PARAMS, kick_max=model.kick_speed_max, kick_rand=model.kick_rand, ball_rand=model.ball_rand,
        post=model.goal_half_width - model.ball_radius, lead_half=params.lead_half, lead_scale=params.lead_scale))
    best = shot_scores(ShotAims(np.ascontiguousarray(aims[:, 1]), lead, kicks, velocities, cross_cycle),
                       float(distance_rate), float(angle_rate), float(speed_rate), model.ball_travel,
                       model.ball_noise_gain, constants, _WINDOW, score)
    take = bool(score[best] >= params.threshold)
    open_lane = False
    if not take and params.lane_range > 0.0 and pressure <= params.lane_pressure \
            and float(np.hypot(*(goal - ball))) <= params.lane_range:
        field = _outfield_cycles(ctx, view, ball, velocities, cross_cycle, params.opponent_margin)
        lead_ok = np.where(field >= UNREACHABLE, model.horizon, field - cross_cycle) >= params.lane_lead
        open_score = np.where(lead_ok, score, -1.0)
        lane = int(np.argmax(open_score))
        if open_score[lane] >= params.lane_score:
            best, take, open_lane = lane, True, True
    return ShotPlan(aim=aims[best].copy(), kick=kicks[best].copy(), ball_vel=velocities[best].copy(),
                    cross_cycle=int(cross_cycle[best]), opponent_cycle=int(theirs[best]),
                    score=float(score[best]), take=take, open_lane=open_lane)


def _outfield_cycles(ctx: SkillContext, view: TeamView, ball: np.ndarray, velocities: np.ndarray,
                     limit: np.ndarray, margin: float) -> np.ndarray:
    """Earliest cycle any opponent but their goalkeeper controls the ball on each shot lane
    (UNREACHABLE: none before the line); opponents start one cycle late, as in
    :func:`agents.skills.lanes.opponent_cycles`."""
    theirs = ctx.arrays(view).theirs
    radius, catch = ctx.opponent_radii(margin)
    keep = np.arange(theirs.pos.shape[0]) != ctx.model.opponent_goalie_index
    if not keep.any():
        return np.full(len(velocities), UNREACHABLE, dtype=np.int64)
    field = Players(ctx.model, theirs.pos[keep], theirs.vel[keep], theirs.effort[keep], radius[keep], catch[keep])
    cycles, _ = intercept_many(ctx, ball, np.ascontiguousarray(velocities), field, 1.0, limit, 1, first_only=True)
    return cycles.min(axis=1)

