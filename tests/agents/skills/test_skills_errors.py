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
    Players,
    ShotParams,
    SkillContext,
    SkillInputError,
    dash_to_points,
    dribble,
    guard_position,
    intercept,
    best_shot,
    intercept_many,
    kick_for_velocity,
)
from agents.errors import AgentsError
from agents.skills.passing import best_pass
from tests.agents.skills.skill_views import CONFIG, make_view

MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
POS = np.zeros((3, 2))


def test_skill_errors_sit_under_the_agents_root_and_stay_value_errors() -> None:
    assert issubclass(SkillInputError, AgentsError) and issubclass(SkillInputError, ValueError)


def test_model_needs_a_config_a_horizon_and_both_sides() -> None:
    with pytest.raises(SkillInputError, match="MatchConfig"):
        MotionModel.even_sides({"field": 1})
    with pytest.raises(SkillInputError, match="horizon"):
        MotionModel.even_sides(CONFIG, horizon=0)
    with pytest.raises(SkillInputError, match="opponents"):
        MotionModel(CONFIG, players=11, goalie=0, opponents=-1, opponent_goalie=-1)
    with pytest.raises(SkillInputError, match="opponent_goalie"):
        MotionModel(CONFIG, players=11, goalie=0, opponents=5, opponent_goalie=5)
    with pytest.raises(TypeError):
        MotionModel(CONFIG)  # the sides are never guessed
    with pytest.raises(SkillInputError, match="MotionModel"):
        SkillContext(CONFIG)


@pytest.mark.parametrize("kwargs, name", [
    ({"pos": np.zeros((3, 3))}, "pos"),
    ({"vel": np.zeros((2, 2))}, "vel"),
    ({"effort": np.ones(4)}, "effort"),
    ({"radius": np.ones(2)}, "radius"),
])
def test_players_name_the_bad_argument(kwargs, name) -> None:
    args = {"pos": POS, "vel": np.zeros((3, 2))}
    args.update(kwargs)
    with pytest.raises(SkillInputError, match=name):
        Players(MODEL, **args)


@pytest.mark.parametrize("kwargs, name", [
    ({"ball": np.zeros(3)}, "ball"),
    ({"ball_vel": "fast"}, "ball_vel"),
    ({"ball_vel": np.zeros((2, 2))}, "ball_vel"),
    ({"players": (POS, POS)}, "players"),
])
def test_intercept_names_the_bad_argument(kwargs, name) -> None:
    args = {"ball": np.zeros(2), "ball_vel": np.zeros(2), "players": Players(MODEL, POS, np.zeros((3, 2)))}
    args.update(kwargs)
    with pytest.raises(SkillInputError, match=name):
        intercept(CTX, **args)


def test_intercept_many_checks_limits_and_players() -> None:
    balls = np.zeros((2, 2))
    players = Players(MODEL, POS, POS)
    with pytest.raises(SkillInputError, match="limit"):
        intercept_many(CTX, balls, balls, players, limit=np.ones(3, dtype=int))
    with pytest.raises(SkillInputError, match="only"):
        intercept_many(CTX, balls, balls, players, only=np.array([0, 5]))
    with pytest.raises(SkillInputError, match="match ball_vel"):
        intercept_many(CTX, balls, np.zeros((3, 2)), players)
    with pytest.raises(SkillInputError, match="reaction"):
        intercept_many(CTX, balls, balls, players, reaction=-1)


def test_dash_and_kick_name_the_bad_argument() -> None:
    with pytest.raises(SkillInputError, match="targets"):
        dash_to_points(MODEL, Players(MODEL, POS, POS), np.zeros((2, 2)))
    with pytest.raises(SkillInputError, match="speed_cap"):
        dash_to_points(MODEL, Players(MODEL, POS, POS), POS, speed_cap=np.ones(2))
    with pytest.raises(SkillInputError, match="out"):
        dash_to_points(MODEL, Players(MODEL, POS, POS), POS, out=np.zeros((3, 2), dtype=np.float32))
    with pytest.raises(SkillInputError, match="players"):
        dash_to_points(MODEL, POS, POS)
    with pytest.raises(SkillInputError, match="desired"):
        kick_for_velocity(MODEL, np.zeros(2), np.zeros(2), np.zeros(2), np.zeros(3))
    with pytest.raises(SkillInputError, match="ball_vel"):
        kick_for_velocity(MODEL, np.zeros(2), np.zeros(2), [1.0], np.zeros(2))
    with pytest.raises(SkillInputError, match="player_vel"):
        kick_for_velocity(MODEL, np.zeros(2), np.zeros(2), np.zeros(2), np.zeros(2), player_vel=[1.0, 2.0, 3.0])
    with pytest.raises(SkillInputError, match="ball"):
        guard_position(MODEL, [1.0, 2.0, 3.0])


def test_player_indices_are_checked() -> None:
    view = make_view()
    with pytest.raises(SkillInputError, match="passer index 11"):
        best_pass(CTX, view, 11)
    with pytest.raises(SkillInputError, match="player must be an integer"):
        dribble(CTX, view, 2.0)
    with pytest.raises(SkillInputError, match="shooter index -1"):
        best_shot(CTX, view, -1)


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
