"""The built-in team's shape in open play: :class:`Shape` keeps the team one block that moves
at a running pace, with a rest defence, support around the ball and follow-ups of shots.

Team frame: we attack +x, our goal at x = -half_length; units m, m/cycle, cycles.

* **Attack or defend, with hysteresis.** The ball race says every cycle who gets to the ball
  first, and that flips back and forth whenever two players race for a loose ball. The team
  switches between attacking and defending only when the race is won by a clear margin
  (``switch_margin`` cycles) or when the other side has been winning it for
  ``switch_persist`` cycles.
* **A block that runs, not jumps.** The point the formation is queried at (where the ball
  will be controlled) and the block's shift up the field (``TeamStyle.depth``, plus
  ``attack_push`` when attacking) move at most ``push_speed`` per cycle forwards and
  ``drop_speed`` per cycle backwards, and so does every role target (so that a change of
  formation when possession changes is run, not jumped).
* **Rest defence.** When attacking, the back line (the formation's defenders) stays
  ``rest_ball_gap`` goal-side of the ball and ``rest_forward_margin`` goal-side of the
  opponents' most advanced player, but no more than ``rest_max_gap`` behind the ball; when
  defending, it stays ``defend_ball_gap`` goal-side of the ball.
* **Support.** When attacking and an opponent can get to the ball within
  ``support_pressure`` cycles, the targets of the ``support_players`` roles nearest our ball
  carrier (not the forwards, who keep their places up front, nor the back line unless the ball
  is in our third, nor the carrier's own role) move to open spots ``support_radii`` from it,
  level with or ahead of it or a little behind, where the pass lane is far from the opponents,
  onside and not on another role's target. This happens before the roles are assigned: the
  role assigner decides who runs to a support spot, as it decides who goes anywhere else.
* **Follow-up.** For ``follow_up_cycles`` after our shot (until an opponent has the ball),
  the ``follow_up_players`` forwards nearest the goal run to the rebound area in front of it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from agents import skills
from soccer_sim.rules.offside import offside_line
from agents.teams.shape_kernels import (
    SHAPE_PARAMS, SUPPORT_PARAMS, advance_block, settle_targets, support_spots, switch_side)
from formations.formation_set import Situation
from soccer_sim.kernels import make_record
from soccer_sim.team import TeamView

__all__ = ["Shape", "ShapeParams"]

BACKWARD_LIMIT = -0.5
"""Support spots lie in directions from the carrier whose forward share (cosine) is at least
this: up to 120 degrees from straight ahead, so support helps the ball forward rather than
back."""
BACK_LINE_FLOOR = 6.0
"""The back line is never held deeper than this in front of our goal line (m): the goal
area's edge is as deep as it gets."""


