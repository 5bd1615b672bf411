"""The cluster backend: the same matches as Ray tasks (``--backend ray [--address HOST:PORT]``).

Needs the optional ``ray`` extra (``pip install -e ".[ray]"``).

Which cluster: ``--address`` names one; without it the cluster Ray's own convention names
(the ``RAY_ADDRESS`` variable, as set by ``ray job submit``) is joined, and otherwise a private
local instance with ``--workers`` CPUs is started (never another cluster on this machine, and
never local resources passed to an existing cluster). One line on stderr says which.

Which code: with code shipping on (the default) the driver's own packages go with the job: as
Ray ``py_modules`` to a cluster, on ``PYTHONPATH`` to a private local instance (same files, same
numba cache). Every node then passes a pre-flight (:mod:`experiments.runner.preflight`,
one task pinned to the node) before any match: same code version, configuration hash and
libraries as the driver, kernels compiled. Failing nodes are left out, one stderr line each.

Scheduling: every match is pinned to an accepted node with a free CPU (node affinity), so the
driver knows where each runs. Nodes that join during the run are pre-flighted and used; a node
that leaves, or fails :data:`NODE_FAILURE_LIMIT` tasks in a row for reasons outside the match
(a dead worker, a missing module), is taken out and its matches go to the other nodes, each
at most :data:`MATCH_RETRIES` more times. A returned row whose code version is not the
driver's is never stored: its node is taken out and the match played elsewhere. An overdue
task (past ``--match-timeout`` plus :data:`RAY_GRACE`) is cancelled and recorded as failed.

Crash blame: each match task keeps its worker's deciding slot (the side whose team code is
running) in a small file on its node (:mod:`experiments.runner.slots`). When a task fails
because its worker died, one more task pinned to that node reads the slot: a worker that died
inside a team's code forfeits the match for that team, as on the local pool, and that failure
does not count against the node. If nobody is to blame (or the node is gone) the failure is
the node's, as above. An overdue task's slot is read the same way once it is cancelled (a team
hung deaf to the worker's timer forfeits).
"""

from __future__ import annotations

import sys
import time
from collections import Counter, deque
from collections.abc import Callable, Iterable, Iterator
from typing import TextIO

from experiments.results.record import FORFEIT_NONE, MatchRecord
from experiments.runner.preflight import PREFLIGHT_TIMEOUT, Expected, NodeCheck, check_node, failure_reason
from experiments.runner.ray_cluster import (ClusterNode, MatchTask, RayUnavailable, code_runtime_env, connect,
                                            import_ray, node_gone, play_on_node, worker_died)
from experiments.runner.slots import new_token, take_slot
from experiments.runner.spec import MatchSpec
from experiments.runner.worker import failed_record

__all__ = ["RayPool", "RayUnavailable", "code_runtime_env"]

RAY_GRACE = 30.0
"""Seconds a Ray task may overrun ``--match-timeout`` (worker start-up included) before it is cancelled."""

NODE_FAILURE_LIMIT = 3
"""Tasks in a row a node may fail for reasons outside the match before it is taken out."""

MATCH_RETRIES = 2
"""Times a match whose node failed or left is played again on another node within the run."""

NODE_POLL = 2.0
"""Seconds between looks at the cluster's membership (nodes joining or leaving)."""

NODE_WAIT = 60.0
"""Seconds a run with matches left but no usable node waits for one to join before giving up."""

BLAME_TIMEOUT = 30.0
"""Seconds the task that reads a dead worker's slot on its node may take; past that nobody is blamed."""

