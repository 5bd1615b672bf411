"""A team's messages encoded and decoded in batches (agents.messages) agree with the one-message functions."""

from __future__ import annotations

import numpy as np

from agents.messages import (MAX_AGE, VOTE, WORLD, MessageError, VoteMessage, WorldMessage, decode, decode_texts,
                             encode, encode_world_clipped)
from agents.messages import heard_batch, vote_texts, world_texts
from agents.roles.voting import VoteBook


def test_a_teams_world_messages_are_the_single_encoders_ones_row_by_row():
    rng = np.random.default_rng(3)
    n = 11
    ball = rng.uniform(-70, 70, (n, 2))          # some beyond the ranges: clipped
    ball[0] = (0.05, -0.15)                        # halves of a step: rounded to even, as Python's round
    ball_vel = rng.uniform(-4, 4, (n, 2))
    age = rng.integers(-2, 30, n)
    sender = rng.uniform(-60, 60, (n, 2))
    present = np.ones(n, dtype=bool)
    present[4] = False
    texts = world_texts(ball, ball_vel, age, sender, present)
    for i in range(n):
        expected = encode_world_clipped(tuple(ball[i]), tuple(ball_vel[i]), int(age[i]), tuple(sender[i]))
        assert texts[i] == (expected if present[i] else None)
    assert decode(texts[1]).ball_age == min(max(int(age[1]), 0), MAX_AGE)


def test_a_teams_votes_are_the_single_encoders_ones():
    rng = np.random.default_rng(5)
    assignments = np.array([rng.permutation(10) for _ in range(11)])
    texts = vote_texts(assignments, 123457, np.ones(11, dtype=bool))
    for row, text in zip(assignments, texts):
        assert text == VoteBook.message(row, 123457)
        assert decode(text) == VoteMessage(assignment=tuple(row.tolist()), cycle=123457)


def test_decoding_many_at_once_gives_each_messages_kind_and_values():
    world = WorldMessage(ball=(12.3, -4.5), ball_velocity=(0.5, -0.26), ball_age=3, sender=(-20.0, 7.1))
    vote = VoteMessage(assignment=(2, 0, 1, 4, 3), cycle=77)
    good_world, good_vote = encode(world), encode(vote)
    bad = ["short", "é" * 10, "(" * 10, "~" * 10]    # wrong length, not ASCII, outside the alphabet, no encoder's
    decoded = decode_texts([good_world, *bad, good_vote])
    assert decoded.kind.tolist() == [WORLD, -1, -1, -1, -1, VOTE]
    np.testing.assert_allclose(decoded.world[0], [12.3, -4.5, 0.5, -0.26, 3, -20.0, 7.1])
    assert decoded.world_message(0) == decode(good_world)
    assert decoded.vote_message(5) == vote
    for text in bad:
        try:
            decode(text)
        except MessageError:
            continue
        raise AssertionError(f"{text!r} decoded")


def test_heard_messages_keep_their_listener_and_speaker():
    texts = [encode(VoteMessage(assignment=(1, 0), cycle=c)) for c in range(3)]
    heard = heard_batch(((), ((0, texts[0]),), ((3, texts[1]), (1, texts[2]))))
    assert heard.listener.tolist() == [1, 2, 2]
    assert heard.speaker.tolist() == [0, 3, 1]
    assert heard.decoded.vote_cycle.tolist() == [0, 1, 2]
