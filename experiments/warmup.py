"""Compiling the simulator's numba kernels once per machine, before any match is timed.

Every kernel is decorated with ``cache=True``: numba keeps its machine code on disk (in
``__pycache__`` beside the source, or under ``NUMBA_CACHE_DIR``) and a later process loads it
in milliseconds. Without a warm-up the first match on a fresh install compiles some thirty
kernels inside its own clock (and its ``--match-timeout``), and every worker of a tournament
compiles the same ones at the same time.

:func:`warm_kernels` is called by the parent process before any match starts: it looks the
teams' kernels up in :mod:`experiments.kernel_manifest` (recorded by
:mod:`experiments.kernel_record`), checks the on-disk cache for each, and when any is missing
prints ``compiling kernels (first run only)`` to stderr and compiles them in this process and
one helper process per further core, each taking the next kernel from one shared list (the
costliest first), all saving into the same cache. While they compile, the kernels done of the
total and the seconds elapsed are shown (:class:`~experiments.runner.progress.CountProgress`:
one line kept up to date on a terminal, a line every few seconds in a log), so a first run
never sits silent for the minutes a loaded machine may take. Processes started afterwards (the match,
the workers) load them from there; :func:`load_kernels` does it up front in a worker.

The warm-up only saves time: a kernel it misses (a team not in the manifest, a manifest gone
stale) is compiled on first use as before, and a match's results never depend on it.
"""

from __future__ import annotations

import contextlib
import multiprocessing
import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from types import SimpleNamespace
from typing import Protocol, TextIO

COMPILING_LINE = "compiling kernels (first run only)"

PARTIAL_ENTRY = "(partial observation)"
"""The manifest's entry for the kernels a partially observed match adds (recorded from a
built-in team's self-play under partial observation)."""
"""The line printed to stderr before a cold cache is filled."""


@dataclass(frozen=True)
class Kernel:
    """One compiled kernel and one tuple of argument types it is called with from Python."""

    module: str
    function: str
    signature: str
    """The argument types as numba type expressions, e.g. ``(float64, Array(float64, 1, 'C', False, aligned=True))``."""
    seconds: float = 0.0
    """Its cold compile time where the manifest was recorded (a weight for sharing the work)."""

    @property
    def name(self) -> str:
        return f"{self.module}:{self.function}"


@dataclass(frozen=True)
class WarmUp:
    """What :func:`warm_kernels` did."""

    kernels: tuple[Kernel, ...]
    """The kernels the teams need (all in the cache afterwards unless one failed to compile)."""
    compiled: int
    """How many were missing from the cache and were compiled."""
    processes: int
    """Processes that compiled (0 when the cache was warm)."""
    seconds: float


def kernels_for(teams: Iterable[str], observation: str = "full") -> tuple[Kernel, ...]:
    """The kernels the matches of ``teams`` call, from the manifest: the simulator's own (those
    every built-in team's matches call), every registered team's, a mixed team's members'; under
    ``observation="partial"`` also those of a partially observed match (the see model, the
    players' world models and votes: the manifest's entry :data:`PARTIAL_ENTRY`). A team the
    manifest does not know (a ``package.module:Attribute`` path) adds none: its own kernels
    compile on first use."""
    from experiments.kernel_manifest import KERNELS, TEAMS

    teams_only = [ids for name, ids in TEAMS.items() if name != PARTIAL_ENTRY]
    indices: set[int] = set.intersection(*(set(ids) for ids in teams_only))
    for team in teams:
        for name in _member_names(team):
            indices.update(TEAMS.get(name, ()))
    if observation == "partial":
        indices.update(TEAMS.get(PARTIAL_ENTRY, ()))
    return tuple(Kernel(*KERNELS[i]) for i in sorted(indices))


def observation_of(specs: Iterable) -> str:
    """``"partial"`` when any of the match ``specs`` plays under partial observation, else
    ``"full"`` (a spec of full observation has no configuration of its own, or a full one)."""
    for spec in specs:
        configuration = getattr(spec, "configuration", None)
        if configuration is not None and configuration.observation.partial:
            return "partial"
    return "full"


def _member_names(team: str) -> list[str]:
    from experiments.mixed_team import is_mixed_name, member_names

    return sorted(set(member_names(team))) if is_mixed_name(team) else [team]


