"""The built-in team and its named variants: registration, set-up errors, what the team does
in typical situations, and the figures it reports."""

from __future__ import annotations

import numpy as np
import pytest

import soccer_sim
from agents.teams import FormationTeam, TeamStyle, builtin
from agents.teams.shape import ShapeParams
from soccer_sim import MatchConfig, PlayMode, SideInfo
from soccer_sim.registry import available_teams, resolve_team
from soccer_sim.team import TeamView
from soccer_sim.team_hooks import Drawable, Drawing, ReportsStatistics

CONFIG = MatchConfig()
NAMES = [*builtin.ASSIGNER_VARIANTS, "statues", "counter-442", "press-433", "possession"]


def view(own_pos, opp_pos, ball, ball_vel=(0.0, 0.0), mode=PlayMode.PLAY_ON, ours=False, cycle=100) -> TeamView:
    own_pos, opp_pos = np.asarray(own_pos, float), np.asarray(opp_pos, float)
    return TeamView(own_pos=own_pos, own_vel=np.zeros_like(own_pos), opp_pos=opp_pos, opp_vel=np.zeros_like(opp_pos),
                    ball=np.asarray(ball, float), ball_vel=np.asarray(ball_vel, float),
                    stamina=np.full(11, CONFIG.stamina.maximum), play_mode=mode, mode_ours=ours, cycle=cycle)


def ready(team: FormationTeam, seed: int = 0) -> FormationTeam:
    team.reset(SideInfo(0, "us", "them", 11, 0, 11, 0), CONFIG, np.random.default_rng(seed))
    return team


