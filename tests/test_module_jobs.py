"""Modules are split by job: every module of the project opens with a docstring that names
its job (what it owns), so a newcomer finds where a thing is decided by reading first lines.

A module's length is no rule of its own: one job may need a long module (an algorithm's
compiled loops read best in one file), and a short module that does two jobs is split.
What keeps the packages apart is ``tests/test_import_graph.py``."""

from __future__ import annotations

import ast
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PACKAGES = ("soccer_sim", "agents", "formations", "experiments", "kernel_cache", "rcss_bridge")
SHORTEST_JOB = 20
"""Characters: a first line shorter than this cannot say what a module owns."""


def modules_without_a_job(root: Path) -> list[str]:
    """Modules of the packages whose docstring is missing or whose first line is too short to
    name a job (package ``__init__`` files included: a package has a job too)."""
    missing = []
    for package in PACKAGES:
        for path in sorted((root / package).rglob("*.py")):
            docstring = ast.get_docstring(ast.parse(path.read_text())) or ""
            first_line = docstring.strip().splitlines()[0] if docstring.strip() else ""
            if len(first_line) < SHORTEST_JOB:
                missing.append(path.relative_to(root).as_posix())
    return missing


def test_every_module_names_its_job():
    assert modules_without_a_job(ROOT) == []


def test_a_module_without_a_docstring_is_found(tmp_path):
    (tmp_path / "soccer_sim").mkdir()
    (tmp_path / "soccer_sim" / "named.py").write_text('"""The match loop: teams decide, physics steps."""\n')
    (tmp_path / "soccer_sim" / "unnamed.py").write_text("x = 1\n")
    (tmp_path / "soccer_sim" / "terse.py").write_text('"""Helpers."""\n')
    assert modules_without_a_job(tmp_path) == ["soccer_sim/terse.py", "soccer_sim/unnamed.py"]
