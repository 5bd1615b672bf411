"""Fuzzing the Python API's constructors: configuration dataclasses, scenario loading,
``run_match``'s arguments and the assignment functions.

Each call runs in a forked child (:mod:`tests.experiments.forked`) with a time bound, and must
either be refused with one of the project's errors (``SoccerSimError``, ``FormationError``,
``AgentsError``, ``ExperimentError``) or work: no other exception, no hang, no special file
opened as a scenario, no input changed. A configuration value is refused at construction, naming
its field, or gives a match that plays; an assignment that returns has finite totals, and
complex coordinates are refused rather than cut to their real part.

The default run is derandomized and small; the ``slow`` variants draw many more examples.
A failing example is reported as found (no shrinking: a hang costs the bound).
"""

from __future__ import annotations

import dataclasses
import math
import os
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp

from tests.experiments.extremes import extreme_numbers
from tests.experiments.forked import Forked, run_forked
from tests.robustness.steps import Unsupported, make_device
from tests.robustness.watch import changed, snapshot

BOUND = 15.0
"""Seconds a call may take: a 5-cycle match takes well under one (a few on a loaded machine)."""

FAST = settings(max_examples=12, deadline=None, derandomize=True, database=None,
                phases=(Phase.explicit, Phase.generate), suppress_health_check=list(HealthCheck))
SLOW = settings(max_examples=300, deadline=None, database=None, phases=(Phase.explicit, Phase.generate),
                suppress_health_check=list(HealthCheck))

EXTREME_VALUES = [1e308, -1e308, 1e-308, -1e-308, -1, 0, 0.0, -0.0, 10**30, -(10**30), 2**63, 2**64, math.nan,
                  math.inf, -math.inf, 1e9]
"""Huge, tiny, negative and non-finite numbers."""


@pytest.fixture(scope="module")
def warm() -> None:
    """Load the kernels in this process once, so each forked match starts warm."""
    from soccer_sim import MatchConfig, run_match

    run_match("idle", "chaser", config=MatchConfig(max_cycles=5))


def expect_refused_or_working(where: str, run: Forked) -> None:
    """No hang, no death by a signal, nothing raised but the project's errors."""
    assert not run.timed_out, f"{where}: hangs ({run.describe()})"
    assert run.exit_signal is None and run.exited is None, f"{where}: {run.describe()}; {run.stderr[-300:]!r}"
    assert run.raised is None or run.project_error, f"{where}: not one of the project's errors: {run.describe()}"


# ------------------------------------------------------------------------------ configuration
def configuration_fields() -> list[tuple[tuple[str, ...], str]]:
    """(path of the dataclass inside MatchConfig, numeric field) for every configuration
    dataclass, nested ones included; the empty path is MatchConfig itself."""
    from soccer_sim import MatchConfig

    found = []

    def walk(value, path):
        for item in dataclasses.fields(value):
            inner = getattr(value, item.name)
            if dataclasses.is_dataclass(inner):
                walk(inner, (*path, item.name))
            elif not isinstance(inner, (bool, str)) and ("float" in str(item.type) or "int" in str(item.type)):
                found.append((path, item.name))

    walk(MatchConfig(), ())
    return found


def config_with(path: tuple[str, ...], name: str, value):
    """A MatchConfig of 5 cycles whose dataclass at ``path`` has ``name=value`` (each level
    built by its constructor, so each level's checks run)."""
    from soccer_sim import MatchConfig

    def build(default, rest):
        if not rest:
            return type(default)(**{**_own_values(default), name: value})
        head = rest[0]
        return type(default)(**{**_own_values(default), head: build(getattr(default, head), rest[1:])})

    base = MatchConfig(max_cycles=5) if name != "max_cycles" or path else MatchConfig()
    return build(base, path)


def _own_values(instance) -> dict:
    return {item.name: getattr(instance, item.name) for item in dataclasses.fields(instance) if item.init}


def numbers():
    """Values no field should take without a word (as the command line's extreme numbers)."""
    return st.one_of(st.sampled_from(EXTREME_VALUES), extreme_numbers())


