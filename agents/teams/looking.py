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
degrees, team frame; distances in metres. The per-cycle work is one compiled call
(:func:`neck_turns`: a scan weighs 19 neck angles, each against the 8 or 9 sectors its cone
covers; 30-85 µs a cycle for a team of 1-11 players on a busy 2-core machine, about 0.5 s of
a 6000-cycle match).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from numba import njit

from soccer_sim.config import MatchConfig
from soccer_sim.kernels import make_record
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
    """Degrees left off each side of the view cone when counting what a face covers and
    whether it can hold the ball (the body turns a little before the next see)."""
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
            if isinstance(value, bool) or not (isinstance(value, (int, float)) and math.isfinite(value) and value >= 0):
                raise ValueError(f"LookParams.{name} must be a finite number >= 0, got {value!r}")
        if isinstance(self.sector, bool) or not (isinstance(self.sector, (int, float)) and 0.0 < self.sector <= 90.0
                                                 and 360.0 % self.sector == 0.0):
            raise ValueError(f"LookParams.sector must divide 360 and lie in (0, 90] degrees, got {self.sector!r}")


LOOK_RECORD = np.dtype([(name, np.float64) for name in (
    "fresh_cycles", "watch_distance", "sensed_distance", "half_angle", "cone_half", "min_neck", "max_neck", "ahead",
    "x_limit", "y_limit")])
"""The constants :func:`neck_turns` reads, by name: :class:`LookParams`' with the match's see
model (``half_angle``: half the view cone; ``cone_half``: it less ``cone_margin``;
``sensed_distance``: ``visible_distance`` less ``sensed_margin``; the neck's limits) and field
(``x_limit``, ``y_limit``: the half length and width plus ``pitch_margin``)."""


class LookSenses(NamedTuple):
    """What each of a team's players senses of itself this cycle (n,...), team frame: body
    direction and neck angle (degrees), whether a see arrived, whether it is on the pitch, its
    believed position (m)."""

    body: np.ndarray
    neck: np.ndarray
    saw: np.ndarray
    present: np.ndarray
    position: np.ndarray


@njit(cache=True, nogil=True)
def _wrap(angle: float) -> float:  # pragma: no cover - compiled
    """``angle`` (degrees) folded into [-180, 180)."""
    return (angle + 180.0) % 360.0 - 180.0


@njit(cache=True, nogil=True)
def _cone_sectors(face: float, half: float, centres: np.ndarray) -> tuple[int, int]:  # pragma: no cover
    """The sectors whose centres lie less than ``half`` degrees from ``face`` (degrees): the
    indices ``k0 .. k1`` (both included; k1 < k0 for none), to be taken modulo the number of
    sectors (``centres`` (S,), evenly spaced, ascending from -180 + a half sector)."""
    width = centres[1] - centres[0] if centres.shape[0] > 1 else 360.0
    low = (face - half - centres[0]) / width
    high = (face + half - centres[0]) / width
    return int(math.floor(low)) + 1, int(math.ceil(high)) - 1


@njit(cache=True, nogil=True)
def _covered_age(ages: np.ndarray, centres: np.ndarray, face: float, half: float) -> float:  # pragma: no cover
    """The sum of the sector ``ages`` whose centres lie less than ``half`` degrees from ``face``."""
    k0, k1 = _cone_sectors(face, half, centres)
    total = 0.0
    for k in range(k0, k1 + 1):
        total += ages[k % centres.shape[0]]
    return total


@njit(cache=True, nogil=True)
def _scan_neck(i: int, senses: LookSenses, ages: np.ndarray, centres: np.ndarray, candidates: np.ndarray,
               prm: np.ndarray) -> float:  # pragma: no cover - compiled
    """Player ``i``'s neck angle for a scan: the candidate whose cone covers the oldest
    sectors, faces on the pitch first, the smallest turn on a tie (module docstring)."""
    body, neck = senses.body[i], senses.neck[i]
    px, py = senses.position[i, 0], senses.position[i, 1]
    best, best_any = -math.inf, -math.inf
    chosen, chosen_any = candidates[0], candidates[0]
    for c in range(candidates.shape[0]):
        face = body + candidates[c]
        ranked = _covered_age(ages, centres, face, prm[0].cone_half) - abs(candidates[c] - neck) / 1000.0
        if ranked > best_any:  # (a turn < 1000 degrees breaks ties only)
            best_any, chosen_any = ranked, candidates[c]
        a = math.radians(face)
        on_pitch = abs(px + prm[0].ahead * math.cos(a)) <= prm[0].x_limit and \
            abs(py + prm[0].ahead * math.sin(a)) <= prm[0].y_limit
        if on_pitch and ranked > best:
            best, chosen = ranked, candidates[c]
    return chosen if best > -math.inf else chosen_any


