"""The PettingZoo parallel environment: one or both teams played by outside agents.

Agents are named ``left_0`` ... ``left_10`` (the home team, which kicks off from the left) and
``right_0`` ... (the away team); player 0 is the goalkeeper. Each step is one match cycle:
the controlled players' actions (see :mod:`soccer_sim.env.spaces`) replace their team's
decision, an uncontrolled side is played by a team (a registered name or a Team object),
and every agent observes the world in its own team's frame.

Rewards: +1 to every agent of a team when it scores, -1 when it concedes; with
``reward_shaping`` w > 0, every agent of a team also gets w times the ball's progress towards
the opponents' goal in the cycle (metres along the team's attacking direction), off by default.
An episode ends for all agents together: *terminated* at the end of the match (or at the
first goal with ``end_on_goal``), *truncated* after ``max_cycles`` steps
(:meth:`soccer_sim.ending.MatchEnd.episode_end` of the environment's
:class:`~soccer_sim.setup.MatchSetup`).
"""

from __future__ import annotations

import functools
from typing import Any

import numpy as np
from gymnasium import spaces
from pettingzoo import ParallelEnv

from soccer_sim.config import MatchConfig
from soccer_sim.env.spaces import ACTION_SIZE, ActionDecoder, ObservationBuilder, check_actions
from soccer_sim.match import Match
from soccer_sim.registry import resolve_team
from soccer_sim.setup import MatchSetup
from soccer_sim.state import AWAY, HOME, PlayMode
from soccer_sim.team import SideInfo, TeamCommand

DEFAULT_OPPONENT = "static"
"""The built-in team that won the default tournament (README): the default opponent."""

SIDES = ("left", "right")
ACTION_MODE_GROUP = "soccer_sim.action_modes"
"""Entry point group of high-level action translators (the built-in one: ``high_level``)."""


def load_action_mode(name: str) -> Any:
    """A new translator of the action mode ``name`` (an entry point of :data:`ACTION_MODE_GROUP`):
    an object with ``size(n)``, ``reset(side_info, config)`` and ``command_for(view, actions)``."""
    from importlib import metadata

    found = {ep.name: ep for ep in metadata.entry_points(group=ACTION_MODE_GROUP)}
    if name not in found:
        known = ", ".join(["low_level", *sorted(found)])
        raise ValueError(f"unknown action_mode {name!r}; known: {known}")
    return found[name].load()()
CONTROLLED = {"left": (HOME,), "right": (AWAY,), "both": (HOME, AWAY)}


class _ExternalTeam:
    """A team whose command comes from the environment's agents (set before each cycle)."""

    def __init__(self, name: str) -> None:
        self.name = name
        self.command: TeamCommand | None = None

    def reset(self, side_info: SideInfo, config: MatchConfig, rng: np.random.Generator) -> None:
        n = side_info.players_per_team
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view) -> TeamCommand:
        return self.command


