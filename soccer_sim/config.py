"""Every physical and rule parameter of a match, importable from here.

The physics and stamina parameters live in this module, the field's in
:mod:`soccer_sim.field_config` and the referee's and the tackles' in :mod:`soccer_sim.rule_config`
(both re-exported here), the shared checks and :class:`ConfigError` in
:mod:`soccer_sim.config_checks`.

Defaults follow the RoboCup 2D soccer simulator's server parameters where one
exists. Units: metres, cycles (one cycle = ``cycle_seconds`` of game time),
metres per cycle for speeds and metres per cycle² for accelerations. The
absolute frame has its origin at the centre spot, x along the length of the
field (towards the right-hand goal) and y across it.

All configs are frozen dataclasses; each checks its fields when constructed (their ranges are
:mod:`soccer_sim.config_ranges`'s, docs/limits.md lists them) and rejects impossible values
with a :class:`ConfigError` naming the field.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from dataclasses import field as default_of

from soccer_sim.config_checks import ConfigError
from soccer_sim.config_ranges import check_ranges
from soccer_sim.field_config import STANDARD_FIELD, FieldConfig
from soccer_sim.perception.config import ObservationConfig
from soccer_sim.rule_config import RuleConfig, TackleConfig


BODY_BALL_CONTACTS = ("rcssserver", "swept", "rigid")
"""The values of :attr:`PhysicsConfig.body_ball_contact`."""


@dataclass(frozen=True)
class PhysicsConfig:
    """Bodies, motion limits, kicking and noise."""

    cycle_seconds: float = 0.1
    """Game time of one simulation cycle (s)."""
    player_radius: float = 0.3
    ball_radius: float = 0.085
    player_speed_max: float = 1.05
    """Largest player speed (m/cycle)."""
    dash_power_max: float = 100.0
    """Largest dash power (rcssserver ``maxpower``); stamina is paid in power units."""
    dash_power_rate: float = 0.006
    """Acceleration per unit of dash power at full effort (m/cycle² per power unit;
    rcssserver ``dash_power_rate``): a full-power dash accelerates by 0.6 m/cycle²."""
    side_dash_rate: float = 0.4
    """Power fraction of a dash at 90° to the player's direction of motion (rcssserver 17
    ``side_dash_rate``; see :mod:`soccer_sim.kinematics` for an orientation-less robot)."""
    back_dash_rate: float = 0.7
    """Power fraction of a dash straight against the player's direction of motion
    (rcssserver 17 ``back_dash_rate``)."""
    dash_heading_speed: float = 0.2
    """Speed (m/cycle) from which a moving robot's direction of motion counts fully as its
    heading for the side/back dash rates; below it the rates blend linearly towards 1 (a
    robot at rest dashes equally well in every direction). No rcssserver counterpart."""
    player_decay: float = 0.4
    """Fraction of a player's velocity kept from one cycle to the next."""
    ball_decay: float = 0.94
    """Fraction of the ball's velocity kept from one cycle to the next."""
    ball_speed_max: float = 3.0
    """Largest ball speed (m/cycle)."""
    kick_speed_max: float = 2.7
    """Largest velocity change the kicks of one cycle can give the ball together (m/cycle):
    each kick is clipped to it before effectiveness, and so is their sum (rcssserver
    ``ball_accel_max``: all kicks on the ball in a cycle add into one acceleration that is
    capped)."""
    cap_summed_kicks: bool = True
    """Cap the sum of a cycle's kicks at ``kick_speed_max`` (rcssserver). False caps each kick
    alone, so two kickers can exceed the limit (the simulator's behaviour before 0.2)."""
    kickable_margin: float = 0.7
    """The ball is kickable when its surface is within this distance of the player's surface (m)."""
    kick_distance_penalty: float = 0.25
    """Kick power lost when the ball lies at the far edge of the kickable margin (rcssserver's
    kick rule, ``player.cpp``: ``0.25 * dist_ball / kickable_margin``, where ``dist_ball`` is the
    gap between the ball's and the player's surfaces)."""
    kick_angle_penalty: float = 0.25
    """Kick power lost when the ball lies straight behind the player's body (rcssserver's kick
    rule: ``0.25 * dir_diff / 180°``, ``dir_diff`` the angle between the body direction and the
    direction to the ball; the body direction is :mod:`soccer_sim.body`'s). It does not depend
    on the direction the ball is sent."""
    inertia_moment: float = 5.0
    """How much speed limits a player's turn (rcssserver ``inertia_moment`` of the default
    player type): the largest turn is ``180° / (1 + inertia_moment * speed)``. Used by the
    body-direction model (:mod:`soccer_sim.body`) that the kick rule asks where a body faces."""
    player_rand: float = 0.1
    """Movement noise of the players (rcssserver ``player_rand``): after its dash, a player's
    velocity gets a random vector of length uniform in ``[0, player_rand * speed]`` and
    direction uniform in ``[-180°, 180°)`` (rcssserver's ``MPObject::noise``)."""
    ball_rand: float = 0.05
    """Movement noise of the ball (rcssserver ``ball_rand``), drawn like ``player_rand`` from
    the ball's speed after this cycle's kicks."""
    kick_rand: float = 0.1
    """Kick noise (rcssserver ``kick_rand`` of the default player type): each kick adds a
    random vector of length uniform in ``[0, kick_rand * power / max_power * (pos_rate +
    speed_rate)]`` (``pos_rate = 0.5 + 0.25 * (dir_diff / 180° + dist_ball / kickable_margin)``,
    ``speed_rate = 0.5 + 0.5 * ball_speed / (ball_speed_max * ball_decay)``) and uniform
    direction: it grows with the ball's distance, its angle to the body and its speed."""
    player_mass: float = 70.0
    """Mass of a player's body (kg); only the ratio to ``ball_mass`` matters in collisions."""
    ball_mass: float = 0.43
    """Mass of the ball (kg)."""
    player_restitution: float = 0.2
    """Bounciness of a player's body in collisions (0: dead stop, 1: perfectly elastic). The
    restitution of a contact is the product of the two bodies' values."""
    ball_restitution: float = 0.8
    """Bounciness of the ball; goal posts are perfectly elastic, so the ball keeps this fraction
    of its normal speed off a post and ``ball_restitution * player_restitution`` off a player."""
    body_ball_contact: str = "rcssserver"
    """How a player's body and the ball meet.

    * ``"rcssserver"`` (rcssserver's ``Stadium::collisions``): after everything has moved, a
      player and the ball that overlap are moved apart along the line between their centres,
      each by half the overlap, repeated (at most 10 rounds) while any overlap remains; a ball
      overlapping several players goes to the mean of its separated positions; then the
      velocity of every body that met another is multiplied by ``collision_velocity_factor``
      once. Only overlaps at the end of the cycle count, so a fast ball can pass through a
      player and a slow player pushes the ball. Outside play on the ball stays and the player
      is moved off it.
    * ``"swept"`` (not rcssserver's): the paths of the cycle are swept and both bodies are put
      back where they first touched, velocities times ``collision_velocity_factor``; no ball
      passes through a player, and a body never propels the ball. This cycle's kickers let the
      ball pass.
    * ``"rigid"``: the collision solver treats them as rigid discs with the restitutions
      above, so a running player pushes the ball ahead at its own speed (the simulator's
      behaviour before 0.2)."""
    collision_velocity_factor: float = -0.1
    """Factor on the ball's and the player's velocities after a body-ball contact
    (rcssserver: -0.1, hard-coded in ``MPObject::updateCollisionVel``); within [-1, 0]."""
    max_substep_distance: float = 0.3
    """Physics sub-steps are added until no body moves further than this in one sub-step (m),
    so that a full-speed ball cannot pass through a player. Motion is measured relative to the
    bodies it could meet in the cycle (see soccer_sim.physics.SubstepPlanner): a body far from
    everything cannot pass through anything, whatever its speed."""

    def __post_init__(self) -> None:
        self.validate()

    def validate(self) -> None:
        """ConfigError naming the first field out of its range (:mod:`soccer_sim.config_ranges`)
        or out of proportion with the others."""
        check_ranges(self)
        if not isinstance(self.cap_summed_kicks, bool):
            raise ConfigError(f"PhysicsConfig.cap_summed_kicks must be a bool, got {self.cap_summed_kicks!r}")
        if self.body_ball_contact not in BODY_BALL_CONTACTS:
            raise ConfigError(f"PhysicsConfig.body_ball_contact must be one of {', '.join(BODY_BALL_CONTACTS)}, "
                              f"got {self.body_ball_contact!r}")
        if self.max_substep_distance > 2 * self.ball_radius + 2 * self.player_radius:
            raise ConfigError("PhysicsConfig.max_substep_distance must not exceed the ball-player contact diameter")

    @property
    def cycles_per_minute(self) -> float:
        """Cycles in one minute of game time (600 at the default ``cycle_seconds`` of 0.1 s)."""
        return 60.0 / self.cycle_seconds

    @property
    def player_accel_max(self) -> float:
        """Largest dash acceleration at full effort, straight ahead (m/cycle²):
        ``dash_power_max * dash_power_rate``."""
        return self.dash_power_max * self.dash_power_rate

    @property
    def kickable_distance(self) -> float:
        """Centre-to-centre distance within which a player can kick the ball (m)."""
        return self.player_radius + self.ball_radius + self.kickable_margin

    @property
    def kick_noise(self) -> float:
        """Derived, not a parameter: the kick noise as one figure for planners that model it
        as a uniform spread of the ball's direction (radians). It is the half-width of the
        uniform spread with the same standard deviation as the direction of a full-power kick
        of a ball at rest touching the body, ``kick_rand`` and ``ball_rand`` together (a
        random vector of length uniform in ``[0, a]`` has a standard deviation of ``a / √6``
        across): about 0.044 at the defaults (rcssserver measured: 1.41° standard deviation)."""
        across = math.sqrt((self.kick_rand ** 2 + (self.ball_rand * self.kick_speed_max) ** 2) / 6.0)
        return math.sqrt(3.0) * across / self.kick_speed_max


