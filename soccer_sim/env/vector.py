"""Several matches stepped together, arrays in and out: :func:`vector_env`.

A vector environment holds ``num_envs`` copies of the parallel environment (the same options
for each) and steps them as one: actions go in as one array, observations, rewards and flags
come out as arrays, agents in the order of ``possible_agents`` (``left_0``, ``left_1``, ...,
``right_0``, ...):

=================  ================================  =========================================
what               shape                             what
=================  ================================  =========================================
actions            ``(E, N, *action_shape)``         ``(E, N, 5)`` float for low-level actions
                                                     (``6 + s`` with ``say_values=s``),
                                                     ``(E, N)`` integers for the high level
observations       ``(E, N, D)`` float32             every agent's observation
rewards            ``(E, N)`` float32                the reward of the step
terminations       ``(E, N)`` bool                   episode over (match end, goal, scenario)
truncations        ``(E, N)`` bool                   cut at ``max_cycles``
infos              list of E dicts agent -> info     as the parallel environment gives them
                                                     (empty dicts with ``infos=False``)
=================  ================================  =========================================

``E`` is ``num_envs`` and ``N`` the agents of one environment. A match whose episode ends in a
step is reset at once in that step (the "same step" auto-reset of Stable-Baselines3 and
SuperSuit): the step returns the new episode's first observations, and that match's info dict
carries the ended episode under ``"final_observation"`` (its ``(N, D)`` last observations) and
``"final_info"`` (its last agent infos). A match is never stepped after its end.

Seeds: ``reset(seed=s)`` resets match ``i`` with seed ``s + i`` (a list gives one seed per
match); every later reset, the automatic ones included, draws from that match's own seed
sequence, exactly as a single environment's ``reset()`` without a seed does. So match ``i``
of a vector environment gives, step for step, what ``parallel_env(...).reset(seed=s + i)``
gives with the same actions, in process or in a subprocess.

``processes=0`` steps every match in this process, one after another
(:class:`SyncVectorEnv`); ``processes=k`` spreads them over ``k`` worker processes
(:class:`SubprocVectorEnv`: contiguous blocks, started with multiprocessing's ``spawn`` method
by default, so it works the same on Linux, macOS and Windows and from notebooks; a script
that makes one must guard its top level with ``if __name__ == "__main__":``). Each worker
builds its matches itself from ``env_fn`` (default: ``parallel_env(**env_kwargs)``), which
must therefore pickle: a module-level function or a ``functools.partial`` of one, with a team
named by its registered name rather than passed as an object. Close a subprocess vector
environment (``close()`` or a ``with`` block) to end its workers.

Bad actions (the wrong shape, a NaN, a discrete choice out of range) are refused with a
ValueError naming the match and the agent before any match steps; an error raised inside a
worker is raised in the caller with its own type, the worker's traceback chained to it.
"""

from __future__ import annotations

import functools
import multiprocessing as mp
import traceback
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np


def vector_env(num_envs: int, processes: int = 0, env_fn: Callable[[], Any] | None = None,
               context: str = "spawn", infos: bool = True, **env_kwargs: Any) -> SyncVectorEnv | SubprocVectorEnv:
    """``num_envs`` matches of ``parallel_env(**env_kwargs)`` (or of ``env_fn()``) stepped together,
    in this process (``processes=0``) or in ``processes`` worker processes; see the module docstring.
    ``infos=False`` leaves the agent infos out (faster: no dicts built or sent)."""
    if env_fn is not None and env_kwargs:
        raise ValueError("give either env_fn or parallel_env options, not both")
    if env_fn is None:
        from soccer_sim.env.parallel import SoccerParallelEnv  # what parallel_env makes

        env_fn = functools.partial(SoccerParallelEnv, **env_kwargs)
    if isinstance(processes, bool) or not isinstance(processes, (int, np.integer)) or processes < 0:
        raise ValueError(f"processes must be a non-negative integer, got {processes!r}")
    if processes == 0:
        return SyncVectorEnv(num_envs, env_fn, infos=infos)
    return SubprocVectorEnv(num_envs, env_fn, processes=int(processes), context=context, infos=infos)


