"""The default backend: a pool of worker processes on this machine, one match per task.

Unlike ``concurrent.futures``, the pool watches every worker itself: a worker that dies (a
crash, ``kill -9``) or overruns a match's time budget is replaced and its match recorded as
failed, and the run goes on. Each worker has a slot of shared memory where it marks the side
whose code it is running (see :class:`experiments.runner.worker._Watched`): a worker that dies
or hangs inside a team's code forfeits the match for that team; otherwise nobody is blamed.
Workers are reused from match to match (the simulator's compiled kernels load once per
worker). :meth:`LocalPool.warm_up` compiles the kernels into numba's on-disk cache before the
first worker starts, and each worker loads them before its first match, so neither compile
nor load time is charged to a match's time budget.
"""

from __future__ import annotations

import multiprocessing
import signal
import time
from collections import deque
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from multiprocessing.connection import Connection, wait
from typing import Any

from experiments.results.record import FORFEIT_NONE, MatchRecord
from experiments.runner.spec import MatchSpec
from experiments.runner.worker import failed_record, play_spec
from experiments.warmup import Kernel, load_kernels, observation_of, warm_kernels

KILL_GRACE = 10.0
"""Seconds a worker may overrun ``--match-timeout`` before it is killed (its own timer should
have stopped the match first)."""

READY = "ready"
"""What a worker sends once it has started and loaded the kernels: the parent's clock for its
first match starts then, so start-up is never charged to a match's time budget."""


def _worker_main(connection: Connection, config_hash: str, version: str, timeout: float | None,
                 kernels: tuple[Kernel, ...] = (), slot: Any = None, figures: Callable | None = None) -> None:
    """A worker: load ``kernels``, say READY, then play the specs the parent sends until it sends
    None or goes away, marking in ``slot`` (shared with the parent) the side whose code runs."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    load_kernels(kernels)
    connection.send(READY)
    while True:
        try:
            spec = connection.recv()
        except (EOFError, OSError):
            return
        if spec is None:
            return
        connection.send(play_spec(spec, config_hash, version, timeout, deciding=slot, figures=figures))


@dataclass
class _Worker:
    process: multiprocessing.Process
    connection: Connection
    spec: MatchSpec | None = None
    started: float = 0.0
    """When the parent's clock for ``spec`` started (once the worker is ready)."""
    ready: bool = False
    """Whether the worker has said READY (its first spec may wait in the pipe until then)."""
    slot: Any = None
    """Shared [side running team code, side whose act returned last] of the worker, or None."""

    def culprit(self) -> int:
        """The side whose code the worker is running now (FORFEIT_NONE if none, or no slot)."""
        return FORFEIT_NONE if self.slot is None else int(self.slot[0])


class LocalPool:
    """``workers`` processes (spawned, so nothing of the parent's state leaks into a match)."""

    def __init__(self, workers: int, config_hash: str, version: str, timeout: float | None,
                 figures: Callable | None = None) -> None:
        self.size = workers
        self.most_at_once = 0
        """The most worker processes this pool has run at once: ``size`` at most, fewer when
        there were fewer matches to play (the run line reports it)."""
        self._figures = figures
        self._args = (config_hash, version, timeout)
        self._timeout = timeout
        self._context = multiprocessing.get_context("spawn")
        self._workers: list[_Worker] = []
        self._kernels: tuple[Kernel, ...] = ()

    def warm_up(self, specs: Iterable[MatchSpec]) -> None:
        """Compile the kernels the teams of ``specs`` need into the on-disk cache (on this pool's
        number of processes, only if the cache is cold); workers started later load them."""
        specs = list(specs)
        teams = sorted({name for spec in specs for name in spec.team_names})
        self._kernels = warm_kernels(teams, processes=self.size, observation=observation_of(specs)).kernels

    def _start_worker(self) -> _Worker:
        parent_end, child_end = self._context.Pipe()
        slot = self._context.RawArray("i", [FORFEIT_NONE, FORFEIT_NONE])
        process = self._context.Process(target=_worker_main,
                                        args=(child_end, *self._args, self._kernels, slot, self._figures),
                                        daemon=True, name="soccer-sim-worker")
        process.start()
        child_end.close()
        return _Worker(process, parent_end, slot=slot)

    def run(self, specs: Iterable[MatchSpec]) -> Iterator[MatchRecord]:
        """Play every spec; yield each record as its match finishes (in any order)."""
        pending = specs if hasattr(specs, "popleft") else deque(specs)  # a ClaimQueue: claimed lazily
        config_hash, version, _ = self._args
        try:
            self._workers = [self._start_worker() for _ in range(min(self.size, len(pending)))]
            self.most_at_once = max(self.most_at_once, len(self._workers))
            while pending or any(w.spec is not None for w in self._workers):
                for worker in self._workers:
                    if worker.spec is None and pending:
                        worker.spec, worker.started = pending.popleft(), time.monotonic()
                        worker.connection.send(worker.spec)
                busy = [w for w in self._workers if w.spec is not None]
                ready = set(wait([w.connection for w in busy] + [w.process.sentinel for w in busy],
                                 timeout=self._wait_time(busy)))
                for i, worker in enumerate(self._workers):
                    if worker.spec is None:
                        continue
                    if worker.connection in ready:
                        try:
                            record = worker.connection.recv()
                        except (EOFError, OSError):
                            record = None
                        if record == READY:
                            worker.ready, worker.started = True, time.monotonic()
                            continue
                        if record is not None:
                            worker.spec = None
                            yield record
                            continue
                    if worker.process.sentinel in ready or not worker.process.is_alive():
                        worker.process.join(1.0)
                        yield self._failed(worker, config_hash, version,
                                           f"WorkerDied: the worker process ended with exit code "
                                           f"{worker.process.exitcode} while playing this match")
                        self._workers[i] = self._replace(worker)
                    elif self._overdue(worker):
                        yield self._failed(worker, config_hash, version,
                                           f"MatchTimeout: match exceeded its time budget of {self._timeout:g} s "
                                           "and its worker was killed")
                        self._workers[i] = self._replace(worker)
        finally:
            self.close()

    def _wait_time(self, busy: list[_Worker]) -> float | None:
        timed = [w for w in busy if w.ready]
        if self._timeout is None or not timed:
            return 1.0
        now = time.monotonic()
        return max(0.05, min(w.started + self._timeout + KILL_GRACE - now for w in timed))

    def _overdue(self, worker: _Worker) -> bool:
        return (self._timeout is not None and worker.ready
                and time.monotonic() > worker.started + self._timeout + KILL_GRACE)

    @staticmethod
    def _failed(worker: _Worker, config_hash: str, version: str, message: str) -> MatchRecord:
        """The record of ``worker``'s match, given up on: forfeited by the team whose code the
        worker was running (read before the worker is replaced), else nobody's fault."""
        side = worker.culprit()
        return failed_record(worker.spec, config_hash, version, time.monotonic() - worker.started, message,
                             forfeit=side)

    def _replace(self, worker: _Worker) -> _Worker:
        _stop(worker)
        return self._start_worker()

    def close(self) -> None:
        """Stop every worker (asking first, then killing)."""
        for worker in self._workers:
            try:
                worker.connection.send(None)
            except (OSError, ValueError):
                pass
        deadline = time.monotonic() + 2.0
        for worker in self._workers:
            worker.process.join(max(0.0, deadline - time.monotonic()) if worker.spec is None else 0.0)
            _stop(worker)
        self._workers = []


def _stop(worker: _Worker) -> None:
    if worker.process.is_alive():
        worker.process.kill()
        worker.process.join(5.0)
    worker.connection.close()
