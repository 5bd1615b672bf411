"""The built-in team's tackles (agents.skills.tackling): when a player tackles, in which
direction, foul tackles, the goalkeeper's dive, and a match in which tackles happen."""

from __future__ import annotations

import math

import numpy as np
import pytest

from agents.skills import MotionModel, SkillInputError
from agents.skills.tackling import Occasion, TackleParams, Tackling
from agents.teams import FormationTeam
from soccer_sim import MatchConfig, SideInfo, run_match
from soccer_sim.state import EventKind
from soccer_sim.tackles import body_frame_failure

from tests.agents.skills.skill_views import CONFIG, HL, N, make_view

MODEL = MotionModel.even_sides(CONFIG)
TACKLES = CONFIG.tackles


def tackling(**params) -> Tackling:
    """Our tackling with ``params``; fair tackles only unless a test asks for foul tackles."""
    params.setdefault("foul_tackles", False)
    return Tackling(MODEL, TACKLES, np.full(N, MODEL.inertia_moment), 0, TackleParams(**params))


def crossing_y(ball, degrees: float) -> float:
    """Where a ball pushed from ``ball`` in direction ``degrees`` crosses our goal line."""
    dx, dy = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return ball[1] + dy * (-HL - ball[0]) / dx


def test_a_likely_tackle_on_an_opponents_ball_is_made_towards_their_goal() -> None:
    ball = (0.0, 0.0)
    view = make_view(own={5: (-1.4, 0.0)}, opp={9: (0.9, 0.0)}, ball=ball)  # we face the ball from 1.4 m
    tackle = tackling().choose(view, Occasion.ON_BALL)
    assert tackle is not None and tackle.player == 5 and not tackle.foul
    expected = 1.0 - body_frame_failure(TACKLES, 1.4, 0.0, 0.0, 0.0, MODEL.inertia_moment, False)[0]
    assert tackle.probability == pytest.approx(expected) and tackle.probability > 0.8
    assert math.cos(math.radians(tackle.direction)) > 0.9  # straight ahead: up the field
    foul = tackling(foul_tackles=True).choose(view, Occasion.ON_BALL)  # uncarded, in midfield: the foul tackle
    foul_expected = 1.0 - body_frame_failure(TACKLES, 1.4, 0.0, 0.0, 0.0, MODEL.inertia_moment, True)[0]
    assert foul is not None and foul.foul and foul.probability == pytest.approx(foul_expected)
    assert foul_expected > expected


def test_no_tackle_when_the_chance_is_low_or_nobody_is_in_reach() -> None:
    far = make_view(own={5: (-1.9, 0.0)}, opp={9: (0.9, 0.0)})  # 1.9 m: about 27 % in midfield
    assert tackling().choose(far, Occasion.ON_BALL) is None
    assert tackling(min_probability=0.2).choose(far, Occasion.ON_BALL) is not None
    assert tackling().choose(make_view(own={5: (-3.0, 0.0)}, opp={9: (0.9, 0.0)}), Occasion.ON_BALL) is None
    # from behind, the body facing away from where the ball could usefully go: no poke
    behind = make_view(own={5: (1.4, 0.0)}, opp={9: (-0.9, 0.0)}, ball=(0.0, 0.0))
    assert tackling().choose(behind, Occasion.ON_BALL) is None


def test_frozen_or_absent_players_and_the_goalkeeper_do_not_tackle() -> None:
    view = make_view(own={0: (-1.4, 0.0)}, opp={9: (0.9, 0.0)})
    assert tackling().choose(view, Occasion.ON_BALL) is None  # row 0 is the goalkeeper
    view = make_view(own={5: (-1.4, 0.0)}, opp={9: (0.9, 0.0)})
    view.frozen[5] = 3
    assert tackling().choose(view, Occasion.ON_BALL) is None
    view.frozen[5] = 0
    view.present[5] = False
    assert tackling().choose(view, Occasion.ON_BALL) is None


def test_in_our_third_the_push_goes_away_from_our_goal_and_towards_the_touchline() -> None:
    ball = (-40.0, 8.0)
    view = make_view(own={3: (-41.3, 7.5), 4: (-10.0, 0.0)}, opp={9: (-39.2, 8.4)}, ball=ball)
    tackle = tackling().choose(view, Occasion.ON_BALL)
    assert tackle is not None and tackle.player == 3
    d = math.radians(tackle.direction)
    assert math.cos(d) > 0.0 and math.sin(d) > 0.0


