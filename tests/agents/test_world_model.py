"""Each player's own world model (agents.teams.world_model): filtered ball, players by number or
by nearest, team-mates' messages, and that a player's model uses only its own observations."""

from __future__ import annotations

import numpy as np

from agents.messages import TeamMessage, encode
from agents.teams.speaking import speaker_of
from agents.teams.belief_kernels import AGE_NEVER
from agents.teams.world_model import TeamBeliefs
from soccer_sim import MatchConfig
from soccer_sim.match import Match
from soccer_sim.perception.config import ObservationConfig
from soccer_sim.perception.views import OPPONENT, TEAMMATE, PlayerViews
from soccer_sim.trivial_teams import ChaserTeam

N, M = 3, 2
K = N + M - 1
CONFIG = MatchConfig()


def views(cycle: int, **rows) -> PlayerViews:
    """Hand-built views of a 3-player team (nobody sees anything unless given)."""
    base = dict(stamina=np.full(N, 8000.0), effort=np.ones(N), capacity=np.full(N, np.inf),
                frozen=np.zeros(N, np.int64), present=np.ones(N, bool), player_types=np.zeros(N, np.intp),
                holds_ball=np.zeros(N, bool), position=np.array([[-10.0, 0.0], [0.0, 5.0], [10.0, -5.0]]),
                velocity=np.zeros((N, 2)), body_direction=np.zeros(N), localised=np.ones(N, bool),
                saw=np.ones(N, bool), ball_seen=np.zeros(N, bool), ball=np.full((N, 2), np.nan),
                ball_distance=np.full(N, np.nan), ball_direction=np.full(N, np.nan),
                seen_count=np.zeros(N, np.int64), seen_position=np.full((N, K, 2), np.nan),
                seen_distance=np.full((N, K), np.nan), seen_direction=np.full((N, K), np.nan),
                seen_side=np.zeros((N, K), np.int8), seen_number=np.full((N, K), -1, np.int8))
    base.update(rows)
    return PlayerViews(cycle=cycle, **base)


def see_ball_at(points: dict[int, tuple[float, float]], cycle: int, **extra) -> PlayerViews:
    v = views(cycle, **extra)
    for i, at in points.items():
        v.ball_seen[i] = True
        v.ball[i] = at
        v.ball_distance[i] = np.hypot(*(np.array(at) - v.position[i]))
    return v


def test_a_rolling_ball_is_tracked_and_a_kick_restarts_the_filter():
    beliefs = TeamBeliefs(N, M, CONFIG)
    decay = CONFIG.physics.ball_decay
    pos, vel = np.array([0.0, 0.0]), np.array([1.0, 0.0])
    for cycle in range(12):
        beliefs.update(see_ball_at({0: tuple(pos)}, cycle))
        pos, vel = pos + vel, vel * decay
    assert np.hypot(*(beliefs.ball[0] - (pos - vel / decay))) < 0.3
    assert abs(beliefs.ball_vel[0, 0] - vel[0]) < 0.15
    assert beliefs.ball_age[0] == 0 and beliefs.ball_age[1] == AGE_NEVER  # player 1 saw nothing
    # a kick: the ball now goes the other way; two sightings later the belief follows it
    kicked = pos - vel / decay
    beliefs.update(see_ball_at({0: tuple(kicked + [-2.0, 0.0])}, 12))
    beliefs.update(see_ball_at({0: tuple(kicked + [-3.8, 0.0])}, 13))
    assert beliefs.ball_vel[0, 0] < -1.0


def test_players_by_number_then_the_nearest_of_their_side():
    beliefs = TeamBeliefs(N, M, CONFIG)
    v = views(0)
    v.seen_count[0] = 2
    v.seen_position[0, :2] = [[5.0, 5.0], [20.0, 0.0]]
    v.seen_side[0, :2] = [OPPONENT, TEAMMATE]
    v.seen_number[0, :2] = [1, 2]
    v.seen_distance[0, :2] = [16.0, 30.0]
    beliefs.update(v)
    np.testing.assert_allclose(beliefs.opp_pos[0, 1], [5.0, 5.0])
    np.testing.assert_allclose(beliefs.mate_pos[0, 2], [20.0, 0.0])
    assert beliefs.mate_age[0, 2] == 0 and beliefs.opp_age[0, 0] == AGE_NEVER
    # next cycle an opponent without number near the believed opponent 1 is taken for it
    v = views(1)
    v.seen_count[0] = 1
    v.seen_position[0, 0] = [6.0, 5.5]
    v.seen_side[0, 0] = OPPONENT
    v.seen_distance[0, 0] = 17.0
    beliefs.update(v)
    np.testing.assert_allclose(beliefs.opp_pos[0, 1], [6.0, 5.5])
    assert beliefs.opp_age[0, 1] == 0
    # its own column is its self-localisation
    np.testing.assert_allclose(beliefs.mate_pos[np.arange(N), np.arange(N)], v.position)


