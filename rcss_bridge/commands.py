"""Commands to the server: one team's :class:`~soccer_sim.team.TeamCommand` for a step as
each player's order for rcssserver (:class:`~rcss_bridge.client.PlayerOrder`).

rcssserver executes one body command per player and step (``kick``, ``dash``, ``turn``,
``tackle``, ``catch``, ``move``: the first it receives). The simulator keeps, of what a team
asks one player, the command of highest priority, tackle > catch > kick > move > dash
(:func:`soccer_sim.kernels.one_body_command`); the translation asks that same kernel, so both
engines drop the same commands, then writes the one left in the server's terms, relative to
the player's body (:class:`PlayerBodies`: what each player knows of itself from its views):

* **tackle**: ``(tackle DIR on|off)``, DIR the tackle's direction (team frame) less the body's,
  within ``minmoment`` / ``maxmoment``; ``on`` for a foul tackle.
* **catch** (the goalkeeper's row only, as in the simulator): ``(catch DIR)`` towards the
  ball, within ``min_catch_angle`` / ``max_catch_angle`` (the catchable area's reach round
  the body); straight ahead when the ball is unknown.
* **kick**: ``(kick POWER DIR)``, DIR the kick vector's direction less the body's. The power
  gives the ball the change the simulator would have given it: the request clipped to
  ``kick_speed_max``, times the simulator's kick rate (the ball's distance and its angle to
  the body of :mod:`soccer_sim.body`'s model), over the player type's ``kick_power_rate``
  times the server's rate for the ball's place relative to the real body
  (:mod:`soccer_sim.kick_rate` for both: one formula); within ``maxpower``. A goalkeeper
  holding the ball kicks at full rate in both (the held ball lies touching the front of the
  body). With the ball's place unknown, or beyond the kickable distance (where the server
  does not kick: the command is spent all the same), the two rates are taken as equal.
* **move**: ``(move X Y)`` (the team frame is the server's for a move, both sides) only where
  the server allows one: before kick-off and after a goal (``before_kick_off``, ``goal_l``,
  ``goal_r``), and for the goalkeeper while it holds the ball, at most ``goalie_max_moves``
  times after each catch. Elsewhere the move is no command (as in the simulator) and the
  next one in priority is taken.
* **dash**: a turn or ``(dash POWER DIR)`` by :func:`~rcss_bridge.body_control.choose_run`.
* **nothing asked**: the body is turned to where :mod:`soccer_sim.body`'s model says a body
  faces (towards the ball, as far as the player's speed lets it turn), so that the real body
  and the modelled one agree as often as a free command allows.

Then the view width: ``(change_view narrow|normal|wide)`` when the command's ``change_view``
asks a player for a width other than the one its last ``sense_body`` told. Then the neck: the
command's own ``turn_neck`` when it has one (``(turn_neck MOMENT)`` within
``minneckmoment`` / ``maxneckmoment``; none for NaN or 0: the simulator's rule, so a team that
chooses where to look looks there on the server too), else a ``(turn_neck MOMENT)`` that keeps
the ball in view (:func:`~rcss_bridge.body_control.neck_moment`: the simulator's players that
never turn their neck look along a body that faces the ball). Then the say, sent quoted by the
client layer.
A player not present or frozen (after a tackle or a foul) sends no body command; one whose
body direction is not known yet (no see with flags so far) only a move.

Commands are counted (:attr:`CommandTranslator.sent`, by the server's names, ``dropped`` for
commands the priority left out, ``unaimed`` for those without a known body). Bad input is a
:class:`~rcss_bridge.errors.CommandError` naming the team and the player.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from soccer_sim.body import ball_angle_to_body, facing, turn_angle
from soccer_sim.config import MatchConfig
from soccer_sim.kernels import one_body_command
from soccer_sim.kick_rate import kick_angle_rate, kick_distance_rate, kick_effectiveness
from soccer_sim.perception.views import PlayerViews
from soccer_sim.player_types import PlayerType, check_choice, default_type
from soccer_sim.perception.view_width import KEEP, NORMAL, VIEW_WIDTHS, check_view_widths
from soccer_sim.team import TeamCommand, TeamError, command_array

from rcss_bridge.body_control import RUN_HORIZON, ServerRules, choose_run, clamp, neck_moment, turn_moment
from rcss_bridge.errors import CommandError
from rcss_bridge.localisation import wrap
from rcss_bridge.orders import PlayerOrder

MOVE_MODES = frozenset({"before_kick_off", "goal_l", "goal_r"})
"""rcssserver's play modes in which every player may ``move`` (``Player::move``); besides
them only the goalkeeper holding the ball may, ``goalie_max_moves`` times."""

BALL_LOOK_STEPS = 4
"""Steps after a player last saw the ball itself during which its neck follows the ball it
believes in (two sees at the normal view width); later it looks around until it sees the ball."""

DECIMALS = 2
"""Decimals of the numbers the translation writes (powers, degrees, metres)."""


def number(value: float) -> str:
    """``value`` as the translation writes it: rounded to :data:`DECIMALS`, no exponent, no
    ``-0``."""
    text = f"{round(value, DECIMALS) + 0.0:.{DECIMALS}f}".rstrip("0").rstrip(".")
    return "0" if text in ("", "-0") else text


@dataclass(eq=False)
class PlayerBodies:
    """What each of a team's ``n`` players knows of itself at a step (team frame, as the
    views; row ``i`` is shirt ``i + 1``)."""

    body_direction: np.ndarray
    """(n,) the body's direction (degrees; NaN: not known yet)."""
    neck: np.ndarray
    """(n,) the neck: the face's angle to the body (degrees; ``sense_body``'s ``head_angle``)."""
    velocity: np.ndarray
    """(n, 2) the sensed velocity (m/cycle)."""
    ball_offset: np.ndarray
    """(n, 2) where the player believes the ball lies from itself (m; NaN: unknown)."""
    effort: np.ndarray
    """(n,) effort (the share of a dash's power that counts)."""
    types: np.ndarray
    """(n,) each player's type id."""
    present: np.ndarray
    """(n,) bool: connected and not sent off."""
    frozen: np.ndarray
    """(n,) steps each player still cannot act."""
    holds_ball: np.ndarray
    """(n,) bool: the goalkeeper holds the ball."""
    view_width: np.ndarray | None = None
    """(n,) each player's view width code as its last ``sense_body`` told it
    (:mod:`soccer_sim.perception.view_width`; None: all ``normal``)."""
    ball_unseen: np.ndarray | None = None
    """(n,) steps since each player last saw the ball itself (0: this step; None: all 0). The
    neck follows the believed ball for :data:`BALL_LOOK_STEPS` steps after that, then looks
    around: a belief nobody refreshes (the ball moved out of everybody's sight) must not keep
    every eye away from the ball."""

    @classmethod
    def from_views(cls, views: PlayerViews, necks: np.ndarray, ball: np.ndarray | None = None,
                   ball_unseen: np.ndarray | None = None) -> PlayerBodies:
        """From a step's views (:class:`~rcss_bridge.views_builder.ViewsBuilder`), the necks it
        keeps (:attr:`~rcss_bridge.views_builder.ViewsBuilder.necks`), where each player
        believes the ball is (``ball`` (n, 2) team frame; None: where it saw it this step) and
        the steps since each saw it (:attr:`~rcss_bridge.views_builder.ViewsBuilder.ball_unseen`)."""
        ball = views.ball if ball is None else np.asarray(ball, dtype=np.float64)
        if ball.shape != views.position.shape:
            raise CommandError("?", f"ball must have shape {views.position.shape}, got {ball.shape}")
        effort = np.where(np.isfinite(views.effort), views.effort, 1.0)
        velocity = np.where(np.isfinite(views.velocity), views.velocity, 0.0)
        return cls(body_direction=views.body_direction.copy(), neck=np.asarray(necks, dtype=np.float64).copy(),
                   velocity=velocity, ball_offset=ball - views.position, effort=effort,
                   types=views.player_types.copy(), present=views.present.copy(), frozen=views.frozen.copy(),
                   holds_ball=views.holds_ball.copy(), view_width=views.view_width.copy(),
                   ball_unseen=None if ball_unseen is None else np.asarray(ball_unseen, dtype=np.int64).copy())


