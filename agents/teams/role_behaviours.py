"""Role behaviours: each position moves its formation target its own way in open play.

The formation gives every role a target that slides with the ball; on top of it, applied to
the role targets every play-on cycle before the roles are assigned (so every assigner sees
the same targets), each position (:mod:`agents.teams.positions`) does its job. Team frame,
metres: we attack +x, our goal at ``x = -half_length``; "attacking" is the formation's attack
situation (we win the race for the ball), "defending" its defend situation.

* **Centre-backs** hold the line ``back_line_gap`` behind every other outfield role and never
  beyond ``back_line_limit`` (they are the rest defence when we attack); when defending each marks the opponent nearest its target
  (within ``mark_radius``, a different one each), standing ``mark_distance`` goal-side of it
  (a marker follows its forward rather than the line).
* **Full-backs** overlap when we attack on their side of the field (``overlap_push`` further
  up, at least ``overlap_width`` wide), always 2 m inside the wide attackers' width when we
  attack, and tuck in when defending (their y scaled by
  ``tuck_in``).
* **The holding midfielder** screens: when defending it stands on the line from our goal to
  the ball, ``screen_gap`` in front of the centre-backs; when attacking it stays
  ``hold_behind`` behind the ball (but ``back_line_gap`` in front of the centre-backs).
* **Central midfielders** support the ball when we attack: one farther than
  ``support_distance`` from the ball comes to that distance, along the line to the ball.
* **Wingers** run in behind when we attack: up to the offside line (``behind_line`` short of
  it) and at least ``winger_width`` wide, the widest players (in the final third the far-side
  winger keeps its narrowed target, to attack the far post). **Wide midfielders** give width
  (``wide_midfielder_width``) but keep their depth.
* **The centre-forward** stays high: up at the offside line when attacking, never deeper than
  ``forward_floor`` when defending (an outlet for the clearance).

The work is one compiled kernel over the roles (:func:`adjust_role_targets`), a couple of
microseconds per cycle.
"""

from __future__ import annotations

import math
from dataclasses import astuple, dataclass, fields

import numpy as np
from numba import njit

from soccer_sim.kernels import make_record
from soccer_sim.rules.offside import offside_line
from agents.teams import positions
from formations import FormationSet

_CB = positions.POSITIONS.index(positions.CENTRE_BACK)
_FB = positions.POSITIONS.index(positions.FULL_BACK)
_HM = positions.POSITIONS.index(positions.HOLDING_MIDFIELDER)
_CM = positions.POSITIONS.index(positions.CENTRAL_MIDFIELDER)
_WM = positions.POSITIONS.index(positions.WIDE_MIDFIELDER)
_WG = positions.POSITIONS.index(positions.WINGER)
_CF = positions.POSITIONS.index(positions.CENTRE_FORWARD)
_GK = positions.POSITIONS.index(positions.GOALKEEPER)


