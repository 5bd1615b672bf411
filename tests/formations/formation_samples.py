"""Formations and documents shared by the formation tests (not a test module)."""

from __future__ import annotations

from typing import Any

import numpy as np

from formations import Role


def eleven_roles() -> list[Role]:
    """Eleven roles with three partner pairs and central roles."""
    roles = [Role(1, "keeper", "goalkeeper")]
    roles += [Role(2, "right back", "defender", 3), Role(3, "left back", "defender", 2)]
    roles += [Role(4, "centre back", "defender"), Role(5, "sweeper", "defender")]
    roles += [
        Role(6, "right mid", "midfielder", 8),
        Role(7, "holding mid", "midfielder"),
        Role(8, "left mid", "midfielder", 6),
    ]
    roles += [
        Role(9, "striker", "forward"),
        Role(10, "right forward", "forward", 11),
        Role(11, "left forward", "forward", 10),
    ]
    return roles


def scattered_balls(rng: np.random.Generator, count: int) -> np.ndarray:
    """Random ball positions in the field, at least 2 m apart, plus the four corners."""
    balls = [(-52.5, -34.0), (-52.5, 34.0), (52.5, -34.0), (52.5, 34.0)]
    while len(balls) < count:
        candidate = (rng.uniform(-52.5, 52.5), rng.uniform(-34.0, 34.0))
        if min(np.hypot(candidate[0] - x, candidate[1] - y) for x, y in balls) > 2.0:
            balls.append(candidate)
    return np.array(balls)


def small_document() -> dict[str, Any]:
    """A valid formation in our layout: three roles, four samples."""
    return {
        "format": "soccer-sim-formation",
        "version": 1,
        "name": "small",
        "description": "for tests",
        "roles": [
            {"number": 1, "name": "keeper", "kind": "goalkeeper"},
            {"number": 2, "name": "right", "kind": "defender", "partner": 3},
            {"number": 3, "name": "left", "kind": "defender", "partner": 2},
        ],
        "samples": [
            {"ball": [-30.0, 0.0], "positions": {"1": [-50.0, 0.0], "2": [-40.0, -10.0], "3": [-40.0, 10.0]}},
            {"ball": [30.0, 0.0], "positions": {"1": [-48.0, 0.0], "2": [0.0, -15.0], "3": [0.0, 15.0]}},
            {"ball": [0.0, 20.0], "positions": {"1": [-49.0, 1.0], "2": [-20.0, -5.0], "3": [-20.0, 25.0]}},
            {"ball": [0.0, -20.0], "positions": {"1": [-49.0, -1.0], "2": [-20.0, -25.0], "3": [-20.0, 5.0]}},
        ],
    }