def warm_kernels(teams: Iterable[str], processes: int | None = None, stream: TextIO | None = None,
                 observation: str = "full", here: bool = True) -> WarmUp:
    """Make sure every kernel the matches of ``teams`` under ``observation`` need is in the
    on-disk cache (see :func:`ensure_cached`)."""
    return ensure_cached(kernels_for(teams, observation), processes, stream, here)


def ensure_cached(kernels: Sequence[Kernel], processes: int | None = None, stream: TextIO | None = None,
                  here: bool = True) -> WarmUp:
    """Make sure every one of ``kernels`` is in the on-disk cache, compiling the missing ones on
    ``processes`` processes (default and at most: every core; this one included unless ``here``
    is False, see :func:`compile_kernels`), with one line on ``stream`` (default stderr) before
    and one after when anything had to be compiled."""
    start = time.perf_counter()
    kernels = tuple(kernels)
    missing = [kernel for kernel in kernels if not is_cached(kernel)]
    if not missing:
        return WarmUp(kernels, 0, 0, time.perf_counter() - start)
    from experiments.runner.progress import CountProgress

    stream = stream if stream is not None else sys.stderr
    print(COMPILING_LINE, file=stream, flush=True)
    cores = os.cpu_count() or 1
    progress = CountProgress(len(missing), "compiling kernels", "done", stream)
    used = compile_kernels(missing, min(processes or cores, cores), here, progress)
    seconds = time.perf_counter() - start
    print(f"compiled {len(missing)} kernels in {seconds:.1f} s on {used} process(es)", file=stream, flush=True)
    return WarmUp(kernels, len(missing), used, seconds)


def is_cached(kernel: Kernel) -> bool:
    """Whether numba's on-disk cache holds ``kernel`` for this machine and this version of its
    source (read from the kernel's cache index, without loading or compiling anything)."""
    dispatcher = dispatcher_of(kernel)
    if dispatcher is None:
        return True  # nothing to compile: the manifest names a kernel that is gone
    try:
        cache = dispatcher._cache
        key = cache._index_key(signature_of(kernel), dispatcher.targetctx.codegen())
        return key in cache._cache_file._load_index()
    except Exception:  # noqa: BLE001 - numba internals changed or the index is unreadable: compile to be sure
        return False


def dispatcher_of(kernel: Kernel):
    """The kernel's numba dispatcher, or None when its module or function no longer exists."""
    import importlib

    try:
        target = importlib.import_module(kernel.module)
        for part in kernel.function.split("."):
            target = getattr(target, part)
    except (ImportError, AttributeError):
        return None
    return target if hasattr(target, "py_func") and hasattr(target, "compile") else None


def signature_of(kernel: Kernel) -> tuple:
    """The kernel's argument types as numba types. A compiled structure's type (a numba
    ``StructRef``, written ``numba.NameType((field, type), ...)``) is one its module defines;
    importing the kernel's module (:func:`dispatcher_of`) registers it. A named tuple's type is
    written ``named('module.Class', (field types,))``."""
    from numba.core import types

    dispatcher_of(kernel)
    structures = SimpleNamespace(**{cls.__name__: _structure_maker(cls) for cls in _subclasses(types.StructRef)})
    namespace = {**vars(types), "numba": structures, "named": _named_tuple_type}
    return tuple(eval(kernel.signature, {"__builtins__": {}}, namespace))  # noqa: S307 - text from the manifest


def _named_tuple_type(path: str, fields: tuple) -> object:
    """The numba type of a named tuple of class ``path`` (``module.Class``) with ``fields``'
    types: how the manifest writes a kernel's named-tuple argument
    (:func:`experiments.kernel_record.signature_text`)."""
    import importlib

    from numba.core import types

    module, _, name = path.rpartition(".")
    return types.BaseTuple.from_types(list(fields), getattr(importlib.import_module(module), name))


def _structure_maker(cls: type) -> Callable[..., object]:
    """``cls`` made from its fields as the signature's text lists them."""
    return lambda *fields: cls(list(fields))


def _subclasses(cls: type) -> list[type]:
    """Every subclass of ``cls`` defined so far, at any depth."""
    found = []
    for sub in cls.__subclasses__():
        found += [sub, *_subclasses(sub)]
    return found


