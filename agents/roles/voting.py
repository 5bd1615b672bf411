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

from agents.messages import CYCLE_MODULUS, HeardMessages, VoteMessage, encode


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
        self.votes = np.zeros((n, n, k), dtype=np.int64)
        """(n, n, k): ``votes[i, j]`` the last assignment player i heard from team-mate j."""
        self.vote_cycle = np.full((n, n), -(1 << 40), dtype=np.int64)
        """(n, n): the cycle each of those votes was computed for (very negative: none)."""
        self._heard = HeardMessages()
        self._keys: list[list[tuple[int, ...]]] = [[tuple(range(k))] * n for _ in range(n)]
        self._cycles: list[list[int]] = [[-(1 << 40)] * n for _ in range(n)]

    @staticmethod
    def message(assignment: np.ndarray, cycle: int) -> str:
        """A vote for ``assignment`` (``assignment[j]`` the role of player j) computed at ``cycle``."""
        return encode(VoteMessage(assignment=tuple(int(r) for r in assignment), cycle=int(cycle)))

    def hear(self, cycle: int, heard_mates: tuple[tuple[tuple[int, str], ...], ...]) -> None:
        """Store the votes among the team-mates' messages each player heard at ``cycle`` (other
        messages are left alone; a vote of the wrong size is ignored)."""
        for i, speaker, vote in self._heard.of_kind(heard_mates, VoteMessage):
            if len(vote.assignment) != self.k or not 0 <= speaker < self.n:
                continue
            # the cycle travels modulo CYCLE_MODULUS: the latest cycle <= now with that residue
            computed = cycle - (cycle - vote.cycle) % CYCLE_MODULUS
            if computed >= self._cycles[i][speaker]:
                self.votes[i, speaker] = vote.assignment
                self.vote_cycle[i, speaker] = computed
                self._keys[i][speaker] = vote.assignment
                self._cycles[i][speaker] = computed

    def follow(self, cycle: int, own: np.ndarray) -> np.ndarray:
        """(n, k): the assignment each player follows, from its own proposal ``own[i]`` (n, k)
        and the fresh votes it holds (module docstring)."""
        n = self.n
        proposals = np.asarray(own, dtype=np.int64)
        if proposals.shape != (n, self.k):
            raise ValueError(f"VoteBook.follow: own proposals must be ({n}, {self.k}), got {proposals.shape}")
        return np.stack([self.follow_one(i, cycle, proposals[i]) for i in range(n)])

    def follow_one(self, i: int, cycle: int, proposal: np.ndarray) -> np.ndarray:
        """The assignment player ``i`` follows given its own ``proposal`` (k,): :meth:`follow`
        for one player (its row uses only its own memory)."""
        own = tuple(np.asarray(proposal, dtype=np.int64).tolist())
        # per assignment: [votes for it, then its best row's (recency, -team-mate index) for ties]
        tally: dict[tuple[int, ...], list] = {own: [1, (1 << 41, 1)]}
        horizon, keys, cycles = self.horizon, self._keys[i], self._cycles[i]
        for j in range(self.n):
            if j == i or cycle - cycles[j] > horizon:
                continue
            rank = (cycles[j], -j)
            entry = tally.get(keys[j])
            if entry is None:
                tally[keys[j]] = [1, rank]
            else:
                entry[0] += 1
                entry[1] = max(entry[1], rank)
        best = max(tally.items(), key=lambda item: (item[1][0], item[1][1]))[0]
        return np.array(best, dtype=np.int64)


def role_conflicts(roles: np.ndarray, n_roles: int) -> tuple[int, int]:
    """(roles claimed by two or more players, roles claimed by nobody) for ``roles`` (k,), the
    role each player believes it holds (under one shared assignment both are 0)."""
    counts = np.bincount(np.asarray(roles, dtype=np.int64), minlength=n_roles)[:n_roles]
    return int(np.count_nonzero(counts > 1)), int(np.count_nonzero(counts == 0))
