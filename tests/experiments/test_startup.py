"""Start-up: the kernel warm-up (compiled once into the on-disk cache, loaded afterwards, a
progress line only when cold, before any match clock), its manifest, and a light ``--help``."""

from __future__ import annotations

import inspect
import json
import os
from pathlib import Path

import pytest

from experiments.warmup import COMPILING_LINE, PARTIAL_ENTRY, Kernel
from tests.fresh_python import run_python


TINY_MODULE = """
from numba import njit


@njit(cache=True)
def add(a, b):
    return a + b


@njit(cache=True)
def scale(x, k):
    return x * k
"""


@pytest.fixture
def tiny(tmp_path: Path) -> Path:
    """A module ``tinykernels`` with two cached kernels, importable from ``tmp_path``."""
    (tmp_path / "tinykernels.py").write_text(TINY_MODULE)
    return tmp_path


TINY_KERNELS = """
from experiments.warmup import Kernel
KERNELS = [Kernel("tinykernels", "add", "(int64, int64)", 1.0),
           Kernel("tinykernels", "scale", "(Array(float64, 1, 'C', False, aligned=True), float64)", 2.0)]
"""


def test_a_warm_up_elsewhere_leaves_this_process_only_loading(tiny: Path) -> None:
    cache = tiny / "cache"
    out = run_python(TINY_KERNELS + """
import json
from experiments.warmup import dispatcher_of, ensure_cached, is_cached, load_kernels
done = ensure_cached(KERNELS, processes=1, here=False)
compiled_here = [len(dispatcher_of(k).overloads) for k in KERNELS]
load_kernels(KERNELS)
stats = [dispatcher_of(k).stats for k in KERNELS]
print(json.dumps([done.compiled, done.processes, compiled_here, all(is_cached(k) for k in KERNELS),
                  [len(s.cache_hits) for s in stats], [len(s.cache_misses) for s in stats]]))
""", tiny, cache)
    # one helper compiled both into the cache; this process compiled nothing and loaded both
    assert json.loads(out.stdout) == [2, 1, [0, 0], True, [1, 1], [0, 0]]


def test_warm_up_compiles_into_the_cache_dir_and_a_later_process_loads_without_compiling(tiny: Path) -> None:
    cache = tiny / "cache"
    first = run_python(TINY_KERNELS + """
import sys
from experiments.warmup import ensure_cached, is_cached
assert not any(is_cached(k) for k in KERNELS)
done = ensure_cached(KERNELS, processes=2)
print(done.compiled, done.processes)
""", tiny, cache)
    # both missing, compiled on this process and one helper (on a machine of two cores or more)
    assert first.stdout.split() == ["2", str(min(2, os.cpu_count() or 1))]
    assert first.stderr.splitlines()[0] == COMPILING_LINE
    assert sorted(p.name.split("-")[0] for p in cache.rglob("*.nbi")) == ["tinykernels.add", "tinykernels.scale"]
    second = run_python(TINY_KERNELS + """
import json
from experiments.warmup import dispatcher_of, ensure_cached, is_cached, load_kernels
assert all(is_cached(k) for k in KERNELS)
done = ensure_cached(KERNELS)
load_kernels(KERNELS)
stats = [dispatcher_of(k).stats for k in KERNELS]
print(json.dumps([done.compiled, [len(s.cache_hits) for s in stats], [len(s.cache_misses) for s in stats]]))
""", tiny, cache)
    assert json.loads(second.stdout) == [0, [1, 1], [0, 0]]
    assert second.stderr == ""  # warm: no progress line


def test_a_changed_kernel_counts_as_cold_again(tiny: Path) -> None:
    cache = tiny / "cache"
    script = TINY_KERNELS + """
from experiments.warmup import ensure_cached
print(ensure_cached(KERNELS[:1], processes=1).compiled)
"""
    assert run_python(script, tiny, cache).stdout.split() == ["1"]
    assert run_python(script, tiny, cache).stdout.split() == ["0"]
    (tiny / "tinykernels.py").write_text(TINY_MODULE.replace("a + b", "b + a"))
    again = run_python(script, tiny, cache)
    assert again.stdout.split() == ["1"] and COMPILING_LINE in again.stderr


def test_a_stale_manifest_entry_is_skipped(tiny: Path) -> None:
    done = run_python(TINY_KERNELS + """
from experiments.warmup import Kernel, ensure_cached, is_cached
stale = [Kernel("tinykernels", "gone", "(int64,)"), Kernel("tinykernels", "add", "(unicode_type, int64)")]
print(ensure_cached(stale + KERNELS[:1], processes=1).compiled, is_cached(KERNELS[0]))
""", tiny, tiny / "cache")
    assert done.stdout.split() == ["2", "True"]  # the kernel that is gone is not missing; the bad types fail quietly


