"""Which heterogeneous player type plays which role, and how fast each player is.

**The choice** (:func:`choose_types`, the built-in team's ``choose_player_types``): the
roles pick types one after another from the match's types, each non-default type at most once
(the default type 0 any number of times; the choice is made before the team sees the match's
configuration, and once is within any ``pt_max`` >= 1, rcssserver's default 1), in this order:

1. **Forwards, then the wide players** (full-backs and wide midfielders: a defender or
   midfielder whose target, with the ball on the centre spot, is at least
   :data:`WIDE_Y` metres from the middle): the fastest type left, by real top speed
   (:func:`top_speed`), ties by acceleration. They make the long runs in behind and the
   overlaps, where a faster player wins the race.
2. **The central midfielders**: the type left with the most stamina recovery per cycle
   (``stamina_inc_max``), ties by ``extra_stamina``. They run the most, all match long.
3. **The centre-backs**: the fastest type left (they race forwards back to goal).
4. **The goalkeeper**: the type left with the largest catchable area
   (``catchable_area_l_stretch``), ties by the lower type id.

Players are matched to roles by their shirt numbers (outfield player j holds outfield role j
at kick-off, as the team's ``static`` assigner keeps them); a side smaller than the formation
picks for its first roles. Ties between types go to the lower type id, so the choice is a
pure function of the types.

**Speeds** (:func:`time_scales`): every outfield player's time factor for the role
assigners (``RoleContext.time_scale``): the default type's top speed over the player's, so
``distance * factor`` is the player's time to a target in metres run at the default speed.
None when all outfield players are equally fast: the assigners then use plain distances.
"""

from __future__ import annotations

import numpy as np

from formations.formation_set import FormationSet, Situation
from soccer_sim.config import MatchConfig

WIDE_Y = 15.0
"""A defender or midfielder whose target (ball on the centre spot) is at least this far (m)
from the middle is a wide player (full-back, wide midfielder); the 4-3-3's centre-backs and
central midfielders stand within 13 m of it, its full-backs and wingers at 21-24 m."""


DASH_POWER_MAX = MatchConfig().physics.dash_power_max
"""rcssserver's ``maxpower`` (100), the dash power the type choice assumes."""


def top_speed(player_type: object, dash_power_max: float = DASH_POWER_MAX) -> float:
    """A type's real top speed (m/cycle): where its fullest dash's acceleration
    (``dash_power_max * dash_power_rate * effort_max``) and its decay balance, capped at its
    ``player_speed_max`` (rcssserver's ``realSpeedMax``)."""
    accel = acceleration(player_type, dash_power_max)
    decay = player_type.player_decay
    return float(min(player_type.player_speed_max, accel / (1.0 - decay))) if decay < 1.0 \
        else float(player_type.player_speed_max)


def acceleration(player_type: object, dash_power_max: float = DASH_POWER_MAX) -> float:
    """A type's largest speed gain in one cycle (m/cycle^2): ``dash_power_max *
    dash_power_rate * effort_max``."""
    return float(dash_power_max * player_type.dash_power_rate * player_type.effort_max)


def role_groups(formation_set: FormationSet, outfield_roles: np.ndarray) -> tuple[list[int], list[int], list[int]]:
    """The outfield roles (values of ``outfield_roles``) in the choosing order: (fast roles,
    forwards first then wide players; stamina roles, central midfielders; the other roles)."""
    spots = formation_set.positions((0.0, 0.0), Situation.NORMAL)
    kinds = [role.kind for role in formation_set.roles]
    forwards = [int(r) for r in outfield_roles if kinds[r] == "forward"]
    wide = [int(r) for r in outfield_roles if kinds[r] != "forward" and abs(spots[r, 1]) >= WIDE_Y]
    central_mid = [int(r) for r in outfield_roles if kinds[r] == "midfielder" and abs(spots[r, 1]) < WIDE_Y]
    rest = [int(r) for r in outfield_roles if int(r) not in forwards + wide + central_mid]
    return forwards + wide, central_mid, rest


def choose_types(types: tuple, formation_set: FormationSet, outfield_roles: np.ndarray, players: int,
                 goalie: int) -> list[int]:
    """One type id per player (row order) as the module docstring says. ``outfield_roles``
    the formation's outfield roles in shirt order; ``players`` the side's size and ``goalie``
    its goalkeeper's row (-1: none)."""
    if not types:
        return [0] * players
    pt_max = 1
    used = np.zeros(len(types), dtype=np.int64)
    speed = [(top_speed(t), acceleration(t)) for t in types]
    stamina = [(float(t.stamina_inc_max), float(t.extra_stamina)) for t in types]
    stretch = [(float(t.catchable_area_l_stretch), 0.0) for t in types]

    def pick(score: list[tuple[float, float]]) -> int:
        best = -1
        for type_id in range(len(types)):
            if type_id and used[type_id] >= pt_max:
                continue
            if best < 0 or score[type_id] > score[best]:
                best = type_id
        used[best] += 1
        return best

    outfield_rows = [row for row in range(players) if row != goalie]
    row_of_role = {int(outfield_roles[j]): row for j, row in enumerate(outfield_rows) if j < len(outfield_roles)}
    choice = [0] * players
    fast, central, rest = role_groups(formation_set, outfield_roles)
    for roles, score in ((fast, speed), (central, stamina), (rest, speed)):
        for role in roles:
            if role in row_of_role:
                choice[row_of_role[role]] = pick(score)
    if 0 <= goalie < players:
        choice[goalie] = pick(stretch)
    return choice


def time_scales(types: tuple, own_types: tuple, outfield: np.ndarray, config: MatchConfig) -> np.ndarray | None:
    """(k,) each outfield player's time factor (the default type's top speed over its own),
    or None when the outfield players are all equally fast (or the types are unknown)."""
    if not types or not own_types or len(outfield) == 0:
        return None
    power = config.physics.dash_power_max
    speeds = np.array([top_speed(types[own_types[row]], power) for row in outfield])
    if np.all(speeds == speeds[0]):
        return None
    return top_speed(types[0], power) / speeds
