"""Heterogeneous player types: rcssserver 19's draws (``heteroplayer.cpp``) and the teams' choice.

Type 0 is the default type, its parameters those of the match's physics, stamina and tackle
configs. Every other type is drawn from the match seed: six deltas, each uniform in its
``PlayerTypeConfig`` range, each moving one parameter by the delta and its trade-off partner
by ``delta * factor`` (player_decay with inertia_moment, dash_power_rate with stamina_inc_max,
kickable_margin with kick_rand, extra_stamina with effort_max and effort_min, kick_power_rate
with foul_detect_probability; player_speed_max with stamina_inc_max and the old
dash_power_rate with player_size are drawn too, with rcssserver's zero-width default ranges).
A draw is kept when its reachable top speed lies in ``[player_speed_max_min,
player_speed_max]``; after ``max_trials`` failed draws the type is the default one.

A team picks a type per player at reset through
:class:`~soccer_sim.team_hooks.ChoosesPlayerTypes`; a team without the hook plays every
player as type 0. At most ``pt_max`` players of one non-default type per team
(:func:`check_choice`). Players are not substituted during a match.
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from soccer_sim.config import MatchConfig
from soccer_sim.team import TeamError

_EPS = 1e-10
"""rcssserver's ``EPS`` in the top-speed acceptance test."""


@dataclass(frozen=True)
class PlayerType:
    """One player type's parameters (rcssserver's ``player_type`` fields)."""

    id: int
    player_speed_max: float
    stamina_inc_max: float
    player_decay: float
    inertia_moment: float
    dash_power_rate: float
    player_size: float
    kickable_margin: float
    kick_rand: float
    extra_stamina: float
    effort_max: float
    effort_min: float
    kick_power_rate: float
    foul_detect_probability: float
    catchable_area_l_stretch: float

    def as_dict(self) -> dict[str, float]:
        """The parameters by name (``id`` included)."""
        return asdict(self)


KICK_POWER_RATE = 0.027
"""rcssserver's default ``kick_power_rate`` (kick speed per power unit): ``kick_speed_max / 100``."""


def default_type(config: MatchConfig) -> PlayerType:
    """Type 0: the parameters the match's configuration gives every player."""
    phys, stam = config.physics, config.stamina
    return PlayerType(
        id=0, player_speed_max=phys.player_speed_max, stamina_inc_max=stam.recovery_per_cycle,
        player_decay=phys.player_decay, inertia_moment=phys.inertia_moment, dash_power_rate=phys.dash_power_rate,
        player_size=phys.player_radius, kickable_margin=phys.kickable_margin, kick_rand=phys.kick_rand,
        extra_stamina=stam.extra_stamina, effort_max=stam.effort_max, effort_min=stam.effort_min,
        kick_power_rate=phys.kick_speed_max / phys.dash_power_max,
        foul_detect_probability=config.tackles.foul_detect_probability, catchable_area_l_stretch=1.0)


def _delta(rng: np.random.Generator, low: float, high: float) -> float:
    """rcssserver's ``HeteroPlayer::delta``: ``low`` when the range is empty, else uniform."""
    if low == high:
        return low
    return float(rng.uniform(min(low, high), max(low, high)))