@dataclass(frozen=True)
class StaminaConfig:
    """Stamina, effort and recovery, as the RoboCup 2D simulator (rcssserver) models them.

    Every player has a stamina (starts at ``maximum``), an effort (the fraction of the dash
    power that turns into acceleration, starts at ``effort_max``), a recovery rate (starts
    at 1) and a capacity (starts at ``capacity``). A dash of power p costs p stamina and may
    use at most the current stamina plus ``extra_stamina``. After the dashes of a cycle,
    every player's stamina model is updated: below ``recover_dec_thr * maximum`` the recovery
    rate falls by ``recover_dec`` (never below ``recover_min``; it never rises again within
    a half); below ``effort_dec_thr * maximum`` the effort falls by ``effort_dec`` (never
    below ``effort_min``); at or above ``effort_inc_thr * maximum`` it rises by
    ``effort_inc`` (never above ``effort_max``); then stamina recovers by
    ``recovery * recovery_per_cycle`` (up to ``maximum``), paid from the capacity: once the
    capacity is spent, stamina no longer recovers. Everything is restored at half time.
    Defaults: rcssserver's (``stamina_max``, ``stamina_inc_max``, ``extra_stamina``,
    ``stamina_capacity``, ``recover_*``, ``effort_*`` of the default player type).
    """

    maximum: float = 8000.0
    """Largest stamina (rcssserver ``stamina_max``)."""
    recovery_per_cycle: float = 45.0
    """Stamina recovered per cycle at recovery rate 1 (rcssserver ``stamina_inc_max``)."""
    extra_stamina: float = 50.0
    """Dash power a player may use beyond its current stamina (rcssserver ``extra_stamina``)."""
    capacity: float | None = 130600.0
    """Stamina a player can recover in one half (rcssserver ``stamina_capacity``); None for no limit."""
    recover_dec_thr: float = 0.3
    """Fraction of ``maximum`` below which the recovery rate falls."""
    recover_dec: float = 0.002
    """Fall of the recovery rate per cycle spent below its threshold."""
    recover_min: float = 0.5
    """Lowest recovery rate."""
    effort_dec_thr: float = 0.3
    """Fraction of ``maximum`` below which the effort falls."""
    effort_dec: float = 0.005
    """Fall of the effort per cycle spent below its threshold."""
    effort_min: float = 0.6
    """Lowest effort."""
    effort_inc_thr: float = 0.6
    """Fraction of ``maximum`` at or above which the effort recovers."""
    effort_inc: float = 0.01
    """Rise of the effort per cycle spent above its threshold."""
    effort_max: float = 1.0
    """Highest (and initial) effort."""

    def __post_init__(self) -> None:
        self.validate()

    def validate(self) -> None:
        """ConfigError naming the first field out of its range (:mod:`soccer_sim.config_ranges`)
        or out of proportion with the others."""
        check_ranges(self)
        if self.effort_min > self.effort_max:
            raise ConfigError(f"StaminaConfig.effort_min ({self.effort_min}) must not exceed effort_max ({self.effort_max})")

    @property
    def capacity_or_inf(self) -> float:
        """``capacity`` as a number (infinite when unlimited)."""
        return math.inf if self.capacity is None else float(self.capacity)


