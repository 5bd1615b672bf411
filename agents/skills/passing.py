"""Passing: candidate receivers, lead passes, the lane check and the choice of the best pass.

For every team-mate who may receive (not the passer, not offside, the goalkeeper only if
asked), a few target points are tried: its position and points in front of it
(:attr:`PassParams.leads`, "lead passes" that let it run onto the ball). For each target the
ball is kicked so that it covers the distance and still arrives at one of ``arrival_speeds``
(the decay model gives the initial speed ``distance * (1 - decay) + arrival_speed``), capped
at what one kick from where the passer stands can give (:func:`kick_for_velocity`). The pass
is **safe** when the receiver controls the ball on that trajectory at least ``min_lead``
cycles before any opponent could (:mod:`agents.skills.lanes`).

Safe passes are scored at the point where the receiver is predicted to take the ball: the
target when it can run there in time and no opponent gets to the ball first, else where it
can first meet the ball. With the weights of :class:`PassParams` the score rewards a point
further forward, closer to the opponents' goal, in open space (distance from the nearest
opponent) and a comfortable lead over the opponents; the best pass is returned.

A team-mate in an offside position is never a receiver; one who touches the ball on its way
is penalised by the referee too, so the team should keep such players out of the chase
(``ball_race(..., eligible=...)``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from agents.skills.ball_kernels import LEAD_CAP, PASS_PARAMS, beyond_line
from soccer_sim.rules.offside import offside_line
from agents.skills.context import SkillContext, ViewArrays
from agents.skills.interception_kernels import Runners
from agents.skills.model import MotionModel, SkillInputError, check_params, check_player, float_array
from agents.skills.pass_search import PASS_PLAN, PassSearch, best_pass_search, pass_receivers
from soccer_sim.kernels import make_record
from soccer_sim.team import TeamView

__all__ = ["LEAD_CAP", "PassParams", "PassPlan", "best_pass", "offside_line", "offside_positions", "pass_candidates"]


@dataclass(frozen=True)
class PassParams:
    """Tunable choices of the passing skill (metres, cycles, m/cycle)."""

    leads: tuple[tuple[float, float], ...] = ((0.0, 0.0), (3.0, 0.0), (6.0, 0.0), (3.0, 3.0), (3.0, -3.0))
    """Offsets from the receiver's position to the points tried (m, team frame)."""
    arrival_speeds: tuple[float, ...] = (0.8, 1.6)
    """Ball speeds tried at the target (m/cycle): slow passes are easy to control, fast ones
    leave opponents less time; each target is tried with each."""
    min_distance: float = 3.0
    """Shorter passes are not considered (the passer could as well dribble)."""
    max_distance: float = 40.0
    """Longer passes are not considered (noise makes them unreliable)."""
    field_margin: float = 2.0
    """Targets are kept this far inside the lines."""
    min_lead: int = 2
    """Cycles by which the receiver must beat every opponent to the ball."""
    opponent_margin: float = 0.2
    """Extra control distance given to opponents (m), for noise."""
    extra_cycles: int = 10
    """Cycles searched beyond the ball's arrival at the target (the receiver may be late)."""
    allow_goalie: bool = False
    """Whether our goalkeeper may receive."""
    weight_forward: float = 1.0
    """Weight of the reception point's progress towards +x (per 20 m, clipped to [-1, 1.5])."""
    weight_goal: float = 0.5
    """Weight of the reception point's closeness to the opponents' goal (1 at the goal, 0 a field length away)."""
    weight_space: float = 0.6
    """Weight of the nearest opponent's distance to the reception point (per 10 m, capped at 1)."""
    weight_lead: float = 0.6
    """Weight of the receiver's lead over the opponents (per 10 cycles, capped at 1)."""

    def __post_init__(self) -> None:
        check_params(self, positive=("min_distance", "max_distance", "field_margin"),
                     non_negative=("opponent_margin", "weight_forward", "weight_goal", "weight_space", "weight_lead"),
                     whole=("min_lead", "extra_cycles"))
        leads = np.asarray(self.leads, dtype=float)
        if leads.ndim != 2 or leads.shape[1] != 2 or len(leads) == 0 or not np.isfinite(leads).all():
            raise SkillInputError(f"PassParams.leads must be a non-empty sequence of (x, y) offsets, "
                                  f"got {self.leads!r}")
        speeds = np.asarray(self.arrival_speeds, dtype=float)
        if speeds.ndim != 1 or len(speeds) == 0 or not (np.isfinite(speeds) & (speeds > 0)).all():
            raise SkillInputError(f"PassParams.arrival_speeds must be positive speeds, got {self.arrival_speeds!r}")
        if self.min_distance > self.max_distance:
            raise SkillInputError("PassParams.min_distance must not exceed max_distance")



