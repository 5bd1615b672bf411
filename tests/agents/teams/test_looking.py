"""Where the built-in team's players look (agents.teams.looking): each player's neck turn from
its own row, at the ball or over the field it has seen least recently, within the server's
limits in a match."""

from __future__ import annotations

from dataclasses import replace

import numpy as np
import pytest

from agents.teams.builtin import counter_442_team
from agents.teams.formation_team import FormationTeam
from agents.teams.looking import LookParams, Looker
from agents.teams.style import TeamStyle
from soccer_sim.config import MatchConfig
from soccer_sim.match import Match
from soccer_sim.perception.config import ObservationConfig
from soccer_sim.perception.views import PlayerViews

PARTIAL = MatchConfig(observation=ObservationConfig("partial"))
LIMITS = PARTIAL.observation.see


def views_of(n: int, position, body, neck, saw=True) -> PlayerViews:
    """Hand-made views of ``n`` players with the senses the looker reads (the rest empty)."""
    k = 2 * n - 1
    return PlayerViews(
        stamina=np.full(n, 8000.0), effort=np.ones(n), capacity=np.full(n, np.inf), frozen=np.zeros(n, dtype=np.int64),
        present=np.ones(n, dtype=bool), player_types=np.zeros(n, dtype=np.int64), holds_ball=np.zeros(n, dtype=bool),
        position=np.array(position, dtype=float).reshape(n, 2), velocity=np.zeros((n, 2)),
        body_direction=np.broadcast_to(np.asarray(body, dtype=float), (n,)).copy(), localised=np.zeros(n, dtype=bool),
        saw=np.broadcast_to(np.asarray(saw, dtype=bool), (n,)).copy(), ball_seen=np.zeros(n, dtype=bool),
        ball=np.full((n, 2), np.nan), ball_distance=np.full(n, np.nan), ball_direction=np.full(n, np.nan),
        seen_count=np.zeros(n, dtype=np.int64), seen_position=np.full((n, k, 2), np.nan),
        seen_distance=np.full((n, k), np.nan), seen_direction=np.full((n, k), np.nan),
        seen_side=np.zeros((n, k), dtype=np.int8), seen_number=np.full((n, k), -1, dtype=np.int8),
        neck_angle=np.broadcast_to(np.asarray(neck, dtype=float), (n,)).copy())


def test_a_stale_or_near_ball_is_looked_at_and_a_fresh_far_one_is_not():
    looker = Looker(LookParams(), 4, PARTIAL)
    position = [(0.0, 0.0)] * 4
    ball = np.array([(30.0, 30.0), (30.0, 30.0), (5.0, 5.0), (1.0, 1.0)])  # 45 degrees away
    age = np.array([3, 0, 0, 0])
    turns = looker.turn_necks(views_of(4, position, 0.0, 10.0), ball, age)
    assert turns[0] == pytest.approx(35.0)  # stale: the face to the ball (neck 45)
    assert turns[2] == pytest.approx(35.0)  # 7 m away: watched
    assert turns[1] != pytest.approx(35.0) and turns[3] != pytest.approx(35.0)  # fresh and far; sensed anyway
    # a ball straight behind cannot be brought into the cone: the player scans
    behind = Looker(LookParams(), 1, PARTIAL).turn_necks(views_of(1, [(0.0, 0.0)], 0.0, 0.0), np.array([(-20.0, 0.0)]), np.array([9]))
    assert np.isfinite(behind[0]) and abs(behind[0]) <= LIMITS.max_neck_angle


def test_a_scan_looks_where_the_player_has_not_looked_and_keeps_within_the_neck_range():
    looker = Looker(LookParams(), 1, PARTIAL)
    ball, fresh = np.array([(40.0, 0.0)]), np.array([0])
    neck, faces = 0.0, []
    for _ in range(8):  # in the middle of the pitch, the body along +x, the ball far ahead and fresh
        turn = looker.turn_necks(views_of(1, [(0.0, 0.0)], 0.0, neck), ball, fresh)[0]
        neck += turn
        assert LIMITS.min_neck_angle <= neck <= LIMITS.max_neck_angle and abs(turn) <= LIMITS.max_neck_moment
        faces.append(neck)
    assert min(faces) < -30.0 and max(faces) > 30.0  # it looks to both sides in turn
    assert len(set(faces[:3])) == 3


