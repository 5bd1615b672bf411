"""The say/hear channel's compiled steps (:mod:`soccer_sim.perception.audio`): who a message
reaches, both teams' coded messages as one block, and which arrived messages each listener
hears within its capacities."""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, nogil=True)
def arrivals(pos: np.ndarray, spoke: np.ndarray, cut: float, out: np.ndarray) -> None:  # pragma: no cover - compiled
    """``out[l, s]``: speaker ``s`` said something (``spoke``) within ``cut`` m of listener
    ``l`` (never the speaker itself); ``pos`` (players, 2) m."""
    n = pos.shape[0]
    cut2 = cut * cut
    for l in range(n):
        for s in range(n):
            dx, dy = pos[l, 0] - pos[s, 0], pos[l, 1] - pos[s, 1]
            out[l, s] = spoke[s] and l != s and dx * dx + dy * dy <= cut2


@njit(cache=True, nogil=True)
def join_said(codes0: np.ndarray, speaks0: np.ndarray, codes1: np.ndarray, speaks1: np.ndarray, pos: np.ndarray,
              cut: float, silent: int, codes: np.ndarray, speaks: np.ndarray,
              arrived: np.ndarray) -> bool:  # pragma: no cover - compiled
    """Both teams' coded messages of one width as one block (``codes`` (players, width): the
    first team's rows, then the second's, a silent player's row all ``silent``; ``speaks``
    (players,)) and their :func:`arrivals` into ``arrived``; returns whether anybody spoke."""
    n0 = codes0.shape[0]
    spoke = False
    for i in range(codes.shape[0]):
        src, row = (codes0, i) if i < n0 else (codes1, i - n0)
        says = speaks0[row] if i < n0 else speaks1[row]
        speaks[i] = says
        spoke = spoke or says
        for j in range(codes.shape[1]):
            codes[i, j] = src[row, j] if says else silent
    arrivals(pos, speaks, cut, arrived)
    return spoke


@njit(cache=True, nogil=True)
def choose_heard(arrived: np.ndarray, key: np.ndarray, team: np.ndarray, cap: np.ndarray, regained: int,
                 hear_max: int, hear_decay: int, spoken: bool, heard: np.ndarray) -> None:  # pragma: no cover
    """Each listener's capacities ``cap`` (players, 2: team-mates, opponents) first regain
    ``regained`` up to ``hear_max``; then, when anything was ``spoken``, which arrived messages
    each listener hears in full (into ``heard``), spending those capacities: per side, the
    arrivals with the smallest ``key`` (the server's random order), as many as the side's
    capacity pays for at ``hear_decay`` each (all of them when that is 0)."""
    n = arrived.shape[0]
    if regained:
        for l in range(cap.shape[0]):
            for side in range(2):
                cap[l, side] = min(cap[l, side] + regained, hear_max)
    if not spoken:
        return
    for l in range(n):
        for side in range(2):
            allowed = cap[l, side] // hear_decay if hear_decay > 0 else n
            taken = 0
            while taken < allowed:
                best, best_key = -1, 0.0
                for s in range(n):
                    if arrived[l, s] and not heard[l, s] and (team[s] == team[l]) == (side == 0) \
                            and (best < 0 or key[l, s] < best_key):
                        best, best_key = s, key[l, s]
                if best < 0:
                    break
                heard[l, best] = True
                taken += 1
            cap[l, side] -= hear_decay * taken