class SoccerParallelEnv(ParallelEnv):
    """See the module docstring; build it with :func:`soccer_sim.env.parallel_env`."""

    metadata = {"name": "soccer_sim_v0", "render_modes": ["rgb_array", "human"], "render_fps": 10,
                "is_parallelizable": True}

    def __init__(self, controlled: str = "both", opponent: Any = DEFAULT_OPPONENT, max_cycles: int | None = None,
                 end_on_goal: bool = False, config: MatchConfig | None = None, render_mode: str | None = None,
                 reward_shaping: float = 0.0, action_mode: str = "low_level") -> None:
        if controlled not in CONTROLLED:
            raise ValueError(f"controlled must be 'left', 'right' or 'both', got {controlled!r}")
        if render_mode not in (None, *self.metadata["render_modes"]):
            raise ValueError(f"render_mode must be None, 'rgb_array' or 'human', got {render_mode!r}")
        if max_cycles is not None and (isinstance(max_cycles, bool) or int(max_cycles) != max_cycles
                                       or max_cycles < 1):
            raise ValueError(f"max_cycles must be a positive integer or None, got {max_cycles!r}")
        if not (np.isfinite(reward_shaping) and reward_shaping >= 0):
            raise ValueError(f"reward_shaping must be a non-negative number, got {reward_shaping!r}")
        self.config = config or MatchConfig()
        if not isinstance(self.config, MatchConfig):
            raise TypeError(f"config must be a MatchConfig, got {type(self.config).__name__}")
        self.controlled = controlled
        self.sides = CONTROLLED[controlled]
        self.opponent = opponent
        if controlled != "both":
            resolve_team(opponent)  # an unknown name fails here, naming the registered teams
        self.max_cycles = max_cycles
        self.end_on_goal = end_on_goal
        self.render_mode = render_mode
        self.reward_shaping = float(reward_shaping)
        self.setup = setup = MatchSetup.resolve(self.config)
        """The regular match every episode plays (sides, goalkeepers, end)."""
        n = setup.sizes[HOME]
        self.n = n
        self.possible_agents = [f"{SIDES[side]}_{i}" for side in self.sides for i in range(n)]
        self._index = {agent: (int(agent.startswith("right")), int(agent.split("_")[1]))
                       for agent in self.possible_agents}
        sizes, goalies = setup.sizes, setup.goalies
        size = ObservationBuilder(sizes[HOME], sizes[AWAY], goalies[HOME], self.config).size
        self._observation_space = spaces.Box(-np.inf, np.inf, (size,), dtype=np.float32)
        self.action_mode = action_mode
        self._high_level = {side: load_action_mode(action_mode) for side in self.sides} \
            if action_mode != "low_level" else {}
        if self._high_level:
            self._action_space = spaces.Discrete(next(iter(self._high_level.values())).size(n))
        else:
            self._action_space = spaces.Box(-1.0, 1.0, (ACTION_SIZE,), dtype=np.float32)
        self._builders = {side: ObservationBuilder(sizes[side], sizes[1 - side], goalies[side], self.config)
                          for side in self.sides}
        self._decoders = {side: ActionDecoder(sizes[side], goalies[side], self.config) for side in self.sides}
        self._side_agents = {side: [f"{SIDES[side]}_{i}" for i in range(n)] for side in self.sides}
        self._seeds = np.random.SeedSequence()
        self._match: Match | None = None
        self.agents: list[str] = []

    # ------------------------------------------------------------------ spaces
    @functools.lru_cache(maxsize=None)  # noqa: B019 - one space object per agent, as PettingZoo wants
    def observation_space(self, agent: str) -> spaces.Box:
        self._check_agent(agent)
        return self._observation_space

    @functools.lru_cache(maxsize=None)  # noqa: B019
    def action_space(self, agent: str) -> spaces.Box:
        self._check_agent(agent)
        return self._action_space

    def _side_info(self, side: int) -> SideInfo:
        return self.setup.side_info(side, self._match.team_names)

    def _check_agent(self, agent: str) -> None:
        if agent not in self._index:
            raise ValueError(f"unknown agent {agent!r}; the agents are {', '.join(self.possible_agents)}")

    # ------------------------------------------------------------------ episode
    def reset(self, seed: int | None = None, options: dict | None = None) -> tuple[dict, dict]:
        if seed is not None:
            self._seeds = np.random.SeedSequence(int(seed))
        match_seed = int(self._seeds.spawn(1)[0].generate_state(1)[0])
        teams = [_ExternalTeam(f"agents-{SIDES[side]}") if side in self.sides else self.opponent
                 for side in (HOME, AWAY)]
        recorders = self._human_recorders()
        self._match = Match(teams[HOME], teams[AWAY], seed=match_seed, recorders=recorders, setup=self.setup)
        self._match.start()
        self._externals = {side: self._match.teams[side] for side in self.sides}
        for side, translator in self._high_level.items():
            translator.reset(self._side_info(side), self.config)
        self._steps = 0
        self._events_seen = len(self._match.events)
        self.agents = list(self.possible_agents)
        observations = self._observe()
        info = self._info([])
        infos = {agent: {**info, "events": []} for agent in self.agents}
        return observations, infos

    def step(self, actions: dict[str, Any]) -> tuple[dict, dict, dict, dict, dict]:
        match = self._match
        if match is None or not self.agents:
            raise RuntimeError("call reset() before step(), and again after the episode ended")
        self._check_actions(actions)
        for side in self.sides:
            if self._high_level:
                choices = np.array([self._check_choice(f"{SIDES[side]}_{i}", actions[f"{SIDES[side]}_{i}"])
                                    for i in range(self.n)], dtype=np.int64)
                command = self._high_level[side].command_for(match.frames[side].view, choices)
            else:
                names = self._side_agents[side]
                command = self._decoders[side].decode(check_actions(names, [actions[a] for a in names]))
            external = self._externals[side].command
            external.dash[:] = command.dash
            external.kick[:] = command.kick
            external.catch = command.catch
        state = match.state
        score_before = state.score.copy()
        ball_before = state.ball.copy()
        match.step()
        self._steps += 1
        goals = state.score - score_before
        team_reward = {HOME: float(goals[HOME] - goals[AWAY]), AWAY: float(goals[AWAY] - goals[HOME])}
        if self.reward_shaping:
            progress = (state.ball[0] - ball_before[0]) * state.home_attacks
            team_reward[HOME] += self.reward_shaping * progress
            team_reward[AWAY] -= self.reward_shaping * progress
        terminated, truncated = self.setup.end.episode_end(state, goal_scored=bool(goals.any()),
                                                           end_on_goal=self.end_on_goal, steps=self._steps,
                                                           max_cycles=self.max_cycles)
        observations = self._observe()
        events = self._new_events()
        rewards = {agent: team_reward[self._index[agent][0]] for agent in self.agents}
        terminations = {agent: terminated for agent in self.agents}
        truncations = {agent: truncated for agent in self.agents}
        info = self._info(events)
        infos = {agent: {**info, "events": list(events)} for agent in self.agents}
        if terminated or truncated:
            self.agents = []
            if self.render_mode == "human":
                match.finish()
        return observations, rewards, terminations, truncations, infos

    def _check_choice(self, agent: str, action: Any) -> int:
        """A high-level action as an int in the Discrete space; ValueError naming the agent."""
        value = np.asarray(action)
        if value.shape not in ((), (1,)) or value.dtype.kind not in "iu":
            raise ValueError(f"action of {agent} must be one integer (action_mode={self.action_mode!r}), "
                             f"got {action!r}")
        choice = int(value.reshape(-1)[0])
        if not 0 <= choice < self._action_space.n:
            raise ValueError(f"action of {agent} must be in 0..{self._action_space.n - 1}, got {choice}")
        return choice

    def _check_actions(self, actions: dict[str, Any]) -> None:
        if not isinstance(actions, dict):
            raise ValueError(f"actions must be a dict agent -> action, got {type(actions).__name__}")
        unknown = sorted(set(actions) - set(self.agents))
        if unknown:
            finished = [a for a in unknown if a in self._index]
            raise ValueError(f"actions for agents that are not live: {', '.join(map(str, unknown))}"
                             + (f" ({', '.join(finished)} finished or not controlled)" if finished else ""))
        missing = [agent for agent in self.agents if agent not in actions]
        if missing:
            raise ValueError(f"no action for the live agents {', '.join(missing)}")

    # ------------------------------------------------------------------ what agents see
    def _observe(self) -> dict[str, np.ndarray]:
        match = self._match
        state = match.state
        observations = {}
        for side in self.sides:
            view = match.frames[side].update_view(state, state.attack_direction(side))
            rows = self._builders[side].build(view)
            for i in range(self.n):
                observations[f"{SIDES[side]}_{i}"] = rows[i]
        return observations

    def _new_events(self) -> list[str]:
        from soccer_sim.analysis.events import describe_event

        log = self._match.events
        names = self._match.team_names
        start, self._events_seen = self._events_seen, len(log)
        return [describe_event(names, log.kind[k], log.team[k], log.player[k], log.x[k], log.y[k], log.detail[k])
                for k in range(start, len(log))]

    def _info(self, events: list[str]) -> dict[str, Any]:
        state = self._match.state
        return {"play_mode": PlayMode(state.play_mode).name.lower(), "cycle": int(state.cycle),
                "score": (int(state.score[0]), int(state.score[1])), "events": events}

    def state(self) -> np.ndarray:
        """The global state, absolute frame, float32: every player's x, y, vx, vy (home then
        away), the ball's x, y, vx, vy, the score, the cycle and the play mode."""
        if self._match is None:
            raise RuntimeError("call reset() first")
        s = self._match.state
        return np.concatenate([np.hstack([s.pos, s.vel]).reshape(-1), s.ball, s.ball_vel,
                               s.score.astype(float), [float(s.cycle), float(int(s.play_mode))]]).astype(np.float32)

    def state_space(self) -> spaces.Box:
        return spaces.Box(-np.inf, np.inf, (8 * self.n + 8,), dtype=np.float32)

    # ------------------------------------------------------------------ rendering
    def _human_recorders(self) -> list:
        if self.render_mode != "human":
            return []
        from soccer_sim.replay import ReplayError, RerunRecorder
        from soccer_sim.replay.recorder import has_display

        if not has_display():
            raise ReplayError("render_mode='human' streams to a rerun viewer, which needs a display; use "
                              "render_mode='rgb_array', or record with soccer_sim.replay.RerunRecorder(path) "
                              "and watch the file elsewhere")
        return [RerunRecorder(spawn=True, flush_every=10)]

    def render(self) -> np.ndarray | None:
        if self.render_mode is None:
            import gymnasium

            gymnasium.logger.warn("render() called without a render_mode; pass render_mode='rgb_array' or 'human'")
            return None
        if self._match is None:
            raise RuntimeError("call reset() before render()")
        if self.render_mode == "rgb_array":
            from soccer_sim.env.render import render_rgb

            return render_rgb(self._match.state, self.config.field)
        return None  # "human": the match streams to the viewer as it plays

    def close(self) -> None:
        self._match = None
