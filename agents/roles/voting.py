"""Reconciling the role assignments that a team's players compute each on its own world model.

Under partial observation every player runs the role assigner on what it believes, so two
players may compute different assignments. As in UT Austin Villa's decentralised positioning
(SCRAM's setting), players broadcast their assignment as a vote (a
:class:`~agents.messages.VoteMessage`: the whole permutation and the cycle it was computed for)
and each follows the assignment most of the votes it knows agree on.

:class:`VoteBook` keeps, for each listening player, the latest vote it heard from each
team-mate (row ``i`` is player ``i``'s memory, filled only from what player ``i`` heard), and
:meth:`VoteBook.follow` picks per player among its own proposal and the votes at most
``horizon`` cycles old: the assignment with the most identical votes; on a tie its own
proposal if that is among the most voted, else the most recent of the tied (then the lowest
team-mate index). With everyone's models agreeing this is the shared assignment; when they
differ, it pulls players towards one.

:func:`role_conflicts` measures the disagreement that is left: roles that two or more players
believe they hold, and roles nobody holds.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from agents.messages import CYCLE_MODULUS, VOTE, HeardBatch, VoteMessage, encode, heard_batch, vote_texts

NO_VOTE = -(1 << 40)
"""The cycle of a vote never heard."""


class VoteBook:
    """Each of a team's ``n`` players' memory of its team-mates' votes on an assignment of ``k``
    roles (default ``n``; e.g. the outfield roles) (module docstring)."""

    def __init__(self, n: int, horizon: int = 20, k: int | None = None) -> None:
        k = n if k is None else k
        if n < 1 or n > 11 or k < 1 or k > 11:
            raise ValueError(f"VoteBook: a team has 1 to 11 players and roles, got {n} players, {k} roles")
        if horizon < 0:
            raise ValueError(f"VoteBook: horizon must be >= 0 cycles, got {horizon}")
        self.n, self.k, self.horizon = n, k, horizon
        self.votes = np.tile(np.arange(k, dtype=np.int64), (n, n, 1))
        """(n, n, k): ``votes[i, j]`` the last assignment player i heard from team-mate j."""
        self.vote_cycle = np.full((n, n), NO_VOTE, dtype=np.int64)
        """(n, n): the cycle each of those votes was computed for (NO_VOTE: none)."""

    @staticmethod
    def message(assignment: np.ndarray, cycle: int) -> str:
        """A vote for ``assignment`` (``assignment[j]`` the role of player j) computed at ``cycle``."""
        return encode(VoteMessage(assignment=tuple(int(r) for r in assignment), cycle=int(cycle)))

    @staticmethod
    def messages(assignments: np.ndarray, cycle: int, present: np.ndarray) -> list[str | None]:
        """Each present player's vote for its row of ``assignments`` (n, k) computed at ``cycle``."""
        return vote_texts(np.ascontiguousarray(assignments, dtype=np.int64), int(cycle), present)

    def hear(self, cycle: int, heard: HeardBatch | tuple) -> None:
        """Store the votes among the team-mates' messages each player heard at ``cycle``
        (``heard``: a :class:`~agents.messages.HeardBatch`, or per listener its
        (team-mate index, text) pairs); other messages are left alone, and a vote of the
        wrong size or from no team-mate is ignored."""
        if not isinstance(heard, HeardBatch):
            heard = heard_batch(heard)
        if heard.listener.size:
            d = heard.decoded
            _store_votes(heard.listener, heard.speaker, d.kind, d.vote, d.vote_size, d.vote_cycle, VOTE, cycle,
                         CYCLE_MODULUS, self.votes, self.vote_cycle)

    def follow(self, cycle: int, own: np.ndarray) -> np.ndarray:
        """(n, k): the assignment each player follows, from its own proposal ``own[i]`` (n, k)
        and the fresh votes it holds (module docstring)."""
        n = self.n
        proposals = np.ascontiguousarray(own, dtype=np.int64)
        if proposals.shape != (n, self.k):
            raise ValueError(f"VoteBook.follow: own proposals must be ({n}, {self.k}), got {proposals.shape}")
        out = np.empty_like(proposals)
        follow_votes(np.arange(n), self.votes, self.vote_cycle, proposals, cycle, self.horizon, out)
        return out

    def follow_one(self, i: int, cycle: int, proposal: np.ndarray) -> np.ndarray:
        """The assignment player ``i`` follows given its own ``proposal`` (k,): :meth:`follow`
        for one player (its row uses only its own memory)."""
        proposals = np.empty((self.n, self.k), dtype=np.int64)
        proposals[i] = proposal
        follow_votes(np.array([i]), self.votes, self.vote_cycle, proposals, cycle, self.horizon, proposals)
        return proposals[i].copy()


