"""Our corner-kick and kick-in routines: who moves where, and how the taker plays the ball.

**Corner kick** (ours). Up to ``corner_runners`` outfield players (those whose set-play
spots are furthest forward, the taker and the short team-mate left out) go to spots in the
opponents' box: the near post, the far post, the penalty spot and the far edge of the goal
area (team frame, "near" being the corner's side). The team-mate nearest the ball comes short
(``short_gap`` metres infield and back from the ball), the others keep the formation's shape
behind. The taker waits ``corner_wait`` cycles for the runners, then crosses: to each box
spot a ball is kicked to arrive there at ``cross_speed``, and the cross whose lane our first
player to take the ball inside their box wins by the most cycles over the opponents is taken
when that lead is at least ``cross_lead``; else, when the short team-mate is free
(:func:`agents.skills.lane_open`), it is played short; else the best-led cross is taken all
the same (a contested cross into the box, as real corners mostly are).

**Kick-in** (ours). The team-mate nearest the ball (not the taker) comes short, ``short_gap``
metres infield and a little forward of the ball. The taker plays the on-ball decision's pass
when it chooses one (to the short player or anyone better placed); otherwise it plays the
ball down the line: ``line_length`` metres forwards, ``line_inside`` metres inside the
touchline, for a forward to run onto.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from agents import skills
from agents.skills.model import check_params
from soccer_sim.team import TeamView


PENALTY_SPOT = 11.0
"""Distance of the penalty spot from the goal line (m; the laws of the game)."""


@dataclass(frozen=True)
class RoutineParams:
    """Tunable choices of our corner and kick-in routines (metres, cycles, m/cycle)."""

    corner_runners: int = 4
    """Outfield players who go into the opponents' box at our corner kicks (at most four spots)."""
    cross_speed: float = 1.2
    """Speed at which a cross arrives at its box spot (m/cycle): slow enough to control."""
    cross_lead: int = 2
    """A cross is preferred to the short corner when our player wins its lane by this many
    cycles (one more than a tie, for the noise of a long kick)."""
    cross_margin: float = 0.2
    """Extra control distance given to the opponents when a cross's lane is judged (m, noise)."""
    corner_wait: int = 30
    """Cycles our corner taker waits before kicking so the runners reach the box (the team's
    patience, half the referee's set-play timeout, caps it: a corner is never left to stall)."""
    short_gap: float = 6.0
    """How far infield of the ball the short team-mate stands at corners and kick-ins (m)."""
    line_length: float = 18.0
    """Length of a kick-in played down the line (m)."""
    line_inside: float = 3.0
    """A kick-in down the line goes this far inside the touchline (m)."""
    line_stop: float = 2.0
    """A kick-in down the line that nobody takes stops at least this far short of the
    opponents' goal line (m): it arrives at its target at ``cross_speed`` and so would roll
    about 20 m further, over the goal line for a goal kick (about two a match between
    built-in teams) whenever the kick-in was taken in the opponents' half."""

    def __post_init__(self) -> None:
        check_params(self, positive=("cross_speed", "short_gap", "line_length"),
                     non_negative=("line_inside", "cross_margin", "line_stop"),
                     whole=("corner_runners", "cross_lead", "corner_wait"))


def box_spots(model: skills.MotionModel, ball_y: float) -> np.ndarray:
    """(4, 2) the spots our runners take at a corner kick from the side of ``ball_y``: near
    post, far post, penalty spot, far edge of the goal area (team frame)."""
    side = 1.0 if ball_y > 0.0 else -1.0
    line = model.half_length
    post = model.goal_half_width
    return np.array([[line - 4.0, side * (post - 3.0)], [line - 5.0, -side * (post - 2.0)],
                     [line - PENALTY_SPOT, 0.0], [line - model.goal_area_length - 2.0, -side * post]])


def short_spot(model: skills.MotionModel, ball: np.ndarray, corner: bool, params: RoutineParams) -> np.ndarray:
    """Where the short team-mate stands: ``short_gap`` infield of the ball, back from a corner
    or a little forward of a kick-in, kept on the field."""
    side = 1.0 if float(ball[1]) > 0.0 else -1.0
    forward = -0.7 * params.short_gap if corner else 0.3 * params.short_gap
    spot = np.array([float(ball[0]) + forward, float(ball[1]) - side * params.short_gap])
    spot[0] = np.clip(spot[0], -model.half_length + 1.0, model.half_length - 1.0)
    return spot


