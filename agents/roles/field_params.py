"""The parameters of the supporters' potential field (:mod:`agents.roles.potential_field`).

:class:`FieldParams` is what a user sets (checked on construction); the compiled kernels read
the same numbers by name from a one-element structured array (:meth:`FieldParams.as_record`,
dtype :data:`FIELD_DTYPE`), which costs a compiled call no more than a plain array.
"""

from __future__ import annotations

import math
from dataclasses import astuple, dataclass, fields

import numpy as np

from agents.roles.errors import RoleError


@dataclass(frozen=True)
class FieldParams:
    """Weights (per metre, or the height of a ramp term), reaches and distances (m) of the
    supporters' field, and how far one step goes. The defaults balance the terms so that a
    supporter settles within a few metres of its formation target."""

    wall_weight: float = 3.0
    """Height of the wall ramp at a line."""
    wall_reach: float = 3.0
    """Distance from a line (m) where the wall ramp starts."""
    area_weight: float = 3.0
    """Height of the penalty-area ramp at the area's edge."""
    area_reach: float = 2.0
    """Distance outside our penalty area (m) where its ramp starts."""
    teammate_weight: float = 2.0
    """Height of the ramp between two team-mates on the same spot."""
    teammate_reach: float = 5.0
    """Team-mates farther apart than this (m) do not repel."""
    ball_weight: float = 0.4
    """Per metre off the equilibrium circle around the ball (offensive supporters)."""
    ball_distance: float = 12.0
    """Radius of the equilibrium circle around the ball (m)."""
    ball_soft: float = 2.0
    """Soft radius of the ball term's huber (m)."""
    forward_weight: float = 0.5
    """Per metre an offensive supporter is short of ``ball_x + forward_offset``."""
    forward_offset: float = 3.0
    """How far ahead of the ball (m) offensive supporters should be."""
    defensive_weight: float = 0.5
    """Per metre a defensive supporter is beyond ``ball_x - defensive_offset``."""
    defensive_offset: float = 5.0
    """How far goal-side of the ball (m) defensive supporters should be."""
    corridor_clear_weight: float = 3.0
    """Height of the ramp on the ball-to-their-goal segment (offensive supporters, attacking)."""
    corridor_width: float = 4.0
    """Half-width (m) of the shooting corridor kept clear."""
    corridor_block_weight: float = 0.3
    """Per metre a defensive supporter is off the ball-to-our-goal segment (defending)."""
    corridor_block_soft: float = 1.0
    """Soft radius of the blocking term's huber (m)."""
    side_weight: float = 0.3
    """Per metre a supporter is on the wrong side of the field's long axis."""
    side_threshold: float = 5.0
    """Anchors (and balls) within this distance (m) of the long axis have no side."""
    anchor_weight: float = 0.5
    """Per metre from the formation target."""
    anchor_soft: float = 2.0
    """Soft radius of the anchor term's huber (m)."""
    lookahead: float = 3.0
    """Metres moved per unit of gradient when stepping down the field..."""
    max_step: float = 5.0
    """...but never more than this (m)."""
    field_margin: float = 1.0
    """A steered point stays this far (m) inside the touchlines and goal lines."""

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) or value < 0:
                raise RoleError(f"FieldParams.{f.name} must be a finite number >= 0, got {value!r}")
        for name in ("wall_reach", "area_reach", "teammate_reach", "corridor_width"):
            if getattr(self, name) <= 0:
                raise RoleError(f"FieldParams.{name} must be > 0 (it divides the ramp), got {getattr(self, name)!r}")

    def as_record(self) -> np.ndarray:
        """The parameters as a one-element :data:`FIELD_DTYPE` array, what the compiled kernels
        read by name (``params[0].wall_weight``)."""
        return np.array([astuple(self)], dtype=FIELD_DTYPE)


FIELD_DTYPE = np.dtype([(f.name, np.float64) for f in fields(FieldParams)], align=True)
"""The record the kernels read: one float64 field per :class:`FieldParams` field, same names."""
