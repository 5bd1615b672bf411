"""Passing: candidate receivers, lead passes, the lane check and the choice of the best pass.

For every team-mate who may receive (not the passer, not offside, the goalkeeper only if
asked), a few target points are tried: its position and points in front of it
(:attr:`PassParams.leads`, "lead passes" that let it run onto the ball). For each target the
ball is kicked so that it covers the distance and still arrives at one of ``arrival_speeds``
(the decay model gives the initial speed ``distance * (1 - decay) + arrival_speed``), capped
at what one kick from where the passer stands can give (:func:`kick_for_velocity`). The pass
is **safe** when the receiver controls the ball on that trajectory at least ``min_lead``
cycles before any opponent could (:mod:`agents.skills.lanes`).

Safe passes are scored at the point where the receiver is predicted to take the ball: the
target when it can run there in time and no opponent gets to the ball first, else where it
can first meet the ball. With the weights of :class:`PassParams` the score rewards a point
further forward, closer to the opponents' goal, in open space (distance from the nearest
opponent) and a comfortable lead over the opponents; the best pass is returned.

A team-mate in an offside position is never a receiver; one who touches the ball on its way
is penalised by the referee too, so the team should keep such players out of the chase
(``ball_race(..., eligible=...)``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numba import njit

from agents.skills.interception import UNREACHABLE, intercept_many_checked, opponent_radii, race_players
from agents.skills.kicking import kick_for_velocity
from agents.skills.lanes import lane_arrivals
from agents.skills.model import MotionModel, SkillInputError, check_params, check_player, float_array, view_effort


@dataclass(frozen=True)
class PassParams:
    """Tunable choices of the passing skill (metres, cycles, m/cycle)."""

    leads: tuple[tuple[float, float], ...] = ((0.0, 0.0), (3.0, 0.0), (6.0, 0.0), (3.0, 3.0), (3.0, -3.0))
    """Offsets from the receiver's position to the points tried (m, team frame)."""
    arrival_speeds: tuple[float, ...] = (0.8, 1.6)
    """Ball speeds tried at the target (m/cycle): slow passes are easy to control, fast ones
    leave opponents less time; each target is tried with each."""
    min_distance: float = 3.0
    """Shorter passes are not considered (the passer could as well dribble)."""
    max_distance: float = 40.0
    """Longer passes are not considered (noise makes them unreliable)."""
    field_margin: float = 2.0
    """Targets are kept this far inside the lines."""
    min_lead: int = 2
    """Cycles by which the receiver must beat every opponent to the ball."""
    opponent_margin: float = 0.2
    """Extra control distance given to opponents (m), for noise."""
    extra_cycles: int = 10
    """Cycles searched beyond the ball's arrival at the target (the receiver may be late)."""
    allow_goalie: bool = False
    """Whether our goalkeeper may receive."""
    weight_forward: float = 1.0
    """Weight of the reception point's progress towards +x (per 20 m, clipped to [-1, 1.5])."""
    weight_goal: float = 0.5
    """Weight of the reception point's closeness to the opponents' goal (1 at the goal, 0 a field length away)."""
    weight_space: float = 0.6
    """Weight of the nearest opponent's distance to the reception point (per 10 m, capped at 1)."""
    weight_lead: float = 0.6
    """Weight of the receiver's lead over the opponents (per 10 cycles, capped at 1)."""

    def __post_init__(self) -> None:
        check_params(self, positive=("min_distance", "max_distance", "field_margin"),
                     non_negative=("opponent_margin", "weight_forward", "weight_goal", "weight_space", "weight_lead"),
                     whole=("min_lead", "extra_cycles"))
        leads = np.asarray(self.leads, dtype=float)
        if leads.ndim != 2 or leads.shape[1] != 2 or len(leads) == 0 or not np.isfinite(leads).all():
            raise SkillInputError(f"PassParams.leads must be a non-empty sequence of (x, y) offsets, "
                                  f"got {self.leads!r}")
        speeds = np.asarray(self.arrival_speeds, dtype=float)
        if speeds.ndim != 1 or len(speeds) == 0 or not (np.isfinite(speeds) & (speeds > 0)).all():
            raise SkillInputError(f"PassParams.arrival_speeds must be positive speeds, got {self.arrival_speeds!r}")
        if self.min_distance > self.max_distance:
            raise SkillInputError("PassParams.min_distance must not exceed max_distance")



