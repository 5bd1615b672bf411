"""Our corner kicks and kick-ins (agents.teams.routines) and the goalkeeper's place in play:
runners go into the box and the corner is crossed into it (or played short when every cross
is lost and the short team-mate is free); at a kick-in a team-mate comes short and the ball
is played to it or down the line; the goalkeeper holds its line when an attacker wins the
race to the ball and comes out when it wins it."""

from __future__ import annotations

import numpy as np
import pytest

from agents import skills
from agents.teams import routines
from soccer_sim import PlayMode
from soccer_sim.team import TeamView
from tests.agents.teams.test_set_play_stalls import CONFIG, HL, play_set_play, ready, view

HW = CONFIG.field.half_width
CORNER = np.array([HL - CONFIG.rules.corner_inset, -(HW - CONFIG.rules.corner_inset)])
MODEL = skills.MotionModel(CONFIG, players=11, goalie=0, opponents=11, opponent_goalie=0)
CTX = skills.SkillContext(MODEL)


def attacking_line_up() -> np.ndarray:
    """Our team spread over the opponents' half, the right back (3) at the corner."""
    own = np.array([[-45.0, 0.0], [10.0, -20.0], [10.0, 20.0], [CORNER[0] - 0.6, CORNER[1]], [5.0, 0.0],
                    [25.0, -10.0], [35.0, -25.0], [25.0, 10.0], [38.0, -5.0], [30.0, 0.0], [38.0, 15.0]])
    return own


def defending(box: bool) -> np.ndarray:
    """Their team: the goalkeeper on its line; outfield players at the edge of their box, or
    (``box``) packed on every spot in it."""
    opp = np.array([[HL - 1.0, 0.0], *[[HL - 18.0, -20.0 + 4.5 * i] for i in range(10)]])
    if box:
        spots = routines.box_spots(MODEL, CORNER[1])
        for i, spot in enumerate(spots):
            opp[1 + 2 * i] = spot + (0.6, 0.0)
            opp[2 + 2 * i] = spot + (-0.6, 0.3)
        opp[9] = CORNER + (-7.0, 7.0)  # in the way of the crosses, 9.9 m from the ball
    return opp


def path_enters_their_box(ball: np.ndarray, kick: np.ndarray, taker_pos: np.ndarray) -> bool:
    _, velocity = skills.kick_for_velocity(MODEL, taker_pos, ball, np.zeros(2), kick)
    path = MODEL.ball_path(ball, velocity, 40)
    return bool(MODEL.in_penalty_area(path, ours=False).any())


def test_at_our_corner_runners_go_into_the_box_and_the_corner_is_crossed_into_it() -> None:
    team = ready("mmdr")
    own = attacking_line_up()
    opp = defending(box=False)
    team.act(view(own, opp, CORNER, PlayMode.CORNER_KICK, cycle=300))
    taker = team.pipeline.decisions[0].set_plays.taker
    assert taker == 3
    in_box = MODEL.in_penalty_area(np.delete(team.pipeline.goals, [0, taker], axis=0), ours=False)
    assert in_box.sum() >= 3  # the runners' spots are in their box
    cycle, kicker, kick = play_set_play(team, own, opp, CORNER, PlayMode.CORNER_KICK, 300, 40)
    assert kicker == taker and cycle == 300 + team.style.routines.corner_wait
    assert path_enters_their_box(CORNER, kick, own[kicker])
    direction = kick / np.hypot(*kick)
    assert direction[1] > 0.5  # across towards the goal, not along the goal line or back


def test_the_corner_routine_crosses_to_a_runner_that_wins_its_lane() -> None:
    own = attacking_line_up()
    opp = defending(box=False)
    spots = routines.box_spots(MODEL, CORNER[1])
    own[8] = spots[1]  # a runner waiting at the far post, no defender near
    kind, kick = routines.corner_kick(CTX, view(own, opp, CORNER, PlayMode.CORNER_KICK), 3, np.arange(1, 11),
                                      routines.RoutineParams())
    assert kind == "cross"
    assert path_enters_their_box(CORNER, kick, own[3])


