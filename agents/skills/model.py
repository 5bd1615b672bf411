"""The motion model the skills predict with, built once from a :class:`MatchConfig`.

Every number comes from the configuration (nothing is hard-coded), so the skills follow the
simulator's parameters. The rules mirrored here are those of :mod:`soccer_sim.kinematics`
(the RoboCup 2D soccer simulator's):

* **Player**, per cycle: ``vel += accel`` (``|accel| <= player_accel_max * effort``), speed
  clipped to ``player_speed_max``, ``pos += vel``, ``vel *= player_decay``. Without the clip
  the motion is linear, so after ``k`` cycles a player can be anywhere within a disc of
  radius ``reach(k) * effort`` around the point it would coast to,
  ``pos + vel * (1 - decay^k) / (1 - decay)``. :attr:`MotionModel.reach` tabulates
  ``reach(k)`` from rest at full effort (speed clip included). The weaker dash against the
  direction of motion (side/back dash rates) is left out of the predictions.
* **Ball**, per cycle: ``pos += vel``, ``vel *= ball_decay``; after ``k`` cycles it has
  travelled ``vel * (1 - decay^k) / (1 - decay)``.
* **Noise** (rcssserver's, as the simulator draws it): a kick adds a random vector of length
  uniform in ``[0, kick_rand * power / kick_speed_max * (pos_rate + speed_rate)]``, and every
  cycle the ball's velocity gets one of length uniform in ``[0, ball_rand * speed]``, both in
  a uniform direction. :meth:`MotionModel.kick_spread` turns them into the spread of where a
  kicked ball is after ``k`` cycles.

Frames: the team-relative frame of :class:`soccer_sim.TeamView` (we attack +x, our goal line
at ``x = -half_length``). Units: metres, cycles, m/cycle, m/cycle².
"""

from __future__ import annotations

import functools
import math

import numpy as np

from agents.errors import AgentsError
from agents.skills.ball_kernels import KICK_MODEL, kick_spreads
from agents.skills.interception_kernels import MotionTables
from soccer_sim.config import MatchConfig
from soccer_sim.kernels import make_record
from soccer_sim.team import SideInfo, TeamView


class SkillInputError(AgentsError, ValueError):
    """A skill was called with an impossible argument (wrong shape, index out of range, ...);
    the message names the argument."""


