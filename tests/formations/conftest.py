"""Shared fixtures of the formation tests."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Callable

import numpy as np
import pytest

from tests.formations.formation_samples import eleven_roles, scattered_balls
from formations import Formation


@pytest.fixture(scope="session")
def random_formation() -> Formation:
    """An irregular formation: random samples and random positions."""
    rng = np.random.default_rng(7)
    balls = scattered_balls(rng, 40)
    positions = rng.uniform(-50.0, 50.0, (len(balls), 11, 2)) * (1.0, 0.6)
    return Formation(eleven_roles(), balls, positions, name="random")


@pytest.fixture
def write_json(tmp_path: Path) -> Callable[[str, Any], Path]:
    """Write a JSON document (or raw text) to a file in tmp_path and return its path."""

    def write(name: str, document: Any) -> Path:
        path = tmp_path / name
        path.write_text(document if isinstance(document, str) else json.dumps(document), encoding="utf-8")
        return path

    return write
