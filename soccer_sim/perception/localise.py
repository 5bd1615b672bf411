"""Self-localisation: the position and velocity a player believes it has.

rcssserver never tells a player where it is. It sees the field's 55 flags (``field.cpp``'s
landmarks: centre, goals, posts, penalty boxes, corners, and the ring of flags 5 m outside the
lines) with the same quantisation as the ball but the finer ``quantize_step_l`` (0.01), and
reads its own speed from ``sense_body`` (``bodysender.cpp``: ``Quantize(|v|, 0.01)`` and the
velocity's direction relative to the body in integer degrees).

**The model.** Each flag ``f`` in the view cone (or, outside it, within ``visible_distance``)
and within ``max_observation_length`` gives a reported distance
``d_f = Quantize(exp(Quantize(log(|f - p| + EPS), quantize_step_l)), 0.1)`` and direction
``a_f`` = the angle from the body to the flag rounded to ``direction_step``. The player knows
its body direction ``b`` (as a real agent does from the lines it sees) and estimates
``p_f = f - d_f (cos(b + a_f), sin(b + a_f))``; its position is the mean of the ``p_f``. The
error thus follows the server's quantisation: at most 0.05 m (+0.5 %) along each flag's line
of sight and ``d_f sin(0.5°)`` across it, averaged over the flags in view. With no flag in view
the position is NaN and ``localised`` False. Velocity: magnitude ``Quantize(|v|, 0.01)`` m/cycle,
direction rounded to ``direction_step`` relative to the body (``BodySenderPlayerV6``).
``SeeParams.exact_self`` returns the true position and velocity instead.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from soccer_sim.field_config import STANDARD_FIELD, FieldConfig
from soccer_sim.perception.params import SeeParams
from soccer_sim.perception.kernels import localise_into, position_from_sightings, see_record, sense_velocities

FLAG_MARGIN = 5.0
"""rcssserver's ``PITCH_MARGIN`` (m): the outer ring of flags stands this far outside the lines."""
FLAG_RING_X = tuple(float(x) for x in range(-50, 51, 10))
"""x (m) of the outer-ring flags beyond each touchline (rcssserver's ``(f t l 50)`` ...
``(f b r 50)``): every 10 m, at the same places whatever the pitch's length."""
FLAG_RING_Y = tuple(float(y) for y in range(-30, 31, 10))
"""y (m) of the outer-ring flags behind each goal line (``(f l t 30)`` ... ``(f r b 30)``)."""


def field_flags(field: FieldConfig = STANDARD_FIELD) -> np.ndarray:
    """The positions (55, 2) m of rcssserver's flags for the pitch ``field`` (its length,
    width, goal width and penalty area) centred on the origin: centre and the two ends of the
    halfway line, the four corners, both goals' centres and posts, the three flags of each
    penalty box, and the outer ring (:data:`FLAG_RING_X` along the touchlines' outside,
    :data:`FLAG_RING_Y` behind the goal lines)."""
    hl, hw, hg = field.half_length, field.half_width, field.goal_width / 2.0
    px, py = hl - field.penalty_area_length, field.penalty_area_width / 2.0
    pts = [(0.0, 0.0), (0.0, -hw), (0.0, hw)]
    for sx in (-1.0, 1.0):
        pts += [(sx * hl, -hw), (sx * hl, hw), (sx * hl, 0.0), (sx * hl, -hg), (sx * hl, hg),
                (sx * px, -py), (sx * px, 0.0), (sx * px, py)]
        pts += [(sx * (hl + FLAG_MARGIN), y) for y in FLAG_RING_Y]
    for sy in (-1.0, 1.0):
        pts += [(x, sy * (hw + FLAG_MARGIN)) for x in FLAG_RING_X]
    return np.array(pts, dtype=np.float64)


DEFAULT_FLAGS = field_flags()
"""The 55 flags of the default pitch (:data:`soccer_sim.field_config.STANDARD_FIELD`), m."""


