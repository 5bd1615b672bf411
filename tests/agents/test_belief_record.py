"""A team's intake in one compiled call (:mod:`agents.teams.belief_record`, made by
:meth:`TeamBeliefs.update`): the same world models and votes as decoding the messages,
updating the models and storing the votes one after the other, bad messages and a side
without votes included."""

from __future__ import annotations

import numpy as np
import pytest

from agents.messages import WORLD, WorldMessage, encode, heard_batch, vote_texts
from agents.roles.voting import VoteBook
from agents.teams.belief_kernels import believe
from agents.teams.world_model import TeamBeliefs
from tests.agents.test_world_model import CONFIG, M, N, see_ball_at


def _heard(cycle: int) -> tuple:
    """Team-mates' messages of a cycle: world messages, votes, and texts that are no message."""
    world = encode(WorldMessage(ball=(3.0 + cycle, -2.0), ball_velocity=(0.4, 0.1), ball_age=cycle % 5,
                                sender=(-4.0, 1.5)))
    votes = vote_texts(np.array([[2, 0, 1], [1, 2, 0], [0, 1, 2]]), cycle - 1, np.ones(N, bool))
    return (((1, votes[1]), (2, votes[2])), ((0, world), (2, "not a msg!")), ((0, votes[0]), (1, "(bad)")))


def _three_steps(beliefs: TeamBeliefs, book: VoteBook | None, views) -> None:
    """The intake one step after another: decode, the world-model kernel, the vote book."""
    heard = heard_batch(views.heard_mates)
    believe(beliefs.ball, beliefs.ball_vel, beliefs.ball_age, beliefs.mate_pos, beliefs.mate_age, beliefs.opp_pos,
            beliefs.opp_age, beliefs._last_seen, beliefs._last_seen_cycle, views.ball_seen, views.ball,
            views.ball_distance, views.saw, views.seen_count, views.seen_position, views.seen_side,
            views.seen_number, views.seen_distance, views.position, heard.listener, heard.speaker,
            heard.decoded.kind, heard.decoded.world, WORLD, views.cycle, beliefs._params, beliefs._ball_decay,
            beliefs._ball_speed_max)
    if book is not None:
        book.hear(views.cycle, heard)


@pytest.mark.parametrize("with_votes", [True, False])
def test_one_call_gives_what_the_three_steps_give(with_votes: bool) -> None:
    apart, together = TeamBeliefs(N, M, CONFIG), TeamBeliefs(N, M, CONFIG)
    book_apart = VoteBook(N, 20, N) if with_votes else None
    book_together = VoteBook(N, 20, N) if with_votes else None
    arrays = (book_together.votes, book_together.vote_cycle) if with_votes else None
    for cycle in range(1, 9):
        views = see_ball_at({0: (1.0 * cycle, 0.5), 2: (1.1 * cycle, 0.4)} if cycle < 4 else {}, cycle)
        views.heard_mates = _heard(cycle) if cycle % 3 else ((),) * N  # some silent cycles
        _three_steps(apart, book_apart, views)
        together.update(views, arrays)
    for name in ("ball", "ball_vel", "ball_age", "mate_pos", "mate_age", "opp_pos", "opp_age"):
        np.testing.assert_array_equal(getattr(together, name), getattr(apart, name), err_msg=name)
    assert together.ball_age[1] <= 5  # player 1 saw nothing: the ball came from a message
    if with_votes:
        np.testing.assert_array_equal(book_together.votes, book_apart.votes)
        np.testing.assert_array_equal(book_together.vote_cycle, book_apart.vote_cycle)
        assert (book_together.votes[0, 1] == [1, 2, 0]).all() and (book_together.votes[2, 0] == [2, 0, 1]).all()