@dataclass(frozen=True)
class PassPlan:
    """A chosen pass: ``kick`` is the request to put in ``TeamCommand.kick`` for the passer."""

    receiver: int
    target: np.ndarray
    """(2,) point the ball is sent to (m)."""
    receive_point: np.ndarray
    """(2,) where the receiver is predicted to take the ball (m), the point scored: the target
    when the receiver can be there when the ball arrives and no opponent gets to the ball
    before, else the point of its earliest interception."""
    kick: np.ndarray
    """(2,) kick request (m/cycle)."""
    ball_vel: np.ndarray
    """(2,) the ball's velocity right after the kick."""
    arrival_cycle: int
    """Cycles until the ball reaches the target."""
    receive_cycle: int
    """Cycle at which the receiver controls the ball."""
    opponent_cycle: int
    """Earliest cycle an opponent controls it (UNREACHABLE: none before it leaves the field,
    or none early enough to change the decision: see :func:`_deciding_cycles`)."""
    score: float


def offside_positions(model: MotionModel, own_pos: np.ndarray, opp_pos: np.ndarray, ball: np.ndarray) -> np.ndarray:
    """Bool per team-mate: in an offside position (in the opponents' half, ahead of the ball and
    of the second-last opponent). All False when the offside rule is off."""
    n = own_pos.shape[0]
    if not model.offside or opp_pos.shape[0] < 2:
        return np.zeros(n, dtype=bool)
    own_pos, opp_pos = float_array("own_pos", own_pos, (n, 2)), float_array("opp_pos", opp_pos, (-1, 2))
    return _beyond_line(own_pos, opp_pos, float(ball[0]))


@njit(cache=True, nogil=True)
def offside_line(opp_pos: np.ndarray, ball_x: float) -> float:  # pragma: no cover - compiled
    """The offside line's x (team frame): the second-last opponent's x (duplicates counted),
    the ball's, or the halfway line, whichever is furthest forward."""
    last = second = -math.inf
    for i in range(opp_pos.shape[0]):
        x = opp_pos[i, 0]
        if x > last:
            last, second = x, last
        elif x > second:
            second = x
    return max(second, ball_x, 0.0)


@njit(cache=True, nogil=True)
def _beyond_line(own_pos: np.ndarray, opp_pos: np.ndarray, ball_x: float) -> np.ndarray:  # pragma: no cover
    """Whether each of ``own_pos`` is beyond :func:`offside_line`."""
    line = offside_line(opp_pos, ball_x)
    out = np.empty(own_pos.shape[0], dtype=np.bool_)
    for i in range(own_pos.shape[0]):
        out[i] = own_pos[i, 0] > line
    return out


def pass_candidates(model: MotionModel, view: object, passer: int, params: PassParams = PassParams()) -> np.ndarray:
    """Indices of the team-mates the ``passer`` may pass to (not itself, not offside, the
    goalkeeper only when ``params.allow_goalie``)."""
    n = model.players_per_team
    passer = check_player(passer, n, "passer")
    ok = ~offside_positions(model, view.own_pos, view.opp_pos, view.ball)
    ok[passer] = False
    if not params.allow_goalie and model.goalie_index >= 0:
        ok[model.goalie_index] = False
    return np.flatnonzero(ok)