@dataclass(frozen=True)
class PlayerTypeConfig:
    """Heterogeneous player types as rcssserver 19 draws them (``player_param.conf``).

    Type 0 is the default type (the physics, stamina and tackle configs' values); types
    ``1..types-1`` are drawn from the match seed by :mod:`soccer_sim.player_types`, each from
    deltas uniform in the ranges below, the trade-off partner of each delta moving by
    ``delta * factor``. A team that never chooses types plays everyone as type 0. Players are
    not substituted during a match, so rcssserver's ``subs_max`` has no counterpart.
    """

    types: int = 18
    """Number of player types, the default one included (rcssserver ``player_types``)."""
    pt_max: int = 1
    """At most this many players of one non-default type per team (rcssserver ``pt_max``)."""
    player_speed_max_delta_min: float = 0.0
    """rcssserver ``player_speed_max_delta_min`` (m/cycle)."""
    player_speed_max_delta_max: float = 0.0
    """rcssserver ``player_speed_max_delta_max`` (m/cycle)."""
    stamina_inc_max_delta_factor: float = 0.0
    """rcssserver ``stamina_inc_max_delta_factor``."""
    player_decay_delta_min: float = -0.1
    """rcssserver ``player_decay_delta_min``."""
    player_decay_delta_max: float = 0.1
    """rcssserver ``player_decay_delta_max``."""
    inertia_moment_delta_factor: float = 25.0
    """rcssserver ``inertia_moment_delta_factor``."""
    dash_power_rate_delta_min: float = 0.0
    """rcssserver ``dash_power_rate_delta_min`` (the pre-v14 dash trade-off, unused by default)."""
    dash_power_rate_delta_max: float = 0.0
    """rcssserver ``dash_power_rate_delta_max``."""
    player_size_delta_factor: float = -100.0
    """rcssserver ``player_size_delta_factor``."""
    new_dash_power_rate_delta_min: float = -0.0012
    """rcssserver ``new_dash_power_rate_delta_min``."""
    new_dash_power_rate_delta_max: float = 0.0008
    """rcssserver ``new_dash_power_rate_delta_max``."""
    new_stamina_inc_max_delta_factor: float = -6000.0
    """rcssserver ``new_stamina_inc_max_delta_factor``."""
    kickable_margin_delta_min: float = -0.1
    """rcssserver ``kickable_margin_delta_min`` (m)."""
    kickable_margin_delta_max: float = 0.1
    """rcssserver ``kickable_margin_delta_max`` (m)."""
    kick_rand_delta_factor: float = 1.0
    """rcssserver ``kick_rand_delta_factor``."""
    extra_stamina_delta_min: float = 0.0
    """rcssserver ``extra_stamina_delta_min``."""
    extra_stamina_delta_max: float = 50.0
    """rcssserver ``extra_stamina_delta_max``."""
    effort_max_delta_factor: float = -0.004
    """rcssserver ``effort_max_delta_factor``."""
    effort_min_delta_factor: float = -0.004
    """rcssserver ``effort_min_delta_factor``."""
    kick_power_rate_delta_min: float = 0.0
    """rcssserver ``kick_power_rate_delta_min``."""
    kick_power_rate_delta_max: float = 0.0
    """rcssserver ``kick_power_rate_delta_max``."""
    foul_detect_probability_delta_factor: float = 0.0
    """rcssserver ``foul_detect_probability_delta_factor``."""
    catchable_area_l_stretch_min: float = 1.0
    """rcssserver ``catchable_area_l_stretch_min``."""
    catchable_area_l_stretch_max: float = 1.3
    """rcssserver ``catchable_area_l_stretch_max``."""
    player_speed_max_min: float = 0.75
    """A drawn type is kept only if its top speed ``dash_power_max * dash_power_rate *
    effort_max / (1 - player_decay)`` is at least this (rcssserver ``player_speed_max_min``)."""
    max_trials: int = 1000
    """Draws per type before it falls back to the default type (rcssserver's ``MAX_TRIAL``)."""

    def __post_init__(self) -> None:
        self.validate()

    def validate(self) -> None:
        """ConfigError naming the first field out of its range (:mod:`soccer_sim.config_ranges`)."""
        check_ranges(self)


