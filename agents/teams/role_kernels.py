"""The compiled kernels of the built-in team's positioning: settling the outfield players on
their roles (and measuring how far they are from them), the style's changes to the
formation's targets, and keeping attackers onside."""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from soccer_sim.rules.offside import offside_line


@njit(cache=True, nogil=True)
def settle_roles(goals: np.ndarray, rows: np.ndarray, targets: np.ndarray, role_of_player: np.ndarray,
                 steered: np.ndarray | None, players: np.ndarray, previous: np.ndarray, unfilled: float,
                 measured: bool) -> tuple[int, float, float, int]:  # pragma: no cover - compiled
    """Write the outfield players' goals (row ``rows[i]`` of ``goals``: ``steered[i]``, or its
    role's target when ``steered`` is None) and return the cycle's figures: role switches
    since ``previous``, and when ``measured`` the mean and the largest distance from a player
    to its role's target and the roles whose player is farther than ``unfilled`` (zeros when
    not measured)."""
    k = players.shape[0]
    switches, total, largest, far = 0, 0.0, 0.0, 0
    for i in range(k):
        t = role_of_player[i]
        if steered is None:
            goals[rows[i], 0] = targets[t, 0]
            goals[rows[i], 1] = targets[t, 1]
        else:
            goals[rows[i], 0] = steered[i, 0]
            goals[rows[i], 1] = steered[i, 1]
        if t != previous[i]:
            switches += 1
        if measured:
            d = math.hypot(players[i, 0] - targets[t, 0], players[i, 1] - targets[t, 1])
            total += d
            if d > largest:
                largest = d
            if d > unfilled:
                far += 1
    return switches, total / max(k, 1), largest, far


@njit(cache=True, nogil=True)
def shape_targets(targets: np.ndarray, rows: np.ndarray, shift: float, shifted: bool, x_limit: float,
                  forwards: np.ndarray, narrowing: float, narrowed: bool) -> None:  # pragma: no cover - compiled
    """The style's changes to the formation's targets (team frame, in place): ``rows`` moved
    ``shift`` metres up the field and kept within ``|x| <= x_limit`` when ``shifted``; the
    ``forwards``' y scaled by ``narrowing`` when ``narrowed``."""
    if shifted:
        for r in rows:
            targets[r, 0] = min(max(targets[r, 0] + shift, -x_limit), x_limit)
    if narrowed:
        for r in forwards:
            targets[r, 1] *= narrowing


@njit(cache=True, nogil=True)
def pull_onside(goals: np.ndarray, rows: np.ndarray, opp_pos: np.ndarray, ball_x: float,
                margin: float) -> None:  # pragma: no cover - compiled
    """Goals of ``rows`` beyond the offside line (the second-last opponent or the ball, never
    in our half) are pulled back to ``margin`` behind it (but not into our half)."""
    limit = offside_line(opp_pos[:, 0], ball_x) - margin
    for r in rows:
        if goals[r, 0] > limit:
            goals[r, 0] = max(limit, 0.0)


def steered_goals(players: np.ndarray, steps: np.ndarray, anchors: np.ndarray) -> np.ndarray:
    """A steering assigner's goal points (``steps``: each player's next point a short way down
    its field, e.g. potential-field bidding's) as goal points in the same directions but as
    far away as the players' role targets (``anchors``), all (m, 2) in the team frame.

    The team paces a run by how far its goal is (:mod:`agents.skills.pacing`): a goal one
    field step away would read as "arrived" and leave the player walking or standing, however
    far its role target is. A step no longer than the player's way to its target is kept."""
    step = steps - players
    length = np.hypot(step[:, 0], step[:, 1])
    reach = np.hypot(anchors[:, 0] - players[:, 0], anchors[:, 1] - players[:, 1])
    scale = np.where(length > 1e-9, np.maximum(reach, length) / np.maximum(length, 1e-9), 1.0)
    return players + step * scale[:, None]