class CommandTranslator:
    """One team's commands in the server's terms, step by step (module docstring).

    ``types``: the server's player types by id; ``config``: the match's configuration (the
    server's, :meth:`~rcss_bridge.params.ServerParameters.match_config`: kick limits and
    penalties, radii); ``goalie``: the goalkeeper's row; ``horizon``: the run the body
    controller plans for (:data:`~rcss_bridge.body_control.RUN_HORIZON`)."""

    def __init__(self, team_name: str, players: int, rules: ServerRules, types: Sequence[PlayerType],
                 config: MatchConfig, goalie: int = 0, horizon: int = RUN_HORIZON) -> None:
        if not types:
            raise CommandError(team_name, "the server's player types are needed (none given)")
        if not 0 <= goalie < players:
            raise CommandError(team_name, f"goalkeeper row {goalie} is not a row of {players} players")
        self.team_name = team_name
        self.n = players
        self.rules = rules
        self.types = tuple(types)
        self.config = config
        self.goalie = goalie
        self.horizon = horizon
        self.sent: Counter[str] = Counter()
        """Commands sent so far by the server's names; ``dropped``: commands the one-body
        rule left out; ``unaimed``: commands not sent for want of a known body direction."""
        self.turns = np.zeros(players)
        """(n,) the body turn (degrees) each player's order of the last :meth:`translate`
        makes (0 for none): ``MOMENT / (1 + inertia_moment x speed)``, what the views
        builder turns the body by until the next see (:meth:`~rcss_bridge.views_builder.ViewsBuilder.turned`)."""
        self._goalie_moves = 0
        """Moves sent since the goalkeeper's last catch."""
        self._goalie_held = False

    # ------------------------------------------------------------------------------------
    def translate(self, command: TeamCommand, bodies: PlayerBodies, server_mode: str) -> dict[int, PlayerOrder]:
        """Each present player's order for this step (rows absent or sent off get none).
        ``server_mode``: the server's play mode as last heard
        (:attr:`~rcss_bridge.play_modes.RefereeState.server_mode`)."""
        dash, kick, move, tackle, foul, catch, say, turn_neck, widths = self._read(command)
        self._check_bodies(bodies)
        holding = bool(bodies.holds_ball[self.goalie])
        if holding and not self._goalie_held:
            self._goalie_moves = 0
        self._goalie_held = holding
        allowed = np.zeros(self.n, dtype=bool)
        if move is not None:
            if server_mode in MOVE_MODES:
                allowed[:] = True
            elif holding and self._goalie_moves < self.rules.goalie_max_moves:
                allowed[self.goalie] = True
        acting = bodies.present & (bodies.frozen <= 0)
        rows = np.concatenate([dash, kick], axis=1)
        rows[~acting] = 0.0
        tackles = np.where(acting, tackle, np.nan)
        catches = np.array([catch and bool(acting[self.goalie]), False])
        moving = allowed & acting
        ignored = np.zeros(2, dtype=np.int64)
        one_body_command(rows, tackles, catches, np.array([self.goalie, -1], dtype=np.int64), moving, self.n,
                         ignored)
        self.sent["dropped"] += int(ignored[0])
        orders: dict[int, PlayerOrder] = {}
        self.turns = np.zeros(self.n)
        for row in range(self.n):
            if not bodies.present[row]:
                continue
            turned = 0.0
            if not math.isnan(tackles[row]):
                body = self._tackle(row, tackles[row], bool(foul[row]), bodies)
            elif row == self.goalie and catches[0]:
                body = self._catch(row, bodies)
            elif rows[row, 2] != 0.0 or rows[row, 3] != 0.0:
                body = self._kick(row, rows[row, 2], rows[row, 3], bodies)
            elif moving[row]:
                body = f"(move {number(move[row, 0])} {number(move[row, 1])})"
                if row == self.goalie and server_mode not in MOVE_MODES:
                    self._goalie_moves += 1
            elif rows[row, 0] != 0.0 or rows[row, 1] != 0.0:
                body, turned = self._dash(row, rows[row, 0], rows[row, 1], bodies)
            elif acting[row]:
                body, turned = self._face_ball(row, bodies)
            else:
                body = ""
            if body:
                self.sent[body[1:body.index(" ")]] += 1
            if turned:
                self.turns[row] = self._turn_angle(row, turned, bodies)
            neck = (self._neck(row, self.turns[row], bodies) if turn_neck is None
                    else self._turn_neck(float(turn_neck[row])))
            view = "" if widths is None else self._change_view(row, int(widths[row]), bodies)
            orders[row] = PlayerOrder(body + view + neck, None if say is None else say[row])
        return orders

    # ------------------------------------------------------------------------------ input
    def _read(self, command: object) -> tuple:
        """The command's parts as arrays, checked as the simulator checks them."""
        if not isinstance(command, TeamCommand):
            raise CommandError(self.team_name, f"expected a TeamCommand, got {type(command).__name__}")
        dash = self._vectors(command.dash, "dash")
        kick = self._vectors(command.kick, "kick")
        move = None if command.move is None else self._vectors(command.move, "move")
        tackle = np.full(self.n, np.nan)
        if command.tackle is not None:
            tackle = self._angles(command.tackle, "tackle")
        foul = np.zeros(self.n, dtype=bool)
        if command.foul is not None:
            flags = np.asarray(command.foul)
            if flags.shape != (self.n,) or flags.dtype.kind not in "bi":
                raise CommandError(self.team_name, f"command.foul must be a bool array of shape {(self.n,)}, "
                                   f"got {flags.dtype} of shape {flags.shape}")
            foul = flags != 0
        catch = command.catch
        if isinstance(catch, np.bool_ | bool) or (isinstance(catch, int | np.integer) and catch in (0, 1)):
            catch = bool(catch)
        else:
            raise CommandError(self.team_name, f"command.catch must be a bool, got {catch!r}")
        say = command.say
        if say is not None and (isinstance(say, str | bytes) or not hasattr(say, "__len__") or len(say) != self.n):
            raise CommandError(self.team_name, f"command.say must be a sequence of {self.n} messages (str or None)")
        turn_neck = None if command.turn_neck is None else self._angles(command.turn_neck, "turn_neck")
        widths = None
        if command.change_view is not None:
            widths = check_view_widths(command.change_view, self.n)
            if isinstance(widths, str):
                raise CommandError(self.team_name, widths)
        return dash, kick, move, tackle, foul, catch, say, turn_neck, widths

    def _array(self, values: object, name: str, shape: tuple[int, ...]) -> np.ndarray:
        return command_array(values, name, shape, lambda message: CommandError(self.team_name, message)).copy()

    def _angles(self, values: object, name: str) -> np.ndarray:
        """One angle per player (degrees, NaN allowed), checked as the simulator checks them."""
        array = self._array(values, name, (self.n,))
        bad = np.flatnonzero(np.isinf(array))
        if bad.size:
            raise CommandError(self.team_name, f"command.{name} is infinite: {array[bad[0]]}", int(bad[0]))
        return array

    def _vectors(self, values: object, name: str) -> np.ndarray:
        array = self._array(values, name, (self.n, 2))
        bad = np.flatnonzero(~np.isfinite(array).all(axis=1))
        if bad.size:
            raise CommandError(self.team_name, f"command.{name} is not finite: {array[bad[0]].tolist()}", int(bad[0]))
        return array

    def _check_bodies(self, bodies: PlayerBodies) -> None:
        if not isinstance(bodies, PlayerBodies):
            raise CommandError(self.team_name, f"expected PlayerBodies, got {type(bodies).__name__}")
        for name, shape in (("body_direction", (self.n,)), ("neck", (self.n,)), ("velocity", (self.n, 2)),
                            ("ball_offset", (self.n, 2)), ("effort", (self.n,)), ("types", (self.n,)),
                            ("present", (self.n,)), ("frozen", (self.n,)), ("holds_ball", (self.n,))):
            shape_seen = np.shape(getattr(bodies, name))
            if shape_seen != shape:
                raise CommandError(self.team_name, f"bodies.{name} must have shape {shape}, got {shape_seen}")
        if bodies.view_width is not None and np.shape(bodies.view_width) != (self.n,):
            raise CommandError(self.team_name, f"bodies.view_width must have shape {(self.n,)}, "
                               f"got {np.shape(bodies.view_width)}")
        bad = [int(t) for t in bodies.types if not 0 <= int(t) < len(self.types)]
        if bad:
            raise CommandError(self.team_name, f"player type {bad[0]} is not one of the server's "
                               f"{len(self.types)} types")

    # ------------------------------------------------------------------------------ commands
    def _aimed(self, row: int, bodies: PlayerBodies) -> float | None:
        """The row's body direction, or None (counted as ``unaimed``) when not known yet."""
        body = float(bodies.body_direction[row])
        if math.isfinite(body):
            return body
        self.sent["unaimed"] += 1
        return None

    def _ball(self, row: int, bodies: PlayerBodies) -> tuple[float, float] | None:
        x, y = (float(v) for v in bodies.ball_offset[row])
        return (x, y) if math.isfinite(x) and math.isfinite(y) else None

    def _tackle(self, row: int, direction: float, foul: bool, bodies: PlayerBodies) -> str:
        body = self._aimed(row, bodies)
        if body is None:
            return ""
        relative = clamp(wrap(direction - body), self.rules.min_moment, self.rules.max_moment)
        return f"(tackle {number(relative)} {'on' if foul else 'off'})"

    def _catch(self, row: int, bodies: PlayerBodies) -> str:
        body = self._aimed(row, bodies)
        if body is None:
            return ""
        ball = self._ball(row, bodies)
        relative = 0.0 if ball is None else wrap(math.degrees(math.atan2(ball[1], ball[0])) - body)
        return f"(catch {number(clamp(relative, self.rules.min_catch_angle, self.rules.max_catch_angle))})"

    def _kick(self, row: int, kx: float, ky: float, bodies: PlayerBodies) -> str:
        body = self._aimed(row, bodies)
        if body is None:
            return ""
        player = self.types[int(bodies.types[row])]
        request = min(math.hypot(kx, ky), self.config.physics.kick_speed_max)
        ratio = 1.0
        ball = self._ball(row, bodies)
        reach = player.player_size + self.config.physics.ball_radius + player.kickable_margin
        if ball is not None and not bodies.holds_ball[row] and math.hypot(*ball) <= reach:
            ratio = self.simulator_kick_rate(row, ball, bodies) / self.server_kick_rate(row, ball, body, bodies)
        power = clamp(request * ratio / player.kick_power_rate, 0.0, self.rules.max_power)
        relative = clamp(wrap(math.degrees(math.atan2(ky, kx)) - body), self.rules.min_moment, self.rules.max_moment)
        return f"(kick {number(power)} {number(relative)})"

    def simulator_kick_rate(self, row: int, ball: tuple[float, float], bodies: PlayerBodies) -> float:
        """The share of a kick the simulator gives the ball at ``ball`` (offset from the
        player, m): its kick rate with the body of :mod:`soccer_sim.body`'s model."""
        phys, player = self.config.physics, self.types[int(bodies.types[row])]
        vx, vy = (float(v) for v in bodies.velocity[row])
        angle = ball_angle_to_body(vx, vy, ball[0], ball[1], player.inertia_moment)
        distance = kick_distance_rate(math.hypot(*ball), phys.player_radius + phys.ball_radius, player.kickable_margin)
        return kick_effectiveness(distance, kick_angle_rate(angle), phys.kick_distance_penalty,
                                  phys.kick_angle_penalty)

    def server_kick_rate(self, row: int, ball: tuple[float, float], body: float, bodies: PlayerBodies) -> float:
        """The share of a kick rcssserver gives the ball at ``ball`` (offset from the player,
        m) for a body at ``body`` degrees (``Player::kick``'s rate; the same formula)."""
        phys, player = self.config.physics, self.types[int(bodies.types[row])]
        dir_diff = abs(wrap(math.degrees(math.atan2(ball[1], ball[0])) - body))
        distance = kick_distance_rate(math.hypot(*ball), player.player_size + phys.ball_radius, player.kickable_margin)
        rate = kick_effectiveness(distance, kick_angle_rate(math.radians(dir_diff)), phys.kick_distance_penalty,
                                  phys.kick_angle_penalty)
        return max(rate, 1e-9)

    def _dash(self, row: int, ax: float, ay: float, bodies: PlayerBodies) -> tuple[str, float]:
        """A dash request as a dash or a turn (:func:`~rcss_bridge.body_control.choose_run`),
        and the turn's moment (0 for a dash)."""
        body = self._aimed(row, bodies)
        if body is None:
            return "", 0.0
        player = self.types[int(bodies.types[row])]
        vx, vy = (float(v) for v in bodies.velocity[row])
        run = choose_run(ax, ay, body, vx, vy, float(bodies.effort[row]), player, self.rules, self.horizon)
        if run.turn:
            return self._turn(run.moment)
        return f"(dash {number(run.power)} {number(run.direction)})", 0.0

    def _face_ball(self, row: int, bodies: PlayerBodies) -> tuple[str, float]:
        """A free body command: turn to where :mod:`soccer_sim.body`'s model faces (the ball,
        as far as the speed lets the body turn), and the turn's moment."""
        body = float(bodies.body_direction[row])
        ball = self._ball(row, bodies)
        if not math.isfinite(body) or ball is None:
            return "", 0.0
        player = self.types[int(bodies.types[row])]
        vx, vy = (float(v) for v in bodies.velocity[row])
        fx, fy = facing(vx, vy, ball[0], ball[1], player.inertia_moment)
        angle = wrap(math.degrees(math.atan2(fy, fx)) - body)
        return self._turn(turn_moment(angle, math.hypot(vx, vy), player, self.rules))

    @staticmethod
    def _turn(moment: float) -> tuple[str, float]:
        """``(turn MOMENT)`` as written, and the moment the server reads; nothing for a
        moment that rounds to zero."""
        text = number(moment)
        return ("", 0.0) if text == "0" else (f"(turn {text})", float(text))

    def _change_view(self, row: int, width: int, bodies: PlayerBodies) -> str:
        """``(change_view WIDTH)`` for a width code other than :data:`KEEP` and the player's own."""
        current = NORMAL if bodies.view_width is None else int(bodies.view_width[row])
        if width == KEEP or width == current:
            return ""
        return f"(change_view {VIEW_WIDTHS[width]})"

    def _turn_neck(self, moment: float) -> str:
        """The command's own neck turn (degrees; NaN or 0: none) as ``(turn_neck MOMENT)``
        within ``minneckmoment`` / ``maxneckmoment``."""
        if math.isnan(moment):
            return ""
        text = number(clamp(moment, self.rules.min_neck_moment, self.rules.max_neck_moment))
        return "" if text == "0" else f"(turn_neck {text})"

    def _turn_angle(self, row: int, moment: float, bodies: PlayerBodies) -> float:
        """The body turn (degrees) a ``(turn MOMENT)`` makes at the player's speed."""
        player = self.types[int(bodies.types[row])]
        return turn_angle(moment, math.hypot(*(float(v) for v in bodies.velocity[row])), player.inertia_moment)

    def _neck(self, row: int, turn: float, bodies: PlayerBodies) -> str:
        """The ``turn_neck`` that keeps the ball in view after this step's body turn of
        ``turn`` degrees (0: none)."""
        body = float(bodies.body_direction[row])
        if not math.isfinite(body):
            return ""
        body += turn
        ball = self._ball(row, bodies)
        stale = bodies.ball_unseen is not None and bodies.ball_unseen[row] > BALL_LOOK_STEPS
        direction = math.nan if ball is None or stale else math.degrees(math.atan2(ball[1], ball[0]))
        moment = neck_moment(float(bodies.neck[row]), body, direction, self.rules)
        return f"(turn_neck {number(moment)})" if number(moment) != "0" else ""