def test_a_fresher_ball_from_a_team_mate_is_taken_a_staler_one_not():
    beliefs = TeamBeliefs(N, M, CONFIG)
    beliefs.update(see_ball_at({2: (30.0, 10.0)}, 0))
    # the speaker says the ball where it expects it when heard, with its velocity then
    said = encode(TeamMessage((), 0, False, ball=(31.5, 10.0), ball_age=0, ball_velocity=(0.45, 0.0)))
    heard = ((), ((2, said),), ((0, said),))   # player 1 hears player 2; player 2 hears "player 0"
    beliefs.update(views(1, heard_mates=heard))
    np.testing.assert_allclose(beliefs.ball[1], [31.5, 10.0], atol=1e-9)
    np.testing.assert_allclose(beliefs.ball_vel[1], [0.45, 0.0], atol=1e-9)
    assert beliefs.ball_age[1] == 1
    # player 2 saw the ball itself one cycle ago: the same message (age 1 when heard) is not fresher
    assert beliefs.ball_age[2] == 1 and abs(beliefs.ball[2, 0] - 31.5) > 0.2
    # a message that carries the speaker's position places it (age 1), and the listener keeps
    # the ball velocity it believes when taking a fresher ball without one
    before = beliefs.ball_vel[1].copy() * CONFIG.physics.ball_decay
    said = encode(TeamMessage((), 1, False, ball=(20.0, 3.0), ball_age=0, sender=(12.0, -4.0)))
    beliefs.update(views(2, heard_mates=((), ((2, said),), ())))
    np.testing.assert_allclose(beliefs.mate_pos[1, 2], [12.0, -4.0], atol=1e-9)
    assert beliefs.mate_age[1, 2] == 1
    np.testing.assert_allclose(beliefs.ball[1], [20.0, 3.0], atol=1e-9)
    np.testing.assert_allclose(beliefs.ball_vel[1], before, atol=1e-9)
    # texts that are not team messages are ignored
    beliefs.update(views(3, heard_mates=((), ((0, "not-a-msg!"),), ())))


def test_a_players_model_uses_only_its_own_observations():
    """Changing what player 2 sees and hears changes nothing in players 0 and 1's models."""
    first, second = TeamBeliefs(N, M, CONFIG), TeamBeliefs(N, M, CONFIG)
    rng = np.random.default_rng(0)
    for cycle in range(30):
        a = see_ball_at({0: (cycle * 0.5, 1.0), 1: (cycle * 0.5 + 0.1, 1.0), 2: (cycle * 0.5, 1.2)}, cycle)
        b = see_ball_at({0: (cycle * 0.5, 1.0), 1: (cycle * 0.5 + 0.1, 1.0), 2: tuple(rng.uniform(-40, 40, 2))},
                        cycle)
        b.position[2] = rng.uniform(-40, 40, 2)
        b.seen_count[2] = 1
        b.seen_position[2, 0] = rng.uniform(-40, 40, 2)
        b.seen_side[2, 0] = OPPONENT
        b.seen_distance[2, 0] = 10.0
        first.update(a)
        second.update(b)
    for name in ("ball", "ball_vel", "ball_age", "mate_pos", "mate_age", "opp_pos", "opp_age"):
        np.testing.assert_array_equal(getattr(first, name)[:2], getattr(second, name)[:2], err_msg=name)
    assert not np.array_equal(first.ball[2], second.ball[2])


class _Believer(ChaserTeam):
    def __init__(self, talk: bool) -> None:
        self.talk = talk

    def reset(self, side_info, config, rng):
        super().reset(side_info, config, rng)
        self.beliefs = TeamBeliefs(side_info.players_per_team, side_info.opponents, config)

    def act(self, views):
        self.beliefs.update(views)
        command = super().act(views)
        speaker = speaker_of(views.cycle, len(views.present))
        if self.talk:  # (in turns: one speaker a cycle)
            command.say = [None] * len(views.present)
            command.say[speaker] = self.beliefs.message(speaker, views.cycle)
        return command


def _errors(talk: bool) -> tuple[float, float]:
    home = _Believer(talk)
    match = Match(home, ChaserTeam(), seed=3, config=MatchConfig(observation=ObservationConfig("partial"),
                                                                max_cycles=600))
    match.start()
    ball, mates = [], []
    while match.state.cycle < 600:
        match.step()
        sign = match.state.attack_direction(0)
        ball.append(np.hypot(*(home.beliefs.ball - match.state.ball * sign).T))
        truth = match.state.pos[:11] * sign
        mates.append(np.hypot(*(home.beliefs.mate_pos - truth[None]).reshape(-1, 2).T))
    return float(np.median(np.concatenate(ball))), float(np.percentile(np.concatenate(mates), 90))


def test_in_a_match_beliefs_follow_the_truth_and_messages_keep_team_mates_known():
    ball_quiet, mates_quiet = _errors(False)
    ball_talk, mates_talk = _errors(True)
    assert ball_quiet < 1.0 and ball_talk < 1.0
    assert mates_talk < 5.0 < mates_quiet  # without messages players behind stay unknown


