"""The goalkeeper's catch (area, penalty area, ban), its hold as rcssserver (moves, catch fault, the free
kick's time) and release."""

import math

import pytest

from soccer_sim.config import MatchConfig
from soccer_sim.state import AWAY, HOME, NO_PLAYER, EventKind, PlayMode
from tests.soccer_sim.referee_world import N, catch, config_with, kick, kinds, make_world, step

CFG = MatchConfig()
HL = CFG.field.half_length
PA = CFG.field.penalty_area_length
GK = 0  # home goalkeeper row; home defends -x in the first half


def keeper_world(gk=(-48.0, 2.0), ball=(-47.0, 2.5), **kw):
    return make_world(ball=ball, ball_vel=(-1.0, 0.2), moves={GK: gk}, last_touch=N + 9, **kw)


def test_legal_catch_makes_the_goalkeeper_hold_the_ball():
    ref, st, ev = keeper_world()
    catch(ref, st, HOME)
    assert (st.play_mode, st.mode_team, st.ball_holder) == (PlayMode.GOALIE_HOLDS, HOME, GK)
    # rcssserver: the goalkeeper steps towards the ball until they touch; the ball stays
    assert not st.ball_vel.any() and st.ball.tolist() == [-47.0, 2.5]
    touching = CFG.physics.player_radius + CFG.physics.ball_radius
    assert math.dist(st.pos[GK], st.ball) == pytest.approx(touching)
    assert st.last_touch == GK
    [(cycle, team, player, x, y, _)] = ev.of_kind(EventKind.CATCH)
    assert (cycle, team, player, x, y) == (100, HOME, 0, -47.0, 2.5)
    assert kinds(ev) == [EventKind.CATCH, EventKind.SET_PLAY]


@pytest.mark.parametrize("distance, caught", [(CFG.rules.catch_length - 0.01, True), (CFG.rules.catch_length + 0.01, False)])
def test_catch_reach_is_the_catch_length(distance, caught):
    ref, st, ev = keeper_world(gk=(-45.0, 0.0), ball=(-45.0 + 0.6 * distance, 0.8 * distance))
    catch(ref, st, HOME)
    assert (st.play_mode == PlayMode.GOALIE_HOLDS) == caught


@pytest.mark.parametrize("gk, ball", [
    ((-HL + PA - 0.5, 0.0), (-HL + PA + 0.3, 0.0)),  # ball just outside the penalty area
    ((-HL + PA + 0.3, 0.0), (-HL + PA - 0.5, 0.0)),  # goalkeeper just outside it
    ((HL - 3.0, 0.0), (HL - 2.5, 0.0)),  # in the opponents' penalty area
])
def test_no_catch_outside_the_own_penalty_area(gk, ball):
    ref, st, ev = keeper_world(gk=gk, ball=ball)
    catch(ref, st, HOME)
    assert st.play_mode == PlayMode.PLAY_ON and st.ball_holder == NO_PLAYER
    assert EventKind.CATCH not in kinds(ev)


def test_only_the_goalkeeper_of_the_requesting_team_catches():
    ref, st, ev = keeper_world()
    catch(ref, st, AWAY)  # the away goalkeeper is far away at the other end
    assert st.play_mode == PlayMode.PLAY_ON


def test_away_goalkeeper_catches_in_its_own_area_after_half_time():
    ref, st, ev = make_world(ball=(-47.0, 0.0), home_attacks=-1, moves={N: (-47.5, 0.5)})
    catch(ref, st, AWAY)
    assert (st.play_mode, st.mode_team, st.ball_holder) == (PlayMode.GOALIE_HOLDS, AWAY, N)


def test_catch_ban_after_a_failed_attempt():
    ban = CFG.rules.catch_ban_cycles
    ref, st, ev = keeper_world(ball=(-44.0, 2.0))  # out of reach: the attempt fails
    catch(ref, st, HOME)
    assert st.play_mode == PlayMode.PLAY_ON
    st.ball[:] = (-47.5, 2.0)  # now within reach, but banned
    for _ in range(ban):
        step(ref, st)
        catch(ref, st, HOME)
        assert st.play_mode == PlayMode.PLAY_ON
    step(ref, st)
    catch(ref, st, HOME)
    assert st.play_mode == PlayMode.GOALIE_HOLDS
    assert ev.of_kind(EventKind.CATCH)[0][0] == 100 + ban + 1


def test_requests_outside_the_penalty_area_start_no_ban():
    # A team that asks to catch every cycle must still catch once the ball arrives.
    ref, st, ev = keeper_world(ball=(-HL + PA + 3.0, 2.0))  # ball outside the area
    catch(ref, st, HOME)
    assert st.play_mode == PlayMode.PLAY_ON
    step(ref, st)
    st.ball[:] = (-47.5, 2.0)  # the next cycle the ball is within reach
    catch(ref, st, HOME)
    assert st.play_mode == PlayMode.GOALIE_HOLDS


def test_no_catch_at_set_plays():
    ref, st, ev = keeper_world(mode=PlayMode.FREE_KICK, mode_team=AWAY)
    catch(ref, st, HOME)
    assert st.play_mode == PlayMode.FREE_KICK and st.ball_holder == NO_PLAYER


