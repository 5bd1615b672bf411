"""Offside positions, judged at the moment a player kicks the ball.

A team-mate of the kicker is in an offside position when its centre is (strictly) in the
opponents' half, nearer the opponents' goal line than the ball and nearer than the
second-last opponent. Being level with the ball or with the second-last opponent is not
offside. The referee (soccer_sim.referee) decides which kicks mark players and when a
marked player is penalised.
"""

from __future__ import annotations

import numpy as np


def mark_offside_positions(pos: np.ndarray, n: int, team: int, direction: int, ball_x: float,
                           kickers: np.ndarray, out: np.ndarray) -> bool:
    """Write into ``out`` ((2n,) bool) which players of ``team`` are in an offside position.

    ``pos`` is the (2n, 2) absolute player positions (home rows first), ``direction`` the
    kicking team's attack direction (+1 towards +x), ``ball_x`` the ball's x when kicked and
    ``kickers`` the rows that kicked (never marked). With a single opponent there is no
    second-last opponent; the opponents' goal line takes its place, so nobody is offside.
    Returns whether any player was marked.
    """
    own = slice(0, n) if team == 0 else slice(n, 2 * n)
    opp = slice(n, 2 * n) if team == 0 else slice(0, n)
    depth = direction * pos[own, 0]  # distance towards the opponents' goal line
    opp_depth = direction * pos[opp, 0]
    if n >= 2:
        second_last = float(np.partition(opp_depth, n - 2)[n - 2])
    else:
        second_last = float("inf")
    out[:] = False
    marks = out[own]
    np.logical_and(depth > 0.0, depth > direction * ball_x, out=marks)
    marks &= depth > second_last
    out[kickers] = False
    return bool(marks.any())
