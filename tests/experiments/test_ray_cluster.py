"""The Ray backend on a real multi-node cluster in this process (``ray.cluster_utils.Cluster``):
nodes that cannot import the project or run different code are found before any match and
left out, the code version stored is the one each worker ran, the cluster RAY_ADDRESS names is
joined without local resources, and nodes that leave or join during a run are followed.

Every node's worker processes get their own PYTHONPATH (``env_vars`` of the node): this
checkout (a good node), a copy of the project with one source file changed (different code),
or a directory whose ``sitecustomize`` hides the editable install (a venv with Ray but without
the project). The driver runs from an empty directory so Ray does not put a checkout on the
workers' path."""

from __future__ import annotations

import shutil
import time
from pathlib import Path

import pytest

from experiments.cli import main
from experiments.results.record import FORFEIT_NONE
from experiments.results.store import ResultStore
from experiments.runner.fingerprint import DIGITS, PACKAGES, package_dirs, source_digest
from experiments.runner.preflight import failure_reason
from experiments.runner.spec import MatchSpec, code_version, config_for, config_hash
from experiments.runner.worker import play_spec
from tests.experiments.helpers import outcome

ROOT = Path(__file__).resolve().parents[2]

HIDE_PROJECT = '''"""Hide the editable install of the project: this interpreter plays a venv without it."""
import sys

sys.meta_path[:] = [f for f in sys.meta_path if "__editable__" not in getattr(f, "__module__", "")]
'''


def copy_project(destination: Path, change: str | None = None) -> Path:
    """The four packages copied under ``destination`` (no caches), with ``change`` (a relative
    path) given an extra line of code."""
    for name in PACKAGES:
        shutil.copytree(ROOT / name, destination / name, ignore=shutil.ignore_patterns("__pycache__"))
    if change:
        with open(destination / change, "a") as file:
            file.write("\nLOCAL_CHANGE = True\n")
    return destination


# ---- the code version (no Ray) -----------------------------------------------------------------

def test_code_version_is_the_hash_of_the_imported_sources(tmp_path) -> None:
    dirs = package_dirs()
    assert all(dirs[name] == ROOT / name for name in PACKAGES)  # this checkout is what the tests import
    assert code_version() == source_digest(dirs)[:DIGITS]
    same = copy_project(tmp_path / "same")
    (same / "agents" / "__pycache__").mkdir(exist_ok=True)
    (same / "agents" / "__pycache__" / "stale.py").write_text("x = 1\n")  # caches are not code
    assert source_digest({name: same / name for name in PACKAGES}) == source_digest(dirs)
    changed = copy_project(tmp_path / "changed", "agents/skills.py")
    assert source_digest({name: changed / name for name in PACKAGES}) != source_digest(dirs)


def test_package_data_that_changes_play_is_part_of_the_code_version(tmp_path) -> None:
    project = copy_project(tmp_path / "p")
    dirs = {name: project / name for name in PACKAGES}
    before = source_digest(dirs)
    formation = next((project / "formations" / "data").glob("*.json"))
    formation.write_text(formation.read_text() + " ")
    assert source_digest(dirs) != before


def test_a_played_record_carries_the_code_version_of_the_process_that_played(tmp_path) -> None:
    from experiments.runner.worker import play_spec

    spec = MatchSpec("chaser", "idle", 3, 20)
    record = play_spec(spec, config_hash(config_for(20)), "the driver's version", None)
    assert record.error is None
    assert record.code_version == code_version() != "the driver's version"


def test_failure_reason_names_the_missing_module() -> None:
    error = RuntimeError("The remote function failed to import on the worker.\n  Traceback ...\n"
                         "ModuleNotFoundError: No module named 'experiments'")
    assert failure_reason(error) == "cannot import the project (No module named 'experiments')"
    assert failure_reason(OSError("first\nlast line")) == "OSError: last line"


