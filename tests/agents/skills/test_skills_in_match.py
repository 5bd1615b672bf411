"""End to end in the real simulator (noise off): a scripted team that uses the skills reaches
a rolling ball where and when the interception predicted, scores with the shot it chose and
gets a pass to its receiver."""

from __future__ import annotations

import numpy as np

from agents.skills import MotionModel, Players, SkillContext, ball_race, best_pass, best_shot, dash_to_points
from soccer_sim.state import EventKind
from tests.agents.skills.skill_views import HL, N, ScriptedTeam, far_positions, play_on_match, quiet_config

CONFIG = quiet_config(max_cycles=400)
MODEL = MotionModel.even_sides(CONFIG)
CTX = SkillContext(MODEL)
KICKABLE = CONFIG.physics.kickable_distance


def test_the_predicted_first_player_reaches_the_rolling_ball_on_time() -> None:
    predictions: list[tuple[int, int, np.ndarray]] = []

    def script(view):
        race = ball_race(CTX, view)
        if not predictions:
            predictions.append((race.ours.first, race.ours.first_cycle, race.ours.points[race.ours.first].copy()))
        targets = view.own_pos.copy()  # everyone else stays put
        first = race.ours.first
        targets[first] = race.ours.points[first]
        dash = np.zeros((N, 2))
        runner = Players(MODEL, view.own_pos[first:first + 1], view.own_vel[first:first + 1],
                         view.effort[first:first + 1])
        dash[first] = dash_to_points(MODEL, runner, targets[first:first + 1])[0]
        return dash, np.zeros((N, 2)), False

    home = ScriptedTeam(script)
    own = far_positions(-1.0)
    own[6] = (10.0, 8.0)   # closest to where the ball rolls
    own[7] = (25.0, -6.0)  # further down the line, later
    match = play_on_match(home, ScriptedTeam(), CONFIG, own, far_positions(1.0), ball=(0.0, 0.0),
                          ball_vel=(1.8, 0.0))
    for _ in range(25):
        match.step()
    first, cycle, point = predictions[0]
    assert first == 6 and 3 <= cycle <= 20
    start = home.views[0]["cycle"]
    at = [v for v in home.views if v["cycle"] == start + cycle][0]
    assert np.linalg.norm(at["ball"] - at["own_pos"][6]) <= KICKABLE + 1e-6
    assert np.linalg.norm(at["ball"] - point) < 1e-6
    before = [v for v in home.views if v["cycle"] == start + cycle - 1][0]
    assert np.linalg.norm(before["ball"] - before["own_pos"][6]) > KICKABLE


def test_the_chosen_shot_scores() -> None:
    shooter = 9

    def script(view):
        kick = np.zeros((N, 2))
        if np.linalg.norm(view.ball - view.own_pos[shooter]) <= KICKABLE:
            kick[shooter] = best_shot(CTX, view, shooter).kick
        return np.zeros((N, 2)), kick, False

    own = far_positions(-1.0)
    own[shooter] = (HL - 16.0, 3.0)
    away = far_positions(1.0)
    away[0] = (HL - 1.0, -4.0)  # their goalkeeper (idle) covers one side
    home = ScriptedTeam(script)
    match = play_on_match(home, ScriptedTeam(), CONFIG, own, away, ball=(HL - 15.5, 3.0), ball_vel=(0.0, 0.0))
    for _ in range(15):
        match.step()
    assert match.state.score[0] == 1
    assert [e[1] for e in match.events.of_kind(EventKind.SHOT)] == [0]


def test_the_chosen_pass_reaches_the_receiver() -> None:
    passer, receiver = 9, 10
    plans = []

    def script(view):
        kick, dash = np.zeros((N, 2)), np.zeros((N, 2))
        if not plans:
            plans.append(best_pass(CTX, view, passer))
            kick[passer] = plans[0].kick
        else:
            race = ball_race(CTX, view)
            runner = Players(MODEL, view.own_pos[receiver:receiver + 1], view.own_vel[receiver:receiver + 1])
            dash[receiver:receiver + 1] = dash_to_points(MODEL, runner, race.ours.points[receiver:receiver + 1])
            if np.linalg.norm(view.ball - view.own_pos[receiver]) <= KICKABLE:
                kick[receiver] = -view.ball_vel  # stop it
        return dash, kick, False

    own = far_positions(-1.0)
    own[passer] = (0.0, 0.0)
    own[receiver] = (18.0, 6.0)
    away = far_positions(1.0)
    away[5] = (9.0, -4.0)
    home = ScriptedTeam(script)
    match = play_on_match(home, ScriptedTeam(), CONFIG, own, away, ball=(0.6, 0.0), ball_vel=(0.0, 0.0))
    for _ in range(30):
        match.step()
    assert plans[0].receiver == receiver
    passes = match.events.of_kind(EventKind.PASS)
    assert len(passes) == 1 and passes[0][1] == 0 and passes[0][5] == receiver