def routine_goals(view: TeamView, model: skills.MotionModel, goals: np.ndarray, outfield: np.ndarray, taker: int,
                  corner: bool, params: RoutineParams) -> tuple[np.ndarray, np.ndarray]:
    """The routine's players and their goal points, ``(rows (k,), points (k, 2))``: the short
    team-mate, and at a corner the box runners (those of ``outfield`` whose ``goals``, on entry
    their formation spots, are furthest forward; the taker is left out). Chosen once per set
    play by the caller (the ball does not move meanwhile)."""
    rows: list[int] = []
    points: list[np.ndarray] = []
    others = outfield[outfield != taker]
    if others.size:
        ball = np.asarray(view.ball, float)
        gaps = np.hypot(*(view.own_pos[others] - ball).T)
        short = int(others[int(np.argmin(gaps))])
        rows.append(short)
        points.append(short_spot(model, ball, corner, params))
        runners = others[others != short]
        count = min(params.corner_runners, runners.size, 4) if corner else 0
        if count:
            runners = runners[np.argsort(-goals[runners, 0], kind="stable")[:count]]
            # Each spot to the free runner nearest it, spot by spot (at most four: cheap).
            free = list(runners)
            for spot in box_spots(model, float(ball[1]))[:count]:
                near = int(np.argmin([np.hypot(*(view.own_pos[r] - spot)) for r in free]))
                rows.append(int(free.pop(near)))
                points.append(spot)
    return np.array(rows, dtype=np.int64), np.array(points, dtype=float).reshape(-1, 2)


def corner_kick(ctx: skills.SkillContext, view: TeamView, taker: int, outfield: np.ndarray,
                params: RoutineParams) -> tuple[str, np.ndarray]:
    """The corner taker's kick: ("cross", kick) into the box or ("short", kick) to the short
    team-mate (see the module docstring)."""
    model = ctx.model
    ball = np.asarray(view.ball, float)
    spots = box_spots(model, float(ball[1]))
    delta = spots - ball
    distance = np.hypot(delta[:, 0], delta[:, 1])
    speed = np.minimum(distance * (1.0 - model.ball_decay) + params.cross_speed, model.ball_speed_max)
    wanted = delta / distance[:, None] * speed[:, None]
    kicks, velocities = skills.kick_for_velocity(model, view.own_pos[taker], ball, view.ball_vel, wanted,
                                                 player_vel=view.own_vel[taker])
    ours, points = skills.teammate_cycles(ctx, view, ball, velocities)
    # Only a team-mate taking the ball inside their box makes a cross (not one it passes on the way).
    ours = np.where(model.in_penalty_area(points, ours=False), ours, skills.UNREACHABLE)
    ours[:, taker] = skills.UNREACHABLE
    if model.goalie_index >= 0:
        ours[:, model.goalie_index] = skills.UNREACHABLE
    theirs, _ = skills.opponent_cycles(ctx, view, ball, velocities, extra_radius=params.cross_margin)
    lead = theirs.astype(float) - ours.min(axis=1)
    best = int(np.argmax(lead))
    if lead[best] >= params.cross_lead:
        return "cross", kicks[best]
    others = outfield[outfield != taker]
    if others.size:
        short = int(others[int(np.argmin(np.hypot(*(view.own_pos[others] - ball).T)))])
        to_mate = view.own_pos[short] - ball
        gap = float(np.hypot(*to_mate))
        if gap > 1.0:
            velocity = to_mate / gap * min(gap * (1.0 - model.ball_decay) + params.cross_speed, model.ball_speed_max)
            kick, real = skills.kick_for_velocity(model, view.own_pos[taker], ball, view.ball_vel, velocity,
                                                  player_vel=view.own_vel[taker])
            if skills.lane_open(ctx, view, ball, real, short, min_lead=2):
                return "short", kick
    return "cross", kicks[best]


def kick_in(ctx: skills.SkillContext, view: TeamView, taker: int, decision: skills.DecisionParams,
            params: RoutineParams) -> np.ndarray:
    """The kick-in taker's kick: the on-ball decision's pass, else down the line."""
    chosen = skills.decide_on_ball(ctx, view, taker, decision)
    if chosen.action == skills.OnBallAction.PASS or chosen.action == skills.OnBallAction.SHOOT:
        return chosen.kick
    return down_the_line(ctx, view, taker, params)


def down_the_line(ctx: skills.SkillContext, view: TeamView, taker: int, params: RoutineParams) -> np.ndarray:
    """The kick of ``taker`` giving the ball :func:`line_velocity`."""
    model = ctx.model
    kick, _ = skills.kick_for_velocity(model, view.own_pos[taker], np.asarray(view.ball, float), view.ball_vel,
                                       line_velocity(model, view.ball, params), player_vel=view.own_vel[taker])
    return kick


def line_velocity(model: skills.MotionModel, ball: np.ndarray, params: RoutineParams) -> np.ndarray:
    """(2,) the ball's velocity (m/cycle) playing it ``line_length`` forwards along the
    touchline, ``line_inside`` inside it (the target kept short of the opponents' goal line),
    slow enough that, untouched, it stops ``line_stop`` short of that line."""
    ball = np.asarray(ball, float)
    side = 1.0 if float(ball[1]) > 0.0 else -1.0
    target = np.array([min(float(ball[0]) + params.line_length, model.half_length - 3.0),
                       side * (model.half_width - params.line_inside)])
    delta = target - ball
    distance = max(float(np.hypot(*delta)), 1e-9)
    speed = min(distance * (1.0 - model.ball_decay) + params.cross_speed, model.ball_speed_max)
    forward = float(delta[0]) / distance  # share of the roll towards the goal line
    if forward > 0.0:
        room = max(model.half_length - params.line_stop - float(ball[0]), 0.0)
        speed = min(speed, room * (1.0 - model.ball_decay) / forward)
    return delta / distance * speed
