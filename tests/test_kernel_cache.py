"""numba's cache kept in step with what a kernel takes from other files (:mod:`kernel_cache`):
a change to a called kernel's module, or to the constants it reads, recompiles the caller,
while a change to an unrelated file keeps its cache; the project's kernels get that stamp."""

from __future__ import annotations

import json
from pathlib import Path

import kernel_cache
from tests.fresh_python import run_python

ROOT = Path(__file__).resolve().parents[1]

CALLEE = """
from numba import njit
STEP = {step}


@njit(cache=True)
def g(x):
    return x + STEP
"""
CALLER = """
from numba import njit
from .b import g


@njit(cache=True)
def f(x):
    return g(x) * 10
"""
SCRIPT = """
import json
from pathlib import Path
import kernel_cache
kernel_cache.install(Path.cwd(), ("kpkg",))
from kpkg import a
print(json.dumps([a.f(1), len(a.f.stats.cache_hits)]))
"""


def _play(tmp_path: Path, cache: Path | None) -> list[int]:
    """f(1) in a fresh Python (numba's cache beside the sources, or in ``cache``), and whether
    it came from the cache."""
    return json.loads(run_python(SCRIPT, tmp_path, cache).stdout)


def _package(tmp_path: Path) -> Path:
    package = tmp_path / "kpkg"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "a.py").write_text(CALLER)
    (package / "b.py").write_text(CALLEE.format(step=1))
    (package / "c.py").write_text("VALUE = 1\n")
    return package


def test_a_change_in_a_called_module_recompiles_the_caller(tmp_path: Path) -> None:
    package = _package(tmp_path)
    for cache in (None, tmp_path / "cache"):  # beside the sources, and in NUMBA_CACHE_DIR
        (package / "b.py").write_text(CALLEE.format(step=1))
        assert _play(tmp_path, cache)[0] == 20
        assert _play(tmp_path, cache) == [20, 1]  # loaded from the cache
        (package / "b.py").write_text(CALLEE.format(step=2))
        assert _play(tmp_path, cache) == [30, 0]  # numba alone would load 20 again
        (package / "c.py").write_text("VALUE = 2\n")  # imported by nobody
        assert _play(tmp_path, cache) == [30, 1]


def test_the_projects_kernels_depend_on_the_kernels_they_call() -> None:
    from agents.assignment.scram import mmdr_points
    from agents.teams.pipeline_kernels import derive_worlds

    assert type(mmdr_points._cache._impl._locator).__name__.startswith("Project")
    files = set(kernel_cache.dependencies(ROOT / "agents" / "teams" / "pipeline_kernels.py"))
    assert {"agents/teams/shape_kernels.py", "agents/skills/interception_kernels.py",
            "formations/interpolation_kernels.py", "agents/roles/conflicts.py", "agents/teams/speaking.py"} <= files
    assert "agents/assignment/deletion.py" in kernel_cache.dependencies(ROOT / "agents" / "assignment" / "scram.py")
    assert "soccer_sim/match.py" not in files  # not imported by any kernel module on the way
    assert derive_worlds._cache._impl._locator.get_source_stamp() == kernel_cache.dependency_stamp(
        ROOT / "agents" / "teams" / "pipeline_kernels.py")