@njit(cache=True, nogil=True)
def _store_votes(listener, speaker, kind, vote, size, vote_cycle_sent, vote_kind, cycle, modulus, votes,
                 vote_cycle) -> None:  # pragma: no cover - compiled
    """Keep each heard vote of the right size from a team-mate, unless the listener holds a
    newer one from that team-mate (the cycle travels modulo ``modulus``: the latest cycle no
    later than now with that residue)."""
    n, k = votes.shape[0], votes.shape[2]
    for p in range(listener.shape[0]):
        i, j = listener[p], speaker[p]
        if kind[p] != vote_kind or size[p] != k or j < 0 or j >= n:
            continue
        computed = cycle - (cycle - vote_cycle_sent[p]) % modulus
        if computed >= vote_cycle[i, j]:
            votes[i, j, :] = vote[p, :k]
            vote_cycle[i, j] = computed


@njit(cache=True, nogil=True)
def follow_votes(rows: np.ndarray, votes: np.ndarray, vote_cycle: np.ndarray, proposals: np.ndarray, cycle: int,
                 horizon: int, out: np.ndarray) -> None:  # pragma: no cover - compiled
    """For each player ``i`` of ``rows``, into ``out[i]``: among its own ``proposals[i]`` and
    the votes it holds at most ``horizon`` cycles old, the assignment with the most identical
    votes; on a tie its own if that is among them, else the most recent (then the lowest
    team-mate index). ``out`` may be ``proposals``.

    The votes are grouped first (each fresh vote joins its own proposal's group or the group of
    the first earlier identical vote, found by a hash of the assignment and then compared in
    full), so a player's tally costs one pass over its team-mates' votes."""
    n, k = votes.shape[0], votes.shape[2]
    fresh = np.empty(n, dtype=np.bool_)
    keys = np.empty(n, dtype=np.int64)
    group = np.empty(n, dtype=np.int64)  # -1: the own proposal's, else the group's first voter
    count = np.empty(n, dtype=np.int64)
    latest = np.empty(n, dtype=np.int64)
    latest_j = np.empty(n, dtype=np.int64)
    own = np.empty(k, dtype=np.int64)
    for i in rows:
        own[:] = proposals[i]
        own_key = _assignment_key(own)
        own_count = 1
        for j in range(n):
            fresh[j] = j != i and cycle - vote_cycle[i, j] <= horizon
            if not fresh[j]:
                continue
            keys[j] = _assignment_key(votes[i, j])
            if keys[j] == own_key and _same(votes[i, j], own):
                group[j] = -1
                own_count += 1
                continue
            group[j] = j
            for c in range(j):
                if fresh[c] and group[c] == c and keys[c] == keys[j] and _same(votes[i, c], votes[i, j]):
                    group[j] = c
                    break
            g = group[j]
            if g == j:
                count[j], latest[j], latest_j[j] = 1, vote_cycle[i, j], j
            else:
                count[g] += 1
                if vote_cycle[i, j] > latest[g]:
                    latest[g], latest_j[g] = vote_cycle[i, j], j
        best, best_count, best_cycle, best_j = -1, own_count, 0, 0   # -1: the own proposal
        for c in range(n):
            if not fresh[c] or group[c] != c:
                continue
            if count[c] > best_count or (count[c] == best_count and best >= 0
                                         and (latest[c] > best_cycle
                                              or (latest[c] == best_cycle and latest_j[c] < best_j))):
                best, best_count, best_cycle, best_j = c, count[c], latest[c], latest_j[c]
        if best >= 0:
            out[i] = votes[i, best]
        else:
            out[i] = own


@njit(cache=True, nogil=True)
def _assignment_key(a: np.ndarray) -> int:  # pragma: no cover - compiled
    """A hash of an assignment (equal assignments have equal keys; wraps around int64)."""
    key = 0
    for r in range(a.shape[0]):
        key = key * 1_000_003 + a[r] + 1
    return key


@njit(cache=True, nogil=True)
def _same(a: np.ndarray, b: np.ndarray) -> bool:  # pragma: no cover - compiled
    """Whether two assignments are equal."""
    for r in range(a.shape[0]):
        if a[r] != b[r]:
            return False
    return True


@njit(cache=True, nogil=True)
def role_conflicts(roles: np.ndarray, n_roles: int) -> tuple[int, int]:  # pragma: no cover - compiled
    """(roles claimed by two or more players, roles claimed by nobody) for ``roles`` (k,) int64,
    the role each player believes it holds (under one shared assignment both are 0); roles
    outside ``0 .. n_roles - 1`` are not counted."""
    counts = np.zeros(n_roles, dtype=np.int64)
    for r in roles:
        if 0 <= r < n_roles:
            counts[r] += 1
    shared, empty = 0, 0
    for c in counts:
        if c > 1:
            shared += 1
        elif c == 0:
            empty += 1
    return shared, empty


@njit(cache=True, nogil=True)
def believed_conflicts(followed: np.ndarray, outfield: np.ndarray) -> tuple[int, int]:  # pragma: no cover
    """:func:`role_conflicts` of the roles the ``outfield`` players (k,) believe they hold:
    player ``outfield[j]``'s own entry ``followed[outfield[j], j]`` of the assignment it
    follows (``followed`` (n, k))."""
    k = outfield.shape[0]
    roles = np.empty(k, dtype=np.int64)
    for j in range(k):
        roles[j] = followed[outfield[j], j]
    return role_conflicts(roles, k)
