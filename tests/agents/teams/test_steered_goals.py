"""A steering assigner's one-step goals become goals as far as the role targets, in the step's
direction, so that the team's pacing (by distance to the goal) does not read a short field
step as "arrived"; and the built-in bidding team's players run to their places."""

from __future__ import annotations

import numpy as np

from agents.teams.role_kernels import steered_goals


def test_a_short_step_is_stretched_to_the_role_targets_distance_in_its_direction() -> None:
    players = np.array([[0.0, 0.0], [10.0, 5.0], [3.0, 3.0]])
    steps = np.array([[1.0, 0.0], [10.0, 4.0], [3.0, 3.0]])      # a step right, a step down, no step
    anchors = np.array([[0.0, 20.0], [10.0, 5.5], [9.0, 9.0]])     # 20 m away, 0.5 m away, far
    goals = steered_goals(players, steps, anchors)
    np.testing.assert_allclose(goals[0], [20.0, 0.0])             # the step's direction, 20 m out
    np.testing.assert_allclose(goals[1], [10.0, 4.0])             # a step longer than the way: kept
    np.testing.assert_allclose(goals[2], [3.0, 3.0])              # no step: stays


def test_the_bidding_teams_players_far_from_their_places_run() -> None:
    """Players 20 m and more from their role targets in play on: with one-step goals the
    pacing would let most of them walk (a goal 1 m away); stretched, they all run."""
    from soccer_sim import MatchConfig, PlayMode, SideInfo
    from soccer_sim.registry import resolve_team
    from soccer_sim.team import TeamView

    config = MatchConfig()
    team, _ = resolve_team("bidding")
    team.reset(SideInfo(0, "us", "them", 11, 0, 11, 0), config, np.random.default_rng(0))
    own = np.array([[-50.0, 0.0], *[[-45.0, -30.0 + 6.0 * i] for i in range(10)]])  # all crammed at our goal line
    opp = np.array([[50.0, 0.0], *[[20.0, -30.0 + 6.0 * i] for i in range(10)]])
    view = TeamView(own_pos=own, own_vel=np.zeros_like(own), opp_pos=opp, opp_vel=np.zeros_like(opp),
                    ball=np.array([10.0, 0.0]), ball_vel=np.zeros(2), stamina=np.full(11, config.stamina.maximum),
                    play_mode=PlayMode.PLAY_ON, mode_ours=False, cycle=100)
    dash = team.act(view).dash
    speeds = np.hypot(dash[1:, 0], dash[1:, 1])
    # A dash of 0.6 m/cycle^2 is full power; a walk towards a 1 m goal is a small fraction of it.
    assert np.count_nonzero(speeds > 0.3) >= 8


def test_bidding_is_told_each_players_reach_from_the_race_and_only_bidding() -> None:
    from agents import skills
    from agents.roles import make_assigner
    from agents.skills.interception import BallRace, Interception
    from agents.teams.on_ball import ball_reach
    from soccer_sim import MatchConfig

    model = skills.MotionModel(MatchConfig(), players=11, goalie=0, opponents=11, opponent_goalie=0)
    ours = Interception(np.array([0, 4, skills.UNREACHABLE, 10]), np.zeros((4, 2)), 0, 0)
    race = BallRace(ours, Interception(np.array([3]), np.zeros((1, 2)), 0, 3))
    reach = ball_reach(race.ours.cycles, np.array([1, 2, 3]), model)
    np.testing.assert_allclose(reach, [4 * model.top_speed, np.inf, 10 * model.top_speed])
    assert make_assigner("bidding").uses_ball_reach
    assert not any(make_assigner(name).uses_ball_reach for name in ("mmdr", "mmd+msd2", "static", "greedy", "random"))


def test_a_ball_the_bidding_teams_goalkeeper_wins_in_its_area_is_the_goalkeepers() -> None:
    """Bidding names an outfield ball player, but a ball our goalkeeper reaches first in our
    penalty area is its own, as under every other assigner (it used to stay on its line)."""
    from soccer_sim import MatchConfig, PlayMode, SideInfo
    from soccer_sim.registry import resolve_team
    from soccer_sim.team import TeamView

    config = MatchConfig()
    keepers = {}
    for name in ("bidding", "mmdr"):
        team, _ = resolve_team(name)
        team.reset(SideInfo(0, "us", "them", 11, 0, 11, 0), config, np.random.default_rng(0))
        own = np.array([[-51.0, 0.0], *[[-20.0, -30.0 + 6.0 * i] for i in range(10)]])
        opp = np.array([[50.0, 0.0], *[[10.0, -30.0 + 6.0 * i] for i in range(10)]])
        for cycle in (100, 101):  # (bidding names its ball player from the cycle before)
            view = TeamView(own_pos=own, own_vel=np.zeros_like(own), opp_pos=opp, opp_vel=np.zeros_like(opp),
                            ball=np.array([-44.0, 3.0]), ball_vel=np.array([-0.3, 0.0]),
                            stamina=np.full(11, config.stamina.maximum), play_mode=PlayMode.PLAY_ON, mode_ours=False,
                            cycle=cycle)
            team.act(view)
        keepers[name] = team.pipeline.goals[0].copy()
        assert team.pipeline.assigners[0].ball_player() is None or name == "bidding"
    # The keeper runs onto the ball's path (a few metres out), not to its guard point on the line.
    for goal in keepers.values():
        assert goal[0] > -47.0 and abs(goal[1] - 3.0) < 1.5
    np.testing.assert_allclose(keepers["bidding"], keepers["mmdr"])


def test_the_assigner_is_told_where_the_ball_will_be_controlled_not_the_blocks_lagging_query_point() -> None:
    """The formation's query point follows the ball at a running pace; bidding's ball role
    (alignment) and its supporters' field (shot lines) are about the ball itself."""
    from soccer_sim import MatchConfig, PlayMode, SideInfo
    from soccer_sim.registry import resolve_team
    from soccer_sim.team import TeamView

    config = MatchConfig()
    team, _ = resolve_team("bidding")
    team.reset(SideInfo(0, "us", "them", 11, 0, 11, 0), config, np.random.default_rng(0))
    own = np.array([[-51.0, 0.0], *[[-10.0 + 2.0 * (i % 5), -20.0 + 4.0 * i] for i in range(10)]])
    opp = np.array([[50.0, 0.0], *[[30.0, -30.0 + 6.0 * i] for i in range(10)]])
    for cycle, ball in ((100, (-5.0, 0.0)), (102, (20.0, 2.0))):  # a long ball: 25 m in two cycles
        view = TeamView(own_pos=own, own_vel=np.zeros_like(own), opp_pos=opp, opp_vel=np.zeros_like(opp),
                        ball=np.array(ball), ball_vel=np.zeros(2), stamina=np.full(11, config.stamina.maximum),
                        play_mode=PlayMode.PLAY_ON, mode_ours=False, cycle=cycle)
        team.act(view)
    assert np.hypot(*(team.pipeline.block[0, :2] - (20.0, 2.0))) > 20.0  # the block is still on its way
    assert np.hypot(*(team.pipeline.contexts[0].ball - (20.0, 2.0))) < 1.0  # the ball stands still: controlled where it is