def spread_out(side: float = -1.0) -> np.ndarray:
    """A plausible line-up in one half (team frame), goalkeeper first."""
    pos = np.array([[-50.0, 0.0], *[[-30.0 + 5.0 * (i % 5), -20.0 + 10.0 * (i // 5) * 2 + (i % 5)] for i in range(10)]])
    return pos if side < 0 else -pos


@pytest.mark.parametrize("name", NAMES)
def test_every_built_in_team_is_registered_and_plays(name: str) -> None:
    assert name in available_teams()
    team, shown = resolve_team(name)
    assert shown == name and isinstance(team, FormationTeam)
    result = soccer_sim.run_match(name, "idle", seed=1, config=MatchConfig(max_cycles=150))
    assert result.cycles == 150


def test_the_assigner_variants_differ_only_in_their_assigner() -> None:
    teams = [resolve_team(name)[0] for name in builtin.ASSIGNER_VARIANTS]
    assert len({team.style for team in teams}) == 1
    assert [team.assigner_name for team in teams] == list(builtin.ASSIGNER_VARIANTS)


def test_reference_opponents_have_their_own_styles() -> None:
    styles = {name: resolve_team(name)[0].style for name in ("counter-442", "press-433", "possession")}
    assert styles["counter-442"].system == "4-4-2" and styles["counter-442"].depth < 0
    assert styles["press-433"].pressers >= 2 and styles["press-433"].depth > 0
    assert len(set(styles.values())) == 3


def test_unknown_assigner_and_wrong_team_size_are_clear_errors() -> None:
    with pytest.raises(ValueError, match="nonsense"):
        FormationTeam("nonsense")
    with pytest.raises(ValueError, match="at most 11 players"):
        FormationTeam().reset(SideInfo(0, "us", "them", 12, 0, 12, 0), MatchConfig(players_per_team=12),
                              np.random.default_rng(0))
    with pytest.raises(ValueError, match="not 11 with 11 outfield"):  # no goalkeeper: ten outfield roles
        FormationTeam().reset(SideInfo(0, "us", "them", 11, -1, 11, 0), MatchConfig(), np.random.default_rng(0))


def test_the_fastest_player_runs_to_the_interception_point_and_others_hold_formation() -> None:
    # (no support runs: they move two players off their targets, see tests/agents/teams/test_shape.py)
    team = ready(FormationTeam("mmd+msd2", TeamStyle(shape=ShapeParams(support_players=0))))
    own = spread_out()
    ball, ball_vel = np.array([5.0, 10.0]), np.array([-1.5, 0.0])  # rolling towards us, nobody near
    command = team.act(view(own, spread_out(+1.0), ball, ball_vel))
    pipeline = team.pipeline
    role_targets = pipeline.targets[0][pipeline.match_roles[0]][pipeline.followed[0]]
    away = np.flatnonzero(np.hypot(*(pipeline.goals[pipeline.outfield] - role_targets).T) > 1e-9)
    assert away.size == 1  # one runner; the others hold formation (their goals are their role targets)
    runner = int(pipeline.outfield[away[0]])
    # The runner heads for a point on the ball's path (y = 10), ahead of the ball, not at the ball...
    goal = pipeline.goals[runner]
    assert goal[1] == pytest.approx(10.0, abs=0.5) and goal[0] < ball[0] - 2.0
    # ...flat out (an urgent player: a full-power dash towards that point).
    dash = command.dash[runner]
    assert np.hypot(*dash) == pytest.approx(pipeline.model.accel_max)
    assert dash @ (goal - own[runner]) > 0.9 * np.hypot(*dash) * np.hypot(*(goal - own[runner]))


def test_the_player_on_the_ball_shoots_when_close_and_free() -> None:
    team = ready(FormationTeam("mmd+msd2"))
    own = spread_out()
    own[9] = (40.0, 0.5)
    opp = spread_out(+1.0)
    opp[0] = (52.0, 6.5)  # their goalkeeper stands by a post
    command = team.act(view(own, opp, (40.7, 0.5)))
    assert np.hypot(*command.kick[9]) > 2.0  # a hard kick...
    assert command.kick[9][0] > 0  # ...towards the goal
    assert np.count_nonzero(np.hypot(*command.kick.T)) == 1  # nobody else kicks


def test_the_goalkeeper_guards_the_line_and_catches_but_not_a_back_pass() -> None:
    team = ready(FormationTeam("mmd+msd2"))
    own = spread_out()
    own[0] = (-50.0, 0.0)
    command = team.act(view(own, spread_out(+1.0), (-49.4, 0.5), (-1.0, 0.0)))
    assert command.catch  # a ball from the opponents, within reach in our area
    team = ready(FormationTeam("mmd+msd2"))
    own[3] = (-30.0, 0.0)
    team.act(view(own, spread_out(+1.0), (-29.5, 0.0)))  # our player 3 plays the ball back...
    command = team.act(view(own, spread_out(+1.0), (-49.4, 0.5), (-1.0, 0.0), cycle=101))
    assert not command.catch  # ...so the goalkeeper must not pick it up


def test_kick_off_places_everybody_in_our_half_with_a_taker_at_the_ball() -> None:
    team = ready(FormationTeam("mmd+msd2"))
    command = team.act(view(spread_out(), spread_out(+1.0), (0.0, 0.0), mode=PlayMode.KICK_OFF, ours=True))
    assert command.move is not None
    assert (command.move[:, 0] <= 0.0).all()
    assert np.hypot(*command.move.T).min() < 1.5  # the kick-off taker stands at the ball


def test_statues_hold_their_kick_off_spots() -> None:
    result_team = resolve_team("statues")[0]
    positions = []

    class Watch:
        def on_start(self, match): pass
        def on_end(self, match): pass
        def on_cycle(self, match):
            positions.append(match.state.pos[1:11].copy())

    soccer_sim.run_match(result_team, "idle", seed=3, config=MatchConfig(max_cycles=300), recorders=[Watch()])
    pipeline = result_team.pipeline
    spots = pipeline.kick_off_spots[pipeline.match_roles[0]]
    final = positions[-1]
    # Every outfield player ends up at its own spot (the idle opponents never take the ball away).
    assert np.hypot(*(final - spots).T).max() < 3.0


def test_reported_statistics_and_drawing() -> None:
    team = FormationTeam("greedy")
    result = soccer_sim.run_match(team, "chaser", seed=2, config=MatchConfig(max_cycles=600))
    reported = result.statistics[0].reported
    assert set(reported) == {"role_switches_per_minute", "target_distance_mean", "target_distance_max",
                             "role_unfilled_share", "fixed_roles_optimal_share", "makespan_gap",
                             "held_roles_optimal_share", "held_makespan_gap"}
    assert 0.0 <= reported["fixed_roles_optimal_share"] <= 1.0 and reported["makespan_gap"] >= 0.0
    assert reported["target_distance_max"] >= reported["target_distance_mean"] > 0.0
    assert 0.0 <= reported["role_unfilled_share"] <= 1.0
    drawing = team.drawing()
    assert isinstance(team, Drawable) and isinstance(team, ReportsStatistics) and isinstance(drawing, Drawing)
    assert drawing.targets.shape == (11, 2) and drawing.goals.shape == (11, 2)
    assert sorted(drawing.role_of_player.tolist()) == list(range(10))
    np.testing.assert_array_equal(drawing.outfield, np.arange(1, 11))
    np.testing.assert_array_equal(drawing.assigned_targets, drawing.targets[1:][drawing.role_of_player])
    assert drawing.formation_triangles.shape[1] == 3
    assert drawing.formation_triangles.max() < len(drawing.formation_balls)


def test_drawing_before_the_first_assignment_has_no_roles() -> None:
    drawing = ready(FormationTeam("greedy")).drawing()
    assert isinstance(drawing, Drawing)
    assert drawing.role_of_player is None and drawing.assigned_targets is None
    assert drawing.targets.shape == (11, 2) and drawing.outfield.tolist() == list(range(1, 11))


def test_a_team_is_deterministic_for_a_seed() -> None:
    a = soccer_sim.run_match("random", "press-433", seed=4, config=MatchConfig(max_cycles=400))
    b = soccer_sim.run_match("random", "press-433", seed=4, config=MatchConfig(max_cycles=400))
    assert np.array_equal(a.state.pos, b.state.pos) and a.events.as_arrays()["kind"].tolist() == \
        b.events.as_arrays()["kind"].tolist()