def _check_num_envs(num_envs: Any) -> int:
    if isinstance(num_envs, bool) or not isinstance(num_envs, (int, np.integer)) or num_envs < 1:
        raise ValueError(f"num_envs must be a positive integer, got {num_envs!r}")
    return int(num_envs)


def _seeds(seed: int | Sequence[int] | None, count: int) -> list[int | None]:
    """One seed (or None) per match: ``seed + i``, or the ``count`` seeds of a sequence."""
    if seed is None:
        return [None] * count
    if isinstance(seed, (int, np.integer)) and not isinstance(seed, bool):
        return [int(seed) + i for i in range(count)]
    seeds = list(seed)
    if len(seeds) != count or not all(isinstance(s, (int, np.integer)) and not isinstance(s, bool) for s in seeds):
        raise ValueError(f"seed must be an integer, None or {count} integers (one per match), got {seed!r}")
    return [int(s) for s in seeds]


class _Slot:
    """One match of a vector environment: arrays in and out, reset as soon as its episode ends.

    Uses the environment's batched ``reset_arrays``/``step_arrays`` where it has them (the
    soccer environment), else the dict API of any PettingZoo ParallelEnv with Box observations."""

    def __init__(self, env: Any, infos: bool) -> None:
        self.env = env
        self.agents = list(env.possible_agents)
        space = env.observation_space(self.agents[0])
        if not hasattr(space, "shape") or space.shape is None or len(space.shape) != 1:
            raise ValueError(f"a vector environment needs flat Box observations, got {space} "
                             "(leave action_mask_in_observation off: the masks are in the infos)")
        self.shape = space.shape
        # Looked up on the class: a wrapper forwarding attributes must not be bypassed.
        self.arrays = all(hasattr(type(env), name) for name in ("step_arrays", "reset_arrays", "current_infos"))
        self.infos = infos

    def reset(self, seed: int | None) -> tuple[np.ndarray, dict]:
        if self.arrays:
            obs = self.env.reset_arrays(seed)
            return obs, self.env.current_infos() if self.infos else {}
        observations, infos = self.env.reset(seed=seed)
        return self._stack(observations), infos if self.infos else {}

    def step(self, actions: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, dict]:
        env = self.env
        if self.arrays:
            obs, reward, terminated, truncated = env.step_arrays(actions)
            infos = env.current_infos() if self.infos else {}
        else:
            live = env.agents
            observations, rewards, terminations, truncations, infos = env.step(
                {agent: actions[k] for k, agent in enumerate(self.agents) if agent in live})
            obs = self._stack(observations)
            reward = np.array([rewards.get(a, 0.0) for a in self.agents], dtype=np.float32)
            terminated = np.array([terminations.get(a, True) for a in self.agents], dtype=bool)
            truncated = np.array([truncations.get(a, False) for a in self.agents], dtype=bool)
            infos = infos if self.infos else {}
        if not env.agents:  # the episode ended for everyone: start the next at once
            infos = {"final_observation": obs, "final_info": infos}
            obs, reset_infos = self.reset(None)
            infos.update(reset_infos)
        return obs, reward, terminated, truncated, infos

    def _stack(self, observations: dict) -> np.ndarray:
        """The (N, D) observations in agent order; zeros for an agent without one this step."""
        return np.stack([np.asarray(observations[a], dtype=np.float32) if a in observations
                         else np.zeros(self.shape, dtype=np.float32) for a in self.agents])