@dataclass(frozen=True)
class SelfEstimate:
    """What ``n`` players believe about themselves."""

    position: np.ndarray
    """Believed positions (n, 2) m; NaN where not localised."""
    velocity: np.ndarray
    """Believed velocities (n, 2) m/cycle."""
    localised: np.ndarray
    """(n,) True where at least one flag was seen (always True with ``exact_self``)."""
    flags_seen: np.ndarray
    """(n,) number of flags the estimate averages (0 with ``exact_self``)."""


def localise(positions: np.ndarray, velocities: np.ndarray, body_dirs: np.ndarray,
             params: SeeParams = SeeParams(), flags: np.ndarray | None = None) -> SelfEstimate:
    """Each player's estimate of its own position and velocity by the model of the module
    docstring, for players at ``positions`` (n, 2) m with ``velocities`` (n, 2) m/cycle and
    body directions ``body_dirs`` (n,) degrees; ``flags`` default :func:`field_flags`.
    Deterministic (the server's flag quantisation has no random part)."""
    pos = np.asarray(positions, dtype=np.float64).reshape(-1, 2)
    vel = np.asarray(velocities, dtype=np.float64).reshape(-1, 2)
    body = np.asarray(body_dirs, dtype=np.float64).reshape(-1)
    n = len(pos)
    if vel.shape != pos.shape or body.shape != (n,):
        raise ValueError(f"localise: positions {pos.shape}, velocities {vel.shape} and body_dirs "
                         f"{body.shape} must describe the same players")
    if params.exact_self:
        return SelfEstimate(position=pos.copy(), velocity=vel.copy(), localised=np.ones(n, dtype=bool),
                            flags_seen=np.zeros(n, dtype=np.int64))
    flag_pts = DEFAULT_FLAGS if flags is None else np.ascontiguousarray(flags, dtype=np.float64).reshape(-1, 2)
    position = np.empty((n, 2))
    count = np.empty(n, dtype=np.int64)
    localise_into(np.ascontiguousarray(pos), np.ascontiguousarray(body), flag_pts, see_record(params), position,
                  count)
    return SelfEstimate(position=position, velocity=sensed_velocity(vel, body, params), localised=count > 0,
                        flags_seen=count)


def sensed_velocity(velocities: np.ndarray, body_dirs: np.ndarray, params: SeeParams = SeeParams()) -> np.ndarray:
    """The velocities (n, 2) m/cycle that ``sense_body`` reports for true ``velocities`` (n, 2)
    m/cycle and body directions ``body_dirs`` (n,) degrees: the speed quantised to 0.01 m/cycle,
    the direction relative to the body rounded to ``direction_step`` (``BodySenderPlayerV6``)."""
    vel = np.asarray(velocities, dtype=np.float64).reshape(-1, 2)
    body = np.asarray(body_dirs, dtype=np.float64).reshape(-1)
    out = np.empty((len(vel), 2))
    sense_velocities(np.ascontiguousarray(vel), np.ascontiguousarray(body), float(params.direction_step), out)
    return out


def position_from_flags(flags: np.ndarray, distances: np.ndarray, directions: np.ndarray,
                        look: float) -> np.ndarray:
    """The module's position estimate (2,) m from sightings a player was told rather than
    ones computed here: the flags at ``flags`` (k, 2) m seen at ``distances`` (k,) m and
    ``directions`` (k,) degrees relative to the look direction ``look`` (degrees, same frame
    as the flags); NaN when k = 0. A client of the real server (``rcss_bridge``) uses it with
    the flags of a ``see`` and the look direction it estimates."""
    pts = np.ascontiguousarray(flags, dtype=np.float64).reshape(-1, 2)
    dist = np.ascontiguousarray(distances, dtype=np.float64).reshape(-1)
    dirs = np.ascontiguousarray(directions, dtype=np.float64).reshape(-1)
    if not len(pts) == len(dist) == len(dirs):
        raise ValueError(f"position_from_flags: {len(pts)} flags, {len(dist)} distances and {len(dirs)} "
                         "directions must describe the same sightings")
    return np.array(position_from_sightings(pts, dist, dirs, float(look)))
