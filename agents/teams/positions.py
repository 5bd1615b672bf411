"""Finer positions for a formation's roles: centre-back, full-back, holding midfielder, ...

A formation role only has a *kind* (goalkeeper, defender, midfielder, forward: see
:data:`formations.ROLE_KINDS`). Teams and reports want the football position the role plays,
which this module derives from the kind and the formation's geometry, so it works for any
valid formation, not just the built-in ones:

* the role's *reference spot* is its mean target in the normal situation over a grid of ball
  positions that is symmetric in y (so a role's own lateral slot survives and the block's
  slide with the ball cancels out); team frame, metres, we attack +x;
* a role is *wide* when its reference spot is at least ``wide_fraction`` of the default
  field's half width (:data:`soccer_sim.config.STANDARD_FIELD`, the field the built-in
  formations are designed for) from the long axis;
* goalkeeper -> ``"goalkeeper"``; defender -> ``"full-back"`` (wide) or ``"centre-back"``;
  forward -> ``"winger"`` (wide) or ``"centre-forward"`` (a 4-4-2's strikers are
  centre-forwards); midfielder -> ``"wide-midfielder"`` (wide), else ``"holding-midfielder"``
  for the deepest central midfielder when at least two central midfielders play and it sits
  ``holding_gap`` metres or more behind the next one (a 4-3-3's anchor; a flat 4-4-2 has
  none), else ``"central-midfielder"``.
"""

from __future__ import annotations

import numpy as np

from formations import FormationSet, Situation
from soccer_sim.config import STANDARD_FIELD

GOALKEEPER = "goalkeeper"
CENTRE_BACK = "centre-back"
FULL_BACK = "full-back"
HOLDING_MIDFIELDER = "holding-midfielder"
CENTRAL_MIDFIELDER = "central-midfielder"
WIDE_MIDFIELDER = "wide-midfielder"
WINGER = "winger"
CENTRE_FORWARD = "centre-forward"

POSITIONS: tuple[str, ...] = (GOALKEEPER, CENTRE_BACK, FULL_BACK, HOLDING_MIDFIELDER, CENTRAL_MIDFIELDER,
                              WIDE_MIDFIELDER, WINGER, CENTRE_FORWARD)
"""Every position label, from the back to the front (a label's index is its code)."""

POSITION_KINDS: dict[str, str] = {
    GOALKEEPER: "goalkeeper", CENTRE_BACK: "defender", FULL_BACK: "defender", HOLDING_MIDFIELDER: "midfielder",
    CENTRAL_MIDFIELDER: "midfielder", WIDE_MIDFIELDER: "midfielder", WINGER: "forward", CENTRE_FORWARD: "forward",
}
"""Position label -> the formation role kind it belongs to (for tables by kind)."""

WIDE_FRACTION = 0.45
"""A role is wide when its reference spot's |y| is at least this share of the default field's
half width (15.3 m on rcssserver's pitch): full-backs and wingers stand about 20 m out, central players within
about 13 m, so the cut falls in the gap between them."""
HOLDING_GAP = 3.0
"""The deepest central midfielder holds when it stands at least this many metres (x) behind
the next one; less is a flat line (midfield lines are a few metres apart at most)."""

_REFERENCE_X = np.linspace(-30.0, 30.0, 7)
_REFERENCE_Y = np.array([-20.0, -10.0, 0.0, 10.0, 20.0])
"""Ball positions over which the reference spots are averaged (symmetric in y)."""


def reference_spots(formation_set: FormationSet) -> np.ndarray:
    """(roles, 2) each role's mean normal-situation target over ball positions in the middle
    of the field (symmetric in y), team frame, metres."""
    balls = np.array([(x, y) for x in _REFERENCE_X for y in _REFERENCE_Y], dtype=np.float64)
    return formation_set.positions_many(balls, Situation.NORMAL).mean(axis=0)


def position_labels(formation_set: FormationSet, wide_fraction: float = WIDE_FRACTION,
                    holding_gap: float = HOLDING_GAP) -> tuple[str, ...]:
    """The position label (one of :data:`POSITIONS`) of each role of ``formation_set``, in role
    order (see the module docstring for the rules)."""
    if not isinstance(formation_set, FormationSet):
        raise TypeError(f"position_labels needs a FormationSet, not {type(formation_set).__name__}")
    if not 0.0 < wide_fraction < 1.0:
        raise ValueError(f"wide_fraction must lie in (0, 1), not {wide_fraction!r}")
    if not holding_gap >= 0.0:
        raise ValueError(f"holding_gap must be >= 0 m, not {holding_gap!r}")
    spots = reference_spots(formation_set)
    wide = np.abs(spots[:, 1]) >= wide_fraction * STANDARD_FIELD.half_width
    labels: list[str] = []
    for i, role in enumerate(formation_set.roles):
        if role.kind == "goalkeeper":
            labels.append(GOALKEEPER)
        elif role.kind == "defender":
            labels.append(FULL_BACK if wide[i] else CENTRE_BACK)
        elif role.kind == "forward":
            labels.append(WINGER if wide[i] else CENTRE_FORWARD)
        else:
            labels.append(WIDE_MIDFIELDER if wide[i] else CENTRAL_MIDFIELDER)
    central = [i for i, label in enumerate(labels) if label == CENTRAL_MIDFIELDER]
    if len(central) >= 2:
        depth = sorted(central, key=lambda i: float(spots[i, 0]))
        if spots[depth[1], 0] - spots[depth[0], 0] >= holding_gap:
            labels[depth[0]] = HOLDING_MIDFIELDER
    return tuple(labels)


def position_codes(formation_set: FormationSet) -> np.ndarray:
    """:func:`position_labels` as int64 codes (indices into :data:`POSITIONS`), for kernels."""
    return np.array([POSITIONS.index(label) for label in position_labels(formation_set)], dtype=np.int64)


def nearest_roles(formation_set: FormationSet, outfield_roles: np.ndarray, ball: np.ndarray,
                  players: np.ndarray) -> np.ndarray:
    """The outfield roles (sorted) a smaller side's outfield ``players`` (k, 2) m take: those
    whose targets for the ball at ``ball`` lie nearest them, one each (a minimal total distance
    matching)."""
    from scipy.optimize import linear_sum_assignment

    targets = formation_set.positions(ball, Situation.NORMAL)[outfield_roles]
    cost = np.hypot(players[:, None, 0] - targets[None, :, 0], players[:, None, 1] - targets[None, :, 1])
    _, chosen = linear_sum_assignment(cost)
    return np.sort(outfield_roles[chosen])


def current_labels(role_labels: list[str], n: int, outfield: np.ndarray, match_roles: np.ndarray,
                   role_of_player: np.ndarray | None, goalie: int, goalie_role: int) -> list[str]:
    """Each of ``n`` players' current position label (row order): the goalkeeper's, then each
    outfield player's assigned role's (its own formation role's before the first assignment).
    ``role_labels``: the label of each formation role."""
    labels = [role_labels[r] for r in range(n)]
    if len(outfield):
        roles = match_roles if role_of_player is None else match_roles[role_of_player]
        for player, role in zip(outfield.tolist(), roles.tolist()):
            labels[player] = role_labels[role]
    if 0 <= goalie < n:
        labels[goalie] = role_labels[goalie_role]
    return labels
