"""Compiled kernels of :mod:`agents.teams.world_model`: one cycle of every player's beliefs.

Each kernel runs over a team's observers; row ``i`` of every output depends only on row ``i``
of the inputs (observer ``i``'s own sightings, messages and earlier beliefs), which is what
makes the model decentralised. Team frame, metres, m/cycle, cycles.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

AGE_NEVER = 1_000_000
"""The age (cycles) of something never seen."""


@njit(cache=True, nogil=True)
def predict_beliefs(ball: np.ndarray, ball_vel: np.ndarray, ball_age: np.ndarray, mate_age: np.ndarray,
                    opp_age: np.ndarray, ball_decay: float) -> None:  # pragma: no cover - compiled
    """Advance every observer's beliefs by one cycle: the ball rolls on with its believed
    velocity and slows by ``ball_decay``; every age grows by one (players are believed to stay
    where they were last seen)."""
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
def see_ball(ball: np.ndarray, ball_vel: np.ndarray, ball_age: np.ndarray, last_seen: np.ndarray,
             last_seen_cycle: np.ndarray, seen: np.ndarray, at: np.ndarray, distance: np.ndarray, cycle: int,
             gain: float, velocity_gain: float, noise_share: float, near: float, ball_decay: float,
             speed_max: float) -> None:  # pragma: no cover - compiled
    """Fold each observer's ball sighting (``seen``, ``at``, reported ``distance``) into its
    belief: an alpha-beta filter on the predicted position (``gain`` of the residual into the
    position, ``velocity_gain`` into the velocity), restarted when the residual is larger than
    the sighting's noise allows (``noise_share`` of the distance plus 0.3 m: the ball was kicked
    or the belief was stale), the velocity then taken from the last two sightings. A sighting
    nearer than ``near`` m is precise enough to be taken as it is, with the velocity from the
    last two sightings when they are recent."""
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
def see_players(saw: np.ndarray, count: np.ndarray, at: np.ndarray, side: np.ndarray, number: np.ndarray,
                distance: np.ndarray, mate_pos: np.ndarray, mate_age: np.ndarray, opp_pos: np.ndarray,
                opp_age: np.ndarray, gate_share: float, gate_floor: float) -> None:  # pragma: no cover - compiled
    """Fold each observer's player sightings into its beliefs about team-mates (``mate_*``,
    (n, n)) and opponents (``opp_*``, (n, m)). A sighting with a number updates that player; one
    with a side but no number, the nearest player of that side not yet updated this cycle within
    the gate (``gate_share`` of the reported distance plus ``gate_floor`` m); one with neither,
    the nearest such player of either side within the gate. The observer's own row (its
    team-mate column ``i``) is left to the self-localisation."""
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
def hear_world(listener: np.ndarray, speaker: np.ndarray, kind: np.ndarray, world: np.ndarray, world_kind: int,
               mate_pos: np.ndarray, mate_age: np.ndarray, ball: np.ndarray, ball_vel: np.ndarray,
               ball_age: np.ndarray, ball_decay: float) -> None:  # pragma: no cover - compiled
    """Fold the team-mates' world messages heard this cycle into each listener's beliefs: rows
    of (listener, speaker, kind, values (ball x, y, velocity x, y, age, sender x, y)); only
    rows of ``world_kind`` from another team-mate count. The sender is where it said it was
    (age 1) unless the listener knows fresher; the ball is taken when fresher than the
    listener's, rolled on by the cycle the message took."""
    n = ball.shape[0]
    for p in range(listener.shape[0]):
        i, j = listener[p], speaker[p]
        if kind[p] != world_kind or j < 0 or j >= n or j == i:
            continue
        if mate_age[i, j] > 1:
            mate_pos[i, j, 0] = world[p, 5]
            mate_pos[i, j, 1] = world[p, 6]
            mate_age[i, j] = 1
        age = int(world[p, 4]) + 1
        if age < ball_age[i]:
            vx, vy = world[p, 2], world[p, 3]
            ball[i, 0] = world[p, 0] + vx
            ball[i, 1] = world[p, 1] + vy
            ball_vel[i, 0] = vx * ball_decay
            ball_vel[i, 1] = vy * ball_decay
            ball_age[i] = age


@njit(cache=True, nogil=True)
def believe(ball: np.ndarray, ball_vel: np.ndarray, ball_age: np.ndarray, mate_pos: np.ndarray,
            mate_age: np.ndarray, opp_pos: np.ndarray, opp_age: np.ndarray, last_seen: np.ndarray,
            last_seen_cycle: np.ndarray, ball_seen: np.ndarray, ball_at: np.ndarray, ball_distance: np.ndarray,
            saw: np.ndarray, count: np.ndarray, at: np.ndarray, side: np.ndarray, number: np.ndarray,
            distance: np.ndarray, position: np.ndarray, listener: np.ndarray, speaker: np.ndarray,
            kind: np.ndarray, world: np.ndarray, world_kind: int, cycle: int, p: np.ndarray, ball_decay: float,
            speed_max: float) -> None:  # pragma: no cover - compiled
    """One cycle of every observer's beliefs in one call: :func:`predict_beliefs`,
    :func:`see_ball`, :func:`see_players`, each observer's own position (its
    self-localisation, ``position``), then :func:`hear_world`. ``p``: the
    :class:`~agents.teams.world_model.BeliefParams` (ball gain, velocity gain, noise share,
    near, gate share, gate floor)."""
    predict_beliefs(ball, ball_vel, ball_age, mate_age, opp_age, ball_decay)
    see_ball(ball, ball_vel, ball_age, last_seen, last_seen_cycle, ball_seen, ball_at, ball_distance, cycle, p[0],
             p[1], p[2], p[3], ball_decay, speed_max)
    see_players(saw, count, at, side, number, distance, mate_pos, mate_age, opp_pos, opp_age, p[4], p[5])
    for i in range(ball.shape[0]):
        mate_pos[i, i, 0] = position[i, 0]
        mate_pos[i, i, 1] = position[i, 1]
        mate_age[i, i] = 0
    hear_world(listener, speaker, kind, world, world_kind, mate_pos, mate_age, ball, ball_vel, ball_age, ball_decay)


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