class _VectorBase:
    """What both vector environments share: spaces, checks, the context-manager protocol."""

    num_envs: int
    possible_agents: list[str]
    observation_space: Any
    action_space: Any

    @property
    def num_agents(self) -> int:
        """Agents of one match (N)."""
        return len(self.possible_agents)

    def _check_actions(self, actions: Any) -> np.ndarray:
        space = self.action_space
        shape = (self.num_envs, self.num_agents, *space.shape)
        array = np.asarray(actions)
        if array.shape != shape:
            raise ValueError(f"actions must have shape {shape} (matches, agents, action), got {array.shape}")
        if space.shape == () and array.dtype.kind not in "iu":
            raise ValueError(f"actions must be integers for a discrete action space, got dtype {array.dtype}")
        # Checked here, before any match steps, so that a bad action leaves every match where it was.
        if space.shape == ():
            bad = (array < 0) | (array >= space.n)
            what = f"in 0..{space.n - 1}"
        else:
            try:
                bad = ~np.isfinite(array.astype(np.float64)).reshape(*shape[:2], -1).all(axis=2)
            except (TypeError, ValueError):
                raise ValueError(f"actions must be numbers, got dtype {array.dtype}") from None
            what = "finite"
        if bad.any():
            e, k = (int(i) for i in np.argwhere(bad)[0])
            raise ValueError(f"action of {self.possible_agents[k]} in match {e} must be {what}, "
                             f"got {array[e, k].tolist()}")
        return array

    def __enter__(self):
        return self

    def __exit__(self, *exc_info: Any) -> None:
        self.close()


class SyncVectorEnv(_VectorBase):
    """The matches of a vector environment stepped one after another in this process."""

    def __init__(self, num_envs: int, env_fn: Callable[[], Any], infos: bool = True) -> None:
        self.num_envs = _check_num_envs(num_envs)
        self._slots = [_Slot(env_fn(), infos) for _ in range(self.num_envs)]
        first = self._slots[0].env
        self.possible_agents = list(first.possible_agents)
        self.observation_space = first.observation_space(self.possible_agents[0])
        """The observation space of one agent."""
        self.action_space = first.action_space(self.possible_agents[0])
        """The action space of one agent."""
        self.envs = [slot.env for slot in self._slots]
        """The parallel environments (for inspection: step them through this object only)."""

    def reset(self, seed: int | Sequence[int] | None = None) -> tuple[np.ndarray, list[dict]]:
        """Resets every match; observations (E, N, D) and the infos (see the module docstring)."""
        out = [slot.reset(s) for slot, s in zip(self._slots, _seeds(seed, self.num_envs))]
        return np.stack([o for o, _ in out]), [i for _, i in out]

    def step(self, actions: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, list[dict]]:
        """One cycle of every match: observations, rewards, terminations, truncations, infos."""
        array = self._check_actions(actions)
        return _gather([slot.step(array[e]) for e, slot in enumerate(self._slots)])

    def close(self) -> None:
        for slot in self._slots:
            slot.env.close()


def _gather(results: list[tuple]) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, list[dict]]:
    obs, rewards, terminated, truncated, infos = zip(*results)
    return np.stack(obs), np.stack(rewards), np.stack(terminated), np.stack(truncated), list(infos)


def _worker(connection: Any, env_fn: Callable[[], Any], count: int, infos: bool) -> None:
    """A worker process: builds ``count`` matches and serves reset/step/close requests."""
    try:
        slots = [_Slot(env_fn(), infos) for _ in range(count)]
        first = slots[0].env
        agent = first.possible_agents[0]
        connection.send(("ok", (list(first.possible_agents), first.observation_space(agent),
                                first.action_space(agent))))
    except BaseException as error:  # noqa: BLE001 - reported to the parent, which raises it
        _send_error(connection, error)
        connection.close()
        return
    while True:
        try:
            command, payload = connection.recv()
        except EOFError:  # the parent went away
            break
        try:
            if command == "step":
                reply = _gather([slot.step(payload[k]) for k, slot in enumerate(slots)])  # few arrays to pickle
            elif command == "reset":
                reply = [slot.reset(seed) for slot, seed in zip(slots, payload)]
            elif command == "close":
                for slot in slots:
                    slot.env.close()
                connection.send(("ok", None))
                break
            else:
                raise ValueError(f"unknown request {command!r}")
            connection.send(("ok", reply))
        except BaseException as error:  # noqa: BLE001
            _send_error(connection, error)
    connection.close()


