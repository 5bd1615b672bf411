"""Passing: candidate receivers, lead passes, the lane check and the choice of the best pass.

For every team-mate who may receive (not the passer, not offside, the goalkeeper only if
asked), a few target points are tried: its position and points in front of it
(:attr:`PassParams.leads`, "lead passes" that let it run onto the ball). For each target the
ball is kicked so that it covers the distance and still arrives at one of ``arrival_speeds``
(the decay model gives the initial speed ``distance * (1 - decay) + arrival_speed``), capped
at what one kick from where the passer stands can give (:func:`kick_for_velocity`). The pass
is **safe** when the receiver controls the ball on that trajectory at least ``min_lead``
cycles before any opponent could (:mod:`agents.skills.lanes`).

Safe passes are scored at the point where the receiver is predicted to take the ball (the
target when it can run there in time and no opponent gets to the ball first; else where it
can first meet the ball; the
weights of :class:`PassParams`): further forward, closer to the opponents' goal, in open
space (distance from the nearest opponent) and with a comfortable lead over the opponents;
the best one is returned.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from agents.skills.interception import UNREACHABLE
from agents.skills.kicking import kick_for_velocity
from agents.skills.lanes import opponent_cycles, teammate_cycles
from agents.skills.model import MotionModel, check_player, view_effort


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
    """Earliest cycle an opponent controls it (UNREACHABLE: none before it leaves the field)."""
    score: float


def offside_positions(model: MotionModel, own_pos: np.ndarray, opp_pos: np.ndarray, ball: np.ndarray) -> np.ndarray:
    """Bool per team-mate: in an offside position (in the opponents' half, ahead of the ball and
    of the second-last opponent). All False when the offside rule is off."""
    n = own_pos.shape[0]
    if not model.offside or opp_pos.shape[0] < 2:
        return np.zeros(n, dtype=bool)
    line = max(np.partition(opp_pos[:, 0], -2)[-2], float(ball[0]), 0.0)
    return own_pos[:, 0] > line


def pass_candidates(model: MotionModel, view: object, passer: int, params: PassParams = PassParams()) -> np.ndarray:
    """Indices of the team-mates the ``passer`` may pass to (not itself, not offside, the
    goalkeeper only when ``params.allow_goalie``)."""
    n = model.players_per_team
    passer = check_player(passer, n, "passer")
    ok = ~offside_positions(model, view.own_pos, view.opp_pos, view.ball)
    ok[passer] = False
    if not params.allow_goalie:
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
    ball = np.asarray(view.ball, float)
    leads = np.asarray(params.leads, float)
    speeds = np.asarray(params.arrival_speeds, float)
    targets = (view.own_pos[receivers][:, None, :] + leads[None, :, :]).reshape(-1, 2)
    targets = model.clamp_to_field(targets, params.field_margin)
    owners = np.repeat(receivers, len(leads) * len(speeds))
    arrive = np.tile(speeds, len(targets))
    targets = np.repeat(targets, len(speeds), axis=0)
    delta = targets - ball
    dist = np.hypot(delta[:, 0], delta[:, 1])
    keep = (dist >= params.min_distance) & (dist <= params.max_distance)
    if not keep.any():
        return None
    targets, owners, delta, dist, arrive = targets[keep], owners[keep], delta[keep], dist[keep], arrive[keep]
    direction = delta / dist[:, None]
    wanted = direction * model.ball_speed_for(dist, arrive)[:, None]
    kicks, velocities = kick_for_velocity(model, view.own_pos[passer], ball, view.ball_vel, wanted, holder)
    speed = np.einsum("ij,ij->i", velocities, direction)  # speed along the intended line
    on_line = speed > 0.99 * np.hypot(velocities[:, 0], velocities[:, 1])
    arrival = model.ball_cycles_to(dist, speed)
    usable = on_line & np.isfinite(arrival) & (arrival <= model.horizon)
    if not usable.any():
        return None
    idx = np.flatnonzero(usable)
    arrival_cycle = np.ceil(arrival[idx]).astype(np.int64)
    limit = np.minimum(arrival_cycle + params.extra_cycles, model.horizon)
    ours, our_points = teammate_cycles(model, view, ball, velocities[idx], limit)
    receive = ours[np.arange(idx.size), owners[idx]]
    received_at = our_points[np.arange(idx.size), owners[idx]]
    theirs, _ = opponent_cycles(model, view, ball, velocities[idx], limit, params.opponent_margin)
    safe = (receive < UNREACHABLE) & (theirs - receive >= params.min_lead)
    if not safe.any():
        return None
    sel = np.flatnonzero(safe)
    chosen = idx[sel]
    # Run onto it: the receiver takes the ball at the target when it can be there by the
    # ball's arrival and no opponent gets to the ball before that; else where it meets it first.
    runner = owners[chosen]
    effort = view_effort(view, model.players_per_team)[runner]
    settle = view.own_pos[runner] + model.player_coast[-1] * view.own_vel[runner]
    need = np.hypot(*(targets[chosen] - settle).T) - model.kickable_distance
    run_cycles = np.searchsorted(model.reach, np.maximum(need, 0.0) / effort)
    at_target = (run_cycles <= arrival_cycle[sel]) & (theirs[sel] >= arrival_cycle[sel] + params.min_lead)
    pts = np.where(at_target[:, None], targets[chosen], received_at[sel])
    gap = pts[:, None, :] - view.opp_pos[None, :, :]
    space = np.sqrt(np.min(np.einsum("pkj,pkj->pk", gap, gap), axis=1)) if view.opp_pos.shape[0] else np.full(len(sel), 10.0)
    lead = np.minimum(theirs[sel] - receive[sel], 10) / 10.0
    goal = model.goal_centre(ours=False)
    closeness = 1.0 - np.hypot(pts[:, 0] - goal[0], pts[:, 1] - goal[1]) / (2.0 * model.half_length)
    forward = np.clip((pts[:, 0] - ball[0]) / 20.0, -1.0, 1.5)
    score = (params.weight_forward * forward + params.weight_goal * closeness
             + params.weight_space * np.minimum(space / 10.0, 1.0) + params.weight_lead * lead)
    best = int(np.argmax(score))
    j = int(chosen[best])
    return PassPlan(receiver=int(owners[j]), target=targets[j].copy(), receive_point=pts[best].copy(),
                    kick=kicks[j].copy(),
                    ball_vel=velocities[j].copy(), arrival_cycle=int(arrival_cycle[sel[best]]),
                    receive_cycle=int(receive[sel[best]]), opponent_cycle=int(theirs[sel[best]]),
                    score=float(score[best]))
