"""The body controller: a requested acceleration as a turn or a dash, and the neck that keeps
the ball in view, by rcssserver's rules for a player with a body direction.

The project's teams ask for an acceleration vector (``TeamCommand.dash``, team frame,
m/cycle²); the simulator's robots have no body and dash in any direction. rcssserver's
players dash relative to their body, ``(dash POWER DIR)``, at the share ``dir_rate`` of the
power that the side and back dash rates leave (``side_dash_rate`` at 90° from the body,
``back_dash_rate`` straight behind it, linear in between: :func:`dash_rate`), and they turn
with ``(turn MOMENT)``, a turn of ``MOMENT / (1 + inertia_moment * speed)`` that takes the
cycle's one body command (:func:`soccer_sim.body.turn_angle`).

**Turn or dash** (:func:`choose_run`). Two plans are played forward for
``horizon`` cycles with the server's rules (dash rates, effort, the type's
``dash_power_rate``, top speed and decay, the turn's reach at each cycle's speed): *dash*, the
requested acceleration now and every cycle, in the requested direction from the body as it
is; *turn*, one turn towards the requested direction (as far as it reaches at the player's
speed), then the same dashes from the body as turned. The plan whose displacement along the
requested direction is larger is taken (the dash on a tie); only its first command is sent,
and the choice is made again every cycle (so a turn the speed cuts short is followed by
another when that pays). A request the body's angle lets through in full (a
gentle one, or one nearly ahead) is always a dash; a strong one well off the body's line waits
for a turn. With the default horizon (:data:`RUN_HORIZON`, 4 cycles) a full request within
about 43° of the body is a dash and one beyond it a turn (at rest a full back dash, rate 0.7,
just loses to a turn and three forward dashes); a moving player asked to go more than about
120-150° the other way dashes backwards, as its turn would fall short.

**The neck** (:func:`neck_moment`). After the body's command the face (body + neck) is
turned towards where the ball is believed to be, the neck within ``minneckang`` /
``maxneckang`` of the body and turned by at most ``minneckmoment`` / ``maxneckmoment`` a
cycle; with the ball unknown the neck swings from one end to the other, so that two steps
look over the widest arc.

Angles in degrees; rcssserver's names in the docstrings.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from soccer_sim.body import turn_angle
from soccer_sim.kernels import dash_direction_rate
from soccer_sim.player_types import PlayerType

from rcss_bridge.errors import ProtocolError
from rcss_bridge.localisation import wrap

RUN_HORIZON = 4
"""Cycles over which :func:`choose_run` compares dashing now with turning first (the module
docstring): long enough that a turn of one cycle pays for itself against a side or back
dash, short enough that a gentle or nearly straight request never waits for one."""

ALIGNED = 0.5
"""Degrees within which a body counts as facing the requested direction (half of rcssserver
19's ``dash_angle_step``, 1°: a dash direction is rounded to it anyway)."""


@dataclass(frozen=True)
class ServerRules:
    """The server parameters the command translation obeys (rcssserver's ``server_param``
    names beside each field; the defaults are rcssserver 19's)."""

    max_power: float = 100.0
    """``maxpower``: the largest kick power."""
    min_moment: float = -180.0
    """``minmoment``: the smallest turn moment, kick and tackle direction."""
    max_moment: float = 180.0
    """``maxmoment``."""
    min_neck_angle: float = -90.0
    """``minneckang``: the neck's smallest angle to the body."""
    max_neck_angle: float = 90.0
    """``maxneckang``."""
    min_neck_moment: float = -180.0
    """``minneckmoment``: the smallest neck turn of one cycle."""
    max_neck_moment: float = 180.0
    """``maxneckmoment``."""
    min_dash_power: float = 0.0
    """``min_dash_power`` (0 in rcssserver 19: a back dash is a dash at 180°)."""
    max_dash_power: float = 100.0
    """``max_dash_power``."""
    min_dash_angle: float = -180.0
    """``min_dash_angle``: the smallest dash direction relative to the body."""
    max_dash_angle: float = 180.0
    """``max_dash_angle``."""
    dash_angle_step: float = 1.0
    """``dash_angle_step``: dash directions are rounded to it."""
    side_dash_rate: float = 0.4
    """``side_dash_rate``: the share of a dash's power at 90° from the body."""
    back_dash_rate: float = 0.7
    """``back_dash_rate``: the share straight behind the body."""
    min_catch_angle: float = -90.0
    """``min_catch_angle``: the smallest catch direction relative to the body."""
    max_catch_angle: float = 90.0
    """``max_catch_angle``."""
    goalie_max_moves: int = 2
    """``goalie_max_moves``: moves the goalkeeper may make while it holds the ball."""

    @classmethod
    def from_server(cls, server: dict | object) -> ServerRules:
        """The rules from a ``server_param`` mapping (``ServerParameters.server``); a
        :class:`~rcss_bridge.errors.ProtocolError` naming a missing or non-numeric value."""
        values: dict[str, float | int] = {}
        for name, field_name in SERVER_NAMES:
            value = server.get(name) if hasattr(server, "get") else None  # type: ignore[union-attr]
            if not isinstance(value, float | int) or isinstance(value, bool):
                raise ProtocolError(f"server_param has no numeric {name} (got {value!r})")
            values[field_name] = int(round(value)) if field_name == "goalie_max_moves" else float(value)
        return cls(**values)  # type: ignore[arg-type]


SERVER_NAMES: tuple[tuple[str, str], ...] = (
    ("maxpower", "max_power"), ("minmoment", "min_moment"), ("maxmoment", "max_moment"),
    ("minneckang", "min_neck_angle"), ("maxneckang", "max_neck_angle"),
    ("minneckmoment", "min_neck_moment"), ("maxneckmoment", "max_neck_moment"),
    ("min_dash_power", "min_dash_power"), ("max_dash_power", "max_dash_power"),
    ("min_dash_angle", "min_dash_angle"), ("max_dash_angle", "max_dash_angle"),
    ("dash_angle_step", "dash_angle_step"), ("side_dash_rate", "side_dash_rate"),
    ("back_dash_rate", "back_dash_rate"), ("min_catch_angle", "min_catch_angle"),
    ("max_catch_angle", "max_catch_angle"), ("goalie_max_moves", "goalie_max_moves"),
)
"""rcssserver's ``server_param`` name of every :class:`ServerRules` field."""


def clamp(value: float, low: float, high: float) -> float:
    return min(max(value, low), high)


def dash_direction(relative: float, rules: ServerRules) -> float:
    """A dash direction relative to the body as the server executes it
    (``NormalizeDashAngle``): within ``min_dash_angle`` / ``max_dash_angle``, rounded to
    ``dash_angle_step``."""
    direction = clamp(wrap(relative), rules.min_dash_angle, rules.max_dash_angle)
    if rules.dash_angle_step > 0.0:
        direction = rules.dash_angle_step * round(direction / rules.dash_angle_step)
    return direction


def dash_rate(direction: float, rules: ServerRules) -> float:
    """rcssserver's ``dir_rate`` of a dash ``direction`` degrees from the body: the
    simulator's dash-rate formula (:func:`soccer_sim.kernels.dash_direction_rate`) with the
    body as the heading, counted in full."""
    a = math.radians(direction)
    return dash_direction_rate(math.cos(a), math.sin(a), 1.0, 1.0, 0.0, 1.0, rules.side_dash_rate,
                               rules.back_dash_rate, 1.0)


def dash_power(size: float, direction: float, effort: float, player: PlayerType, rules: ServerRules) -> float:
    """The power of a dash at ``direction`` from the body that gives an acceleration of
    ``size`` m/cycle² (``effort * power * dir_rate * dash_power_rate``), within the server's
    power limits."""
    per_power = effort * dash_rate(direction, rules) * player.dash_power_rate
    if per_power <= 0.0:
        return rules.max_dash_power
    return clamp(size / per_power, rules.min_dash_power, rules.max_dash_power)


def turn_moment(angle: float, speed: float, player: PlayerType, rules: ServerRules) -> float:
    """The moment that turns a player moving at ``speed`` by ``angle`` degrees (the inverse
    of :func:`soccer_sim.body.turn_angle`), within ``minmoment`` / ``maxmoment``."""
    return clamp(angle / turn_angle(1.0, speed, player.inertia_moment), rules.min_moment, rules.max_moment)


@dataclass(frozen=True)
class Run:
    """A body command for a requested acceleration: ``(turn moment)`` when ``turn`` is set,
    else ``(dash power direction)``."""

    turn: bool
    power: float = 0.0
    direction: float = 0.0
    moment: float = 0.0


def _progress(vx: float, vy: float, body: float, want: float, size: float, turn_first: bool, effort: float,
              player: PlayerType, rules: ServerRules, horizon: int) -> float:
    """Metres covered along ``want`` in ``horizon`` cycles by a player at velocity (vx, vy)
    with its body at ``body`` that dashes for ``size`` m/cycle² towards ``want`` every cycle,
    after turning towards it first, as far as one turn reaches, when ``turn_first`` (server
    rules, noise aside)."""
    covered = 0.0
    ux, uy = math.cos(math.radians(want)), math.sin(math.radians(want))
    for cycle in range(horizon):
        remaining = wrap(want - body)
        ax = ay = 0.0
        if turn_first and cycle == 0:
            reach = turn_angle(rules.max_moment, math.hypot(vx, vy), player.inertia_moment)
            body += clamp(remaining, -reach, reach)
        else:
            direction = dash_direction(remaining, rules)
            power = dash_power(size, direction, effort, player, rules)
            accel = power * effort * dash_rate(direction, rules) * player.dash_power_rate
            heading = math.radians(body + direction)
            ax, ay = accel * math.cos(heading), accel * math.sin(heading)
        vx, vy = vx + ax, vy + ay
        speed = math.hypot(vx, vy)
        if speed > player.player_speed_max:
            vx, vy = vx * player.player_speed_max / speed, vy * player.player_speed_max / speed
        covered += vx * ux + vy * uy
        vx, vy = vx * player.player_decay, vy * player.player_decay
    return covered


def choose_run(ax: float, ay: float, body: float, vx: float, vy: float, effort: float, player: PlayerType,
               rules: ServerRules, horizon: int = RUN_HORIZON) -> Run:
    """The body command for a requested acceleration (ax, ay) (m/cycle², the frame of
    ``body``, degrees, and of the velocity (vx, vy), m/cycle): a dash, or a turn towards the
    request first (module docstring)."""
    size = math.hypot(ax, ay)
    want = math.degrees(math.atan2(ay, ax))
    remaining = wrap(want - body)
    dash_now = _progress(vx, vy, body, want, size, False, effort, player, rules, horizon)
    turn_first = _progress(vx, vy, body, want, size, True, effort, player, rules, horizon)
    if abs(remaining) > ALIGNED and turn_first > dash_now:
        return Run(True, moment=turn_moment(remaining, math.hypot(vx, vy), player, rules))
    direction = dash_direction(remaining, rules)
    return Run(False, power=dash_power(size, direction, effort, player, rules), direction=direction)


def neck_moment(neck: float, body_after: float, ball_direction: float, rules: ServerRules) -> float:
    """The ``turn_neck`` moment that points the face at ``ball_direction`` (the frame of
    ``body_after``, the body's direction after this cycle's turn; NaN: the ball is unknown,
    and the neck swings to its other end) for a neck now at ``neck`` degrees to the body."""
    if math.isfinite(ball_direction):
        target = clamp(wrap(ball_direction - body_after), rules.min_neck_angle, rules.max_neck_angle)
    else:
        target = rules.max_neck_angle if neck <= 0.0 else rules.min_neck_angle
    return clamp(target - neck, rules.min_neck_moment, rules.max_neck_moment)
