"""Running a list of match specifications into a results file.

:func:`run_matches` plays what the file does not hold yet (on a local process pool or on Ray),
stores every match as it finishes and returns the stored records of all the specs, sorted by
key: so the same specs give the same records with 1 or N workers, in one go or resumed.
"""

from __future__ import annotations

import contextlib
import os
import sys
import time
import warnings
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from experiments.errors import ExperimentError, ParameterError
from experiments.results.leases import LEASE_SECONDS, SharedWork
from experiments.results.record import FORFEIT_NONE, MatchRecord
from experiments.results.store import ResultsError, ResultStore, StorageError
from experiments.runner.progress import RunProgress
from experiments.runner.spec import SIMULATOR, MatchSpec, code_version, config_description, config_for, config_hash

if TYPE_CHECKING:  # annotations only
    from soccer_sim import MatchConfig
    from soccer_sim.scenarios import Scenario

DEFAULT_MATCH_TIMEOUT = 600.0
"""Seconds one match may take before it is stopped and forfeited (a full match between two
built-in teams takes about a second or two)."""

BACKENDS = ("local", "ray")

FAILURE_SHARE = 0.2
"""A run stops when more than this share of its finished matches failed with no team at
fault (a worker or node lost outside team code) ..."""
FAILURE_MIN_MATCHES = 20
"""... once at least this many matches have finished (fewer say little about the cause)."""

MAX_SEED = 2**63 - 1
"""The largest seed a results file can store (SQLite integers are signed 64-bit)."""


def unblamed(record: MatchRecord) -> bool:
    """:func:`experiments.stats.unblamed` (imported when called: the statistics need numpy)."""
    from experiments.stats import unblamed as failed_with_no_team_at_fault

    return failed_with_no_team_at_fault(record)


class MixedCodeVersions(ResultsError):
    """A resume with ``same_code`` into a results file holding matches of another code version."""

    def __init__(self, path: str, others: str, version: str) -> None:
        super().__init__(f"{path} holds matches played by another code version ({others}), not by this code "
                         f"({version}); same_code refuses to mix them: use another results file, or allow it")
        self.path, self.others, self.version = path, others, version

    def __reduce__(self):
        return type(self), (self.path, self.others, self.version)


class MixedCodeWarning(ExperimentError, UserWarning):
    """A resume into a results file holding matches of another code version: its tables will
    mix code versions (``same_code`` refuses this instead)."""

    def __init__(self, path: str, others: str, version: str) -> None:
        super().__init__(f"{path} holds matches played by another code version ({others}); this run plays the "
                         f"rest with {version}, so its tables mix code versions (same_code refuses this)")
        self.path, self.others, self.version = path, others, version

    def __reduce__(self):
        return type(self), (self.path, self.others, self.version)


class RunStopped(ExperimentError):
    """The failure policy stopped the run; the message says why, what is stored and how to resume."""


@dataclass(frozen=True)
class FailurePolicy:
    """When a run gives up: more than ``max_share`` of at least ``min_matches`` finished
    matches failed with no team at fault. A team's own failures (forfeits) never stop a run:
    they are results."""

    max_share: float = FAILURE_SHARE
    min_matches: int = FAILURE_MIN_MATCHES

    def exceeded(self, finished: int, failed: int) -> bool:
        return finished >= self.min_matches and failed > self.max_share * finished


@dataclass
class _Tally:
    """What the matches finished in this run came to."""

    finished: int = 0
    completed: int = 0
    """Played to their end (a score)."""
    unblamed: int = 0
    """Failed with no team at fault."""
    last_error: str = ""

    def add(self, record: MatchRecord) -> None:
        self.finished += 1
        self.completed += record.played
        if unblamed(record):
            self.unblamed += 1
            self.last_error = record.error or ""


