"""agent2d text formation files written by the tests (not a test module).

Coordinates here are the soccer server's (y to the right of a player facing
the opponent goal), as agent2d writes them.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

ROLES = [
    (1, "Goalie", 0),
    (2, "CenterBack", -1),
    (3, "CenterBack", 2),
    (4, "SideBack", -1),
    (5, "SideBack", 4),
    (6, "DefensiveHalf", 0),
    (7, "OffensiveHalf", -1),
    (8, "OffensiveHalf", 7),
    (9, "SideForward", -1),
    (10, "SideForward", 9),
    (11, "CenterForward", 0),
]
"""number, name, symmetry: the 4-1-2-3 roles agent2d's formations use."""

MIRROR = [0, 2, 1, 4, 3, 5, 7, 6, 9, 8, 10]
"""Row of each role's mirror (partners swapped)."""

BASE = np.array(
    [(-50, 0), (-20, -7), (-20, 7), (-16, -17), (-16, 17), (-30, 0), (-6, -11), (-6, 11), (9, -24), (9, 24), (10, 0)],
    dtype=float,
)
"""Positions at ball (0, 0), server frame."""

HALF_BALLS = [(0.0, 0.0), (54.5, -36.0), (30.37, -15.92), (-19.61, -5.46), (-54.5, 0.0), (42.76, 0.0), (-4.28, -16.81)]
"""Ball positions of one half (y <= 0); the others are their mirrors."""


def positions_for(ball: tuple[float, float]) -> np.ndarray:
    """(11, 2) positions at *ball*, two decimals, mirror-consistent and not linear in the ball."""
    bx, by = ball
    shift = np.array([0.55 * bx + 0.004 * by * by - 0.002 * bx * abs(bx), 0.35 * by])
    return np.round(BASE + np.where(np.arange(11)[:, None] == 0, 0.0, shift), 2)


def mirrored_samples() -> list[tuple[tuple[float, float], np.ndarray]]:
    """Samples over the whole field: each half sample and its mirror (roles swapped, y negated)."""
    samples = []
    for ball in HALF_BALLS:
        positions = positions_for(ball)
        samples.append((ball, positions))
        if ball[1] != 0.0:
            mirrored = positions[MIRROR] * (1.0, -1.0)
            samples.append(((ball[0], -ball[1]), mirrored))
    return samples


def _number(value: float) -> str:
    return f"{value:g}"


def dt_v2_text(samples=None, roles=ROLES, *, version: int = 2) -> str:
    """A ``Formation DelaunayTriangulation 2`` file as agent2d's tools write it (with a comment)."""
    samples = mirrored_samples() if samples is None else samples
    lines = [f"Formation DelaunayTriangulation {version}", "# written by the tests", "Begin Roles"]
    lines += [f"{n} {name} {pair}" for n, name, pair in roles]
    lines += ["End Roles", f"Begin Samples 2 {len(samples)}"]
    for k, (ball, positions) in enumerate(samples):
        lines += [f"----- {k} -----", f"Ball {_number(ball[0])} {_number(ball[1])}"]
        lines += [f"{n} {_number(x)} {_number(y)}" for n, (x, y) in enumerate(positions, start=1)]
    lines += ["End Samples", "End"]
    return "\n".join(lines) + "\n"


def dt_v1_text(samples=None) -> str:
    """The older layout: one role line, one line of 24 numbers per sample, then End."""
    samples = mirrored_samples() if samples is None else samples
    lines = ["Formation DelaunayTriangulation", " ".join(f"{name} {pair}" for _, name, pair in ROLES)]
    for ball, positions in samples:
        lines.append(" ".join(_number(v) for v in (*ball, *positions.ravel())))
    lines.append("End")
    return "\n".join(lines) + "\n"


STATIC_POSITIONS = [(-49, 0), (-30, 10), (-30, -10), (-20, 0), (-20, -20), (-20, 20), (-10, -10), (0, -20), (-10, 10), (0, 1), (0, 20)]


def static_text(names=None) -> str:
    """A ``Formation Static`` file like agent2d's before-kick-off.conf (tabs and comments included)."""
    names = names or ["Goalie"] + ["Sample"] * 10
    lines = ["Formation Static", "# -----------------", "# move positions when playmode is BeforeKickOff or AfterGoal."]
    lines += [f"{n} {name} \t {x:.1f}\t{y:.1f}" for n, (name, (x, y)) in enumerate(zip(names, STATIC_POSITIONS), 1)]
    lines.append("# -----------------")
    return "\n".join(lines) + "\n"