def test_a_push_never_goes_into_our_goal_mouth_but_may_go_behind_for_a_corner() -> None:
    # Our defender chases towards our goal line: its body faces the line.
    ball = (-49.0, 9.0)
    view = make_view(own={3: (-47.6, 9.0)}, opp={9: (-49.9, 8.6)}, ball=ball, own_vel={3: (-0.6, 0.0)})
    tackle = tackling().choose(view, Occasion.ON_BALL)
    assert tackle is not None
    d = math.radians(tackle.direction)
    if math.cos(d) < 0.0:
        assert abs(crossing_y(ball, tackle.direction)) > MODEL.goal_half_width + 2.0
    # Straight at the goal centre from in front of it: every strong push would go in, none is taken.
    centre = make_view(own={3: (-45.6, 0.0)}, opp={9: (-48.0, 0.4)}, ball=(-47.0, 0.0), own_vel={3: (-0.6, 0.0)})
    chosen = tackling(min_score=0.0).choose(centre, Occasion.ON_BALL)
    assert chosen is None or math.cos(math.radians(chosen.direction)) >= 0.0 or \
        abs(crossing_y((-47.0, 0.0), chosen.direction)) > MODEL.goal_half_width + 2.0


def test_a_foul_tackle_outside_our_penalty_area_until_the_tackler_is_carded() -> None:
    pos = np.array([[30.0 + i, 30.0] for i in range(N)])  # everybody else far up the field
    pos[0] = (-50.0, 0.0)
    pos[5] = (-21.4, 0.0)
    view = make_view(own=pos, opp={9: (-20.9, 0.0)}, ball=(-20.0, 0.0))  # in our half, outside the area
    first = tackling(foul_tackles=True).choose(view, Occasion.ON_BALL)
    assert first is not None and first.foul and first.player == 5  # as helios-base: foul while uncarded
    assert tackling(foul_tackles=True).choose(view, Occasion.ON_BALL).foul  # and again: no memory but the card
    view.cards = np.zeros(N, dtype=np.int64)
    view.cards[5] = 1
    carded = tackling(foul_tackles=True).choose(view, Occasion.ON_BALL)
    assert carded is not None and not carded.foul and carded.player == 5  # a second yellow would send it off
    view.cards[5] = 0
    assert not tackling(foul_tackles=False).choose(view, Occasion.ON_BALL).foul
    area_line = -MODEL.half_length + MODEL.penalty_area_length
    inside = pos.copy()
    inside[5] = (area_line - 3.4, 0.0)
    in_area = tackling(foul_tackles=True).choose(make_view(own=inside, opp={9: (area_line - 2.9, 0.0)}, ball=(area_line - 2.0, 0.0)),
                                Occasion.ON_BALL)
    assert in_area is not None and not in_area.foul  # never a foul in our penalty area
    midfield = pos.copy()
    midfield[5] = (8.6, 0.0)
    assert tackling(foul_tackles=True).choose(make_view(own=midfield, opp={9: (11.0, 0.0)}, ball=(10.0, 0.0)), Occasion.ON_BALL).foul


def test_occasions_blocks_and_the_goalkeepers_dive() -> None:
    team = tackling()
    shot = make_view(own={0: (-50.0, 0.0)}, ball=(-48.8, 0.9), ball_vel=(-2.5, 0.0))  # keeper 1.5 m away
    assert team.occasion(shot, 30, 1_000_000, ours_last=False) == Occasion.SHOT
    assert team.occasion(shot, 30, 1_000_000, ours_last=True) == Occasion.NONE  # our own ball
    assert team.occasion(make_view(ball=(-20.0, 0.0), ball_vel=(0.0, 1.5)), 3, 8, False) == Occasion.BLOCK
    assert team.occasion(make_view(ball=(20.0, 0.0), ball_vel=(0.0, 1.5)), 3, 8, False) == Occasion.NONE
    assert team.occasion(make_view(ball=(20.0, 0.0)), 0, 8, False) == Occasion.ON_BALL
    assert tackling(enabled=False).occasion(make_view(ball=(20.0, 0.0)), 0, 8, False) == Occasion.NONE
    # The goalkeeper 1.5 m from a shot it cannot catch dives; one it can catch it leaves to the catch.
    dive = team.choose(shot, Occasion.SHOT, keeper_misses=True)
    assert dive is not None and dive.player == 0
    out_x = -2.5 + 2.7 * math.cos(math.radians(dive.direction))  # about the ball's velocity after the push
    out_y = 2.7 * math.sin(math.radians(dive.direction))
    assert out_x >= 0.0 or abs(0.9 + out_y * (-HL + 48.8) / out_x) > MODEL.goal_half_width  # wide of the goal
    assert team.choose(shot, Occasion.SHOT, keeper_misses=False) is None
    assert tackling(keeper_saves=False).choose(shot, Occasion.SHOT, keeper_misses=True) is None


