"""Speaking turns: who of a team says the team message in a cycle, and what it carries.

rcssserver lets every player say one message a cycle, but a listener hears at most
``hear_max`` (1) team-mate a cycle, chosen at random among those who spoke
(:mod:`soccer_sim.perception.audio`). If every player speaks every cycle, a given team-mate's
message reaches a given listener once in about ten cycles, and the players' votes on the role
assignment stay apart. If one player speaks per cycle, every listener within
``audio_cut_dist`` (50 m) hears that one message: the channel becomes a broadcast.

So the team's players speak in turns by shirt order: the speaker of cycle ``t`` is player
``t mod n`` (:func:`speaker_of`; a player not on the pitch leaves its turn silent). Its message
(:class:`agents.messages.TeamMessage`) carries the role assignment it computed this cycle on
its own beliefs, its vote, marked **settled** when it is the team's assignment already or the
proposal the previous speaker made (:func:`settles`): the team's assignment changes to a
proposal that two consecutive speakers made alike, each on its own beliefs. Every listener
follows a settled assignment from the next cycle, when the message is heard, the speaker
included (:func:`take_proposal`): the whole team changes assignment in the same cycle, within
two cycles of a change that the players' beliefs agree on, and a player who missed a message
(out of range) is back in step with the next settled one. It also carries the
ball as the speaker believes it and, alternately, the ball's velocity or the speaker's own
position (:func:`carries_velocity`: every speaker alternates between the two from one turn to
its next, and consecutive speakers differ).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

from agents.message_kernels import SENDER, VELOCITY, message_number

AGREEMENTS: tuple[str, ...] = ("settled", "speaker", "own")
"""How a team's players under partial observation come to the assignment they follow
(``TeamStyle.agreement``): ``"settled"`` (the default) the last settled proposal heard
(:func:`settles`: two consecutive speakers alike, or the team's already); ``"speaker"`` every
proposal heard, at once (no second view asked: the assignment may swap back and forth with
the speakers' beliefs); ``"own"`` each its own proposal, on its own beliefs (the turns carry
only the world information; players may disagree)."""


def check_agreement(value: object) -> str:
    """``value`` if it is one of :data:`AGREEMENTS`; a ValueError naming the problem otherwise."""
    if value not in AGREEMENTS:
        raise ValueError(f"agreement must be one of {', '.join(map(repr, AGREEMENTS))}, got {value!r}")
    return str(value)


class TurnMemory(NamedTuple):
    """What each belief row keeps of the team messages heard (the pipeline's arrays; k columns:
    the outfield roles, none for a team that does not talk)."""

    followed: np.ndarray
    """(rows, k) int64 the team's assignment as the row holds it: what its player follows."""
    heard_cycle: np.ndarray
    """(rows,) int64 the cycle the last proposal heard was computed for (a row follows the
    team's assignment while this is recent)."""
    proposal: np.ndarray
    """(rows, k) int64 the last proposal heard."""
    proposal_cycle: np.ndarray
    """(rows,) int64 the cycle it was computed for."""


NEVER = -(1 << 40)
"""The cycle of a proposal never heard."""


def turn_memory(rows: int, k: int) -> TurnMemory:
    """A :class:`TurnMemory` of ``rows`` belief rows for ``k`` roles, nothing heard yet."""
    return TurnMemory(followed=np.tile(np.arange(k, dtype=np.int64), (rows, 1)),
                      heard_cycle=np.full(rows, NEVER, dtype=np.int64),
                      proposal=np.tile(np.arange(k, dtype=np.int64), (rows, 1)),
                      proposal_cycle=np.full(rows, NEVER, dtype=np.int64))


@njit(cache=True, nogil=True)
def speaker_of(cycle: int, n: int) -> int:  # pragma: no cover - compiled
    """The player whose turn it is to speak at ``cycle`` in a team of ``n`` (-1: no players)."""
    return cycle % n if n > 0 else -1


@njit(cache=True, nogil=True)
def carries_velocity(cycle: int, n: int) -> bool:  # pragma: no cover - compiled
    """Whether the message said at ``cycle`` carries the ball's velocity (else the speaker's
    position): ``(t mod n + t div n)`` even, so the speaker of a turn carries the other payload
    at its next turn (``t + n``) and consecutive speakers within a round differ."""
    if n <= 0:
        return True
    return (cycle % n + cycle // n) % 2 == 0


@njit(cache=True, nogil=True)
def settles(i: int, proposal: np.ndarray, computed: int, memory: TurnMemory) -> bool:  # pragma: no cover - compiled
    """Whether the speaker ``i``'s ``proposal`` (k,), computed at ``computed``, settles the
    team's assignment: it is the assignment the speaker holds as the team's already, or the
    proposal it heard from the previous speaker, computed on that speaker's own beliefs (a
    change needs a second, independent view: beliefs differ by their noise, and a proposal that
    only one view supports would otherwise swap roles back and forth every cycle)."""
    same_team = same_previous = True
    previous = memory.proposal_cycle[i] == computed - 1
    for r in range(proposal.shape[0]):
        same_team &= memory.followed[i, r] == proposal[r]
        same_previous &= memory.proposal[i, r] == proposal[r]
    return same_team or (previous and same_previous)


@njit(cache=True, nogil=True)
def take_proposal(i: int, proposal: np.ndarray, computed: int, settled: bool, memory: TurnMemory,
                  horizon: int) -> None:  # pragma: no cover - compiled
    """Player ``i`` hears a speaker's ``proposal`` (k,) computed at ``computed`` (its own
    included: a speaker knows what it said): a ``settled`` one becomes the team's assignment as
    ``i`` holds it (``memory.followed[i]``), as does any proposal when ``i`` holds no team
    assignment heard within ``horizon`` cycles; either way it is the last proposal heard, and
    any message keeps the team's assignment fresh."""
    if settled or computed - memory.heard_cycle[i] > horizon:
        memory.followed[i, :] = proposal
    memory.heard_cycle[i] = max(memory.heard_cycle[i], computed)
    memory.proposal[i, :] = proposal
    memory.proposal_cycle[i] = computed


@njit(cache=True, nogil=True)
def speaker_message(proposal: np.ndarray, cycle: int, settled: bool, ball: np.ndarray, ball_vel: np.ndarray,
                    ball_age: int, position: np.ndarray, n: int, ball_decay: float,
                    grid: np.ndarray) -> int:  # pragma: no cover - compiled
    """The number of the team message the speaker of ``cycle`` (in a team of ``n``) says: its
    ``proposal`` (k,), ``settled`` or not (:func:`settles`); its ball (2,) m, velocity (2,)
    m/cycle and age as it expects them when the message is heard (one cycle on: rolled by the
    velocity, which slows by ``ball_decay``); and the ball's velocity or its own ``position``
    (2,) m, as the turn has it (:func:`carries_velocity`). ``grid``: the message grid
    (:data:`agents.messages.MESSAGE_GRID`)."""
    ahead = np.empty(2)
    extra = np.empty(2)
    velocity = carries_velocity(cycle, n)
    for a in range(2):
        ahead[a] = ball[a] + ball_vel[a]
        extra[a] = ball_vel[a] * ball_decay if velocity else position[a]
    return message_number(proposal, cycle, settled, ahead, ball_age, extra, VELOCITY if velocity else SENDER, grid)