def _config_example(path: tuple[str, ...], name: str, value, must_refuse: bool = False) -> None:
    from soccer_sim import run_match
    from tests.experiments.forked import project_errors

    def call():
        try:
            config = config_with(path, name, value)
        except project_errors() as exc:
            return ("refused", str(exc))
        return ("played", int(run_match("idle", "chaser", config=config).cycles))

    where = f"{'.'.join(('MatchConfig', *path))}({name}={value!r})"
    run = run_forked(call, bound=BOUND, cwd=Path.cwd())
    expect_refused_or_working(where, run)
    assert run.raised is None, f"{where}: accepted at construction, then the match failed: {run.describe()}"
    verdict, detail = run.returned
    assert verdict == "refused" or not must_refuse, f"{where}: accepted at construction"
    if verdict == "refused":
        assert name in detail, f"{where}: refused without naming {name}: {detail!r}"


def _config_test(config: settings) -> None:
    @config
    @given(st.sampled_from(configuration_fields()), numbers())
    def fuzz(field, value):
        _config_example(*field, value)

    fuzz()


def test_configuration_values_are_refused_by_name_or_play(warm):
    _config_test(FAST)


@pytest.mark.slow
def test_configuration_values_at_length(warm):
    _config_test(SLOW)


@pytest.mark.parametrize("path, name, value", [
    (("field",), "length", 1e308), (("rules",), "set_play_clearance", 1e308), (("physics",), "ball_radius", 1e308),
], ids=["field length", "set_play_clearance", "ball_radius"])
def test_the_values_that_broke_physics(warm, path, name, value):
    """The cases found by hand (a match spinning for ever, a team blamed for the physics): values
    that break physics are refused at construction, naming the field."""
    _config_example(path, name, value, must_refuse=True)


# ------------------------------------------------------------------------------ scenarios and run_match
SPECIAL_SCENARIOS = {"fifo.toml": "fifo", "zero.toml": "zero", "urandom.json": "urandom", "link.toml": "link",
                     "folder.json": "directory"}


@pytest.fixture(scope="module")
def places(tmp_path_factory) -> Path:
    """A directory with special files named like scenario files (device nodes are private;
    the kinds the platform does not allow are left out)."""
    root = tmp_path_factory.mktemp("api-places")
    os.mkfifo(root / "fifo.toml")
    (root / "folder.json").mkdir()
    (root / "junk.toml").write_bytes(bytes(range(256)))
    (root / "empty.toml").write_bytes(b"")
    for name, kind in (("zero.toml", "zero"), ("urandom.json", "urandom"), ("nodes/zero", "zero")):
        try:
            make_device(root / name, kind)
        except Unsupported:
            pass
    if (root / "nodes" / "zero").exists():
        os.symlink("nodes/zero", root / "link.toml")
    return root


def scenario_arguments(places: Path) -> list:
    present = [str(places / name) for name in (*SPECIAL_SCENARIOS, "junk.toml", "empty.toml")
               if (places / name).exists() or (places / name).is_symlink()]
    return [None, 5, b"kick-off", "", "no-such-scenario", object(), places, places / "missing.toml", *present]


BAD_ARGUMENTS = {
    "seed": [-1, 2**64, 10**30, 1e308, math.nan, "x", None, 1.5],
    "recorders": ["x", [None], [object()], 5, None, [1, 2]],
    "home": ["", 5, None, "nobody", object(), "no_such_pkg.mod:Team"],
    "config": ["x", 5, object()],
}


def _run_match_example(places: Path, argument: str, value) -> None:
    from soccer_sim import MatchConfig, run_match

    def call():
        arguments = {"home": "idle", "away": "chaser", "config": MatchConfig(max_cycles=5), argument: value}
        return int(run_match(**arguments).cycles)

    before = snapshot(places, ())
    run = run_forked(call, bound=BOUND, cwd=places)
    expect_refused_or_working(f"run_match({argument}={value!r})", run)
    assert not changed(before, places, ()), f"run_match({argument}={value!r}) changed {changed(before, places, ())}"


def _run_match_test(places: Path, config: settings) -> None:
    choices = [*((name, value) for name, values in BAD_ARGUMENTS.items() for value in values),
               *(("scenario", value) for value in scenario_arguments(places))]

    @config
    @given(st.sampled_from(choices))
    def fuzz(choice):
        _run_match_example(places, *choice)

    fuzz()


def test_run_match_arguments_are_refused_or_work(warm, places):
    _run_match_test(places, FAST)


@pytest.mark.slow
def test_run_match_arguments_at_length(warm, places):
    _run_match_test(places, settings(SLOW, max_examples=100))


