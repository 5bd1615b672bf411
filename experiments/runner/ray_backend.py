"""The cluster backend: the same matches as Ray tasks (``--backend ray --address auto|HOST:PORT``).

Needs the optional ``ray`` extra (``pip install -e ".[ray]"``). With no address a local Ray
instance is started with ``--workers`` CPUs. At most one task per CPU of the cluster is in
flight, so a task's submission time is close to its start and an overdue task (past
``--match-timeout`` plus a grace period) can be cancelled and recorded as failed.
"""

from __future__ import annotations

import time
from collections import deque
from collections.abc import Iterable, Iterator

from experiments.results.record import MatchRecord
from experiments.runner.spec import MatchSpec
from experiments.runner.worker import failed_record, play_spec

RAY_GRACE = 30.0
"""Seconds a Ray task may overrun ``--match-timeout`` (worker start-up included) before it is cancelled."""


class RayUnavailable(Exception):
    """Ray is not installed or the cluster cannot be reached."""


class RayPool:
    """Plays specs as Ray tasks on the cluster at ``address`` (None: a new local instance)."""

    def __init__(self, workers: int | None, config_hash: str, version: str, timeout: float | None,
                 address: str | None = None) -> None:
        try:
            import ray
        except ImportError:
            raise RayUnavailable("the Ray backend needs Ray: pip install 'soccer-sim[ray]' "
                                 "(or pip install ray)") from None
        self._ray = ray
        self._args = (config_hash, version, timeout)
        self._timeout = timeout
        self._started_here = not ray.is_initialized()
        if self._started_here:
            options = dict(include_dashboard=False, log_to_driver=False, configure_logging=False)
            try:
                if address:
                    ray.init(address=address, **options)
                else:
                    ray.init(num_cpus=workers, **options)
            except Exception as exc:  # noqa: BLE001 - Ray raises many kinds for an unreachable cluster
                raise RayUnavailable(f"cannot start or reach Ray{f' at {address}' if address else ''}: "
                                     f"{type(exc).__name__}: {exc}") from None
        cpus = int(ray.cluster_resources().get("CPU", 1))
        self.size = min(workers, cpus) if (workers and not address) else cpus
        self._remote = ray.remote(num_cpus=1, max_retries=0)(play_spec)

    def warm_up(self, specs: Iterable[MatchSpec]) -> None:
        """Compile the kernels the teams of ``specs`` need into this machine's numba cache before
        any task starts (the workers of a local Ray instance load them from there; nodes of a
        remote cluster compile on their first match, within ``RAY_GRACE``)."""
        from experiments.warmup import warm_kernels

        warm_kernels(sorted({name for spec in specs for name in (spec.home, spec.away)}), processes=self.size)

    def run(self, specs: Iterable[MatchSpec]) -> Iterator[MatchRecord]:
        ray = self._ray
        pending = specs if hasattr(specs, "popleft") else deque(specs)  # a ClaimQueue: claimed lazily
        in_flight: dict[object, tuple[MatchSpec, float]] = {}
        config_hash, version, timeout = self._args
        try:
            while pending or in_flight:
                while pending and len(in_flight) < self.size:
                    spec = pending.popleft()
                    in_flight[self._remote.remote(spec, *self._args)] = (spec, time.monotonic())
                done, _ = ray.wait(list(in_flight), num_returns=1, timeout=1.0)
                for ref in done:
                    spec, started = in_flight.pop(ref)
                    try:
                        yield ray.get(ref)
                    except Exception as exc:  # noqa: BLE001 - a lost worker or node
                        yield failed_record(spec, config_hash, version, time.monotonic() - started,
                                            f"{type(exc).__name__}: {exc}")
                if timeout is not None:
                    now = time.monotonic()
                    for ref, (spec, started) in list(in_flight.items()):
                        if now > started + timeout + RAY_GRACE:
                            ray.cancel(ref, force=True)
                            del in_flight[ref]
                            yield failed_record(spec, config_hash, version, time.monotonic() - started,
                                                f"MatchTimeout: match exceeded its time budget of {timeout:g} s "
                                                "and its Ray task was cancelled")
        finally:
            for ref in in_flight:
                ray.cancel(ref, force=True)

    def close(self) -> None:
        if self._started_here:
            self._ray.shutdown()

