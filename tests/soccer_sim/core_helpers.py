"""Helpers for the match-loop tests: scripted teams and a quiet (noise-free) config."""

from __future__ import annotations

import hashlib
from dataclasses import replace

import numpy as np

from soccer_sim import MatchConfig, TeamCommand
from soccer_sim.config import PhysicsConfig


def quiet_config(**match_fields) -> MatchConfig:
    """The default config without any noise, so physics results are exact."""
    physics = replace(PhysicsConfig(), player_rand=0.0, ball_rand=0.0, kick_rand=0.0)
    return replace(MatchConfig(), physics=physics, **match_fields)


class Scripted:
    """A team whose command comes from ``script(view) -> (dash, kick)`` (own frame);
    remembers every view's copy of the fields named in ``keep``."""

    def __init__(self, script=None, keep=(), catch=False, move=None) -> None:
        self.script = script
        self.keep = keep
        self.catch = catch
        self.move = move
        self.seen: list[dict] = []
        self.resets = 0

    def reset(self, side_info, config, rng) -> None:
        self.n = side_info.players_per_team
        self.side_info = side_info
        self.rng = rng
        self.resets += 1

    def act(self, view) -> TeamCommand:
        if self.keep:
            self.seen.append({name: np.copy(getattr(view, name)) for name in self.keep})
        if self.script is None:
            dash, kick = np.zeros((self.n, 2)), np.zeros((self.n, 2))
        else:
            dash, kick = self.script(view)
        return TeamCommand(dash=dash, kick=kick, catch=self.catch, move=self.move)


class TrajectoryHash:
    """Recorder hashing every cycle's positions, velocities, ball and stamina (bit-exact)."""

    def __init__(self) -> None:
        self.digest = hashlib.sha256()
        self.cycles = 0

    def on_start(self, match) -> None:
        self._add(match)

    def on_cycle(self, match) -> None:
        self.cycles += 1
        self._add(match)

    def on_end(self, match) -> None:
        events = match.events.as_arrays()
        for key in sorted(events):
            self.digest.update(events[key].tobytes())

    def _add(self, match) -> None:
        state = match.state
        for array in (state.pos, state.vel, state.ball, state.ball_vel, state.stamina, state.effort,
                      state.recovery, state.capacity):
            self.digest.update(np.ascontiguousarray(array).tobytes())

    def hexdigest(self) -> str:
        return self.digest.hexdigest()