def player_type_commands(choice: object, types: Sequence[PlayerType], players: int, pt_max: int,
                         team_name: str) -> list[str]:
    """The online coach's ``(change_player_type UNUM TYPE)`` for every player of a team's
    ``choose_player_types`` choice (checked as the simulator checks it: ``players`` type ids
    of the server's ``types``, at most ``pt_max`` of one non-default type). Every player gets
    one, type 0 included: without it the server gives the players it was not told about types
    of its own at kick-off."""
    try:
        ids = check_choice(choice, tuple(types), players, pt_max, team_name)
    except TeamError as exc:
        raise CommandError(team_name, exc.message, exc.player) from None
    return [f"(change_player_type {row + 1} {int(type_id)})" for row, type_id in enumerate(ids)]


def warm_up() -> None:
    """Compile (or load from numba's cache) the kernels the translation calls, before any
    player connects (a step's first call must not spend the server's 1.25 s)."""
    rows = np.zeros((1, 4))
    one_body_command(rows, np.full(1, np.nan), np.zeros(2, dtype=bool), np.array([0, -1], dtype=np.int64),
                     np.zeros(1, dtype=bool), 1, np.zeros(2, dtype=np.int64))
    facing(0.0, 0.0, 1.0, 0.0, 5.0)
    ball_angle_to_body(0.0, 0.0, 1.0, 0.0, 5.0)
    turn_angle(1.0, 0.0, 5.0)
    kick_effectiveness(kick_distance_rate(0.5, 0.385, 0.7), kick_angle_rate(0.0), 0.25, 0.25)
    choose_run(0.6, 0.0, 0.0, 0.0, 0.0, 1.0, _WARM_TYPE, ServerRules(), 1)


_WARM_TYPE = default_type(MatchConfig())
"""A player type to call the kernels with in :func:`warm_up` (the default type)."""
