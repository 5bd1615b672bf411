"""The figures of ``bench soccer`` from an rcssserver game log (``.rcg``, read by
:func:`soccer_sim.rcg.read_rcg`): a real server's match or one soccer-sim wrote.

The per-cycle figures are those of :class:`~experiments.benchmarks.soccer_cycles.CycleFigures`,
fed from the show lines (every show line after the first is a cycle; a show line is in play
on when the last ``(playmode ...)`` line at or before its cycle is ``play_on``; the recovery
threshold and the relocation limit come from the log's ``server_param`` line). The counts:

* **goals**: the last ``(team ...)`` line's score;
* **kicks**, **tackles**, **goalkeeper catches**: the rise of each player's kick, tackle and
  catch counters in its ``(c ...)`` (rcssserver counts a kick or a catch only when it
  succeeds, every tackle tried); **tackles won**: a tackle whose show line has the
  tackle flag without the fault flag;
* set plays, from the changes of play mode (a mode line repeating the previous one is not a
  change): **corners** ``corner_kick_X``, **kick-ins** ``kick_in_X``, **goal kicks**
  ``goal_kick_X``, **offside calls** ``offside_X``, **fouls** ``foul_charge_X``, **dropped
  balls** ``drop_ball``, **free kicks** ``free_kick_X`` and ``indirect_free_kick_X`` except
  the free kick rcssserver gives a goalkeeper's side right after its keeper catches the ball
  (a catch by side X in that cycle or the one before; soccer-sim counts that restart
  separately, as the catch).

**Passes (kick to kick)** and **shots (ball path)**: as :mod:`experiments.benchmarks.soccer_plays`
defines them (the pitch's half length is rcssserver's, the simulator's default field's, which the
log does not give).

Not in a log, so shown as ``-``: **shots**, **shots ending on a body** and **passes** (their
definitions, :mod:`soccer_sim.analysis.plays`, need the ball's velocity at the kick, before the
ball moved and was perturbed, and the body touches of the ball; a show line has the state
after the cycle's motion), **set-play retakes** (a retaken goal kick does not change the play
mode, so the log does not show it), **teammate contacts** (not logged), and the **distance
run by role** unless role labels are given (a log names no roles; for helios-base they come
from its formation file, :mod:`experiments.benchmarks.helios_roles`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence

import numpy as np

from experiments.benchmarks.rcg_walk import CATCH, KEYS, KICK, TACKLE_COUNT, log_figures, mode_changes, walk_shows
from experiments.benchmarks.soccer_match import COUNTED, place_figures, role_figure
from soccer_sim.config import STANDARD_FIELD
from soccer_sim.rcg import GameLog

NOT_IN_A_LOG = ("shots", "shots ending on a body", "passes", "set-play retakes", "teammate contacts",
               "body commands dropped")
"""Counted figures a game log cannot give (see the module docstring)."""
HALF_LENGTH = STANDARD_FIELD.half_length
"""Half the length of rcssserver's pitch (m; a constant of the server, not in the log)."""
_MODE_FIGURES = {"corner_kick": "corners", "kick_in": "kick-ins", "goal_kick": "goal kicks",
                 "offside": "offside calls", "foul_charge": "fouls", "free_kick": "free kicks",
                 "indirect_free_kick": "free kicks"}
"""Play mode (without its side) -> the figure a change to it counts in."""


def rcg_figures(log: GameLog, labels: Mapping[str, Sequence[str]] | None = None,
                groups: Mapping[str, str] | None = None) -> dict[str, float | None]:
    """Every figure of ``bench soccer`` that the game log defines (None for the others).
    ``labels``: per side letter (``l``, ``r``) the role label of shirt numbers 1..11, for the
    distance run by role; None leaves those figures out. ``groups`` (label -> group, e.g.
    position -> role kind): the distance run by group too. A ValueError for a log with no
    show line or without the server parameters the figures need."""
    cycles, plays = log_figures(log, HALF_LENGTH)
    row_labels = None
    if labels is not None:
        row_labels = [labels[side][unum - 1] for side, unum in KEYS]
    counts = dict.fromkeys(COUNTED, 0.0)
    catches: set[tuple[str, int]] = set()
    for step in walk_shows(log):
        if step.number == 0:
            cycles.start(step.pos)
            continue
        rise = step.rise
        counts["kicks"] += float(rise[:, KICK].sum())
        counts["goalkeeper catches"] += float(rise[:, CATCH].sum())
        counts["tackles"] += float(rise[:, TACKLE_COUNT].sum())
        counts["tackles won"] += float(step.won.size)
        catches.update((KEYS[int(i)][0], step.cycle) for i in np.flatnonzero(rise[:, CATCH] > 0))
        play_on = step.mode == "play_on"
        cycles.add(step.pos, step.ball[:2], step.stamina, step.outfield, play_on, row_labels)
        plays.add(np.flatnonzero(rise[:, KICK] > 0), np.flatnonzero(rise[:, CATCH] > 0), step.won, step.touched,
                  step.ball, play_on)
    modes = sorted(log.play_modes, key=lambda m: m[0])  # file order is cycle order; stable
    _count_modes(modes, catches, counts)
    if log.teams:
        counts["goals"] = float(log.teams[-1][3] + log.teams[-1][4])
    figures: dict[str, float | None] = {name: (None if name in NOT_IN_A_LOG else value)
                                        for name, value in counts.items()}
    figures.update(plays.figures())
    figures.update(cycles.figures())
    if row_labels is not None:
        figures.update({role_figure(label): km for label, km in cycles.role_distances().items()})
        figures.update(place_figures(cycles))
        if groups is not None:
            figures.update({role_figure(group): km for group, km in cycles.role_distances(groups).items()})
            figures.update(place_figures(cycles, groups))
    return figures


def _count_modes(modes: list[tuple[int, str]], catches: set[tuple[str, int]], counts: dict[str, float]) -> None:
    """Add the set plays, calls and dropped balls of the play-mode changes to ``counts``."""
    for cycle, name in mode_changes(modes):
        if name == "drop_ball":
            counts["dropped balls"] += 1
            continue
        base, _, side = name.rpartition("_")
        figure = _MODE_FIGURES.get(base) if side in ("l", "r") else None
        if figure is None:
            continue
        if base == "free_kick" and ((side, cycle) in catches or (side, cycle - 1) in catches):
            continue  # the restart after the keeper's catch
        counts[figure] += 1