def best_pass(model: MotionModel, view: object, passer: int, params: PassParams = PassParams(),
              holder: bool = False) -> PassPlan | None:
    """The best safe pass for ``passer`` (who must be able to kick the ball), or None.

    ``holder``: the passer is our goalkeeper holding the ball (kicks at full effectiveness).
    """
    receivers = pass_candidates(model, view, passer, params)
    if receivers.size == 0:
        return None
    ball = np.asarray(view.ball, np.float64)
    size = receivers.size * len(params.leads) * len(params.arrival_speeds)
    targets, wanted = np.empty((size, 2)), np.empty((size, 2))
    owners = np.empty(size, dtype=np.int64)
    leads = np.asarray(params.leads, dtype=np.float64).reshape(-1, 2)
    count = _pass_targets(view.own_pos, receivers, leads, np.asarray(params.arrival_speeds, dtype=np.float64), ball,
                          model.half_length - params.field_margin, model.half_width - params.field_margin,
                          params.min_distance, params.max_distance, model.ball_decay, targets, owners, wanted)
    if count == 0:
        return None
    targets, owners, wanted = targets[:count], owners[:count], wanted[:count]
    kicks, velocities = kick_for_velocity(model, view.own_pos[passer], ball, view.ball_vel, wanted, holder)
    arrival = np.empty(count, dtype=np.int64)
    limit = np.empty(count, dtype=np.int64)
    usable = lane_arrivals(targets, wanted, velocities, ball, model.ball_decay, model.horizon, params.extra_cycles,
                           arrival, limit)
    if usable.size == 0:
        return None
    vel_u, own_u, lim_u = velocities[usable], owners[usable], limit[usable]
    # The lanes' searches on the view's checked arrays (those of the ball race): the same
    # calls as teammate_cycles and opponent_cycles make, without checking them again.
    ball_row, _, ours_now, theirs_now = race_players(model, view)
    ours, our_points = intercept_many_checked(model, ball_row, vel_u, ours_now, -1.0, lim_u, 0, False, own_u)
    rows = np.arange(usable.size)
    receive, received_at = ours[rows, own_u], our_points[rows, own_u]
    radius, catch = opponent_radii(model, params.opponent_margin)
    opponents = (theirs_now[0], theirs_now[1], theirs_now[2], radius, catch)
    theirs = intercept_many_checked(model, ball_row, vel_u, opponents, 1.0,
                                    _deciding_cycles(receive, arrival[usable], lim_u, params.min_lead), 1, True,
                                    _NO_RECEIVER)[0].min(axis=1, initial=UNREACHABLE)
    effort = view_effort(view, model.players_per_team)
    score = np.empty(usable.size)
    points = np.empty((usable.size, 2))
    best = _pass_scores(targets[usable], received_at, receive, theirs, arrival[usable], own_u, view.own_pos,
                        view.own_vel, effort, view.opp_pos, ball, model.reach, float(model.player_coast[-1]),
                        model.kickable_distance, model.half_length, params.min_lead,
                        np.array([params.weight_forward, params.weight_goal, params.weight_space, params.weight_lead]),
                        score, points)
    if best < 0:
        return None
    j = int(usable[best])
    return PassPlan(receiver=int(owners[j]), target=targets[j].copy(), receive_point=points[best].copy(),
                    kick=kicks[j].copy(), ball_vel=velocities[j].copy(), arrival_cycle=int(arrival[j]),
                    receive_cycle=int(receive[best]), opponent_cycle=int(theirs[best]), score=float(score[best]))


_NO_RECEIVER = np.zeros(0, dtype=np.int64)  # every opponent is searched on every lane

LEAD_CAP = 10
"""Cycles of lead over the opponents beyond which a pass scores no better (the score's lead
term is ``min(lead, LEAD_CAP) / LEAD_CAP``)."""


@njit(cache=True, nogil=True)
def _deciding_cycles(receive: np.ndarray, arrival: np.ndarray, limit: np.ndarray,
                     min_lead: int) -> np.ndarray:  # pragma: no cover - compiled
    """Per lane, the last cycle at which an opponent's interception can still change the
    pass's safety or score: ``receive + max(LEAD_CAP, min_lead)`` or ``arrival + min_lead``,
    whichever is later, within ``limit``; 0 for a lane the receiver never reaches (it is not
    scored). Opponents later than that count as UNREACHABLE, which decides the same, so the
    search stops there (the opponents' search is most of a pass decision's cost)."""
    out = np.empty(receive.shape[0], dtype=np.int64)
    for i in range(receive.shape[0]):
        if receive[i] >= UNREACHABLE:
            out[i] = 0
        else:
            out[i] = min(limit[i], max(receive[i] + max(LEAD_CAP, min_lead), arrival[i] + min_lead))
    return out


