"""The parameters of the see model and the cycles on which a player receives a see.

Every default is rcssserver's (``serverparam.cpp`` / ``heteroplayer.cpp`` names in each field's
docstring) for a player with view width ``normal`` and view quality ``high``.

**When a see arrives.** rcssserver's timer ticks every ``send_step / 4`` ms (37.5 ms) and a
player with view width ``normal`` gets a visual every 4 ticks (``visualsenderplayer.cpp``,
``VisualSenderPlayerV1::sendVisual``; ``player.cpp`` sets ``M_visual_send_interval`` 4), i.e.
every ``send_step`` = 150 ms, while the world steps every ``simulator_step`` = 100 ms. A see sent
at time ``t`` ms belongs to cycle ``floor(t / 100)``; with sees at ``offset + 150 k`` the cycles
with a see are ``0, 1, 3, 4, 6, 7, ...`` for offset 0: alternately one and two cycles apart.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields, replace

import numpy as np

from soccer_sim.config_checks import ConfigError
from soccer_sim.config_ranges import check_ranges
from soccer_sim.field_config import STANDARD_FIELD

MAX_DIST_IN_PITCH = math.hypot(STANDARD_FIELD.length, STANDARD_FIELD.width)
"""``heteroplayer.cpp``'s ``maximum_dist_in_pitch`` (m): the diagonal of rcssserver's pitch
(:data:`soccer_sim.field_config.STANDARD_FIELD`), whatever field a match plays on."""


@dataclass(frozen=True)
class SeeParams:
    """What a player sees and how precisely (distances m, angles degrees, times ms)."""

    visible_angle: float = 90.0
    """Total width of the view cone (degrees) around the face (the body direction plus the neck
    angle): ``visible_angle`` with view width ``normal`` (half of it ``narrow``, twice ``wide``:
    :mod:`.view_width`). An object is in the cone when ``|direction| < visible_angle / 2``."""
    visible_distance: float = 3.0
    """``visible_distance`` (m): objects outside the cone are still seen up to this distance,
    but only as anonymous ``(B)`` / ``(P)`` (no team, no number)."""
    quantize_step: float = 0.1
    """``quantize_step``: step of the log-distance quantisation of the ball and players (0: none)."""
    quantize_step_l: float = 0.01
    """``quantize_step_l``: step of the log-distance quantisation of the flags (landmarks),
    used by the self-localisation model (0: none)."""
    distance_step: float = 0.1
    """The final rounding (m) of every observed distance: the ``Quantize(..., 0.1)`` of
    ``QuantizeObservation::calcDistImpl`` (0: none)."""
    direction_step: float = 1.0
    """Rounding of observed directions (degrees): the integer degrees of the protocol (version
    7 on rounds rather than truncates; 0: none)."""
    unum_far_length: float = 20.0
    """``unum_far_length`` (m): up to this observed distance a player's number is always seen."""
    unum_too_far_length: float = 40.0
    """``unum_too_far_length`` (m): beyond it the number is never seen; in between, the chance
    of losing it rises linearly."""
    team_far_length: float = 40.0
    """``team_far_length`` (m; ``serverparam.cpp``'s default; version-18 player types set the
    pitch diagonal): up to this observed distance a player's team is always seen."""
    team_too_far_length: float = 60.0
    """``team_too_far_length`` (m): beyond it the team is never seen; linear in between."""
    max_observation_length: float = MAX_DIST_IN_PITCH
    """``player_max_observation_length`` / ``ball_max_observation_length`` /
    ``flag_max_observation_length`` (m): nothing farther is seen, even in the cone."""
    omnidirectional: bool = False
    """No cone: every object up to ``max_observation_length`` is seen with full detail (a mode
    rcssserver does not have, for studies that want range and noise limits only)."""
    exact_self: bool = False
    """Give each player its true position and velocity instead of the self-localisation model
    of :mod:`soccer_sim.perception.localise`."""
    min_neck_angle: float = -90.0
    """``minneckang`` (degrees): the smallest angle of the neck (the face's direction relative
    to the body; ``TeamCommand.turn_neck``)."""
    max_neck_angle: float = 90.0
    """``maxneckang`` (degrees): the largest angle of the neck."""
    min_neck_moment: float = -180.0
    """``minneckmoment`` (degrees): the smallest neck turn of one cycle (a larger one is clipped)."""
    max_neck_moment: float = 180.0
    """``maxneckmoment`` (degrees): the largest neck turn of one cycle."""
    send_step: int = 150
    """``send_step`` (ms): time between two sees with view width ``normal``."""
    simulator_step: int = 100
    """``simulator_step`` (ms): length of one cycle."""

    def __post_init__(self) -> None:
        for f in fields(self):
            if f.type in ("bool", bool) and not isinstance(getattr(self, f.name), (bool, np.bool_)):
                raise ConfigError(f"SeeParams.{f.name} must be a bool, got {getattr(self, f.name)!r}")
        check_ranges(self)  # every number against its range (soccer_sim.config_ranges)
        for near, far in (("unum_far_length", "unum_too_far_length"), ("team_far_length", "team_too_far_length")):
            if getattr(self, far) < getattr(self, near):
                raise ConfigError(f"SeeParams.{far} ({getattr(self, far)}) must be >= {near} ({getattr(self, near)})")
        if not self.min_neck_angle <= 0.0 <= self.max_neck_angle:  # a player starts with its neck at 0
            raise ConfigError(f"SeeParams.min_neck_angle ({self.min_neck_angle}) must be <= 0 <= max_neck_angle "
                              f"({self.max_neck_angle})")
        if not self.min_neck_moment <= 0.0 <= self.max_neck_moment:
            raise ConfigError(f"SeeParams.min_neck_moment ({self.min_neck_moment}) must be <= 0 <= max_neck_moment "
                              f"({self.max_neck_moment})")

    def without_noise(self) -> SeeParams:
        """These parameters with every source of observation noise off, the view's limits kept
        (cone, ranges, see timing): distances and directions of the ball, players and flags
        reported exactly (no quantisation: ``quantize_step``, ``quantize_step_l``,
        ``distance_step`` and ``direction_step`` 0, so the self-localisation from flags is
        exact on cycles with a see), and no player's team or number lost with distance (both
        "far" lengths at ``max_observation_length``, beyond which nothing is seen). A player
        within ``visible_distance`` but outside the cone stays anonymous (a limit of the view,
        not noise), and ``sense_body``'s own speed keeps its 0.01 m/cycle resolution. Not an
        rcssserver mode: for studies that separate the cost of noise from the view's limits."""
        far = max(self.max_observation_length, self.team_too_far_length, self.unum_too_far_length)
        return replace(self, quantize_step=0.0, quantize_step_l=0.0, distance_step=0.0, direction_step=0.0,
                       unum_far_length=far, unum_too_far_length=far, team_far_length=far, team_too_far_length=far)


def see_cycles(cycles: np.ndarray | int, params: SeeParams = SeeParams(),
               offset_ms: np.ndarray | int = 0) -> np.ndarray:
    """Whether a player receives a see during each of ``cycles`` (cycle ``c`` spans
    ``[c * simulator_step, (c + 1) * simulator_step)`` ms), with sees sent at
    ``offset_ms + k * send_step`` for ``k >= 0`` (``offset_ms`` may be one per player: rcssserver
    players connect at different moments, so their sees are out of phase). Broadcasts."""
    c = np.asarray(cycles, dtype=np.int64)
    off = np.asarray(offset_ms, dtype=np.int64)
    if np.any(c < 0):
        raise ValueError("see_cycles: cycles must be >= 0")
    if np.any(off < 0):
        raise ValueError("see_cycles: offset_ms must be >= 0")
    send, sim = int(params.send_step), int(params.simulator_step)

    def sent_before(t: np.ndarray) -> np.ndarray:
        """Number of sees sent at times < t (ms)."""
        return np.where(t > off, (t - off + send - 1) // send, 0)

    return sent_before((c + 1) * sim) > sent_before(c * sim)
