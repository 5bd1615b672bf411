"""The built-in team's ``ball_role`` option: the player who goes for the ball keeps its role in
the matching ("keep") or leaves it ("leave"), and the registered ``-leave`` variants."""

from __future__ import annotations

import tomllib
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from agents.assignment import assign
from agents.teams.pipeline_kernels import ball_player
from agents.teams import FormationTeam, TeamStyle, builtin
from agents.teams.ball_role import covered_role
from soccer_sim import MatchConfig, PlayMode, SideInfo
from soccer_sim.registry import resolve_team
from soccer_sim.team import TeamView

CONFIG = MatchConfig()


def _ready(team: FormationTeam) -> FormationTeam:
    team.reset(SideInfo(0, "us", "them", 11, 0, 11, 0), CONFIG, np.random.default_rng(0))
    return team


def _situation() -> TeamView:
    """Our players spread over our half, the ball rolling towards our right winger's area:
    one player races for it, far from its formation place."""
    own = np.array([[-50.0, 0.0], [-35.0, -20.0], [-35.0, 20.0], [-38.0, -7.0], [-38.0, 7.0], [-25.0, 0.0],
                    [-5.0, -22.0], [-18.0, -12.0], [-3.0, 1.0], [-18.0, 12.0], [-5.0, 22.0]])
    opp = -own
    ball, ball_vel = np.array([8.0, -12.0]), np.array([-1.6, -0.3])
    return TeamView(own_pos=own, own_vel=np.zeros_like(own), opp_pos=opp, opp_vel=np.zeros_like(opp), ball=ball,
                    ball_vel=ball_vel, stamina=np.full(11, CONFIG.stamina.maximum), play_mode=PlayMode.PLAY_ON,
                    cycle=101)


def _act(assigner: str, ball_role: str) -> tuple[FormationTeam, int, np.ndarray]:
    """The team after one cycle of play on: (team, its ball player's team row, the outfield
    roles' targets)."""
    team = _ready(FormationTeam(assigner, TeamStyle(ball_role=ball_role)))
    view = _situation()
    team.act(view)
    pipeline = team.pipeline
    ball_row = int(ball_player(pipeline.state, 0)) if ball_role == "leave" else -1
    return team, ball_row, pipeline.targets[0][pipeline.match_roles[0]]


def _roles(team: FormationTeam) -> np.ndarray:
    """The outfield players' roles (indices into the outfield roles) the team follows."""
    return team.pipeline.followed[0]


def test_leave_takes_the_ball_player_out_of_the_matching() -> None:
    team, ball_row, targets = _act("mmdr", "leave")
    assert ball_row >= 1  # an outfield player goes for the ball
    roles = _roles(team)
    assert sorted(roles.tolist()) == list(range(10))  # still every role held once
    i = ball_row - 1  # outfield row
    point = team.pipeline.goals[ball_row]  # where it runs: its interception point
    assert np.hypot(*(point - team.pipeline.win_point[0])) < 1e-9
    covered = covered_role(targets, point)
    assert roles[i] == covered  # it holds the role whose target is nearest its interception point
    assert covered == int(np.argmin(np.hypot(*(targets - point).T)))
    # The nine others: mmdr of exactly the nine other players to the nine other roles.
    rows = [r for r in range(10) if r != i]
    kept = [r for r in range(10) if r != covered]
    players = _situation().own_pos[1:][rows]
    expected = np.array(kept)[assign(players, targets[kept], "mmdr").target_of]
    assert roles[rows].tolist() == expected.tolist()
    # Everybody but the ball player runs to its role's target: the nine remaining roles are filled.
    others = np.array(rows) + 1
    assert np.allclose(team.pipeline.goals[others], targets[roles[rows]])


def test_keep_matches_all_ten_players_to_all_ten_roles() -> None:
    team, _, targets = _act("mmdr", "keep")
    expected = assign(_situation().own_pos[1:], targets, "mmdr").target_of
    assert _roles(team).tolist() == expected.tolist()
    leave_team, _, _ = _act("mmdr", "leave")
    assert _roles(leave_team).tolist() != _roles(team).tolist()  # the option changes the matching


def test_static_leave_swaps_the_covered_role_with_the_ball_players_own() -> None:
    team, ball_row, targets = _act("static", "leave")
    i = ball_row - 1
    covered = covered_role(targets, team.pipeline.goals[ball_row])
    expected = np.arange(10)
    expected[i], expected[covered] = covered, i
    assert covered != i and _roles(team).tolist() == expected.tolist()
    keep, _, _ = _act("static", "keep")
    assert _roles(keep).tolist() == list(range(10))


def test_leave_only_in_play_on() -> None:
    team = _ready(FormationTeam("mmdr", TeamStyle(ball_role="leave")))
    view = _situation()
    view.play_mode, view.mode_ours = PlayMode.KICK_IN, True
    team.act(view)
    targets = team.pipeline.targets[0][team.pipeline.match_roles[0]]
    assert _roles(team).tolist() == assign(view.own_pos[1:], targets, "mmdr").target_of.tolist()


def test_bad_ball_role_is_a_clear_error() -> None:
    with pytest.raises(ValueError, match="ball_role must be one of 'keep', 'leave', got 'drop'"):
        FormationTeam("mmdr", TeamStyle(ball_role="drop"))
    with pytest.raises(ValueError, match="does not apply to the 'bidding' assigner"):
        FormationTeam("bidding", TeamStyle(ball_role="leave"))


def test_leave_variants_are_registered_and_resolve() -> None:
    pyproject = tomllib.loads((Path(__file__).parents[3] / "pyproject.toml").read_text())
    entry_points = pyproject["project"]["entry-points"]["soccer_sim.teams"]
    assert {"mmdr-leave", "mmd+msd2-leave", "static-leave"} <= set(builtin.LEAVE_VARIANTS)
    assert "bidding-leave" not in builtin.LEAVE_VARIANTS
    keep_style = resolve_team("mmdr")[0].style if "mmdr" in entry_points else TeamStyle()
    for name in builtin.LEAVE_VARIANTS:
        team, _ = resolve_team(entry_points[name])  # the registry's path resolution of the entry point
        assert isinstance(team, FormationTeam) and team.name == name
        assert team.assigner_name == name.removesuffix("-leave") and team.style.ball_role == "leave"
        assert replace(team.style, ball_role="keep") == keep_style  # otherwise the same team