@dataclass(frozen=True)
class PassPlan:
    """A chosen pass: ``kick`` is the request to put in ``TeamCommand.kick`` for the passer."""

    receiver: int
    target: np.ndarray
    """(2,) point the ball is sent to (m)."""
    receive_point: np.ndarray
    """(2,) where the receiver is predicted to take the ball (m), the point scored: the target
    when the receiver can be there when the ball arrives and no opponent gets to the ball
    before, else the point of its earliest interception."""
    kick: np.ndarray
    """(2,) kick request (m/cycle)."""
    ball_vel: np.ndarray
    """(2,) the ball's velocity right after the kick."""
    arrival_cycle: int
    """Cycles until the ball reaches the target."""
    receive_cycle: int
    """Cycle at which the receiver controls the ball."""
    opponent_cycle: int
    """Earliest cycle an opponent controls it (UNREACHABLE: none before it leaves the field,
    or none early enough to change the decision: see
    :func:`agents.skills.ball_kernels.deciding_cycles`)."""
    score: float


def offside_positions(model: MotionModel, own_pos: np.ndarray, opp_pos: np.ndarray, ball: np.ndarray) -> np.ndarray:
    """Bool per team-mate: in an offside position (in the opponents' half, ahead of the ball and
    of the second-last opponent). All False when the offside rule is off."""
    n = own_pos.shape[0]
    if not model.offside or opp_pos.shape[0] < 2:
        return np.zeros(n, dtype=bool)
    own_pos, opp_pos = float_array("own_pos", own_pos, (n, 2)), float_array("opp_pos", opp_pos, (-1, 2))
    return beyond_line(own_pos, opp_pos, float(ball[0]))


def pass_candidates(ctx: SkillContext, view: TeamView, passer: int, params: PassParams = PassParams()) -> np.ndarray:
    """Indices of the team-mates the ``passer`` may pass to (not itself, not offside, the
    goalkeeper only when ``params.allow_goalie``)."""
    passer = check_player(passer, ctx.model.players_per_team, "passer")
    return _receivers(ctx, ctx.arrays(view), passer, params)


def _receivers(ctx: SkillContext, arrays: ViewArrays, passer: int, params: PassParams) -> np.ndarray:
    """:func:`pass_candidates` on the view's checked ``arrays``."""
    model = ctx.model
    theirs = arrays.theirs
    return pass_receivers(arrays.ours.pos, theirs.pos, float(arrays.ball[0, 0]),
                          model.offside and theirs.pos.shape[0] >= 2, passer,
                          model.goalie_index if not params.allow_goalie else -1)


def best_pass(ctx: SkillContext, view: TeamView, passer: int, params: PassParams = PassParams(),
              holder: bool = False) -> PassPlan | None:
    """The best safe pass for ``passer`` (who must be able to kick the ball), or None.

    ``holder``: the passer is our goalkeeper holding the ball (kicks at full effectiveness).
    The search is one compiled call (:func:`agents.skills.pass_search.best_pass_search`).
    """
    passer = check_player(passer, ctx.model.players_per_team, "passer")
    arrays = ctx.arrays(view)
    receivers = _receivers(ctx, arrays, passer, params)
    if receivers.size == 0:
        return None
    ours, theirs = arrays.ours, arrays.theirs
    search = ctx.table(("best_pass", params), lambda: pass_search_inputs(ctx, params))
    radius, catch = ctx.opponent_radii(params.opponent_margin)
    found = np.zeros(1, dtype=PASS_PLAN)
    if not best_pass_search(arrays.ball, arrays.ball_vel, receivers, passer, bool(holder), ours.runners,
                            Runners(theirs.pos, theirs.vel, theirs.effort, radius, catch), search, found):
        return None
    plan = dict(zip(_PLAN_FIELDS, found.item(0)))  # by name (a void's fields one by one cost more than the search)
    return PassPlan(receiver=plan["receiver"], target=np.array((plan["target_x"], plan["target_y"])),
                    receive_point=np.array((plan["receive_x"], plan["receive_y"])),
                    kick=np.array((plan["kick_x"], plan["kick_y"])), ball_vel=np.array((plan["ball_vx"], plan["ball_vy"])),
                    arrival_cycle=plan["arrival_cycle"], receive_cycle=plan["receive_cycle"],
                    opponent_cycle=plan["opponent_cycle"], score=plan["score"])


_PLAN_FIELDS = PASS_PLAN.names


def pass_search_inputs(ctx: SkillContext, params: PassParams) -> PassSearch:
    """:func:`best_pass_search`'s inputs that hold for a match and ``params``."""
    model = ctx.model
    record = make_record(
        PASS_PARAMS, x_max=model.half_length - params.field_margin, y_max=model.half_width - params.field_margin,
        min_distance=params.min_distance, max_distance=params.max_distance, decay=model.ball_decay,
        horizon=model.horizon, extra_cycles=params.extra_cycles, min_lead=params.min_lead,
        coast=model.player_coast[-1], kickable=model.kickable_distance, half_length=model.half_length,
        weight_forward=params.weight_forward, weight_goal=params.weight_goal, weight_space=params.weight_space,
        weight_lead=params.weight_lead)
    return PassSearch(leads=np.asarray(params.leads, dtype=np.float64).reshape(-1, 2),
                      speeds=np.asarray(params.arrival_speeds, dtype=np.float64), params=record,
                      kick=model.kick_model, intercept=ctx.intercept_params, tables=model.tables)