def test_manifest_names_existing_kernels_with_the_right_number_of_arguments() -> None:
    from experiments.kernel_manifest import KERNELS, TEAMS
    from experiments.kernel_record import builtin_teams, signature_text
    from experiments.warmup import dispatcher_of, signature_of

    assert sorted(TEAMS) == sorted([*builtin_teams(), PARTIAL_ENTRY])
    assert sorted({i for ids in TEAMS.values() for i in ids}) == list(range(len(KERNELS)))
    for entry in KERNELS:
        kernel = Kernel(*entry)
        dispatcher = dispatcher_of(kernel)
        assert dispatcher is not None, f"{kernel.name} is not a numba kernel"
        signature = signature_of(kernel)
        assert len(signature) == len(inspect.signature(dispatcher.py_func).parameters), kernel.name
        # the types read back exactly (a compiled structure's too), or the cache index never matches
        assert signature_text(signature) == kernel.signature, kernel.name


def test_kernels_for_takes_the_union_of_the_teams_and_of_mixed_members() -> None:
    from experiments.kernel_manifest import KERNELS, TEAMS
    from experiments.warmup import kernels_for

    def of(*teams):
        return {Kernel(*KERNELS[i]) for team in teams for i in TEAMS[team]}

    assert set(kernels_for(["mmd+msd2", "press-433"])) == of("mmd+msd2", "press-433")
    assert set(kernels_for(["mixed(static|greedy|static)", "idle"])) == of("static", "greedy", "idle")
    engine = set(kernels_for(["examples.my_team:MyTeam"]))  # the simulator's kernels only
    assert engine and all(engine <= of(team) for team in TEAMS if team != PARTIAL_ENTRY)
    assert {k.module.split(".")[0] for k in engine} == {"soccer_sim"}


def test_partial_observation_adds_the_see_model_and_the_world_models() -> None:
    from experiments.kernel_manifest import KERNELS, TEAMS
    from experiments.warmup import kernels_for, observation_of
    from experiments.runner.spec import paired_specs

    full, partial = set(kernels_for(["mmdr"])), set(kernels_for(["mmdr"], observation="partial"))
    added = {k.name for k in partial - full}
    assert "soccer_sim.perception.kernels:perceive" in added
    assert "agents.teams.belief_record:hear_block_and_believe" in added
    assert "agents.teams.own_view_state:before_roles_of" in added
    assert partial - full == {Kernel(*KERNELS[i]) for i in TEAMS[PARTIAL_ENTRY]} - full
    assert observation_of(paired_specs("mmdr", "chaser", 2, 0, 100, "partial")) == "partial"
    assert observation_of(paired_specs("mmdr", "chaser", 2, 0, 100)) == "full"


def test_help_imports_no_numpy_numba_rich_or_simulator(tmp_path: Path) -> None:
    done = run_python("""
import sys
from experiments.cli import main
try:
    main(["--help"])
except SystemExit:
    pass
heavy = ("numpy", "numba", "rich", "scipy", "pymunk", "soccer_sim", "agents", "formations")
print(sorted({m.split(".")[0] for m in sys.modules} & set(heavy)))
""", tmp_path)
    assert "play one match" in done.stdout
    assert done.stdout.strip().splitlines()[-1] == "[]"


def test_a_chosen_command_still_gets_its_lazily_built_options() -> None:
    from experiments.cli import build_parser

    args = build_parser().parse_args(["tournament", "--teams", "idle,chaser", "--games", "2", "--workers", "1"])
    assert (args.teams, args.games, args.workers, args.backend) == ("idle,chaser", 2, 1, "local")
    assert callable(args.func)
    args = build_parser().parse_args(["bench", "startup", "--repeats", "2"])
    assert (args.benchmark, args.repeats, args.home) == ("startup", 2, "mmd+msd2")


def test_play_warms_the_kernels_before_its_worker_starts(monkeypatch) -> None:
    import experiments.runner.local as local
    from experiments.cli import main
    from experiments.warmup import WarmUp

    order, kernel = [], Kernel("m", "f", "()")

    def warm(teams, processes=None, observation="full"):
        order.append(("warm", tuple(teams)))
        return WarmUp((kernel,), 1, processes, 0.0)

    def start_worker(self):
        order.append(("worker", self._kernels))  # the worker loads these before the match clock starts
        raise ValueError("stopped by the test")

    monkeypatch.setattr(local, "warm_kernels", warm)
    monkeypatch.setattr(local.LocalPool, "_start_worker", start_worker)
    assert main(["play", "greedy", "static", "--cycles", "10"]) == 2
    assert order == [("warm", ("greedy", "static")), ("worker", (kernel,))]