@dataclass(frozen=True)
class RoleParams:
    """How far each position's behaviour moves its target (metres; widths are shares of the
    field's half width)."""

    mark_radius: float = 12.0
    """A defending centre-back marks only an opponent this close to its formation target: a
    back line spans about 30 m, so each centre-back watches its own third of it."""
    mark_distance: float = 2.0
    """The marker stands this far from its opponent towards our goal: near enough to reach a
    pass to it first (a player covers about 1 m a cycle), far enough not to be turned."""
    back_line_gap: float = 2.0
    """Centre-backs stay this far behind the deepest other outfield target: the last line."""
    overlap_push: float = 10.0
    """A full-back overlapping on the ball's side moves this far up (beyond a winger's start)."""
    overlap_width: float = 0.7
    """... and at least this wide (share of the half width; under the winger's, who stays widest)."""
    side_margin: float = 4.0
    """The ball is on a player's side when its y is beyond this on the player's side of the axis."""
    tuck_in: float = 0.75
    """Defending full-backs' y is scaled by this: a narrower back four closes the middle."""
    screen_gap: float = 6.0
    """The holding midfielder screens this far in front of the centre-backs' mean x."""
    hold_behind: float = 8.0
    """When we attack the holding midfielder stays at least this far behind the ball (rest defence)."""
    support_distance: float = 15.0
    """Central midfielders come within this distance of the ball when we attack: a short pass."""
    winger_width: float = 0.85
    """Attacking wingers stand at least this wide (share of the half width), the widest players."""
    wide_midfielder_width: float = 0.78
    """Attacking wide midfielders stand at least this wide (share of the half width)."""
    behind_line: float = 1.0
    """Wingers and centre-forwards run up to this far behind the offside line."""
    forward_floor: float = -3.0
    """A defending centre-forward's target never goes deeper than this x: it waits near the
    halfway line for the clearance instead of crowding our box."""
    back_line_limit: float = 0.0
    """Centre-backs' targets never go beyond this x in open play: they stay at the halfway
    line as the rest defence against a counter (and do not run the length of the field at
    every change of possession)."""

    def __post_init__(self) -> None:
        for name, value in zip(self.__dataclass_fields__, astuple(self)):
            if not np.isfinite(value):
                raise ValueError(f"RoleParams.{name} must be a finite number, not {value!r}")
        for name in ("mark_radius", "mark_distance", "back_line_gap", "overlap_push", "side_margin",
                     "screen_gap", "hold_behind", "support_distance", "behind_line"):
            if getattr(self, name) < 0.0:
                raise ValueError(f"RoleParams.{name} must be >= 0 m, not {getattr(self, name)!r}")
        for name in ("overlap_width", "tuck_in", "winger_width", "wide_midfielder_width"):
            if not 0.0 <= getattr(self, name) <= 1.0:
                raise ValueError(f"RoleParams.{name} must lie in [0, 1], not {getattr(self, name)!r}")


ROLE_PARAMS = np.dtype([(field.name, np.float64) for field in fields(RoleParams)]
                       + [("half_length", np.float64), ("half_width", np.float64)])
"""The record :func:`adjust_role_targets` reads: :class:`RoleParams`' fields (which document
them) and the field's half length and half width (m)."""


class RoleBehaviours:
    """The role behaviours of one team for one match: ``adjust`` moves the role targets."""

    def __init__(self, formation_set: FormationSet, half_length: float, half_width: float,
                 params: RoleParams | None = None) -> None:
        self.params = params or RoleParams()
        self.codes = positions.position_codes(formation_set)
        """Each role's position code (index into :data:`agents.teams.positions.POSITIONS`)."""
        p = self.params
        self.record = make_record(ROLE_PARAMS, half_length=half_length, half_width=half_width,
                                  **{field.name: getattr(p, field.name) for field in fields(p)})
        """The parameters and the field's half length and half width as one :data:`ROLE_PARAMS`
        record, as :func:`adjust_role_targets` reads them."""

    def adjust(self, targets: np.ndarray, attacking: bool, ball: np.ndarray, opp_pos: np.ndarray) -> None:
        """Move ``targets`` ((roles, 2), team frame, in place) by each role's behaviour for the
        ball at ``ball`` (where it will be controlled) and the opponents at ``opp_pos``."""
        adjust_role_targets(targets, self.codes, opp_pos, np.ascontiguousarray(opp_pos[:, 0]), float(ball[0]),
                            float(ball[1]), attacking, self.record)


