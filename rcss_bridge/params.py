"""rcssserver's parameters (``server_param``, ``player_param``, ``player_type``) as the
project's own configuration: :class:`~soccer_sim.config.MatchConfig` and
:class:`~soccer_sim.player_types.PlayerType`.

A player's ``init`` is answered with three kinds of parameter message:
``(server_param (name value) ...)`` (about 230 values), ``(player_param (name value) ...)``
(the heterogeneous types' ranges) and one ``(player_type (id N) (name value) ...)`` per type
(18 by default). :func:`read_parameters` reads each into a plain ``{name: value}`` mapping
(numbers as float, quoted strings as str), kept whole in :class:`ServerParameters`, so a value
the project has no field for stays at hand; :meth:`ServerParameters.match_config` maps every
value the project has a field for (:data:`CONFIG_FIELDS`, one table) into a ``MatchConfig``
with partial observation, and :func:`player_type` reads a type into a ``PlayerType`` (same
field names as the server's).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType

from soccer_sim.config import MatchConfig, PlayerTypeConfig
from soccer_sim.config_checks import ConfigError
from soccer_sim.perception.config import ObservationConfig
from soccer_sim.player_types import PlayerType

from rcss_bridge.errors import ProtocolError
from rcss_bridge.sexpr import parse, unquote

Value = float | str
"""A parameter's value: a number, or a (formerly quoted) string such as a file name."""

MS_PER_SECOND = 1000.0


def _seconds(ms: float) -> float:
    return ms / MS_PER_SECOND


def _same(value: float) -> float:
    return value


def _flag(value: float) -> bool:
    return value != 0.0


def _whole(value: float) -> int:
    return int(round(value))


def _capacity(value: float) -> float | None:
    """``stamina_capacity``: a negative value means no limit (rcssserver), None here."""
    return None if value < 0 else value


