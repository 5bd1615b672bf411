"""The team's shape in open play (agents.teams.shape): the attack/defend switch with
hysteresis, the block and the role targets moving at a running pace, the rest defence, support
around the ball carrier, the follow-up of shots, and the kick-off shape of the built-in
formations. Hand-built situations (team frame: we attack +x)."""

from __future__ import annotations

import numpy as np
import pytest

import formations
from agents import skills
from agents.teams import FormationTeam, TeamStyle
from agents.teams.shape_kernels import advance_block, switch_side
from agents.teams.shape import Shape, ShapeParams
from formations.formation_set import Situation
from soccer_sim import MatchConfig, PlayMode, SideInfo
from soccer_sim.team import TeamView

CONFIG = MatchConfig()
HL, HW = CONFIG.field.half_length, CONFIG.field.half_width
KINDS = [role.kind for role in formations.load_builtin("4-3-3").roles]
PARAMS = ShapeParams()


def view(own_pos, opp_pos, ball, ball_vel=(0.0, 0.0), mode=PlayMode.PLAY_ON, cycle=100) -> TeamView:
    own_pos, opp_pos = np.asarray(own_pos, float), np.asarray(opp_pos, float)
    return TeamView(own_pos=own_pos, own_vel=np.zeros_like(own_pos), opp_pos=opp_pos, opp_vel=np.zeros_like(opp_pos),
                    ball=np.asarray(ball, float), ball_vel=np.asarray(ball_vel, float),
                    stamina=np.full(11, CONFIG.stamina.maximum), play_mode=mode, mode_ours=False, cycle=cycle)


def ready(assigner: str = "static", style: TeamStyle | None = None) -> FormationTeam:
    team = FormationTeam(assigner, style)
    team.reset(SideInfo(0, "us", "them", 11, 0, 11, 0), CONFIG, np.random.default_rng(0))
    return team


def race(ours: int, theirs: int, ours_point=(0.0, 0.0), theirs_point=(0.0, 0.0)) -> skills.BallRace:
    """A ball race our player 1 gets to in ``ours`` cycles and their player 1 in ``theirs``."""
    def side(cycle: int, point) -> skills.Interception:
        cycles = np.full(11, skills.UNREACHABLE, dtype=np.int64)
        cycles[1] = cycle
        points = np.tile(np.asarray(point, float), (11, 1))
        return skills.Interception(cycles, points, 1, cycle)
    return skills.BallRace(side(ours, ours_point), side(theirs, theirs_point))


def bare_shape(params: ShapeParams = PARAMS, depth: float = 0.0, push: float = 8.0) -> Shape:
    return Shape(params, KINDS, depth, push, HL, HW)