@dataclass(frozen=True)
class MatchConfig:
    """Everything that, with the two teams and the seed, determines a match."""

    field: FieldConfig = STANDARD_FIELD
    physics: PhysicsConfig = default_of(default_factory=PhysicsConfig)
    stamina: StaminaConfig = default_of(default_factory=StaminaConfig)
    rules: RuleConfig = default_of(default_factory=RuleConfig)
    tackles: TackleConfig = default_of(default_factory=TackleConfig)
    """Tackles, fouls and cards (rcssserver's)."""
    player_types: PlayerTypeConfig = default_of(default_factory=PlayerTypeConfig)
    """Heterogeneous player types (rcssserver's hetero parameters)."""
    observation: ObservationConfig = default_of(default_factory=ObservationConfig)
    """What the teams perceive: the exact state (``full``, the default) or each player's own
    noisy view and the say/hear channel (``partial``)."""
    players_per_team: int = 11
    max_cycles: int | None = None
    """Stop after this many cycles (None: two full halves)."""

    def __post_init__(self) -> None:
        self.validate()

    def validate(self) -> None:
        for name, kind in (("field", FieldConfig), ("physics", PhysicsConfig), ("stamina", StaminaConfig),
                           ("rules", RuleConfig), ("tackles", TackleConfig),
                           ("player_types", PlayerTypeConfig), ("observation", ObservationConfig)):
            part = getattr(self, name)
            if not isinstance(part, kind):
                raise ConfigError(f"MatchConfig.{name} must be a {kind.__name__}, got {type(part).__name__}")
            part.validate()
        check_ranges(self)
        if self.rules.goalie_index >= self.players_per_team:
            raise ConfigError("RuleConfig.goalie_index must index a player of the team")
        room = min(self.field.length, self.field.width) / 2.0
        if self.rules.set_play_clearance >= room:
            raise ConfigError(f"RuleConfig.set_play_clearance ({self.rules.set_play_clearance:g} m) must be less than "
                              f"half the field's smaller side ({room:g} m): opponents are kept that far from the "
                              "ball at set plays")
        if self.rules.corner_inset >= room:
            raise ConfigError(f"RuleConfig.corner_inset ({self.rules.corner_inset:g} m) must be less than half the "
                              f"field's smaller side ({room:g} m)")

    @property
    def total_cycles(self) -> int:
        """Number of cycles the match lasts."""
        full = 2 * self.rules.half_cycles
        return full if self.max_cycles is None else min(full, self.max_cycles)