@dataclass(frozen=True)
class ShapeParams:
    """How the team keeps its shape in open play (see the module docstring)."""

    switch_margin: int = 3
    """Cycles by which a side must win the ball race for the team to switch between attack
    and defence at once (a loose ball the two sides reach within this of each other does not
    flip the team)."""
    switch_persist: int = 5
    """Cycles the other side must keep winning the race for the team to switch anyway
    (half a second: long enough to ride out a ball bouncing between two players, short
    enough not to give away a counter-attack)."""
    push_speed: float = 0.7
    """Metres per cycle the formation's query point, the block's shift and every role target
    move forwards at most: a running pace a little above a player's sustainable speed (about
    0.6), so the players keep up with their targets and an attack still gets forwards."""
    drop_speed: float = 0.8
    """Metres per cycle they move backwards (or sideways) at most: a faster run than the push
    up, because a team that loses the ball gets back quicker than it pushes up."""
    rest_ball_gap: float = 12.0
    """When attacking, the back line stays at least this far behind the ball (m): far enough
    to meet a counter-attack, close enough to keep the team compact and in support."""
    rest_forward_margin: float = 2.0
    """When attacking, the back line stays this far goal-side of the opponents' most advanced
    player (m), so that a forward waiting for a long ball is not behind it."""
    rest_max_gap: float = 35.0
    """... but never more than this far behind the ball (m): a forward who stays deep in our
    half is left offside rather than stretching the team to 60 m."""
    defend_ball_gap: float = 2.0
    """When defending, the back line stays at least this far goal-side of the ball (m)."""
    support_players: int = 2
    """Roles whose targets move to open spots around our ball carrier."""
    support_radii: tuple[float, ...] = (9.0, 13.0)
    """Distances of the support spots from the carrier (m): a short pass, 8 to 15 m."""
    support_directions: int = 12
    """Directions of the support spots around the carrier (evenly spread; those more than 120
    degrees from straight ahead are left out)."""
    support_every: int = 4
    """Cycles a choice of support spots is kept (for the same carrier) before it is made
    again: the carrier moves a metre or two meanwhile, and choosing every cycle costs time."""
    support_pressure: int = 10
    """Support is sent only while an opponent can get to the ball within this many cycles: a
    pressed carrier needs a pass, a free one runs with the ball while the team keeps its shape
    (supporting every carrier slowed attacks down and cost goals)."""
    support_horizon: int = 8
    """Our carrier is the player who has or gets the ball within this many cycles."""
    lane_cap: float = 5.0
    """A pass lane at least this far (m) from every opponent counts as fully open."""
    space_cap: float = 10.0
    """A support spot at least this far (m) from every opponent counts as fully free."""
    forward_weight: float = 2.0
    """Score of a spot straight ahead of the carrier over one level with it (m of lane gap):
    support that helps the ball forward first."""
    travel_weight: float = 0.25
    """Score lost per metre from the supporting role's own target to the spot, so that a role
    takes a spot near its place and keeps it from cycle to cycle."""
    crowd_distance: float = 7.0
    """A spot this close (m) to another role's target or to a spot already taken is not used."""
    follow_up_players: int = 2
    """Forwards who run to the rebound area after our shot."""
    follow_up_cycles: int = 30
    """Cycles after our shot during which they do (a shot reaches the goal in about 10)."""
    rebound_depth: float = 7.0
    """The rebound spots are this far in front of the opponents' goal line (m)."""
    rebound_spread: float = 4.0
    """... and this far either side of the line from the shot to the goal's centre (m)."""

    def __post_init__(self) -> None:
        for name in ("switch_margin", "switch_persist", "support_players", "support_directions",
                     "follow_up_players", "follow_up_cycles", "support_horizon", "support_every",
                     "support_pressure"):
            value = getattr(self, name)
            if not isinstance(value, int) or isinstance(value, bool) or value < 0:
                raise ValueError(f"ShapeParams.{name} must be a non-negative integer, got {value!r}")
        for name in ("push_speed", "drop_speed"):
            if not getattr(self, name) > 0.0:
                raise ValueError(f"ShapeParams.{name} must be positive (m/cycle), got {getattr(self, name)!r}")
        if not self.support_radii or min(self.support_radii) <= 0.0:
            raise ValueError(f"ShapeParams.support_radii must be positive distances, got {self.support_radii!r}")