def write_directory(root: Path, files: dict[str, str]) -> Path:
    """Write a formations-dt directory of *files* (name -> text) and return it."""
    root.mkdir(parents=True, exist_ok=True)
    for name, text in files.items():
        (root / name).write_text(text, encoding="utf-8")
    return root


# ----------------------------------------------------------------- other layouts helios-base uses
LINEUP = [
    (1, "Keeper", -48.5, 0.0),
    (2, "CenterBack", -31.0, -7.5),
    (3, "CenterBack", -31.0, 7.5),
    (4, "SideBack", -27.5, -19.0),
    (5, "SideBack", -27.5, 19.0),
    (6, "DefensiveHalf", -22.0, 0.5),
    (7, "OffensiveHalf", -14.0, -11.5),
    (8, "OffensiveHalf", -14.0, 11.5),
    (9, "Winger", -4.0, -27.0),
    (10, "Winger", -4.0, 27.0),
    (11, "Striker", -9.5, 0.0),
]
"""number, name, x, y of a fixed line-up (server frame)."""

LINEUP_KINDS = ["goalkeeper"] + ["defender"] * 4 + ["midfielder"] * 3 + ["forward"] * 3
"""Kinds of :data:`LINEUP` from its role names."""


def lineup_positions() -> np.ndarray:
    """(11, 2) positions of :data:`LINEUP`, server frame."""
    return np.array([(x, y) for _, _, x, y in LINEUP], dtype=float)


def static_v0_text(*, end: bool = False) -> str:
    """A ``Formation Static 0`` file as librcsc's editor saves one: player lines, then an empty
    ``Begin Samples 2 0`` / ``End Samples`` block (and ``End`` if *end*)."""
    lines = ["Formation Static 0"] + [f"{n} {name} {_number(x)} {_number(y)}" for n, name, x, y in LINEUP]
    lines += ["Begin Samples 2 0", "End Samples"] + (["End"] if end else [])
    return "\n".join(lines) + "\n"


def static_json_document(role_type: str = "Unknown", ball: tuple[float, float] = (0.0, 0.0)) -> dict:
    """helios-base's JSON static layout: every role of type *role_type*, side C, pair 0, one sample."""
    sample = {"index": 0, "ball": {"x": ball[0], "y": ball[1]}}
    sample.update({str(n): {"x": x, "y": y} for n, _, x, y in LINEUP})
    roles = [{"number": n, "name": name, "type": role_type, "side": "C", "pair": 0} for n, name, _, _ in LINEUP]
    return {"version": "", "method": "Static", "role": roles, "data": [sample]}


CSV_TYPES = ["G", "DF", "DF", "DF", "DF", "MF", "MF", "MF", "FW", "FW", "FW"]
"""RoleType row of :func:`csv_dt_text` (G, DF, MF, FW)."""


def csv_dt_text(samples=None, types=CSV_TYPES) -> str:
    """helios-base's comma-separated ``Method,DelaunayTriangulation`` layout, with a time-stamp comment."""
    samples = mirrored_samples() if samples is None else samples
    numbers = ",".join(str(n) for n, _, _ in ROLES)
    lines = [
        "# 20240101-120000",
        "Method,DelaunayTriangulation",
        "RoleNumber," + numbers,
        "RoleName," + ",".join(name for _, name, _ in ROLES),
        "RoleType," + ",".join(types),
        "SymmetryNumber," + ",".join(str(pair) for _, _, pair in ROLES),
        "Marker," + ",".join("0" for _ in ROLES),
        "SetplayMarker," + ",".join("0" for _ in ROLES),
        "SampleData",
        f"Size,{len(samples)}",
        "idx,ballX,ballY," + ",".join(f"{n}X,{n}Y" for n, _, _ in ROLES),
    ]
    for k, (ball, positions) in enumerate(samples):
        lines.append(",".join(_number(v) for v in (k, *ball, *positions.ravel())))
    return "\n".join(lines) + "\n"


def csv_static_text() -> str:
    """helios-base's comma-separated ``Method,Static`` layout of :data:`LINEUP`."""
    lines = [
        "Method,Static",
        "RoleNumber," + ",".join(str(n) for n, _, _, _ in LINEUP),
        "RoleName," + ",".join(name for _, name, _, _ in LINEUP),
        "#PositionIdx," + ",".join(f"{n}X,{n}Y" for n, _, _, _ in LINEUP),
        "Position," + ",".join(_number(v) for v in lineup_positions().ravel()),
    ]
    return "\n".join(lines) + "\n"
