"""Partial observation in the match: what each player's view holds, when messages arrive, and
that the model is seeded and deterministic (docs/simulator.md §14)."""

from __future__ import annotations

import math
import subprocess
import sys
from dataclasses import replace

import numpy as np
import pytest

from soccer_sim import MatchConfig, run_match
from soccer_sim.match import Match
from soccer_sim.perception import AudioParams, SeeParams
from soccer_sim.perception.config import ObservationConfig
from soccer_sim.perception.views import OPPONENT, TEAMMATE, PlayerViews
from soccer_sim.team import TeamCommand, TeamError
from soccer_sim.trivial_teams import ChaserTeam

PARTIAL = ObservationConfig("partial")


def partial_config(cycles: int, **see) -> MatchConfig:
    return MatchConfig(observation=replace(PARTIAL, see=SeeParams(**see)), max_cycles=cycles)


class Talker(ChaserTeam):
    """A chaser whose players say ``msg(cycle, i)`` (None: silent) and which records its views."""

    def __init__(self, msg=lambda cycle, i: f"c{cycle}p{i}") -> None:
        self.msg = msg
        self.heard: list[tuple[int, tuple, tuple]] = []

    def act(self, view):
        command = super().act(view)
        self.heard.append((view.cycle, view.heard_mates, view.heard_opponents))
        command.say = [self.msg(view.cycle, i) for i in range(view.n)]
        return command


def test_full_observation_is_the_default_and_refuses_nothing():
    assert MatchConfig().observation.mode == "full"
    result = run_match("chaser", "idle", seed=3, config=MatchConfig(max_cycles=50))
    assert result.cycles == 50


def test_a_team_written_for_the_full_view_is_refused_by_name():
    class FullOnly:
        def reset(self, side_info, config, rng):
            pass

        def act(self, view):  # pragma: no cover - never called
            raise AssertionError

    with pytest.raises(TeamError, match="cannot play under partial observation") as info:
        Match(FullOnly(), "chaser", config=partial_config(10))
    assert info.value.team_name == "FullOnly"


def test_teams_get_player_views_and_never_see_beyond_cone_or_range():
    """Every listed player lies in the observer's cone (within max_observation_length) or within
    visible_distance, is never the observer itself, and its reported distance is the server's
    quantisation of the true one."""
    match = Match(ChaserTeam(), ChaserTeam(), seed=2, config=partial_config(300))
    match.start()
    params = match.config.observation.see
    checked = 0
    while match.state.cycle < 300:
        state = match.state
        pos, vel, ball = state.pos.copy(), state.vel.copy(), state.ball.copy()
        match.step()  # observes the state copied above, then moves
        obs = match.observer
        views = obs.views
        rows = obs.seen_rows
        for team, view in enumerate(views):
            assert isinstance(view, PlayerViews)
            first = 0 if team == 0 else match.sizes[0]
            for i in range(view.n):
                p = first + i
                k = int(view.seen_count[i])
                assert k == 0 or view.saw[i]
                assert np.all(np.isnan(view.seen_distance[i, k:]))
                body = math.radians(view.body_direction[i]) + (0.0 if state.attack_direction(team) > 0 else math.pi)
                for c in range(k):
                    q = rows[p, c]
                    assert q != p
                    d = pos[q] - pos[p]
                    dist = math.hypot(*d)
                    rel = math.degrees(math.atan2(d[1], d[0]) - body)
                    rel = (rel + 180.0) % 360.0 - 180.0
                    in_cone = abs(rel) < params.visible_angle / 2 + 1e-9 and dist < params.max_observation_length
                    assert in_cone or dist <= params.visible_distance
                    assert abs(view.seen_distance[i, c] - dist) <= 0.06 * dist + 0.051
                    side = view.seen_side[i, c]
                    if side != 0:
                        assert side == (TEAMMATE if (q < match.sizes[0]) == (team == 0) else OPPONENT)
                    if view.seen_number[i, c] >= 0:
                        assert view.seen_number[i, c] == q - (0 if q < match.sizes[0] else match.sizes[0])
                    checked += 1
                if view.ball_seen[i]:
                    d = ball - pos[p]
                    assert abs(view.ball_distance[i] - math.hypot(*d)) <= 0.06 * math.hypot(*d) + 0.051
    assert checked > 1000


def test_sees_arrive_on_two_cycles_of_three_and_beliefs_stay_close():
    match = Match(ChaserTeam(), ChaserTeam(), seed=5, config=partial_config(120))
    match.start()
    saw = []
    errors = []
    while match.state.cycle < 120:
        truth = match.state.pos.copy()
        match.step()
        views = match.observer.views
        saw.append(np.concatenate([v.saw for v in views]))
        sign = np.repeat([match.state.attack_direction(0), match.state.attack_direction(1)], match.sizes)
        belief = np.concatenate([v.position for v in views]) * sign[:, None]
        errors.append(np.hypot(*(belief - truth).T))
    saw = np.array(saw)
    assert np.allclose(saw.mean(axis=0), 2 / 3, atol=0.02)  # 80 sees in 120 cycles per player
    assert np.median(np.concatenate(errors)) < 0.3


