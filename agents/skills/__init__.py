"""Soccer skills for the built-in teams: interception, movement, kicks, passing, shooting,
dribbling, clearing, goalkeeping and the on-ball decision.

Everything works in the team-relative frame of :class:`soccer_sim.TeamView` (we attack +x,
our goal line at ``x = -half_length``), in metres and cycles, and reads every physical number
from the :class:`~soccer_sim.config.MatchConfig` through one :class:`MotionModel`. A team makes
one :class:`SkillContext` per match in ``Team.reset`` (the model, tables made once, and the
view's arrays checked once) and hands it to every skill that reads a view::

    from agents import skills

    ctx = skills.SkillContext.for_match(config, side_info)  # horizon=60 cycles by default
    model = ctx.model
    race = skills.ball_race(ctx, view, eligible=~offside)    # who gets to the ball, when, where
    race.ours.first, race.ours.first_cycle, race.ours.points[race.ours.first]
    race.we_win, race.lead

    skills.paced_dashes(ctx, view, targets, urgent=chasers,   # arrive and stop, all players,
                        out=command.dash)                    # sprinting only when it matters

    decision = skills.decide_on_ball(ctx, view, player)      # shoot / pass / dribble / clear
    command.kick[player] = decision.kick
    if decision.dash is not None:
        command.dash[player] = decision.dash

    keeper = skills.guard_position(model, view.ball)         # goalkeeper's guard point (x, y)
    command.catch = skills.should_catch(ctx, view, teammate_kicked_last=back_pass)
    skills.distribute(ctx, view).kick                        # holding: pass or clear

Skills that read a view take the :class:`SkillContext`; those on plain points and vectors
(kicks, dashes, the guard point, aim points, offside positions) take the :class:`MotionModel`.

The API, by module:

* :mod:`~agents.skills.model`: :class:`MotionModel` (reach table, ball rollout, sustainable
  speed, field geometry), :class:`SkillInputError`.
* :mod:`~agents.skills.context`: :class:`SkillContext`, :class:`Players` (one team's players,
  checked), :class:`ViewArrays`.
* :mod:`~agents.skills.interception`: :func:`intercept` (one team, one ball),
  :func:`intercept_many` (many ball trajectories), :func:`ball_race` (both teams),
  :data:`UNREACHABLE`.
* :mod:`~agents.skills.movement`: :func:`dash_to_points`, :func:`speed_caps`,
  :func:`paced_dashes` (for a team every cycle, under the stamina policy of
  :mod:`~agents.skills.pacing`, :class:`PacingParams`).
* :mod:`~agents.skills.kicking`: :func:`kickable`, :func:`kick_effectiveness`,
  :func:`kick_for_velocity`.
* :mod:`~agents.skills.lanes`: :func:`opponent_cycles`, :func:`teammate_cycles`,
  :func:`lane_open` (is a pass lane safe?).
* :mod:`~agents.skills.passing`: :func:`best_pass`, :func:`pass_candidates`,
  :func:`offside_positions`, :class:`PassParams`, :class:`PassPlan`.
* :mod:`~agents.skills.shooting`: :func:`best_shot`, :func:`aim_points`,
  :class:`ShotParams`, :class:`ShotPlan`.
* :mod:`~agents.skills.dribbling`: :func:`dribble`, :func:`dribble_directions`,
  :class:`DribbleParams`, :class:`DribblePlan`.
* :mod:`~agents.skills.clearing`: :func:`best_clearance`, :func:`goal_kick_clearance`,
  :class:`ClearParams`, :class:`ClearPlan`.
* :mod:`~agents.skills.goalkeeping`: :func:`guard_position`, :func:`should_catch`,
  :func:`comes_out`, :func:`distribute`, :class:`GoalieParams`.
* :mod:`~agents.skills.crossing`: :func:`best_cross`, :func:`in_crossing_zone`,
  :class:`CrossParams`, :class:`CrossPlan`.
* :mod:`~agents.skills.saving`: :func:`parry_kick`, :func:`parry_direction`,
  :func:`goalkeeper_kick`, :class:`SaveParams`.
* :mod:`~agents.skills.decision`: :func:`decide_on_ball` (the one place the player on the
  ball decides), :class:`DecisionParams` with :class:`FinishParams`, :class:`CarryParams` and
  :class:`SafetyParams`, :class:`BallDecision`, :class:`OnBallAction`.

The compiled kernels live in three modules: :mod:`~agents.skills.interception_kernels`,
:mod:`~agents.skills.ball_kernels` (kicks, lanes, passes) and
:mod:`~agents.skills.player_kernels` (dashes, the dribbling fan, the guard point).

Conventions: positions (n, 2) and velocities in the team frame; ``effort`` (n,) from the
view (missing: 1); opponents are predicted at full effort, reacting one cycle after our kicks;
a player's "control distance" is the kickable distance (the catch length for a goalkeeper in
its own penalty area); cycles count from the current view (0: now); :data:`UNREACHABLE`
marks a ball a player cannot get before it leaves the field or the searched cycles. Tunable
thresholds live in the ``*Params`` dataclasses, with their meaning and unit. Bad arguments
raise :class:`SkillInputError` naming them.

Timings of every call for a team of 11: ``python -m agents.skills.timing``
(:mod:`agents.skills.timing`).
"""

