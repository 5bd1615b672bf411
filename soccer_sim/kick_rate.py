"""rcssserver's kick rate: how much of a kick's power reaches the ball, by where the ball lies.

rcssserver (``Player::kick`` in ``src/player.cpp``) scales a kick's power by

    effective_kick_power_rate = kick_power_rate * (1 - 0.25 * dir_diff / 180 - 0.25 * dist_ball / kickable_margin)

where ``dir_diff`` is the angle between the player's body and the direction to the ball and
``dist_ball`` the gap between the player's and the ball's edges (``ball distance - player_size
- ball_size``). The 0.25 factors are the simulator's ``angle_penalty`` and
``distance_penalty`` (:class:`soccer_sim.config.PhysicsConfig`). Neither rate is clamped,
as the server does not clamp them: a ball overlapping the player's edge kicks a little
harder than one touching it.

The simulator's kick (:func:`soccer_sim.kernels.apply_kicks`) and every agent that predicts a
kick (:mod:`agents.skills.ball_kernels`) compute the rate here, so the two cannot drift apart.
"""

from __future__ import annotations

import math

from numba import njit


@njit(cache=True, nogil=True)
def kick_distance_rate(ball_distance: float, touch_distance: float,
                       kickable_margin: float) -> float:  # pragma: no cover - compiled
    """rcssserver's ``dist_ball / kickable_margin``: the gap between player and ball edges
    (``ball_distance`` between centres less ``touch_distance``, both m) over the kickable margin (m)."""
    return (ball_distance - touch_distance) / kickable_margin


@njit(cache=True, nogil=True)
def kick_angle_rate(angle_to_body: float) -> float:  # pragma: no cover - compiled
    """rcssserver's ``dir_diff / 180°`` for the angle between body and ball (radians, [0, pi])."""
    return angle_to_body / math.pi


@njit(cache=True, nogil=True)
def kick_effectiveness(distance_rate: float, angle_rate: float, distance_penalty: float,
                       angle_penalty: float) -> float:  # pragma: no cover - compiled
    """The share of a kick's power that reaches the ball (1 with the ball touching the front
    of the body): ``1 - angle_penalty * angle_rate - distance_penalty * distance_rate``."""
    return 1.0 - angle_penalty * angle_rate - distance_penalty * distance_rate
