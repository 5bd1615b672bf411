"""Tackles, frozen players and players sent off: the tackle phase of a match cycle.

rcssserver's ``(tackle DIR [on|off])`` (``TeamCommand.tackle`` and ``TeamCommand.foul``), as
its ``Player::tackle`` computes it, with the parameters of :class:`~soccer_sim.config.TackleConfig`:

* **Reach.** The ball's centre relative to the tackler's, in the frame of the tackler's body
  (x ahead, y to the side; where the body faces is :func:`soccer_sim.body.facing`: at rest
  the player faces the ball), gives the failure probability
  ``(x / tackle_dist)^e + (|y| / tackle_width)^e`` (``x / tackle_back_dist`` for a ball
  behind, never reached with the default 0). ``e`` is ``tackle_exponent``, or
  ``foul_exponent`` for a foul tackle while an opponent can kick the ball (within its type's
  kickable distance; otherwise the foul flag is dropped, as rcssserver does).
* **Push.** A successful tackle in direction ``d`` pushes the ball with
  ``(max_back_tackle_power + (max_tackle_power - max_back_tackle_power) * (1 - |a| / 180°))
  * tackle_power_rate * (1 - 0.5 * |b| / 180°)`` m/cycle towards ``d``, where ``a`` is ``d``
  relative to the body and ``b`` the ball's direction relative to the body, plus a noise of
  up to ``kick_rand * tackle_rand_factor * (pos_rate + speed_rate)`` in a uniform direction
  (``kick_rand`` is the kick noise :attr:`~soccer_sim.config.PhysicsConfig.kick_rand`, as
  rcssserver scales the player type's ``kick_rand``; ``pos_rate = 0.5 + 0.5 * success probability``, ``speed_rate = 0.5 + 0.5 * ball speed /
  (ball_speed_max * ball_decay)``). The push is capped at ``kick_speed_max`` (rcssserver's
  ``ball_accel_max``) and added to the ball's velocity after the cycle's kicks, the result
  capped at ``ball_speed_max``. A tackle succeeds only where its player may kick (the
  referee's kick mask): otherwise (the opponents' set play, the pause after a goal, a held
  ball) it does nothing, as rcssserver's tackles do nothing in its stopped play modes.
* **Freeze.** A tackling player neither dashes nor kicks in the cycle of its tackle and cannot
  act (dash, kick, tackle, catch) for ``tackle_cycles`` cycles in all, whether it reached the
  ball or not; a foul tackle that pushes the ball does not freeze the tackler. Players fouled
  by a foul tackle are frozen for ``foul_cycles`` (:mod:`soccer_sim.rules.fouls`).
* **Sent off.** A player sent off (:mod:`soccer_sim.rules.fouls`) is parked off the pitch
  (:func:`~soccer_sim.rules.fouls.parking_spot`) at the end of every cycle, still, and its
  commands are ignored; ``WorldState.present`` flags it.

A match that never sees a tackle does no work here beyond one check per cycle, and draws no
random numbers: its play is bit-identical to a match without tackles.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from soccer_sim.body import facing
from soccer_sim.config import MatchConfig, TackleConfig
from soccer_sim.kernels import PT_INERTIA_MOMENT, PT_KICK_RAND, PT_KICKABLE
from soccer_sim.rules.fouls import park_absent
from soccer_sim.state import NO_PLAYER, WorldState


def failure_probability(x: float, y: float, tackle_dist: float, tackle_back_dist: float, tackle_width: float,
                        exponent: float) -> float:
    """rcssserver's tackle failure probability for the ball at (x, y) in the tackler's body
    frame (x ahead); 1 or more means the tackle cannot succeed."""
    reach = tackle_dist if x > 0.0 else tackle_back_dist
    if abs(reach) <= 1.0e-5:
        return 1.0
    return (abs(x) / reach) ** exponent + (abs(y) / tackle_width) ** exponent


def body_frame_failure(cfg: TackleConfig, to_ball_x: float, to_ball_y: float, vx: float, vy: float,
                       inertia_moment: float, foul: bool) -> tuple[float, float, float, float, float]:
    """A tackle's failure probability for a tackler with velocity ``(vx, vy)`` (m/cycle) and the
    ball at ``(to_ball_x, to_ball_y)`` from it (m; any frame), its body facing as
    :func:`soccer_sim.body.facing` says: (failure probability, the ball's x ahead and y to the
    side in the body frame, the body direction's unit vector). ``foul``: a foul tackle on a
    ball an opponent can kick (``foul_exponent``). The one computation :class:`Tackles` and a
    team weighing a tackle both use."""
    fx, fy = facing(vx, vy, to_ball_x, to_ball_y, inertia_moment)
    x, y = to_ball_x * fx + to_ball_y * fy, to_ball_y * fx - to_ball_x * fy  # the ball in the body frame
    exponent = cfg.foul_exponent if foul else cfg.tackle_exponent
    return failure_probability(x, y, cfg.tackle_dist, cfg.tackle_back_dist, cfg.tackle_width, exponent), x, y, fx, fy


def push_acceleration(cfg: TackleConfig, relative: float, ball_angle: float) -> float:
    """The push (m/cycle, before the noise) of a successful tackle in a direction ``relative``
    radians from the body (|relative| <= pi) on a ball ``ball_angle`` radians (|.| <= pi) off
    the body's direction: hardest straight ahead, ``max_back_tackle_power`` straight back."""
    power = cfg.max_back_tackle_power + (cfg.max_tackle_power - cfg.max_back_tackle_power) * (
        1.0 - abs(relative) / math.pi)
    return power * cfg.tackle_power_rate * (1.0 - 0.5 * abs(ball_angle) / math.pi)


@dataclass
class TackleOutcome:
    """The tackles of one cycle, for the referee (rows are player rows, home first)."""

    rows: list[int] = field(default_factory=list)
    """Every player that tackled, in row order."""
    reached: list[bool] = field(default_factory=list)
    """Per tackler: the success draw came out (the tackle reached the ball)."""
    fouls: list[bool] = field(default_factory=list)
    """Per tackler: a foul tackle (the flag kept only while an opponent could kick the ball)."""
    pushers: list[int] = field(default_factory=list)
    """The tacklers whose tackle pushed the ball (reached it where they may kick)."""
    dashed: np.ndarray | None = None
    """(P,) bool: which players dashed in this cycle or the one before (rcssserver's
    ``dashed()`` in its foul check: true from a dash until the end of the next cycle; the
    server counts a dash of the tackle's own cycle only when it was received before the
    tackle, and a cycle's commands here have no order, so all of them count)."""


class Tackles:
    """The tackle phase of one match: resolves tackle commands, keeps frozen players still and
    sent-off players parked. ``rng`` draws the tackles' success and noise (and the referee's
    foul decisions share it), so a match without tackles never draws from it."""

    def __init__(self, config: MatchConfig, state: WorldState, goalie_rows: Sequence[int],
                 rng: np.random.Generator, types: np.ndarray | None = None) -> None:
        self.config = config.tackles
        self._physics = config.physics
        self._inertia = config.physics.inertia_moment
        self._kickable = config.physics.kickable_distance
        self._goalie_rows = tuple(goalie_rows)
        self._home = state.sizes[0]
        self._parking_field = config.field
        self._pushes: list[tuple[float, float]] = []
        self.types = types
        """Each player row's type parameters (:attr:`soccer_sim.kinematics.Kinematics.types`,
        which the match's kinematics keep up to date): the tackler's ``inertia_moment`` and
        ``kick_rand``; None: the physics config's."""
        self.rng = rng
        self.busy = False
        """Whether any player is frozen or sent off (then every cycle has work to do)."""

    # ------------------------------------------------------------------ asked by the match loop
    def resolve(self, state: WorldState, tackle: np.ndarray, foul: np.ndarray, tackling: bool,
                commands: np.ndarray, catch: np.ndarray, mask: np.ndarray) -> TackleOutcome | None:
        """Before the kicks: ignore the commands of frozen and absent players (their rows of
        ``commands``, (P, 4), zeroed; their goalkeeper's ``catch`` request dropped), then
        resolve the tackles asked for (``tackle``: (P,) absolute directions in radians, NaN for
        none; ``foul``: (P,) flags; ``tackling``: whether any is asked). The ball is not pushed
        yet (:meth:`push`). None when nobody tackled."""
        if self.busy:
            if not state.present.all():
                park_absent(state, self._home, self._parking_field)  # a kick-off move may have placed them
            idle = (state.frozen > 0) | ~state.present
            if idle.any():
                commands[idle] = 0.0
                for team, row in enumerate(self._goalie_rows):
                    if row != NO_PLAYER and idle[row]:
                        catch[team] = False
                if tackling:
                    tackle = np.where(idle, np.nan, tackle)
        if not tackling or not self.config.enabled:
            return None
        rows = np.flatnonzero(np.isfinite(tackle))
        if rows.size == 0:
            return None
        outcome = TackleOutcome(dashed=np.any(commands[:, 0:2] != 0.0, axis=1) | state.dashed_before)
        outcome.dashed[rows] = False
        commands[rows] = 0.0  # a tackle is the player's one command of the cycle
        kickable = self._opponents_can_kick(state)
        cfg = self.config
        for row in rows.tolist():
            intentional = bool(foul[row]) and kickable[0 if row >= self._home else 1]
            reached, push = self._tackle(state, row, float(tackle[row]), intentional)
            outcome.rows.append(row)
            outcome.reached.append(reached)
            outcome.fouls.append(intentional)
            pushes = reached and bool(mask[row])
            state.frozen[row] = 0 if (pushes and intentional) else cfg.tackle_cycles
            if pushes:
                outcome.pushers.append(row)
                self._pushes.append(push)
        self.busy = True
        return outcome

    def push(self, state: WorldState, outcome: TackleOutcome, kicked: bool) -> None:
        """After the kicks: the successful tackles push the ball (see the module docstring);
        the last touch goes to the pusher nearest the ball unless a kick was taken."""
        if not outcome.pushers:
            return
        ax = sum(p[0] for p in self._pushes)
        ay = sum(p[1] for p in self._pushes)
        self._pushes.clear()
        physics = self._physics
        accel = math.hypot(ax, ay)
        if accel > physics.kick_speed_max:
            ax *= physics.kick_speed_max / accel
            ay *= physics.kick_speed_max / accel
        vx, vy = float(state.ball_vel[0]) + ax, float(state.ball_vel[1]) + ay
        speed = math.hypot(vx, vy)
        if speed > physics.ball_speed_max:
            vx *= physics.ball_speed_max / speed
            vy *= physics.ball_speed_max / speed
        state.ball_vel[0], state.ball_vel[1] = vx, vy
        if not kicked:
            rows = outcome.pushers
            d = np.hypot(state.pos[rows, 0] - state.ball[0], state.pos[rows, 1] - state.ball[1])
            state.last_touch = int(rows[int(np.argmin(d))])

    def end_cycle(self, state: WorldState) -> None:
        """End of a cycle while :attr:`busy`: frozen counts fall by one, sent-off players are
        put back on their parking spots (the referee may have moved them)."""
        frozen = state.frozen
        np.subtract(frozen, 1, out=frozen, where=frozen > 0)
        absent = not state.present.all()
        if absent:
            park_absent(state, self._home, self._parking_field)
        self.busy = absent or bool(frozen.any())

    # ------------------------------------------------------------------ the rules
    def _tackle(self, state: WorldState, row: int, direction: float,
                intentional: bool) -> tuple[bool, tuple[float, float]]:
        """One tackle: whether it reached the ball, and the push it gives it then."""
        cfg = self.config
        px, py = float(state.pos[row, 0]), float(state.pos[row, 1])
        dx, dy = float(state.ball[0]) - px, float(state.ball[1]) - py
        types = self.types
        inertia = self._inertia if types is None else float(types[row, PT_INERTIA_MOMENT])
        kick_rand = self._physics.kick_rand if types is None else float(types[row, PT_KICK_RAND])
        prob, x, y, fx, fy = body_frame_failure(cfg, dx, dy, float(state.vel[row, 0]), float(state.vel[row, 1]),
                                                inertia, intentional)
        if prob >= 1.0 or self.rng.random() >= 1.0 - prob:
            return False, (0.0, 0.0)
        body = math.atan2(fy, fx)
        relative = math.remainder(direction - body, 2.0 * math.pi)  # (-pi, pi]: the direction from the body
        accel = push_acceleration(cfg, relative, math.atan2(y, x))
        physics = self._physics
        pos_rate = 0.5 + 0.5 * (1.0 - prob)
        speed_rate = 0.5 + 0.5 * math.hypot(state.ball_vel[0], state.ball_vel[1]) / (
            physics.ball_speed_max * physics.ball_decay)
        noise = self.rng.uniform(0.0, kick_rand * cfg.tackle_rand_factor * (pos_rate + speed_rate))
        noise_dir = self.rng.uniform(-math.pi, math.pi)
        return True, (accel * math.cos(direction) + noise * math.cos(noise_dir),
                      accel * math.sin(direction) + noise * math.sin(noise_dir))

    def _opponents_can_kick(self, state: WorldState) -> tuple[bool, bool]:
        """(home, away): whether a present player of that team has the ball within its own
        kickable distance (its type's, as rcssserver's ``ballKickable``)."""
        d = np.hypot(state.pos[:, 0] - state.ball[0], state.pos[:, 1] - state.ball[1])
        kickable = self._kickable if self.types is None else self.types[:, PT_KICKABLE]
        near = (d <= kickable) & state.present
        home = self._home
        return bool(near[:home].any()), bool(near[home:].any())