def test_the_runner_warms_up_before_the_progress_clock_and_the_first_worker(monkeypatch, tmp_path: Path) -> None:
    import experiments.runner.local as local
    import experiments.runner.run as run
    from experiments.runner import MatchSpec, run_matches
    from experiments.warmup import WarmUp

    order, kernel = [], Kernel("m", "f", "()")

    class Stop(Exception):
        pass

    def warm(teams, processes=None, observation="full"):
        order.append(("warm", tuple(teams), processes))
        return WarmUp((kernel,), 1, processes, 0.0)

    def start_worker(self):
        order.append(("worker", self._kernels))
        raise Stop

    real_progress = run.RunProgress
    monkeypatch.setattr(local, "warm_kernels", warm)
    monkeypatch.setattr(local.LocalPool, "_start_worker", start_worker)
    monkeypatch.setattr(run, "RunProgress", lambda *a, **k: order.append(("progress",)) or real_progress(*a, **k))
    specs = [MatchSpec("greedy", "static", 0, 10), MatchSpec("static", "mixed(idle|greedy)", 1, 10)]
    with pytest.raises(Stop):
        run_matches(specs, tmp_path / "r.sqlite", "tournament", {}, cycles=10, workers=2, progress=False)
    assert order == [("warm", ("greedy", "mixed(idle|greedy)", "static"), 2), ("progress",), ("worker", (kernel,))]


def test_a_worker_loads_the_kernels_before_it_takes_a_match(monkeypatch) -> None:
    import multiprocessing

    import experiments.runner.local as local

    order, kernel = [], Kernel("m", "f", "()")
    monkeypatch.setattr(local.signal, "signal", lambda *args: None)  # keep this process's Ctrl-C handler
    monkeypatch.setattr(local, "load_kernels", lambda kernels: order.append(("load", tuple(kernels))))
    parent, child = multiprocessing.Pipe()

    class Watched:
        def recv(self):
            order.append(("recv",))
            return child.recv()

        def send(self, value):
            child.send(value)

    parent.send(None)
    local._worker_main(Watched(), "hash", "version", 1.0, (kernel,))
    assert order == [("load", (kernel,)), ("recv",)]


@pytest.mark.slow
def test_manifest_matches_a_fresh_recording_of_the_default_teams(tmp_path: Path) -> None:
    """If this fails, a kernel's arguments changed: run ``python -m experiments.kernel_record --write``."""
    from experiments.kernel_manifest import KERNELS, TEAMS

    for team in ("mmd+msd2", "press-433"):
        done = run_python(f"""
from experiments.kernel_record import main
main(["--team", {team!r}])
""", tmp_path)
        recorded = {(k["module"], k["function"], k["signature"]) for k in json.loads(done.stdout)}
        assert recorded == {tuple(KERNELS[i][:3]) for i in TEAMS[team]}, team


@pytest.mark.slow
def test_after_the_warm_up_a_match_compiles_nothing(tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    first = run_python("""
from experiments.warmup import warm_kernels
warm_kernels(["mmd+msd2", "press-433"])
""", tmp_path, cache)
    assert first.stderr.splitlines()[0] == COMPILING_LINE
    second = run_python("""
import gc, json
from numba.core.dispatcher import Dispatcher
from experiments.warmup import warm_kernels
from soccer_sim import MatchConfig, run_match
warm_kernels(["mmd+msd2", "press-433"])
run_match("mmd+msd2", "press-433", seed=0, config=MatchConfig(max_cycles=600))
ours = ("soccer_sim", "agents", "formations")
misses = sorted(f"{d.py_func.__module__}:{d.py_func.__qualname__}" for d in gc.get_objects()
                if isinstance(d, Dispatcher) and d.py_func.__module__.split(".")[0] in ours and d.stats.cache_misses)
print(json.dumps(misses))
""", tmp_path, cache)
    assert second.stderr == ""
    assert json.loads(second.stdout) == []


def test_a_worker_is_not_timed_until_it_is_ready() -> None:
    from experiments.runner.local import LocalPool, _Worker

    pool = LocalPool(1, "hash", "version", 1.0)
    worker = _Worker(process=None, connection=None, spec=object(), started=0.0)  # sent long ago
    assert not pool._overdue(worker) and pool._wait_time([worker]) == 1.0
    worker.ready = True
    assert pool._overdue(worker)


@pytest.mark.slow
def test_compile_time_is_not_charged_to_a_tight_match_timeout(tmp_path: Path) -> None:
    done = run_python(f"""
from experiments.runner import MatchSpec, run_matches
if __name__ == "__main__":
    specs = [MatchSpec("chaser", "idle", seed, 20) for seed in range(3)]
    summary = run_matches(specs, {str(tmp_path / 'r.sqlite')!r}, "tournament", {{}}, cycles=20, workers=2,
                          match_timeout=1.0, progress=False)
    print(summary.errors, [r.error for r in summary.records])
""", tmp_path, tmp_path / "cache")
    assert done.stderr.splitlines()[0] == COMPILING_LINE  # the cache was cold: compiled before the matches
    assert done.stdout.split()[0] == "0", done.stdout