def test_bad_params_are_named() -> None:
    with pytest.raises(SkillInputError, match="min_probability"):
        TackleParams(min_probability=1.5)
    with pytest.raises(SkillInputError, match="blocks"):
        TackleParams(blocks="yes")
    with pytest.raises(SkillInputError, match="inertia"):
        Tackling(MODEL, TACKLES, np.ones(3), 0)


def team_view(own, opp, ball):
    return make_view(own=own, opp=opp, ball=ball)


def test_the_team_tackles_only_when_it_cannot_kick_the_ball_itself() -> None:
    team = FormationTeam("mmdr")
    team.reset(SideInfo(0, "us", "them", N, 0, N, 0), CONFIG, np.random.default_rng(0))
    far = np.array([[-50.0, 0.0], *[[-30.0 + 3.0 * i, -30.0] for i in range(N - 1)]])
    far[5] = (-1.4, 0.0)
    opp = np.array([[50.0, 0.0], *[[10.0 + 3.0 * i, 30.0] for i in range(N - 1)]])
    opp[9] = (0.9, 0.0)
    command = team.act(make_view(own=far, opp=opp, ball=(0.0, 0.0)))
    assert command.tackle is not None and np.isfinite(command.tackle[5])
    assert np.isnan(np.delete(command.tackle, 5)).all()
    near = far.copy()
    near[5] = (-0.8, 0.0)  # within the kickable distance: it kicks instead
    command = team.act(make_view(own=near, opp=opp, ball=(0.0, 0.0)))
    assert command.tackle is None and np.any(command.kick[5] != 0.0)


def test_built_in_teams_tackle_in_a_short_match() -> None:
    # (2000 cycles: about a tackle every 500 cycles per match, so 1000 can hold none)
    result = run_match("mmdr", "counter-442", seed=2, config=MatchConfig(max_cycles=2000))
    tackles = result.events.of_kind(EventKind.TACKLE)
    assert tackles and any(detail % 2 == 1 for *_, detail in tackles)
    assert sum(s.tackles for s in result.statistics) == len(tackles)


def test_frozen_players_are_left_out_of_the_ball_and_a_shot_at_us_is_blocked_wide() -> None:
    from agents import skills
    from agents.teams.on_ball import able_players, choose_kicker, on_ball_kick

    view = make_view(own={5: (-0.5, 0.0)}, ball=(0.0, 0.0))
    assert able_players(view, None) is None
    view.frozen[5] = 4
    able = able_players(view, None)
    assert not able[5] and able.sum() == N - 1
    ctx = skills.SkillContext(MODEL)
    race = skills.ball_race(ctx, view, able)
    assert race.ours.first != 5 and choose_kicker(view, race, -1, MODEL.kickable_distance, able) == -1
    # An outfield player who can kick an opponent's shot at our goal deflects it wide and behind.
    shot = make_view(own={4: (-44.0, 1.0)}, opp={9: (-30.0, 0.0)}, ball=(-44.0, 0.2), ball_vel=(-2.4, -0.1))
    team = tackling()
    assert team.shot_at_us(shot, ours_last=False) and not team.shot_at_us(shot, ours_last=True)
    race = skills.ball_race(ctx, shot)
    kick, dash, is_shot = on_ball_kick(ctx, shot, 4, 0, skills.DecisionParams(), race, False, True)
    out = shot.ball_vel + kick
    assert dash is None and not is_shot and out[0] < 0.0
    assert abs(0.2 + out[1] * (-HL + 44.0) / out[0]) > MODEL.goal_half_width + 2.0
