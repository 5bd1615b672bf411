"""The tackle, foul and card marks of a game log's players: the state flags and the tackle
counter rcssserver shows for them.

rcssserver raises a player's flags when it acts and keeps some of them up while the player
is frozen (its ``Player::resetState``):

- a tackle raises TACKLE (the success draw came out), TACKLE and TACKLE_FAULT (the ball was
  in reach but the draw failed) or TACKLE_FAULT alone (out of reach), and counts one tackle
  (counter 8 of the ``(c ...)`` counts); the flags stay up while the tackler is frozen:
  ``tackle_cycles`` shows, one show for a foul tackle that pushed the ball (which does not
  freeze the tackler);
- a player frozen by an opponent's foul tackle shows FOUL_CHARGED for ``foul_cycles`` shows;
- a yellow card stays on the player (YELLOW_CARD) for the rest of the match.

soccer-sim's TACKLE events say whether the draw came out; whether a missed ball was in reach
is worked out again from the state the tackle saw (the previous show's), by
:func:`soccer_sim.tackles.failure_probability`. How long a flag stays up follows the
match's own ``WorldState.frozen`` count, so both always agree.
"""

from __future__ import annotations

import numpy as np

from soccer_sim.body import facing
from soccer_sim.config import TackleConfig
from soccer_sim.rcg.mapping import FOUL_CHARGED, TACKLE, TACKLE_FAULT, YELLOW_CARD
from soccer_sim.state import WorldState
from soccer_sim.tackles import failure_probability

TACKLE_COUNT = 8
"""Index of the tackle counter among a player's 12 ``(c ...)`` counts (rcssserver 19: kick,
dash, turn, catch, move, turn_neck, change_view, say, tackle, pointto, attentionto,
change_focus)."""
_REACHED, _FOUL = 1, 2   # bits of a TACKLE event's detail


class Marks:
    """Per-player tackle, foul-charge and card flags of one match's log. Idle (one check per
    cycle) until the first tackle."""

    def __init__(self, rows: int, config: TackleConfig, inertia_moment: float) -> None:
        self.config = config
        self._inertia = inertia_moment
        self._tackle_left = np.zeros(rows, dtype=np.int64)   # shows the tackle flags still stay up
        self._tackle_bits = np.zeros(rows, dtype=np.int64)
        self._charged_left = np.zeros(rows, dtype=np.int64)
        self._frozen = np.zeros(rows, dtype=np.int64)        # WorldState.frozen at the last show
        self._pos = np.zeros((rows, 2))                      # the state the next tackles see
        self._vel = np.zeros((rows, 2))
        self._ball = np.zeros(2)
        self.active = False
        """Whether any flag is up or any player frozen (then every cycle has work to do)."""
        self.cards = False
        """Whether any yellow card has been shown."""

    def remember(self, state: WorldState) -> None:
        """Keep the state after a cycle: the next cycle's tackles are judged on it."""
        np.copyto(self._pos, state.pos)
        np.copyto(self._vel, state.vel)
        np.copyto(self._ball, state.ball)

    def tackle_bits(self, row: int, detail: int) -> int:
        """The flags of ``row``'s tackle (a TACKLE event's ``detail``) on the remembered state."""
        if detail & _REACHED:
            return TACKLE
        cfg = self.config
        px, py = self._pos[row]
        dx, dy = self._ball[0] - px, self._ball[1] - py
        fx, fy = facing(float(self._vel[row, 0]), float(self._vel[row, 1]), float(dx), float(dy),
                        self._inertia)
        x, y = dx * fx + dy * fy, dy * fx - dx * fy    # the ball in the tackler's body frame
        exponent = cfg.foul_exponent if detail & _FOUL else cfg.tackle_exponent
        prob = failure_probability(float(x), float(y), cfg.tackle_dist, cfg.tackle_back_dist, cfg.tackle_width,
                                   exponent)
        return TACKLE_FAULT if prob >= 1.0 else TACKLE | TACKLE_FAULT

    def mark(self, state: WorldState, flags: np.ndarray, tackles: list[tuple[int, int]]) -> None:
        """Add this cycle's marks to ``flags`` (P,); ``tackles``: (row, detail) of this cycle's
        TACKLE events. ``state`` is the state after the cycle."""
        frozen = state.frozen
        if tackles:
            for row, detail in tackles:
                self._tackle_bits[row] = self.tackle_bits(row, detail)
                self._tackle_left[row] = frozen[row] + 1   # frozen after this cycle's count-down
            self.active = True
        if self.active:
            # frozen again (not counting down) without a tackle: fouled by a foul tackle
            fouled = (frozen > 0) & (frozen >= self._frozen) & (self._tackle_left <= frozen)
            self._charged_left[fouled] = frozen[fouled] + 1
            tackling = self._tackle_left > 0
            flags[tackling] |= self._tackle_bits[tackling]
            flags[self._charged_left > 0] |= FOUL_CHARGED
            np.subtract(self._tackle_left, 1, out=self._tackle_left, where=tackling)
            np.subtract(self._charged_left, 1, out=self._charged_left, where=self._charged_left > 0)
            np.copyto(self._frozen, frozen)
            self.active = bool(self._tackle_left.any() or self._charged_left.any() or frozen.any())
        if self.cards:
            flags[state.cards == 1] |= YELLOW_CARD