def test_the_preflight_refuses_other_libraries_and_configurations() -> None:
    from experiments.runner.preflight import Expected, check_node, library_versions

    mine = code_version(), config_hash(config_for(100))
    other_numpy = tuple((name, "0.0.1" if name == "numpy" else version) for name, version in library_versions())
    found = check_node(Expected(*mine, 100, ("chaser",), other_numpy))
    assert found.problem == f"has numpy {dict(library_versions())['numpy']} (driver: 0.0.1)"
    found = check_node(Expected(mine[0], "0123456789abcdef", 100, ("chaser",), library_versions()))
    assert found.problem == f"has a different match configuration (hash {mine[1]} != driver's 0123456789abcdef)"
    found = check_node(Expected(*mine, 100, ("chaser", "no_such_module:Team"), library_versions()))
    assert found.problem.startswith("cannot load team 'no_such_module:Team' (")


def test_code_is_shipped_as_py_modules_to_a_cluster_and_on_pythonpath_to_a_local_instance() -> None:
    from experiments.runner.ray_cluster import code_runtime_env

    cluster = code_runtime_env(local=False)
    assert sorted(cluster["py_modules"]) == sorted(str(ROOT / name) for name in PACKAGES)
    assert "__pycache__" in cluster["excludes"]
    local = code_runtime_env(local=True)
    assert local["env_vars"]["PYTHONPATH"].split(":")[0] == str(ROOT)


# ---- the driver's bookkeeping (no Ray: a stand-in answers get and cancel) ---------------------

class _Answers:
    """Stands in for the ``ray`` module: ``get`` returns or raises what each ref was given."""

    def __init__(self, answers: dict) -> None:
        self.answers = answers

    def get(self, ref):
        answer = self.answers[ref]
        if isinstance(answer, BaseException):
            raise answer
        return answer

    def cancel(self, ref, force: bool = False) -> None:
        pass


def _pool_with_nodes(answers: dict, *node_ids: str):
    import io
    from collections import Counter, deque

    from experiments.runner.ray_backend import RayPool
    from experiments.runner.ray_cluster import ClusterNode

    pool = object.__new__(RayPool)
    pool._ray, pool._args, pool._timeout, pool._stream = _Answers(answers), ("hash", "driver", None), None, io.StringIO()
    pool._in_flight, pool._pending, pool._played, pool._checks = {}, deque(), Counter(), {}
    pool._nodes = {node_id: ClusterNode(node_id, "10.0.0.1", 1, "ready") for node_id in node_ids}
    return pool


def _finish(pool, ref, spec: MatchSpec, node_id: str, attempt: int = 0) -> list:
    from experiments.runner.ray_cluster import MatchTask

    node = pool._nodes[node_id]
    node.busy += 1
    return list(pool._finished(ref, MatchTask(spec, node, time.monotonic(), attempt), "driver"))


def test_a_row_played_by_other_code_is_not_stored_and_its_node_is_taken_out() -> None:
    from experiments.results.record import MatchRecord

    spec = MatchSpec("chaser", "idle", 1, 100)
    pool = _pool_with_nodes({"r": MatchRecord("chaser", "idle", 1, "hash", "other")}, "a", "b")
    assert _finish(pool, "r", spec, "a") == []
    assert pool._nodes["a"].state == "out" and pool._nodes["b"].state == "ready"
    assert "node a (10.0.0.1) excluded: runs different code (version other != driver's driver)" in pool._stream.getvalue()
    assert [(s, attempt) for s, attempt, _ in pool._pending] == [(spec, 1)]


def test_a_node_failing_three_tasks_in_a_row_is_taken_out_and_retries_are_bounded() -> None:
    from experiments.runner.ray_backend import MATCH_RETRIES, NODE_FAILURE_LIMIT

    assert (NODE_FAILURE_LIMIT, MATCH_RETRIES) == (3, 2)  # the documented defaults
    failure = RuntimeError("ModuleNotFoundError: No module named 'agents'")
    pool = _pool_with_nodes({ref: failure for ref in "xyz"}, "a", "b")
    specs = [MatchSpec("chaser", "idle", seed, 100) for seed in range(3)]
    assert _finish(pool, "x", specs[0], "a") == [] and _finish(pool, "y", specs[1], "a") == []
    assert pool._nodes["a"].state == "ready"  # two in a row: still in
    given_up = _finish(pool, "z", specs[2], "a", attempt=MATCH_RETRIES)
    assert pool._nodes["a"].state == "out"
    assert "3 tasks failed in a row (last: cannot import the project (No module named 'agents'))" in pool._stream.getvalue()
    assert [record.seed for record in given_up] == [2]  # its third play failed: recorded, nobody blamed
    assert given_up[0].error.endswith("(played 3 times)") and given_up[0].forfeit == FORFEIT_NONE
    assert sorted(s.seed for s, _, failed_on in pool._pending if failed_on == {"a"}) == [0, 1]


