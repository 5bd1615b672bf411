"""Saves: a ball near our goal that we can kick but not hold is sent wide of the goal.

The referee grants a catch only to our goalkeeper, inside our penalty area, with the ball
within the catch length, not from a team-mate's kick and not within the ban after a failed
attempt (:mod:`soccer_sim.rules.goalkeeper`, rcssserver's ``CatchRef``). A goalkeeper that can
kick the ball but not catch it, with an opponent close, parries: it knocks the ball away from
the goal towards the ball's side of the field instead of trying a pass or a clearance that
the opponent may block back into the goal. An outfield player contesting the ball with an
opponent inside our penalty area does the same (a block or deflection).

**Direction.** Towards ``side`` = the sign of the ball's y (the left for y = 0). With the
ball within ``behind_depth`` of our goal line the ball is aimed at a point on our goal line
``wide_gap`` metres beyond the post (and beyond the ball's own y): it crosses the line
outside the goal mouth, a corner kick rather than a goal. Further out it is aimed across and
``forward_share`` forwards (towards the touchline, away from the goal). Kicked as hard as one
kick allows (:func:`agents.skills.kicking.kick_for_velocity`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from agents.skills.context import SkillContext
from agents.skills.goalkeeping import distribute
from agents.skills.kicking import kick_for_velocity
from agents.skills.model import check_params, check_player
from soccer_sim.team import TeamView


@dataclass(frozen=True)
class SaveParams:
    """Tunable choices of the parry (metres, cycles)."""

    pressure_cycles: int = 2
    """The goalkeeper parries (rather than distributes) a ball it cannot catch when an opponent
    can control it within this many cycles."""
    behind_depth: float = 8.0
    """Within this distance of our goal line a parry goes behind, wide of the post (m)."""
    wide_gap: float = 6.0
    """A parry behind crosses our goal line this far beyond the post at least (m)."""
    forward_share: float = 0.3
    """Further out, the parry's forward component per unit of its sideways one."""

    def __post_init__(self) -> None:
        check_params(self, positive=("wide_gap",), non_negative=("behind_depth", "forward_share"),
                     whole=("pressure_cycles",))


def parry_direction(ctx: SkillContext, ball: np.ndarray, params: SaveParams = SaveParams()) -> np.ndarray:
    """(2,) unit direction of a parry of the ball at ``ball`` (team frame; see the module
    docstring): wide of our goal, never across its mouth."""
    model = ctx.model
    bx, by = float(ball[0]), float(ball[1])
    side = 1.0 if by > 0.0 else -1.0
    goal_line = -model.half_length
    if bx - goal_line <= params.behind_depth:
        target_y = side * max(model.goal_half_width + params.wide_gap, abs(by) + params.wide_gap)
        dx, dy = goal_line - bx, target_y - by
        if dx > -0.5:  # on (or behind) the line: straight across, away from the goal
            dx, dy = 0.0, side
    else:
        dx, dy = params.forward_share, side
    norm = math.hypot(dx, dy)
    return np.array([dx / norm, dy / norm])


def parry_kick(ctx: SkillContext, view: TeamView, player: int, params: SaveParams = SaveParams()) -> np.ndarray:
    """The kick request (2,) of ``player`` (who can kick the ball) parrying it wide."""
    model = ctx.model
    player = check_player(player, model.players_per_team, "player")
    ball = np.asarray(view.ball, float)
    wanted = parry_direction(ctx, ball, params) * model.kick_speed_max
    kick, _ = kick_for_velocity(model, view.own_pos[player], ball, view.ball_vel, wanted,
                                player_vel=view.own_vel[player])
    return kick


def goalkeeper_kick(ctx: SkillContext, view: TeamView, goalie: int, pressure: int,
                    params: SaveParams = SaveParams()) -> np.ndarray:
    """The kick of our goalkeeper on a ball it may kick but not catch: a parry wide when an
    opponent can control the ball within ``pressure_cycles`` (``pressure``: the cycles until
    the first opponent does, e.g. ``ball_race(...).theirs.first_cycle``), else a pass or a
    clearance (:func:`agents.skills.goalkeeping.distribute`)."""
    if pressure <= params.pressure_cycles:
        return parry_kick(ctx, view, goalie, params)
    return distribute(ctx, view, goalie).kick
