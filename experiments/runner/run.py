"""Running a list of match specifications into a results file.

:func:`run_matches` plays what the file does not hold yet (on a local process pool or on Ray),
stores every match as it finishes and returns the stored records of all the specs, sorted by
key: so the same specs give the same records with 1 or N workers, in one go or resumed.
"""

from __future__ import annotations

import os
import time
from collections.abc import Sequence
from dataclasses import dataclass, field

from experiments.results.record import MatchRecord
from experiments.results.store import ResultStore
from experiments.runner.progress import RunProgress
from experiments.runner.spec import MatchSpec, code_version, config_description, config_for, config_hash

DEFAULT_MATCH_TIMEOUT = 600.0
"""Seconds one match may take before it is stopped and forfeited (a full match between two
built-in teams takes about a second or two)."""

BACKENDS = ("local", "ray")


@dataclass
class RunSummary:
    """What a run did, and every stored record of its specs."""

    path: str
    total: int
    """Distinct matches of the run."""
    already_stored: int
    played: int
    errors: int
    """Failed matches among all ``total`` (stored earlier or now)."""
    seconds: float
    workers: int
    records: list[MatchRecord] = field(default_factory=list)

    def line(self) -> str:
        rate = self.played / self.seconds * 3600 if self.seconds > 0 and self.played else 0.0
        resumed = f" ({self.already_stored} already stored)" if self.already_stored else ""
        return (f"{self.total} matches in {self.path}{resumed}: played {self.played} in {self.seconds:.1f} s "
                f"on {self.workers} worker(s) ({rate:,.0f} matches/hour), {self.errors} failed")


def run_matches(specs: Sequence[MatchSpec], path: str | os.PathLike, kind: str, params: dict[str, object], *,
                cycles: int | None = None, workers: int | None = None, backend: str = "local",
                address: str | None = None, match_timeout: float | None = DEFAULT_MATCH_TIMEOUT,
                retry_errors: bool = False, progress: bool = True) -> RunSummary:
    """Play every spec (all with ``cycles``) that ``path`` does not hold, store each as it
    finishes, and return the summary with the records of all ``specs``.

    Raises :class:`~experiments.results.store.ResultsError` for an unusable file and
    :class:`~experiments.runner.ray_backend.RayUnavailable` when Ray cannot be used;
    KeyboardInterrupt leaves every finished match stored."""
    if any(spec.cycles != cycles for spec in specs):
        raise ValueError("every spec of a run must use the run's cycles")
    if backend not in BACKENDS:
        raise ValueError(f"unknown backend {backend!r}; choose one of {', '.join(BACKENDS)}")
    specs = list(dict.fromkeys(specs))
    config = config_for(cycles)
    digest, version = config_hash(config), code_version()
    start = time.monotonic()
    with ResultStore.create(path, kind, digest, config_description(config), params) as store:
        keys = [spec.key for spec in specs]
        # A failure no team is blamed for (a worker that died, a lost Ray node) is played again;
        # a forfeit is a result (the same team would fail the same way) unless retry_errors.
        store.forget_errors(keys, unattributed_only=not retry_errors)
        stored = store.keys()
        todo = [spec for spec in specs if spec.key not in stored]
        workers = workers or os.cpu_count() or 1
        used = 0
        if todo:
            pool = _pool(backend, workers, digest, version, match_timeout, address)
            used = pool.size
            try:
                with RunProgress(len(todo), kind, enabled=progress) as bar:
                    for record in pool.run(todo):
                        store.add(record)
                        bar.advance(record.error is not None)
            finally:
                pool.close()
        records = store.records(keys)
    return RunSummary(str(path), len(specs), len(specs) - len(todo), len(todo),
                      sum(r.error is not None for r in records), time.monotonic() - start, used, records)


def _pool(backend: str, workers: int, digest: str, version: str, timeout: float | None, address: str | None):
    if backend == "ray":
        from experiments.runner.ray_backend import RayPool

        return RayPool(workers, digest, version, timeout, address)
    from experiments.runner.local import LocalPool

    return LocalPool(workers, digest, version, timeout)