# ---- a cluster in this process ------------------------------------------------------------------

ray = pytest.importorskip("ray")
pytestmark = pytest.mark.xdist_group("ray")  # one Ray instance at a time on the machine


@pytest.fixture
def cluster(tmp_path, monkeypatch):
    """A one-node cluster (the head, a good node) torn down afterwards; the driver runs from an
    empty directory and RAY_ADDRESS is unset."""
    from ray.cluster_utils import Cluster

    driver = tmp_path / "driver"
    driver.mkdir()
    monkeypatch.chdir(driver)
    monkeypatch.delenv("RAY_ADDRESS", raising=False)
    made = Cluster(initialize_head=True, head_node_args={"num_cpus": 1, "env_vars": {"PYTHONPATH": str(ROOT)}})
    try:
        yield made
    finally:
        ray.shutdown()
        made.shutdown()


def add_good_node(cluster, cpus: int = 1):
    return cluster.add_node(num_cpus=cpus, env_vars={"PYTHONPATH": str(ROOT)})


def add_bare_node(cluster, tmp_path: Path):
    hidden = tmp_path / "bare"
    hidden.mkdir()
    (hidden / "sitecustomize.py").write_text(HIDE_PROJECT)
    return cluster.add_node(num_cpus=1, env_vars={"PYTHONPATH": str(hidden)})


def add_other_code_node(cluster, tmp_path: Path):
    other = copy_project(tmp_path / "other", "soccer_sim/__init__.py")
    node = cluster.add_node(num_cpus=1, env_vars={"PYTHONPATH": str(other)})
    return node, source_digest({name: other / name for name in PACKAGES})[:DIGITS]


TOURNAMENT = ["tournament", "--teams", "chaser,idle", "--games", "4", "--cycles", "100", "--workers", "2",
              "--no-progress", "--backend", "ray"]


def test_nodes_without_the_project_or_with_other_code_are_excluded_and_nothing_wrong_is_stored(
        cluster, tmp_path, monkeypatch, capsys) -> None:
    bare = add_bare_node(cluster, tmp_path)
    other, other_version = add_other_code_node(cluster, tmp_path)
    monkeypatch.setenv("RAY_ADDRESS", cluster.address)  # as under `ray job submit`: no --address
    out = tmp_path / "cluster.sqlite"
    assert main([*TOURNAMENT, "--no-ship-code", "--out", str(out)]) == 0
    err = capsys.readouterr().err
    assert f"joined the cluster at {cluster.address} (RAY_ADDRESS): 3 node(s), 3 CPU(s) used" in err
    assert (f"node {bare.node_id} ({bare.node_ip_address}) excluded: cannot import the project "
            "(No module named 'experiments')") in err
    assert (f"node {other.node_id} ({other.node_ip_address}) excluded: runs different code "
            f"(version {other_version} != driver's {code_version()})") in err
    assert other_version != code_version()
    with ResultStore.open(out) as store:
        records = store.records()
    assert len(records) == 4
    assert all(record.error is None for record in records)
    assert {record.code_version for record in records} == {code_version()}


@pytest.mark.slow
def test_with_code_shipped_a_node_without_the_project_plays(cluster, tmp_path, capsys) -> None:
    from experiments.runner.ray_backend import RayPool

    bare = add_bare_node(cluster, tmp_path)
    version = code_version()
    pool = RayPool(None, config_hash(config_for(100)), version, None, cluster.address, ship_code=True)
    try:
        specs = [MatchSpec("chaser", "idle", seed, 100) for seed in range(6)]
        pool.warm_up(specs)
        records = list(pool.run(specs))
        played = pool.played_per_node
    finally:
        pool.close()
    assert "excluded" not in capsys.readouterr().err
    assert sorted(r.seed for r in records) == list(range(6))
    assert all(r.error is None and r.code_version == version for r in records)
    assert played.get(f"node {bare.node_id} ({bare.node_ip_address})", 0) > 0


