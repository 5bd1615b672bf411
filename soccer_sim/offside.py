"""Offside positions, judged at the moment a player kicks the ball.

A team-mate of the kicker is in an offside position when its centre is (strictly) in the
opponents' half, nearer the opponents' goal line than the ball and nearer than the
second-last opponent. Being level with the ball or with the second-last opponent is not
offside. The referee (soccer_sim.referee) decides which kicks mark players and when a
marked player is penalised (when it plays the ball), with a free kick on the offside line.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np


def mark_offside_positions(pos: np.ndarray, n: int | tuple[int, int], team: int, direction: int, ball_x: float,
                           kickers: Sequence[int] | np.ndarray, out: np.ndarray) -> float | None:
    """Write into ``out`` ((P,) bool) which players of ``team`` are in an offside position.

    ``pos`` is the (P, 2) absolute player positions (home rows first), ``n`` the players per
    side (an int for two even sides, or (home, away)), ``direction`` the kicking team's attack
    direction (+1 towards +x), ``ball_x`` the ball's x when kicked and ``kickers`` the rows
    that kicked (never marked). With fewer than two opponents there is no second-last
    opponent; the opponents' goal line takes its place, so nobody is offside.
    Returns the offside line's x (absolute frame) if any player was marked, else None.
    """
    home, away = (n, n) if isinstance(n, (int, np.integer)) else n
    total = home + away
    own = slice(0, home) if team == 0 else slice(home, total)
    opp = slice(home, total) if team == 0 else slice(0, home)
    m = away if team == 0 else home
    if m >= 2:
        # Second-last opponent: the second-largest depth among the opponents.
        opp_x = pos[opp, 0]
        second_last = (float(np.partition(opp_x, m - 2)[m - 2]) if direction > 0
                       else -float(np.partition(opp_x, 1)[1]))
    else:
        second_last = float("inf")
    # The offside line: the halfway line, the ball or the second-last opponent, whichever is deepest.
    line = max(0.0, direction * ball_x, second_last)
    out[:] = False
    marks = out[own]
    np.greater(pos[own, 0] * direction, line, out=marks)
    out[kickers] = False
    return direction * line if np.count_nonzero(marks) > 0 else None
