"""Where the built-in team's players look under partial observation: each player's neck turn
(``TeamCommand.turn_neck``) from its own belief row, the way helios-base's players choose it.

rcssserver's players see only within their view cone, centred on the face (body direction
plus neck angle, :mod:`soccer_sim.perception.neck`). A player that never turns its neck looks
along its body, which in the simulator faces the ball (:mod:`soccer_sim.body`): it sees the
ball on nearly every see, and the players beside and behind it only when they are close or a
team-mate tells of them. helios-base's players instead turn their neck every cycle: at the
ball when what they know of it is old, otherwise over the field where they have not looked for
longest (its ``Neck_TurnToBallOrScan`` and ``Neck_ScanField``). :class:`Looker` makes the same
choice, per player, from that player's row alone:

1. **The ball**, when the player's belief of it is stale (older than
   :attr:`LookParams.fresh_cycles`) or the ball is near (within
   :attr:`LookParams.watch_distance`: a ball the player may soon have to play or chase), and
   a neck within its range can bring it into the cone; not when the ball lies so close that
   the player senses it anyway (within ``visible_distance``, where rcssserver shows the ball
   whatever the direction).
2. Otherwise **the field it has seen least recently**: the player keeps, per direction sector
   of :attr:`LookParams.sector` degrees (team frame), the cycles since the sector was last in
   its view cone; of the neck angles within the server's range (in steps of one sector), it
   takes the one whose cone covers the oldest sectors in sum -- the team-mates and opponents
   its positioning, passing and role votes read, where they may have moved unseen --,
   leaving out a face whose point :attr:`LookParams.ahead` metres away lies off the pitch
   (the stands hold nothing to see) unless every choice does. Ties go to the smallest turn.

The next cycle's body direction is taken to be this cycle's (the simulator's body model turns
it towards the ball as the player moves, so it changes little between cycles). Angles in
degrees, team frame; distances in metres.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.perception.views import PlayerViews

AGE_CAP = 1000
"""The largest sector age kept (cycles): beyond it a sector counts as never seen."""


@dataclass(frozen=True)
class LookParams:
    """How the built-in team's players choose where to look (module docstring)."""

    fresh_cycles: int = 0
    """A ball belief older than this (cycles since it was seen, by the player or the team-mate
    who told it) is stale, and the player looks at the ball (helios-base's
    ``Neck_TurnToBallOrScan`` count threshold, 0 by default there too)."""
    watch_distance: float = 15.0
    """A player whose believed ball lies within this (m) keeps looking at it (it may have to
    intercept, tackle or receive soon)."""
    sensed_margin: float = 0.5
    """A ball believed within ``visible_distance`` less this (m) is sensed whatever the face's
    direction, so the player scans instead."""
    sector: float = 10.0
    """Width of the direction sectors whose ages a player keeps, and the step between the neck
    angles it chooses from (degrees)."""
    cone_margin: float = 5.0
    """Degrees left off each side of the view cone when counting what a face covers (the body
    turns a little before the next see)."""
    ahead: float = 20.0
    """A face counts as off the pitch when the point this far ahead (m) ..."""
    pitch_margin: float = 3.0
    """... lies more than this (m) outside the field's lines."""

    def __post_init__(self) -> None:
        if not (isinstance(self.fresh_cycles, int) and not isinstance(self.fresh_cycles, bool)
                and self.fresh_cycles >= 0):
            raise ValueError(f"LookParams.fresh_cycles must be an integer >= 0, got {self.fresh_cycles!r}")
        for name in ("watch_distance", "sensed_margin", "cone_margin", "ahead", "pitch_margin"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and np.isfinite(value) and value >= 0.0):
                raise ValueError(f"LookParams.{name} must be a finite number >= 0, got {value!r}")
        if not (isinstance(self.sector, (int, float)) and 0.0 < self.sector <= 90.0 and 360.0 % self.sector == 0.0):
            raise ValueError(f"LookParams.sector must divide 360 and lie in (0, 90] degrees, got {self.sector!r}")


def _wrap(angles: np.ndarray) -> np.ndarray:
    """Angles (degrees) folded into [-180, 180)."""
    return (angles + 180.0) % 360.0 - 180.0