@pytest.mark.slow
def test_a_node_that_leaves_mid_run_has_its_matches_played_elsewhere(cluster, tmp_path, capsys) -> None:
    from experiments.runner.ray_backend import RayPool

    leaving = add_good_node(cluster)
    version = code_version()
    pool = RayPool(None, config_hash(config_for(2000)), version, None, cluster.address, ship_code=False)
    specs = [MatchSpec("chaser", "idle", seed, 2000) for seed in range(8)]
    records = []
    try:
        pool.warm_up(specs)
        for record in pool.run(specs):
            records.append(record)
            if len(records) == 1:
                cluster.remove_node(leaving, allow_graceful=False)
    finally:
        pool.close()
    err = capsys.readouterr().err
    assert f"node {leaving.node_id} ({leaving.node_ip_address}) excluded" in err
    assert sorted(r.seed for r in records) == list(range(8))
    assert all(r.error is None and r.code_version == version for r in records)
    # The same rows as the matches played uninterrupted, one after another in this process.
    uninterrupted = [play_spec(spec, config_hash(config_for(2000)), version, None) for spec in specs]
    assert outcome(sorted(records, key=lambda r: r.seed)) == outcome(uninterrupted)


@pytest.mark.slow
def test_a_node_that_joins_mid_run_is_checked_and_used(cluster, tmp_path) -> None:
    """After the first match the head's CPU is taken by a stand-in task (up to 120 s), so the
    rest can only be played by the node that joins then (or by the head once that ends)."""
    from ray.util.scheduling_strategies import NodeAffinitySchedulingStrategy

    from experiments.runner.ray_backend import RayPool

    version = code_version()
    pool = RayPool(None, config_hash(config_for(200)), version, None, cluster.address, ship_code=False)
    specs = [MatchSpec("chaser", "idle", seed, 200) for seed in range(6)]
    records, joined, holder = [], None, None
    try:
        pool.warm_up(specs)
        for record in pool.run(specs):
            records.append(record)
            if joined is None:
                head = ray.get_runtime_context().get_node_id()
                hold = ray.remote(num_cpus=1)(lambda: time.sleep(120))
                holder = hold.options(scheduling_strategy=NodeAffinitySchedulingStrategy(head, soft=False)).remote()
                joined = add_good_node(cluster)
            elif holder is not None and pool.played_per_node.get(f"node {joined.node_id} ({joined.node_ip_address})"):
                ray.cancel(holder, force=True)
                holder = None
        played = pool.played_per_node
    finally:
        pool.close()
    assert len(records) == 6 and all(r.error is None for r in records)
    assert played.get(f"node {joined.node_id} ({joined.node_ip_address})", 0) > 0


@pytest.mark.slow
def test_without_address_a_cluster_on_this_machine_is_not_joined(cluster, tmp_path, capsys) -> None:
    out = tmp_path / "local.sqlite"
    assert main([*TOURNAMENT, "--workers", "1", "--out", str(out)]) == 0
    err = capsys.readouterr().err
    assert "started a private local Ray instance: 1 node(s), 1 CPU(s) used" in err
    with ResultStore.open(out) as store:
        assert len(store.records()) == 4



@pytest.mark.slow
def test_a_cluster_where_no_node_can_play_is_refused_before_any_match(tmp_path, monkeypatch, capsys) -> None:
    from ray.cluster_utils import Cluster

    hidden = tmp_path / "bare"
    hidden.mkdir()
    (hidden / "sitecustomize.py").write_text(HIDE_PROJECT)
    driver = tmp_path / "driver"
    driver.mkdir()
    monkeypatch.chdir(driver)
    monkeypatch.delenv("RAY_ADDRESS", raising=False)
    bare = Cluster(initialize_head=True, head_node_args={"num_cpus": 1, "env_vars": {"PYTHONPATH": str(hidden)}})
    try:
        out = tmp_path / "none.sqlite"
        assert main([*TOURNAMENT, "--no-ship-code", "--address", bare.address, "--out", str(out)]) == 2
    finally:
        ray.shutdown()
        bare.shutdown()
    err = capsys.readouterr().err
    assert "excluded: cannot import the project (No module named 'experiments')" in err
    assert err.splitlines()[-1].startswith("error: no node of the Ray cluster can play this run (1 checked")
    with ResultStore.open(out) as store:
        assert store.records() == []
