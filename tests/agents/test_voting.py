"""Reconciling per-player role assignments by votes (agents.roles.voting)."""

from __future__ import annotations

import numpy as np
import pytest

from agents.messages import WorldMessage, encode
from agents.roles.voting import VoteBook, believed_conflicts, role_conflicts

IDENTITY = np.arange(4)
SWAP = np.array([1, 0, 2, 3])


def heard(pairs: dict[int, list[tuple[int, str]]], n: int = 4) -> tuple:
    return tuple(tuple(pairs.get(i, [])) for i in range(n))


def test_without_votes_each_player_follows_its_own_proposal():
    book = VoteBook(4)
    own = np.stack([IDENTITY, SWAP, IDENTITY, SWAP])
    np.testing.assert_array_equal(book.follow(0, own), own)


def test_the_majority_of_fresh_votes_wins_and_stale_votes_do_not_count():
    book = VoteBook(4, horizon=5)
    # player 1 proposes SWAP but hears IDENTITY from players 0, 2 and 3
    swap_vote, id_vote = VoteBook.message(SWAP, 10), VoteBook.message(IDENTITY, 10)
    for cycle, speaker in ((10, 0), (11, 2), (12, 3)):
        book.hear(cycle, heard({1: [(speaker, id_vote)], 0: [(1, swap_vote)]}))
    own = np.stack([IDENTITY, SWAP, IDENTITY, IDENTITY])
    followed = book.follow(12, own)
    np.testing.assert_array_equal(followed[1], IDENTITY)
    # player 0 heard one SWAP vote: a tie with its own proposal, which it keeps
    np.testing.assert_array_equal(followed[0], IDENTITY)
    # sixteen cycles later the votes are stale: player 1 is back to its own proposal
    np.testing.assert_array_equal(book.follow(26, own)[1], SWAP)


def test_a_player_follows_the_others_when_they_outvote_it_two_to_one():
    book = VoteBook(4)
    book.hear(5, heard({0: [(1, VoteBook.message(SWAP, 5))]}))
    book.hear(6, heard({0: [(2, VoteBook.message(SWAP, 6))]}))
    np.testing.assert_array_equal(book.follow(6, np.stack([IDENTITY] * 4))[0], SWAP)


def test_only_votes_of_the_right_size_from_team_mates_are_kept():
    book = VoteBook(4)
    world = encode(WorldMessage(ball=(1.0, 2.0), ball_velocity=(0.0, 0.0), ball_age=0, sender=(0.0, 0.0)))
    book.hear(3, heard({0: [(1, world)], 1: [(2, VoteBook.message(np.arange(3), 3))], 2: [(3, "garbage!!!")]}))
    assert np.all(book.vote_cycle < 0)
    with pytest.raises(ValueError, match="own proposals must be"):
        book.follow(3, np.zeros((3, 3)))


def test_role_conflicts_count_shared_and_empty_roles():
    assert role_conflicts(np.array([0, 1, 2, 3]), 4) == (0, 0)
    assert role_conflicts(np.array([0, 0, 2, 2]), 4) == (2, 2)
    assert role_conflicts(np.array([1, 1, 1, 3]), 4) == (1, 2)


def test_believed_conflicts_read_each_players_own_entry():
    rng = np.random.default_rng(3)
    outfield = np.array([1, 2, 4, 5])  # (row 0 the goalkeeper, row 3 absent from the outfield)
    for _ in range(50):
        followed = np.array([rng.permutation(4) for _ in range(6)])
        followed[rng.integers(0, 6)] = rng.integers(0, 4, 4)  # one player's odd belief
        own = followed[outfield, np.arange(4)]
        assert believed_conflicts(followed, outfield) == role_conflicts(own, 4)
    same = np.tile(np.array([2, 0, 3, 1]), (6, 1))
    assert believed_conflicts(same, outfield) == (0, 0)
    clash = same.copy()
    clash[2, 1] = 2  # player 2 (column 1) believes it holds player 1's role 2
    assert believed_conflicts(clash, outfield) == (1, 1)


def test_one_player_follows_as_the_team_call_says_and_votes_may_cover_fewer_roles():
    book = VoteBook(5, k=4)
    book.hear(5, heard({0: [(1, VoteBook.message(SWAP, 5))], 2: [(4, VoteBook.message(SWAP, 5))]}, n=5))
    book.hear(6, heard({0: [(3, VoteBook.message(SWAP, 6))]}, n=5))
    own = np.stack([IDENTITY] * 5)
    team = book.follow(6, own)
    for i in range(5):
        np.testing.assert_array_equal(book.follow_one(i, 6, own[i]), team[i])
    np.testing.assert_array_equal(team[0], SWAP)
    np.testing.assert_array_equal(team[1], IDENTITY)


def test_between_tied_votes_of_others_the_most_recent_wins_then_the_lowest_team_mate():
    other = np.array([0, 2, 1, 3])
    own = np.stack([np.array([3, 2, 1, 0])] + [IDENTITY] * 4)

    def book_with(swap_cycle: int, other_cycle: int) -> VoteBook:
        book = VoteBook(5, k=4)  # player 0 holds SWAP from 3 and 4, `other` from 1 and 2: two each
        for speaker, vote, cycle in ((3, SWAP, swap_cycle), (4, SWAP, swap_cycle), (1, other, other_cycle),
                                     (2, other, other_cycle)):
            book.hear(10, heard({0: [(speaker, VoteBook.message(vote, cycle))]}, n=5))
        return book

    np.testing.assert_array_equal(book_with(9, 8).follow(10, own)[0], SWAP)    # the newer
    np.testing.assert_array_equal(book_with(8, 9).follow(10, own)[0], other)
    np.testing.assert_array_equal(book_with(9, 9).follow_one(0, 10, own[0]), other)  # team-mate 1 before 3


def _followed_by_the_rule(votes, vote_cycle, proposal, i, cycle, horizon):
    """The docstring's rule, spelt out: the most identical votes; ties to the own proposal,
    then the most recent vote, then the lowest team-mate index."""
    n = votes.shape[0]
    fresh = [j for j in range(n) if j != i and cycle - vote_cycle[i, j] <= horizon]
    tally: dict[tuple, list] = {tuple(proposal): [1, None, None]}
    for j in fresh:
        entry = tally.setdefault(tuple(votes[i, j]), [0, None, None])
        entry[0] += 1
        if entry[1] is None or vote_cycle[i, j] > entry[1]:
            entry[1], entry[2] = int(vote_cycle[i, j]), j
    own = tally.pop(tuple(proposal))
    best, best_key = tuple(proposal), (own[0], 1, 0, 0)
    for assignment, (count, latest, first_j) in tally.items():
        key = (count, 0, latest, -first_j)
        if key[0] > best_key[0] or (key[0] == best_key[0] and best_key[1] == 0 and key[2:] > best_key[2:]):
            best, best_key = assignment, key
    return np.array(best)


def test_following_matches_the_rule_over_many_random_vote_books():
    rng = np.random.default_rng(7)
    pool = np.array([rng.permutation(4) for _ in range(3)])  # few distinct assignments: many ties
    for _ in range(300):
        book = VoteBook(6, horizon=5, k=4)
        book.votes[:] = pool[rng.integers(0, 3, size=(6, 6))]
        book.vote_cycle[:] = rng.integers(90, 101, size=(6, 6))
        i = int(rng.integers(0, 6))
        proposal = pool[int(rng.integers(0, 3))]
        expected = _followed_by_the_rule(book.votes, book.vote_cycle, proposal, i, 100, 5)
        np.testing.assert_array_equal(book.follow_one(i, 100, proposal), expected)
