"""The neck (rcssserver's ``turn_neck``): a player's command turns it within the server's
limits, its views report it, and its sees look along body plus neck (docs/simulator.md §12)."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from soccer_sim.config import MatchConfig
from soccer_sim.match import Match
from soccer_sim.perception import SeeParams
from soccer_sim.perception.config import ObservationConfig
from soccer_sim.perception.neck import turned_necks
from soccer_sim.perception.observer import Observer
from soccer_sim.rcg import RcgRecorder, read_rcg
from soccer_sim.state import WorldState
from soccer_sim.team import TeamError
from soccer_sim.trivial_teams import ChaserTeam

LIMITS = SeeParams()


def partial(cycles: int, **see) -> MatchConfig:
    return MatchConfig(observation=ObservationConfig("partial", see=SeeParams(**see)), max_cycles=cycles)


def test_a_turn_is_clipped_to_the_moment_then_the_neck_to_its_range():
    necks = np.array([0.0, 80.0, -80.0, 10.0, 0.0, 30.0])
    moments = np.array([45.0, 30.0, -500.0, np.nan, 250.0, -120.0])
    assert turned_necks(necks, moments, LIMITS).tolist() == [45.0, 90.0, -90.0, 10.0, 90.0, -90.0]
    narrow = SeeParams(min_neck_angle=-30.0, max_neck_angle=60.0, min_neck_moment=-20.0, max_neck_moment=20.0)
    assert turned_necks(np.array([0.0, 50.0, 0.0]), np.array([90.0, 90.0, -90.0]), narrow).tolist() == \
        [20.0, 60.0, -20.0]


class Asking(ChaserTeam):
    """A chaser whose command sets ``field`` to ``values(cycle, n)`` every cycle; it keeps
    what it asked and, under partial observation, copies of its views' ``recorded`` arrays."""

    def __init__(self, field: str, values, recorded: tuple[str, ...] = ()) -> None:
        self.field, self.values = field, values
        self.asked: list = []
        self.views: dict[str, list[np.ndarray]] = {name: [] for name in recorded}

    def act(self, view):
        command = super().act(view)
        if hasattr(view, "neck_angle"):  # (partial observation's views)
            for name, kept in self.views.items():
                kept.append(getattr(view, name).copy())
        asked = self.values(view.cycle, len(view.stamina))
        setattr(command, self.field, asked)
        self.asked.append(asked)
        return command


def turner(turns) -> Asking:
    """A chaser whose players turn their necks by ``turns(cycle, n)``."""
    return Asking("turn_neck", turns, ("neck_angle",))


def test_wild_turns_keep_the_neck_within_the_servers_limits_by_rcssservers_rule():
    rng = np.random.default_rng(4)
    team = turner(lambda cycle, n: rng.uniform(-500.0, 500.0, n))
    Match(team, "chaser", seed=2, config=partial(120)).run()
    reported = np.array(team.views["neck_angle"])
    assert reported[0].tolist() == [0.0] * len(reported[0])  # every neck starts along the body
    assert reported.min() >= LIMITS.min_neck_angle and reported.max() <= LIMITS.max_neck_angle
    assert reported.min() == LIMITS.min_neck_angle and reported.max() == LIMITS.max_neck_angle
    for before, asked, after in zip(reported, team.asked, reported[1:]):
        assert np.array_equal(after, turned_necks(before, asked, LIMITS))  # the command's turn, next cycle
    assert 0.0 < np.abs(np.diff(reported, axis=0)).max() <= LIMITS.max_neck_moment


def test_under_full_observation_a_turn_is_checked_and_changes_nothing():
    team = turner(lambda cycle, n: np.full(n, 30.0))
    result = Match(team, "chaser", seed=2, config=MatchConfig(max_cycles=30)).run()
    assert result.cycles == 30
    plain = Match("chaser", "chaser", seed=2, config=MatchConfig(max_cycles=30)).run()
    assert np.array_equal(result.state.pos, plain.state.pos)


@pytest.mark.parametrize("turns, message, player", [
    (lambda n: np.full(n, np.inf), r"command.turn_neck is infinite: inf", 0),
    (lambda n: np.r_[np.zeros(n - 1), -np.inf], r"command.turn_neck is infinite: -inf", "last"),
    (lambda n: np.zeros(n + 1), r"command.turn_neck must have shape \(\d+,\), got \(\d+,\)", None),
    (lambda n: np.array(["left"] * n), r"command.turn_neck must be numeric, got dtype <U4", None),
    (lambda n: [object()] * n, r"command.turn_neck is not a numeric array", None),
])
def test_a_bad_neck_turn_is_a_team_error_naming_the_field(turns, message, player):
    team = turner(lambda cycle, n: turns(n))
    with pytest.raises(TeamError, match=message) as info:
        Match(team, "chaser", seed=1, config=partial(5)).run()
    assert info.value.team_name == "Asking"
    assert info.value.player == (10 if player == "last" else player)