class Looker:
    """The neck turns of one team's ``n`` players, cycle by cycle (module docstring), for a
    match of ``config`` (its see model: view cone, ``visible_distance``, neck limits; its
    field)."""

    def __init__(self, params: LookParams, n: int, config: MatchConfig) -> None:
        see = config.observation.see
        self.params = params
        self.half_angle = see.visible_angle / 2.0
        """Half the view cone (degrees)."""
        self.sensed_distance = max(see.visible_distance - params.sensed_margin, 0.0)
        self.neck_range = (see.min_neck_angle, see.max_neck_angle)
        """The neck's limits (degrees; ``minneckang``, ``maxneckang``)."""
        self.centres = np.arange(-180.0 + params.sector / 2.0, 180.0, params.sector)
        """(S,) the direction sectors' centres (degrees, team frame)."""
        low, high = self.neck_range
        self.candidates = np.unique(np.clip(np.append(np.arange(low, high, params.sector), high), low, high))
        """(C,) the neck angles a scan chooses from (degrees)."""
        self.sector_age = np.full((n, len(self.centres)), AGE_CAP, dtype=np.int64)
        """(n, S) per player, the cycles since each sector was last in its view cone."""
        self.limits = (config.field.length / 2.0 + params.pitch_margin, config.field.width / 2.0 + params.pitch_margin)
        """The half length and half width (m) a face's point ahead must stay within."""

    def turn_necks(self, views: PlayerViews, ball: np.ndarray, ball_age: np.ndarray) -> np.ndarray:
        """This cycle's ``turn_neck`` (n,) degrees (NaN for players off the pitch or whose body
        direction is not known), row ``i``
        from player ``i``'s own row only: its senses in ``views`` (position, body direction,
        neck angle, whether a see arrived), its believed ``ball`` (n, 2) m and that belief's age
        ``ball_age`` (n,) cycles. Updates each player's sector ages from its see first."""
        params = self.params
        body, neck = views.body_direction, views.neck_angle
        self._age_sectors(body + neck, views.saw)
        position = views.position
        offset = ball - position
        distance = np.hypot(offset[:, 0], offset[:, 1])
        to_ball = np.degrees(np.arctan2(offset[:, 1], offset[:, 0]))
        relative = _wrap(to_ball - body)
        low, high = self.neck_range
        reach = self.half_angle - params.cone_margin  # the ball in the cone of a face within the neck's range
        reachable = (relative >= low - reach) & (relative <= high + reach)
        wanted = (ball_age > params.fresh_cycles) | (distance < params.watch_distance)
        at_ball = reachable & wanted & ~(distance < self.sensed_distance) & np.isfinite(distance)
        target = np.where(at_ball, np.clip(relative, low, high), self._scan(body, neck, position))
        turns = target - neck
        turns[~(views.present & np.isfinite(body) & np.isfinite(neck))] = np.nan  # (a body not known yet: no turn)
        return turns

    def _age_sectors(self, face: np.ndarray, saw: np.ndarray) -> None:
        """Every sector one cycle older; those in the cone of a player's see this cycle (its
        face ``face`` (n,) degrees) seen now."""
        np.minimum(self.sector_age + 1, AGE_CAP, out=self.sector_age)
        covered = np.abs(_wrap(self.centres[None, :] - face[:, None])) < self.half_angle
        covered &= saw[:, None]
        self.sector_age[covered] = 0

    def _scan(self, body: np.ndarray, neck: np.ndarray, position: np.ndarray) -> np.ndarray:
        """Each player's neck angle (n,) for a scan: the candidate whose cone covers the oldest
        sectors, faces on the pitch first, the smallest turn on a tie (module docstring)."""
        params = self.params
        faces = body[:, None] + self.candidates[None, :]  # (n, C)
        inside = np.abs(_wrap(self.centres[None, None, :] - faces[:, :, None])) < self.half_angle - params.cone_margin
        score = (inside * self.sector_age[:, None, :]).sum(axis=2).astype(np.float64)  # (n, C)
        radians = np.radians(faces)
        ahead_x = position[:, 0:1] + params.ahead * np.cos(radians)
        ahead_y = position[:, 1:2] + params.ahead * np.sin(radians)
        on_pitch = (np.abs(ahead_x) <= self.limits[0]) & (np.abs(ahead_y) <= self.limits[1])
        on_pitch |= ~on_pitch.any(axis=1, keepdims=True)  # every face off the pitch: judge them all
        turn = np.abs(self.candidates[None, :] - neck[:, None])
        ranked = np.where(on_pitch, score - turn / 1000.0, -np.inf)  # (a turn < 1000 degrees breaks ties only)
        return self.candidates[np.argmax(ranked, axis=1)]
