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
import os
import signal
import sys
import threading
import time
from collections import deque
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from multiprocessing.connection import Connection, wait
from typing import Any

from experiments.errors import ExperimentError
from experiments.results.record import FORFEIT_NONE, MatchRecord
from experiments.runner.spec import MatchSpec
from experiments.runner.worker import failed_record, play_spec
from experiments.warmup import Kernel, load_kernels, observation_of, warm_kernels

KILL_GRACE = 10.0
"""Seconds a worker may overrun ``--match-timeout`` before it is killed (its own timer should
have stopped the match first)."""

SINGLE_MATCH_KILL_GRACE = 2.0
"""The same for the one match of :func:`play_in_worker` (``soccer-sim play``), where a person
waits: the worker's own timer answers within a fraction of a second when it can strike at all."""

QUICK_START = "fork" if sys.platform.startswith("linux") else "spawn"
"""How :func:`play_in_worker` starts its worker: on Linux by forking this process, which already
holds the simulator (some 0.05 s), elsewhere as a fresh interpreter (spawn: about 1.8 s more,
to import the simulator and load its kernels again)."""

READY = "ready"
"""What a worker sends once it has started and loaded the kernels: the parent's clock for its
first match starts then, so start-up is never charged to a match's time budget."""


def _worker_main(connection: Connection, config_hash: str, version: str, timeout: float | None,
                 kernels: tuple[Kernel, ...] = (), slot: Any = None, figures: Callable | None = None,
                 report: Callable | None = None) -> None:
    """A worker: load ``kernels``, say READY, then play the specs the parent sends until it sends
    None or goes away, marking in ``slot`` (shared with the parent) the side whose code runs.
    What team code prints goes to stderr (stdout belongs to the parent's report), and a worker
    whose parent has died ends at once, without a word (nobody is left to read its record)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    _send_prints_to_stderr()
    _exit_with_parent()
    load_kernels(kernels)
    try:
        connection.send(READY)
        while True:
            try:
                spec = connection.recv()
            except (EOFError, OSError):
                return
            if spec is None:
                return
            connection.send(play_spec(spec, config_hash, version, timeout, deciding=slot, figures=figures,
                                      report=report))
    except OSError:  # the parent went away (a broken pipe): nobody is left to tell
        return


def _send_prints_to_stderr() -> None:
    """Point this process's standard output at its standard error, for Python's ``print`` and
    for anything written to file descriptor 1 (a team's compiled code, a child process), so a
    team's prints never mix with the parent's report on stdout (``play --json``)."""
    try:
        sys.stdout.flush()
    except (OSError, ValueError):
        pass
    try:
        os.dup2(2, 1)
    except OSError:  # no standard error to point at: leave stdout as it is
        return
    sys.stdout = sys.stderr


def _exit_with_parent() -> None:
    """End this worker (status 0, nothing printed) as soon as its parent process dies, even in
    the middle of a match: a thread waits on the parent's sentinel. An orphan would otherwise
    play its match to the end and fail to send the record to a closed pipe."""
    parent = multiprocessing.parent_process()
    if parent is None:
        return

    def watch() -> None:
        parent.join()
        os._exit(0)

    threading.Thread(target=watch, name="soccer-sim-parent-watch", daemon=True).start()


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
                 figures: Callable | None = None, *, report: Callable | None = None,
                 start_method: str = "spawn", kill_grace: float = KILL_GRACE) -> None:
        """``report``: see :func:`~experiments.runner.worker.play_spec`; ``start_method``: how
        workers start (multiprocessing's name; spawn by default, so nothing of this process's
        state reaches a match); ``kill_grace``: seconds past ``timeout`` before a worker that
        does not answer is killed."""
        self.size = workers
        self.most_at_once = 0
        """The most worker processes this pool has run at once: ``size`` at most, fewer when
        there were fewer matches to play (the run line reports it)."""
        self._figures = figures
        self._report = report
        self._args = (config_hash, version, timeout)
        self._timeout = timeout
        self._kill_grace = kill_grace
        self._context = multiprocessing.get_context(start_method)
        self._workers: list[_Worker] = []
        self._kernels: tuple[Kernel, ...] = ()

    def warm_up(self, specs: Iterable[MatchSpec], processes: int | None = None) -> None:
        """Compile the kernels the teams of ``specs`` need into the on-disk cache (on
        ``processes`` processes, default this pool's number, only if the cache is cold);
        workers started later load them."""
        specs = list(specs)
        teams = sorted({name for spec in specs for name in spec.team_names})
        self._kernels = warm_kernels(teams, processes=processes or self.size,
                                     observation=observation_of(specs)).kernels

    def _start_worker(self) -> _Worker:
        parent_end, child_end = self._context.Pipe()
        slot = self._context.RawArray("i", [FORFEIT_NONE, FORFEIT_NONE])
        process = self._context.Process(target=_worker_main,
                                        args=(child_end, *self._args, self._kernels, slot, self._figures, self._report),
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
                                           f"WorkerDied: the worker process {process_end(worker.process.exitcode)} "
                                           "while playing this match")
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
        return max(0.05, min(w.started + self._timeout + self._kill_grace - now for w in timed))

    def _overdue(self, worker: _Worker) -> bool:
        return (self._timeout is not None and worker.ready
                and time.monotonic() > worker.started + self._timeout + self._kill_grace)

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


def process_end(exitcode: int | None) -> str:
    """How a process ended, from its ``exitcode`` (multiprocessing's: negative for a signal):
    ``ended with exit code 3`` or ``was killed by signal SIGKILL``."""
    if exitcode is not None and exitcode < 0:
        try:
            name = signal.Signals(-exitcode).name
        except ValueError:
            name = str(-exitcode)
        return f"was killed by signal {name}"
    return f"ended with exit code {exitcode}"


class MatchFailed(ExperimentError):
    """The match of :func:`play_in_worker` did not finish: ``error`` is its record's
    ``Kind: what happened`` (naming the team whose code was running, if any), ``forfeit`` the
    side at fault (FORFEIT_NONE: nobody)."""

    def __init__(self, error: str, forfeit: int = FORFEIT_NONE) -> None:
        super().__init__(error)
        self.error, self.forfeit = error, forfeit

    def __reduce__(self):
        return type(self), (self.error, self.forfeit)


def play_in_worker(spec: MatchSpec, timeout: float | None, report: Callable | None = None) -> MatchRecord:
    """Play one spec in a worker process of its own, as a tournament plays each of its
    matches, and return its record; MatchFailed when the match did not finish. Whatever the
    teams' code does (hangs deaf to the timer, raises anything, ends or kills its process),
    this process stays in control and the error says what happened and whose code was running.
    Kernels missing from the cache are compiled first on every core, off the match's clock;
    ``report`` as for :func:`play_spec`."""
    from experiments.runner.spec import code_version, config_hash

    pool = LocalPool(1, config_hash(spec.config(), spec.scenario), code_version(), timeout, report=report,
                     start_method=QUICK_START, kill_grace=SINGLE_MATCH_KILL_GRACE)
    pool.warm_up([spec], processes=os.cpu_count() or 1)
    (record,) = pool.run([spec])  # run stops its worker before it returns
    if record.error is not None:
        raise MatchFailed(record.error, record.forfeit)
    return record
