"""Ray itself for the cluster backend (:mod:`experiments.runner.ray_backend`): joining or
starting Ray, the code a job ships, the match task that runs on a node, what the driver keeps
of each node and task, and how a failed task's error is told apart (node gone, worker died).
"""

from __future__ import annotations

import os
from collections.abc import Callable
from dataclasses import dataclass

from experiments.errors import ExperimentError
from experiments.results.record import MatchRecord
from experiments.runner.slots import FileSlot
from experiments.runner.spec import MatchSpec
from experiments.runner.worker import play_spec

SHIP_EXCLUDES = ["__pycache__", "*.pyc", "*.nbi", "*.nbc"]
"""Left out of the shipped packages: caches that belong to this machine."""

ADDRESS_PROBE_SECONDS = 5.0
"""Seconds the Ray address of a cluster to join has to accept a connection before the run
gives up on it with one line (Ray's own client keeps retrying an address that does not answer)."""

class RayUnavailable(ExperimentError):
    """Ray is not installed, the cluster cannot be reached or none of its nodes can play."""


def import_ray():
    """The ``ray`` module, or RayUnavailable saying how to install it."""
    try:
        import ray
    except ImportError:
        raise RayUnavailable("the Ray backend needs Ray: pip install 'soccer-sim[ray]' (or pip install ray)") from None
    return ray


def connect(ray, workers: int | None, address: str | None, ship_code: bool) -> tuple[bool, str]:
    """Join the cluster at ``address`` (else the one ``RAY_ADDRESS`` names), or start a private
    local instance with ``workers`` CPUs, unless Ray is already initialized in this process;
    ship this machine's packages with the job when ``ship_code``. Returns (whether the run has
    a private local instance, one phrase saying which Ray is used); RayUnavailable when Ray
    cannot be started or reached."""
    target = address or os.environ.get("RAY_ADDRESS") or None
    if ray.is_initialized():
        return False, "using the Ray session already initialized in this process"
    if target:
        probe_address(target)
    options: dict = dict(include_dashboard=False, log_to_driver=False, configure_logging=False)
    if ship_code:
        options["runtime_env"] = code_runtime_env(target is None)
    try:
        if target:
            ray.init(address=target, **options)  # an existing cluster: its own resources
        else:
            ray.init(address="local", num_cpus=workers, **options)
    except Exception as exc:  # noqa: BLE001 - Ray raises many kinds for an unreachable cluster
        where = f" at {target}" if target else ""
        raise RayUnavailable(f"cannot start or reach Ray{where}: {type(exc).__name__}: {exc}") from None
    if target:
        return False, (f"joined the cluster at {ray.get_runtime_context().gcs_address}"
                       f"{'' if address else ' (RAY_ADDRESS)'}")
    return True, "started a private local Ray instance"


def probe_address(target: str) -> None:
    """RayUnavailable, within :data:`ADDRESS_PROBE_SECONDS`, when nothing accepts a connection
    at the cluster address ``target`` (``HOST:PORT``, or ``ray://HOST:PORT`` for Ray Client),
    dialled as given (a loopback address stays on loopback). ``auto`` and addresses Ray cannot
    parse are left to Ray, which answers those at once."""
    import socket

    scheme, _, rest = target.rpartition("://")
    host, _, port_text = rest.rpartition(":")
    host = host.strip("[]")
    if not host or not port_text.isdigit():
        return
    try:
        socket.create_connection((host, int(port_text)), timeout=ADDRESS_PROBE_SECONDS).close()
    except socket.timeout:
        reason = f"no answer within {ADDRESS_PROBE_SECONDS:g} s"
    except socket.gaierror as exc:
        reason = f"unknown host ({exc.strerror})"
    except OSError as exc:
        reason = exc.strerror or type(exc).__name__
    else:
        return
    raise RayUnavailable(f"cannot reach the Ray cluster at {target}: {reason.lower()}; start it (ray start --head) "
                         "or give the address of a running one")


@dataclass
class ClusterNode:
    """A node of the cluster as the run sees it."""

    id: str
    ip: str
    slots: int
    state: str = "checking"
    """checking (pre-flight running), ready, or out."""
    busy: int = 0
    failures: int = 0
    """Tasks failed in a row for reasons outside the match."""
    submit: object = None
    """The match task pinned to this node."""

    @property
    def name(self) -> str:
        return f"node {self.id} ({self.ip})"


@dataclass
class MatchTask:
    spec: MatchSpec
    node: ClusterNode
    started: float
    attempt: int
    failed_on: frozenset[str] = frozenset()
    """Nodes this match failed on before (tried last)."""
    token: str = ""
    """Names the task's slot file on its node (:mod:`experiments.runner.slots`)."""


def play_on_node(token: str, spec: MatchSpec, config_hash: str, code_version: str, timeout: float | None,
                 figures: Callable[[], object] | None = None) -> MatchRecord:
    """The match task: :func:`play_spec` with its deciding slot in the file ``token`` names on
    this node, removed when the match returns (left for the driver if the worker dies)."""
    with FileSlot(token) as slot:
        return play_spec(spec, config_hash, code_version, timeout, deciding=slot.values, figures=figures)


def code_runtime_env(local: bool) -> dict:
    """The job's runtime_env that makes Ray workers import the driver's packages: their parent
    directories first on PYTHONPATH for a private local instance (the same files, so the same
    numba cache), the package directories as ``py_modules`` for a cluster."""
    from experiments.runner.fingerprint import package_dirs

    dirs = package_dirs()
    if local:
        roots = list(dict.fromkeys(str(path.parent) for path in dirs.values()))
        existing = [entry for entry in os.environ.get("PYTHONPATH", "").split(os.pathsep) if entry]
        return {"env_vars": {"PYTHONPATH": os.pathsep.join(dict.fromkeys(roots + existing))}}
    return {"py_modules": [str(path) for path in dirs.values()], "excludes": SHIP_EXCLUDES}


def node_gone(exc: BaseException) -> bool:
    """Whether a task failed because its node died or no longer exists."""
    from ray import exceptions

    gone = tuple(getattr(exceptions, name) for name in ("NodeDiedError", "TaskUnschedulableError")
                 if hasattr(exceptions, name))
    return isinstance(exc, gone)


def worker_died(exc: BaseException) -> bool:
    """Whether a task failed because the worker process running it ended (a crash, os._exit)."""
    from ray import exceptions

    return isinstance(exc, exceptions.WorkerCrashedError) or (
        isinstance(exc, exceptions.RayTaskError) and isinstance(exc.cause, exceptions.WorkerCrashedError))
