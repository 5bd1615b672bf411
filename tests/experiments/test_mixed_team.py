"""Mixed (drop-in) teams: player i follows its own member team's decision."""

from __future__ import annotations

import numpy as np
import pytest

from experiments.mixed_team import MixedTeam, member_names, mixed_name, mixed_team
from soccer_sim import MatchConfig, SideInfo, TeamError, TeamView, run_match
from tests.experiments.helpers import SCRIPTED

FORWARD, SIDEWAYS = SCRIPTED + "Forward", SCRIPTED + "Sideways"


def view(n: int = 11) -> TeamView:
    zeros = np.zeros((n, 2))
    return TeamView(own_pos=np.arange(2 * n, dtype=float).reshape(n, 2), own_vel=zeros, opp_pos=zeros,
                    opp_vel=zeros, ball=np.zeros(2), ball_vel=np.zeros(2), stamina=np.full(n, 8000.0))


def test_each_player_takes_its_own_teams_row() -> None:
    members = [FORWARD if i % 3 == 0 else SIDEWAYS for i in range(11)]    # goalkeeper (0) is Forward
    team = MixedTeam(members)
    team.reset(SideInfo(0, "m", "o", 11, 0, 11, 0), MatchConfig(), np.random.default_rng(0))
    command = team.act(view())
    forward = np.array([m == FORWARD for m in members])
    assert np.allclose(command.dash[forward], (0.01, 0.0)) and np.allclose(command.dash[~forward], (0.0, 0.02))
    assert np.allclose(command.kick[forward], (0.5, 0.0)) and np.allclose(command.kick[~forward], 0.0)
    assert command.catch is True                     # the goalkeeper's team asks to catch
    assert all(t.seen == [(11, 2)] for t in team.teams)  # every member team saw the full team view
    team = MixedTeam([SIDEWAYS] + [FORWARD] * 10)
    team.reset(SideInfo(0, "m", "o", 11, 0, 11, 0), MatchConfig(), np.random.default_rng(0))
    assert team.act(view()).catch is False


def test_names_round_trip_and_bad_members() -> None:
    name = mixed_name(["chaser", "idle", "chaser"])
    assert name == "mixed(chaser|idle|chaser)" and member_names(name) == ["chaser", "idle", "chaser"]
    assert mixed_team(name).codes == ["chaser", "idle"]
    with pytest.raises(ValueError, match="member of a mixed team"):
        mixed_name(["a|b"])
    team = MixedTeam(["chaser"] * 3)
    with pytest.raises(TeamError, match="3 member players but the match plays 11"):
        team.reset(SideInfo(0, "m", "o", 11, 0, 11, 0), MatchConfig(), np.random.default_rng(0))


class _PlayerDistances:
    """Recorder: distance covered by every player (absolute frame)."""

    def on_start(self, match) -> None:
        self.last = match.state.pos.copy()
        self.total = np.zeros(len(self.last))

    def on_cycle(self, match) -> None:
        self.total += np.linalg.norm(match.state.pos - self.last, axis=1)
        self.last = match.state.pos.copy()

    def on_end(self, match) -> None:
        pass


def test_a_mixed_match_is_deterministic_and_each_player_plays_its_own_code() -> None:
    config = MatchConfig(max_cycles=300)
    members = ["idle"] + ["chaser"] * 5 + ["idle"] * 5
    first, again = _PlayerDistances(), _PlayerDistances()
    result = run_match(MixedTeam(members), "idle", seed=4, config=config, recorders=[first])
    repeat = run_match(MixedTeam(members), "idle", seed=4, config=config, recorders=[again])
    assert result.statistics[0].as_dict() == repeat.statistics[0].as_dict()
    assert np.array_equal(first.total, again.total)
    home = first.total[:11]
    assert home[1:6].min() > 10.0 * max(home[6:].max(), home[0], 0.1)   # chasers run, idle players barely move


def test_a_mixed_team_without_goalkeeper_plays_a_scenario() -> None:
    """On a side with no goalkeeper nobody catches (player 0 would otherwise ask to catch)."""
    from soccer_sim.scenarios import get_scenario

    team = MixedTeam([FORWARD, SIDEWAYS, FORWARD])
    info = SideInfo(0, "m", "o", 3, -1, opponents=0, opponent_goalie_index=-1)
    team.reset(info, MatchConfig(), np.random.default_rng(0))
    assert team.act(view(3)).catch is False
    scenario = get_scenario("3-vs-1-with-keeper")
    result = run_match(mixed_team(mixed_name(["chaser", "idle", "chaser"])), "idle", seed=3, scenario=scenario)
    assert result.end_reason and result.score is not None
