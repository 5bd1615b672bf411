"""Kicks: who may kick, how effective a kick is, and the kick that gives the ball a velocity.

The rule mirrored is :meth:`soccer_sim.kinematics.Kinematics.kick` (rcssserver's): a kick
request ``r`` is clipped to ``kick_speed_max`` and multiplied by an effectiveness

    ``1 - kick_distance_penalty * min(1, gap / kickable_margin)
         - kick_angle_penalty * dir_diff / pi``

where ``gap`` is the distance between the ball's and the player's surfaces and ``dir_diff``
the angle between where the kicker's body faces and the ball. The body direction is the
simulator's (:mod:`soccer_sim.body`, from the kicker's velocity): a player at rest or slow
faces the ball, so only the distance counts; a fast one whose ball lies well off its line of
motion loses some power too. It never depends on the kick's direction. A goalkeeper holding
the ball kicks at full effectiveness. The ball's speed is then clipped to ``ball_speed_max``.

:func:`kick_for_velocity` inverts the rule: the change needed is ``desired - ball_vel``; the
request is that change divided by the effectiveness of its direction. When the change is
larger than one kick allows, it keeps the desired *direction* and gives the largest speed
along it that one kick can reach (the effectiveness depends on the kick's direction, so a
few rounds of solving a quadratic, checked, with bisection as the fallback); when no speed
along the desired direction is reachable (a fast ball would have to be turned round), it
kicks at full power towards the point of the desired ray closest to the ball's current
velocity. The compiled kernels are in :mod:`agents.skills.ball_kernels`.
"""

from __future__ import annotations

import numpy as np

from agents.skills.ball_kernels import effect_kernel, kick_kernel
from agents.skills.model import MotionModel, float_array


def kickable(model: MotionModel, pos: np.ndarray, ball: np.ndarray) -> np.ndarray:
    """Bool per player (``pos`` (n, 2) or (2,)): the ball's centre is within the kickable distance."""
    diff = np.asarray(pos, float) - np.asarray(ball, float)
    return np.einsum("...i,...i->...", diff, diff) <= model.kickable_distance ** 2


def kick_effectiveness(model: MotionModel, player: np.ndarray, ball: np.ndarray, kick: np.ndarray,
                       player_vel: np.ndarray | None = None) -> np.ndarray:
    """Effectiveness (fraction of the requested change that reaches the ball) of kicks in the
    directions ``kick`` ((k, 2) or (2,)) by a player at ``player`` moving at ``player_vel``
    ((2,), None: at rest) on the ball at ``ball``."""
    kick = np.asarray(kick, dtype=np.float64)
    single = kick.ndim == 1
    rows = float_array("kick", kick.reshape(1, -1) if single else kick, (-1, 2))
    out = np.empty(rows.shape[0])
    effect_kernel(float_array("player", player, (2,)), _velocity(player_vel), float_array("ball", ball, (2,)), rows,
                  out, model.kick_model)
    return out[0] if single else out


def kick_for_velocity(model: MotionModel, player: np.ndarray, ball: np.ndarray, ball_vel: np.ndarray,
                      desired: np.ndarray, holder: bool = False,
                      player_vel: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """The kick request that makes the ball leave with velocity ``desired`` ((k, 2) or (2,),
    team frame, m/cycle), and the velocity it really gets (same shape; equal to ``desired``
    when one kick can do it, else the best direction-preserving result). ``player``, ``ball``,
    ``ball_vel``: (2,). ``holder``: the kicker is a goalkeeper holding the ball (full
    effectiveness). ``player_vel``: the kicker's velocity ((2,), None: at rest), which sets
    where its body faces. Noise is not modelled here (:meth:`MotionModel.kick_spread`).
    """
    desired = np.asarray(desired, dtype=np.float64)
    single = desired.ndim == 1
    rows = float_array("desired", desired.reshape(1, -1) if single else desired, (-1, 2))
    kick = np.empty_like(rows)
    result = np.empty_like(rows)
    kick_kernel(float_array("player", player, (2,)), _velocity(player_vel), float_array("ball", ball, (2,)),
                float_array("ball_vel", ball_vel, (2,)), rows, kick, result, model.kick_model, bool(holder))
    if single:
        return kick[0], result[0]
    return kick, result


_AT_REST = np.zeros(2)


def _velocity(player_vel: np.ndarray | None) -> np.ndarray:
    """The kicker's velocity as the kernels take it (at rest when None)."""
    return _AT_REST if player_vel is None else float_array("player_vel", player_vel, (2,))
