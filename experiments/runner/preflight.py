"""The pre-flight of a Ray node: can it play the run's matches exactly as the driver would?

Before a node gets its first match, one task pinned to it (:func:`check_node`) imports the
project, compares the node's code version (:mod:`experiments.runner.fingerprint`), the
configuration hash of the run and the versions of the libraries that shape play with the
driver's, loads the run's teams, and only then compiles their numba kernels into the node's
cache (so no match clock includes a compile). A node that fails is left out of the run and
named in one line.
"""

from __future__ import annotations

import re
import time
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # annotations only
    from soccer_sim import MatchConfig
    from soccer_sim.scenarios import Scenario

PLAY_LIBRARIES = ("numpy", "scipy", "numba", "pymunk", "lap")
"""Libraries whose version can change a match's result: a node must have the driver's."""

PREFLIGHT_TIMEOUT = 600.0
"""Seconds a node's pre-flight may take (setting up the shipped code and a cold compile of the
kernels included) before the node is left out."""


@dataclass(frozen=True)
class NodeCheck:
    """What a node's pre-flight found; ``problem`` is None when the node may play."""

    code_version: str
    config_hash: str
    problem: str | None = None
    seconds: float = 0.0


@dataclass(frozen=True)
class Expected:
    """What every node must match: the driver's code version, configuration hash and library
    versions, and what the run plays (for the configuration and the kernels)."""

    code_version: str
    config_hash: str
    cycles: int | None
    teams: tuple[str, ...]
    libraries: tuple[tuple[str, str | None], ...]
    configuration: MatchConfig | None = None
    """The run's whole configuration when its specs give one (else the one of ``cycles``)."""
    scenario: Scenario | None = None

    @classmethod
    def of_driver(cls, code_version: str, config_hash: str, cycles: int | None, teams: tuple[str, ...],
                  configuration: MatchConfig | None = None, scenario: Scenario | None = None) -> Expected:
        return cls(code_version, config_hash, cycles, teams, library_versions(), configuration, scenario)

    def config(self) -> MatchConfig:
        """The configuration this node computes for the run."""
        from experiments.runner.spec import config_for

        return self.configuration if self.configuration is not None else config_for(self.cycles)


def library_versions() -> tuple[tuple[str, str | None], ...]:
    """(name, installed version or None) of each of :data:`PLAY_LIBRARIES` in this process."""
    from importlib import metadata

    versions = []
    for name in PLAY_LIBRARIES:
        try:
            versions.append((name, metadata.version(name)))
        except metadata.PackageNotFoundError:
            versions.append((name, None))
    return tuple(versions)


def check_node(expected: Expected) -> NodeCheck:
    """Run on the node: compare it with ``expected``, then warm the kernels. Never raises for a
    difference found (it is the returned ``problem``); an import that fails raises, and the
    driver turns the error into the reason (:func:`failure_reason`)."""
    from experiments.runner.fingerprint import code_version
    from experiments.runner.spec import config_hash

    start = time.perf_counter()
    version, digest = code_version(), config_hash(expected.config(), expected.scenario)

    def result(problem: str | None) -> NodeCheck:
        return NodeCheck(version, digest, problem, time.perf_counter() - start)

    if version != expected.code_version:
        return result(f"runs different code (version {version} != driver's {expected.code_version})")
    if digest != expected.config_hash:
        return result(f"has a different match configuration (hash {digest} != driver's {expected.config_hash})")
    for (name, mine), (_, theirs) in zip(library_versions(), expected.libraries):
        if mine != theirs:
            return result(f"has {name} {mine or 'missing'} (driver: {theirs or 'missing'})")
    from experiments.runner.worker import make_team

    for team in expected.teams:  # a team module installed on the driver only fails here, not per match
        try:
            make_team(team)
        except Exception as exc:  # noqa: BLE001 - whatever stops the team from loading on this node
            return result(f"cannot load team {team!r} ({type(exc).__name__}: {exc})")
    import io

    from experiments.warmup import warm_kernels

    # One process: helper processes spawned from inside a Ray worker would re-run its main module.
    warm_kernels(expected.teams, processes=1, stream=io.StringIO(), observation=expected.config().observation.mode)
    return result(None)


def failure_reason(exc: BaseException) -> str:
    """One line saying why a task failed on a node: the import that failed (a node without the
    project) or the last line of the error."""
    text = str(exc)
    missing = re.findall(r"(?:ModuleNotFoundError|ImportError): ([^\n]+)", text)
    if missing:
        return f"cannot import the project ({missing[-1].strip()})"
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    last = lines[-1] if lines else type(exc).__name__
    last = re.sub(r"\x1b\[[0-9;]*m", "", last)
    return f"{type(exc).__name__}: {last}"[:300]
