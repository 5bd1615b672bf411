"""The situations rcssserver 19 was probed in, replayed on soccer-sim.

Two rigs: :class:`Pitch` is a whole match in play on whose probe players do exactly what the
test sets (the reference tests against the server's traces, ``tests/data/rcssserver/``, read
by :func:`trace`); :class:`Rig` runs the motion rules of one cycle in the match's order (kicks, dashes with the
movement noise, the move with the body-ball contacts, decay) on a world with player 0 and the
ball placed by the test and everyone else parked far away, in play on, without the referee:
the same as the probes' trainer set-ups. The real server's figures these situations are
compared with are in ``docs/simulator.md`` (the "rcssserver rule -> ours -> parameter" table).
"""

from __future__ import annotations

import json
import math
from dataclasses import replace
from functools import cache
from pathlib import Path

import numpy as np

from soccer_sim import Match, PlayMode, TeamCommand
from soccer_sim.config import MatchConfig, PhysicsConfig, RuleConfig
from soccer_sim.kinematics import CycleNoise, Kinematics
from soccer_sim.physics import Physics
from soccer_sim.state import WorldState

N = 11
ROWS = 2 * N
FAR = np.array([[-40.0 + 3.0 * (i % 10), -30.0 + 5.0 * (i // 10)] for i in range(ROWS)])
"""Everyone not in the situation: far from the centre and from each other."""


def probe_config(noise: bool, contact: str = "rcssserver") -> MatchConfig:
    """The default configuration with the given body-ball contact; without noise unless ``noise``."""
    physics = PhysicsConfig(body_ball_contact=contact)
    if not noise:
        physics = replace(physics, player_rand=0.0, ball_rand=0.0, kick_rand=0.0)
    return MatchConfig(physics=physics)


class Rig:
    """One probe world: player 0 and the ball wherever the test puts them."""

    def __init__(self, config: MatchConfig, seed: int = 0) -> None:
        self.state = state = WorldState((N, N))
        state.pos[:] = FAR
        state.ball[:] = (0.0, 25.0)
        state.play_mode = PlayMode.PLAY_ON
        self.physics = Physics(config, state)
        self.kin = Kinematics(config, ROWS)
        self.kin.restore(state.stamina, state.effort, state.recovery, state.capacity)
        self.noise = CycleNoise(np.random.default_rng(seed), ROWS)
        self._rows = np.zeros(ROWS, dtype=np.int64)

    def cycle(self, dash: np.ndarray | None = None, kick: np.ndarray | None = None) -> list[int]:
        """One cycle with the (ROWS, 2) dash and kick requests given (none by default); returns
        the rows whose body touched the ball."""
        state, kin = self.state, self.kin
        self.noise.draw()
        dash = np.zeros((ROWS, 2)) if dash is None else dash.copy()
        kick = np.zeros((ROWS, 2)) if kick is None else kick
        count, _ = kin.kick_candidates(state.pos, state.ball, kick, np.ones(ROWS, dtype=bool), -1, self._rows)
        kickers = self._rows[:count].copy()
        if count:
            kin.kick(kickers, state.pos, state.vel, state.ball, state.ball_vel, kick, kin.ball_distance, -1,
                     self.noise.kick)
        kin.dash(state.vel, state.ball_vel, state.stamina, state.effort, state.recovery, state.capacity, dash,
                 self.noise.motion)
        touchers = self.physics.step(1, kickers)
        kin.decay(state.vel, state.ball_vel)
        return touchers.tolist()


def dash_power(power: float, direction: tuple[float, float] = (1.0, 0.0)) -> np.ndarray:
    """Player 0 dashes with rcssserver dash power ``power`` along ``direction`` (a unit vector)."""
    dash = np.zeros((ROWS, 2))
    dash[0] = np.asarray(direction) * power * PhysicsConfig().dash_power_rate
    return dash


def kick_full(direction: tuple[float, float] = (1.0, 0.0)) -> np.ndarray:
    """Player 0 kicks with power 100 along ``direction`` (a unit vector)."""
    kick = np.zeros((ROWS, 2))
    kick[0] = np.asarray(direction) * PhysicsConfig().kick_speed_max
    return kick


def ball_launched_at_a_standing_player(speed: float, noise: bool = False, contact: str = "rcssserver",
                                       trials: int = 20) -> dict[str, int]:
    """The probe ``ball{speed}_at_player_{j}``: a standing player at the origin, the ball
    launched along +x at ``speed`` from ``-10 - speed * j / 20`` (every phase of its last step),
    14 cycles. Counts the trials by where the ball ends: beyond 1 m (``through``), just past the
    centre (``stop``), or on the near side (``back``)."""
    outcome = {"through": 0, "stop": 0, "back": 0}
    for j in range(trials):
        rig = Rig(probe_config(noise, contact), seed=j)
        rig.state.pos[0] = (0.0, 0.0)
        rig.state.ball[:] = (-10.0 - speed * j / 20.0, 0.0)
        rig.state.ball_vel[:] = (speed, 0.0)
        for _ in range(14):
            rig.cycle()
        x = rig.state.ball[0]
        outcome["through" if x > 1.0 else "stop" if x > 0.0 else "back"] += 1
    return outcome


def run_at_a_still_ball(power: float, cycles: int, start: float, step: float, noise: bool = False,
                        contact: str = "rcssserver") -> list[tuple[float, bool]]:
    """The probes ``run_into_ball_x{k}`` (power 100, 15 cycles, start 5.00..5.95 m before the
    ball) and ``walk_into_ball_x{k}`` (power 30, 40 cycles, start 3.000..3.285 m): player 0
    dashes along +x at a ball at rest on the origin, never kicking, from ``start - step * k``
    for k in 0..19. Returns (the ball's final x, whether the player ended beyond it) per start."""
    results = []
    for k in range(20):
        rig = Rig(probe_config(noise, contact), seed=k)
        rig.state.pos[0] = (start - step * k, 0.0)
        rig.state.ball[:] = (0.0, 0.0)
        for _ in range(cycles):
            rig.cycle(dash=dash_power(power))
        results.append((float(rig.state.ball[0]), bool(rig.state.pos[0, 0] > rig.state.ball[0])))
    return results


def first_step_of_a_kick(ball_offset: tuple[float, float], direction: tuple[float, float] = (1.0, 0.0),
                         noise: bool = False, seed: int = 0,
                         player_vel: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """Player 0 at (-30, 0) (moving at ``player_vel``) kicks a ball at rest at ``ball_offset``
    from it with power 100 along ``direction``; returns the ball's displacement in the kick's
    cycle (what the probes measured: the kicked velocity plus the cycle's ball noise)."""
    rig = Rig(probe_config(noise), seed=seed)
    rig.state.pos[0] = (-30.0, 0.0)
    rig.state.vel[0] = player_vel
    rig.state.ball[:] = (-30.0 + ball_offset[0], ball_offset[1])
    before = rig.state.ball.copy()
    rig.cycle(kick=kick_full(direction))
    return rig.state.ball - before


def kick_once(ball_offset: tuple[float, float], kick_vector: tuple[float, float], holder: int = -1,
              player_vel: tuple[float, float] = (0.0, 0.0), config: MatchConfig | None = None,
              noise: np.ndarray | None = None) -> tuple[int, np.ndarray]:
    """The kick rule alone: player 0 at the origin moving at ``player_vel``, the ball at rest at
    ``ball_offset``, player 0 requests ``kick_vector`` (the configuration without noise unless
    given; kick noise draws ``noise``, none by default); returns (kickers found, the ball's new
    velocity)."""
    config = probe_config(noise=False) if config is None else config
    kin = Kinematics(config, ROWS)
    vel = np.zeros((ROWS, 2))
    vel[0] = player_vel
    pos = FAR.copy()
    pos[0] = (0.0, 0.0)
    ball = np.array(ball_offset, dtype=float)
    ball_vel = np.zeros(2)
    kick = np.zeros((ROWS, 2))
    kick[0] = kick_vector
    rows = np.zeros(ROWS, dtype=np.int64)
    count, nearest = kin.kick_candidates(pos, ball, kick, np.ones(ROWS, dtype=bool), holder, rows)
    assert math.isclose(nearest, math.hypot(*ball_offset))
    if count:
        kin.kick(rows[:count], pos, vel, ball, ball_vel, kick, kin.ball_distance, holder,
                 np.zeros((ROWS, 2)) if noise is None else noise)
    return count, ball_vel


def direction_degrees(vector: np.ndarray) -> float:
    """Direction of a 2-vector in degrees."""
    return math.degrees(math.atan2(vector[1], vector[0]))


# ------------------------------------------------------------- the match-level rig (Pitch)

DATA = Path(__file__).resolve().parents[1] / "data" / "rcssserver"
PROBE = 9
"""Index of the probe player in its team (not the goalkeeper)."""
N_TEAM = N
FULL = 10.0
"""A request far beyond any limit (m/cycle² for a dash, m/cycle for a kick): "full power"."""


@cache
def trace(name: str) -> dict:
    """One reference file (read once)."""
    return json.loads((DATA / f"{name}.json").read_text())


def config(player_rand: float = 0.0, ball_rand: float = 0.0, kick_rand: float = 0.0) -> MatchConfig:
    """Defaults with the given noise (rcssserver's ``player_rand``, ``ball_rand``, ``kick_rand``;
    none by default), no half time within a test, and no stuck ball dropped: the probes run one
    after the other on one match, where the server's trainer placed every probe afresh."""
    physics = replace(PhysicsConfig(), player_rand=player_rand, ball_rand=ball_rand, kick_rand=kick_rand)
    rules = replace(RuleConfig(), half_cycles=50_000, stuck_ball_cycles=None)
    return replace(MatchConfig(), physics=physics, rules=rules, max_cycles=100_000)


class Probe:
    """A team whose players do exactly what the test sets before each step (own frame)."""

    def __init__(self) -> None:
        self.dash = np.zeros((N_TEAM, 2))
        self.kick = np.zeros((N_TEAM, 2))
        self.tackle: np.ndarray | None = None

    def reset(self, side_info, config, rng) -> None:
        pass

    def act(self, view) -> TeamCommand:
        if self.tackle is None:
            return TeamCommand(dash=self.dash.copy(), kick=self.kick.copy())
        return TeamCommand(dash=self.dash.copy(), kick=self.kick.copy(), tackle=self.tackle.copy())

    def idle(self) -> None:
        self.dash[:] = 0.0
        self.kick[:] = 0.0
        if self.tackle is not None:
            self.tackle[:] = np.nan


class Pitch:
    """A match in play-on with every player parked along y = -30 and the probes placed by the
    test; ``home``/``away`` are the Probe teams (the away team's frame is turned by 180°)."""

    def __init__(self, cfg: MatchConfig | None = None, seed: int = 0) -> None:
        self.home, self.away = Probe(), Probe()
        self.match = Match(self.home, self.away, seed=seed, config=cfg or config())
        self.match.start()
        self.state = self.match.state
        self.park()

    def park(self) -> None:
        """Set up a probe phase as the server's trainer did: everyone parked and still, the
        ball away, play on, and every player fresh (the trainer's ``(recover)``)."""
        state = self.state
        self.match.kinematics.restore(state.stamina, state.effort, state.recovery, state.capacity)
        state.play_mode, state.mode_team = PlayMode.PLAY_ON, -1
        state.pos[:, 0] = np.linspace(-48.0, 48.0, len(state.pos))
        state.pos[:, 1] = -30.0
        state.vel[:] = 0.0
        state.ball[:] = (0.0, 25.0)
        state.ball_vel[:] = 0.0

    def place(self, index: int, x: float, y: float, vx: float = 0.0, vy: float = 0.0) -> None:
        self.state.pos[index] = (x, y)
        self.state.vel[index] = (vx, vy)

    def ball(self, x: float, y: float, vx: float = 0.0, vy: float = 0.0) -> None:
        self.state.ball[:] = (x, y)
        self.state.ball_vel[:] = (vx, vy)

    def step(self) -> None:
        self.match.step()
        self.home.idle()
        self.away.idle()


HOME_PROBE, AWAY_PROBE = PROBE, N_TEAM + PROBE


def binomial_share_agrees(ours: int, n_ours: int, theirs: int, n_theirs: int, sigmas: float = 2.5) -> bool:
    """Two observed shares agree within ``sigmas`` standard errors of their difference (with a
    continuity allowance of half a trial on each side)."""
    pooled = (ours + theirs) / (n_ours + n_theirs)
    se = math.sqrt(max(pooled * (1 - pooled), 0.25 / (n_ours + n_theirs)) * (1 / n_ours + 1 / n_theirs))
    slack = 0.5 / n_ours + 0.5 / n_theirs
    return abs(ours / n_ours - theirs / n_theirs) <= sigmas * se + slack