from agents.skills.clearing import ClearParams, ClearPlan, best_clearance, goal_kick_clearance
from agents.skills.context import Players, SkillContext, ViewArrays
from agents.skills.crossing import CrossParams, CrossPlan, best_cross, in_crossing_zone
from agents.skills.decision import (BallDecision, CarryParams, DecisionParams, FinishParams, OnBallAction, SafetyParams,
                                    decide_on_ball)
from agents.skills.dribbling import DribbleParams, DribblePlan, dribble, dribble_directions
from agents.skills.goalkeeping import (Distribution, GoalieParams, comes_out, distribute, guard_position,
                                      should_catch)
from agents.skills.interception import UNREACHABLE, BallRace, Interception, ball_race, intercept, intercept_many
from agents.skills.kicking import kick_effectiveness, kick_for_velocity, kickable
from agents.skills.lanes import lane_open, opponent_cycles, teammate_cycles
from agents.skills.model import MotionModel, SkillInputError, view_effort
from agents.skills.movement import dash_to_points, paced_dashes, speed_caps
from agents.skills.pacing import PacingParams
from agents.skills.passing import PassParams, PassPlan, best_pass, offside_positions, pass_candidates
from agents.skills.saving import SaveParams, goalkeeper_kick, parry_direction, parry_kick
from agents.skills.shooting import ShotParams, ShotPlan, aim_points, best_shot

__all__ = [
    "UNREACHABLE", "BallDecision", "BallRace", "CarryParams", "FinishParams", "SafetyParams", "ClearParams", "ClearPlan", "CrossParams", "CrossPlan",
    "best_cross", "in_crossing_zone", "DecisionParams", "Distribution", "DribbleParams", "DribblePlan",
    "GoalieParams", "Interception", "MotionModel", "OnBallAction", "PassParams", "PacingParams", "PassPlan",
    "Players", "ShotParams", "ShotPlan", "SkillContext", "SkillInputError", "ViewArrays", "aim_points",
    "ball_race", "best_clearance", "best_pass", "best_shot", "dash_to_points", "decide_on_ball", "distribute",
    "dribble", "dribble_directions", "goal_kick_clearance", "guard_position", "intercept", "intercept_many",
    "kick_effectiveness", "kick_for_velocity", "kickable", "lane_open", "offside_positions", "opponent_cycles",
    "paced_dashes", "pass_candidates", "should_catch", "speed_caps", "teammate_cycles", "view_effort",
    "SaveParams", "comes_out", "goalkeeper_kick", "parry_direction", "parry_kick",
]
