"""The compiled kernels of the team's shape (:mod:`agents.teams.shape`): the back line held
behind the ball and the role targets moved at a running pace, and the support spots around
our ball carrier. Team frame: we attack +x; units m and m/cycle.

The shape's numbers travel as named records, as in :mod:`soccer_sim.kernels` (one-element
numpy structured arrays read by field name, made once per match by
:class:`~agents.teams.shape.Shape`): :data:`SHAPE_PARAMS` and :data:`SUPPORT_PARAMS`. What
changes every cycle (the ball's x, whether play is on, whether the team attacks, whether the
targets move at the block's pace) comes as named arguments."""

from __future__ import annotations

import math

import numpy as np
from numba import njit


SHAPE_PARAMS = np.dtype([(name, np.float64) for name in (
    "rest_ball_gap", "rest_forward_margin", "rest_max_gap", "defend_ball_gap", "back_floor", "push", "drop")])
"""The block's and the back line's numbers (:func:`advance_block`, :func:`settle_targets`; m and
m/cycle): the :class:`~agents.teams.shape.ShapeParams` of the same names (``push`` and ``drop``
are its ``push_speed`` and ``drop_speed``) and ``back_floor``, the deepest x of the back line."""

SUPPORT_PARAMS = np.dtype([(name, np.float64) for name in (
    "x_limit", "y_limit", "lane_cap", "space_cap", "forward_weight", "travel_weight", "crowd_distance")])
"""The support spots' numbers (:func:`support_spots`): the largest |x| and |y| of a spot (m) and
the :class:`~agents.teams.shape.ShapeParams` of the same names."""


@njit(cache=True, nogil=True)
def switch_side(lead: int, in_play: bool, attacking: bool, pending: int, margin: int,
                persist: int) -> tuple[bool, int]:  # pragma: no cover - compiled
    """Attack or defend with hysteresis: (attacking, pending) after a ball race whose ``lead``
    (cycles; positive: we are first) says who wins the ball. Out of play (not ``in_play``
    before) the side follows the race at once; a change of side waits until the race has said
    so ``persist`` cycles in a row (``pending`` counts them) or by ``margin`` cycles or more."""
    winning = lead > 0
    if not in_play:
        return winning, 0
    if winning == attacking:
        return attacking, 0
    pending += 1
    if abs(lead) >= margin or pending >= persist:
        return winning, 0
    return attacking, pending


@njit(cache=True, nogil=True)
def advance_block(block: np.ndarray, point: np.ndarray, shift: float, in_play: bool,
                  params: np.ndarray) -> None:  # pragma: no cover - compiled
    """Move the block (in place: ``block`` = (query x, query y, shift)) towards the query
    ``point`` and the ``shift``: at most ``push`` metres forwards (+x) or ``drop`` metres
    otherwise, each (``params``: a :data:`SHAPE_PARAMS` record); at once when not ``in_play``
    (the first cycle of play)."""
    push, drop = params[0].push, params[0].drop
    if not in_play:
        block[0], block[1], block[2] = point[0], point[1], shift
        return
    dx, dy = point[0] - block[0], point[1] - block[1]
    d = math.hypot(dx, dy)
    cap = push if dx > 0.0 else drop
    if d > cap:
        dx, dy = dx * cap / d, dy * cap / d
    block[0] += dx
    block[1] += dy
    step = shift - block[2]
    block[2] += min(step, push) if step > 0.0 else max(step, -drop)


@njit(cache=True, nogil=True)
def settle_targets(targets: np.ndarray, previous: np.ndarray, rows: np.ndarray, back_rows: np.ndarray,
                   opp_pos: np.ndarray, params: np.ndarray, ball_x: float, play_on: bool, attacking: bool,
                   limited: bool) -> None:  # pragma: no cover - compiled
    """The shape's last word on the role targets (in place), ``params`` (a :data:`SHAPE_PARAMS`
    record) giving the numbers. In ``play_on`` the ``back_rows`` are held behind the ball at
    ``ball_x``: when ``attacking`` (rest defence) at or below ``ball_x - rest_ball_gap`` and
    ``rest_forward_margin`` behind the opponents' most advanced player but no more than
    ``rest_max_gap`` behind the ball, otherwise at or below ``ball_x - defend_ball_gap``; never
    below ``back_floor``. When ``limited``, each of ``rows`` moves from ``previous`` by at most
    ``push`` (a move forwards, +x) or ``drop`` (any other move) metres. ``previous`` is then set
    to the targets of ``rows``."""
    p = params[0]
    if play_on:
        if attacking:
            front = np.inf
            for j in range(opp_pos.shape[0]):  # their goalkeeper is never their most advanced
                front = min(front, opp_pos[j, 0])
            limit = min(ball_x - p.rest_ball_gap, max(front - p.rest_forward_margin, ball_x - p.rest_max_gap))
        else:
            limit = ball_x - p.defend_ball_gap
        limit = max(limit, p.back_floor)
        for r in back_rows:
            if targets[r, 0] > limit:
                targets[r, 0] = limit
    push, drop = p.push, p.drop
    for r in rows:
        if limited:
            dx = targets[r, 0] - previous[r, 0]
            dy = targets[r, 1] - previous[r, 1]
            d = math.hypot(dx, dy)
            cap = push if dx > 0.0 else drop
            if d > cap:
                s = cap / d
                targets[r, 0] = previous[r, 0] + dx * s
                targets[r, 1] = previous[r, 1] + dy * s
        previous[r, 0] = targets[r, 0]
        previous[r, 1] = targets[r, 1]


