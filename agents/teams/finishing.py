"""Finishing under pressure: a ball near the opponents' goal that an opponent is about to win
(or is kicking too) is shot rather than dribbled or cleared (team frame: we attack +x).

Near the goal, the on-ball decision dribbles or clears when no shot clears its threshold. With
a defender on the ball as well, both kicks add up and the defender's (wide of its post and
behind: :mod:`agents.skills.saving`) then decides where the ball goes; a dribble is lost and a
clearance meets the defender's mirror image. A real forward closed down at the edge of the box
shoots at once: the ball goes in, the goalkeeper must save, or a block sends it behind for a
corner. :func:`finishing_shot` is that choice: the best aim of
:func:`agents.skills.best_shot` at full power, whatever its score.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from agents import skills
from agents.skills.model import check_params
from soccer_sim.team import TeamView


def goal_distance(half_length: float, point: np.ndarray) -> float:
    """Distance (m) from ``point`` (team frame) to the opponents' goal centre (half_length, 0)."""
    return float(np.hypot(half_length - float(point[0]), float(point[1])))


@dataclass(frozen=True)
class FinishParams:
    """When a pressed player near the opponents' goal shoots (metres, cycles)."""

    shot_range: float = 25.0
    """Within this distance of the opponents' goal centre (m) a pressed or contested ball is
    shot: about the penalty area's depth plus a few metres, where real forwards still shoot and
    about as far as a full-power shot keeps enough pace to beat a goalkeeper's reach (0: never)."""
    pressure_cycles: int = 3
    """An opponent controlling the ball within this many cycles counts as pressing (the
    decision's own pressure horizon, shorter than the open-lane shot's): the dribble would be
    lost before it gets closer."""

    def __post_init__(self) -> None:
        check_params(self, non_negative=("shot_range",), whole=("pressure_cycles",))


FINISH = FinishParams()
"""The built-in team's finishing choice."""


def finishing_shot(ctx: skills.SkillContext, view: TeamView, kicker: int, decision: skills.BallDecision,
                   contested: bool, shot_params: skills.ShotParams,
                   params: FinishParams = FINISH) -> np.ndarray | None:
    """The kick of ``kicker`` (an outfield player who can kick the ball) shooting because it is
    pressed near the opponents' goal, or None when it should do what ``decision`` says: the
    decision is to dribble or clear (a shot or a pass stands), and the ball is within
    ``shot_range`` of the goal centre with an opponent on it (``contested``) or controlling
    it within ``pressure_cycles`` (``decision.pressure``)."""
    if params.shot_range <= 0.0 or decision.action not in (skills.OnBallAction.DRIBBLE, skills.OnBallAction.CLEAR):
        return None
    if not contested and decision.pressure > params.pressure_cycles:
        return None
    if goal_distance(ctx.model.half_length, view.ball) > params.shot_range:
        return None
    plan = skills.best_shot(ctx, view, kicker, shot_params, pressure=int(decision.pressure))
    return None if plan is None else plan.kick