def test_a_corner_is_played_short_when_every_cross_is_lost_and_the_short_team_mate_is_free() -> None:
    own = attacking_line_up()
    opp = defending(box=True)
    short = routines.short_spot(MODEL, CORNER, True, routines.RoutineParams())
    own[6] = short
    kind, kick = routines.corner_kick(CTX, view(own, opp, CORNER, PlayMode.CORNER_KICK), 3, np.arange(1, 11),
                                      routines.RoutineParams())
    assert kind == "short"
    to_mate = (short - CORNER) / np.hypot(*(short - CORNER))
    assert float(kick @ to_mate) / np.hypot(*kick) > 0.99


def test_at_our_kick_in_a_team_mate_comes_short() -> None:
    team = ready("mmdr")
    ball = np.array([10.0, -HW])
    own = attacking_line_up()
    own[3] = ball + (-0.6, 0.5)
    own[6] = ball + (3.0, 8.0)  # the nearest team-mate
    team.act(view(own, defending(box=False), ball, PlayMode.KICK_IN, cycle=500))
    assert team.pipeline.decisions[0].set_plays.taker == 3
    expected = routines.short_spot(MODEL, ball, False, team.style.routines)
    assert np.allclose(team.pipeline.goals[6], expected)
    assert 0.0 < expected[1] - ball[1] <= team.style.routines.short_gap + 1e-9  # infield of the ball


def test_a_kick_in_with_nobody_free_goes_down_the_line() -> None:
    ball = np.array([0.0, -HW])
    own = attacking_line_up()
    own[3] = ball + (-0.6, 0.5)
    opp = defending(box=False)
    for i in range(1, 11):  # a marker goal-side of every team-mate, right on top of it
        opp[i] = own[i] + (0.7, 0.0)
    opp[0] = (HL - 1.0, 0.0)
    v = view(own, opp, ball, PlayMode.KICK_IN)
    kick = routines.kick_in(CTX, v, 3, skills.DecisionParams(), routines.RoutineParams())
    assert np.allclose(kick, routines.down_the_line(CTX, v, 3, routines.RoutineParams()))
    direction = kick / np.hypot(*kick)
    assert direction[0] > 0.9 and abs(direction[1]) < 0.3  # forwards, along the touchline



@pytest.mark.parametrize("x", [20.0, 30.0, 40.0])
def test_a_kick_in_down_the_line_near_their_goal_stops_short_of_the_goal_line(x) -> None:
    """Untouched, the ball played down the line stops ``line_stop`` short of the opponents'
    goal line (it arrives at its target at ``cross_speed`` and would roll on over the line
    for a goal kick), and still goes forwards along the touchline."""
    ball = np.array([x, -HW])
    own = attacking_line_up()
    own[3] = ball + (-0.6, 0.5)
    v = view(own, defending(box=False), ball, PlayMode.KICK_IN)
    params = routines.RoutineParams()
    kick = routines.down_the_line(CTX, v, 3, params)
    velocity = routines.line_velocity(MODEL, ball, params)
    assert np.allclose(kick, skills.kick_for_velocity(MODEL, v.own_pos[3], ball, v.ball_vel, velocity,
                                                      player_vel=v.own_vel[3])[0])
    rest = ball + velocity / (1.0 - MODEL.ball_decay)
    assert velocity[0] > abs(velocity[1])  # forwards, along the touchline
    assert rest[0] <= HL - params.line_stop + 1e-6
    # Arriving at its target at cross_speed instead, it would have rolled over the goal line.
    delta = np.array([min(x + params.line_length, HL - 3.0), -(HW - params.line_inside)]) - ball
    distance = float(np.hypot(*delta))
    arriving = min(distance * (1.0 - MODEL.ball_decay) + params.cross_speed, MODEL.ball_speed_max)
    assert x + delta[0] / distance * arriving / (1.0 - MODEL.ball_decay) > HL