def test_a_matchs_delivery_is_believed_as_the_same_messages_given_as_tuples():
    """The compiled path for a match's HeardLog and the general one for plain tuples (and for
    texts that are not all ours) leave every world model and vote bit for bit the same."""
    from dataclasses import replace

    from agents.messages import said_bytes
    from agents.teams.speaking import turn_memory
    from soccer_sim.perception.views import HeardLog
    from soccer_sim.registry import resolve_team

    class Twin:
        """A built-in decentralised team whose views also feed three more world models: one
        from the delivery, one from the same messages as tuples, one with a stranger's text."""

        observation_modes = ("partial",)

        def __init__(self) -> None:
            self.inner = resolve_team("mmdr")[0]
            self.compared = self.heard = 0
            self.stranger_ignored = False

        def reset(self, side_info, config, rng):
            self.inner.reset(side_info, config, rng)
            n, m = side_info.players_per_team, side_info.opponents
            self.models = [TeamBeliefs(n, m, config) for _ in range(3)]
            self.books = [turn_memory(n, n - 1) for _ in range(3)]

        def act(self, views):
            assert isinstance(views.heard_mates, HeardLog)
            assert said_bytes(views.heard_mates.messages) is not None  # (the compiled path is the one taken)
            plain = replace(views, heard_mates=tuple(views.heard_mates))
            odd = tuple(tuple((s, "not ours!") if s == 1 else (s, t) for s, t in row) for row in views.heard_mates)
            for model, book, given in zip(self.models, self.books, (views, plain, replace(views, heard_mates=odd))):
                model.update(given, book, 20)
            first, second, third = self.models
            for name in ("ball", "ball_vel", "ball_age", "mate_pos", "mate_age", "opp_pos", "opp_age"):
                assert np.array_equal(getattr(first, name), getattr(second, name), equal_nan=True), name
            for a, b in zip(self.books[0], self.books[1]):
                assert np.array_equal(a, b)
            self.heard += sum(len(row) for row in views.heard_mates)
            self.compared += 1
            self.stranger_ignored |= not np.array_equal(first.mate_age, third.mate_age)
            return self.inner.act(views)

    twin = Twin()
    Match(twin, "static", seed=5, config=MatchConfig(observation=ObservationConfig("partial"), max_cycles=200)).run()
    assert twin.compared == 200 and twin.heard > 1000
    assert (twin.books[0].proposal_cycle >= 0).any()  # proposals were heard and taken
    assert twin.stranger_ignored  # the stranger's text was ignored: some team-mate was believed older


def test_a_players_own_kick_changes_the_ball_velocity_it_believes():
    """TeamBeliefs.kicked against the numpy it stands for: only kicks of players who believe
    the ball within reach count, and the believed velocity is capped at ball_speed_max."""
    rng = np.random.default_rng(8)
    speed_max = CONFIG.physics.ball_speed_max
    for _ in range(40):
        beliefs = TeamBeliefs(N, M, CONFIG)
        beliefs.mate_pos[:] = rng.uniform(-3, 3, (N, N, 2))
        beliefs.ball[:] = beliefs.mate_pos[np.arange(N), np.arange(N)] + rng.uniform(-1.5, 1.5, (N, 2))
        beliefs.ball_vel[:] = rng.uniform(-2, 2, (N, 2))
        kick = rng.uniform(-2.5, 2.5, (N, 2)) * (rng.random((N, 1)) < 0.7)
        expected = beliefs.ball_vel.copy()
        gap = beliefs.ball - beliefs.mate_pos[np.arange(N), np.arange(N)]
        mine = kick.any(axis=1) & (np.einsum("ij,ij->i", gap, gap) <= 1.2 ** 2)
        expected[mine] += kick[mine]
        speed = np.hypot(expected[mine, 0], expected[mine, 1])
        expected[mine] *= np.minimum(1.0, speed_max / np.maximum(speed, 1e-9))[:, None]
        beliefs.kicked(kick, 1.2)
        np.testing.assert_array_equal(beliefs.ball_vel, expected)


def test_a_ball_age_said_as_the_most_a_message_holds_is_never_taken():
    """A speaker whose ball is MAX_AGE cycles old or older says MAX_AGE: the ball may be any
    older, so a listener who has not seen the ball for longer still does not take it."""
    from agents.messages import MAX_AGE

    beliefs = TeamBeliefs(N, M, CONFIG)
    beliefs.update(views(0))  # nobody has seen the ball
    stale = encode(TeamMessage((), 0, False, ball=(20.0, 3.0), ball_age=MAX_AGE, ball_velocity=(0.0, 0.0)))
    fresh = encode(TeamMessage((), 1, False, ball=(21.0, 3.0), ball_age=MAX_AGE - 1, ball_velocity=(0.0, 0.0)))
    beliefs.update(views(1, heard_mates=((), ((2, stale),), ())))
    assert beliefs.ball_age[1] > 1000 and not np.allclose(beliefs.ball[1], [20.0, 3.0])
    beliefs.update(views(2, heard_mates=((), ((2, fresh),), ())))
    assert beliefs.ball_age[1] == MAX_AGE and np.allclose(beliefs.ball[1], [21.0, 3.0])