def test_a_scan_keeps_its_face_on_the_pitch():
    """On the right touch line (team frame, y = -34) with the body along +x, a scan never looks
    out over the stands while the pitch lies the other way."""
    looker = Looker(LookParams(), 1, PARTIAL)
    neck = 0.0
    for _ in range(6):
        neck += looker.turn_necks(views_of(1, [(0.0, -33.0)], 0.0, neck), np.array([(40.0, -33.0)]), np.array([0]))[0]
        assert neck >= -20.0


def test_a_players_neck_turn_depends_on_its_own_row_only():
    rng = np.random.default_rng(3)
    n, cycles = 6, 25
    looker, other = Looker(LookParams(), n, PARTIAL), Looker(LookParams(), n, PARTIAL)
    neck, other_neck = np.zeros(n), np.zeros(n)
    for _ in range(cycles):
        position = rng.uniform(-40.0, 40.0, (n, 2))
        body = rng.uniform(-180.0, 180.0, n)
        ball = rng.uniform(-40.0, 40.0, (n, 2))
        age = rng.integers(0, 4, n)
        saw = rng.random(n) < 0.7
        mine = looker.turn_necks(views_of(n, position, body, neck, saw), ball, age)
        # every row but 0 changed: row 0's turn must stay
        position[1:], body[1:], ball[1:] = rng.uniform(-40, 40, (n - 1, 2)), rng.uniform(-180, 180, n - 1), 0.0
        age[1:], saw[1:] = 9, ~saw[1:]
        theirs = other.turn_necks(views_of(n, position, body, other_neck, saw), ball, age)
        assert theirs[0] == mine[0]
        assert not np.array_equal(theirs[1:], mine[1:]) or n == 1
        neck, other_neck = neck + mine, other_neck + theirs
    assert np.array_equal(looker.sector_age[0], other.sector_age[0])


def test_bad_look_parameters_are_refused_by_name():
    with pytest.raises(ValueError, match="LookParams.sector"):
        LookParams(sector=7.0)
    with pytest.raises(ValueError, match="LookParams.fresh_cycles"):
        LookParams(fresh_cycles=-1)
    with pytest.raises(ValueError, match="LookParams.watch_distance"):
        LookParams(watch_distance=float("nan"))


class NeckWatch:
    """A recorder of the home team's neck angles as its views report them, each cycle checked
    against the observer's after the cycle before (the turns of a cycle's commands show in the
    next cycle's sense_body)."""

    def __init__(self) -> None:
        self.necks: list[np.ndarray] = []
        self.turned = None

    def on_start(self, match) -> None:
        pass

    def on_cycle(self, match) -> None:
        observer = match.observer
        home = observer.views[0]
        if self.turned is not None:
            assert np.array_equal(home.neck_angle, self.turned)
        self.turned = observer.necks[:observer.sizes[0]].copy()
        self.necks.append(home.neck_angle.copy())

    def on_end(self, match) -> None:
        pass


def test_scanning_players_keep_their_necks_within_the_servers_limits_over_a_match():
    watch = NeckWatch()
    team = FormationTeam("mmdr", TeamStyle(scans=True), name="mmdr")
    Match(team, counter_442_team(), seed=5, config=replace(PARTIAL, max_cycles=400), recorders=[watch]).run()
    necks = np.array(watch.necks)
    assert necks.min() >= LIMITS.min_neck_angle and necks.max() <= LIMITS.max_neck_angle
    assert np.abs(np.diff(necks, axis=0)).max() <= LIMITS.max_neck_moment
    assert necks.min() < -45.0 and necks.max() > 45.0  # they do look around
    assert (np.diff(necks, axis=0) != 0.0).mean() > 0.3


def test_a_team_that_does_not_scan_never_turns_its_neck():
    watch = NeckWatch()
    Match(FormationTeam("mmdr", TeamStyle(), name="mmdr"), counter_442_team(), seed=5,
          config=replace(PARTIAL, max_cycles=100), recorders=[watch]).run()
    assert not np.array(watch.necks).any()


def test_under_full_observation_scanning_changes_nothing():
    config = MatchConfig(max_cycles=150)
    plain = Match(FormationTeam("mmdr", TeamStyle(), name="mmdr"), counter_442_team(), seed=2, config=config).run()
    scanning = Match(FormationTeam("mmdr", TeamStyle(scans=True), name="mmdr"), counter_442_team(), seed=2,
                     config=config).run()
    assert np.array_equal(plain.state.pos, scanning.state.pos)