@njit(cache=True, nogil=True)
def _pass_targets(own_pos: np.ndarray, receivers: np.ndarray, leads: np.ndarray, speeds: np.ndarray, ball: np.ndarray,
                  x_max: float, y_max: float, min_distance: float, max_distance: float, decay: float,
                  targets: np.ndarray, owners: np.ndarray, wanted: np.ndarray) -> int:  # pragma: no cover
    """Candidate targets (receiver + lead, kept within |x| <= x_max, |y| <= y_max), each with
    each arrival speed, at a usable distance; the ball velocity each needs. Returns the count."""
    count = 0
    for r in range(receivers.shape[0]):
        who = receivers[r]
        for j in range(leads.shape[0]):
            tx = min(max(own_pos[who, 0] + leads[j, 0], -x_max), x_max)
            ty = min(max(own_pos[who, 1] + leads[j, 1], -y_max), y_max)
            dx, dy = tx - ball[0], ty - ball[1]
            dist = math.sqrt(dx * dx + dy * dy)
            if dist < min_distance or dist > max_distance:
                continue
            for k in range(speeds.shape[0]):
                speed = dist * (1.0 - decay) + speeds[k]
                targets[count, 0] = tx
                targets[count, 1] = ty
                owners[count] = who
                wanted[count, 0] = dx / dist * speed
                wanted[count, 1] = dy / dist * speed
                count += 1
    return count


@njit(cache=True, nogil=True)
def _pass_scores(targets: np.ndarray, received_at: np.ndarray, receive: np.ndarray, theirs: np.ndarray,
                 arrival: np.ndarray, owners: np.ndarray, own_pos: np.ndarray, own_vel: np.ndarray, effort: np.ndarray,
                 opp_pos: np.ndarray, ball: np.ndarray, reach: np.ndarray, coast: float, kickable: float,
                 half_length: float, min_lead: int, weights: np.ndarray, score: np.ndarray,
                 points: np.ndarray) -> int:  # pragma: no cover - compiled
    """Score the safe candidates (see the module docstring); unsafe ones score -inf. Returns
    the best row, or -1 when none is safe."""
    best, best_score = -1, -np.inf
    for i in range(targets.shape[0]):
        score[i] = -np.inf
        if receive[i] >= UNREACHABLE or theirs[i] - receive[i] < min_lead:
            continue
        who = owners[i]
        # Run onto it: the receiver takes the ball at the target when it can be there by the
        # ball's arrival and no opponent gets to the ball before; else where it meets it first.
        sx = own_pos[who, 0] + coast * own_vel[who, 0]
        sy = own_pos[who, 1] + coast * own_vel[who, 1]
        need = max(math.sqrt((targets[i, 0] - sx) ** 2 + (targets[i, 1] - sy) ** 2) - kickable, 0.0) / effort[who]
        run = np.searchsorted(reach, need)
        if run <= arrival[i] and theirs[i] >= arrival[i] + min_lead:
            px, py = targets[i, 0], targets[i, 1]
        else:
            px, py = received_at[i, 0], received_at[i, 1]
        points[i, 0] = px
        points[i, 1] = py
        space = 10.0
        for o in range(opp_pos.shape[0]):
            space = min(space, math.sqrt((px - opp_pos[o, 0]) ** 2 + (py - opp_pos[o, 1]) ** 2))
        lead = min(theirs[i] - receive[i], LEAD_CAP) / LEAD_CAP
        closeness = 1.0 - math.sqrt((px - half_length) ** 2 + py * py) / (2.0 * half_length)
        forward = min(max((px - ball[0]) / 20.0, -1.0), 1.5)
        value = weights[0] * forward + weights[1] * closeness + weights[2] * space / 10.0 + weights[3] * lead
        score[i] = value
        if value > best_score:
            best, best_score = i, value
    return best