def _send_error(connection: Any, error: BaseException) -> None:
    """Reports ``error`` and its traceback to the parent (as a RuntimeError if it does not pickle)."""
    trace = traceback.format_exc()
    try:
        connection.send(("error", (error, trace)))
    except Exception:  # noqa: BLE001 - an exception object that cannot be pickled
        connection.send(("error", (RuntimeError(f"{type(error).__name__}: {error}"), trace)))


class SubprocVectorEnv(_VectorBase):
    """The matches of a vector environment spread over worker processes, stepped at once."""

    def __init__(self, num_envs: int, env_fn: Callable[[], Any], processes: int = 2,
                 context: str = "spawn", infos: bool = True) -> None:
        self.num_envs = _check_num_envs(num_envs)
        if not 1 <= processes <= self.num_envs:
            raise ValueError(f"processes must be between 1 and num_envs={self.num_envs}, got {processes}")
        counts = [self.num_envs // processes + (w < self.num_envs % processes) for w in range(processes)]
        self._bounds = np.cumsum([0, *counts])
        ctx = mp.get_context(context)
        self._connections, self._processes = [], []
        self.closed = False
        for count in counts:
            parent, child = ctx.Pipe()
            process = ctx.Process(target=_worker, args=(child, env_fn, count, infos), daemon=True)
            process.start()
            child.close()
            self._connections.append(parent)
            self._processes.append(process)
        try:
            spec = self._receive_all()[0]
        except BaseException:
            self.close()
            raise
        self.possible_agents, self.observation_space, self.action_space = spec

    def _receive_all(self) -> list[Any]:
        replies = [connection.recv() for connection in self._connections]
        for worker, (status, payload) in enumerate(replies):
            if status == "error":
                error, trace = payload
                raise error from RuntimeError(f"in vector env worker {worker}:\n{trace}")
        return [payload for _, payload in replies]

    def _send_all(self, command: str, payloads: list[Any]) -> None:
        if self.closed:
            raise RuntimeError("the vector environment is closed")
        for connection, payload in zip(self._connections, payloads):
            connection.send((command, payload))

    def _blocks(self, items: Sequence[Any]) -> list[Any]:
        return [items[a:b] for a, b in zip(self._bounds[:-1], self._bounds[1:])]

    def reset(self, seed: int | Sequence[int] | None = None) -> tuple[np.ndarray, list[dict]]:
        """Resets every match; observations (E, N, D) and the infos (see the module docstring)."""
        self._send_all("reset", self._blocks(_seeds(seed, self.num_envs)))
        out = [item for block in self._receive_all() for item in block]
        return np.stack([o for o, _ in out]), [i for _, i in out]

    def step(self, actions: Any) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, list[dict]]:
        """One cycle of every match (the workers step theirs at the same time)."""
        array = self._check_actions(actions)
        self._send_all("step", self._blocks(array))
        blocks = self._receive_all()
        return (*(np.concatenate([block[k] for block in blocks]) for k in range(4)),
                [info for block in blocks for info in block[4]])

    def close(self) -> None:
        """Ends the worker processes (safe to call twice)."""
        if self.closed:
            return
        self.closed = True
        for connection in self._connections:
            try:
                connection.send(("close", None))
            except (BrokenPipeError, OSError):
                pass
        for connection, process in zip(self._connections, self._processes):
            try:
                if connection.poll(5.0):
                    connection.recv()
            except (EOFError, OSError):
                pass
            process.join(timeout=5.0)
            if process.is_alive():
                process.terminate()
                process.join(timeout=1.0)
            connection.close()

    def __del__(self) -> None:
        if getattr(self, "closed", True) is False:
            self.close()
