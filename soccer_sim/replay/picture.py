"""A still picture of a replay at one cycle (matplotlib), drawn from the recorded data."""

from __future__ import annotations

import os

import numpy as np

from soccer_sim.config import FieldConfig, PhysicsConfig
from soccer_sim.replay.field import GRASS_COLOUR, LINE_COLOUR, field_lines, goal_frames
from soccer_sim.replay.reader import Replay
from soccer_sim.replay.recorder import TEAM_COLOURS, TEAM_KEYS, ReplayError


def default_cycle(replay: Replay) -> int:
    """The cycle of the last goal (a few cycles before it, to show the shot), else the middle."""
    goals = [cycle for cycle, text in replay.events if text.startswith("GOAL")]
    if goals:
        return max(int(replay.cycles[0]), goals[-1] - 5)
    return int(replay.cycles[len(replay.cycles) // 2])


def draw_replay(replay: Replay, path: str | os.PathLike, cycle: int | None = None,
                field: FieldConfig | None = None, trail: int = 30,
                physics: PhysicsConfig | None = None) -> tuple[str, int]:
    """Draw the field at ``cycle``: both teams with shirt numbers, the ball and its last
    ``trail`` positions, each team's role targets and the lines from players to their role's
    target; the title gives the game minute by ``physics``' cycle length (default: the server's
    0.1 s). Returns (the file written, the cycle drawn); ReplayError for a cycle not recorded."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    field = field or FieldConfig()
    cycle = default_cycle(replay) if cycle is None else int(cycle)
    found = np.flatnonzero(replay.cycles == cycle)
    if not len(found):
        raise ReplayError(f"cycle {cycle} is not in the replay (it holds cycles {int(replay.cycles[0])} to "
                          f"{int(replay.cycles[-1])})")
    k = int(found[0])
    fig, ax = plt.subplots(figsize=(10.5, 7.2))
    ax.set_facecolor(np.array(GRASS_COLOUR) / 255.0)
    for line in field_lines(field) + goal_frames(field):
        ax.plot(line[:, 0], line[:, 1], color=np.array(LINE_COLOUR) / 255.0, lw=1.2, zorder=1)
    for team, key in enumerate(TEAM_KEYS):
        colour = np.array(TEAM_COLOURS[team]) / 255.0
        if key in replay.targets and k < len(replay.targets[key]):
            targets = replay.targets[key][k]
            ax.scatter(targets[:, 0], targets[:, 1], s=40, marker="x", color=colour, alpha=0.7, zorder=2)
        if key in replay.lines and k < len(replay.lines[key]):
            for segment in replay.lines[key][k]:
                ax.plot(segment[:, 0], segment[:, 1], color=colour, lw=0.8, alpha=0.8, zorder=2)
        if key in replay.players:
            players = replay.players[key][k]
            ax.scatter(players[:, 0], players[:, 1], s=170, color=colour, edgecolors="black", zorder=3)
            for i, (x, y) in enumerate(players):
                ax.text(x, y, str(i + 1), ha="center", va="center", fontsize=7, color="white", zorder=4)
    past = replay.ball[max(0, k - trail):k + 1]
    ax.plot(past[:, 0], past[:, 1], color="white", alpha=0.6, lw=1.5, zorder=4)
    ax.scatter(*replay.ball[k], s=45, color="white", edgecolors="black", zorder=5)
    score = replay.score[k]
    minute = cycle / (physics or PhysicsConfig()).cycles_per_minute
    ax.set_title(f"cycle {cycle} ({minute:.1f} min): {int(score[0])} - {int(score[1])}  "
                 f"(home red attacks +x; crosses: role targets)")
    hl, hw, m = field.length / 2, field.width / 2, field.margin
    ax.set_xlim(-hl - m, hl + m)
    ax.set_ylim(-hw - m, hw + m)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return os.fspath(path), cycle
