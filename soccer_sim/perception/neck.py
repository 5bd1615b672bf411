"""rcssserver's neck: where a player's face points relative to its body, and how
``(turn_neck MOMENT)`` moves it.

A player sees along its **face**, the body direction (:mod:`soccer_sim.body`) plus the neck
angle. The neck starts at 0 (the face along the body) and changes only by the player's own
``turn_neck`` (``TeamCommand.turn_neck``): ``Player::turn_neck`` adds the moment, clipped to
``minneckmoment`` / ``maxneckmoment``, to the neck angle and clips the sum to ``minneckang`` /
``maxneckang`` (rcssserver 19: -180..180 and -90..90 degrees), without noise, at most once a
cycle, also while the player is frozen after a tackle. The body turning does not move the neck
(it is relative to the body), so the face turns with the body.
"""

from __future__ import annotations

import numpy as np

from soccer_sim.perception.params import SeeParams


def turned_necks(necks: np.ndarray, moments: np.ndarray, params: SeeParams,
                 out: np.ndarray | None = None) -> np.ndarray:
    """The neck angles (degrees) after ``(turn_neck moments)`` from ``necks`` (degrees), by the
    module docstring's rule, element-wise (NaN moments: no turn). Into ``out`` when given."""
    moment = np.clip(np.nan_to_num(np.asarray(moments, dtype=np.float64), nan=0.0),
                     params.min_neck_moment, params.max_neck_moment)
    return np.clip(np.asarray(necks, dtype=np.float64) + moment, params.min_neck_angle, params.max_neck_angle,
                   out=out)