class RayPool:
    """Plays specs as Ray tasks on the cluster at ``address`` (see the module docstring)."""

    def __init__(self, workers: int | None, config_hash: str, version: str, timeout: float | None,
                 address: str | None = None, *, ship_code: bool = True, figures: Callable[[], object] | None = None,
                 stream: TextIO | None = None) -> None:
        ray = import_ray()
        self._ray = ray
        self._args = (config_hash, version, timeout)
        self._timeout = timeout
        self._stream = stream
        ship = ship_code
        self._figures = figures
        self._started_here = not ray.is_initialized()
        self._local, where = connect(ray, workers, address, ship)
        self._cap = workers if self._local else None
        nodes = self._alive()
        cpus = sum(self._slots(info) for info in nodes.values())
        self.size = max(cpus, 1)
        self.most_at_once = 0
        """The most matches this pool has had in flight at once (the run line reports it)."""
        shipped = ("driver's code shipped" if ship and self._started_here else
                   "code not shipped: every node must have the project installed")
        self._say(f"ray: {where}: {len(nodes)} node(s), {cpus} CPU(s) used; {shipped}")
        self._remote = ray.remote(num_cpus=1, max_retries=0)(play_on_node)
        self._check = ray.remote(num_cpus=1, max_retries=0)(check_node)
        self._take_slot = ray.remote(num_cpus=0, max_retries=0)(take_slot)
        self._blames: dict[object, tuple[MatchTask, str, float, bool]] = {}
        """Slot reads in flight: the failed task, why it failed, when (the read started then),
        whether it was cancelled as overdue (else its worker died)."""
        self._nodes: dict[str, ClusterNode] = {}
        self._checks: dict[object, tuple[ClusterNode, float]] = {}
        self._expected: Expected | None = None
        self._played: Counter[str] = Counter()
        self._last_poll = 0.0

    # ---- cluster membership -------------------------------------------------------------

    def _say(self, line: str) -> None:
        print(line, file=self._stream if self._stream is not None else sys.stderr, flush=True)

    def _alive(self) -> dict[str, dict]:
        """The cluster's live nodes that have CPUs, by node id."""
        return {info["NodeID"]: info for info in self._ray.nodes()
                if info.get("Alive") and self._slots(info) > 0}

    def _slots(self, info: dict) -> int:
        cpus = int(info.get("Resources", {}).get("CPU", 0))
        return min(cpus, self._cap) if self._cap else cpus

    def _poll(self) -> list[MatchRecord]:
        """Pre-flight new nodes, take out nodes that left; the records of matches given up."""
        self._last_poll = time.monotonic()
        alive = self._alive()
        given_up: list[MatchRecord] = []
        for node_id, info in alive.items():
            if node_id not in self._nodes:
                node = ClusterNode(node_id, info.get("NodeManagerAddress", "?"), self._slots(info))
                pin = self._pin(node_id)
                node.submit = self._remote.options(scheduling_strategy=pin).remote
                self._nodes[node_id] = node
                self._checks[self._check.options(scheduling_strategy=pin).remote(self._expected)] = (node, time.monotonic())
        for node in self._nodes.values():
            if node.state != "out" and node.id not in alive:
                given_up += self._take_out(node, "left the cluster")
        return given_up

    def _checked(self, ref, node: ClusterNode) -> None:
        """Accept or leave out ``node`` by its pre-flight's result."""
        try:
            check: NodeCheck = self._ray.get(ref)
            problem = check.problem
        except Exception as exc:  # noqa: BLE001 - the node could not even run the check
            problem = failure_reason(exc)
        if node.state == "out":
            return
        if problem is None:
            node.state = "ready"
        else:
            self._take_out(node, problem)

    def _take_out(self, node: ClusterNode, reason: str) -> list[MatchRecord]:
        """Leave ``node`` out of the run; its matches in flight go back to the queue (or are
        given up after :data:`MATCH_RETRIES`); returns the records of those given up."""
        node.state = "out"
        self._say(f"ray: {node.name} excluded: {reason}")
        given_up = []
        for ref, task in list(self._in_flight.items()):
            if task.node is node:
                self._ray.cancel(ref, force=True)
                del self._in_flight[ref]
                given_up += self._requeue(task, f"RayNodeLost: {node.name} {reason}")
        node.busy = 0
        return given_up

    def _requeue(self, task: MatchTask, message: str) -> list[MatchRecord]:
        if task.attempt < MATCH_RETRIES:
            self._pending.appendleft((task.spec, task.attempt + 1, task.failed_on | {task.node.id}))
            return []
        config_hash, version, _ = self._args
        return [failed_record(task.spec, config_hash, version, time.monotonic() - task.started,
                              f"{message} (played {task.attempt + 1} times)")]

    # ---- the run --------------------------------------------------------------------------

    def warm_up(self, specs: Iterable[MatchSpec]) -> None:
        """Pre-flight every node of the cluster (imports, code version, configuration hash,
        libraries, kernels) before any match; RayUnavailable when none passes. A private local
        instance first compiles the kernels here on every core (its workers share this cache)."""
        specs = list(specs)
        teams = tuple(sorted({name for spec in specs for name in spec.team_names}))
        config_hash, version, _ = self._args
        setting = (specs[0].cycles, specs[0].configuration, specs[0].scenario) if specs else (None, None, None)
        cycles, configuration, scenario = setting     # one per run (see run_setting)
        self._expected = Expected.of_driver(version, config_hash, cycles, teams, configuration, scenario)
        if self._local:
            from experiments.warmup import observation_of, warm_kernels

            warm_kernels(teams, processes=self.size, observation=observation_of(specs))
        self._in_flight: dict[object, MatchTask] = {}
        self._pending: deque[tuple[MatchSpec, int, frozenset[str]]] = deque()
        self._poll()
        deadline = time.monotonic() + PREFLIGHT_TIMEOUT
        while self._checks and time.monotonic() < deadline:
            done, _ = self._ray.wait(list(self._checks), num_returns=1, timeout=1.0)
            for ref in done:
                self._checked(ref, self._checks.pop(ref)[0])
        self._expire_checks(force=True)
        if not any(node.state == "ready" for node in self._nodes.values()):
            raise RayUnavailable(f"no node of the Ray cluster can play this run ({len(self._nodes)} checked, "
                                 "each excluded above); install the project on the nodes or let the run ship it with "
                                 "the job")

    def _expire_checks(self, force: bool = False) -> None:
        now = time.monotonic()
        for ref, (node, started) in list(self._checks.items()):
            if force or now > started + PREFLIGHT_TIMEOUT:
                self._ray.cancel(ref, force=True)
                del self._checks[ref]
                if node.state != "out":
                    self._take_out(node, f"its pre-flight took longer than {PREFLIGHT_TIMEOUT:g} s")

    def run(self, specs: Iterable[MatchSpec]) -> Iterator[MatchRecord]:
        specs = list(specs)
        if self._expected is None:
            self.warm_up(specs)
        ray = self._ray
        self._pending.extend((spec, 0, frozenset()) for spec in specs)
        _, version, timeout = self._args
        idle_since: float | None = None
        try:
            while self._pending or self._in_flight or self._blames:
                if time.monotonic() - self._last_poll > NODE_POLL:
                    yield from self._poll()
                self._expire_checks()
                self._submit()
                if self._pending and not self._in_flight and not self._checks and not self._blames:
                    idle_since = idle_since or time.monotonic()
                    if time.monotonic() - idle_since > NODE_WAIT:
                        yield from self._give_up()
                        continue
                else:
                    idle_since = None
                waiting = list(self._in_flight) + list(self._checks) + list(self._blames)
                if not waiting:
                    time.sleep(min(NODE_POLL, 1.0))
                    continue
                done, _ = ray.wait(waiting, num_returns=1, timeout=1.0)
                for ref in done:
                    if ref in self._checks:
                        self._checked(ref, self._checks.pop(ref)[0])
                    elif ref in self._in_flight:
                        yield from self._finished(ref, self._in_flight.pop(ref), version)
                    elif ref in self._blames:
                        yield from self._blamed(ref, *self._blames.pop(ref))
                yield from self._expire_blames()
                if timeout is not None:
                    now = time.monotonic()
                    for ref, task in list(self._in_flight.items()):
                        if now > task.started + timeout + RAY_GRACE:
                            ray.cancel(ref, force=True)
                            del self._in_flight[ref]
                            task.node.busy -= 1
                            self._ask_slot(task, f"MatchTimeout: match exceeded its time budget of {timeout:g} s "
                                                 "and its Ray task was cancelled", overdue=True)
        finally:
            for ref in list(self._in_flight) + list(self._checks) + list(self._blames):
                ray.cancel(ref, force=True)
            self._in_flight.clear()
            self._checks.clear()
            self._blames.clear()

    def _submit(self) -> None:
        """Start pending matches on ready nodes with a free CPU, one node after another; a
        match that failed on a node goes elsewhere when another node is ready."""
        ready = [node for node in self._nodes.values() if node.state == "ready"]
        while self._pending and ready:
            for node in list(ready):
                if not self._pending:
                    break
                if node.busy >= node.slots:
                    ready.remove(node)
                    continue
                spec, attempt, failed_on = self._pending[0]
                if node.id in failed_on and any(other.id not in failed_on for other in ready):
                    continue
                self._pending.popleft()
                node.busy += 1
                task = MatchTask(spec, node, time.monotonic(), attempt, failed_on, new_token())
                self._in_flight[node.submit(task.token, spec, *self._args, figures=self._figures)] = task
                self.most_at_once = max(self.most_at_once, len(self._in_flight))

    def _finished(self, ref, task: MatchTask, version: str) -> Iterator[MatchRecord]:
        node = task.node
        node.busy = max(node.busy - 1, 0)
        try:
            record: MatchRecord = self._ray.get(ref)
        except Exception as exc:  # noqa: BLE001 - a dead worker, a lost node, a module missing there
            reason = failure_reason(exc)
            if worker_died(exc) and not node_gone(exc):  # whose code was it running? ask its node
                self._ask_slot(task, reason)
                return
            yield from self._node_failed(task, reason, node_gone(exc))
            return
        if record.code_version != version:  # never store what other code played
            if node.state != "out":
                yield from self._take_out(node, f"runs different code (version {record.code_version} "
                                                f"!= driver's {version})")
            yield from self._requeue(task, f"RayNodeLost: {node.name} runs different code")
            return
        node.failures = 0
        self._played[node.name] += 1
        yield record

    @staticmethod
    def _pin(node_id: str):
        from ray.util.scheduling_strategies import NodeAffinitySchedulingStrategy

        return NodeAffinitySchedulingStrategy(node_id, soft=False)

    def _node_failed(self, task: MatchTask, reason: str, gone: bool = False) -> Iterator[MatchRecord]:
        """``task`` failed with nobody to blame: one more failure in a row of its node (taken
        out at :data:`NODE_FAILURE_LIMIT`, or at once if ``gone``), the match played again."""
        node = task.node
        node.failures += 1
        if node.state != "out" and gone:
            yield from self._take_out(node, "left the cluster")
        elif node.failures >= NODE_FAILURE_LIMIT and node.state != "out":
            yield from self._take_out(node, f"{node.failures} tasks failed in a row (last: {reason})")
        yield from self._requeue(task, f"RayTaskFailed on {node.name}: {reason}")

    def _ask_slot(self, task: MatchTask, reason: str, overdue: bool = False) -> None:
        """Read, on its node, the slot of ``task``, whose worker died (or, if ``overdue``, was
        cancelled): whose code was it running? The answer is handled by :meth:`_blamed`."""
        ref = self._take_slot.options(scheduling_strategy=self._pin(task.node.id)).remote(task.token)
        self._blames[ref] = (task, reason, time.monotonic(), overdue)

    def _blamed(self, ref, task: MatchTask, reason: str, ended: float, overdue: bool,
                answered: bool = True) -> Iterator[MatchRecord]:
        """The slot of ``task`` has been read (``ref``; not if ``answered`` is False): the match
        is forfeited by the side whose code the worker was running. With no side (or no
        answer), an overdue match fails unblamed and a dead worker is its node's failure."""
        side = FORFEIT_NONE
        if answered:
            try:
                side = int(self._ray.get(ref))
            except Exception:  # noqa: BLE001 - the node went away too: nobody can be blamed
                pass
        if side == FORFEIT_NONE and not overdue:
            yield from self._node_failed(task, reason)
            return
        config_hash, version, _ = self._args
        message = reason if overdue else (f"WorkerDied: the Ray worker process on {task.node.name} died while "
                                          f"playing this match ({reason})")
        yield failed_record(task.spec, config_hash, version, ended - task.started, message, forfeit=side)

    def _expire_blames(self) -> Iterator[MatchRecord]:
        """Slot reads unanswered after :data:`BLAME_TIMEOUT`: cancelled, nobody blamed."""
        now = time.monotonic()
        for ref, (task, reason, ended, overdue) in list(self._blames.items()):
            if now > ended + BLAME_TIMEOUT:
                self._ray.cancel(ref, force=True)
                del self._blames[ref]
                yield from self._blamed(ref, task, reason, ended, overdue, answered=False)

    def _give_up(self) -> Iterator[MatchRecord]:
        """No node can play and none joined within NODE_WAIT: the matches left fail (unblamed,
        so the next run plays them again)."""
        config_hash, version, _ = self._args
        self._say(f"ray: no usable node for {NODE_WAIT:g} s; {len(self._pending)} match(es) left unplayed")
        while self._pending:
            spec, _, _ = self._pending.popleft()
            yield failed_record(spec, config_hash, version, 0.0,
                                "RayNoNode: no node of the cluster could play this match (see the excluded nodes)")

    @property
    def played_per_node(self) -> dict[str, int]:
        """Matches each node returned a stored row for, by node name (id and IP)."""
        return dict(self._played)

    def close(self) -> None:
        if len(self._played) > 1:
            self._say("ray: matches per node: " + ", ".join(f"{name}: {n}" for name, n in sorted(self._played.items())))
        if self._started_here:
            self._ray.shutdown()