@dataclass
class RunSummary:
    """What a run did, and every stored record of its specs."""

    path: str
    total: int
    """Distinct matches of the run."""
    already_stored: int
    played: int
    """Matches run now (whatever their outcome)."""
    errors: int
    """Failed matches among all ``total`` (stored earlier or now)."""
    seconds: float
    workers: int
    records: list[MatchRecord] = field(default_factory=list)
    completed: int = 0
    """Matches run now and played to their end: the only ones the rate counts."""

    by_others: int = 0
    """Matches of the run played and stored meanwhile by another run on the same file."""
    unfinished: int = 0
    """Matches another run on the same file was still playing when this one stopped waiting."""

    @property
    def unplayed(self) -> int:
        """Matches of the run that failed with no team at fault: missing from the tables."""
        return sum(unblamed(r) for r in self.records)

    def line(self) -> str:
        rate = self.completed / self.seconds * 3600 if self.seconds > 0 and self.completed else 0.0
        resumed = f" ({self.already_stored} already stored)" if self.already_stored else ""
        unplayed = f" ({self.unplayed} with no team at fault)" if self.unplayed else ""
        shared = f", {self.by_others} played by another run" if self.by_others else ""
        return (f"{self.total} matches in {self.path}{resumed}: played {self.played} in {self.seconds:.1f} s "
                f"on {self.workers} worker(s) ({rate:,.0f} matches/hour){shared}, {self.errors} failed{unplayed}")

    def incomplete(self) -> str:
        """The message for a run whose tables lack matches another run is still playing."""
        return (f"tables incomplete: {self.unfinished} matches are being played by another driver; run the same "
                "command again when it finishes")


def run_matches(specs: Sequence[MatchSpec], path: str | os.PathLike, kind: str, params: dict[str, object], *,
                cycles: int | None = None, workers: int | None = None, backend: str = "local",
                address: str | None = None, match_timeout: float | None = DEFAULT_MATCH_TIMEOUT,
                retry_errors: bool = False, progress: bool = True, record_dir: str | os.PathLike | None = None,
                record_every: int = 1, rcg_dir: str | os.PathLike | None = None, policy: FailurePolicy = FailurePolicy(),
                figures: Callable[[], object] | None = None, ship_code: bool = True, same_code: bool = False,
                wait: float | None = None) -> RunSummary:
    """Play every spec (all with ``cycles``) that ``path`` does not hold, store each as it
    finishes, and return the summary with the records of all ``specs``.

    ``record_dir``: write a rerun replay of every ``record_every``-th spec (in the order given,
    the first included) played in this run into that directory, named after its teams and seed;
    ``rcg_dir``: likewise an rcssserver game log (``.rcg``) of the same specs.
    ``figures``: a picklable factory of a :class:`~experiments.runner.worker.MatchFigures`
    recorder whose figures of the whole match go into both teams' statistics.
    ``ship_code``: with the Ray backend, send the driver's packages with the job (``--ship-code``;
    off: every node must have the project installed).

    Failure policy (``policy``, the same for every backend): a failure no team is blamed for
    leaves the match out of the tables (a re-run plays it again); when more than
    FAILURE_SHARE of at least FAILURE_MIN_MATCHES matches finished in this run failed that
    way, the run stops with :class:`RunStopped`, every finished match stored.

    Several runs may share ``path`` (see :mod:`experiments.results.leases`): each claims a match
    before playing it, and at the end waits for the matches another run is still playing (up
    to ``wait`` seconds without progress; default: the match timeout plus a lease's life), so
    its records are complete unless ``RunSummary.unfinished`` says otherwise. A resume that
    would mix code versions is warned about (:class:`MixedCodeWarning`, shown on stderr by
    Python's warnings), or refused with ``same_code``.

    Raises ParameterError (a ValueError) for a parameter out of range (seeds a results file
    cannot store, ``record_every``, ``record_dir``, ``rcg_dir``),
    :class:`~experiments.results.store.ResultsError` for an unusable file,
    :class:`~experiments.results.store.StorageError` when storing fails part-way (disk full) and
    :class:`~experiments.runner.ray_backend.RayUnavailable` when Ray cannot be used; every
    finished match stays stored, after Ctrl-C (KeyboardInterrupt) too."""
    if any(spec.cycles != cycles for spec in specs):
        raise ValueError("every spec of a run must use the run's cycles")
    if backend not in BACKENDS:
        raise ValueError(f"unknown backend {backend!r}; choose one of {', '.join(BACKENDS)}")
    specs = list(dict.fromkeys(specs))
    config, scenario, engine = run_setting(specs, cycles)
    check_seeds(specs)
    if record_dir is not None or rcg_dir is not None:
        specs = with_replays(specs, None if record_dir is None else Path(record_dir), record_every,
                             None if rcg_dir is None else Path(rcg_dir))
    digest, version = config_hash(config, scenario, engine), code_version()
    start = time.monotonic()
    check_code_versions(path, kind, digest, version, specs, retry_errors, same_code)
    with ResultStore.create(path, kind, digest, config_description(config, scenario, engine), params) as store:
        keys = [spec.key for spec in specs]
        # A failure no team is blamed for (a worker that died, a lost Ray node) is played again;
        # a forfeit is a result (the same team would fail the same way) unless retry_errors.
        store.forget_errors(keys, unattributed_only=not retry_errors)
        stored = store.keys()
        todo = [spec for spec in specs if spec.key not in stored]
        workers = workers or os.cpu_count() or 1
        used = played = 0
        tally = _Tally()
        if wait is None:
            wait = (match_timeout or DEFAULT_MATCH_TIMEOUT) + LEASE_SECONDS
        with SharedWork(store, todo, wait, log=_note) as shared, contextlib.ExitStack() as running:
            pool = None
            for claimed in shared.queues():        # matches claimed one by one, shared with other runs
                if pool is None:
                    pool = _pool(backend, workers, digest, version, match_timeout, address, figures, ship_code)
                    running.callback(pool.close)
                    pool.warm_up(todo)  # compile the kernels once, before any worker, match clock or ETA starts
                    bar = running.enter_context(RunProgress(len(todo), kind, enabled=progress))
                    shared.on_stored = lambda _spec: bar.advance()
                for record in pool.run(claimed):
                    _store(store, record, keys)  # (releases its lease)
                    tally.add(record)
                    bar.advance(record.error is not None, unblamed(record))
                    played += 1
                    if policy.exceeded(tally.finished, tally.unblamed):
                        raise RunStopped(_stop_message(tally, policy, len(todo), store.path))
            used = pool.most_at_once if pool is not None else 0
        records = store.records(keys)
    return RunSummary(str(path), len(specs), len(specs) - len(todo), played,
                      sum(r.error is not None for r in records), time.monotonic() - start, used, records,
                      tally.completed, shared.by_others, shared.unfinished)