def _draw_one(config: MatchConfig, type_id: int, rng: np.random.Generator) -> PlayerType:
    """One type, drawn as rcssserver's ``HeteroPlayer()`` does (the default type after
    ``max_trials`` rejected draws)."""
    pt, base = config.player_types, default_type(config)
    power_max = config.physics.dash_power_max
    for _ in range(pt.max_trials):
        d = _delta(rng, pt.player_speed_max_delta_min, pt.player_speed_max_delta_max)
        speed_max = base.player_speed_max + d
        stamina_inc = base.stamina_inc_max + d * pt.stamina_inc_max_delta_factor
        if speed_max <= 0.0 or stamina_inc <= 0.0:
            continue
        d = _delta(rng, pt.player_decay_delta_min, pt.player_decay_delta_max)
        decay = base.player_decay + d
        inertia = base.inertia_moment + d * pt.inertia_moment_delta_factor
        if decay <= 0.0 or inertia < 0.0:
            continue
        d = _delta(rng, pt.dash_power_rate_delta_min, pt.dash_power_rate_delta_max)
        dash_rate = base.dash_power_rate + d
        size = base.player_size + d * pt.player_size_delta_factor
        if dash_rate <= 0.0 or size <= 0.0:
            continue
        d = _delta(rng, pt.new_dash_power_rate_delta_min, pt.new_dash_power_rate_delta_max)
        dash_rate = base.dash_power_rate + d
        stamina_inc = base.stamina_inc_max + d * pt.new_stamina_inc_max_delta_factor
        if dash_rate <= 0.0 or stamina_inc <= 0.0:
            continue
        d = _delta(rng, pt.kickable_margin_delta_min, pt.kickable_margin_delta_max)
        margin = base.kickable_margin + d
        kick_rand = base.kick_rand + d * pt.kick_rand_delta_factor
        if margin <= 0.0 or kick_rand < 0.0:
            continue
        d = _delta(rng, pt.extra_stamina_delta_min, pt.extra_stamina_delta_max)
        extra = base.extra_stamina + d
        effort_max = base.effort_max + d * pt.effort_max_delta_factor
        effort_min = base.effort_min + d * pt.effort_min_delta_factor
        if extra < 0.0 or effort_max <= 0.0 or effort_min <= 0.0:
            continue
        d = _delta(rng, pt.kick_power_rate_delta_min, pt.kick_power_rate_delta_max)
        kick_power_rate = base.kick_power_rate + d
        foul_detect = base.foul_detect_probability + d * pt.foul_detect_probability_delta_factor
        stretch = _delta(rng, pt.catchable_area_l_stretch_min, pt.catchable_area_l_stretch_max)
        real_speed_max = power_max * dash_rate * effort_max / (1.0 - decay)
        if pt.player_speed_max_min - _EPS < real_speed_max < speed_max + _EPS:
            return PlayerType(
                id=type_id, player_speed_max=speed_max, stamina_inc_max=stamina_inc, player_decay=decay,
                inertia_moment=inertia, dash_power_rate=dash_rate, player_size=size, kickable_margin=margin,
                kick_rand=kick_rand, extra_stamina=extra, effort_max=effort_max, effort_min=effort_min,
                kick_power_rate=kick_power_rate, foul_detect_probability=foul_detect,
                catchable_area_l_stretch=stretch)
    base_dict = base.as_dict()
    base_dict["id"] = type_id
    return PlayerType(**base_dict)


def draw_player_types(config: MatchConfig, seed: np.random.SeedSequence | int) -> tuple[PlayerType, ...]:
    """The match's ``config.player_types.types`` types: type 0 the default, the others drawn
    in order from one generator seeded by ``seed`` (the match's player-type seed stream)."""
    rng = np.random.default_rng(seed)
    return (default_type(config),) + tuple(
        _draw_one(config, i, rng) for i in range(1, config.player_types.types))


def check_choice(choice: object, types: tuple[PlayerType, ...], players: int, pt_max: int,
                 team_name: str) -> np.ndarray:
    """A team's choice as an int array of ``players`` type ids; a
    :class:`~soccer_sim.team.TeamError` naming the team (and the player) for a choice of the
    wrong length, an unknown type id, or more than ``pt_max`` players of one non-default type
    (rcssserver's ``pt_max``; the goalkeeper may be of any type, as in rcssserver)."""
    try:
        values = choice.tolist() if isinstance(choice, np.ndarray) else list(choice)  # type: ignore[call-overload]
    except TypeError as exc:
        raise TeamError(team_name, f"choose_player_types must return a sequence of type ids, got {choice!r}") from exc
    if not isinstance(values, list):  # a zero-dimensional array
        raise TeamError(team_name, f"choose_player_types must return a sequence of type ids, got {choice!r}")
    if len(values) != players:
        raise TeamError(team_name, f"choose_player_types must return {players} type ids, got {len(values)}")
    counts: dict[int, int] = {}
    out = np.empty(players, dtype=np.intp)
    for player, value in enumerate(values):
        if isinstance(value, bool) or not isinstance(value, int) or not 0 <= value < len(types):
            raise TeamError(team_name, f"player type {value!r} is not a type id in [0, {len(types)})", player)
        counts[value] = counts.get(value, 0) + 1
        if value != 0 and counts[value] > pt_max:
            raise TeamError(team_name, f"player type {value} is chosen by more than pt_max={pt_max} players",
                            player)
        out[player] = value
    return out