def one_runner_observer(send_step: int = 100) -> tuple[Observer, WorldState]:
    """One player per side (every cycle a see): home's at the origin sprinting along +x, the
    ball 14 m away up and behind it (135 degrees from its motion), the away player far off."""
    config = ObservationConfig("partial", see=SeeParams(send_step=send_step, exact_self=True))
    state = WorldState((1, 1), pos=[(0.0, 0.0), (40.0, -30.0)], vel=[(1.0, 0.0), (0.0, 0.0)], ball=(-10.0, 10.0))
    observer = Observer(config, (1, 1), ("home", "away"), decay=np.full(2, 0.4), inertia=np.full(2, 5.0),
                        type_ids=np.zeros(2, dtype=np.int64), rng=np.random.default_rng(0))
    return observer, state


def test_the_view_cone_follows_body_plus_neck():
    observer, state = one_runner_observer()
    home = observer.observe(state)[0]
    # a sprinter's body turns towards the ball by at most 180 / (1 + 5 * 1.0) = 30 degrees
    assert home.body_direction[0] == pytest.approx(30.0)
    assert home.saw[0] and not home.ball_seen[0]  # 105 degrees off the body: out of the cone, 14 m away
    observer.turn_necks(np.array([90.0, 0.0]), np.ones(2, dtype=bool))
    state.cycle += 1
    home = observer.observe(state)[0]
    assert home.neck_angle[0] == 90.0
    assert home.ball_seen[0]  # the face (120 degrees) has the ball 15 degrees off it
    assert home.ball_direction[0] == pytest.approx(105.0, abs=0.6)  # reported relative to the body
    assert np.hypot(*(home.ball[0] - (-10.0, 10.0))) < 1.0
    observer.turn_necks(np.array([-180.0, 0.0]), np.ones(2, dtype=bool))
    state.cycle += 1
    home = observer.observe(state)[0]
    assert home.neck_angle[0] == -90.0 and not home.ball_seen[0]


def test_a_player_off_the_pitch_keeps_its_neck():
    observer, _ = one_runner_observer()
    observer.turn_necks(np.array([40.0, 40.0]), np.array([True, False]))
    assert observer.necks.tolist() == [40.0, 0.0]


def test_sensed_velocity_is_relative_to_the_face_as_rcssservers():
    """The sense_body velocity direction is rounded relative to the face: with the neck at half
    a degree the rounding moves by that half degree, and the speed stays."""
    config = replace(ObservationConfig("partial"), see=SeeParams(send_step=100))
    state = WorldState((1, 1), pos=[(0.0, 0.0), (40.0, -30.0)], vel=[(0.3, 0.1234), (0.0, 0.0)], ball=(5.0, 0.0))
    speeds = []
    for neck in (0.0, 0.5):
        observer = Observer(config, (1, 1), ("home", "away"), decay=np.full(2, 0.4), inertia=np.full(2, 5.0),
                            type_ids=np.zeros(2, dtype=np.int64), rng=np.random.default_rng(0))
        observer.turn_necks(np.array([neck, 0.0]), np.ones(2, dtype=bool))
        speeds.append(observer.observe(state)[0].velocity[0].copy())
    assert np.hypot(*speeds[0]) == pytest.approx(np.hypot(*speeds[1]))
    assert not np.allclose(speeds[0], speeds[1], atol=1e-6)


def test_the_game_log_shows_each_players_neck(tmp_path):
    """The .rcg's NECK is the neck after the cycle's turns: shirt 1 of the left side turns
    +30 degrees a cycle up to the limit, the others never."""
    path = tmp_path / "neck.rcg"
    team = turner(lambda cycle, n: np.r_[30.0, np.zeros(n - 1)])
    Match(team, "chaser", seed=2, config=partial(8), recorders=[RcgRecorder(path)]).run()
    shows = read_rcg(path).shows
    necks = [(show.cycle, show.player("l", 1).neck) for show in shows]
    assert necks[:5] == [(0, 0.0), (1, 30.0), (2, 60.0), (3, 90.0), (4, 90.0)]  # (the show at the start: 0)
    assert all(show.player("l", 2).neck == 0.0 and show.player("r", 1).neck == 0.0 for show in shows)
