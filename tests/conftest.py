"""Fixtures shared by every test package."""

from __future__ import annotations

import io
import os
from pathlib import Path

import pytest


MAX_TEST_WORKERS = 8
"""At most this many test processes with ``-n auto`` (each imports numpy, numba and pymunk:
a many-core machine would otherwise start one per core)."""


def pytest_xdist_auto_num_workers(config: pytest.Config) -> int:
    """``-n auto``: one test process per core this process may use (its CPU affinity, and a
    container's CPU quota where cgroup v2 sets one), at most :data:`MAX_TEST_WORKERS`."""
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    try:
        quota, period = Path("/sys/fs/cgroup/cpu.max").read_text().split()
        if quota != "max":
            cores = min(cores, max(1, int(int(quota) / int(period))))
    except (OSError, ValueError):
        pass
    return max(1, min(cores, MAX_TEST_WORKERS))


def pytest_sessionstart(session: pytest.Session) -> None:
    """Fill a cold numba cache with every kernel of the built-in teams' matches (full and
    partial observation) on every core before the first test, as ``soccer-sim`` does before a
    tournament: on a fresh clone the kernels are then compiled side by side rather than one at
    a time inside whichever tests call them first. It only saves time: no test needs it, and a
    kernel it misses is compiled on first use as always."""
    from experiments.kernel_manifest import KERNELS
    from experiments.warmup import Kernel, ensure_cached

    ensure_cached([Kernel(*entry) for entry in KERNELS], stream=io.StringIO())


@pytest.fixture
def team_module(tmp_path, monkeypatch):
    """Write a module ``name`` with ``source`` on a fresh sys.path entry; return its name (for
    teams given as ``module:Attribute`` paths)."""
    monkeypatch.syspath_prepend(str(tmp_path))

    def write(name: str, source: str) -> str:
        (tmp_path / f"{name}.py").write_text(source)
        return name

    return write
