"""Fixtures shared by every test package."""

from __future__ import annotations

import pytest


@pytest.fixture
def team_module(tmp_path, monkeypatch):
    """Write a module ``name`` with ``source`` on a fresh sys.path entry; return its name (for
    teams given as ``module:Attribute`` paths)."""
    monkeypatch.syspath_prepend(str(tmp_path))

    def write(name: str, source: str) -> str:
        (tmp_path / f"{name}.py").write_text(source)
        return name

    return write