PROGRESS_EVERY_SECONDS = 1.0
"""How often the progress of a compilation is looked at (and, on a terminal, redrawn)."""


class _Progress(Protocol):
    def show(self, done: int) -> None: ...

    def close(self, done: int) -> None: ...


def compile_kernels(kernels: Sequence[Kernel], processes: int, here: bool = True,
                    progress: _Progress | None = None) -> int:
    """Compile ``kernels`` into the on-disk cache on up to ``processes`` processes, this one
    included unless ``here`` is False (then helper processes do it all: a process that compiled
    kernels runs its matches some 5 % slower than one that loaded them from the cache, which a
    benchmark must not measure); returns how many took part. The kernels of one function stay
    together (they share its cache index), the costliest first, each process taking the next
    when it is free. ``progress`` (e.g. a :class:`~experiments.runner.progress.CountProgress`)
    is shown the number of kernels done every :data:`PROGRESS_EVERY_SECONDS` by a thread of
    this process, and closed with the final count."""
    groups: dict[str, list[Kernel]] = {}
    for kernel in kernels:
        groups.setdefault(kernel.name, []).append(kernel)
    work = sorted(groups.values(), key=lambda group: -sum(k.seconds for k in group))
    context = multiprocessing.get_context("spawn")
    finished = context.Value("i", 0)
    with _showing(progress, finished):
        helpers_count = min(processes, len(work)) - (1 if here else 0)
        if here and helpers_count <= 0:
            _compile_share(work, None, finished)
            return 1
        helpers_count = max(helpers_count, 1)
        counter = context.Value("i", 0)
        helpers = [context.Process(target=_helper_main, args=(work, counter, finished), daemon=True,
                                   name="soccer-sim-compile") for _ in range(helpers_count)]
        for helper in helpers:
            helper.start()
        try:
            if here:
                _compile_share(work, counter, finished)
            for helper in helpers:
                helper.join()
        except BaseException:  # Ctrl-C: do not wait for the helpers (each cache file is written atomically)
            for helper in helpers:
                helper.terminate()
            for helper in helpers:
                helper.join()
            raise
    return helpers_count + (1 if here else 0)


@contextlib.contextmanager
def _showing(progress: _Progress | None, finished) -> Iterator[None]:
    """Within the block, a daemon thread shows ``progress`` the count in ``finished`` every
    :data:`PROGRESS_EVERY_SECONDS`; at the end it is closed with the final count (also after
    Ctrl-C: the line it drew is ended)."""
    if progress is None:
        yield
        return
    stop = threading.Event()

    def watch() -> None:
        while not stop.wait(PROGRESS_EVERY_SECONDS):
            progress.show(finished.value)

    watcher = threading.Thread(target=watch, name="soccer-sim-compile-progress", daemon=True)
    watcher.start()
    try:
        yield
    finally:
        stop.set()
        watcher.join()
        progress.close(finished.value)


def _helper_main(work: list[list[Kernel]], counter, finished) -> None:
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the parent's to handle
    _compile_share(work, counter, finished)


def _compile_share(work: list[list[Kernel]], counter, finished) -> None:
    """Compile groups of ``work`` in turn: all of them, or with a shared ``counter`` the next
    one no other process has taken; each kernel done adds one to the shared ``finished``."""
    position = 0
    while True:
        if counter is not None:
            with counter.get_lock():
                position = counter.value
                counter.value += 1
        if position >= len(work):
            return
        for kernel in work[position]:
            _compile(kernel)
            with finished.get_lock():
                finished.value += 1
        position += 1


def _compile(kernel: Kernel) -> None:
    """Compile (or load) one kernel; a stale manifest entry is skipped, never fatal."""
    dispatcher = dispatcher_of(kernel)
    if dispatcher is None:
        return
    try:
        dispatcher.compile(signature_of(kernel))
    except Exception:  # noqa: BLE001 - the match compiles whatever it really calls on first use
        pass


def load_kernels(kernels: Iterable[Kernel]) -> None:
    """Load ``kernels`` into this process (from the cache :func:`warm_kernels` filled), so a
    worker's first match does not spend its time budget on it."""
    for kernel in kernels:
        _compile(kernel)