class Shape:
    """The team's shape state during one match (see the module docstring).

    ``kinds``: the formation's role kinds (row r of the targets is role r); ``depth`` and
    ``attack_push``: the style's shift of the outfield block (m) in open play and its extra
    when attacking; ``half_length``/``half_width`` of the field (m)."""

    def __init__(self, params: ShapeParams, kinds: list[str], depth: float, attack_push: float,
                 half_length: float, half_width: float) -> None:
        self.params = params
        self.depth = depth
        self.attack_push = attack_push
        self.half_length = half_length
        self.half_width = half_width
        self.back_roles = np.array([r for r, k in enumerate(kinds) if k == "defender"], dtype=np.int64)
        self.outfield_roles = np.array([r for r, k in enumerate(kinds) if k != "goalkeeper"], dtype=np.int64)
        self.is_back = np.array([k == "defender" for k in kinds])
        self.is_forward = np.array([k == "forward" for k in kinds])
        self.attacking = False
        """Whether the team attacks (the switch with hysteresis)."""
        self._pending = 0
        """Cycles the race has been won by the side we are not playing for."""
        self._block = np.zeros(3)
        """The formation's query point and the block's shift, moved at the block's pace."""
        self.query = self._block[:2]
        """Where the formation is queried (a view of ``_block``)."""
        self.ball_point = np.zeros(2)
        """Where the ball will be controlled (the race winner's interception point, else the
        ball), this cycle of play on: what the block's query point moves towards."""
        self.previous = np.zeros((len(kinds), 2))
        """Last cycle's role targets."""
        self._primed = False
        """Whether ``previous`` holds last cycle's targets (not on the team's first cycle)."""
        self._in_play = False
        """Whether the last cycle was play on (the rate limits start from the set play's shape)."""
        self.shot_cycle = -(1 << 30)
        """The cycle of our last shot."""
        self.shot_from = np.zeros(2)
        angles = np.arange(params.support_directions) * (2.0 * math.pi / max(params.support_directions, 1))
        unit = np.stack([np.cos(angles), np.sin(angles)], axis=1)
        unit = unit[unit[:, 0] >= BACKWARD_LIMIT]  # support level with or ahead of the ball, or a little behind
        self.offsets = np.concatenate([unit * radius for radius in params.support_radii])
        """The support spots relative to the carrier, (S, 2)."""
        self._settle_record = make_record(
            SHAPE_PARAMS, rest_ball_gap=params.rest_ball_gap, rest_forward_margin=params.rest_forward_margin,
            rest_max_gap=params.rest_max_gap, defend_ball_gap=params.defend_ball_gap,
            back_floor=-half_length + BACK_LINE_FLOOR, push=params.push_speed, drop=params.drop_speed)
        """The numbers :func:`advance_block` and :func:`settle_targets` read."""
        self._support_record = make_record(
            SUPPORT_PARAMS, x_limit=half_length - 3.0, y_limit=half_width - 2.0, lane_cap=params.lane_cap,
            space_cap=params.space_cap, forward_weight=params.forward_weight, travel_weight=params.travel_weight,
            crowd_distance=params.crowd_distance)
        """The numbers :func:`support_spots` reads."""
        self._held = 0
        """Cycles the current support spots are kept for yet."""
        self._carrier = -1
        """The carrier they were chosen for."""
        self._chosen, self._chosen_spots = _NONE, _NO_SPOTS
        """The supporters' rows and their spots."""
        self._rows = np.zeros(max(params.support_players, 1), dtype=np.int64)
        self._spots = np.zeros((max(params.support_players, 1), 2))

    def restart(self) -> None:
        """Start the block and the targets afresh next cycle (no pace limit from stale ones):
        for a brain that did not act last cycle."""
        self._in_play = False
        self._primed = False

    @property
    def settle_record(self) -> np.ndarray:
        """A copy of the block's and the back line's numbers as the compiled kernels read them
        (a :data:`~agents.teams.shape_kernels.SHAPE_PARAMS` record: :func:`advance_block`,
        :func:`settle_targets`), for positioning that runs them on its own."""
        return self._settle_record.copy()

    @property
    def support_record(self) -> np.ndarray:
        """A copy of the support spots' numbers as the compiled kernels read them (a
        :data:`~agents.teams.shape_kernels.SUPPORT_PARAMS` record: :func:`support_spots`)."""
        return self._support_record.copy()

    @property
    def shift(self) -> float:
        """The block's shift up the field (m, moved at the block's pace)."""
        return float(self._block[2])

    # ------------------------------------------------------------------ attack or defend
    def play_on(self, view: TeamView, race: skills.BallRace) -> tuple[Situation, np.ndarray]:
        """The formation situation (attack or defend, with hysteresis) and where to query it
        (the race winner's interception point, moved at the block's pace)."""
        p = self.params
        winning = race.lead > 0
        self.attacking, self._pending = switch_side(int(race.lead), self._in_play, self.attacking, self._pending,
                                                    p.switch_margin, p.switch_persist)
        ours, theirs = race
        if winning and ours.first >= 0:
            point = ours.points[ours.first]
        elif theirs.first >= 0:
            point = theirs.points[theirs.first]
        else:
            point = view.ball
        self.ball_point[:] = point
        block = self._block
        advance_block(block, point, self.depth + self.attack_push if self.attacking else self.depth,
                      self._in_play, self._settle_record)
        self._in_play = True
        return (Situation.ATTACK if self.attacking else Situation.DEFEND), self.query

    def settle(self, view: TeamView, targets: np.ndarray, play_on: bool) -> None:
        """The last changes to the role targets (in place): in play on the back line is held
        behind the ball (rest defence when attacking) and every target moves at most the
        block's pace from last cycle's (the first cycle of play from the set play's targets);
        otherwise the targets are only remembered."""
        settle_targets(targets, self.previous, self.outfield_roles, self.back_roles, view.opp_pos, self._settle_record,
                       float(view.ball[0]), bool(play_on), self.attacking, bool(play_on and self._primed))
        self._in_play = play_on
        self._primed = True

    # ------------------------------------------------------------------ support and follow-up
    def shot(self, cycle: int, ball: np.ndarray) -> None:
        """We shot this cycle from ``ball``: the forwards follow it up."""
        self.shot_cycle = cycle
        self.shot_from = np.array(ball, dtype=np.float64)

    def support(self, view: TeamView, race: skills.BallRace, ball_player: int, outfield: np.ndarray,
                match_roles: np.ndarray, role_of_player: np.ndarray | None, targets: np.ndarray) -> None:
        """Support as role targets (in place, before the roles are assigned): the targets of the
        ``support_players`` eligible roles nearest our ball carrier move to open spots around
        it, so the role assigner decides who runs there. ``outfield[i]`` held the formation role
        ``match_roles[role_of_player[i]]`` at the last assignment (None: no assignment yet, no
        support); ``ball_player`` is the row sent at the ball (-1: none)."""
        p = self.params
        # (the cheap tests first: this runs every cycle of play)
        if (not self.attacking or ball_player < 0 or role_of_player is None
                or race.theirs.first_cycle > p.support_pressure):
            self._held = 0
            return
        if self._held > 0 and ball_player == self._carrier:
            self._held -= 1  # the same carrier a cycle later: the same spots
            targets[self._chosen] = self._chosen_spots
            return
        if race.ours.cycles[ball_player] > p.support_horizon:
            self._held = 0
            return
        self._held, self._carrier = p.support_every - 1, ball_player
        self._chosen, self._chosen_spots = _NONE, _NO_SPOTS
        carrier = race.ours.points[ball_player]
        # The forwards keep their places up front, the back line is the rest defence (unless
        # the ball is in our third), and the carrier's own role is the carrier's.
        eligible = ~self.is_forward[match_roles]
        if carrier[0] > -self.half_length / 3.0:
            eligible &= ~self.is_back[match_roles]
        eligible[role_of_player[outfield == ball_player]] = False
        candidates = match_roles[eligible]
        if not candidates.size or p.support_players == 0:
            return
        x_max = offside_line(view.opp_pos[:, 0], float(view.ball[0])) - 1.0
        count = support_spots(carrier, targets, targets, candidates, view.opp_pos, self.offsets,
                              p.support_players, x_max, self._support_record, self._rows, self._spots)
        self._chosen, self._chosen_spots = self._rows[:count].copy(), self._spots[:count].copy()
        targets[self._chosen] = self._chosen_spots

    def follow_up(self, view: TeamView, race: skills.BallRace, ball_player: int, outfield: np.ndarray,
                  match_roles: np.ndarray, role_of_player: np.ndarray, goals: np.ndarray, urgent: np.ndarray) -> None:
        """Follow-up goals after our shot (in place; team frame): ``outfield[i]`` plays the
        formation role ``match_roles[role_of_player[i]]``."""
        if view.cycle - self.shot_cycle <= self.params.follow_up_cycles:
            self._follow_up(view, race, ball_player, outfield, match_roles[role_of_player], goals, urgent)

    def _follow_up(self, view: TeamView, race: skills.BallRace, ball_player: int, outfield: np.ndarray,
                   player_roles: np.ndarray, goals: np.ndarray, urgent: np.ndarray) -> np.ndarray:
        """After our shot the forwards nearest the rebound spots run there (whoever the race
        says wins the loose ball, until an opponent has it); returns their rows."""
        p = self.params
        if view.cycle - self.shot_cycle > p.follow_up_cycles or p.follow_up_players == 0:
            return _NONE
        if race.theirs.first_cycle == 0 and race.ours.first_cycle > 0:
            self.shot_cycle = -(1 << 30)  # an opponent has the ball: the follow-up is over
            return _NONE
        goal_x = self.half_length - p.rebound_depth
        # Spots either side of the shot's line to the goal, at the rebound depth.
        from_x, from_y = self.shot_from
        t = (goal_x - from_x) / (self.half_length - from_x) if self.half_length - from_x > 1e-9 else 1.0
        centre_y = from_y * (1.0 - min(max(t, 0.0), 1.0))
        spots = np.array([[goal_x, centre_y - p.rebound_spread], [goal_x, centre_y + p.rebound_spread]])
        mask = self.is_forward[player_roles] & (outfield != ball_player)
        rows = outfield[mask]
        if not rows.size:
            return _NONE
        gaps = np.hypot(view.own_pos[rows, 0] - goal_x, view.own_pos[rows, 1] - centre_y)
        rows = rows[np.argsort(gaps, kind="stable")[: min(p.follow_up_players, len(spots))]]
        for row in rows:
            k = int(np.argmin(np.hypot(*(spots - view.own_pos[row]).T)))
            goals[row] = spots[k]
            spots[k] = np.inf  # taken
            urgent[row] = True
        return rows


_NONE = np.zeros(0, dtype=np.int64)
_NO_SPOTS = np.zeros((0, 2))

