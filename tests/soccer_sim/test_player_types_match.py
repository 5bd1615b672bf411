"""Player types in a match: the teams' choice, per-player parameters in play, and what the
teams are told."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim.config import MatchConfig
from soccer_sim.match import Match
from soccer_sim.team import TeamCommand, TeamError
from soccer_sim.trivial_teams import ChaserTeam, IdleTeam

CONFIG = MatchConfig(max_cycles=120)


def _top(t) -> float:
    """A type's reachable top speed (m/cycle): full-power dashes against its decay, capped."""
    return min(t.player_speed_max, 100.0 * t.dash_power_rate * t.effort_max / (1.0 - t.player_decay))


class Sprinters:
    """Every player dashes flat out towards +y; players 1 and 2 take the fastest and the
    slowest drawn types (or ``picks``), the others the default type."""

    def __init__(self, picks=None) -> None:
        self.picks = picks
        self.info = None

    def choose_player_types(self, types, side_info):
        if self.picks is not None:
            return self.picks
        drawn = sorted(types[1:], key=_top)
        ids = [0] * side_info.players_per_team
        ids[1], ids[2] = drawn[-1].id, drawn[0].id
        return ids

    def reset(self, side_info, config, rng) -> None:
        self.info = side_info
        n = side_info.players_per_team
        self._command = TeamCommand(dash=np.tile([0.0, 10.0], (n, 1)), kick=np.zeros((n, 2)))

    def act(self, view) -> TeamCommand:
        return self._command


class DefaultChooser(Sprinters):
    def choose_player_types(self, types, side_info):
        return [0] * side_info.players_per_team


def _speeds(home, seed=3, cycles=20):
    match = Match(home, IdleTeam(), seed=seed, config=CONFIG)
    match.start()
    late = []
    for cycle in range(cycles):
        match.step()
        if cycle >= cycles // 2:  # running at top speed: the mean speed of the later cycles
            late.append(np.hypot(match.state.vel[:, 0], match.state.vel[:, 1]))
    return match, np.mean(late, axis=0)


def test_a_fast_type_runs_faster_and_a_slow_one_slower():
    match, top = _speeds(Sprinters())
    fast, slow = match.player_types[match.type_ids[1]], match.player_types[match.type_ids[2]]
    assert _top(fast) > _top(slow) + 0.05
    # player_decay scales the speed measured after the move's decay; compare speeds before it
    before = top / np.array([match.player_types[i].player_decay for i in match.type_ids])
    assert before[1] > before[2] + 0.05
    assert before[0] == pytest.approx(_top(match.player_types[0]), abs=0.05)
    assert before[1] == pytest.approx(_top(fast), abs=0.05) and before[2] == pytest.approx(_top(slow), abs=0.05)


def test_a_team_that_chooses_only_the_default_type_plays_exactly_as_one_that_never_chooses():
    a, top_a = _speeds(DefaultChooser())
    b, top_b = _speeds(_Plain())
    assert np.array_equal(top_a, top_b) and np.array_equal(a.state.pos, b.state.pos)
    assert not a.type_ids.any() and not b.type_ids.any()


class _Plain:
    """A sprinter without the choosing hook."""

    def reset(self, side_info, config, rng) -> None:
        Sprinters.reset(self, side_info, config, rng)

    def act(self, view) -> TeamCommand:
        return self._command


def test_the_teams_are_told_their_own_parameters_and_the_opponents_types():
    home, away = Sprinters(), Sprinters(picks=[0, 0, 0, 0, 0, 0, 0, 5, 6, 7, 0])
    match = Match(home, away, seed=4, config=CONFIG)
    match.start()
    assert home.info.own_types == tuple(int(i) for i in match.type_ids[:11])
    assert home.info.opponent_types == (0, 0, 0, 0, 0, 0, 0, 5, 6, 7, 0) == away.info.own_types
    assert away.info.opponent_types == home.info.own_types
    assert home.info.player_types is match.player_types and len(home.info.player_types) == 18
    assert away.info.own_type(8) == match.player_types[6]
    assert match.kinematics.types[11 + 8, 6] == match.player_types[6].player_decay