@njit(cache=True, nogil=True)
def adjust_role_targets(targets: np.ndarray, codes: np.ndarray, opp_pos: np.ndarray, line_x: np.ndarray,
                        ball_x: float, ball_y: float, attacking: bool,
                        params: np.ndarray) -> None:  # pragma: no cover - compiled
    """The behaviours of the module docstring, in place; ``line_x`` (m,): the opponents' x the
    offside line is drawn from (their x as believed, or as far up as they may have stepped
    since seen); ``params``: a :data:`ROLE_PARAMS` record."""
    p = params[0]
    mark_radius, mark_distance, back_line_gap = p.mark_radius, p.mark_distance, p.back_line_gap
    overlap_push, overlap_width, side_margin, tuck_in = p.overlap_push, p.overlap_width, p.side_margin, p.tuck_in
    screen_gap, hold_behind, support_distance = p.screen_gap, p.hold_behind, p.support_distance
    winger_width, wide_mid_width, behind_line = p.winger_width, p.wide_midfielder_width, p.behind_line
    forward_floor, back_line_limit = p.forward_floor, p.back_line_limit
    half_length, half_width = p.half_length, p.half_width
    n = targets.shape[0]
    line = offside_line(line_x, ball_x) - behind_line
    final_third = ball_x > half_length / 3.0
    # Attacking full-backs stay inside the narrowest wide attacker (who keep the touchline).
    wide_floor = 1.0
    for r in range(n):
        if codes[r] == _WG:
            wide_floor = min(wide_floor, winger_width)
        elif codes[r] == _WM:
            wide_floor = min(wide_floor, wide_mid_width)
    fb_cap = wide_floor * half_width - 2.0
    for r in range(n):
        c = codes[r]
        x, y = targets[r, 0], targets[r, 1]
        side = 1.0 if y >= 0.0 else -1.0
        ball_side = ball_y * side > side_margin
        if c == _FB:
            if attacking:
                if ball_side:
                    x += overlap_push
                    y = side * max(abs(y), overlap_width * half_width)
                y = side * min(abs(y), fb_cap)
            else:
                y *= tuck_in
        elif c == _WG:
            if attacking:
                x = max(x, line)
                if ball_side or not final_third:
                    y = side * max(abs(y), winger_width * half_width)
        elif c == _WM:
            if attacking:
                y = side * max(abs(y), wide_mid_width * half_width)
        elif c == _CF:
            x = max(x, line) if attacking else max(x, forward_floor)
        elif c == _CM:
            if attacking:
                dx, dy = x - ball_x, y - ball_y
                d = math.hypot(dx, dy)
                if d > support_distance:
                    x = ball_x + dx * support_distance / d
                    y = ball_y + dy * support_distance / d
        targets[r, 0], targets[r, 1] = x, y
    # Centre-backs: mark when defending, then hold the last line.
    marking = np.zeros(n, dtype=np.bool_)
    if not attacking:
        used = np.zeros(opp_pos.shape[0], dtype=np.bool_)
        for r in range(n):
            if codes[r] != _CB:
                continue
            best, best_d = -1, mark_radius
            for j in range(opp_pos.shape[0]):
                if not used[j]:
                    d = math.hypot(opp_pos[j, 0] - targets[r, 0], opp_pos[j, 1] - targets[r, 1])
                    if d < best_d:
                        best, best_d = j, d
            if best >= 0:
                used[best] = True
                marking[r] = True
                ox, oy = opp_pos[best, 0], opp_pos[best, 1]
                gx, gy = -half_length - ox, -oy
                g = max(math.hypot(gx, gy), 1e-9)
                targets[r, 0] = ox + gx * mark_distance / g
                targets[r, 1] = oy + gy * mark_distance / g
    others = np.inf
    for r in range(n):
        if codes[r] != _CB and codes[r] != _GK:
            others = min(others, targets[r, 0])
    cb_sum, cb_count = 0.0, 0
    for r in range(n):
        if codes[r] == _CB:
            if others < np.inf and not marking[r]:  # (a marker stays goal-side of its forward)
                targets[r, 0] = min(targets[r, 0], others - back_line_gap, back_line_limit)
            cb_sum += targets[r, 0]
            cb_count += 1
    cb_x = cb_sum / cb_count if cb_count else (others if others < np.inf else -half_length / 2.0)
    # The holding midfielder: screen the way to our goal, or stay behind the ball.
    for r in range(n):
        if codes[r] != _HM:
            continue
        if attacking:
            targets[r, 0] = max(min(targets[r, 0], ball_x - hold_behind), cb_x + back_line_gap)
        else:
            x = min(cb_x + screen_gap, ball_x - 1.0)
            run = ball_x + half_length
            targets[r, 0] = x
            targets[r, 1] = ball_y * (x + half_length) / run if run > 1.0 else 0.0
    x_limit, y_limit = half_length - 2.0, half_width - 1.5
    for r in range(n):
        if codes[r] != _GK:
            targets[r, 0] = min(max(targets[r, 0], -x_limit), x_limit)
            targets[r, 1] = min(max(targets[r, 1], -y_limit), y_limit)