CONFIG_FIELDS: tuple[tuple[str, str, object], ...] = (
    # (rcssserver's server_param name, MatchConfig field path, conversion)
    ("goal_width", "field.goal_width", _same),
    ("simulator_step", "physics.cycle_seconds", _seconds),
    ("player_size", "physics.player_radius", _same),
    ("ball_size", "physics.ball_radius", _same),
    ("player_speed_max", "physics.player_speed_max", _same),
    ("maxpower", "physics.dash_power_max", _same),
    ("dash_power_rate", "physics.dash_power_rate", _same),
    ("side_dash_rate", "physics.side_dash_rate", _same),
    ("back_dash_rate", "physics.back_dash_rate", _same),
    ("player_decay", "physics.player_decay", _same),
    ("ball_decay", "physics.ball_decay", _same),
    ("ball_speed_max", "physics.ball_speed_max", _same),
    ("ball_accel_max", "physics.kick_speed_max", _same),
    ("kickable_margin", "physics.kickable_margin", _same),
    ("inertia_moment", "physics.inertia_moment", _same),
    ("player_rand", "physics.player_rand", _same),
    ("ball_rand", "physics.ball_rand", _same),
    ("kick_rand", "physics.kick_rand", _same),
    ("stamina_max", "stamina.maximum", _same),
    ("stamina_inc_max", "stamina.recovery_per_cycle", _same),
    ("extra_stamina", "stamina.extra_stamina", _same),
    ("stamina_capacity", "stamina.capacity", _capacity),
    ("recover_dec_thr", "stamina.recover_dec_thr", _same),
    ("recover_dec", "stamina.recover_dec", _same),
    ("recover_min", "stamina.recover_min", _same),
    ("effort_dec_thr", "stamina.effort_dec_thr", _same),
    ("effort_dec", "stamina.effort_dec", _same),
    ("effort_min", "stamina.effort_min", _same),
    ("effort_inc_thr", "stamina.effort_inc_thr", _same),
    ("effort_inc", "stamina.effort_inc", _same),
    ("effort_init", "stamina.effort_max", _same),
    ("use_offside", "rules.offside", _flag),
    ("offside_kick_margin", "rules.set_play_clearance", _same),
    ("drop_ball_time", "rules.set_play_timeout", _whole),
    ("catchable_area_l", "rules.catch_length", _same),
    ("catchable_area_w", "rules.catch_width", _same),
    ("catch_ban_cycle", "rules.catch_ban_cycles", _whole),
    ("goalie_max_moves", "rules.goalie_max_moves", _whole),
    ("back_passes", "rules.back_pass_rule", _flag),
    ("ckick_margin", "rules.corner_inset", _same),
    ("ball_stuck_area", "rules.stuck_ball_radius", _same),
    ("proper_goal_kicks", "rules.proper_goal_kicks", _flag),
    ("max_goal_kicks", "rules.max_goal_kicks", _whole),
    ("tackle_dist", "tackles.tackle_dist", _same),
    ("tackle_back_dist", "tackles.tackle_back_dist", _same),
    ("tackle_width", "tackles.tackle_width", _same),
    ("tackle_exponent", "tackles.tackle_exponent", _same),
    ("tackle_cycles", "tackles.tackle_cycles", _whole),
    ("tackle_power_rate", "tackles.tackle_power_rate", _same),
    ("max_tackle_power", "tackles.max_tackle_power", _same),
    ("max_back_tackle_power", "tackles.max_back_tackle_power", _same),
    ("tackle_rand_factor", "tackles.tackle_rand_factor", _same),
    ("foul_exponent", "tackles.foul_exponent", _same),
    ("foul_detect_probability", "tackles.foul_detect_probability", _same),
    ("foul_cycles", "tackles.foul_cycles", _whole),
    ("red_card_probability", "tackles.red_card_probability", _same),
    ("player_speed_max_min", "player_types.player_speed_max_min", _same),
    ("visible_angle", "observation.see.visible_angle", _same),
    ("visible_distance", "observation.see.visible_distance", _same),
    ("quantize_step", "observation.see.quantize_step", _same),
    ("quantize_step_l", "observation.see.quantize_step_l", _same),
    ("minneckang", "observation.see.min_neck_angle", _same),
    ("maxneckang", "observation.see.max_neck_angle", _same),
    ("minneckmoment", "observation.see.min_neck_moment", _same),
    ("maxneckmoment", "observation.see.max_neck_moment", _same),
    ("send_step", "observation.see.send_step", _whole),
    ("simulator_step", "observation.see.simulator_step", _whole),
    ("say_msg_size", "observation.audio.say_msg_size", _whole),
    ("audio_cut_dist", "observation.audio.audio_cut_dist", _same),
    ("hear_max", "observation.audio.hear_max", _whole),
    ("hear_inc", "observation.audio.hear_inc", _whole),
    ("hear_decay", "observation.audio.hear_decay", _whole),
)
"""Every ``server_param`` value the project has a field for: its name, the ``MatchConfig``
field it sets (dotted path) and the conversion (ms to s, 0/1 to bool, ...). ``half_time``
(seconds) is converted separately (it needs ``simulator_step``: :data:`HALF_TIME`)."""

HALF_TIME = ("half_time", "rules.half_cycles")
"""rcssserver's ``half_time`` is in seconds of game time; the project counts cycles."""

PLAYER_PARAM_FIELDS: tuple[tuple[str, str], ...] = tuple(
    (f.name, f"player_types.{f.name}") for f in dataclasses.fields(PlayerTypeConfig)
    if f.name not in ("types", "max_trials", "player_speed_max_min")) + (
    ("player_types", "player_types.types"),)
"""Every ``player_param`` value with a field of ``PlayerTypeConfig`` (the same names, but
``player_types`` -> ``types``); ``player_speed_max_min`` is a server_param."""


def read_parameters(text: str, head: str) -> dict[str, Value]:
    """The ``(name value)`` pairs of a ``(head (name value) ...)`` message as a mapping;
    a :class:`ProtocolError` when the message is another one or a pair is malformed."""
    expr = parse(text)
    if not expr or expr[0] != head:
        raise ProtocolError(f"expected a ({head} ...) message, got ({expr[0] if expr else ''} ...)")
    values: dict[str, Value] = {}
    for item in expr[1:]:
        if not isinstance(item, list) or len(item) != 2 or not all(isinstance(t, str) for t in item):
            raise ProtocolError(f"({head} ...): malformed parameter {item!r}")
        name, raw = item
        try:
            values[name] = float(raw)
        except ValueError:
            values[name] = unquote(raw)
    return values


