"""Helpers for the skill tests: hand-built team views, a noise-free config, the motion rules
rolled forward by hand, and a tiny match harness driving a scripted team."""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from soccer_sim import Match, MatchConfig, TeamCommand
from soccer_sim.config import PhysicsConfig
from soccer_sim.state import PlayMode
from soccer_sim.team import TeamView

CONFIG = MatchConfig()
N = CONFIG.players_per_team
HL = CONFIG.field.half_length
HW = CONFIG.field.half_width


def quiet_config(**match_fields) -> MatchConfig:
    """The default config without noise, so the simulator follows the skills' model exactly."""
    physics = replace(PhysicsConfig(), player_rand=0.0, ball_rand=0.0, kick_rand=0.0)
    return replace(MatchConfig(), physics=physics, **match_fields)


def far_positions(side: float) -> np.ndarray:
    """(N, 2) players parked along a touchline, well away from everything (side +1 or -1)."""
    xs = np.linspace(-40.0, 40.0, N)
    return np.column_stack([xs, np.full(N, side * (HW - 1.0))])


def make_view(own=None, opp=None, ball=(0.0, 0.0), ball_vel=(0.0, 0.0), own_vel=None, opp_vel=None,
              effort=None, stamina=None, play_mode=PlayMode.PLAY_ON, ball_holder=-1) -> TeamView:
    """A view with the given rows (a dict {index: (x, y)} or a full (N, 2) array); unlisted players
    stand along the touchlines (ours at -y, theirs at +y), goalkeepers far from everything unless
    listed."""
    own_pos = _rows(own, far_positions(-1.0))
    opp_pos = _rows(opp, far_positions(1.0))
    return TeamView(own_pos=own_pos, own_vel=_rows(own_vel, np.zeros((N, 2))), opp_pos=opp_pos,
                    opp_vel=_rows(opp_vel, np.zeros((N, 2))), ball=np.asarray(ball, float),
                    ball_vel=np.asarray(ball_vel, float),
                    stamina=np.full(N, CONFIG.stamina.maximum) if stamina is None else np.asarray(stamina, float),
                    play_mode=play_mode, ball_holder=ball_holder,
                    effort=None if effort is None else np.asarray(effort, float))


def _rows(given, default: np.ndarray) -> np.ndarray:
    if given is None:
        return default.copy()
    if isinstance(given, dict):
        out = default.copy()
        for i, xy in given.items():
            out[i] = xy
        return out
    return np.asarray(given, float).copy()


def ball_at(config: MatchConfig, ball, ball_vel, cycles: int) -> np.ndarray:
    """The ball after ``cycles`` moves of the model (pos += vel; vel *= decay)."""
    pos, vel = np.array(ball, float), np.array(ball_vel, float)
    for _ in range(cycles):
        pos += vel
        vel *= config.physics.ball_decay
    return pos


def roll_player(config: MatchConfig, pos, vel, accel, cycles: int) -> np.ndarray:
    """Where a player ends after ``cycles`` dashes of the constant acceleration ``accel`` (the
    rules by hand: vel += a, speed clip, pos += vel, vel *= decay; no dash-rate penalty)."""
    phys = config.physics
    pos, vel, accel = np.array(pos, float), np.array(vel, float), np.asarray(accel, float)
    for _ in range(cycles):
        vel = vel + accel
        speed = float(np.hypot(*vel))
        if speed > phys.player_speed_max:
            vel *= phys.player_speed_max / speed
        pos = pos + vel
        vel = vel * phys.player_decay
    return pos


def run_straight(config: MatchConfig, pos, vel, target, cycles: int, effort: float = 1.0) -> np.ndarray:
    """Where a player ends after ``cycles`` full dashes in the one direction that brings it
    closest to ``target`` at that cycle: from the point it would coast to, towards the target."""
    coast = roll_player(config, pos, vel, (0.0, 0.0), cycles)
    gap = np.asarray(target, float) - coast
    size = float(np.hypot(*gap))
    if size < 1e-12:
        return coast
    return roll_player(config, pos, vel, gap / size * config.physics.player_accel_max * effort, cycles)


class ScriptedTeam:
    """A team whose players' dash and kick rows come from ``script(view) -> (dash, kick, catch)``;
    records copies of every view's positions and ball."""

    def __init__(self, script=None) -> None:
        self.script = script
        self.views: list[dict] = []

    def reset(self, side_info, config, rng) -> None:
        self.n = side_info.players_per_team

    def act(self, view) -> TeamCommand:
        self.views.append({"cycle": view.cycle, "own_pos": view.own_pos.copy(), "ball": view.ball.copy(),
                           "ball_vel": view.ball_vel.copy(), "play_mode": view.play_mode,
                           "ball_holder": view.ball_holder})
        if self.script is None or view.play_mode not in (PlayMode.PLAY_ON, PlayMode.GOALIE_HOLDS):
            return TeamCommand(dash=np.zeros((self.n, 2)), kick=np.zeros((self.n, 2)))
        dash, kick, catch = self.script(view)
        return TeamCommand(dash=dash, kick=kick, catch=catch)


def play_on_match(home, away, config: MatchConfig, home_pos, away_pos, ball, ball_vel) -> Match:
    """A started match put into play on with the given absolute positions (home attacks +x in
    the first half, so home's team frame is the absolute frame)."""
    match = Match(home, away, seed=0, config=config)
    match.start()
    state = match.state
    state.pos[:N] = home_pos
    state.pos[N:] = -np.asarray(away_pos, float)  # away's frame is turned by 180°
    state.vel[:] = 0.0
    state.ball[:] = ball
    state.ball_vel[:] = ball_vel
    state.play_mode = PlayMode.PLAY_ON
    return match