def _stop_message(tally: _Tally, policy: FailurePolicy, todo: int, path: object) -> str:
    return (f"run stopped: {tally.unblamed} of the {tally.finished} matches finished so far (of {todo} to play) "
            f"failed with no team at fault, more than {policy.max_share:.0%} (the last: {tally.last_error}); "
            f"every finished match is stored in {path}; fix the cause and run the same command again to resume "
            "(the failed matches are played again)")


def check_code_versions(path: str | os.PathLike, kind: str, digest: str, version: str,
                        specs: Sequence[MatchSpec], retry_errors: bool, same_code: bool) -> None:
    """Before a resume into ``path`` plays anything: a :class:`MixedCodeWarning` when the file
    holds matches of another code version (its tables would mix versions), or
    :class:`MixedCodeVersions` (a ResultsError) with ``same_code``. Read-only, so a refused file is left as it was; a file the run cannot
    use is left for :meth:`ResultStore.create` to refuse."""
    path = Path(path)
    if not path.is_file() or path.stat().st_size == 0:
        return
    try:
        with ResultStore.open(path) as stored:
            if stored.kind != kind or stored.config_hash != digest or not stored.code_versions() - {version}:
                return
            kept = {r.key for r in stored.records()
                    if r.error is None or (not retry_errors and r.forfeit != FORFEIT_NONE)}
            others = ", ".join(sorted(stored.code_versions() - {version}))
    except ResultsError:
        return
    if all(spec.key in kept for spec in specs):
        return                                         # nothing to play: nothing is mixed
    if same_code:
        raise MixedCodeVersions(str(path), others, version)
    warnings.warn(MixedCodeWarning(str(path), others, version), stacklevel=3)


def _note(message: str) -> None:
    print(message, file=sys.stderr, flush=True)


