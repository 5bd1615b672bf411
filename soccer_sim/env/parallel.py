"""The PettingZoo parallel environment: one or both teams played by outside agents.

Agents are named ``left_0`` ... ``left_{n-1}`` (the home team, which kicks off from the left)
and ``right_0`` ... ``right_{m-1}`` (the away team), each side sized from the scenario (11 a
side in the regular match); player 0 is the goalkeeper where the side has one. Each step is
one match cycle: the controlled players' actions (:mod:`soccer_sim.env.spaces`) replace their
team's decision, an uncontrolled side is played by a team (a registered name or a Team
object), and every agent observes the world in its own team's frame.

Under ``observation="partial"`` an agent observes only its own player's perception
(:mod:`soccer_sim.env.partial_spaces`; the match's views of a cycle are taken one call ahead,
:mod:`soccer_sim.env.lookahead`), and with ``say_values`` its action also says a message
(:mod:`soccer_sim.env.say_codec`).

Rewards: :mod:`soccer_sim.env.rewards` (goals by default; named dense terms). Infos:
:mod:`soccer_sim.env.infos` (numbers and fixed-shape arrays). The global state:
:mod:`soccer_sim.env.global_state` (``state()`` and the ``state_space`` attribute).

An episode ends for all agents together: *terminated* when the match is over (its time, or
one of the scenario's end conditions; or at the first goal with ``end_on_goal``), *truncated*
after ``max_cycles`` steps or at the scenario's ``cycle_limit`` (time limits that cut an
episode short, which learners should bootstrap through;
:meth:`soccer_sim.ending.MatchEnd.episode_end`).

**Batched interface** (no dicts): ``reset_arrays(seed)`` and ``step_arrays(actions)`` with
one row per agent in :attr:`possible_agents` order (left first): ``actions`` (N, 5) floats for
the low-level mode (N, 6 + s with ``say_values=s``), (N,) or (N, 1) integers for a discrete
mode; ``step_arrays`` returns ``obs`` (N, D) float32, ``rewards`` (N,) float32,
``terminations`` and ``truncations`` (N,) bool, new arrays each call. ``action_masks()`` is the
(N, A) int8 mask of a discrete mode, :meth:`current_infos` the dict infos on demand. Both
interfaces drive the same episode and may be mixed.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from gymnasium import spaces
from pettingzoo import ParallelEnv

from soccer_sim.env.global_state import GlobalState
from soccer_sim.env.infos import EpisodeInfo
from soccer_sim.env.options import (CONTROLLED, DEFAULT_OPPONENT, RENDER_MODES, SIDES, check_seed,
                                    load_action_mode, resolve_options)
from soccer_sim.env.persistence import ReplayPickling
from soccer_sim.env.rewards import Rewards
from soccer_sim.env.lookahead import LookaheadObserver
from soccer_sim.env.partial_spaces import PartialObservationBuilder
from soccer_sim.env.spaces import (ACTION_SIZE, ActionDecoder, ObservationBuilder, check_action, check_actions,
                                   check_choice, episode_horizon)
from soccer_sim.match import Match
from soccer_sim.state import AWAY, HOME
from soccer_sim.team import SideInfo, TeamCommand

__all__ = ["CONTROLLED", "DEFAULT_OPPONENT", "SIDES", "SoccerParallelEnv", "load_action_mode"]


class _ExternalTeam:
    """A team whose command comes from the environment's agents (set before each cycle); it
    ignores what it is given to see, so it plays under either observation mode."""

    observation_modes = ("full", "partial")

    def __init__(self, name: str) -> None:
        self.name = name
        self.command: TeamCommand | None = None

    def reset(self, side_info: SideInfo, config: Any, rng: np.random.Generator) -> None:
        n = side_info.players_per_team
        self.command = TeamCommand(dash=np.zeros((n, 2)), kick=np.zeros((n, 2)))

    def act(self, view) -> TeamCommand:
        return self.command


class SoccerParallelEnv(ReplayPickling, ParallelEnv):
    """See the module docstring; build it with :func:`soccer_sim.env.parallel_env`."""

    metadata = {"name": "soccer_sim_v1", "render_modes": list(RENDER_MODES), "render_fps": 10,
                "is_parallelizable": True}

    def __init__(self, **options: Any) -> None:
        self._options = opts = resolve_options(**options)
        kw = opts.kwargs
        self.config = opts.setup.config
        self.setup = setup = opts.setup
        """The match every episode plays (sides, goalkeepers, start, end), from the scenario."""
        self.scenario = setup.scenario
        self.controlled, self.opponent = kw["controlled"], kw["opponent"]
        self.max_cycles, self.end_on_goal = kw["max_cycles"], kw["end_on_goal"]
        self.render_mode, self.action_mode = kw["render_mode"], kw["action_mode"]
        self.sides = opts.sides
        sizes, goalies = setup.sizes, setup.goalies
        self.possible_agents = [f"{SIDES[side]}_{i}" for side in self.sides for i in range(sizes[side])]
        self._index = {agent: k for k, agent in enumerate(self.possible_agents)}
        first = (0, sizes[HOME])
        offsets = {side: sum(sizes[s] for s in self.sides if s < side) for side in self.sides}
        self._blocks = {side: slice(offsets[side], offsets[side] + sizes[side]) for side in self.sides}
        rows = {side: slice(first[side], first[side] + sizes[side]) for side in self.sides}
        self.horizon = horizon = episode_horizon(self.max_cycles, self.scenario)
        """The episode's last cycle when it ends before the match would (None: the match's own
        length): the time feature's scale (:func:`~soccer_sim.env.spaces.episode_horizon`)."""
        self.partial = self.config.observation.partial
        """Whether agents observe partially (``observation="partial"``, :mod:`soccer_sim.env.partial_spaces`)."""
        self.say_values = say = kw["say_values"]
        if self.partial:
            self._builders = {side: PartialObservationBuilder(sizes[side], sizes[1 - side], goalies[side], self.config,
                                                              kw["observation_slots"], horizon, say)
                              for side in self.sides}
        else:
            self._builders = {side: ObservationBuilder(sizes[side], sizes[1 - side], goalies[side], self.config,
                                                       kw["observation_slots"], horizon) for side in self.sides}
        self._action_size = ACTION_SIZE + (1 + say if say else 0)
        """Values of a low-level action: 5, and the speak flag and the message's values with ``say_values``."""
        builder = self._builders[self.sides[0]]
        self.observation_slots = builder.slots
        box = spaces.Box(builder.low, builder.high, dtype=np.float32)
        self._decoders = {side: ActionDecoder(sizes[side], goalies[side], self.config) for side in self.sides}
        self._perceived: dict[int, object] = {}
        """Each controlled side's view of the cycle being played (what its agents' observations
        were built from): the decoders send a kick only for a player it shows near the ball."""
        low_level = self.action_mode == "low_level"
        self._translators = {} if low_level else {side: load_action_mode(self.action_mode) for side in self.sides}
        if low_level:
            self._action_space = spaces.Box(-1.0, 1.0, (self._action_size,), dtype=np.float32)
            self._masks = None
        else:
            size = next(iter(self._translators.values())).size(self.observation_slots)
            self._action_space = spaces.Discrete(size)
            self._masks = np.ones((len(self.possible_agents), size), dtype=np.int8)
        self._mask_in_obs = kw["action_mask_in_observation"]
        self._observation_space = spaces.Dict({"observation": box, "action_mask": spaces.Box(
            0, 1, (self._action_space.n,), dtype=np.int8)}) if self._mask_in_obs else box
        self.observation_spaces = {agent: self._observation_space for agent in self.possible_agents}
        self.action_spaces = {agent: self._action_space for agent in self.possible_agents}
        self._global = GlobalState(sizes, self.observation_slots, self.config, horizon)
        self.state_space = self._global.space
        """The global state's Box (:mod:`soccer_sim.env.global_state`)."""
        self._rewards = Rewards(opts.weights, self.sides, rows, offsets, len(self.possible_agents))
        self._obs = np.zeros((len(self.possible_agents), box.shape[0]), dtype=np.float32)
        self._seeds = np.random.SeedSequence()
        self._match: Match | None = None
        self._match_seed: int | None = None
        self._episodes = 0
        self._log: list[np.ndarray] = []
        self._done = (False, False)
        self.agents: list[str] = []

    # ------------------------------------------------------------------ spaces
    def observation_space(self, agent: str) -> spaces.Space:
        """The one observation space of every agent (built once, with the environment)."""
        self._check_agent(agent)
        return self._observation_space

    def action_space(self, agent: str) -> spaces.Space:
        """The one action space of every agent (built once, with the environment)."""
        self._check_agent(agent)
        return self._action_space

    def _check_agent(self, agent: str) -> None:
        if agent not in self._index:
            raise ValueError(f"unknown agent {agent!r}; the agents are {', '.join(self.possible_agents)}")

    # ------------------------------------------------------------------ episodes
    def reset(self, seed: int | None = None, options: dict | None = None) -> tuple[dict, dict]:
        """Start an episode: (observations, infos) by agent. ``seed``: None or a non-negative
        integer (None continues the environment's seed sequence); ``options`` is unused."""
        self.reset_arrays(seed)
        return self._observation_dict(), self.current_infos()

    def reset_arrays(self, seed: int | None = None) -> np.ndarray:
        """Start an episode (``seed``: None continues the environment's seed sequence) and
        return the (N, D) observations, rows in :attr:`possible_agents` order."""
        check_seed(seed)
        if seed is not None:
            self._seeds = np.random.SeedSequence(int(seed))
        self._start(int(self._seeds.spawn(1)[0].generate_state(1)[0]), record=True)
        return self._obs.copy()

    def _start(self, match_seed: int, record: bool) -> None:
        kw = self._options.kwargs
        sizes = self.setup.sizes
        teams = [_ExternalTeam(f"agents-{SIDES[side]}") if side in self.sides or not sizes[side] else self.opponent
                 for side in (HOME, AWAY)]
        recorders = []
        if record and self.render_mode == "human":
            from soccer_sim.env.render import human_recorder

            recorders.append(human_recorder(kw["record_dir"], self._episodes, match_seed))
        self._episodes += 1
        self._match = match = Match(teams[HOME], teams[AWAY], seed=match_seed, recorders=recorders, setup=self.setup)
        self._match_seed = match_seed
        match.start()
        if self.partial:
            match.observer = LookaheadObserver(match.observer)  # the agents see a cycle before it is played
            for builder in self._builders.values():
                builder.reset()
        self._externals = {side: match.teams[side].command for side in self.sides}
        for side, translator in self._translators.items():
            translator.reset(self.setup.side_info(side, match.team_names), self.config)
        self._steps = 0
        self._log = []
        self._done = (False, False)
        self._info = EpisodeInfo(sizes[HOME], kw["event_texts"])  # the start is not a cycle played: no counts
        self._rewards.out[:] = 0.0
        self.agents = list(self.possible_agents)
        self._observe()

    @property
    def match_seed(self) -> int | None:
        """The seed of the match the current episode plays (None before the first reset):
        ``run_match(..., seed=env.match_seed)`` with the same setup plays the same match, e.g.
        with :class:`~soccer_sim.env.policy_team.PolicyTeam` in the controlled side's place."""
        return self._match_seed

    def step(self, actions: dict[str, Any]) -> tuple[dict, dict, dict, dict, dict]:
        """One cycle from every live agent's action: (observations, rewards, terminations,
        truncations, infos) by agent; a ValueError naming the agent for a bad action."""
        self._check_live()
        self._check_keys(actions)
        values = [actions[agent] for agent in self.possible_agents]
        if self._translators:
            checked = np.array([self._check_choice(a, v) for a, v in zip(self.possible_agents, values)],
                               dtype=np.int64)
        else:
            checked = check_actions(self.possible_agents, values, self._action_size)
        agents = self.agents
        self._advance(checked)
        rewards = dict(zip(agents, self._rewards.out.tolist()))
        terminated, truncated = self._done
        return (self._observation_dict(agents), rewards, dict.fromkeys(agents, terminated),
                dict.fromkeys(agents, truncated), self.current_infos(agents))

    def step_arrays(self, actions: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """One step from the (N, A) actions of all agents (see the module docstring); returns
        (obs (N, D), rewards (N,), terminations (N,), truncations (N,))."""
        self._check_live()
        n = len(self.possible_agents)
        if self._translators:
            rows = np.asarray(actions)
            if rows.shape == (n, 1):
                rows = rows[:, 0]
            if rows.shape != (n,) or rows.dtype.kind not in "iu" or not (
                    (rows >= 0) & (rows < self._action_space.n)).all():
                rows = np.array([self._check_choice(a, v) for a, v in zip(self.possible_agents, _rows(actions, n))],
                                dtype=np.int64)
        else:
            rows = check_actions(self.possible_agents, _rows(actions, n), self._action_size)
        self._advance(rows)
        terminated, truncated = self._done
        return (self._obs.copy(), self._rewards.out.copy(), np.full(n, terminated), np.full(n, truncated))

    def _advance(self, rows: np.ndarray, observe: bool = True) -> None:
        """Play one cycle with the checked actions ``rows`` of every agent (``observe=False``:
        refresh the teams' views only, without building observations and masks, when
        replaying steps nobody looks at)."""
        match = self._match
        state = match.state
        for side in self.sides:
            block = rows[self._blocks[side]]
            if self._translators:
                command = self._translators[side].command_for(match.frames[side].view, block)
            else:
                command = self._decoders[side].decode(block, self._perceived[side])
            external = self._externals[side]
            external.dash[:] = command.dash
            external.kick[:] = command.kick
            external.catch = command.catch
            if self.say_values:
                external.say = self._builders[side].codec.encode(block[:, ACTION_SIZE + 1:], block[:, ACTION_SIZE] > 0)
        self._log.append(rows.copy())
        self._rewards.before(state)
        mark = len(match.events)
        score = int(state.score.sum())
        match.step()
        self._steps += 1
        self._info.update(match, mark)
        self._rewards.after(state, match.events, mark)
        terminated, truncated = self.setup.end.episode_end(state, goal_scored=int(state.score.sum()) != score,
                                                           end_on_goal=self.end_on_goal, steps=self._steps,
                                                           max_cycles=self.max_cycles)
        if terminated and match.end_reason == "cycle_limit":
            terminated, truncated = False, True  # the scenario's time limit: a cut, not an outcome
        self._done = (terminated, truncated)
        self._observe(build=observe)
        if self._done[0] or self._done[1]:
            self.agents = []
            if self.render_mode == "human":
                match.finish()

    def _check_live(self) -> None:
        if self._match is None or not self.agents:
            raise RuntimeError("call reset() before step(), and again after the episode ended")

    def _check_keys(self, actions: dict[str, Any]) -> None:
        if not isinstance(actions, dict):
            raise ValueError(f"actions must be a dict agent -> action, got {type(actions).__name__}")
        unknown = sorted(set(actions) - set(self.agents), key=str)
        if unknown:
            finished = [a for a in unknown if a in self._index]
            raise ValueError(f"actions for agents that are not live: {', '.join(map(str, unknown))}"
                             + (f" ({', '.join(finished)} finished or not controlled)" if finished else ""))
        missing = [agent for agent in self.agents if agent not in actions]
        if missing:
            raise ValueError(f"no action for the live agents {', '.join(missing)}")

    def _check_choice(self, agent: str, action: Any) -> int:
        """A discrete action as an int in the action space; ValueError naming the agent
        (:func:`~soccer_sim.env.spaces.check_choice`)."""
        return check_choice(agent, action, self._action_space.n, self.action_mode)

    def check_agent_action(self, agent: str, action: Any) -> None:
        """ValueError naming ``agent`` if ``action`` is not a valid action (the AEC form checks
        each agent's action at its own step)."""
        self._check_agent(agent)
        if self._translators:
            self._check_choice(agent, action)
        else:
            check_action(agent, action, self._action_size)

    # ------------------------------------------------------------------ what agents see
    def _observe(self, build: bool = True) -> None:
        match = self._match
        state = match.state
        if self.partial:  # each agent's own view of the coming cycle (the memories see every cycle)
            views = match.observer.observe(state)
            for side in self.sides:
                self._perceived[side] = views[side]
                self._builders[side].build(views[side], out=self._obs[self._blocks[side]], write=build)
            return
        for side in self.sides:
            view = self._perceived[side] = match.frames[side].update_view(state, state.attack_direction(side))
            if not build:
                continue
            block = self._blocks[side]
            self._builders[side].build(view, out=self._obs[block])
            if self._masks is not None:
                translator = self._translators[side]
                if hasattr(translator, "action_mask"):
                    self._masks[block] = translator.action_mask(view, self.observation_slots)

    def _observation_dict(self, agents: list[str] | None = None) -> dict[str, Any]:
        obs = self._obs.copy()
        names = self.possible_agents if agents is None else agents
        if not self._mask_in_obs:
            return dict(zip(names, obs))
        masks = self._masks.copy()
        return {agent: {"observation": obs[k], "action_mask": masks[k]} for k, agent in enumerate(names)}

    def action_masks(self) -> np.ndarray | None:
        """(N, A) int8: 1 where each agent's discrete action can be taken now (rows in
        :attr:`possible_agents` order); None for the low-level mode, which has no mask."""
        return None if self._masks is None else self._masks.copy()

    def current_infos(self, agents: list[str] | None = None) -> dict[str, dict[str, Any]]:
        """Every agent's info after the last reset or step (:mod:`soccer_sim.env.infos`)."""
        if self._match is None:
            raise RuntimeError("call reset() first")
        names = self.possible_agents if agents is None else agents
        info = self._info.info(self._match.state)
        out = {agent: dict(info) for agent in names}
        if self._masks is not None and not self._mask_in_obs:  # one place only: TorchRL reads both
            masks = self._masks.copy()
            masks.flags.writeable = False
            for k, agent in enumerate(names):
                out[agent]["action_mask"] = masks[k]
        if self._info.event_texts:
            for agent in names:
                out[agent]["event_texts"] = list(info["event_texts"])
        return out

    def state(self) -> np.ndarray:
        """The global state, normalised like the observations (:mod:`soccer_sim.env.global_state`)."""
        if self._match is None:
            raise RuntimeError("call reset() first")
        return self._global.build(self._match.state)

    # ------------------------------------------------------------------ rendering
    def render(self) -> np.ndarray | None:
        """The top view as an (H, W, 3) uint8 image (``rgb_array``), or None (``human``: the
        match streams to the viewer, or its file, as it plays)."""
        if self.render_mode is None:
            import gymnasium

            gymnasium.logger.warn("render() called without a render_mode; pass render_mode='rgb_array' or 'human'")
            return None
        if self._match is None:
            raise RuntimeError("call reset() before render()")
        if self.render_mode == "rgb_array":
            from soccer_sim.env.render import render_rgb

            return render_rgb(self._match.state, self.config.field)
        return None  # "human": the match streams to the viewer (or its file) as it plays

    def close(self) -> None:
        """End the episode (a human recording is flushed) and drop the match."""
        if self._match is not None and self.agents and self.render_mode == "human":
            self._match.finish()  # flush the recording
        self._match = None
        self.agents = []


def _rows(actions: Any, n: int) -> list[Any]:
    """``actions`` as a list of ``n`` rows for the agent-by-agent checks (ValueError for another count)."""
    try:
        rows = list(actions)
    except TypeError:
        raise ValueError(f"actions must be an array of one row per agent ({n}), got {actions!r}") from None
    if len(rows) != n:
        raise ValueError(f"actions must have one row per agent ({n}), got {len(rows)}")
    return rows
