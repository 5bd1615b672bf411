"""Hand-built world states for testing the referee without physics.

Default layout (absolute frame, home attacking +x): each team stands in a loose line in
its own half, 20-30 m from the centre, goalkeepers (row 0 and row n) on their goal lines'
centres, so nobody is near the ball or offside unless a test moves them.
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from soccer_sim.config import MatchConfig, RuleConfig
from soccer_sim.referee import Referee
from soccer_sim.setup import MatchSetup
from soccer_sim.state import HOME, NO_PLAYER, NO_TEAM, EventKind, EventLog, PlayMode, WorldState

N = 11
NO_TOUCH = np.zeros(0, dtype=np.int64)


def config_with(**rules) -> MatchConfig:
    """Default MatchConfig with some RuleConfig fields replaced."""
    return replace(MatchConfig(), rules=replace(RuleConfig(), **rules))


def default_positions(n: int = N, home_attacks: int = 1) -> np.ndarray:
    """(2n, 2) positions: home in its own half, away mirrored into the other half."""
    i = np.arange(n, dtype=float)
    home = np.column_stack((-20.0 - i, -25.0 + 50.0 * i / max(n - 1, 1)))
    home[0] = (-50.0, 0.0)  # goalkeeper
    pos = np.vstack((home, -home))
    return pos * home_attacks


def make_world(*, ball=(0.0, 0.0), ball_vel=(0.0, 0.0), mode: PlayMode = PlayMode.PLAY_ON,
               mode_team: int = NO_TEAM, cycle: int = 100, home_attacks: int = 1,
               last_touch: int = NO_PLAYER, config: MatchConfig | None = None,
               moves: dict[int, tuple[float, float]] | None = None, rng: np.random.Generator | None = None,
               types: np.ndarray | None = None):
    """A referee, a world state and its event log. ``moves`` maps player rows to positions;
    ``rng`` and ``types`` go to the referee (:class:`~soccer_sim.referee.Referee`)."""
    config = config or MatchConfig()
    n = config.players_per_team
    pos = default_positions(n, home_attacks)
    for row, xy in (moves or {}).items():
        pos[row] = xy
    state = WorldState(
        pos=pos, vel=np.zeros((2 * n, 2)), stamina=np.full(2 * n, config.stamina.maximum),
        ball=np.array(ball, dtype=float), ball_vel=np.array(ball_vel, dtype=float),
        cycle=cycle, half=0 if home_attacks == 1 else 1, home_attacks=home_attacks,
        play_mode=mode, mode_team=mode_team if mode != PlayMode.PLAY_ON else NO_TEAM,
        mode_start=cycle, last_touch=last_touch,
    )
    events = EventLog()
    return Referee(MatchSetup.resolve(config), events, rng, types), state, events


def step(referee: Referee, state: WorldState, touchers=NO_TOUCH) -> None:
    """The end of one cycle: the referee judges it, then the clock advances."""
    referee.after_step(state, np.asarray(touchers, dtype=np.int64))
    state.cycle += 1


def kick(referee: Referee, state: WorldState, rows, velocity=(0.0, 0.0), catch=(False, False)) -> None:
    """Apply a kick by ``rows`` giving the ball ``velocity`` (absolute frame), as the loop would."""
    state.ball_vel[:] = velocity
    kickers = np.asarray(rows, dtype=np.int64)
    if len(kickers):
        state.last_touch = int(kickers[-1])
    referee.on_commands(state, kickers, np.asarray(catch, dtype=bool))


def catch(referee: Referee, state: WorldState, team: int = HOME) -> None:
    requests = np.zeros(2, dtype=bool)
    requests[team] = True
    referee.on_commands(state, NO_TOUCH, requests)


def move_ball(state: WorldState, x: float, y: float) -> None:
    state.ball[:] = (x, y)


def kinds(events: EventLog) -> list[EventKind]:
    return [EventKind(k) for k in events.kind]


def set_play_modes(events: EventLog) -> list[PlayMode]:
    return [PlayMode(d) for k, d in zip(events.kind, events.detail) if k == EventKind.SET_PLAY]