def test_every_view_shows_both_sides_types_read_only():
    home, away = Sprinters(), Sprinters(picks=[0, 0, 0, 0, 0, 0, 0, 5, 6, 7, 0])
    match = Match(home, away, seed=4, config=CONFIG)
    match.start()
    match.step()
    home_view, away_view = (frame.view for frame in match.frames)
    assert tuple(away_view.own_types) == (0, 0, 0, 0, 0, 0, 0, 5, 6, 7, 0) == tuple(home_view.opp_types)
    assert tuple(home_view.own_types) == home.info.own_types == tuple(away_view.opp_types)
    with pytest.raises(ValueError):
        home_view.own_types[0] = 3


def test_types_are_deterministic_per_seed_and_play_differs_from_default():
    a, b = Match(ChaserTeam(), IdleTeam(), seed=9, config=CONFIG), Match(ChaserTeam(), IdleTeam(), seed=9,
                                                                        config=CONFIG)
    assert a.player_types == b.player_types
    assert Match(ChaserTeam(), IdleTeam(), seed=10, config=CONFIG).player_types != a.player_types


def test_pt_max_is_enforced_in_a_match_naming_the_team_and_player():
    match = Match(Sprinters(picks=[0, 3, 3, 0, 0, 0, 0, 0, 0, 0, 0]), IdleTeam(), seed=1, config=CONFIG)
    with pytest.raises(TeamError, match=r"player 2: player type 3 is chosen by more than pt_max=1") as err:
        match.start()
    assert err.value.team_name == match.team_names[0] and err.value.player == 2


def test_a_choosing_hook_that_raises_is_the_teams_failure():
    class Broken(Sprinters):
        def choose_player_types(self, types, side_info):
            raise RuntimeError("no idea")

    with pytest.raises(TeamError, match="choose_player_types\\(\\) raised RuntimeError: no idea"):
        Match(Broken(), IdleTeam(), seed=1, config=CONFIG).start()


def test_the_game_log_lists_the_drawn_types_and_each_players_type(tmp_path):
    from soccer_sim.rcg import RcgRecorder, read_rcg

    path = tmp_path / "types.rcg"
    home = Sprinters(picks=[0, 4, 0, 0, 0, 0, 0, 0, 0, 0, 9])
    match = Match(home, IdleTeam(), seed=2, config=MatchConfig(max_cycles=5), recorders=[RcgRecorder(path)])
    match.run()
    log = read_rcg(path)
    assert [int(t["id"]) for t in log.player_types] == list(range(18))
    for line, t in zip(log.player_types, match.player_types):
        assert float(line["player_decay"]) == pytest.approx(t.player_decay, rel=1e-5)
        assert float(line["kickable_margin"]) == pytest.approx(t.kickable_margin, rel=1e-5)
        assert float(line["effort_max"]) == pytest.approx(t.effort_max, rel=1e-5)
        assert float(line["catchable_area_l_stretch"]) == pytest.approx(t.catchable_area_l_stretch, rel=1e-5)
    show = log.shows[-1]
    types = {(p.side, p.unum): p.type for p in show.players}
    assert types[("l", 2)] == 4 and types[("l", 11)] == 9 and types[("l", 1)] == 0 and types[("r", 2)] == 0


def test_a_tacklers_type_sets_its_tackle_noise():
    from dataclasses import replace

    from soccer_sim.kinematics import Kinematics
    from soccer_sim.player_types import default_type
    from soccer_sim.state import WorldState
    from soccer_sim.tackles import Tackles

    config = MatchConfig()
    base = default_type(config)

    def push_speeds(kick_rand: float) -> list[float]:
        kin = Kinematics(config, 2)
        kin.set_types([replace(base, kick_rand=kick_rand), base])
        rng, speeds = np.random.default_rng(5), []
        for _ in range(60):
            state = WorldState((1, 1), pos=[(0.0, 0.0), (30.0, 0.0)], ball=(0.5, 0.0))
            tackles = Tackles(config, state, (-1, -1), rng, kin.types)
            outcome = tackles.resolve(state, np.array([0.0, np.nan]), np.zeros(2, dtype=bool), True,
                                      np.zeros((2, 4)), np.zeros(2, dtype=bool), np.ones(2, dtype=bool))
            tackles.push(state, outcome, kicked=False)
            speeds.append(float(np.hypot(*state.ball_vel)))
        return speeds

    quiet = push_speeds(0.0)
    assert max(quiet) - min(quiet) < 1e-9 and quiet[0] == pytest.approx(2.7)
    noisy = push_speeds(0.2)
    assert min(noisy) < 2.7 - 0.1