def test_holding_until_the_free_kicks_time_is_up_drops_the_ball_at_the_area_corner():
    timeout = 20
    ref, st, ev = keeper_world(gk=(-40.0, 5.0), ball=(-40.5, 5.0), config=config_with(set_play_timeout=timeout))
    catch(ref, st, HOME)  # at cycle 100, which counts as the free kick's first
    for _ in range(timeout):  # cycles 100..119 end held but the last
        assert st.play_mode == PlayMode.GOALIE_HOLDS
        step(ref, st)
    assert (st.play_mode, st.ball_holder) == (PlayMode.PLAY_ON, NO_PLAYER)
    # rcssserver's moveOutOfPenalty: the area's front corner on the ball's side
    assert st.ball.tolist() == [-HL + PA, CFG.field.penalty_area_width / 2]
    [(_, _, _, x, y, replaced)] = ev.of_kind(EventKind.DROP_BALL)
    assert replaced == int(PlayMode.GOALIE_HOLDS)


def test_a_held_ball_carried_out_of_the_area_is_a_catch_fault():
    ref, st, ev = keeper_world()
    catch(ref, st, HOME)
    st.pos[GK] = (-HL + PA + 1.0, 3.0)  # dashed out of the area with the ball
    step(ref, st)
    [(_, team, player, x, y, _)] = ev.of_kind(EventKind.CATCH_FAULT)
    assert (team, player) == (HOME, 0)
    assert (st.play_mode, st.mode_team, st.ball_holder) == (PlayMode.FREE_KICK, AWAY, NO_PLAYER)
    assert st.ball.tolist() == [x, y] and x > -HL + PA  # outside the area already: on the spot


def test_holding_goalkeeper_moves_at_most_goalie_max_moves_times():
    ref, st, ev = keeper_world()
    catch(ref, st, HOME)
    step(ref, st)
    assert ref.holding_keeper(st, HOME) == GK and ref.holding_keeper(st, AWAY) == NO_PLAYER
    assert ref.move_keeper(st, -45.0, 5.0) and st.pos[GK].tolist() == [-45.0, 5.0]
    step(ref, st)
    assert ref.move_keeper(st, -44.0, -6.0)
    step(ref, st)
    assert not ref.move_keeper(st, -46.0, 0.0)  # the third: refused, as (error too_many_moves)
    step(ref, st)
    assert st.pos[GK].tolist() == [-44.0, -6.0] and ref.goalkeeper.refused_moves == [1, 0]
    touching = CFG.physics.player_radius + CFG.physics.ball_radius
    assert math.dist(st.pos[GK], st.ball) == pytest.approx(touching)  # the ball follows


def test_opponents_are_kept_clear_of_the_held_ball():
    ref, st, ev = keeper_world()
    catch(ref, st, HOME)
    st.pos[N + 9] = (-45.0, 2.0)
    step(ref, st)
    assert math.dist(st.pos[N + 9], st.ball) >= CFG.rules.set_play_clearance - 1e-9


def test_kicking_releases_the_ball():
    ref, st, ev = keeper_world()
    catch(ref, st, HOME)
    step(ref, st)
    kick(ref, st, [GK], (2.5, 0.0))
    assert (st.play_mode, st.ball_holder) == (PlayMode.PLAY_ON, NO_PLAYER)
    assert st.ball_vel.tolist() == [2.5, 0.0]
    assert set(kinds(ev)) >= {EventKind.CATCH, EventKind.KICK}


def test_goalkeeper_that_kicks_cannot_catch_in_the_same_cycle():
    ref, st, ev = keeper_world()
    kick(ref, st, [GK], (1.0, 0.0), catch=(True, False))
    assert st.play_mode == PlayMode.PLAY_ON


def test_a_back_pass_cannot_be_caught_and_gives_the_opponents_a_free_kick():
    ref, st, ev = make_world(ball=(-30.0, 2.0), moves={GK: (-48.0, 2.0), 4: (-30.5, 2.0)})
    kick(ref, st, [4], (-2.0, 0.0))  # home player 4 passes back to its goalkeeper
    step(ref, st)
    st.ball[:] = (-47.3, 2.2)  # the ball arrives
    catch(ref, st, HOME)
    assert st.ball_holder == NO_PLAYER
    [(cycle, team, player, x, y, passer)] = ev.of_kind(EventKind.BACK_PASS)
    assert (team, player, passer) == (HOME, 0, 4)
    # Indirect free kick for the opponents; inside the goal area it moves to the area's front line.
    assert (st.play_mode, st.mode_team) == (PlayMode.FREE_KICK, AWAY)
    assert st.ball.tolist() == [-HL + CFG.field.goal_area_length, 2.2]


def test_a_ball_that_came_off_an_opponent_or_a_body_may_be_caught():
    # Kicked back by a team-mate, but an opponent touched it on the way: a legal catch.
    ref, st, ev = make_world(ball=(-30.0, 2.0), moves={GK: (-48.0, 2.0), 4: (-30.5, 2.0), N + 9: (-40.0, 2.0)})
    kick(ref, st, [4], (-2.0, 0.0))
    step(ref, st, touchers=[N + 9])
    st.ball[:] = (-47.3, 2.2)
    catch(ref, st, HOME)
    assert st.ball_holder == GK and EventKind.BACK_PASS not in kinds(ev)
    # A team-mate's body deflection is not a pass either.
    ref, st, ev = make_world(ball=(-40.0, 2.0), ball_vel=(-2.0, 0.0), moves={GK: (-48.0, 2.0), 4: (-40.3, 2.0)})
    step(ref, st, touchers=[4])
    st.ball[:] = (-47.3, 2.2)
    catch(ref, st, HOME)
    assert st.ball_holder == GK


def test_the_back_pass_rule_can_be_switched_off():
    ref, st, ev = make_world(ball=(-30.0, 2.0), moves={GK: (-48.0, 2.0), 4: (-30.5, 2.0)},
                             config=config_with(back_pass_rule=False))
    kick(ref, st, [4], (-2.0, 0.0))
    step(ref, st)
    st.ball[:] = (-47.3, 2.2)
    catch(ref, st, HOME)
    assert st.ball_holder == GK
