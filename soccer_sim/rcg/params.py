"""The parameter lines of a game log: ``(server_param ...)``, ``(player_param ...)`` and the
``(player_type ...)`` lines, for a match's configuration.

The lines list every parameter rcssserver 19 lists, in its order (:mod:`soccer_sim.rcg.defaults`),
so that tools which read them (soccerwindow2 and librcsc take the field's and the players'
sizes, the half length, ... from them) find what they expect. The values soccer-sim's
configuration sets replace rcssserver's defaults (:data:`SERVER_PARAMETERS` names them);
the rest keep rcssserver's defaults. Noise parameters (``player_rand``, ``kick_rand``,
``ball_rand``) keep the server's values: soccer-sim's noise model is not the server's
formula, so its own figures would mean something else there.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence

from soccer_sim.config import MatchConfig
from soccer_sim.player_types import PlayerType
from soccer_sim.rcg.defaults import DEFAULT_PLAYER_TYPE, PLAYER_PARAMS, SERVER_PARAMS

PLAYER_TYPES = 18
"""Player types a log lists (rcssserver's ``player_types``)."""


def number(value: float) -> str:
    """A number as rcssserver's C++ streams print it (six significant digits, no trailing
    zeros; integers without a point)."""
    if isinstance(value, bool):
        return "1" if value else "0"
    return f"{value:g}"


def _capacity(config: MatchConfig) -> float:
    capacity = config.stamina.capacity
    return -1.0 if capacity is None or math.isinf(capacity) else capacity  # rcssserver: negative = unlimited


SERVER_PARAMETERS: dict[str, Callable[[MatchConfig], float]] = {
    "goal_width": lambda c: c.field.goal_width,
    "ball_size": lambda c: c.physics.ball_radius,
    "player_size": lambda c: c.physics.player_radius,
    "player_speed_max": lambda c: c.physics.player_speed_max,
    "maxpower": lambda c: c.physics.dash_power_max,
    "dash_power_rate": lambda c: c.physics.dash_power_rate,
    "side_dash_rate": lambda c: c.physics.side_dash_rate,
    "back_dash_rate": lambda c: c.physics.back_dash_rate,
    "player_decay": lambda c: c.physics.player_decay,
    "ball_decay": lambda c: c.physics.ball_decay,
    "ball_speed_max": lambda c: c.physics.ball_speed_max,
    "ball_accel_max": lambda c: c.physics.kick_speed_max,
    "kick_power_rate": lambda c: c.physics.kick_speed_max / c.physics.dash_power_max,
    "kickable_margin": lambda c: c.physics.kickable_margin,
    "stamina_max": lambda c: c.stamina.maximum,
    "stamina_inc_max": lambda c: c.stamina.recovery_per_cycle,
    "extra_stamina": lambda c: c.stamina.extra_stamina,
    "stamina_capacity": _capacity,
    "recover_dec_thr": lambda c: c.stamina.recover_dec_thr,
    "recover_dec": lambda c: c.stamina.recover_dec,
    "recover_min": lambda c: c.stamina.recover_min,
    "effort_dec_thr": lambda c: c.stamina.effort_dec_thr,
    "effort_dec": lambda c: c.stamina.effort_dec,
    "effort_min": lambda c: c.stamina.effort_min,
    "effort_inc_thr": lambda c: c.stamina.effort_inc_thr,
    "effort_inc": lambda c: c.stamina.effort_inc,
    "effort_init": lambda c: c.stamina.effort_max,
    "simulator_step": lambda c: round(c.physics.cycle_seconds * 1000),
    "half_time": lambda c: c.rules.half_cycles * c.physics.cycle_seconds,  # seconds in rcssserver
    "use_offside": lambda c: c.rules.offside,
    "offside_kick_margin": lambda c: c.rules.set_play_clearance,
    "kick_off_clear": lambda c: c.rules.set_play_clearance,
    "drop_ball_time": lambda c: c.rules.set_play_timeout,
    "catchable_area_l": lambda c: c.rules.catch_length,
    "catchable_area_w": lambda c: c.rules.catch_width,
    "catch_ban_cycle": lambda c: c.rules.catch_ban_cycles,
    "goalie_max_moves": lambda c: c.rules.goalie_max_moves,
    "back_passes": lambda c: c.rules.back_pass_rule,
    "ckick_margin": lambda c: c.rules.corner_inset,
    "ball_stuck_area": lambda c: c.rules.stuck_ball_radius,
    "proper_goal_kicks": lambda c: c.rules.proper_goal_kicks,
    "max_goal_kicks": lambda c: c.rules.max_goal_kicks,
} | {name: (lambda c, name=name: getattr(c.tackles, name)) for name in (
    "tackle_dist", "tackle_back_dist", "tackle_width", "tackle_exponent", "tackle_cycles", "tackle_power_rate",
    "max_tackle_power", "max_back_tackle_power", "tackle_rand_factor", "foul_exponent", "foul_detect_probability",
    "foul_cycles", "red_card_probability")}
"""rcssserver ``server_param`` name -> its value in a soccer-sim configuration (same units:
metres, cycles, rcssserver's power units; ``half_time`` in seconds as the server has it)."""

PLAYER_TYPE_PARAMETERS: dict[str, Callable[[MatchConfig], float]] = {
    name: SERVER_PARAMETERS[name] for name in
    ("player_speed_max", "stamina_inc_max", "player_decay", "dash_power_rate", "player_size",
     "kickable_margin", "extra_stamina", "kick_power_rate")
} | {"effort_max": lambda c: c.stamina.effort_max, "effort_min": lambda c: c.stamina.effort_min,
     "foul_detect_probability": SERVER_PARAMETERS["foul_detect_probability"]}
"""``player_type`` name -> its value for the default type in a soccer-sim configuration."""


def _line(head: str, pairs: Sequence[tuple[str, str]]) -> str:
    return f"({head} " + "".join(f"({name} {value})" for name, value in pairs) + ")"


def _with(pairs: Sequence[tuple[str, str]], values: dict[str, Callable[[MatchConfig], float]],
          config: MatchConfig) -> list[tuple[str, str]]:
    return [(name, number(values[name](config)) if name in values else value) for name, value in pairs]


def server_param_line(config: MatchConfig) -> str:
    """The ``(server_param ...)`` line: rcssserver's defaults with ``config``'s values."""
    return _line("server_param", _with(SERVER_PARAMS, SERVER_PARAMETERS, config))


def player_param_line() -> str:
    """The ``(player_param ...)`` line: rcssserver's defaults (``player_types`` 18)."""
    return _line("player_param", PLAYER_PARAMS)


def player_type_lines(config: MatchConfig, types: Sequence[PlayerType] | None = None) -> list[str]:
    """The ``(player_type (id N) ...)`` lines, one per player type of the match (``types``, as
    :func:`soccer_sim.player_types.draw_player_types` draws them; type 0 the default). Without
    ``types``, 18 lines that all list the default type's parameters from ``config``."""
    pairs = _with([pair for pair in DEFAULT_PLAYER_TYPE if pair[0] != "id"], PLAYER_TYPE_PARAMETERS, config)
    if types is None:
        return [_line("player_type", [("id", str(k)), *pairs]) for k in range(PLAYER_TYPES)]
    lines = []
    for t in types:
        drawn = t.as_dict()
        lines.append(_line("player_type", [("id", str(t.id))] + [
            (name, number(drawn[name]) if name in drawn and t.id != 0 else value) for name, value in pairs]))
    return lines