@njit(cache=True, nogil=True)
def neck_turns(senses: LookSenses, ball: np.ndarray, ball_age: np.ndarray, sector_age: np.ndarray,
               centres: np.ndarray, candidates: np.ndarray, prm: np.ndarray,
               out: np.ndarray) -> None:  # pragma: no cover - compiled
    """Each player's ``turn_neck`` (degrees) into ``out`` (n,), row ``i`` from row ``i`` alone
    (module docstring): first its sector ages (``sector_age`` (n, S), one cycle older; the
    sectors centred at ``centres`` (S,) within the cone of this cycle's see, if one arrived,
    seen now), then the ball (believed at ``ball`` (n, 2), ``ball_age`` (n,) cycles old) or a
    scan over the neck angles ``candidates`` (C,). NaN for a player off the pitch or whose body
    direction or neck is not known. ``prm``: a :data:`LOOK_RECORD`."""
    low, high = prm[0].min_neck, prm[0].max_neck
    reach = prm[0].cone_half  # the ball in the cone of a face within the neck's range
    for i in range(out.shape[0]):
        body, neck = senses.body[i], senses.neck[i]
        face = body + neck
        known = math.isfinite(face)
        for s in range(centres.shape[0]):
            if sector_age[i, s] < AGE_CAP:
                sector_age[i, s] += 1
        if senses.saw[i] and known:
            k0, k1 = _cone_sectors(face, prm[0].half_angle, centres)
            for k in range(k0, k1 + 1):
                sector_age[i, k % centres.shape[0]] = 0
        if not (senses.present[i] and known):
            out[i] = np.nan
            continue
        dx, dy = ball[i, 0] - senses.position[i, 0], ball[i, 1] - senses.position[i, 1]
        distance = math.hypot(dx, dy)
        relative = _wrap(math.degrees(math.atan2(dy, dx)) - body)
        wanted = ball_age[i] > prm[0].fresh_cycles or distance < prm[0].watch_distance
        if math.isfinite(distance) and wanted and not distance < prm[0].sensed_distance and \
                low - reach <= relative <= high + reach:
            target = min(max(relative, low), high)
        else:
            target = _scan_neck(i, senses, sector_age[i], centres, candidates, prm)
        out[i] = target - neck


class Looker:
    """The neck turns of one team's ``n`` players, cycle by cycle (module docstring), for a
    match of ``config`` (its see model: view cone, ``visible_distance``, neck limits; its
    field)."""

    def __init__(self, params: LookParams, n: int, config: MatchConfig) -> None:
        see, field = config.observation.see, config.field
        self.params = params
        low, high = see.min_neck_angle, see.max_neck_angle
        self.record = make_record(
            LOOK_RECORD, fresh_cycles=params.fresh_cycles, watch_distance=params.watch_distance,
            sensed_distance=max(see.visible_distance - params.sensed_margin, 0.0), half_angle=see.visible_angle / 2.0,
            cone_half=see.visible_angle / 2.0 - params.cone_margin, min_neck=low, max_neck=high, ahead=params.ahead,
            x_limit=field.length / 2.0 + params.pitch_margin, y_limit=field.width / 2.0 + params.pitch_margin)
        """The kernel's constants (:data:`LOOK_RECORD`)."""
        self.centres = np.arange(-180.0 + params.sector / 2.0, 180.0, params.sector)
        """(S,) the direction sectors' centres (degrees, team frame)."""
        self.candidates = np.unique(np.clip(np.append(np.arange(low, high, params.sector), high), low, high))
        """(C,) the neck angles a scan chooses from (degrees)."""
        self.sector_age = np.full((n, len(self.centres)), AGE_CAP, dtype=np.int64)
        """(n, S) per player, the cycles since each sector was last in its view cone."""
        self._turns = np.empty(n)

    def turn_necks(self, views: PlayerViews, ball: np.ndarray, ball_age: np.ndarray) -> np.ndarray:
        """This cycle's ``turn_neck`` (n,) degrees (NaN for players off the pitch or whose body
        direction is not known), row ``i`` from player ``i``'s own row only: its senses in
        ``views`` (position, body direction, neck angle, whether a see arrived), its believed
        ``ball`` (n, 2) m and that belief's age ``ball_age`` (n,) cycles (:func:`neck_turns`).
        The array is the looker's, overwritten next cycle."""
        senses = LookSenses(np.ascontiguousarray(views.body_direction, dtype=np.float64),
                            np.ascontiguousarray(views.neck_angle, dtype=np.float64),
                            np.ascontiguousarray(views.saw, dtype=np.bool_),
                            np.ascontiguousarray(views.present, dtype=np.bool_),
                            np.ascontiguousarray(views.position, dtype=np.float64))
        neck_turns(senses, np.ascontiguousarray(ball, dtype=np.float64),
                   np.ascontiguousarray(ball_age, dtype=np.int64), self.sector_age, self.centres, self.candidates,
                   self.record, self._turns)
        return self._turns
