"""rcssserver's ``see`` for soccer-sim's point robots: what each player of a team sees.

soccer-sim's players have no neck, so a player looks along its body direction (the direction
of :func:`soccer_sim.body.facing`; :func:`body_directions` computes it for a team). The model is
rcssserver's ``VisualSenderPlayerV1::sendHighBall`` / ``sendHighPlayer`` with
``QuantizeObservation`` (``visualsenderplayer.cpp``), view quality ``high``, focus point at the
player itself (the default: ``focus_dist`` 0):

* ``dir`` = angle from the body to the object (``calcRadDir``), reported rounded to
  ``direction_step`` degrees;
* true distance ``d``; reported distance ``Quantize(exp(Quantize(log(d + EPS), q)), 0.1)``
  with ``q`` = ``quantize_step``, ``EPS`` = 1e-10 and ``Quantize(v, s) = rint(v / s) * s``;
* **in the cone** (``|dir| < visible_angle / 2`` and ``d < max_observation_length``): seen. A
  player's team is dropped with probability ``(d' - team_far) / (team_too_far - team_far)``
  and, if the team stays, its number with probability
  ``(d' - unum_far) / (unum_too_far - unum_far)`` (both clipped to [0, 1]; ``d'`` the reported
  distance; ``calcNoTeamProb``, ``calcNoUnumProb``);
* **outside the cone** but ``d <= visible_distance``: seen with distance and direction but
  anonymous (``calcCloseName``: ``(B)``, ``(P)``);
* otherwise not seen. A player never sees itself.

With quantisation the reported distance is a deterministic function of the state (as in the
server); the random parts are the identity drops, drawn from the ``numpy.random.Generator`` the
caller passes. Velocities (``dist_chg``, ``dir_chg``) are not modelled here.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from soccer_sim.body import DEFAULT_INERTIA_MOMENT
from soccer_sim.perception.kernels import (ANONYMOUS, EPS, FULL, TEAM_ONLY, UNSEEN, SightingRows, body_degrees,
                                           reported_distances, see_into, see_record)
from soccer_sim.perception.params import SeeParams

__all__ = ["ANONYMOUS", "EPS", "FULL", "TEAM_ONLY", "UNSEEN", "Sightings", "body_directions", "quantized_distance",
           "see"]



def quantized_distance(distance: np.ndarray, log_step: float, final_step: float = 0.1) -> np.ndarray:
    """The distance (m) a player reports for a true ``distance`` (m):
    ``Quantize(exp(Quantize(log(d + EPS), log_step)), final_step)`` with rcssserver's
    ``Quantize(v, q) = rint(v / q) * q`` and ``EPS`` 1e-10 (element-wise, any shape)."""
    d = np.asarray(distance, dtype=np.float64)
    flat = np.ascontiguousarray(d).reshape(-1)
    out = np.empty_like(flat)
    reported_distances(flat, float(log_step), float(final_step), out)
    return out.reshape(d.shape)


def body_directions(positions: np.ndarray, velocities: np.ndarray, ball: np.ndarray,
                    inertia_moment: float | np.ndarray = DEFAULT_INERTIA_MOMENT) -> np.ndarray:
    """Body directions (degrees, absolute frame of the positions) of ``n`` players at
    ``positions`` (n, 2) m with ``velocities`` (n, 2) m/cycle and the ball at ``ball`` (2,) m:
    :func:`soccer_sim.body.facing`, the simulator's one body-direction model (``inertia_moment``
    one number or one per player)."""
    pos = np.ascontiguousarray(positions, dtype=np.float64).reshape(-1, 2)
    vel = np.ascontiguousarray(velocities, dtype=np.float64).reshape(-1, 2)
    if pos.shape != vel.shape:
        raise ValueError(f"body_directions: positions {pos.shape} and velocities {vel.shape} differ")
    inertia = np.broadcast_to(np.asarray(inertia_moment, dtype=np.float64), (len(pos),)).copy()
    out = np.empty(len(pos))
    body_degrees(pos, vel, np.ascontiguousarray(ball, dtype=np.float64).reshape(2), inertia, out)
    return out


@dataclass(frozen=True)
class Sightings:
    """What ``n`` observers see of ``m`` objects (object 0 the ball, then the players in the
    order given). Arrays are (n, m); entries of unseen objects are NaN / :data:`UNSEEN`."""

    seen: np.ndarray
    """True where the observer sees the object."""
    distance: np.ndarray
    """Reported distance (m), a multiple of ``distance_step``."""
    direction: np.ndarray
    """Reported direction relative to the observer's body (degrees, [-180, 180), positive
    counter-clockwise), a multiple of ``direction_step``."""
    identity: np.ndarray
    """:data:`FULL`, :data:`TEAM_ONLY`, :data:`ANONYMOUS` or :data:`UNSEEN` (int8)."""
    in_cone: np.ndarray
    """True where the object was seen in the view cone (False: seen only by being close)."""


def _as_points(name: str, value: np.ndarray, shape: tuple[int, ...] | None = None) -> np.ndarray:
    """``value`` as a float (k, 2) array, with a clear error naming ``name``."""
    arr = np.asarray(value, dtype=np.float64)
    if arr.ndim != 2 or arr.shape[1] != 2:
        raise ValueError(f"see: {name} must have shape (k, 2), got {arr.shape}")
    if shape is not None and arr.shape != shape:
        raise ValueError(f"see: {name} must have shape {shape}, got {arr.shape}")
    if not np.all(np.isfinite(arr)):
        raise ValueError(f"see: {name} must be finite")
    return arr


def see(observers: np.ndarray, body_dirs: np.ndarray, ball: np.ndarray, players: np.ndarray,
        rng: np.random.Generator, params: SeeParams = SeeParams(),
        self_index: np.ndarray | None = None) -> Sightings:
    """What each of ``observers`` (n, 2) m, looking along ``body_dirs`` (n,) degrees, sees of the
    ``ball`` (2,) m and the ``players`` (p, 2) m (all players of both teams).
    ``self_index[i]`` is observer i's row in ``players`` (it never sees itself; -1 or None: not
    among them). Identity drops use ``rng``; everything else is deterministic (module
    docstring). Vectorised over observers x objects."""
    obs = _as_points("observers", observers)
    n = len(obs)
    body = np.asarray(body_dirs, dtype=np.float64).reshape(-1)
    if body.shape != (n,) or not np.all(np.isfinite(body)):
        raise ValueError(f"see: body_dirs must be {n} finite angles, got shape {body.shape}")
    ball_pt = _as_points("ball", np.asarray(ball, dtype=np.float64).reshape(1, 2))
    objects = np.concatenate([ball_pt, _as_points("players", np.asarray(players).reshape(-1, 2))])
    m = len(objects)
    idx = np.full(n, -1, dtype=np.int64)
    if self_index is not None:
        idx = np.asarray(self_index, dtype=np.int64).reshape(-1)
        if idx.shape != (n,) or np.any(idx >= m - 1) or np.any(idx < -1):
            raise ValueError(f"see: self_index must be {n} rows of players (or -1)")
    seen = np.empty((n, m), dtype=bool)
    distance = np.empty((n, m))
    direction = np.empty((n, m))
    identity = np.empty((n, m), dtype=np.int8)
    in_cone = np.empty((n, m), dtype=bool)
    # identity drops: drawn for every pair (team drops, then number drops) so the stream does not
    # depend on who sees what
    uniforms = rng.random((2, n, m))
    see_into(obs, body, objects, idx, np.ones(m, dtype=bool), uniforms, see_record(params),
             SightingRows(seen, distance, direction, identity, in_cone))
    return Sightings(seen=seen, distance=distance, direction=direction, identity=identity, in_cone=in_cone)