def player_type(text: str) -> PlayerType:
    """A ``(player_type (id N) ...)`` message as a :class:`PlayerType` (every field by its
    rcssserver name; a :class:`ProtocolError` naming a missing one)."""
    values = read_parameters(text, "player_type")
    kwargs: dict[str, float | int] = {}
    for f in dataclasses.fields(PlayerType):
        if f.name not in values:
            raise ProtocolError(f"(player_type ...) has no {f.name}")
        kwargs[f.name] = _whole(_number(values, f.name)) if f.name == "id" else _number(values, f.name)
    return PlayerType(**kwargs)  # type: ignore[arg-type]


@dataclass(frozen=True)
class ServerParameters:
    """What the server told a client at ``init``: its ``server_param`` and ``player_param``
    values by name (every one of them, read only) and its player types by id."""

    server: Mapping[str, Value]
    player: Mapping[str, Value]
    types: tuple[PlayerType, ...]

    @classmethod
    def from_messages(cls, server_param: str, player_param: str, player_types: list[str]) -> ServerParameters:
        """From the texts of the three kinds of message (the types in any order, ids 0..n-1)."""
        types = sorted((player_type(text) for text in player_types), key=lambda t: t.id)
        if [t.id for t in types] != list(range(len(types))):
            raise ProtocolError(f"player types {[t.id for t in types]} are not the ids 0..{len(types) - 1}")
        return cls(MappingProxyType(read_parameters(server_param, "server_param")),
                   MappingProxyType(read_parameters(player_param, "player_param")), tuple(types))

    def match_config(self, base: MatchConfig | None = None) -> MatchConfig:
        """``base`` (default: the project's defaults) with every value the server gave that
        the project has a field for (:data:`CONFIG_FIELDS`, :data:`HALF_TIME`,
        :data:`PLAYER_PARAM_FIELDS`), and partial observation (players in the server perceive
        only what it tells them). A value the project rejects is a :class:`ProtocolError`
        naming the server's parameter."""
        settings: dict[str, object] = {"observation.mode": "partial"}
        for name, path, convert in CONFIG_FIELDS:
            if name in self.server:
                settings[path] = convert(_number(self.server, name))  # type: ignore[operator]
        if HALF_TIME[0] in self.server and "simulator_step" in self.server:
            cycles = _number(self.server, HALF_TIME[0]) * MS_PER_SECOND / _number(self.server, "simulator_step")
            settings[HALF_TIME[1]] = _whole(cycles)
        for name, path in PLAYER_PARAM_FIELDS:
            if name in self.player:
                value = _number(self.player, name)
                settings[path] = _whole(value) if path in ("player_types.types", "player_types.pt_max") else value
        config = base if base is not None else MatchConfig(observation=ObservationConfig(mode="partial"))
        try:
            return _replace_paths(config, settings)
        except ConfigError as exc:
            raise ProtocolError(f"the server's parameters do not make a valid configuration: {exc}") from exc

    def unmapped(self) -> dict[str, Value]:
        """The ``server_param`` values without a ``MatchConfig`` field (kept for reference)."""
        mapped = {name for name, _, _ in CONFIG_FIELDS} | {HALF_TIME[0]}
        return {name: value for name, value in self.server.items() if name not in mapped}


def _number(values: Mapping[str, Value], name: str) -> float:
    value = values[name]
    if isinstance(value, str):
        raise ProtocolError(f"parameter {name} should be a number, got {value!r}")
    return value


def _replace_paths(config: object, settings: dict[str, object]) -> object:
    """``config`` (nested frozen dataclasses) with the dotted ``settings`` replaced; the
    validation of each part runs on construction (``MatchConfig`` validates itself)."""
    by_part: dict[str, dict[str, object]] = {}
    direct: dict[str, object] = {}
    for path, value in settings.items():
        part, _, rest = path.partition(".")
        if rest:
            by_part.setdefault(part, {})[rest] = value
        else:
            direct[part] = value
    for part, inner in by_part.items():
        direct[part] = _replace_paths(getattr(config, part), inner)
    return dataclasses.replace(config, **direct)  # type: ignore[type-var]
