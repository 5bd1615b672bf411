"""Compiled kernels of :mod:`agents.teams.world_model`: one cycle of every player's beliefs.

Each kernel runs over a team's observers; row ``i`` of every output depends only on row ``i``
of the inputs (observer ``i``'s own sightings, messages and earlier beliefs), which is what
makes the model decentralised. Team frame, metres, m/cycle, cycles.

The kernels of a cycle's intake read their arguments by name from two records of
:mod:`agents.teams.belief_record`: ``r``, the team's world models
(:class:`~agents.teams.belief_record.BeliefRecord`, updated in place, whose ``params`` is a
:data:`BELIEF_PARAMS` record), and ``see``, what the players' sees of this cycle told them
(:class:`~agents.teams.belief_record.SeeRecord`, the arrays of the
:class:`~soccer_sim.perception.views.PlayerViews` of the same names).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np
from numba import njit

from agents.message_kernels import SENDER, VELOCITY

if TYPE_CHECKING:
    from agents.teams.belief_record import BeliefRecord, SeeRecord

AGE_NEVER = 1_000_000
"""The age (cycles) of something never seen."""

BELIEF_PARAMS = np.dtype([(name, np.float64) for name in (
    "ball_gain", "ball_velocity_gain", "ball_noise_share", "near", "gate_share", "gate_floor")])
"""How the world model weighs what it sees, as a named record (a one-element array of this
dtype, made from :class:`~agents.teams.world_model.BeliefParams` by
:func:`soccer_sim.kernels.make_record`; the fields are the dataclass's, which documents them)."""


@njit(cache=True, nogil=True)
def predict_beliefs(r: BeliefRecord) -> None:  # pragma: no cover - compiled
    """Advance every observer's beliefs by one cycle: the ball rolls on with its believed
    velocity and slows by ``r.ball_decay``; every age grows by one (players are believed to
    stay where they were last seen)."""
    ball, ball_vel, ball_age, mate_age, opp_age, ball_decay = (r.ball, r.ball_vel, r.ball_age, r.mate_age,
                                                               r.opp_age, r.ball_decay)
    for i in range(ball.shape[0]):
        ball[i, 0] += ball_vel[i, 0]
        ball[i, 1] += ball_vel[i, 1]
        ball_vel[i, 0] *= ball_decay
        ball_vel[i, 1] *= ball_decay
        if ball_age[i] < AGE_NEVER:
            ball_age[i] += 1
        for j in range(mate_age.shape[1]):
            if mate_age[i, j] < AGE_NEVER:
                mate_age[i, j] += 1
        for j in range(opp_age.shape[1]):
            if opp_age[i, j] < AGE_NEVER:
                opp_age[i, j] += 1


@njit(cache=True, nogil=True)
def see_ball(r: BeliefRecord, see: SeeRecord, cycle: int) -> None:  # pragma: no cover - compiled
    """Fold each observer's ball sighting of ``cycle`` (``see.ball_seen``, where: ``see.ball``,
    the reported distance: ``see.ball_distance``) into its belief: an alpha-beta filter on the
    predicted position (``ball_gain`` of the residual into the position, ``ball_velocity_gain``
    into the velocity), restarted when the residual is larger than the sighting's noise allows
    (``ball_noise_share`` of the distance plus 0.3 m: the ball was kicked or the belief was
    stale), the velocity then taken from the last two sightings. A sighting nearer than
    ``near`` m is precise enough to be taken as it is, with the velocity from the last two
    sightings when they are recent. The believed speed is capped at ``r.speed_max``."""
    ball, ball_vel, ball_age, last_seen, last_seen_cycle = (r.ball, r.ball_vel, r.ball_age, r.last_seen,
                                                            r.last_seen_cycle)
    seen, at, distance = see.ball_seen, see.ball, see.ball_distance
    params = r.params[0]
    gain, velocity_gain, noise_share, near = (params.ball_gain, params.ball_velocity_gain, params.ball_noise_share,
                                              params.near)
    ball_decay, speed_max = r.ball_decay, r.speed_max
    for i in range(ball.shape[0]):
        if not seen[i]:
            continue
        zx, zy = at[i, 0], at[i, 1]
        rx, ry = zx - ball[i, 0], zy - ball[i, 1]
        gate = noise_share * distance[i] + 0.3
        fresh = ball_age[i] <= 3
        if distance[i] < near and fresh and 0 < cycle - last_seen_cycle[i] <= 3:
            gap = cycle - last_seen_cycle[i]
            rolled = (1.0 - ball_decay ** gap) / (1.0 - ball_decay)
            scale = ball_decay ** (gap - 1) / rolled
            ball_vel[i, 0] = (zx - last_seen[i, 0]) * scale
            ball_vel[i, 1] = (zy - last_seen[i, 1]) * scale
            ball[i, 0], ball[i, 1] = zx, zy
        elif fresh and rx * rx + ry * ry <= gate * gate:
            ball[i, 0] += gain * rx
            ball[i, 1] += gain * ry
            ball_vel[i, 0] += velocity_gain * rx
            ball_vel[i, 1] += velocity_gain * ry
        else:
            vx, vy = 0.0, 0.0
            gap = cycle - last_seen_cycle[i]
            if 0 < gap <= 3:
                # displacement over the gap, turned into the velocity now: s = v0 (1 + d + ... + d^(g-1))
                rolled = (1.0 - ball_decay ** gap) / (1.0 - ball_decay)
                scale = ball_decay ** (gap - 1) / rolled
                vx = (zx - last_seen[i, 0]) * scale
                vy = (zy - last_seen[i, 1]) * scale
            ball[i, 0], ball[i, 1] = zx, zy
            ball_vel[i, 0], ball_vel[i, 1] = vx, vy
        speed = math.hypot(ball_vel[i, 0], ball_vel[i, 1])
        if speed > speed_max:
            ball_vel[i, 0] *= speed_max / speed
            ball_vel[i, 1] *= speed_max / speed
        ball_age[i] = 0
        last_seen[i, 0], last_seen[i, 1] = zx, zy
        last_seen_cycle[i] = cycle


@njit(cache=True, nogil=True)
def see_players(r: BeliefRecord, see: SeeRecord) -> None:  # pragma: no cover - compiled
    """Fold each observer's player sightings (``see.seen_*``, the first ``see.seen_count`` of
    each row, of observers who ``see.saw``) into its beliefs about team-mates (``r.mate_*``,
    (n, n)) and opponents (``r.opp_*``, (n, m)). A sighting with a number updates that player;
    one with a side but no number, the nearest player of that side not yet updated this cycle
    within the gate (``gate_share`` of the reported distance plus ``gate_floor`` m); one with
    neither, the nearest such player of either side within the gate. The observer's own row
    (its team-mate column ``i``) is left to the self-localisation."""
    saw, count, at, side, number, distance = (see.saw, see.seen_count, see.seen_position, see.seen_side,
                                              see.seen_number, see.seen_distance)
    mate_pos, mate_age, opp_pos, opp_age = r.mate_pos, r.mate_age, r.opp_pos, r.opp_age
    params = r.params[0]
    gate_share, gate_floor = params.gate_share, params.gate_floor
    n = mate_pos.shape[0]
    m = opp_pos.shape[1]
    for i in range(n):
        if not saw[i]:
            continue
        # numbered sightings first, so the anonymous ones go to the players left
        for c in range(count[i]):
            k = number[i, c]
            if k < 0:
                continue
            if side[i, c] > 0 and k < n and k != i:
                mate_pos[i, k, 0], mate_pos[i, k, 1] = at[i, c, 0], at[i, c, 1]
                mate_age[i, k] = 0
            elif side[i, c] < 0 and k < m:
                opp_pos[i, k, 0], opp_pos[i, k, 1] = at[i, c, 0], at[i, c, 1]
                opp_age[i, k] = 0
        for c in range(count[i]):
            if number[i, c] >= 0:
                continue
            gate = gate_share * distance[i, c] + gate_floor
            best, best_d, best_mate = -1, gate * gate, False
            if side[i, c] >= 0:
                for k in range(n):
                    if k == i or mate_age[i, k] == 0:
                        continue
                    dx, dy = mate_pos[i, k, 0] - at[i, c, 0], mate_pos[i, k, 1] - at[i, c, 1]
                    d = dx * dx + dy * dy
                    if d < best_d:
                        best, best_d, best_mate = k, d, True
            if side[i, c] <= 0:
                for k in range(m):
                    if opp_age[i, k] == 0:
                        continue
                    dx, dy = opp_pos[i, k, 0] - at[i, c, 0], opp_pos[i, k, 1] - at[i, c, 1]
                    d = dx * dx + dy * dy
                    if d < best_d:
                        best, best_d, best_mate = k, d, False
            if best < 0:
                continue
            if best_mate:
                mate_pos[i, best, 0], mate_pos[i, best, 1] = at[i, c, 0], at[i, c, 1]
                mate_age[i, best] = 0
            else:
                opp_pos[i, best, 0], opp_pos[i, best, 1] = at[i, c, 0], at[i, c, 1]
                opp_age[i, best] = 0


@njit(cache=True, nogil=True)
def hear_world(r: BeliefRecord, listener: np.ndarray, speaker: np.ndarray, decoded: np.ndarray,
               max_age: int) -> None:  # pragma: no cover - compiled
    """Fold the world information of the team messages heard this cycle into each listener's
    beliefs: rows of (listener, speaker, ``decoded``: :data:`~agents.message_kernels.DECODED`
    rows); only valid messages from another team-mate count. The ball is taken when the
    speaker's is fresher than the listener's (its age one more than said: the message took a
    cycle; the speaker said it where it expected it now; an age said as ``max_age``, the most
    a message holds, may be any older and is never taken), with the velocity when the message
    carries it (else the listener keeps the velocity it believes); a speaker who said its own
    position is there (age 1) unless the listener knows fresher."""
    mate_pos, mate_age, ball, ball_vel, ball_age = r.mate_pos, r.mate_age, r.ball, r.ball_vel, r.ball_age
    n = ball.shape[0]
    for p in range(listener.shape[0]):
        i, j = listener[p], speaker[p]
        m = decoded[p]
        if not m.valid or j < 0 or j >= n or j == i:
            continue
        if m.layout == SENDER and mate_age[i, j] > 1:
            mate_pos[i, j, 0] = m.sender_x
            mate_pos[i, j, 1] = m.sender_y
            mate_age[i, j] = 1
        age = m.ball_age + 1
        if m.ball_age < max_age and age < ball_age[i]:
            ball[i, 0] = m.ball_x
            ball[i, 1] = m.ball_y
            if m.layout == VELOCITY:
                ball_vel[i, 0] = m.velocity_x
                ball_vel[i, 1] = m.velocity_y
            ball_age[i] = age


@njit(cache=True, nogil=True)
def believe(r: BeliefRecord, see: SeeRecord, listener: np.ndarray, speaker: np.ndarray, decoded: np.ndarray,
            max_age: int, cycle: int) -> None:  # pragma: no cover - compiled
    """One cycle of every observer's beliefs ``r`` in one call: :func:`predict_beliefs`,
    :func:`see_ball` and :func:`see_players` with the sees of ``cycle`` (``see``), each
    observer's own position (its self-localisation, ``see.position``), then
    :func:`hear_world` with the team messages heard (``listener``, ``speaker``, ``decoded``;
    ``max_age``: the largest ball age a message holds)."""
    predict_beliefs(r)
    see_ball(r, see, cycle)
    see_players(r, see)
    mate_pos, mate_age, position = r.mate_pos, r.mate_age, see.position
    for i in range(mate_pos.shape[0]):
        mate_pos[i, i, 0] = position[i, 0]
        mate_pos[i, i, 1] = position[i, 1]
        mate_age[i, i] = 0
    hear_world(r, listener, speaker, decoded, max_age)


@njit(cache=True, nogil=True)
def own_kicks(kick: np.ndarray, kickable: float, ball: np.ndarray, ball_vel: np.ndarray, mate_pos: np.ndarray,
              speed_max: float) -> None:  # pragma: no cover - compiled
    """Each player's own kick of this cycle (``kick`` (n, 2) m/cycle; a zero row for none) added
    to the ball velocity it believes, when it believes the ball within ``kickable`` m of itself
    (``mate_pos[i, i]``), the sum capped at ``speed_max`` m/cycle."""
    for i in range(kick.shape[0]):
        if kick[i, 0] == 0.0 and kick[i, 1] == 0.0:
            continue
        gx, gy = ball[i, 0] - mate_pos[i, i, 0], ball[i, 1] - mate_pos[i, i, 1]
        if not gx * gx + gy * gy <= kickable * kickable:
            continue
        vx, vy = ball_vel[i, 0] + kick[i, 0], ball_vel[i, 1] + kick[i, 1]
        scale = min(1.0, speed_max / max(math.hypot(vx, vy), 1e-9))
        ball_vel[i, 0], ball_vel[i, 1] = vx * scale, vy * scale