def test_a_message_is_heard_exactly_one_cycle_later_within_range_and_one_per_side():
    home, away = Talker(), Talker(lambda cycle, i: f"o{cycle}")
    match = Match(home, away, seed=1, config=partial_config(60))
    result_cycles = []
    match.start()
    while match.state.cycle < 60:
        pos = match.state.pos.copy()
        match.step()
        result_cycles.append(pos)
    for cycle, mates, opponents in home.heard:
        for i in range(len(mates)):
            assert len(mates[i]) <= 1 and len(opponents[i]) <= 1  # hear_max per side
            for speaker, msg in mates[i]:
                assert msg == f"c{cycle - 1}p{speaker}"
                assert speaker != i
                assert np.hypot(*(result_cycles[cycle - 1][i] - result_cycles[cycle - 1][speaker])) <= 50.0
            for msg in opponents[i]:
                assert msg == f"o{cycle - 1}"
    assert home.heard[0][1] == ((),) * 11  # nothing was said before cycle 0
    assert sum(len(m) for _, mates, _ in home.heard for m in mates) > 500


def test_a_message_out_of_range_is_not_heard():
    far = AudioParams(audio_cut_dist=0.5)
    config = MatchConfig(observation=replace(PARTIAL, audio=far), max_cycles=20)
    home = Talker()
    run_match(home, ChaserTeam(), seed=0, config=config)
    heard = [m for _, mates, _ in home.heard[:3] for m in mates if m]
    assert heard == []  # at the kick-off nobody stands within 0.5 m of a team-mate


@pytest.mark.parametrize("say, fault", [
    (lambda cycle, i: "x" * 11, "more than say_msg_size"),
    (lambda cycle, i: "a,b", "characters the server refuses"),
    (lambda cycle, i: 5, "must be a str or None"),
])
def test_bad_messages_are_a_team_error_naming_the_player(say, fault):
    with pytest.raises(TeamError, match=fault) as info:
        run_match(Talker(say), "chaser", seed=0, config=partial_config(5))
    assert info.value.player == 0


def test_say_must_hold_one_message_per_player():
    class WrongLength(ChaserTeam):
        def act(self, view):
            command = super().act(view)
            command.say = ["hi"]
            return command

    with pytest.raises(TeamError, match="1 say messages for 11 players"):
        run_match(WrongLength(), "chaser", seed=0, config=partial_config(3))
    # under full observation a bad message is refused too (it reaches nobody)
    with pytest.raises(TeamError, match="1 say messages for 11 players"):
        run_match(WrongLength(), "chaser", seed=0, config=MatchConfig(max_cycles=3))


def test_partial_observation_changes_play_and_omniscience_options_work():
    full = run_match("chaser", "chaser", seed=4, config=MatchConfig(max_cycles=400))
    partial = run_match("chaser", "chaser", seed=4, config=partial_config(400))
    exact = run_match("chaser", "chaser", seed=4, config=partial_config(400, exact_self=True, omnidirectional=True))
    assert not np.array_equal(full.state.pos, partial.state.pos)
    assert not np.array_equal(partial.state.pos, exact.state.pos)


def test_exact_self_gives_the_true_position():
    match = Match(ChaserTeam(), ChaserTeam(), seed=5, config=partial_config(30, exact_self=True))
    match.start()
    while match.state.cycle < 30:
        truth = match.state.pos.copy()
        match.step()
        sign = match.state.attack_direction(0)
        np.testing.assert_allclose(match.observer.views[0].position * sign, truth[:11])


_SCRIPT = """
from soccer_sim import MatchConfig, run_match
from soccer_sim.perception.config import ObservationConfig
r = run_match("chaser", "chaser", seed=9, config=MatchConfig(observation=ObservationConfig("partial"), max_cycles=300))
print(r.score, r.state.pos.tobytes().hex())
"""


def test_a_partial_match_is_the_same_in_another_process():
    here = run_match("chaser", "chaser", seed=9, config=partial_config(300))
    out = subprocess.run([sys.executable, "-c", _SCRIPT], capture_output=True, text=True, check=True).stdout.split()
    assert out[-1] == here.state.pos.tobytes().hex()


def test_sent_off_players_are_neither_seen_nor_see():
    match = Match(ChaserTeam(), ChaserTeam(), seed=1, config=partial_config(20))
    match.start()
    match.state.present[3] = False
    match.step()
    obs = match.observer
    assert not obs.views[0].saw[3] and obs.views[0].seen_count[3] == 0
    assert not np.any(obs.seen_rows == 3)