@njit(cache=True, nogil=True)
def _lane_gap(ax: float, ay: float, bx: float, by: float, px: float, py: float) -> float:  # pragma: no cover
    """Distance from point p to the segment a-b."""
    ux, uy = bx - ax, by - ay
    length2 = ux * ux + uy * uy
    t = 0.0 if length2 <= 0.0 else min(max(((px - ax) * ux + (py - ay) * uy) / length2, 0.0), 1.0)
    return math.hypot(ax + t * ux - px, ay + t * uy - py)


@njit(cache=True, nogil=True)
def support_spots(carrier: np.ndarray, own_pos: np.ndarray, goals: np.ndarray, candidates: np.ndarray,
                  opp_pos: np.ndarray, offsets: np.ndarray, count: int, x_max: float, params: np.ndarray,
                  out_rows: np.ndarray, out_spots: np.ndarray) -> int:  # pragma: no cover - compiled
    """Open spots around our ball carrier and who goes there.

    ``carrier`` (2,): where our carrier has (or gets) the ball; ``own_pos``: where the
    possible supporters are (the team passes its role targets: support spots become role
    targets); ``candidates``: rows of ``own_pos`` that may support (the ``count`` nearest the
    carrier do); ``offsets`` (S, 2):
    the spots relative to the carrier; ``params``: a :data:`SUPPORT_PARAMS` record. A spot
    counts only inside ``|x| <= x_limit``,
    ``|y| <= y_limit`` and at or behind ``x_max`` (onside). Its score is the opponents' gap
    to the pass lane (capped at ``lane_cap``) plus half their gap to the spot (capped at
    ``space_cap``) plus ``forward_weight`` times its forward share of the offset, less
    ``travel_weight`` per metre the supporter has to run, less everything when it is within
    ``crowd_distance`` of another row's point in ``goals`` (the candidates' own excluded)
    or of a spot already taken. Writes the supporters to ``out_rows`` and their spots to
    ``out_spots``; returns how many."""
    p = params[0]
    x_limit, y_limit, lane_cap, space_cap = p.x_limit, p.y_limit, p.lane_cap, p.space_cap
    forward_weight, travel_weight, crowd_distance = p.forward_weight, p.travel_weight, p.crowd_distance
    n_c = candidates.shape[0]
    chosen = 0
    picked = np.zeros(n_c, dtype=np.bool_)
    is_candidate = np.zeros(own_pos.shape[0], dtype=np.bool_)
    for c in candidates:
        is_candidate[c] = True
    cx, cy = carrier[0], carrier[1]
    n_s = offsets.shape[0]
    base = np.full(n_s, -np.inf)
    for s in range(n_s):
        sx, sy = cx + offsets[s, 0], cy + offsets[s, 1]
        if abs(sx) > x_limit or abs(sy) > y_limit or sx > x_max:
            continue
        lane, space = lane_cap, space_cap
        for j in range(opp_pos.shape[0]):
            px, py = opp_pos[j, 0], opp_pos[j, 1]
            lane = min(lane, _lane_gap(cx, cy, sx, sy, px, py))
            space = min(space, math.hypot(sx - px, sy - py))
        crowded = False
        for r in range(goals.shape[0]):
            if not is_candidate[r] and math.hypot(goals[r, 0] - sx, goals[r, 1] - sy) < crowd_distance:
                crowded = True
                break
        if crowded:
            continue
        reach = math.hypot(offsets[s, 0], offsets[s, 1])
        base[s] = lane + 0.5 * space + forward_weight * offsets[s, 0] / max(reach, 1e-9)
    while chosen < count:
        # the nearest candidate to the carrier not yet placed
        best_c, best_d = -1, np.inf
        for i in range(n_c):
            if not picked[i]:
                r = candidates[i]
                d = math.hypot(own_pos[r, 0] - cx, own_pos[r, 1] - cy)
                if d < best_d:
                    best_c, best_d = i, d
        if best_c < 0:
            break
        picked[best_c] = True
        row = candidates[best_c]
        best_s, best_score = -1, -np.inf
        for s in range(n_s):
            if base[s] == -np.inf:
                continue
            sx, sy = cx + offsets[s, 0], cy + offsets[s, 1]
            taken = False
            for k in range(chosen):
                if math.hypot(out_spots[k, 0] - sx, out_spots[k, 1] - sy) < crowd_distance:
                    taken = True
            if taken:
                continue
            score = base[s] - travel_weight * math.hypot(own_pos[row, 0] - sx, own_pos[row, 1] - sy)
            if score > best_score:
                best_s, best_score = s, score
        if best_s < 0:
            break
        out_rows[chosen] = row
        out_spots[chosen, 0] = cx + offsets[best_s, 0]
        out_spots[chosen, 1] = cy + offsets[best_s, 1]
        chosen += 1
    return chosen