def breakaway(attacker_gap: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    ball = np.array([-HL + 22.0, 3.0])
    own = np.array([[-30.0 + 3.0 * (i % 5), 10.0 + 2.0 * i] for i in range(11)])
    own[0] = skills.guard_position(MODEL, ball)
    opp = np.array([[HL - 1.0, 0.0], *[[20.0, -25.0 + 5.0 * i] for i in range(10)]])
    opp[9] = ball + (attacker_gap, 0.0)
    return own, opp, ball, np.array([-1.2, -0.1])


def play_on_view(own, opp, ball, ball_vel, opp_vel) -> TeamView:
    return TeamView(own_pos=own, own_vel=np.zeros_like(own), opp_pos=opp, opp_vel=opp_vel, ball=ball,
                    ball_vel=ball_vel, stamina=np.full(11, CONFIG.stamina.maximum), play_mode=PlayMode.PLAY_ON,
                    mode_ours=False, cycle=400)


def test_the_team_goalkeeper_holds_its_line_when_the_attacker_wins_the_race() -> None:
    own, opp, ball, ball_vel = breakaway(attacker_gap=0.5)
    opp_vel = np.zeros_like(opp)
    opp_vel[9] = (-0.9, 0.0)
    team = ready("mmdr")
    team.act(play_on_view(own, opp, ball, ball_vel, opp_vel))
    assert np.allclose(team.pipeline.goals[0], skills.guard_position(MODEL, ball))
    assert np.hypot(*(team.pipeline.goals[0] - own[0])) < 0.5


def test_the_team_goalkeeper_comes_out_when_it_wins_the_race() -> None:
    own, opp, ball, ball_vel = breakaway(attacker_gap=9.0)
    opp_vel = np.zeros_like(opp)
    team = ready("mmdr")
    v = play_on_view(own, opp, ball, ball_vel, opp_vel)
    team.act(v)
    race = skills.ball_race(team.pipeline.skills, v)
    assert race.ours.first == 0
    assert np.allclose(team.pipeline.goals[0], race.ours.points[0])
    assert team.pipeline.goals[0][0] > own[0][0] + 3.0  # out towards the ball


def test_a_defender_pressed_in_our_box_with_nobody_free_kicks_the_ball_wide_of_the_goal() -> None:
    ball = np.array([-HL + 3.0, -6.0])
    own = np.array([[-30.0 + 3.0 * (i % 5), -20.0 + 4.0 * i] for i in range(11)])
    own[0] = (-HL + 1.0, 0.0)
    own[2] = ball + (-0.6, 0.0)  # our defender on the ball, facing its own goal line
    opp = np.array([[HL - 1.0, 0.0], *[[0.0, 0.0]] * 10])
    for i in range(1, 11):  # every team-mate marked closely, so no pass is safe
        opp[i] = own[i] + (-0.7, 0.0)
    opp[1] = ball + (0.9, 0.3)  # an attacker at the ball
    opp[0] = (HL - 1.0, 0.0)
    v = play_on_view(own, opp, ball, np.zeros(2), np.zeros_like(opp))
    team = ready("mmdr")
    command = team.act(v)
    kick = command.kick[2]
    assert np.hypot(*kick) > 0.0 and not command.kick[np.arange(11) != 2].any()
    direction = kick / np.hypot(*kick)
    assert np.allclose(direction, skills.parry_direction(CTX, ball), atol=1e-6)
    # it leaves the field over our goal line wide of the goal, or over the touchline: never into the goal
    t = (-HL - ball[0]) / direction[0] if direction[0] < 0.0 else np.inf
    assert np.isinf(t) or abs(ball[1] + t * direction[1]) > CONFIG.field.goal_width / 2.0 + 1.0


def test_the_corner_wait_never_goes_beyond_the_teams_patience() -> None:
    from dataclasses import replace

    from agents.teams import FormationTeam
    from soccer_sim import SideInfo

    style = replace(ready("mmdr").style, routines=routines.RoutineParams(corner_wait=500))
    team = FormationTeam("mmdr", style)
    team.reset(SideInfo(0, "us", "them", 11, 0, 11, 0), CONFIG, np.random.default_rng(0))
    cycle, kicker, _ = play_set_play(team, attacking_line_up(), defending(box=False), CORNER,
                                     PlayMode.CORNER_KICK, 300, 120)
    assert kicker == 3 and cycle == 300 + team.pipeline.decisions[0].set_plays.patience < 300 + CONFIG.rules.set_play_timeout


def test_routine_params_reject_bad_values() -> None:
    with pytest.raises(skills.SkillInputError, match="short_gap"):
        routines.RoutineParams(short_gap=0.0)
    with pytest.raises(skills.SkillInputError, match="corner_wait"):
        routines.RoutineParams(corner_wait=-1)
