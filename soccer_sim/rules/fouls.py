"""Fouls and cards (rcssserver's ``FoulRef`` with its ``Referee::checkFoul``), and where a
player sent off waits.

A successful tackle that pushed the ball (:mod:`soccer_sim.tackles`) is judged against every
present opponent of the tackler that could kick the ball (within its kickable distance):

* a **foul tackle** (``TeamCommand.foul``) freezes each such opponent for
  ``TackleConfig.foul_cycles`` and is seen with probability ``foul_detect_probability``
  (one draw per opponent): a foul;
* an opponent **charged** (it dashed this cycle or the one before, as rcssserver's
  ``dashed()``, :attr:`soccer_sim.tackles.TackleOutcome.dashed`; stands between the tackler and the
  ball: no further from the tackler than the ball, ahead of it along the tackler-ball line and
  within the two bodies' radii of that line, and faces within 90° of that line by
  :func:`soccer_sim.body.facing`) makes a seen foul tackle a yellow card (a red one with
  ``red_card_probability``); an ordinary tackle that charges it is a foul with probability
  ``foul_detect_probability``, then also a yellow card with ``red_card_probability``
  (rcssserver's own mapping of its draws).

A foul (FOUL event, the tackler) gives the fouled team a free kick where the tackler stands,
moved inside the pitch, out of both goal areas and out of the fouled team's own penalty area
(onto that area's corner); a card is a YELLOW_CARD or RED_CARD event. A second yellow card is
a red one. A player shown a red card is sent off: ``WorldState.present`` turns False, it is
parked off the pitch (:func:`parking_spot`), and if it held the ball the ball is free. Its
team plays on with fewer. Unlike rcssserver, which waits 30 cycles in a foul-charge play mode
before the free kick, the free kick begins at once (as this simulator's offside and
back-pass free kicks do).
"""

from __future__ import annotations

import math

import numpy as np

from soccer_sim.body import facing
from soccer_sim.config import FieldConfig
from soccer_sim.kernels import PT_INERTIA_MOMENT, PT_KICKABLE
from soccer_sim.rules.judge import Judge
from soccer_sim.rules.play_modes import PlayModes
from soccer_sim.state import AWAY, HOME, NO_PLAYER, EventKind, PlayMode, WorldState

PARKING_SPACING = 3.0
"""Metres between the parking spots of a team's players (rcssserver: 3 m per shirt number)."""


def parking_spot(row: int, home: int, field: FieldConfig) -> tuple[float, float]:
    """Where the player of row ``row`` waits once sent off (absolute frame): beside the pitch
    at the outer edge of its margin (``y = -(half_width + margin)``; rcssserver parks 3 m out,
    which a ball leaving the pitch at full speed can still reach), 3 m per shirt number from
    the halfway line, home players at x < 0 and away players at x > 0, as rcssserver does."""
    shirt = row + 1 if row < home else row - home + 1
    side = -1.0 if row < home else 1.0
    return side * PARKING_SPACING * shirt, -(field.half_width + field.margin)


def park_absent(state: WorldState, home: int, field: FieldConfig) -> None:
    """Put every player sent off back on its parking spot, still."""
    for row in np.flatnonzero(~state.present).tolist():
        state.pos[row] = parking_spot(row, home, field)
        state.vel[row] = 0.0


