"""An rcssserver game log (``.rcg``, :func:`soccer_sim.rcg.read_rcg`) walked show line by show
line: what both readers of a log take from each, ``bench soccer``'s figures
(:mod:`experiments.benchmarks.soccer_rcg`) and the match report of a match played in the real
server (:mod:`experiments.rcg_report`).

Players are rows ``0 .. 21``: the left side's shirts 1..11, then the right side's
(:data:`KEYS`). Per show line: where each player stands, its stamina, whether it is an
outfield player on its feet, its state flags, and how much each player's kick, catch and tackle
counters (its ``(c ...)``) rose since the previous show line (rcssserver counts a kick or a
catch only when it succeeds, every tackle tried); a tackle is won when its show line has the
tackle flag without the fault flag; a show line is in the play mode of the last
``(playmode ...)`` line at or before its cycle.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from typing import NamedTuple

import numpy as np

from experiments.benchmarks.soccer_cycles import CycleFigures
from experiments.benchmarks.soccer_plays import PlayFigures
from soccer_sim.rcg import GameLog
from soccer_sim.rcg.mapping import BALL_COLLIDE, GOALIE, MAX_PLAYER, STAND, TACKLE, TACKLE_FAULT

KEYS: tuple[tuple[str, int], ...] = tuple((side, unum) for side in "lr" for unum in range(1, MAX_PLAYER + 1))
"""(side letter, shirt number) of each player row."""
INDEX = {key: i for i, key in enumerate(KEYS)}
"""A player's row by (side letter, shirt number)."""
TEAM = np.repeat([0, 1], MAX_PLAYER)
"""(22,) each row's side: 0 left, 1 right."""
KICK, CATCH, TACKLE_COUNT = 0, 1, 2
"""Columns of :attr:`ShowStep.rise`."""
_COUNTERS = (0, 3, 8)
"""Indices of the kick, catch and tackle counters in a player's ``(c ...)``."""


class LogFigures(NamedTuple):
    """The per-cycle and per-play figures of a log, made from its ``server_param`` line."""

    cycles: CycleFigures
    plays: PlayFigures


def log_figures(log: GameLog, half_length: float) -> LogFigures:
    """:class:`CycleFigures` (the relocation limit: three ``player_speed_max``; the recovery
    threshold) and :class:`PlayFigures` (the goal and ball of the log, the pitch's
    ``half_length`` m) of ``log``; a ValueError for a log without show lines or without the
    server parameters they need."""
    if not log.shows:
        raise ValueError("the game log has no show lines")
    params = log.server_params
    try:
        relocation = 3.0 * float(params["player_speed_max"])
        threshold = float(params["recover_dec_thr"]) * float(params["stamina_max"])
        plays = PlayFigures(TEAM, half_length, float(params["goal_width"]), float(params["ball_size"]),
                            float(params["ball_decay"]))
    except (KeyError, ValueError) as exc:
        raise ValueError(f"the game log's server_param line lacks a number for {exc}") from None
    return LogFigures(CycleFigures(TEAM, relocation, threshold), plays)


class ShowStep(NamedTuple):
    """One show line of a log (module docstring). The arrays are the walk's own, overwritten
    at the next step: read them, do not keep them."""

    number: int
    """The show line's place in the log (0: the first)."""
    cycle: int
    mode: str
    """The play mode the show line is in."""
    entered: tuple[str, ...]
    """The play modes entered since the previous show line, in order."""
    ball: np.ndarray
    """The ball's show line values (x, y, ...)."""
    pos: np.ndarray
    """(22, 2) each player's position (m; the log's frame)."""
    stamina: np.ndarray
    outfield: np.ndarray
    """(22,) bool: an outfield player on its feet."""
    states: np.ndarray
    """(22,) int each player's state flags."""
    rise: np.ndarray
    """(22, 3) int the rise of each player's kick, catch and tackle counters since the previous
    show line (zero at the first)."""
    touched: np.ndarray
    """Rows of the players the ball bounced off."""
    won: np.ndarray
    """Rows of the players whose tackle won the ball (none at the first show line)."""


def walk_shows(log: GameLog) -> Iterator[ShowStep]:
    """Every show line of ``log`` as a :class:`ShowStep`, in order."""
    rows = len(KEYS)
    pos, stamina = np.zeros((rows, 2)), np.full(rows, np.inf)
    outfield, states = np.zeros(rows, dtype=bool), np.zeros(rows, dtype=np.int64)
    previous = np.zeros((rows, 3), dtype=np.int64)
    modes = sorted(log.play_modes, key=lambda m: m[0])  # file order is cycle order; stable
    next_mode, mode = 0, ""
    for number, show in enumerate(log.shows):
        entered = []
        while next_mode < len(modes) and modes[next_mode][0] <= show.cycle:
            mode = modes[next_mode][1]
            entered.append(mode)
            next_mode += 1
        now = previous.copy()
        touched, won = [], []
        outfield[:] = False
        for p in show.players:
            i = INDEX[(p.side, p.unum)]
            pos[i] = p.x, p.y
            stamina[i] = p.stamina
            states[i] = p.state
            outfield[i] = bool(p.state & STAND) and not p.state & GOALIE
            now[i] = [p.counts[c] for c in _COUNTERS]
            if p.state & BALL_COLLIDE:
                touched.append(i)
            if number and now[i, TACKLE_COUNT] > previous[i, TACKLE_COUNT] and p.state & TACKLE \
                    and not p.state & TACKLE_FAULT:
                won.append(i)
        rise = now - previous if number else np.zeros_like(now)
        previous = now
        yield ShowStep(number, show.cycle, mode, tuple(entered), np.array(show.ball), pos, stamina, outfield, states,
                       rise, np.array(touched, dtype=np.intp), np.array(won, dtype=np.intp))


def mode_changes(modes: Iterable[tuple[int, str]]) -> Iterator[tuple[int, str]]:
    """The changes of play mode among ``modes`` ((cycle, mode) of a log's ``(playmode ...)``
    lines, in cycle order): a line repeating the previous mode is not a change."""
    previous = ""
    for cycle, name in modes:
        if name != previous:
            previous = name
            yield cycle, name
