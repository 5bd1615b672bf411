"""Interception of a ball lying on a line: still in play, so still reachable."""

import numpy as np

from agents import skills
from soccer_sim import MatchConfig


def test_a_ball_on_the_touchline_can_be_reached() -> None:
    model = skills.MotionModel.even_sides(MatchConfig())
    ctx = skills.SkillContext(model)
    half_width = MatchConfig().field.half_width
    ball = np.array([-36.0, half_width + 0.05])  # over the line, but not wholly: in play
    pos = np.array([[-36.0, half_width - 5.0]])
    players = skills.Players(model, pos, np.zeros((1, 2)))
    result = skills.intercept(ctx, ball, np.zeros(2), players)
    assert result.first == 0 and 0 < result.first_cycle < 10
    gone = skills.intercept(ctx, ball + (0.0, 0.1), np.zeros(2), players)  # wholly out
    assert gone.first == -1