def opponents(front_x: float = -5.0) -> np.ndarray:
    """Their goalkeeper at their goal and ten players, the most advanced at ``front_x``."""
    pos = np.array([[HL - 1.0, 0.0], *[[front_x + 4.0 * (i % 5), -20.0 + 10.0 * (i // 5) * 4 + i % 5]
                                       for i in range(10)]])
    return pos


# ---------------------------------------------------------------------------- hysteresis
class _Switch:
    """A belief's attack/defend switch as the pipeline runs it (:func:`switch_side`), one race a call."""

    def __init__(self) -> None:
        self.attacking, self.pending, self.in_play = False, 0, False

    def race(self, ours: int, theirs: int) -> Situation:
        self.attacking, self.pending = switch_side(theirs - ours, self.in_play, self.attacking, self.pending,
                                                   PARAMS.switch_margin, PARAMS.switch_persist)
        self.in_play = True
        return Situation.ATTACK if self.attacking else Situation.DEFEND


def test_the_attack_defend_switch_needs_a_clear_or_a_lasting_race_win() -> None:
    switch = _Switch()
    assert switch.race(2, 10) == Situation.ATTACK  # the first cycle of play follows the race
    # They win the race narrowly (by one cycle): we keep attacking until it has lasted.
    for _ in range(PARAMS.switch_persist - 1):
        assert switch.race(5, 4) == Situation.ATTACK
    assert switch.race(5, 4) == Situation.DEFEND
    # We win narrowly for a few cycles (a ball bouncing between two players): still defending.
    for _ in range(PARAMS.switch_persist - 1):
        assert switch.race(4, 5) == Situation.DEFEND
    switch.race(5, 4)  # they win again: the count starts afresh
    assert switch.race(4, 5) == Situation.DEFEND
    # A clear win switches at once.
    assert switch.race(1, 1 + PARAMS.switch_margin) == Situation.ATTACK


# ---------------------------------------------------------------------------- pace
def test_the_query_point_and_the_block_shift_move_at_a_running_pace() -> None:
    record = bare_shape(depth=-2.0, push=8.0).settle_record
    block = np.zeros(3)
    advance_block(block, np.array([-10.0, 0.0]), -2.0 + 8.0, False, record)  # attacking: depth + push
    assert np.allclose(block[:2], (-10.0, 0.0)) and block[2] == pytest.approx(6.0)  # first cycle: no lag
    points, shifts = [(-10.0, 0.0)], []
    for _ in range(30):  # a long ball forwards: the query point follows it at the push pace
        advance_block(block, np.array([20.0, 6.0]), 6.0, True, record)
        points.append(tuple(block[:2]))
    steps = np.hypot(*np.diff(np.array(points), axis=0).T)
    assert np.allclose(steps, PARAMS.push_speed)  # neither a jump nor a stop
    assert points[-1][0] == pytest.approx(-10.0 + 30 * PARAMS.push_speed * 30.0 / np.hypot(30.0, 6.0))
    assert points[-1][0] < 20.0  # still on its way after 30 cycles of a 30 m ball
    for _ in range(10):  # possession lost: the block drops (shift 6 -> -2) at the drop pace
        advance_block(block, np.array([0.0, 0.0]), -2.0, True, record)
        shifts.append(block[2])
    drops = -np.diff([6.0, *shifts])
    assert np.all(drops <= PARAMS.drop_speed + 1e-12) and shifts[-1] == pytest.approx(-2.0)
    assert drops[0] == pytest.approx(PARAMS.drop_speed)


def test_role_targets_never_jump_when_possession_changes_and_then_settle() -> None:
    team = ready()
    own = np.array([[-50.0, 0.0], *[[-20.0 + 3.0 * i, -15.0 + 3.0 * i] for i in range(10)]])
    theirs = opponents(-30.0)
    theirs[5] = (-20.0, 30.0)  # their player on the ball deep in our half: we defend
    team.act(view(own, theirs, (-20.0, 30.0), cycle=10))
    before = team.pipeline.previous[0].copy()
    # Now our player 9 has the ball at their box: attack. Targets move, but at a running pace
    # (the shape's paced targets: support spots are put on top of them, see the support tests).
    own[9] = (30.0, -10.0)
    theirs = opponents(20.0)
    steps = []
    for cycle in range(11, 160):
        team.act(view(own, theirs, (30.5, -10.0), cycle=cycle))
        steps.append(np.hypot(*(team.pipeline.previous[0][1:] - before[1:]).T).max())
        before = team.pipeline.previous[0].copy()
    assert team.pipeline.attacking[0]
    assert max(steps) <= PARAMS.drop_speed + 1e-9 and steps[0] > 0.3
    assert steps[-1] < 1e-9  # settled: the shape's own targets, no longer limited
    # the settled targets are the attack formation at the carrier's point, shifted, rest defence applied
    expected = team.formation_set.positions(team.pipeline.block[0, :2], Situation.ATTACK)
    forwards = [r for r, k in enumerate(KINDS) if k == "forward"]
    assert np.allclose(team.pipeline.targets[0][forwards, 0], np.minimum(expected[forwards, 0] + team.pipeline.block[0, 2], HL - 2.0))


# ---------------------------------------------------------------------------- rest defence
@pytest.mark.parametrize(("ball_x", "front_x", "line"), [
    (20.0, -5.0, -7.0),      # their most advanced player at -5: the back line 2 m goal-side of him
    (30.0, 25.0, 30.0 - PARAMS.rest_ball_gap),  # nobody deep: rest_ball_gap behind the ball
    (30.0, -45.0, -5.0),     # a forward lurking at our box is left offside: at most 35 m behind the ball
])
def test_the_back_line_stays_behind_the_ball_and_their_forwards_when_we_attack(ball_x, front_x, line) -> None:
    team = ready()
    own = np.array([[-50.0, 0.0], *[[-20.0 + 3.0 * i, -15.0 + 3.0 * i] for i in range(10)]])
    own[8] = (ball_x - 0.5, 0.0)  # our centre forward on the ball
    theirs = opponents(front_x)
    theirs[1] = (front_x, 25.0)
    for cycle in range(200):
        team.act(view(own, theirs, (ball_x, 0.0), cycle=cycle))
    assert team.pipeline.attacking[0]
    backs = [r for r, k in enumerate(KINDS) if k == "defender"]
    assert np.all(team.pipeline.targets[0][backs, 0] <= line + 1e-9)
    assert np.any(team.pipeline.targets[0][backs, 0] >= line - 1e-6)  # held at the line, not dropped further
    # No defender near the opponents' box, nor the full backs.
    assert np.all(team.pipeline.targets[0][backs, 0] < HL - CONFIG.field.penalty_area_length - 10.0)


def test_the_back_line_stays_goal_side_of_the_ball_when_we_defend() -> None:
    team = ready()
    own = np.array([[-50.0, 0.0], *[[-30.0 + 3.0 * i, -15.0 + 3.0 * i] for i in range(10)]])
    theirs = opponents(-25.0)
    theirs[3] = (-28.0, 4.0)  # their player on the ball, past our back line's formation spot
    for cycle in range(120):
        team.act(view(own, theirs, (-28.0, 4.0), cycle=cycle))
    assert not team.pipeline.attacking[0]
    backs = [r for r, k in enumerate(KINDS) if k == "defender"]
    assert np.all(team.pipeline.targets[0][backs, 0] <= -28.0 - PARAMS.defend_ball_gap + 1e-9)


# ---------------------------------------------------------------------------- support
NO_SUPPORT = TeamStyle(shape=ShapeParams(support_players=0))
SUPPORT_OWN = np.array([[-50.0, 0.0], [-20.0, -20.0], [-20.0, 20.0], [-22.0, -7.0], [-22.0, 7.0],
                        [-4.0, 2.0], [10.0, -25.0], [2.0, -9.0], [0.0, 0.0], [3.0, 10.0], [12.0, 25.0]])


def support_roles(assigner: str, own, theirs, ball, carrier_row: int = 8):
    """The team after one cycle of play, and the roles whose targets support moved (compared with
    the same team without support), for a carrier ``own[carrier_row]`` on the ``ball``."""
    teams = []
    for style in (None, NO_SUPPORT):
        team = ready(assigner, style)
        team.act(view(own, theirs, ball, cycle=49))  # (a first cycle: support needs the roles held)
        team.act(view(own, theirs, ball, cycle=50))
        teams.append(team)
    team, plain = teams
    moved = [r for r in team.pipeline.match_roles[0] if not np.allclose(team.pipeline.targets[0][r], plain.pipeline.targets[0][r])]
    return team, plain, moved


def test_support_moves_two_midfield_role_targets_to_open_spots_at_passing_distance() -> None:
    carrier = SUPPORT_OWN[8]
    theirs = opponents(30.0)  # (a deep back line: nobody of ours is pulled back onside)
    theirs[1:4] = [(5.0, -4.0), (6.0, 4.0), (3.0, 8.0)]  # lanes ahead and to the left are covered
    ball = carrier + (0.5, 0.0)
    team, plain, moved = support_roles("static", SUPPORT_OWN, theirs, ball)
    assert team.pipeline.attacking[0]
    assert len(moved) == PARAMS.support_players
    backs = {r for r, k in enumerate(KINDS) if k == "defender"}
    forwards = {r for r, k in enumerate(KINDS) if k == "forward"}
    assert not (backs | forwards) & set(moved)  # the rest defence stays back, the forwards up front
    for role in moved:
        spot = team.pipeline.targets[0][role]
        assert 8.0 <= np.hypot(*(spot - ball)) <= 15.0
        assert spot[0] - ball[0] >= -0.5 * np.hypot(*(spot - ball)) - 1e-9  # not far behind the ball
        # the pass lane to the spot is open: no opponent within 2 m of it
        ab = spot - ball
        t = np.clip(((theirs - ball) @ ab) / (ab @ ab), 0.0, 1.0)
        gap = np.hypot(*(ball + t[:, None] * ab - theirs).T)
        assert gap.min() >= 2.0
    # the support roles are the midfield roles whose own targets lie nearest the carrier (whoever plays them)
    carrier_role = team.pipeline.match_roles[0][team.pipeline.followed[0][list(team.pipeline.outfield).index(8)]]
    gaps = {r: np.hypot(*(plain.pipeline.targets[0][r] - carrier)) for r in team.pipeline.match_roles[0]
            if r not in backs | forwards and r != carrier_role}
    assert sorted(moved) == sorted(sorted(gaps, key=gaps.get)[:2])
    assert np.hypot(*(team.pipeline.targets[0][moved[0]] - team.pipeline.targets[0][moved[1]])) >= PARAMS.crowd_distance


@pytest.mark.parametrize("assigner", ["static", "mmdr", "greedy"])
def test_the_role_assigner_decides_who_runs_to_a_support_spot(assigner: str) -> None:
    theirs = opponents(30.0)
    theirs[1] = (5.0, -4.0)  # pressure on the carrier
    own = SUPPORT_OWN.copy()
    own[5] = (-30.0, 0.0)  # the holding midfielder far behind: static still sends it if its role supports
    team, _, moved = support_roles(assigner, own, theirs, own[8] + (0.5, 0.0))
    assert moved
    out_targets = team.pipeline.targets[0][team.pipeline.match_roles[0]]
    for role in moved:
        players = [row for i, row in enumerate(team.pipeline.outfield) if team.pipeline.match_roles[0][team.pipeline.followed[0][i]] == role]
        assert len(players) == 1 and np.allclose(team.pipeline.goals[players[0]], team.pipeline.targets[0][role])
        if assigner == "static":
            assert players[0] == role  # the role's own player, however far
    assert np.allclose(out_targets[team.pipeline.followed[0]][team.pipeline.outfield != 8], team.pipeline.goals[team.pipeline.outfield[team.pipeline.outfield != 8]])


def test_the_carriers_own_role_never_supports() -> None:
    theirs = opponents(30.0)
    theirs[1] = (5.0, -4.0)
    own = SUPPORT_OWN.copy()
    own[[7, 8]] = own[[8, 7]]  # a central midfielder (role 7) carries the ball at the centre spot
    team, _, moved = support_roles("static", own, theirs, own[7] + (0.5, 0.0), carrier_row=7)
    assert moved and 7 not in moved


def test_nobody_supports_when_we_defend() -> None:
    own = np.array([[-50.0, 0.0], *[[-20.0 + 3.0 * i, -15.0 + 3.0 * i] for i in range(10)]])
    theirs = opponents(-10.0)
    team, _, moved = support_roles("static", own, theirs, theirs[2] + (-0.5, 0.0))
    assert not team.pipeline.attacking[0] and moved == []
    planned = team.pipeline.targets[0][team.pipeline.match_roles[0]][team.pipeline.followed[0]]
    off_target = [row for i, row in enumerate(team.pipeline.outfield) if not np.allclose(team.pipeline.goals[row], planned[i])]
    assert len(off_target) == 1  # only the player sent at the ball


# ---------------------------------------------------------------------------- follow-up
def test_forwards_follow_up_our_shot_to_the_rebound_area() -> None:
    team = ready()
    own = np.array([[-50.0, 0.0], [-10.0, -20.0], [-10.0, 20.0], [-12.0, -7.0], [-12.0, 7.0],
                    [5.0, 0.0], [30.0, -22.0], [18.0, -9.0], [33.0, 3.0], [18.0, 10.0], [30.0, 22.0]])
    theirs = opponents(20.0)
    theirs[0] = (HL - 1.0, 0.0)
    ball, ball_vel = np.array([40.0, 4.0]), np.array([2.6, -0.3])
    team.act(view(own, theirs, (30.0, 0.0), cycle=9))
    team.pipeline.decisions[0].shot_cycle, team.pipeline.decisions[0].shot_from = 9, np.array([38.0, 4.2])
    team.act(view(own, theirs, ball, ball_vel, cycle=10))
    forwards = [6, 8, 10]  # static roles: row r plays role r (wingers 7/11 and the centre forward 9)
    rebound_x = HL - PARAMS.rebound_depth
    at_rebound = [row for row in team.pipeline.outfield if abs(team.pipeline.goals[row, 0] - rebound_x) < 1e-9]
    assert len(at_rebound) == PARAMS.follow_up_players and set(at_rebound) <= set(forwards)
    assert abs(team.pipeline.goals[at_rebound[0], 1] - team.pipeline.goals[at_rebound[1], 1]) == pytest.approx(2 * PARAMS.rebound_spread)
    assert 8 in at_rebound  # the centre forward is the nearest
    # Long after the shot they are back on their own targets.
    team.act(view(own, theirs, ball, ball_vel, cycle=10 + PARAMS.follow_up_cycles + 1))
    assert not any(abs(team.pipeline.goals[row, 0] - rebound_x) < 1e-9 for row in team.pipeline.outfield)


# ---------------------------------------------------------------------------- kick-off shape
@pytest.mark.parametrize("system", ["4-3-3", "4-4-2"])
@pytest.mark.parametrize("situation", [Situation.OUR_SET_PLAY, Situation.THEIR_SET_PLAY])
def test_the_kick_off_shape_has_a_back_line(system: str, situation: Situation) -> None:
    fs = formations.load_builtin(system)
    kinds = np.array([role.kind for role in fs.roles])
    pos = fs.positions((0.0, 0.0), situation)
    backs, mids, fwds = pos[kinds == "defender"], pos[kinds == "midfielder"], pos[kinds == "forward"]
    assert len(backs) == 4
    assert np.ptp(backs[:, 0]) <= 0.5 and backs[:, 0].max() <= -20.0  # a level back four, 20 m deep or more
    assert np.ptp(backs[:, 1]) >= 25.0  # spread across the field, not bunched
    assert backs[:, 0].max() < mids[:, 0].min() and np.median(mids[:, 0]) < np.median(fwds[:, 0])
    outfield = pos[kinds != "goalkeeper"]
    assert np.all(outfield[:, 0] <= 0.0)
    if situation == Situation.OUR_SET_PLAY:  # the taker at the ball and the team in its shape behind it
        assert np.min(np.hypot(*outfield.T)) < 1.5
        assert np.ptp(outfield[:, 0]) >= 20.0 and np.ptp(outfield[:, 1]) >= 50.0
        assert np.sum(np.hypot(*outfield.T) < 16.0) <= 4  # not a ring of ten around the centre


def test_shape_params_are_checked() -> None:
    with pytest.raises(ValueError, match="switch_persist"):
        ShapeParams(switch_persist=-1)
    with pytest.raises(ValueError, match="push_speed"):
        ShapeParams(push_speed=0.0)
    with pytest.raises(ValueError, match="support_radii"):
        ShapeParams(support_radii=())


def test_a_free_carrier_runs_with_the_ball_and_nobody_leaves_the_shape() -> None:
    theirs = opponents(30.0)  # nobody within 25 m of our carrier
    team, _, moved = support_roles("static", SUPPORT_OWN, theirs, SUPPORT_OWN[8] + (0.5, 0.0))
    assert team.pipeline.attacking[0] and moved == []


def test_the_shape_hands_its_kernel_records_out_as_copies_of_its_parameters() -> None:
    """What the pipeline needs of the shape comes through public properties: the
    block's and the support spots' numbers as named records with the parameters' values, copies
    that the shape does not see written."""
    params = ShapeParams(rest_ball_gap=11.0, push_speed=0.65, lane_cap=4.5, crowd_distance=6.5)
    shape = Shape(params, KINDS, depth=0.0, attack_push=0.0, half_length=HL, half_width=HW)
    settle, support = shape.settle_record, shape.support_record
    assert settle[0]["rest_ball_gap"] == 11.0 and settle[0]["push"] == 0.65
    assert settle[0]["drop"] == params.drop_speed and settle[0]["back_floor"] > -HL
    assert support[0]["lane_cap"] == 4.5 and support[0]["crowd_distance"] == 6.5
    assert support[0]["x_limit"] < HL and support[0]["y_limit"] < HW
    settle[0]["push"] = 99.0
    support[0]["lane_cap"] = 99.0
    assert shape.settle_record[0]["push"] == 0.65 and shape.support_record[0]["lane_cap"] == 4.5