def run_setting(specs: Sequence[MatchSpec], cycles: int | None) -> tuple[MatchConfig, Scenario | None, str]:
    """The one (configuration, scenario, engine) every spec of a run plays (that of ``cycles``
    in the simulator for no specs): a results file holds the matches of one setting, keyed by
    teams and seed, so specs of different settings, or different specs with the same teams and
    seed, are a ParameterError."""
    settings = {(spec.config(), spec.scenario, spec.engine) for spec in specs}
    if len(settings) > 1:
        raise ParameterError("specs", "must all play one configuration, scenario and engine: a results file holds "
                                      "the matches of one")
    if len({spec.key for spec in specs}) < len(specs):
        raise ParameterError("specs", "must differ in teams or seed: a results file keys its matches by them")
    return settings.pop() if settings else (config_for(cycles), None, SIMULATOR)


def check_seeds(specs: Sequence[MatchSpec]) -> None:
    """ParameterError (a ValueError) for ``seed`` unless every seed of ``specs`` fits a results
    file (0 to MAX_SEED), saying which first seed would: the specs' seeds run from the first
    one upwards."""
    if not specs:
        return
    low, high = min(spec.seed for spec in specs), max(spec.seed for spec in specs)
    if low < 0 or high > MAX_SEED:
        raise ParameterError("seed", f"must be between 0 and {MAX_SEED - (high - low)} for this run (its seeds go "
                             f"from the first seed to the first + {high - low}, and a results file stores seeds up "
                             f"to {MAX_SEED})")


def _store(store: ResultStore, record: MatchRecord, keys: list[tuple[str, str, int]]) -> None:
    """Add ``record`` to ``store``; a failed write (disk full, I/O error) becomes a StorageError
    saying how many of the run's matches are kept and how to continue."""
    import sqlite3

    try:
        store.add(record)
    except (sqlite3.Error, OSError) as exc:
        try:
            kept = f"{len(store.keys() & set(keys))} of the run's {len(keys)} matches are stored in {store.path}"
        except sqlite3.Error:
            kept = f"every match stored before is kept in {store.path}"
        raise StorageError(f"{store.path}: cannot store a match ({exc}); {kept}; make room (or fix the "
                           "file's permissions) and re-run the same command to resume") from None


def _pool(backend: str, workers: int, digest: str, version: str, timeout: float | None, address: str | None,
          figures: Callable[[], object] | None = None, ship_code: bool = True):
    if backend == "ray":
        from experiments.runner.ray_backend import RayPool

        return RayPool(workers, digest, version, timeout, address, ship_code=ship_code, figures=figures)
    from experiments.runner.local import LocalPool

    return LocalPool(workers, digest, version, timeout, figures)


def replay_name(spec: MatchSpec) -> str:
    """The replay file name of a spec: its teams and seed, with path-unsafe characters replaced."""
    import re

    safe = re.sub(r"[^A-Za-z0-9+._-]+", "_", f"{spec.home}-v-{spec.away}-seed{spec.seed}")
    return f"{safe}.rrd"


def with_replays(specs: list[MatchSpec], directory: Path | None, every: int,
                 rcg_directory: Path | None = None) -> list[MatchSpec]:
    """``specs`` with every ``every``-th one (0, every, 2 every, ...) set to record a replay in
    ``directory`` and a game log in ``rcg_directory`` (each created; None: not recorded);
    ParameterError (a ValueError) for ``every`` < 1 or a directory that cannot be made."""
    from dataclasses import replace

    if every < 1:
        raise ParameterError("record_every", f"must be at least 1, got {every}")
    for parameter, where in (("record_dir", directory), ("rcg_dir", rcg_directory)):
        if where is None:
            continue
        try:
            where.mkdir(parents=True, exist_ok=True)
        except OSError as exc:
            raise ParameterError(parameter, f"{where}: cannot create it ({exc.strerror})") from None

    def recorded(spec: MatchSpec) -> MatchSpec:
        name = replay_name(spec)
        return replace(spec, record=None if directory is None else str(directory / name),
                       rcg=None if rcg_directory is None else str(rcg_directory / Path(name).with_suffix(".rcg")))

    return [recorded(spec) if k % every == 0 else spec for k, spec in enumerate(specs)]
