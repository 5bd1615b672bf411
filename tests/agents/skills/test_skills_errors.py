"""Bad input to the skills is a SkillInputError naming the argument, never garbage from a
compiled kernel."""

from __future__ import annotations

import numpy as np
import pytest

from agents.skills import (
    ClearParams,
    DecisionParams,
    DribbleParams,
    GoalieParams,
    MotionModel,
    PassParams,
    ShotParams,
    SkillInputError,
    dash_to_points,
    dribble,
    guard_position,
    intercept,
    best_shot,
    intercept_many,
    kick_for_velocity,
)
from agents.skills.passing import best_pass
from tests.agents.skills.skill_views import CONFIG, make_view

MODEL = MotionModel(CONFIG)
POS = np.zeros((3, 2))


def test_model_needs_a_config_and_a_horizon() -> None:
    with pytest.raises(SkillInputError, match="MatchConfig"):
        MotionModel({"field": 1})
    with pytest.raises(SkillInputError, match="horizon"):
        MotionModel(CONFIG, horizon=0)


@pytest.mark.parametrize("kwargs, name", [
    ({"pos": np.zeros((3, 3))}, "pos"),
    ({"vel": np.zeros((2, 2))}, "vel"),
    ({"effort": np.ones(4)}, "effort"),
    ({"radius": np.ones(2)}, "radius"),
    ({"ball": np.zeros(3)}, "ball"),
    ({"ball_vel": "fast"}, "ball_vel"),
])
def test_intercept_names_the_bad_argument(kwargs, name) -> None:
    args = {"ball": np.zeros(2), "ball_vel": np.zeros(2), "pos": POS, "vel": np.zeros((3, 2))}
    args.update(kwargs)
    with pytest.raises(SkillInputError, match=name):
        intercept(MODEL, **args)


def test_intercept_many_checks_limits_and_players() -> None:
    balls = np.zeros((2, 2))
    with pytest.raises(SkillInputError, match="limit"):
        intercept_many(MODEL, balls, balls, POS, POS, limit=np.ones(3, dtype=int))
    with pytest.raises(SkillInputError, match="only"):
        intercept_many(MODEL, balls, balls, POS, POS, only=np.array([0, 5]))
    with pytest.raises(SkillInputError, match="match ball_vel"):
        intercept_many(MODEL, balls, np.zeros((3, 2)), POS, POS)
    with pytest.raises(SkillInputError, match="reaction"):
        intercept_many(MODEL, balls, balls, POS, POS, reaction=-1)


def test_dash_and_kick_name_the_bad_argument() -> None:
    with pytest.raises(SkillInputError, match="targets"):
        dash_to_points(MODEL, POS, POS, np.zeros((2, 2)))
    with pytest.raises(SkillInputError, match="speed_cap"):
        dash_to_points(MODEL, POS, POS, POS, speed_cap=np.ones(2))
    with pytest.raises(SkillInputError, match="out"):
        dash_to_points(MODEL, POS, POS, POS, out=np.zeros((3, 2), dtype=np.float32))
    with pytest.raises(SkillInputError, match="desired"):
        kick_for_velocity(MODEL, np.zeros(2), np.zeros(2), np.zeros(2), np.zeros(3))
    with pytest.raises(SkillInputError, match="ball_vel"):
        kick_for_velocity(MODEL, np.zeros(2), np.zeros(2), [1.0], np.zeros(2))
    with pytest.raises(SkillInputError, match="ball"):
        guard_position(MODEL, [1.0, 2.0, 3.0])


def test_player_indices_are_checked() -> None:
    view = make_view()
    with pytest.raises(SkillInputError, match="passer index 11"):
        best_pass(MODEL, view, 11)
    with pytest.raises(SkillInputError, match="player must be an integer"):
        dribble(MODEL, view, 2.0)
    with pytest.raises(SkillInputError, match="shooter index -1"):
        best_shot(MODEL, view, -1)


@pytest.mark.parametrize("make, message", [
    (lambda: PassParams(min_distance=-1.0), "PassParams.min_distance"),
    (lambda: PassParams(leads=((1.0,),)), "PassParams.leads"),
    (lambda: PassParams(min_lead=1.5), "PassParams.min_lead"),
    (lambda: ShotParams(threshold=2.0), "ShotParams.threshold"),
    (lambda: ShotParams(aims=0), "ShotParams.aims"),
    (lambda: DribbleParams(probes=()), "DribbleParams.probes"),
    (lambda: ClearParams(fan=True), "ClearParams.fan"),
    (lambda: GoalieParams(near=50.0), "GoalieParams.near"),
    (lambda: DecisionParams(pass_good=float("nan")),
     "DecisionParams.pass_good"),
    (lambda: DecisionParams(shot=None), "DecisionParams.shot"),
])
def test_bad_parameters_are_named(make, message) -> None:
    with pytest.raises(SkillInputError, match=message.replace(".", r"\.")):
        make()