def test_each_players_kickable_margin_and_decay_apply():
    from dataclasses import replace

    from soccer_sim.kinematics import Kinematics
    from soccer_sim.player_types import default_type

    config = MatchConfig()
    base = default_type(config)
    kin = Kinematics(config, 2)
    kin.set_types([replace(base, kickable_margin=0.8, player_decay=0.5), base])
    reach = config.physics.kickable_distance + 0.05  # beyond the default reach, within the wider one
    pos = np.array([[0.0, 0.0], [10.0 + reach, 0.0]])
    for ball_x, expected in ((reach, [0]), (10.0, [])):  # the same distance, each player's own reach
        rows = np.zeros(2, dtype=np.int64)
        count, _ = kin.kick_candidates(pos, np.array([ball_x, 0.0]), np.ones((2, 2)), np.ones(2, dtype=bool), -1,
                                       rows)
        assert rows[:count].tolist() == expected
    vel, ball_vel = np.ones((2, 2)), np.zeros(2)
    kin.decay(vel, ball_vel)
    assert vel[:, 0].tolist() == [0.5, 0.4]


def test_the_foul_judge_uses_the_fouled_players_kickable_margin():
    from dataclasses import replace

    from soccer_sim.config import TackleConfig
    from soccer_sim.kinematics import Kinematics
    from soccer_sim.player_types import default_type
    from soccer_sim.state import EventKind
    from soccer_sim.tackles import TackleOutcome
    from tests.soccer_sim.referee_world import N, NO_TOUCH, kinds, make_world

    tackler, fouled = 5, N + 6
    config = replace(MatchConfig(), tackles=TackleConfig(foul_detect_probability=1.0))
    gap = config.physics.kickable_distance + 0.05  # the ball just beyond a default player's reach

    def fouls(margin: float | None) -> bool:
        types = None
        if margin is not None:
            kin = Kinematics(config, 2 * N)
            base = default_type(config)
            kin.set_types([replace(base, kickable_margin=margin) if row == fouled else base for row in range(2 * N)])
            types = kin.types
        ref, state, events = make_world(ball=(gap, 0.0), config=config, types=types,
                                        moves={tackler: (-1.1, 0.0), fouled: (0.0, 0.0)})
        dashed = np.zeros(2 * N, dtype=bool)
        outcome = TackleOutcome(rows=[tackler], reached=[True], fouls=[True], pushers=[tackler], dashed=dashed)
        ref.on_commands(state, NO_TOUCH, np.zeros(2, dtype=bool), outcome)
        return EventKind.FOUL in kinds(events)

    assert not fouls(None) and not fouls(config.physics.kickable_margin)
    assert fouls(config.physics.kickable_margin + 0.1)


def test_a_goalkeeper_with_a_stretched_catch_area_reaches_further_with_falling_chance():
    from dataclasses import replace

    from soccer_sim.kinematics import Kinematics
    from soccer_sim.player_types import default_type
    from soccer_sim.state import HOME, PlayMode
    from tests.soccer_sim.referee_world import N, catch, make_world

    length = CONFIG.rules.catch_length

    def caught(distance: float, stretch: float | None, seed: int = 0) -> bool:
        rng = types = None
        if stretch is not None:
            kin = Kinematics(CONFIG, 2 * N)
            base = default_type(CONFIG)
            kin.set_types([replace(base, catchable_area_l_stretch=stretch) if row == 0 else base
                           for row in range(2 * N)])
            rng, types = np.random.default_rng(seed), kin.types
        ref, state, _ = make_world(ball=(-45.0 + distance, 0.0), ball_vel=(-1.0, 0.0), moves={0: (-45.0, 0.0)},
                                   last_touch=N + 9, rng=rng, types=types)
        catch(ref, state, HOME)
        return state.play_mode == PlayMode.GOALIE_HOLDS

    assert caught(length - 0.01, None) and not caught(length + 0.05, None)
    assert not caught(length + 0.05, 1.0)  # the default type: no band, no draw
    assert not caught(1.3 * length + 0.01, 1.3)  # beyond the stretched reach
    near = sum(caught(length + 0.1 * 0.3 * length, 1.3, seed) for seed in range(200))  # chance 0.9
    far = sum(caught(length + 0.9 * 0.3 * length, 1.3, seed) for seed in range(200))  # chance 0.1
    assert 160 <= near <= 195 and 5 <= far <= 40