class FoulJudge(Judge):
    """rcssserver's ``FoulRef``: fouls, free kicks and cards after successful tackles. Its
    random draws come from ``rng`` (the match's tackle generator)."""

    name = "fouls"

    def __init__(self, modes: PlayModes, rng: np.random.Generator, types: np.ndarray | None = None) -> None:
        self.modes = modes
        self.rng = rng
        config = modes.config
        self.config = config.tackles
        self._kickable = config.physics.kickable_distance
        self._inertia = config.physics.inertia_moment
        self._sizes = 2.0 * config.physics.player_radius
        self.types = types
        """Each player row's type parameters (:attr:`soccer_sim.kinematics.Kinematics.types`,
        which the match's kinematics keep up to date): a fouled player's kickable distance and
        ``inertia_moment``; None: the physics config's."""

    def tackle_taken(self, state: WorldState, row: int, foul: bool, dashed: np.ndarray) -> None:
        """``row``'s tackle pushed the ball; ``foul``: it was a foul tackle; ``dashed``: (P,)
        which players dashed this cycle or the one before."""
        charge, yellow, red = self._check(state, row, foul, dashed)
        if charge or yellow or red:
            at = (float(state.pos[row, 0]), float(state.pos[row, 1]))  # before the free kick clears the tackler away
            self._call_foul(state, row)
            if red:
                self._red_card(state, row, at)
            elif yellow:
                self._yellow_card(state, row, at)

    def _check(self, state: WorldState, row: int, foul: bool, dashed: np.ndarray) -> tuple[bool, bool, bool]:
        """rcssserver's ``checkFoul``: (foul seen, yellow card, red card)."""
        cfg, rng = self.config, self.rng
        home = self.modes.n
        opponents = range(home, len(state.present)) if row < home else range(home)
        tx, ty = float(state.pos[row, 0]), float(state.pos[row, 1])
        bx, by = float(state.ball[0]), float(state.ball[1])
        ball_dist2 = (bx - tx) ** 2 + (by - ty) ** 2
        angle = math.atan2(by - ty, bx - tx)
        ca, sa = math.cos(angle), math.sin(angle)
        charge = yellow = red = False
        types = self.types
        for p in opponents:
            if not state.present[p]:
                continue
            px, py = float(state.pos[p, 0]), float(state.pos[p, 1])
            kickable = self._kickable if types is None else float(types[p, PT_KICKABLE])
            if math.hypot(bx - px, by - py) > kickable:
                continue
            seen = False
            if foul:
                state.frozen[p] = max(int(state.frozen[p]), cfg.foul_cycles)
                if rng.random() < cfg.foul_detect_probability:
                    seen = charge = True
            if not dashed[p]:
                continue
            rx, ry = px - tx, py - ty
            if rx * rx + ry * ry > ball_dist2:
                continue
            ahead, side = rx * ca + ry * sa, ry * ca - rx * sa
            if ahead < 0.0 or abs(side) > self._sizes:
                continue
            fx, fy = facing(float(state.vel[p, 0]), float(state.vel[p, 1]), bx - px, by - py,
                            self._inertia if types is None else float(types[p, PT_INERTIA_MOMENT]))
            if fx * ca + fy * sa < 0.0:  # the opponent's body more than 90° off the tackle's line
                continue
            if foul:
                if seen:
                    yellow = True
                    if rng.random() < cfg.red_card_probability:
                        yellow, red = False, True
            elif rng.random() < cfg.foul_detect_probability:
                charge = True
                if rng.random() < cfg.red_card_probability:
                    yellow = True
        return charge, yellow, red

    def _call_foul(self, state: WorldState, row: int) -> None:
        """FOUL event; the fouled team's free kick (see the module docstring for the spot)."""
        modes = self.modes
        team = HOME if row < modes.n else AWAY
        fouled = 1 - team
        f = modes.config.field
        x = min(max(float(state.pos[row, 0]), -f.half_length), f.half_length)
        y = min(max(float(state.pos[row, 1]), -f.half_width), f.half_width)
        front = f.half_length - f.goal_area_length
        if abs(x) > front and abs(y) < f.goal_area_width / 2.0:
            x = math.copysign(front, x)
        own = -state.attack_direction(fouled)  # the side of the fouled team's goal
        if own * x > f.half_length - f.penalty_area_length and abs(y) < f.penalty_area_width / 2.0:
            x = own * (f.half_length - f.penalty_area_length)
            y = math.copysign(f.penalty_area_width / 2.0, y)
        modes.events.add(state.cycle, EventKind.FOUL, team, row - team * modes.n,
                         float(state.pos[row, 0]), float(state.pos[row, 1]), 0)
        if state.ball_holder != NO_PLAYER:
            state.ball_holder = NO_PLAYER
        modes.restart(state, PlayMode.FREE_KICK, fouled, x, y)

    def _yellow_card(self, state: WorldState, row: int, at: tuple[float, float]) -> None:
        """YELLOW_CARD event at ``at``; a second one is a red card."""
        if state.cards[row] >= 1:
            self._red_card(state, row, at)
            return
        state.cards[row] = 1
        self._card_event(row, EventKind.YELLOW_CARD, 1, state.cycle, at)

    def _red_card(self, state: WorldState, row: int, at: tuple[float, float]) -> None:
        """RED_CARD event at ``at``; the player is sent off and parked."""
        state.cards[row] = 2
        self._card_event(row, EventKind.RED_CARD, 2, state.cycle, at)
        state.present[row] = False
        state.frozen[row] = 0
        if state.ball_holder == row:
            state.ball_holder = NO_PLAYER
        park_absent(state, self.modes.n, self.modes.config.field)

    def _card_event(self, row: int, kind: EventKind, cards: int, cycle: int, at: tuple[float, float]) -> None:
        n = self.modes.n
        team = HOME if row < n else AWAY
        self.modes.events.add(cycle, kind, team, row - team * n, at[0], at[1], cards)