class MotionModel:
    """Constants and tables of one match configuration, shared by every skill.

    ``horizon`` is the number of cycles the predictions look ahead (interception, passes,
    shots); :attr:`reach` has ``horizon + 1`` entries. Both sides are given explicitly:
    ``players`` and ``goalie`` (-1: none) for ours, ``opponents`` and ``opponent_goalie`` for
    theirs. :meth:`for_side` takes them from a team's ``SideInfo`` (what ``Team.reset``
    receives); :meth:`even_sides` gives both sides the configuration's size and goalkeeper.
    Every physical and field number is read here, once, from the ``config``.
    """

    def __init__(self, config: MatchConfig, *, players: int, goalie: int, opponents: int, opponent_goalie: int,
                 horizon: int = 60) -> None:
        _check_config(config)
        if not (isinstance(horizon, (int, np.integer)) and not isinstance(horizon, bool) and horizon >= 1):
            raise SkillInputError(f"MotionModel.horizon must be a positive integer, got {horizon!r}")
        for name, count in (("players", players), ("opponents", opponents)):
            if isinstance(count, bool) or not isinstance(count, (int, np.integer)) or count < 0:
                raise SkillInputError(f"MotionModel.{name} must be an integer of at least 0, got {count!r}")
        for name, index, count in (("goalie", goalie, players), ("opponent_goalie", opponent_goalie, opponents)):
            if isinstance(index, bool) or not isinstance(index, (int, np.integer)) or not -1 <= index < count:
                raise SkillInputError(f"MotionModel.{name} must be -1 or a player index below {count}, got {index!r}")
        phys, field, rules = config.physics, config.field, config.rules
        self.config = config
        self.horizon = int(horizon)
        self.players_per_team = int(players)
        self.goalie_index = int(goalie)
        """Our goalkeeper's index, -1 when we have none."""
        self.opponents = int(opponents)
        """Players of the opposing side."""
        self.opponent_goalie_index = int(opponent_goalie)
        """The opponents' goalkeeper's index among them, -1 when they have none."""
        self.accel_max = float(phys.player_accel_max)
        """Largest dash acceleration at full effort (m/cycle²)."""
        self.speed_max = float(phys.player_speed_max)
        self.player_decay = float(phys.player_decay)
        self.ball_decay = float(phys.ball_decay)
        self.ball_speed_max = float(phys.ball_speed_max)
        self.kick_speed_max = float(phys.kick_speed_max)
        self.kickable_distance = float(phys.kickable_distance)
        """Centre distance within which a player may kick (m)."""
        self.touch_distance = float(phys.player_radius + phys.ball_radius)
        """Centre distance at which the ball touches a player's body (m)."""
        self.kickable_margin = float(phys.kickable_margin)
        self.kick_distance_penalty = float(phys.kick_distance_penalty)
        self.kick_angle_penalty = float(phys.kick_angle_penalty)
        self.inertia_moment = float(phys.inertia_moment)
        """rcssserver ``inertia_moment``: how speed limits a turn, so where a kicker's body faces
        (:mod:`soccer_sim.body`)."""
        self.kick_model = make_record(
            KICK_MODEL, kick_max=self.kick_speed_max, ball_max=self.ball_speed_max,
            distance_penalty=self.kick_distance_penalty, angle_penalty=self.kick_angle_penalty,
            kickable_margin=self.kickable_margin, touch=self.touch_distance, inertia_moment=self.inertia_moment)
        """The kick rule as the compiled kick kernels read it (a
        :data:`~agents.skills.ball_kernels.KICK_MODEL` record; never to be written)."""
        self.kick_rand = float(phys.kick_rand)
        """rcssserver ``kick_rand``: scale of the kick noise (m/cycle at full power, see :meth:`kick_spread`)."""
        self.ball_rand = float(phys.ball_rand)
        """rcssserver ``ball_rand``: the ball's movement noise per cycle, as a fraction of its speed."""
        self.kick_noise = float(phys.kick_noise)
        """The configuration's one-figure kick noise (radians; ``PhysicsConfig.kick_noise``), for
        callers that want no more; the skills use :meth:`kick_spread`."""
        self.half_length = float(field.half_length)
        self.half_width = float(field.half_width)
        self.goal_half_width = float(field.goal_width / 2.0)
        self.goal_post_radius = float(field.goal_post_radius)
        self.ball_radius = float(phys.ball_radius)
        self.penalty_area_length = float(field.penalty_area_length)
        self.penalty_area_half_width = float(field.penalty_area_width / 2.0)
        self.goal_area_length = float(field.goal_area_length)
        self.goal_area_half_width = float(field.goal_area_width / 2.0)
        self.catch_length = float(rules.catch_length)
        self.offside = bool(rules.offside)
        self.top_speed = min(self.speed_max, self.accel_max / (1.0 - self.player_decay)) \
            if self.player_decay < 1.0 else self.speed_max
        """Steady running speed at full effort (m/cycle): where acceleration and decay balance."""
        self.reach = self._reach_table(self.horizon)
        """(horizon + 1,) distance a player at rest covers in k cycles at full effort (m)."""
        k = np.arange(self.horizon + 1, dtype=np.float64)
        self.ball_travel = _geometric_sums(self.ball_decay, k)
        """(horizon + 1,) factor of the ball's velocity travelled in k cycles: (1 - d^k) / (1 - d)."""
        self.player_coast = _geometric_sums(self.player_decay, k)
        """(horizon + 1,) the same factor for a player's velocity (coasting without dashes)."""
        self.tables = MotionTables(self.reach, self.ball_travel, self.player_coast)
        """The three tables above as the compiled searches take them (the same arrays)."""
        self.ball_noise_gain = _ball_noise_table(self.ball_decay, self.horizon)
        """(horizon + 1,) ``sqrt(sum_j (d^j travel(k - j))^2)`` over ``j < k``: how the ball noise
        of the ``k`` cycles after a kick adds up in the ball's position (per unit of noise at the
        launch speed)."""
        stam = config.stamina
        self.stamina_max = float(stam.maximum)
        self.stamina_low = float(max(stam.recover_dec_thr, stam.effort_dec_thr) * stam.maximum)
        """Stamina below which recovery and effort start falling for good (see StaminaConfig)."""
        self.recovery_per_cycle = float(stam.recovery_per_cycle)
        self.dash_power_rate = float(phys.dash_power_rate)

    @classmethod
    def for_side(cls, config: MatchConfig, side: SideInfo, horizon: int = 60) -> MotionModel:
        """The model of a team that plays as ``side`` (its ``SideInfo``) under ``config``."""
        _check_config(config)
        return cls(config, players=side.players_per_team, goalie=side.goalie_index, opponents=side.opponents,
                   opponent_goalie=side.opponent_goalie_index, horizon=horizon)

    @classmethod
    def even_sides(cls, config: MatchConfig, horizon: int = 60) -> MotionModel:
        """The model for two sides of the configuration's size (``players_per_team``), each
        with its goalkeeper at ``rules.goalie_index``."""
        _check_config(config)
        n, goalie = config.players_per_team, config.rules.goalie_index
        return cls(config, players=n, goalie=goalie, opponents=n, opponent_goalie=goalie, horizon=horizon)

    def _reach_table(self, horizon: int) -> np.ndarray:
        table = np.zeros(horizon + 1)
        speed = dist = 0.0
        for k in range(1, horizon + 1):
            speed = min(speed + self.accel_max, self.speed_max)
            dist += speed
            speed *= self.player_decay
            table[k] = dist
        return table

    # --- ball ------------------------------------------------------------------------------
    def noise_rates(self, gap: np.ndarray | float, angle: np.ndarray | float,
                    ball_speed: np.ndarray | float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The rates of rcssserver's kick noise for a ball ``gap`` from the kicker's surface at
        ``angle`` (``dir_diff``, radians) to its body, moving at ``ball_speed``: the distance
        rate ``gap / kickable_margin`` (within [0, 1]), the angle rate ``angle / pi`` and the
        speed rate ``0.5 + 0.5 * ball_speed / (ball_speed_max * ball_decay)`` (see
        :meth:`kick_spread`)."""
        return (np.clip(np.asarray(gap, float) / self.kickable_margin, 0.0, 1.0), np.asarray(angle, float) / math.pi,
                0.5 + 0.5 * np.asarray(ball_speed, float) / (self.ball_speed_max * self.ball_decay))

    def kick_spread(self, gap: np.ndarray | float, ball_speed: np.ndarray | float, power: np.ndarray | float,
                    launch_speed: np.ndarray | float, cycles: np.ndarray | int,
                    angle: np.ndarray | float = 0.0) -> np.ndarray:
        """Standard deviation (m) across its line of where a kicked ball is ``cycles`` cycles
        after the kick, from the kick noise and the ball noise of those cycles (the simulator's
        rcssserver formulas).

        ``gap``: distance between the ball's and the kicker's surfaces (m; 0 for a goalkeeper
        holding the ball); ``ball_speed``: the ball's speed before the kick; ``power``: length
        of the kick request (clipped to ``kick_speed_max``); ``launch_speed``: the ball's speed
        after it (m/cycle); ``angle``: rcssserver's ``dir_diff`` (radians) between where the
        kicker's body faces and the ball (0 for a kicker facing it; see
        :mod:`agents.skills.kicking`). ``pos_rate = 0.5 + 0.25 * (angle / pi + gap /
        kickable_margin)``; ``speed_rate = 0.5 + 0.5 *
        ball_speed / (ball_speed_max * ball_decay)``. A random vector of length uniform in
        ``[0, a]`` and uniform direction has the standard deviation ``a / sqrt(6)`` across;
        the kick's moves the ball by ``travel(k)`` times that, each cycle's ball noise by the
        travel of the cycles left (:attr:`ball_noise_gain`)."""
        rows = np.broadcast_arrays(
            *self.noise_rates(gap, angle, ball_speed), np.minimum(np.asarray(power, float) / self.kick_speed_max, 1.0),
            np.asarray(launch_speed, float), np.clip(np.asarray(cycles, dtype=np.int64), 0, self.horizon))
        shape = rows[0].shape
        flat = [np.ascontiguousarray(row.ravel()) for row in rows]
        out = np.empty(flat[0].shape[0])
        kick_spreads(*flat, self.ball_travel, self.ball_noise_gain, self.kick_rand, self.ball_rand, out)
        return out.reshape(shape)

    def ball_path(self, ball: np.ndarray, ball_vel: np.ndarray, cycles: int | None = None) -> np.ndarray:
        """(cycles + 1, 2) predicted ball positions after 0..cycles cycles (no obstacles, no
        noise, the field's lines ignored)."""
        cycles = self.horizon if cycles is None else int(cycles)
        travel = self.ball_travel if cycles <= self.horizon else _geometric_sums(
            self.ball_decay, np.arange(cycles + 1, dtype=np.float64))
        return np.asarray(ball, float) + travel[:cycles + 1, None] * np.asarray(ball_vel, float)

    def ball_speed_for(self, distance: np.ndarray | float, end_speed: np.ndarray | float) -> np.ndarray:
        """Initial ball speed that covers ``distance`` and still has ``end_speed`` there (m/cycle):
        ``distance * (1 - d) + end_speed``."""
        return np.asarray(distance, float) * (1.0 - self.ball_decay) + np.asarray(end_speed, float)

    def ball_cycles_to(self, distance: np.ndarray | float, speed: np.ndarray | float) -> np.ndarray:
        """Cycles (fractional) a ball leaving at ``speed`` needs to travel ``distance``; inf when
        it stops short."""
        distance = np.asarray(distance, float)
        left = 1.0 - distance * (1.0 - self.ball_decay) / np.maximum(np.asarray(speed, float), 1e-12)
        return np.where(left > 0.0, np.log(np.maximum(left, 1e-300)) / math.log(self.ball_decay), np.inf)

    # --- players ---------------------------------------------------------------------------
    def sustainable_speed(self, effort: np.ndarray | float = 1.0) -> np.ndarray:
        """Running speed a player can hold for ever on its stamina recovery alone (m/cycle).

        Holding speed ``s`` needs an acceleration ``s * (1 - decay)`` per cycle, i.e. a dash
        power ``s * (1 - decay) / (dash_power_rate * effort)``; setting that equal to
        ``recovery_per_cycle`` gives ``s`` (0.45 m/cycle for a fresh default player).
        """
        effort = np.asarray(effort, float)
        speed = self.recovery_per_cycle * self.dash_power_rate * effort / max(1.0 - self.player_decay, 1e-12)
        return np.minimum(speed, self.top_speed * effort)

    def goal_centre(self, ours: bool) -> np.ndarray:
        """(2,) centre of our goal (``ours``) or of the opponents' goal, team frame."""
        return np.array([-self.half_length if ours else self.half_length, 0.0])

    def in_field(self, points: np.ndarray, margin: float = 0.0) -> np.ndarray:
        """Bool per point: inside the lines shrunk by ``margin`` (m)."""
        points = np.asarray(points, float)
        return (np.abs(points[..., 0]) <= self.half_length - margin) & \
            (np.abs(points[..., 1]) <= self.half_width - margin)

    def clamp_to_field(self, points: np.ndarray, margin: float = 0.0) -> np.ndarray:
        """Points moved inside the lines shrunk by ``margin`` (m)."""
        points = np.array(points, float)
        np.clip(points[..., 0], -self.half_length + margin, self.half_length - margin, out=points[..., 0])
        np.clip(points[..., 1], -self.half_width + margin, self.half_width - margin, out=points[..., 1])
        return points

    def in_penalty_area(self, points: np.ndarray, ours: bool = True) -> np.ndarray:
        """Bool per point: inside our (``ours``) or the opponents' penalty area, lines included."""
        points = np.asarray(points, float)
        depth = self.half_length - self.penalty_area_length
        inside_x = points[..., 0] <= -depth if ours else points[..., 0] >= depth
        return inside_x & (np.abs(points[..., 0]) <= self.half_length) & \
            (np.abs(points[..., 1]) <= self.penalty_area_half_width)


def _check_config(config: object) -> None:
    if not isinstance(config, MatchConfig):
        raise SkillInputError(f"MotionModel needs a MatchConfig, got {type(config).__name__}")


@functools.lru_cache(maxsize=16)
def _ball_noise_table(ball_decay: float, horizon: int) -> np.ndarray:
    """:attr:`MotionModel.ball_noise_gain` for a ball decay and horizon (read only: made once per
    process for each pair, as every team of every match asks for the same one)."""
    travel = _geometric_sums(ball_decay, np.arange(horizon + 1, dtype=np.float64))
    table = np.zeros(horizon + 1)
    for k in range(1, horizon + 1):
        j = np.arange(k)
        table[k] = math.sqrt(float(np.sum((ball_decay ** j * travel[k - j]) ** 2)))
    table.setflags(write=False)
    return table


def _geometric_sums(decay: float, k: np.ndarray) -> np.ndarray:
    """(1 - decay^k) / (1 - decay), with the limit k for decay 1."""
    if decay >= 1.0:
        return k.copy()
    return (1.0 - decay ** k) / (1.0 - decay)


def view_effort(view: TeamView, n: int) -> np.ndarray:
    """The view's per-player effort (n,), checked, or ones when it has none (hand-built views)."""
    effort = getattr(view, "effort", None)
    if effort is None:
        return np.ones(n)
    return float_array("effort", effort, (n,))


def check_player(player: int, n: int, what: str = "player") -> int:
    """``player`` as an int in ``[0, n)``, else a SkillInputError naming it."""
    if isinstance(player, bool) or not isinstance(player, (int, np.integer)):
        raise SkillInputError(f"{what} must be an integer index, got {player!r}")
    if not 0 <= player < n:
        raise SkillInputError(f"{what} index {player} is out of range for {n} players")
    return int(player)


_F64 = np.dtype(np.float64)


def float_array(name: str, value: object, shape: tuple[int, ...]) -> np.ndarray:
    """``value`` as a C-contiguous float64 array of ``shape`` (-1: any length), else a
    SkillInputError naming it. Costs little when it already is one (the hot paths); the
    compiled kernels rely on it, as they do not check bounds."""
    if type(value) is np.ndarray and (value.dtype is _F64 or value.dtype == _F64) and value.flags.c_contiguous:
        array = value
    else:
        try:
            array = np.ascontiguousarray(value, dtype=np.float64)
        except (TypeError, ValueError) as exc:
            raise SkillInputError(f"{name} must be numeric, got {type(value).__name__}") from exc
    got = array.shape
    fits = _SHAPE_FITS.get((got, shape))
    if fits is None:
        fits = len(got) == len(shape) and _dims_match(got, shape)
        if len(_SHAPE_FITS) < 4096:
            _SHAPE_FITS[(got, shape)] = fits
    if not fits:
        want = "(" + ", ".join("n" if w == -1 else str(w) for w in shape) + ("," if len(shape) == 1 else "") + ")"
        raise SkillInputError(f"{name} must have shape {want}, got {got}")
    return array


_SHAPE_FITS: dict[tuple[tuple[int, ...], tuple[int, ...]], bool] = {}
"""Memo of (actual shape, wanted shape) -> fits: the hot paths check the same few shapes."""


def _dims_match(got: tuple[int, ...], shape: tuple[int, ...]) -> bool:
    for want, have in zip(shape, got):
        if want != -1 and want != have:
            return False
    return True


def check_params(owner: object, positive: tuple[str, ...] = (), non_negative: tuple[str, ...] = (),
                 counts: tuple[str, ...] = (), fractions: tuple[str, ...] = (), finite: tuple[str, ...] = (),
                 whole: tuple[str, ...] = ()) -> None:
    """Check the named fields of a skill's parameter dataclass: ``positive`` and
    ``non_negative`` finite numbers, ``finite`` numbers of any sign, ``fractions`` (within
    [0, 1]), ``counts`` (integers >= 1), ``whole`` (integers >= 0); a SkillInputError names
    the class, the field and the value."""
    kind = type(owner).__name__

    def fail(name: str, what: str) -> None:
        raise SkillInputError(f"{kind}.{name} must be {what}, got {getattr(owner, name)!r}")

    for name in positive + non_negative + fractions + finite:
        value = getattr(owner, name)
        if isinstance(value, bool) or not isinstance(value, (int, float, np.integer, np.floating)) \
                or not math.isfinite(value):
            fail(name, "a finite number")
    for name in positive:
        if getattr(owner, name) <= 0:
            fail(name, "positive")
    for name in non_negative:
        if getattr(owner, name) < 0:
            fail(name, "at least 0")
    for name in fractions:
        if not 0.0 <= getattr(owner, name) <= 1.0:
            fail(name, "within [0, 1]")
    for name in counts + whole:
        value = getattr(owner, name)
        least = 1 if name in counts else 0
        if isinstance(value, bool) or not isinstance(value, (int, np.integer)) or value < least:
            fail(name, f"an integer of at least {least}")
