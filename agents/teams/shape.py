"""The built-in team's shape in open play: one block that moves at a running pace, with a rest
defence, support around the ball and follow-ups of shots. :class:`ShapeParams` are its
numbers, :class:`Shape` the constants the pipeline's compiled steps read
(:func:`~agents.teams.pipeline_kernels.derive_worlds` runs them per belief; the follow-ups
are :func:`agents.teams.decisions.follow_up_goals`).

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

from agents.teams.shape_kernels import SHAPE_PARAMS, SUPPORT_PARAMS
from soccer_sim.kernels import make_record

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
                     "follow_up_players", "follow_up_cycles", "support_horizon",
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
    """The team's shape for one match (see the module docstring): the constants the pipeline's
    compiled steps read (:mod:`agents.teams.pipeline_kernels`); each belief's switch, block and
    settled targets live in the pipeline.

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
        angles = np.arange(params.support_directions) * (2.0 * math.pi / max(params.support_directions, 1))
        unit = np.stack([np.cos(angles), np.sin(angles)], axis=1)
        unit = unit[unit[:, 0] >= BACKWARD_LIMIT]  # support level with or ahead of the ball, or a little behind
        self.offsets = np.concatenate([unit * radius for radius in params.support_radii])
        """The support spots relative to the carrier, (S, 2)."""
        self._settle_record = make_record(
            SHAPE_PARAMS, rest_ball_gap=params.rest_ball_gap, rest_forward_margin=params.rest_forward_margin,
            rest_max_gap=params.rest_max_gap, defend_ball_gap=params.defend_ball_gap,
            back_floor=-half_length + BACK_LINE_FLOOR, push=params.push_speed, drop=params.drop_speed)
        """The numbers :func:`~agents.teams.shape_kernels.advance_block` and :func:`~agents.teams.shape_kernels.settle_targets` read."""
        self._support_record = make_record(
            SUPPORT_PARAMS, x_limit=half_length - 3.0, y_limit=half_width - 2.0, lane_cap=params.lane_cap,
            space_cap=params.space_cap, forward_weight=params.forward_weight, travel_weight=params.travel_weight,
            crowd_distance=params.crowd_distance)
        """The numbers :func:`~agents.teams.shape_kernels.support_spots` reads."""

    @property
    def settle_record(self) -> np.ndarray:
        """A copy of the block's and the back line's numbers as the compiled kernels read them
        (a :data:`~agents.teams.shape_kernels.SHAPE_PARAMS` record: :func:`advance_block`,
        :func:`settle_targets`)."""
        return self._settle_record.copy()

    @property
    def support_record(self) -> np.ndarray:
        """A copy of the support spots' numbers as the compiled kernels read them (a
        :data:`~agents.teams.shape_kernels.SUPPORT_PARAMS` record: :func:`support_spots`)."""
        return self._support_record.copy()