def test_load_scenario_refuses_what_is_no_scenario_file(places):
    """Every argument here is refused with a ScenarioError; a FIFO or a device is never opened
    for reading (it would block or never end)."""
    from soccer_sim.scenarios import load_scenario

    failures = []
    for value in scenario_arguments(places):
        before = snapshot(places, ())
        run = run_forked(lambda: repr(load_scenario(value))[:80], bound=10.0, cwd=places)
        if run.timed_out or run.raised is None or not run.project_error or changed(before, places, ()):
            failures.append(f"load_scenario({value!r}): {run.describe()}")
    assert not failures, "\n".join(failures)


# ------------------------------------------------------------------------------ assignment
def point_arrays():
    """Robot or target positions as a caller might pass them, good and bad."""
    rows, dims = st.integers(0, 5), st.integers(1, 3)
    real = st.tuples(rows, dims).flatmap(lambda shape: hnp.arrays(
        np.float64, shape, elements=st.one_of(st.floats(allow_nan=True, allow_infinity=True),
                                              st.sampled_from([1e308, -1e308, 1e150, 0.0]))))
    finite = st.tuples(st.integers(1, 5), st.just(2)).flatmap(lambda shape: hnp.arrays(
        np.float64, shape, elements=st.floats(-1e3, 1e3)))
    complex_ = st.tuples(st.integers(1, 4), st.just(2)).flatmap(lambda shape: hnp.arrays(
        np.complex128, shape, elements=st.complex_numbers(max_magnitude=1e3, allow_nan=False)))
    junk = st.sampled_from([None, 5, "points", [["a", "b"]], [[1, 2], [3]], [[[1, 2]]], [], [[True, False]]])
    return st.one_of(finite, real, complex_, junk)


def _assign_summary(result) -> tuple:
    return (float(result.total), float(result.makespan), int((np.asarray(result.target_of) >= 0).sum()))


def _assign_example(kind: str, method: str, first, second) -> None:
    from agents.assignment import assign, assign_costs

    def call():
        extra = {"rng": 0} if method == "random" else {}
        if kind == "costs":
            return _assign_summary(assign_costs(first, method, **extra))
        return _assign_summary(assign(first, second, method, **extra))

    where = f"{'assign_costs' if kind == 'costs' else 'assign'}({first!r}, {second!r}, {method!r})"[:600]
    run = run_forked(call, bound=BOUND, cwd=Path.cwd())
    expect_refused_or_working(where, run)
    if run.raised is None:
        total, makespan, assigned = run.returned
        if assigned:
            assert math.isfinite(total) and math.isfinite(makespan), f"{where}: returned total {total}, makespan {makespan}"
        for given_ in (first, second):
            if isinstance(given_, np.ndarray) and np.iscomplexobj(given_) and np.any(given_.imag != 0):
                raise AssertionError(f"{where}: complex coordinates accepted (imaginary parts dropped)")


def assignment_calls():
    from agents.assignment import METHODS

    methods = st.sampled_from(METHODS)
    costs = st.one_of(
        st.tuples(st.integers(0, 4), st.integers(0, 4)).flatmap(lambda shape: hnp.arrays(
            np.float64, shape, elements=st.one_of(st.floats(0, 1e308), st.sampled_from([1e308, math.inf, -1.0, math.nan])))),
        point_arrays())
    return st.one_of(st.tuples(st.just("points"), methods, point_arrays(), point_arrays()),
                     st.tuples(st.just("costs"), methods, costs, st.none()))


def _assign_test(config: settings) -> None:
    @config
    @given(assignment_calls())
    def fuzz(call):
        _assign_example(*call)

    fuzz()


def test_assignment_inputs_are_refused_or_solved():
    _assign_test(settings(FAST, max_examples=30))


@pytest.mark.slow
def test_assignment_inputs_at_length():
    _assign_test(SLOW)


@pytest.mark.parametrize("kind, first, second", [
    ("costs", np.full((3, 3), 1e308), None),
    ("points", np.array([[1 + 1j, 2], [3, 4]]), np.array([[0, 0], [1, 1j]])),
], ids=["costs of 1e308", "complex coordinates"])
def test_the_assignment_inputs_found_by_hand(kind, first, second):
    _assign_example(kind, "mmdr", first, second)


def test_the_special_scenario_files_are_there(places):
    """The FIFO and the directory are always made (the device nodes where permitted), and
    every one of them is among the arguments tried."""
    assert (places / "fifo.toml").exists() and (places / "folder.json").is_dir()
    tried = {Path(value).name for value in scenario_arguments(places) if isinstance(value, str)}
    assert {"fifo.toml", "folder.json"} <= tried
