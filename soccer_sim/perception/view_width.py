"""rcssserver's view width (``change_view``): a narrower cone seen more often, or a wider one
seen less often, and when each player's sees arrive.

``(change_view narrow|normal|wide)`` (``Player::change_view``, without synchronous sees) sets
the player's cone to half, once or twice ``visible_angle`` (45°, 90°, 180° by default) and
the interval between its sees to 2, 4 or 8 ticks of the server's visual timer, which ticks
every ``send_step / 4`` ms (37.5 ms): a see every 75, 150 or 300 ms, while a cycle lasts
``simulator_step`` = 100 ms. Each player's sender counts the ticks since its last see and
sends one when the count reaches its interval (``VisualSenderPlayerV1::sendVisual``), so a
change to a shorter interval sends at the player's next tick if the count is already there.
Every player starts with ``normal``. View quality stays ``high`` (``low`` is not modelled).

The simulator delivers at most one see per player and cycle (the latest, when a narrow view
sends two within 100 ms), and a change asked in cycle ``t`` takes effect from the start of
cycle ``t + 1``. :class:`SeeTimer` keeps every player's timer; with every player at
``normal`` it gives exactly the schedule of :func:`~.params.see_cycles`.
"""

from __future__ import annotations

import math

import numpy as np

from soccer_sim.perception.params import SeeParams

NARROW, NORMAL, WIDE = 0, 1, 2
"""The view widths' codes (``TeamCommand.change_view``, ``PlayerViews.view_width``)."""
VIEW_WIDTHS = ("narrow", "normal", "wide")
"""rcssserver's names of the view widths, by code."""
KEEP = -1
"""``TeamCommand.change_view`` for a player that keeps its view width."""
SEE_TICKS = np.array([2, 4, 8], dtype=np.int64)
"""Ticks of the visual timer between two sees, by view width (``M_visual_send_interval``)."""
ANGLE_FACTORS = np.array([0.5, 1.0, 2.0])
"""Each view width's cone as a share of ``visible_angle``."""


def view_angles(widths: np.ndarray, params: SeeParams) -> np.ndarray:
    """The total view angle (degrees) of each player with view width code ``widths``."""
    return ANGLE_FACTORS[np.asarray(widths, dtype=np.int64)] * params.visible_angle


class SeeTimer:
    """When each of ``P`` players receives a see, cycle by cycle, under view widths that may
    change (module docstring). ``offsets_ms``: each player's first see (ms, ``[0, send_step)``:
    rcssserver's players connect at different moments)."""

    def __init__(self, params: SeeParams, offsets_ms: np.ndarray, cycle: int = 0) -> None:
        self.params = params
        self.offsets = np.asarray(offsets_ms, dtype=np.float64)
        self.tick = params.send_step / 4.0
        """The visual timer's tick (ms)."""
        self.widths = np.full(len(self.offsets), NORMAL, dtype=np.int64)
        """(P,) each player's view width code."""
        start, send = float(cycle * params.simulator_step), float(params.send_step)
        self.next_see = self.offsets + send * np.ceil(np.maximum(start - self.offsets, 0.0) / send)
        """(P,) when each player's next see is due (ms), at its widths so far: at ``normal``
        from the start of ``cycle``, the timer's first cycle."""

    def change(self, widths: np.ndarray, cycle: int) -> None:
        """Players whose ``widths`` code (P,) is not :data:`KEEP` take that width from the
        start of cycle ``cycle`` on (their next see comes when the ticks since their last see
        reach the new interval, at their first tick from then on if that is past)."""
        new = np.asarray(widths, dtype=np.int64)
        changed = (new != KEEP) & (new != self.widths)
        if not changed.any():
            return
        start = float(cycle * self.params.simulator_step)
        last = self.next_see - SEE_TICKS[self.widths] * self.tick
        self.widths[changed] = new[changed]
        due = last + SEE_TICKS[self.widths] * self.tick
        first_tick = self.offsets + np.ceil(np.maximum(start - self.offsets, 0.0) / self.tick) * self.tick
        self.next_see = np.where(changed, np.maximum(due, first_tick), self.next_see)

    def sees(self, cycle: int, out: np.ndarray) -> np.ndarray:
        """Whether each player receives a see during ``cycle`` (into ``out``, bool (P,)); the
        cycles must be asked in order, each once."""
        end = float((cycle + 1) * self.params.simulator_step)
        np.less(self.next_see, end, out=out)
        interval = SEE_TICKS[self.widths] * self.tick
        while True:
            late = self.next_see < end
            if not late.any():
                return out
            self.next_see[late] += interval[late]


def check_view_widths(widths: object, n: int) -> np.ndarray | str:
    """``TeamCommand.change_view`` as (n,) codes, or the message saying what is wrong with it."""
    try:
        codes = np.asarray(widths)
    except (TypeError, ValueError) as exc:
        return f"command.change_view is not an array ({exc})"
    if codes.shape != (n,):
        return f"command.change_view must have shape {(n,)} (a code per player), got {codes.shape}"
    if codes.dtype.kind not in "iu":
        return f"command.change_view must hold integer codes ({_CODES}), got dtype {codes.dtype}"
    bad = np.flatnonzero((codes < KEEP) | (codes > WIDE))
    if bad.size:
        return f"command.change_view[{bad[0]}] is {codes[bad[0]]}: not a view width ({_CODES})"
    return codes.astype(np.int64)


_CODES = "NARROW 0, NORMAL 1, WIDE 2, KEEP -1"
