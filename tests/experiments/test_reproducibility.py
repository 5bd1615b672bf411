"""The pinned versions behind README's figures: constraints.txt and the code that writes it."""

from __future__ import annotations

import tomllib
from pathlib import Path

from packaging.requirements import Requirement

from experiments.reproducibility import EXTRAS, canonical, constraints_text, dependency_closure

ROOT = Path(__file__).resolve().parents[2]


def project_requirements() -> set[str]:
    """Canonical names of the project's direct requirements, the extras' included."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    texts = list(project["dependencies"])
    for extra in EXTRAS:
        texts += project["optional-dependencies"][extra]
    return {canonical(Requirement(text).name) for text in texts
            if Requirement(text).marker is None or Requirement(text).marker.evaluate()}


def pinned(text: str) -> dict[str, str]:
    lines = [line for line in text.splitlines() if line and not line.startswith("#")]
    pairs = [line.split("==") for line in lines]
    assert all(len(pair) == 2 and pair[1] for pair in pairs), lines
    return {canonical(name): version for name, version in pairs}


def test_the_committed_constraints_pin_every_direct_requirement_to_one_version():
    pins = pinned((ROOT / "constraints.txt").read_text())
    assert project_requirements() <= set(pins)
    assert "soccer-sim" not in pins


def test_the_closure_is_the_installed_versions_of_what_the_project_needs_and_nothing_else():
    from importlib import metadata

    closure = dependency_closure()
    assert project_requirements() <= set(closure)
    assert closure["numpy"] == metadata.version("numpy")
    # numba needs llvmlite: requirements of requirements are followed.
    assert "llvmlite" in closure
    # Installed packages nobody in the closure requires are left out (pip itself is always installed).
    assert "pip" not in closure and "soccer-sim" not in closure
    assert pinned(constraints_text(closure)) == closure
